// Tests for dynamics/thrusters.h against Gazzino 2018, eqs. (1.72)-(1.80) and
// the L1 cost (1.96)-(1.98).
#include "dynamics/thrusters.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace thrustsched::dynamics {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr double kThrust = 0.265;  // N
constexpr double kMass = 4850.0;   // kg
constexpr double kIsp = 2005.0;    // s

TEST(ThrusterSetTest, Anzel4MatchesPublishedDirections) {
  const ThrusterSet set = ThrusterSet::Anzel4(kThrust, kMass, kIsp);
  // Gazzino 2018 (1.73a-d) at theta 63.64 deg, alpha 7.03 deg (Table 5.1),
  // evaluated here to 6 decimals: columns NE, SE, NW, SW; rows R, T, N.
  Eigen::Matrix<double, 3, 4> expected;
  expected << -0.889286, -0.889286, -0.889286, -0.889286,  //
      -0.109663, -0.109663, +0.109663, +0.109663,          //
      -0.444010, +0.444010, -0.444010, +0.444010;
  ASSERT_EQ(set.size(), 4);
  EXPECT_EQ(set.names(), (std::vector<std::string>{"NE", "SE", "NW", "SW"}));
  for (int i = 0; i < 4; ++i) {
    for (int r = 0; r < 3; ++r) {
      EXPECT_NEAR(set.thruster(i).direction[r], expected(r, i), 1e-6) << "thruster " << i;
    }
    EXPECT_NEAR(set.thruster(i).direction.lpNorm<1>(), 1.442959, 1e-6);
    EXPECT_NEAR(set.thruster(i).direction.norm(), 1.0, 1e-15);
    EXPECT_TRUE(set.thruster(i).enabled);
  }
}

TEST(ThrusterSetTest, AccelerationAndL1Factor) {
  const ThrusterSet set = ThrusterSet::Anzel4(kThrust, kMass, kIsp);
  // Gazzino 2018 (1.78)-(1.80) with Table 5.1: U_max = 0.265 / 4850 = 5.4639e-5 m/s^2.
  EXPECT_NEAR(set.acceleration(), 5.4639e-5, 1e-9);
  const Eigen::MatrixXd u = set.AccelerationMatrix();
  ASSERT_EQ(u.rows(), 3);
  ASSERT_EQ(u.cols(), 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(u.col(i).norm(), kThrust / kMass, 1e-18);
    EXPECT_NEAR(set.L1Factor(i), kThrust / kMass * 1.442959, 1e-10);
    EXPECT_NEAR(set.L1Factor(i), u.col(i).lpNorm<1>(), 1e-18);
  }
  // One day of burn in the L1 metric of Gazzino 2018 (1.96) is 6.812 m/s (derived here).
  EXPECT_NEAR(set.L1Factor(0) * 86400.0, 6.812, 1e-3);
  EXPECT_THROW(set.L1Factor(4), std::out_of_range);
  EXPECT_THROW(set.thruster(-1), std::out_of_range);
}

TEST(ThrusterSetTest, Anzel4OtherAngles) {
  // theta = 0: pure N/S thrust; alpha irrelevant.
  const ThrusterSet polar = ThrusterSet::Anzel4(kThrust, kMass, kIsp, 0.0, 30.0);
  EXPECT_NEAR(polar.thruster(0).direction[2], -1.0, 1e-15);
  EXPECT_NEAR(polar.thruster(1).direction[2], 1.0, 1e-15);
  // theta = 90, alpha = 0: all push toward the Earth (-R).
  const ThrusterSet radial = ThrusterSet::Anzel4(kThrust, kMass, kIsp, 90.0, 0.0);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(radial.thruster(i).direction[0], -1.0, 1e-15);
}

TEST(ThrusterSetTest, Ideal6OrderAndPreset) {
  const ThrusterSet set = ThrusterSet::FromPreset("ideal6", kThrust, kMass, kIsp);
  EXPECT_EQ(set.names(), (std::vector<std::string>{"+R", "+T", "+N", "-R", "-T", "-N"}));
  const Eigen::MatrixXd u = set.AccelerationMatrix() / set.acceleration();
  Eigen::MatrixXd expected(3, 6);
  expected << 1, 0, 0, -1, 0, 0,  //
      0, 1, 0, 0, -1, 0,          //
      0, 0, 1, 0, 0, -1;
  EXPECT_TRUE(u.isApprox(expected, 1e-15));
  for (int i = 0; i < 6; ++i) EXPECT_DOUBLE_EQ(set.L1Factor(i), kThrust / kMass);
  const ThrusterSet anzel = ThrusterSet::FromPreset("anzel4", kThrust, kMass, kIsp, 63.64, 7.03);
  EXPECT_EQ(anzel.size(), 4);
}

TEST(ThrusterSetTest, UnknownPresetNamesIt) {
  EXPECT_THAT([] { ThrusterSet::FromPreset("anzel5", kThrust, kMass, kIsp); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("'anzel5'")));
}

TEST(ThrusterSetTest, MassFlowUsesStandardGravity) {
  const ThrusterSet set = ThrusterSet::Ideal6(kThrust, kMass, kIsp);
  // F / (g0 Isp) = 0.265 / (9.80665 * 2005) kg/s.
  EXPECT_NEAR(set.MassFlow(), 1.3477546e-5, 1e-12);
  EXPECT_DOUBLE_EQ(set.MassFlow() * 9.80665 * kIsp, kThrust);
}

