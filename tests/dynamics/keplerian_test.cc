#include "dynamics/keplerian.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "dynamics/geo_model.h"

namespace thrustsched::dynamics {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kMu = geo::kEarthMu;

// Hand-computed: a = 42164 km, e = 0.1, i = 90 deg, W = 90 deg, w = 0,
// nu = 90 deg. Then r = p = a (1 - e^2) along the perifocal y axis, which for
// W = 90 deg, i = 90 deg is the inertial z axis; the velocity is
// sqrt(mu/p) (-sin nu P + (e + cos nu) Q) with P (the node) = inertial y and
// Q = inertial z: sqrt(mu/p) (0, -1, 0.1).
TEST(KeplerianTest, PolarOrbitMatchesTheHandComputation) {
  KeplerianElements k;
  k.a_m = 42164e3;
  k.e = 0.1;
  k.i_rad = 90 * kDeg;
  k.raan_rad = 90 * kDeg;
  k.arg_perigee_rad = 0;
  k.anomaly_rad = 90 * kDeg;
  const Vector6d rv = CartesianFromKeplerian(k, kMu);
  const double p = k.a_m * (1 - k.e * k.e);
  const double v = std::sqrt(kMu / p);
  EXPECT_NEAR(rv[0], 0.0, 1e-6);
  EXPECT_NEAR(rv[1], 0.0, 1e-6);
  EXPECT_NEAR(rv[2], p, 1e-6);
  EXPECT_NEAR(rv[3], 0.0, 1e-9);
  EXPECT_NEAR(rv[4], -v, 1e-9);
  EXPECT_NEAR(rv[5], 0.1 * v, 1e-9);
}

// Hand-computed with a mean anomaly: e = 0.1 and M = pi/2 - 0.1 give the
// eccentric anomaly E = pi/2 (Kepler: M = E - e sin E), r = a (1 - e cos E) = a
// and, in an equatorial orbit with W = w = 0, r = a (cos E - e, sqrt(1-e^2) sin E, 0).
TEST(KeplerianTest, MeanAnomalyMatchesTheHandComputation) {
  KeplerianElements k;
  k.a_m = 42164e3;
  k.e = 0.1;
  k.anomaly = AnomalyKind::kMean;
  k.anomaly_rad = kPi / 2 - 0.1;
  const Vector6d rv = CartesianFromKeplerian(k, kMu);
  EXPECT_NEAR(rv[0], -0.1 * k.a_m, 1e-6);
  EXPECT_NEAR(rv[1], std::sqrt(1 - 0.01) * k.a_m, 1e-6);
  EXPECT_NEAR(rv[2], 0.0, 1e-9);
  // True anomaly: cos(nu) = (cos E - e) / (1 - e cos E) = -0.1.
  EXPECT_NEAR(TrueFromMeanAnomaly(kPi / 2 - 0.1, 0.1), std::acos(-0.1), 1e-14);
  EXPECT_NEAR(MeanFromTrueAnomaly(std::acos(-0.1), 0.1), kPi / 2 - 0.1, 1e-14);
}

TEST(KeplerianTest, RoundTripsToCartesianAndBack) {
  // A near-GEO orbit (the use case) and an eccentric inclined one, both anomaly kinds.
  const KeplerianElements cases[] = {
      {42165.765e3, 2.1e-4, 0.031 * kDeg, 83.2 * kDeg, 211.7 * kDeg, 97.4 * kDeg,
       AnomalyKind::kTrue},
      {26560e3, 0.72, 63.4 * kDeg, 300.1 * kDeg, 270.0 * kDeg, 355.0 * kDeg, AnomalyKind::kMean},
  };
  for (const KeplerianElements& k : cases) {
    const Vector6d rv = CartesianFromKeplerian(k, kMu);
    const KeplerianElements b = KeplerianFromCartesian(rv, kMu, k.anomaly);
    EXPECT_NEAR(b.a_m, k.a_m, 1e-9 * k.a_m);
    EXPECT_NEAR(b.e, k.e, 1e-9 * k.e);
    EXPECT_NEAR(b.i_rad, k.i_rad, 1e-9 * k.i_rad);
    EXPECT_NEAR(b.raan_rad, k.raan_rad, 1e-9 * k.raan_rad);
    EXPECT_NEAR(b.arg_perigee_rad, k.arg_perigee_rad, 1e-9 * k.arg_perigee_rad);
    EXPECT_NEAR(b.anomaly_rad, k.anomaly_rad, 1e-9 * k.anomaly_rad);
    const Vector6d again = CartesianFromKeplerian(b, kMu);
    EXPECT_LT((again - rv).head<3>().norm(), 1e-9 * rv.head<3>().norm());
    EXPECT_LT((again - rv).tail<3>().norm(), 1e-9 * rv.tail<3>().norm());
  }
}

TEST(KeplerianTest, SingularAnglesFollowTheConvention) {
  // Equatorial circular orbit: node and perigee set to 0, the true longitude
  // W + w + nu kept in the anomaly.
  KeplerianElements k;
  k.a_m = 42165.765e3;
  k.raan_rad = 0.4;
  k.arg_perigee_rad = 0.5;
  k.anomaly_rad = 0.6;
  const KeplerianElements b =
      KeplerianFromCartesian(CartesianFromKeplerian(k, kMu), kMu, AnomalyKind::kTrue);
  EXPECT_EQ(b.raan_rad, 0.0);
  EXPECT_EQ(b.arg_perigee_rad, 0.0);
  EXPECT_NEAR(b.anomaly_rad, 1.5, 1e-12);
}

TEST(KeplerianTest, RejectsInvalidElements) {
  KeplerianElements k;
  k.a_m = 42164e3;
  k.e = 1.0;
  EXPECT_THROW(EquinoctialFromKeplerian(k), std::invalid_argument);
  k.e = 0.0;
  k.i_rad = kPi;
  EXPECT_THROW(EquinoctialFromKeplerian(k), std::invalid_argument);
  k.i_rad = 0.0;
  k.a_m = -1.0;
  EXPECT_THROW(EquinoctialFromKeplerian(k), std::invalid_argument);
  EXPECT_THROW(TrueFromMeanAnomaly(1.0, -0.1), std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::dynamics
