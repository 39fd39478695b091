#include "transfer/replay.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "common/constants.h"
#include "dynamics/two_body.h"

namespace thrustsched::transfer {
namespace {

// Without thrust the replay is Kepler's motion (dynamics::KeplerOrbit, by
// Kepler's equation) and the mass stays.
TEST(ReplayTest, CoastIsKeplersMotion) {
  const MinTimeProblem p = CaillauGtoProblem(1.0);
  const double t = 30 * 3600.0;
  const ReplayResult r = Replay(
      p, t, [](double, const dynamics::Vector6d&, double) { return Eigen::Vector3d::Zero(); });
  const dynamics::KeplerOrbit orbit(CartesianFromEquinoctial(p.initial, p.mu), 0.0, p.mu);
  const dynamics::Vector6d ref = orbit.At(t);
  EXPECT_LT((r.final_rv.head<3>() - ref.head<3>()).norm(), 1e-3);  // m
  EXPECT_LT((r.final_rv.tail<3>() - ref.tail<3>()).norm(), 1e-6);  // m/s
  EXPECT_EQ(r.final_mass_kg, p.mass_kg);
  EXPECT_NEAR(r.final_a_m, SemiMajorAxis(p.initial), 1e-3);
}

// Along the velocity of a circular orbit at low thrust the orbit stays
// nearly circular and its speed falls by the rocket equation's
// delta-v (v_c0 - v_c1 = g0 Isp ln(m0/m1) to first order in the thrust).
TEST(ReplayTest, TangentialThrustSpiralMatchesTheRocketEquation) {
  MinTimeProblem p;
  p.initial = Equinoctial{7000e3, 0, 0, 0, 0, 0};
  p.target = TargetElements::Circular(8000e3);
  p.mass_kg = 1000, p.thrust_n = 0.1, p.isp_s = 1500;
  const double t = 20 * 86400.0;
  const ReplayResult r = Replay(
      p, t, [](double, const dynamics::Vector6d&, double) { return Eigen::Vector3d(0, 1, 0); });
  const double c = common::kStandardGravity_m_s2 * p.isp_s;
  EXPECT_NEAR(r.final_mass_kg, p.mass_kg - p.thrust_n * t / c, 1e-9);
  const double dv = c * std::log(p.mass_kg / r.final_mass_kg);
  const double vc0 = std::sqrt(p.mu / 7000e3), vc1 = std::sqrt(p.mu / r.final_a_m);
  EXPECT_NEAR(vc0 - vc1, dv, 2e-3 * dv);
  EXPECT_LT(r.final_e, 2e-3);
}

TEST(ReplayTest, BadInputThrows) {
  const MinTimeProblem p = CaillauGtoProblem(1.0);
  EXPECT_THROW(Replay(p, -1, nullptr), std::invalid_argument);
  EXPECT_THROW(SampledCommand({}), std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::transfer