TEST(ThrusterSetTest, SubsetKeepsGivenOrderAndFlags) {
  ThrusterSet set = ThrusterSet::Anzel4(kThrust, kMass, kIsp);
  set.Disable({"NW"});
  const ThrusterSet sub = set.Subset({"SW", "NW", "NE"});
  EXPECT_EQ(sub.names(), (std::vector<std::string>{"SW", "NW", "NE"}));
  EXPECT_TRUE(sub.thruster(0).direction.isApprox(set.thruster(3).direction, 0.0));
  EXPECT_FALSE(sub.thruster(1).enabled);
  EXPECT_TRUE(sub.thruster(2).enabled);
  EXPECT_DOUBLE_EQ(sub.thrust_n(), kThrust);
  EXPECT_DOUBLE_EQ(sub.mass_kg(), kMass);
  EXPECT_DOUBLE_EQ(sub.isp_s(), kIsp);
  EXPECT_THAT(
      [&] {
        set.Subset({"NE", "XX"});
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("unknown thruster 'XX'")));
  EXPECT_THAT([&] { set.Subset({}); }, ThrowsMessage<std::invalid_argument>(HasSubstr("empty")));
  EXPECT_THAT(
      [&] {
        set.Subset({"NE", "NE"});
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("'NE' is repeated")));
}

TEST(ThrusterSetTest, DisableAndIndexOf) {
  ThrusterSet set = ThrusterSet::Anzel4(kThrust, kMass, kIsp);
  EXPECT_EQ(set.IndexOf("SE"), 1);
  EXPECT_EQ(set.IndexOf("SW"), 3);
  set.Disable({"SE", "SW"});
  EXPECT_TRUE(set.thruster(0).enabled);
  EXPECT_FALSE(set.thruster(1).enabled);
  EXPECT_FALSE(set.thruster(3).enabled);
  // Disabled thrusters stay in the acceleration matrix.
  EXPECT_GT(set.AccelerationMatrix().col(1).norm(), 0.0);
  EXPECT_THAT([&] { set.IndexOf("north"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("unknown thruster 'north'")));
  // All-or-nothing: an unknown name leaves the set unchanged.
  EXPECT_THAT(
      [&] {
        set.Disable({"NE", "bogus"});
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("'bogus'")));
  EXPECT_TRUE(set.thruster(0).enabled);
}

TEST(ThrusterSetTest, ConstructorNormalisesDirections) {
  const ThrusterSet set({{"a", Eigen::Vector3d(3, 4, 0), true}}, 1.0, 2.0, 300.0);
  EXPECT_TRUE(set.thruster(0).direction.isApprox(Eigen::Vector3d(0.6, 0.8, 0.0), 1e-15));
  EXPECT_DOUBLE_EQ(set.acceleration(), 0.5);
}

TEST(ThrusterSetTest, ConstructorRejectsBadInput) {
  const std::vector<Thruster> one = {{"a", Eigen::Vector3d(1, 0, 0), true}};
  EXPECT_THAT(
      [&] { ThrusterSet(one, 0.0, kMass, kIsp); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("thrust_n must be finite and > 0, got 0")));
  EXPECT_THAT([&] { ThrusterSet(one, -1.0, kMass, kIsp); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("thrust_n")));
  EXPECT_THAT(
      [&] { ThrusterSet(one, kThrust, -3.0, kIsp); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("mass_kg must be finite and > 0, got -3")));
  EXPECT_THAT([&] { ThrusterSet(one, kThrust, 0.0, kIsp); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("mass_kg")));
  EXPECT_THAT([&] { ThrusterSet(one, kThrust, std::nan(""), kIsp); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("mass_kg")));
  EXPECT_THAT([&] { ThrusterSet(one, kThrust, kMass, 0.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("isp_s")));
  EXPECT_THAT([&] { ThrusterSet(one, kThrust, kMass, INFINITY); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("isp_s")));
  EXPECT_THAT([&] { ThrusterSet({}, kThrust, kMass, kIsp); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("empty")));
  EXPECT_THAT(
      [&] {
        ThrusterSet({{"a", Eigen::Vector3d(1, 0, 0), true}, {"a", Eigen::Vector3d(0, 1, 0), true}},
                    kThrust, kMass, kIsp);
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("'a' is repeated")));
  EXPECT_THAT(
      [&] {
        ThrusterSet({{"z", Eigen::Vector3d::Zero(), true}}, kThrust, kMass, kIsp);
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("'z' has zero norm")));
  EXPECT_THAT(
      [&] {
        ThrusterSet({{"q", Eigen::Vector3d(NAN, 0, 1), true}}, kThrust, kMass, kIsp);
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("'q' is not finite")));
  EXPECT_THAT(
      [&] {
        ThrusterSet({{"", Eigen::Vector3d(1, 0, 0), true}}, kThrust, kMass, kIsp);
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("empty name")));
  EXPECT_THAT([] { ThrusterSet::Anzel4(kThrust, kMass, kIsp, NAN, 7.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("theta_deg")));
  EXPECT_THAT([] { ThrusterSet::Anzel4(kThrust, kMass, kIsp, 63.0, INFINITY); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("alpha_deg")));
  EXPECT_THAT([] { ThrusterSet::FromPreset("ideal6", kThrust, -1.0, kIsp); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("mass_kg")));
}

}  // namespace
}  // namespace thrustsched::dynamics
