// Continuous-time propagation of a LinearModel under an on-off input schedule,
// by adaptive high-order integration restarted exactly at every switch time.
// This is what checkers use to judge a schedule between and at grid nodes.
//
//   std::vector<dynamics::InputPulse> pulses = {{/*column=*/1, 0.0, 300.0}};
//   std::vector<Eigen::VectorXd> xs = dynamics::PropagateLinear(
//       model, thrusters.AccelerationMatrix(), x0, /*t0=*/0.0, pulses,
//       /*sample_times=*/{0, 600, 1200});
#ifndef THRUSTSCHED_DYNAMICS_PROPAGATION_H_
#define THRUSTSCHED_DYNAMICS_PROPAGATION_H_

#include <vector>

#include <Eigen/Core>

#include "dynamics/linear_model.h"

namespace thrustsched::dynamics {

/// Input column `column` is on (value 1) on [start_s, end_s).
struct InputPulse {
  int column;
  double start_s;
  double end_s;
};

/// Integrates x' = A x + B U p(t) + d from x(t0) = x0, p_i(t) = sum of the
/// pulses of column i (pulses may overlap; the part of a pulse before t0 is
/// ignored; a pulse with end == start does nothing), and returns x at each
/// sample time (non-decreasing, >= t0; a sample equal to t0 returns x0).
/// Integration: adaptive Runge-Kutta-Fehlberg 7(8), restarted at every switch
/// and sample time, absolute and relative tolerance `tolerance` on the
/// nondimensional state (x / model.state_scale(), time / model.time_scale()).
/// @throws std::invalid_argument on non-finite data (t0, x0, input_columns,
///         pulse or sample times, or model matrices), x0 or input_columns of
///         the wrong size, a pulse with end < start or an unknown column,
///         unsorted samples or samples before t0, or a tolerance not in
///         (0, 1e-3].
/// @throws std::runtime_error if the integration cannot meet the tolerance
///         (step size underflow, e.g. a tolerance far below 1e-15).
std::vector<Eigen::VectorXd> PropagateLinear(const LinearModel& model,
                                             const Eigen::MatrixXd& input_columns,
                                             const Eigen::VectorXd& x0, double t0,
                                             const std::vector<InputPulse>& pulses,
                                             const std::vector<double>& sample_times,
                                             double tolerance = 1e-11);

/// The flow of the unforced model from t0: x(t) = phi(t, t0) x(t0) + drift(t)
/// at each sample time (drift: the response of a zero state to d).
struct LinearFlow {
  std::vector<Eigen::MatrixXd> phi;
  std::vector<Eigen::VectorXd> drift;
};

/// phi and drift by PropagateLinear of the zero state and of the n unit
/// states (what a Monte Carlo of the initial state, or a covariance carried
/// along a plan, needs). @throws as PropagateLinear.
LinearFlow PropagateFlow(const LinearModel& model, double t0,
                         const std::vector<double>& sample_times, double tolerance = 1e-11);

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_PROPAGATION_H_
