// Exact two-body (Kepler) motion, and the inertial meaning of the
// Yamanaka-Ankersen relative state: the nonlinear counterpart against which a
// linearised relative-motion plan is judged (e.g. Monte Carlo collision
// checks of an avoidance manoeuvre, Serra 2015 sec. 4.4).
//
//   dynamics::YamanakaAnkersenModel ya(41.38e6, 0.0119, dynamics::YamanakaAnkersenModel::kEarthMu);
//   dynamics::Vector6d ref = dynamics::ReferenceEci(ya, 0.0);          // reference orbit at t = 0
//   Eigen::VectorXd rel(6);  rel << 10, -2000, 5, 0, 0.01, 0;          // [x,y,z,vx,vy,vz], m, m/s
//   dynamics::Vector6d abs = dynamics::EciFromRelative(ya, rel, 0.0);  // inertial state
//   dynamics::KeplerOrbit orbit(abs, /*t0=*/0.0, ya.mu());
//   dynamics::Vector6d later = orbit.At(3600.0);                        // exact two-body
//
// Inertial frame of the YA reference: the perifocal frame of the reference
// orbit (x to the perigee, z along the angular momentum). The relative state
// is rectilinear: position r = r_ref + C rho with C = [u_R u_T u_N] (radial
// outward, along-track u_N x u_R, orbit normal), velocity v = v_ref +
// C (rho_dot + omega x rho) with omega = nu_dot u_N, nu_dot = h / r^2.
#ifndef THRUSTSCHED_DYNAMICS_TWO_BODY_H_
#define THRUSTSCHED_DYNAMICS_TWO_BODY_H_

#include <Eigen/Core>

#include "dynamics/models.h"
#include "dynamics/orbital_elements.h"

namespace thrustsched::dynamics {

/// An elliptic two-body orbit: the state at any time by Kepler's equation
/// (equinoctial elements of dynamics/orbital_elements.h, mean longitude
/// advanced by n (t - t0)). Position accuracy ~1e-15 of the radius.
class KeplerOrbit {
 public:
  /// @throws std::invalid_argument as EquinoctialFromCartesian (not an
  ///         ellipse, r x v = 0, non-finite values) or if t0 is not finite.
  KeplerOrbit(const Vector6d& eci, double t0, double mu);
  /// ECI state at t (any finite t, before or after t0).
  /// @throws std::invalid_argument if t is not finite.
  Vector6d At(double t) const;
  double mean_motion() const { return n_; }

 private:
  EquinoctialElements elements_;
  double t0_, mu_, n_;
};

/// Inertial state (perifocal frame, m, m/s) of the reference orbit of `model` at t.
Vector6d ReferenceEci(const YamanakaAnkersenModel& model, double t);
/// Columns u_R, u_T, u_N of the model's relative frame at t, in the perifocal frame.
Eigen::Matrix3d RelativeFrameBasis(const YamanakaAnkersenModel& model, double t);
/// Inertial state of the relative state x = [x, y, z, vx, vy, vz] (m, m/s) at t.
/// @throws std::invalid_argument if x is not a finite 6-vector or t is not finite.
Vector6d EciFromRelative(const YamanakaAnkersenModel& model, const Eigen::VectorXd& x, double t);
/// Relative state of an inertial state at t (inverse of EciFromRelative).
/// @throws std::invalid_argument if eci or t is not finite.
Eigen::VectorXd RelativeFromEci(const YamanakaAnkersenModel& model, const Vector6d& eci, double t);

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_TWO_BODY_H_
