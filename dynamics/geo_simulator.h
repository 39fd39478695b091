// Nonlinear GEO simulation model: the judge of every station-keeping
// schedule (the "simulation model" of Gazzino 2018, eqs. (1.40), (B.53)). Cowell
// propagation of the ECI position and velocity under all enabled natural
// forces plus on/off thrust in the satellite's own RTN frame.
//
//   dynamics::GeoSimulator sim(dynamics::GeoModelOptions{});
//   dynamics::Vector6d x0 = sim.EciFromRelative(Eigen::VectorXd::Zero(6), 0.0);  // station point
//   auto thr = dynamics::ThrusterSet::Anzel4(0.265, 4850, 2005);
//   std::vector<dynamics::InputPulse> pulses = {{0, 3600.0, 4500.0}};  // NE on 15 min
//   std::vector<dynamics::Vector6d> xs =
//       sim.Propagate(x0, 0.0, thr.AccelerationMatrix(), pulses, {0.0, 86400.0});
//   Eigen::Vector3d y = sim.RelativeOutputs(xs[1], 86400.0);   // [dr_m, dlat_rad, dlon_rad]
//
// Everything needed to re-propagate a schedule with other tools:
//
// TIME. t is SI seconds elapsed since the model epoch (GeoModelOptions::epoch,
//   a UTC instant). No leap second is inserted during a run:
//   JD_TT(t) = JD_UTC(epoch) + (TAI-UTC(epoch) + 32.184 s + t) / 86400 (TAI-UTC = 37 s in
//   2034, see dynamics/time.h) for the ephemerides; UT1 = UTC at the epoch for Theta.
//   (The chain, the leap-second table's validity and the exchange frames EME2000
//   and GCRF: data/scenarios/README.md, section 10.)
//
// INERTIAL FRAME. Mean equator and mean equinox of the epoch ("mean of epoch",
//   MOE(t0)): a fixed (inertial) frame equal to the mean-of-date frame at
//   t = 0. Precession and nutation of the Earth's axis during the run are
//   neglected: the Earth's rotation axis is the frame's z axis for the whole
//   run (the real pole moves ~20"/yr).
//
// EARTH ROTATION. Theta(t) = GMST(epoch) + omega_E t, omega_E = 7.2921158553e-5 rad/s,
//   GMST by the IAU 1982 formula of dynamics/time.h (GmstRad; 100.7225 deg at
//   2034-01-01T00:00:00Z). Earth-fixed coordinates: r_EF = R3(-Theta) r_ECI
//   (active rotation about z). Geographic coordinates are geocentric on a
//   spherical Earth: r = |r|, lat = asin(z/r), lon = atan2(y, x) - Theta(t)
//   (east, wrapped to (-pi, pi]). (omega_E is the GMST rate; relative to a
//   truly inertial frame Earth turns 7e-12 rad/s slower, i.e. 46"/yr: a model
//   convention, consistent between the linear model, the simulator and the
//   geopotential.)
//
// FORCES (SI), each switchable in GeoModelOptions. Gazzino 2018 (sec. 1.2.2)
//   names them but gives no model; these are standard ones (Montenbruck &
//   Gill 2000, ch. 3):
//   central: mu_E = 3.986004418e14 m^3/s^2.
//   geopotential: EGM2008 normalised C_nm, S_nm to degree and order
//     gravity_degree (<= 4), R_E = 6378137 m, evaluated in the Earth-fixed frame
//     above (Cunningham recursion); `j2` = zonal terms (m = 0), `tesseral` = m >= 1.
//   Sun, Moon: point masses mu_S = 1.32712440018e20, mu_M = 4.902800066e12 m^3/s^2,
//     a = mu_b ((r_b - r)/|r_b - r|^3 - r_b/|r_b|^3), positions from the
//     Montenbruck-Gill low-precision "of date" series (dynamics/ephemerides.h)
//     referred to the MOE(t0) frame (general precession since t0 removed,
//     obliquity of t0).
//   SRP: a = -P C_r (A/m) (AU/|d|)^2 d/|d|, d = r_sun - r, P = 4.56e-6 N/m^2,
//     AU = 1.495978707e11 m; zero inside the cylindrical shadow
//     (r.s < 0 and |r - (r.s) s| < R_E, s = r_sun/|r_sun|); no penumbra.
//   thrust: column i of accel_rtn (m/s^2) while a pulse of input i is on,
//     rotated from the satellite's instantaneous RTN frame (u_R = r/|r|,
//     u_N = (r x v)/|r x v|, u_T = u_N x u_R) to ECI. Constant mass.
//
// INTEGRATION. Runge-Kutta-Fehlberg 7(8) (Boost.Odeint) with step-size
//   control on the state scaled by (a_mp, a_mp omega_E), absolute and relative
//   tolerance `tolerance` (default 1e-12), steps <= 1800 s, stopped and
//   restarted exactly at every pulse start/end and sample time. The shadow
//   boundary is an event: the SRP on/off state is frozen during a step, the
//   shadow function is checked at the end and at 4 interior points of every
//   step (so eclipses longer than 6 min are never stepped over) and crossings
//   are located by bisection to 1e-4 s (RKF78's error estimate cannot see a
//   discontinuity inside a step). Accuracy: Kepler orbit 0.4 m after 60 days;
//   full model 1e-12 vs 1e-14 differ by ~7 m after one year of free drift.
//   Cost ~0.4 ms per simulated day (daily samples), ~1.7 ms per day with
//   5-min samples (geo_benchmark).
//
// STATE CONVERSIONS. The relative state is that of GeoLinearModel:
//   osculating equinoctial elements (mu_E, exact conversions of
//   dynamics/orbital_elements.h) minus the station point, with
//   dl = M_Q - Theta(t) - l_mp wrapped to (-pi, pi].
#ifndef THRUSTSCHED_DYNAMICS_GEO_SIMULATOR_H_
#define THRUSTSCHED_DYNAMICS_GEO_SIMULATOR_H_

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "dynamics/geo_model.h"
#include "dynamics/orbital_elements.h"
#include "dynamics/propagation.h"

