// Concrete LinearModel implementations with closed-form references:
//
//   DoubleIntegrator1d     x'' = a                       (toy benchmark, Serra §5.2)
//   DoubleIntegrator3d     r'' = a, r in R^3
//   HcwModel               Hill-Clohessy-Wiltshire, circular reference orbit
//   YamanakaAnkersenModel  linearised relative motion about an elliptic orbit
//
// All use the same Cartesian relative state, SI units:
//   [x, y, z, vx, vy, vz]  (m, m/s)   x radial (outward), y along-track,
//                                     z orbit normal (angular momentum);
// velocities are time derivatives in the rotating frame; the 3 inputs are the
// thrust acceleration in the local RTN frame (m/s^2), i.e. a_R, a_T, a_N act on
// vx, vy, vz directly; outputs are the positions [x, y, z] (m).
//
//   dynamics::HcwModel hcw(7.2921159e-5);                   // GEO mean motion, rad/s
//   Eigen::Matrix<double, 6, 6> phi = hcw.TransitionMatrix(300.0);
//   Eigen::Matrix<double, 6, 3> g = hcw.ZohInputMatrix(300.0);  // x1 = phi x0 + g a
//
//   dynamics::YamanakaAnkersenModel ya(/*semi_major_axis_m=*/12e6, /*eccentricity=*/0.3);
//   Eigen::Matrix<double, 6, 6> phi_e = ya.TransitionMatrix(/*t=*/9000.0, /*t0=*/0.0);
//
// Scales (LinearModel::state_scale/time_scale): orbital models use time 1/n and
// a length L (constructor parameter, default 1 km) with velocities L n, so that
// the nondimensional A has entries of order one.
#ifndef THRUSTSCHED_DYNAMICS_MODELS_H_
#define THRUSTSCHED_DYNAMICS_MODELS_H_

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "dynamics/linear_model.h"

namespace thrustsched::dynamics {

/// x' = v, v' = a. State [x_m, v_m_s], input a (m/s^2), output [x_m].
class DoubleIntegrator1d final : public LinearModel {
 public:
  /// time_scale_s: characteristic time (s); length_scale_m: characteristic
  /// position (m); the velocity scale is length / time.
  /// @throws std::invalid_argument if a scale is not finite and > 0.
  explicit DoubleIntegrator1d(double time_scale_s = 1.0, double length_scale_m = 1.0);

  std::string_view name() const override { return "double_integrator_1d"; }
  int num_states() const override { return 2; }
  int num_inputs() const override { return 1; }
  int num_outputs() const override { return 1; }
  bool is_time_invariant() const override { return true; }
  ModelMatrices Evaluate(double t) const override;
  OutputMatrices EvaluateOutput(double t) const override;
  std::vector<std::string> state_names() const override;
  std::vector<std::string> output_names() const override;
  Eigen::VectorXd state_scale() const override;
  double time_scale() const override { return time_scale_s_; }

 private:
  double time_scale_s_, length_scale_m_;
};

/// r' = v, v' = a in R^3. State [x,y,z,vx,vy,vz] (m, m/s), inputs [ax,ay,az]
/// (m/s^2), outputs [x,y,z] (m).
class DoubleIntegrator3d final : public LinearModel {
 public:
  /// @throws std::invalid_argument if a scale is not finite and > 0.
  explicit DoubleIntegrator3d(double time_scale_s = 1.0, double length_scale_m = 1.0);

  std::string_view name() const override { return "double_integrator_3d"; }
  int num_states() const override { return 6; }
  int num_inputs() const override { return 3; }
  int num_outputs() const override { return 3; }
  bool is_time_invariant() const override { return true; }
  ModelMatrices Evaluate(double t) const override;
  OutputMatrices EvaluateOutput(double t) const override;
  std::vector<std::string> state_names() const override;
  std::vector<std::string> output_names() const override;
  Eigen::VectorXd state_scale() const override;
  double time_scale() const override { return time_scale_s_; }

 private:
  double time_scale_s_, length_scale_m_;
};

/// Hill-Clohessy-Wiltshire relative motion about a circular orbit of mean
/// motion n (thesis (I.3)):
///   x'' = 3 n^2 x + 2 n y' + a_R,   y'' = -2 n x' + a_T,   z'' = -n^2 z + a_N.
class HcwModel final : public LinearModel {
 public:
  /// @throws std::invalid_argument if mean_motion_rad_s or length_scale_m is
  ///         not finite and > 0.
  explicit HcwModel(double mean_motion_rad_s, double length_scale_m = 1000.0);

  std::string_view name() const override { return "hcw"; }
  int num_states() const override { return 6; }
  int num_inputs() const override { return 3; }
  int num_outputs() const override { return 3; }
  bool is_time_invariant() const override { return true; }
  ModelMatrices Evaluate(double t) const override;
  OutputMatrices EvaluateOutput(double t) const override;
  std::vector<std::string> state_names() const override;
  std::vector<std::string> output_names() const override;
  Eigen::VectorXd state_scale() const override;
  double time_scale() const override { return 1.0 / n_; }

