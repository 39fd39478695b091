#include "dynamics/frames.h"

#include <cmath>

#include <gtest/gtest.h>

#include "dynamics/geo_model.h"
#include "dynamics/geo_orbit_state.h"
#include "dynamics/geo_simulator.h"

namespace thrustsched::dynamics {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kArcsec = kDeg / 3600.0;

// Off-diagonal elements to `tol`, diagonal ones (near 1) to 1e-15.
void ExpectMatrixNear(const Eigen::Matrix3d& got, const double (&want)[3][3], double tol) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(got(i, j), want[i][j], i == j ? 1e-15 : tol) << "(" << i << ", " << j << ")";
    }
  }
}

TEST(FramesTest, PrecessionMatchesTheErfaReferenceValues) {
  // ERFA t_erfa_c.c, t_pmat76: eraPmat76(2400000.5, 50123.9999) (TT).
  const double want[3][3] = {
      {0.9999995504328350733, 0.8696632209480960785e-3, 0.3779153474959888345e-3},
      {-0.8696632209485112192e-3, 0.9999996218428560614, -0.1643284776111886407e-6},
      {-0.3779153474950335077e-3, -0.1643306746147366896e-6, 0.9999999285899790119}};
  ExpectMatrixNear(PrecessionIau1976(2400000.5 + 50123.9999), want, 1e-14);
  // No precession at J2000.0.
  EXPECT_LT((PrecessionIau1976(kJulianDateJ2000) - Eigen::Matrix3d::Identity()).norm(), 1e-16);
}

TEST(FramesTest, FrameBiasMatchesTheErfaReferenceValues) {
  // ERFA t_erfa_c.c, t_bp00: the frame-bias matrix rb (epoch independent).
  const double want[3][3] = {
      {0.9999999999999942498, -0.7078279744199196626e-7, 0.8056217146976134152e-7},
      {0.7078279477857337206e-7, 0.9999999999999969484, 0.3306041454222136517e-7},
      {-0.8056217380986972157e-7, -0.3306040883980552500e-7, 0.9999999999999962084}};
  ExpectMatrixNear(FrameBiasIers2003(), want, 1e-16);
}

TEST(FramesTest, RoundTripsThroughTheModelFrame) {
  const Epoch epoch = Epoch::Parse("2034-01-01T00:00:00Z");
  Vector6d rv;
  rv << -32906.1e3, -26357.2e3, 12.3e3, 1921.4, -2399.1, 0.7;
  for (InertialFrame f : {InertialFrame::kEme2000, InertialFrame::kGcrf}) {
    const Vector6d back = FromModelFrame(ToModelFrame(rv, f, epoch), f, epoch);
    EXPECT_LT((back - rv).head<3>().norm(), 1e-15 * rv.head<3>().norm());
    EXPECT_LT((back - rv).tail<3>().norm(), 1e-15 * rv.tail<3>().norm());
  }
  // GCRF and EME2000 differ by the 23 mas frame bias: 4.7 m at the GEO radius.
  const double d = (ToModelFrame(rv, InertialFrame::kGcrf, epoch) -
                    ToModelFrame(rv, InertialFrame::kEme2000, epoch))
                       .head<3>()
                       .norm();
  EXPECT_GT(d, 1.0);
  EXPECT_LT(d, 5.0);
  EXPECT_EQ(ParseInertialFrame("J2000"), InertialFrame::kEme2000);
  EXPECT_EQ(ParseInertialFrame("GCRF"), InertialFrame::kGcrf);
  EXPECT_FALSE(ParseInertialFrame("ITRF2014").has_value());
  EXPECT_FALSE(ParseInertialFrame("TOD").has_value());
}

// Hand-computed case: the station point (118 deg E) at 2034-01-01T00:00:00Z.
// In the model frame it lies on the equator at right ascension
// a = GMST + 118 deg = 100.7225 + 118 = 218.7225 deg (GMST by the IAU 1982
// formula, time_test). Undoing the precession by hand,
// r_J2000 = R3(zeta) R2(-theta) R3(z) (cos a, sin a, 0), gives
//   delta_J2000 = asin(-sin(theta) cos(a - z)),
//   alpha_J2000 = atan2(sin(a - z), cos(theta) cos(a - z)) - zeta ~ a - z - zeta
// with the linear terms of the angles in T = 0.34 Julian centuries (zeta,
// z = 2306.2181" T, theta = 2004.3109" T; the T^2 terms and theta^2 are
// below 0.6"). Checked to 2" in right ascension (GMST is printed to
// 1e-4 deg) and 0.5" in declination.
TEST(FramesTest, StationPointInEme2000MatchesTheHandComputation) {
  GeoModelOptions opt;  // 118 E, 2034-01-01T00:00:00Z
  const GeoSimulator sim(opt);
  const OrbitState s =
      OrbitFromRelativeState(sim, Eigen::VectorXd::Zero(6), 0.0, InertialFrame::kEme2000);
  const Eigen::Vector3d r = s.rv.head<3>();
  EXPECT_NEAR(r.norm(), geo::kStationRadius, 1e-6);
  EXPECT_NEAR(s.rv.tail<3>().norm(), std::sqrt(geo::kEarthMu / geo::kStationRadius),
              1e-9);  // circular
  const double t =
      (Epoch::Parse("2034-01-01T00:00:00Z").JulianDateTt() - kJulianDateJ2000) / 36525.0;
  const double alpha = 218.7225 * kDeg;
  const double zeta = 2306.2181 * t * kArcsec, z = 2306.2181 * t * kArcsec,
               theta = 2004.3109 * t * kArcsec;
  double ra = std::atan2(r.y(), r.x());
  if (ra < 0) ra += 2 * 3.14159265358979323846;
  const double dec = std::asin(r.z() / r.norm());
  EXPECT_NEAR(ra, alpha - zeta - z, 2.0 * kArcsec);
  EXPECT_NEAR(dec, std::asin(-std::sin(theta) * std::cos(alpha - z)), 0.5 * kArcsec);
}

}  // namespace
}  // namespace thrustsched::dynamics
