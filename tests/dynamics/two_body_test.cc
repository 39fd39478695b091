// Exact two-body motion and the inertial meaning of the Yamanaka-Ankersen
// relative state: Kepler's period, the round trip relative -> inertial ->
// relative, and the defining property of the linearisation: for a relative
// offset of size d the nonlinear motion differs from the Yamanaka-Ankersen
// transition matrix by O(d^2), i.e. by 4x less when d is halved.
#include <cmath>

#include <gtest/gtest.h>

#include "dynamics/two_body.h"

namespace thrustsched::dynamics {
namespace {

// The reference orbit of Serra 2015 ch. 4 Example 1 (n = 7.4996e-5 rad/s, e = 0.0119).
YamanakaAnkersenModel SerraGeo() {
  const double n = 7.4996e-5;
  const double a = std::cbrt(YamanakaAnkersenModel::kEarthMu / (n * n));
  return YamanakaAnkersenModel(a, 0.0119, YamanakaAnkersenModel::kEarthMu, -0.6258);
}

TEST(KeplerOrbitTest, ReturnsAfterOnePeriod) {
  const YamanakaAnkersenModel ya = SerraGeo();
  const Vector6d x0 = ReferenceEci(ya, 0.0);
  const KeplerOrbit orbit(x0, 0.0, ya.mu());
  EXPECT_NEAR(orbit.mean_motion(), ya.mean_motion(), 1e-15);
  EXPECT_LT((orbit.At(ya.period()) - x0).head<3>().norm(), 1e-5);
  // The reference orbit itself is a Kepler orbit: same state at any time.
  for (double t : {-30000.0, 1234.5, 50000.0}) {
    EXPECT_LT((orbit.At(t) - ReferenceEci(ya, t)).head<3>().norm(), 1e-5) << t;
    EXPECT_LT((orbit.At(t) - ReferenceEci(ya, t)).tail<3>().norm(), 1e-9) << t;
  }
}

TEST(TwoBodyTest, RelativeRoundTrip) {
  const YamanakaAnkersenModel ya = SerraGeo();
  Eigen::VectorXd x(6);
  x << 388.0, -2295.0, 4.0, 0.02, 0.05, -2e-4;
  for (double t : {-50000.0, 0.0, 7000.0}) {
    const Eigen::VectorXd back = RelativeFromEci(ya, EciFromRelative(ya, x, t), t);
    EXPECT_LT((back - x).head<3>().norm(), 1e-6) << t;
    EXPECT_LT((back - x).tail<3>().norm(), 1e-12) << t;
  }
  // The frame: x radial outward, y along the velocity's transverse part, z normal.
  const Eigen::Matrix3d c = RelativeFrameBasis(ya, 0.0);
  EXPECT_NEAR((c.transpose() * c - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-14);
  EXPECT_GT(c.col(1).dot(ReferenceEci(ya, 0.0).tail<3>()), 0.0);
  EXPECT_NEAR(c.col(2).z(), 1.0, 1e-15);
}

double LinearizationError(const YamanakaAnkersenModel& ya, double scale, double t) {
  Eigen::VectorXd x0(6);
  x0 << 0.3, -1.0, 0.4, 2e-5, -1e-5, 3e-5;
  x0 *= scale;
  const KeplerOrbit orbit(EciFromRelative(ya, x0, 0.0), 0.0, ya.mu());
  const Eigen::VectorXd nonlinear = RelativeFromEci(ya, orbit.At(t), t);
  const Eigen::VectorXd linear = ya.TransitionMatrix(t, 0.0) * x0;
  return (nonlinear - linear).head<3>().norm();
}

TEST(TwoBodyTest, YamanakaAnkersenIsTheFirstOrder) {
  const YamanakaAnkersenModel ya = SerraGeo();
  const double t = 0.6 * ya.period();
  const double e1 = LinearizationError(ya, 2000.0, t);  // ~2 km offsets
  const double e2 = LinearizationError(ya, 1000.0, t);
  EXPECT_LT(e1, 5.0);  // m, against km of relative motion
  EXPECT_NEAR(e1 / e2, 4.0, 0.2);
}

TEST(TwoBodyTest, RejectsBadInput) {
  const YamanakaAnkersenModel ya = SerraGeo();
  EXPECT_THROW(EciFromRelative(ya, Eigen::VectorXd::Zero(5), 0.0), std::invalid_argument);
  EXPECT_THROW(ReferenceEci(ya, NAN), std::invalid_argument);
  Vector6d parallel;
  parallel << 7e6, 0, 0, 1e3, 0, 0;
  EXPECT_THROW(KeplerOrbit(parallel, 0.0, ya.mu()), std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::dynamics