  double mean_motion() const { return n_; }
  /// Phi(tau) = exp(A tau), Gazzino 2018 eq. (I.4) with entry (5,1) corrected
  /// to 6 n (cos n tau - 1). Any finite tau (negative = backward).
  /// Cancellation-free for small n tau. @throws std::invalid_argument if tau
  /// is not finite.
  Eigen::Matrix<double, 6, 6> TransitionMatrix(double tau) const;
  /// Integral over [0, tau] of Phi(tau - s) B ds (6 x 3, s^2 on positions, s
  /// on velocities): the response to a constant RTN acceleration held for tau.
  /// @throws std::invalid_argument if tau is not finite.
  Eigen::Matrix<double, 6, 3> ZohInputMatrix(double tau) const;

 private:
  double n_, length_scale_m_;
};

/// Linearised Keplerian relative motion about an elliptic reference orbit
/// (Tschauner-Hempel in the time domain), in the same x = radial, y =
/// along-track, z = orbit-normal rotating frame as HcwModel:
///   x'' =  (w^2 + 2k) x + w' y + 2 w y' + a_R
///   y'' = -w' x + (w^2 - k) y - 2 w x' + a_T
///   z'' = -k z + a_N
/// with w = nu' (true-anomaly rate), w' = nu'', k = mu / r^3 of the reference
/// orbit at time t. For e = 0 this is HcwModel exactly.
/// Time t = 0 is the epoch, where the reference true anomaly is
/// `true_anomaly_at_epoch_rad` (0 = perigee).
class YamanakaAnkersenModel final : public LinearModel {
 public:
  static constexpr double kEarthMu = 3.986004418e14;  // m^3/s^2

  /// @throws std::invalid_argument if semi_major_axis_m, mu_m3_s2 or
  ///         length_scale_m is not finite and > 0, eccentricity is not in
  ///         [0, 0.99] or the true anomaly is not finite.
  YamanakaAnkersenModel(double semi_major_axis_m, double eccentricity, double mu_m3_s2 = kEarthMu,
                        double true_anomaly_at_epoch_rad = 0.0, double length_scale_m = 1000.0);

  std::string_view name() const override { return "yamanaka_ankersen"; }
  int num_states() const override { return 6; }
  int num_inputs() const override { return 3; }
  int num_outputs() const override { return 3; }
  bool is_time_invariant() const override { return false; }
  ModelMatrices Evaluate(double t) const override;
  OutputMatrices EvaluateOutput(double t) const override;
  std::vector<std::string> state_names() const override;
  std::vector<std::string> output_names() const override;
  Eigen::VectorXd state_scale() const override;
  double time_scale() const override { return 1.0 / n_; }

  double semi_major_axis() const { return a_; }
  double eccentricity() const { return e_; }
  double mu() const { return mu_; }
  /// Mean motion sqrt(mu / a^3), rad/s.
  double mean_motion() const { return n_; }
  double period() const;

  /// Eccentric anomaly E solving E - e sin E = M (safeguarded Newton, any
  /// finite M, 0 <= e < 1); E - M is in [-e, e].
  /// @throws std::invalid_argument if M is not finite or e is not in [0, 1).
  static double SolveKepler(double mean_anomaly_rad, double eccentricity);
  /// Continuous (unwrapped) true anomaly of the reference at time t (s):
  /// increases by 2 pi per orbit. @throws std::invalid_argument if t is not finite.
  double TrueAnomalyAt(double t) const;
  /// Inverse of TrueAnomalyAt for an unwrapped true anomaly.
  /// @throws std::invalid_argument if nu is not finite.
  double TimeAtTrueAnomaly(double nu_rad) const;

  /// Closed-form Yamanaka-Ankersen transition matrix Phi(t, t0) (6 x 6) of
  /// the state above. @throws std::invalid_argument if t or t0 is not finite.
  Eigen::Matrix<double, 6, 6> TransitionMatrix(double t, double t0) const;
  /// Same, parameterised by the unwrapped true anomalies nu (at t) and nu0
  /// (at t0); the elapsed time comes from Kepler's equation.
  Eigen::Matrix<double, 6, 6> TransitionMatrixFromTrueAnomaly(double nu_rad, double nu0_rad) const;

 private:
  Eigen::Matrix<double, 6, 6> TransitionMatrixImpl(double nu, double nu0, double dt) const;

  double a_, e_, mu_, nu_epoch_, length_scale_m_;
  double n_;                   // mean motion, rad/s
  double p_;                   // semi-latus rectum, m
  double mean_anomaly_epoch_;  // unwrapped mean anomaly at t = 0, rad
};

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_MODELS_H_
