#include "dynamics/geo_orbit_state.h"

#include <cmath>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dynamics/geo_model.h"

namespace thrustsched::dynamics {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// Relative error with the model's state scale as the floor (dl, ex, ... are
// small numbers: their relative error is measured against 0.05 deg).
double RelativeError(const Eigen::VectorXd& got, const Eigen::VectorXd& want,
                     const Eigen::VectorXd& scale) {
  double worst = 0;
  for (int i = 0; i < want.size(); ++i) {
    worst = std::max(worst, std::abs(got(i) - want(i)) / std::max(std::abs(want(i)), scale(i)));
  }
  return worst;
}

TEST(GeoOrbitStateTest, RoundTripsThroughBothExchangeFrames) {
  GeoModelOptions opt;
  const GeoSimulator sim(opt);
  const Eigen::VectorXd scale = GeoLinearModel(opt).state_scale();
  Eigen::VectorXd x(6);
  x << 1234.5, 1.7e-4, -0.9e-4, 2.6e-4, -3.1e-4, 6.1e-4;
  for (InertialFrame f : {InertialFrame::kEme2000, InertialFrame::kGcrf}) {
    for (double t : {0.0, 86400.0 * 3.25}) {
      const OrbitState s = OrbitFromRelativeState(sim, x, t, f);
      EXPECT_EQ(s.frame, f);
      EXPECT_NEAR(s.epoch.SecondsSince(Epoch::Parse(opt.epoch)), t, 1e-6);
      const Eigen::VectorXd back = RelativeStateFromOrbit(sim, s, t);
      EXPECT_LT(RelativeError(back, x, scale), 1e-9) << "frame " << ToString(f) << " t " << t;
    }
  }
}

TEST(GeoOrbitStateTest, EarlierStatesArePropagatedToTheRequestedTime) {
  GeoModelOptions opt;
  const GeoSimulator sim(opt);
  Eigen::VectorXd x(6);
  x << 300.0, 1e-4, 0.0, 2e-4, 0.0, 1e-3;
  // The state 2 h before the epoch, in EME2000 ...
  const OrbitState before = OrbitFromRelativeState(sim, x, -7200.0, InertialFrame::kEme2000);
  // ... gives at t = 0 what the simulator itself gives after 2 h of free motion.
  const Vector6d eci = sim.Propagate(sim.EciFromRelative(x, -7200.0), -7200.0,
                                     Eigen::MatrixXd::Zero(3, 1), {}, {0.0})
                           .front();
  const Eigen::VectorXd want = sim.RelativeFromEci(eci, 0.0);
  const Eigen::VectorXd got = RelativeStateFromOrbit(sim, before, 0.0);
  EXPECT_LT(RelativeError(got, want, GeoLinearModel(opt).state_scale()), 1e-9);
  EXPECT_GT(std::abs(got(5) - x(5)), 1e-6);  // it did move
  // Never backward.
  EXPECT_THAT([&] { RelativeStateFromOrbit(sim, before, -7300.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("after the requested time")));
}

}  // namespace
}  // namespace thrustsched::dynamics