namespace thrustsched::dynamics {

/// Geographic (geocentric, spherical Earth) coordinates; lon east.
struct GeoPoint {
  double r_m;
  double lat_rad;
  double lon_rad;
};

/// The nonlinear judge; const methods are thread-safe.
class GeoSimulator {
 public:
  static constexpr double kDefaultTolerance = 1e-12;

  /// @throws std::invalid_argument with the GeoModelOptions::IsValid message,
  ///         or if tolerance is not in [1e-14, 1e-10].
  explicit GeoSimulator(const GeoModelOptions& options, double tolerance = kDefaultTolerance);

  const GeoModelOptions& options() const;
  double tolerance() const { return tolerance_; }
  /// Theta(t) = GMST(epoch) + omega_E t in [0, 2 pi). @throws if t is not finite.
  double EarthRotationAngle(double t) const;

  /// ECI state (m, m/s) of the relative state x_rel (GeoLinearModel's) at t.
  /// @throws std::invalid_argument if x_rel is not a finite 6-vector, a <= 0,
  ///         e >= 1 or t is not finite.
  Vector6d EciFromRelative(const Eigen::VectorXd& x_rel, double t) const;
  /// Relative state of an ECI state at t (same state as GeoLinearModel).
  /// @throws std::invalid_argument if eci or t is not finite, or the orbit is
  ///         not an ellipse or is retrograde equatorial.
  Eigen::VectorXd RelativeFromEci(const Vector6d& eci, double t) const;
  /// Exact geographic coordinates. @throws std::invalid_argument on non-finite
  ///         input or r = 0.
  GeoPoint Geographic(const Vector6d& eci, double t) const;
  /// [r - a_mp (m), lat (rad), lon - l_mp (rad, wrapped to (-pi, pi])]: the
  /// exact counterpart of GeoLinearModel's outputs C(t) x. @throws as Geographic.
  Eigen::Vector3d RelativeOutputs(const Vector6d& eci, double t) const;
  /// Sum of the enabled natural accelerations except the central term (m/s^2,
  /// ECI) at ECI position r and time t. @throws on non-finite input.
  Eigen::Vector3d PerturbingAcceleration(const Eigen::Vector3d& r_eci, double t) const;

  /// Cowell propagation with all enabled forces plus thrust: input column i of accel_rtn (3 x m,
  /// m/s^2, expressed in the satellite's own RTN frame at each instant) is on during its pulses
  /// (overlapping pulses add; parts before t0 are ignored). Restarted exactly at every pulse
  /// start/end. Returns the ECI state at each sample time (non-decreasing, >= t0).
  /// @throws std::invalid_argument if eci0, t0, accel_rtn or a pulse/sample time is not finite,
  ///         accel_rtn does not have 3 rows, a pulse has end < start or a column outside
  ///         [0, m), or the sample times are decreasing or before t0;
  ///         std::runtime_error if the step-size control fails (e.g. the orbit hits the Earth).
  std::vector<Vector6d> Propagate(const Vector6d& eci0, double t0, const Eigen::MatrixXd& accel_rtn,
                                  const std::vector<InputPulse>& pulses,
                                  const std::vector<double>& sample_times) const;

 private:
  std::shared_ptr<const internal::GeoForceModel> forces_;
  double tolerance_;
};

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_GEO_SIMULATOR_H_
