// A GEO satellite's state as other tools give it (an inertial position and
// velocity at a UTC epoch, in EME2000 or GCRF) and its conversion to and from
// the relative equinoctial state of the GEO models at a model time.
//
//   dynamics::GeoSimulator sim(options);             // station, epoch, forces
//   dynamics::OrbitState s{dynamics::Epoch::Parse("2033-12-31T21:30:00Z"),
//                          dynamics::InertialFrame::kEme2000, rv_m};
//   Eigen::VectorXd x = dynamics::RelativeStateFromOrbit(sim, s, 0.0);   // at t = 0
//   dynamics::OrbitState back = dynamics::OrbitFromRelativeState(sim, x, 0.0,
//                                                                dynamics::InertialFrame::kEme2000);
//
// The chain: rotate to the model frame MOE(t0) (dynamics/frames.h); if the
// state's epoch is before the requested model time, propagate it there with
// the nonlinear model (natural forces, no thrust); take the osculating
// equinoctial elements minus the station point (GeoSimulator::RelativeFromEci).
// Model time of an epoch = UTC seconds since the model epoch, on the uniform
// clock of dynamics/time.h.
#ifndef THRUSTSCHED_DYNAMICS_GEO_ORBIT_STATE_H_
#define THRUSTSCHED_DYNAMICS_GEO_ORBIT_STATE_H_

#include <Eigen/Core>

#include "dynamics/frames.h"
#include "dynamics/geo_simulator.h"
#include "dynamics/time.h"

namespace thrustsched::dynamics {

struct OrbitState {
  Epoch epoch;  // UTC
  InertialFrame frame = InertialFrame::kEme2000;
  Vector6d rv = Vector6d::Zero();  // m, m/s
};

/// Relative state x = [da_m, ex, ey, ix, iy, dl_rad] at model time t of the
/// orbit `state`, propagated forward from its epoch if that is earlier.
/// @throws std::invalid_argument if the state's epoch is after t (the
///         simulator only propagates forward), or the orbit is not an ellipse;
///         std::runtime_error if the propagation fails.
Eigen::VectorXd RelativeStateFromOrbit(const GeoSimulator& sim, const OrbitState& state, double t);
/// The inertial state in `frame` at model time t of the relative state x.
/// @throws std::invalid_argument as GeoSimulator::EciFromRelative.
OrbitState OrbitFromRelativeState(const GeoSimulator& sim, const Eigen::VectorXd& x, double t,
                                  InertialFrame frame);

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_GEO_ORBIT_STATE_H_
