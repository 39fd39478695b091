// The independent schedule checker. It shares no code with the MILP builder:
// it reads the problem definition and a list of burns (from our solver, from
// another solver via an exported MPS file, or written by hand) and judges them
//  - against the operational rules in continuous time (operations.h);
//  - by re-propagating the continuous-time linear model through the burns
//    with adaptive integration (dynamics::PropagateLinear), at every grid node
//    and `samples_per_interval` points inside each interval, and measuring the
//    window violation;
//  - for GEO problems, optionally through the nonlinear simulation model
//    (dynamics::GeoSimulator) as well.
//
//   transcription::CheckOptions opt;
//   opt.samples_per_interval = 4;
//   transcription::CheckReport r = transcription::CheckSchedule(problem, burns, opt);
//   if (!r.operational_ok) for (auto& v : r.rule_violations) std::cerr << v.message << "\n";
//   std::cout << r.max_window_violation << " at t = " << r.worst_time_s << "\n";
#ifndef THRUSTSCHED_TRANSCRIPTION_CHECKER_H_
#define THRUSTSCHED_TRANSCRIPTION_CHECKER_H_

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "transcription/operations.h"
#include "transcription/problem.h"

namespace thrustsched::dynamics {
class GeoSimulator;
}

namespace thrustsched::transcription {

/// Checks only the operational rules (1)-(7) of operations.h, in continuous
/// time, for burns inside the horizon [t0, tf]. Also reports burns outside
/// the horizon, of unknown thrusters, with end <= start, or overlapping
/// burns of the same thruster. Sorted by time.
std::vector<RuleViolation> CheckOperationalRules(const OperationalRules& rules,
                                                 const BoundaryHistory& history,
                                                 const std::vector<ForcedOff>& forced_off,
                                                 int num_thrusters, double t0, double tf,
                                                 const std::vector<Burn>& burns);

/// Fixed-state and state-box terminal constraints hold when their scaled
/// error (TerminalError) is at most this (state-scale units).
inline constexpr double kTerminalTolerance = 1e-6;
/// Station-keeping terminal sets hold when the final state's excess over
/// the exact sets (relative to their half widths) is at most this: the
/// re-propagated final state differs from the MILP's discrete one by the
/// discretisation scheme's error.
inline constexpr double kStationKeepingSetTolerance = 1e-3;

/// The scaled terminal error of `final_state`: max over components of the
/// deviation from terminal.target (kFixedState) or its excess over
/// terminal.tolerance (kStateBox; 0 for an infinite tolerance), divided by
/// `state_scale`; 0 for the other kinds.
double TerminalError(const TerminalSpec& terminal, const Eigen::VectorXd& final_state,
                     const Eigen::VectorXd& state_scale);

struct CheckOptions {
  int samples_per_interval = 4;  // propagation samples strictly inside each interval
  double propagation_tolerance = 1e-11;
  /// GEO only: also replay through this nonlinear model (~0.1-1 s per week).
  std::shared_ptr<const dynamics::GeoSimulator> nonlinear;
  /// GEO only, when `nonlinear` is null: replay through a GeoSimulator made
  /// from the problem's GeoLinearModel options (same station, epoch and
  /// forces), so every GEO schedule is judged by the nonlinear model unless
  /// this is switched off.
  bool nonlinear_default = true;

  /// samples_per_interval >= 0; propagation_tolerance finite and > 0. On
  /// failure `*error` (if given) names the field and the value.
  bool IsValid(std::string* error) const;
};

struct CheckReport {
  bool operational_ok = true;
  std::vector<RuleViolation> rule_violations;

  // Linear re-propagation (continuous model, adaptive, through the burns).
  // Window violation = max over constrained outputs and sample times with
  // t >= enforce_from_s of (|y_k| - half_width_k), in the output's unit
  // (m or rad), 0 if inside. Nodes and inter-sample points both count.
  double max_window_violation = 0.0;
  double max_window_violation_at_nodes = 0.0;
  double worst_time_s = std::numeric_limits<double>::quiet_NaN();
  int worst_output = -1;
  Eigen::VectorXd final_state;                  // x(t_N) of the re-propagation
  std::vector<double> sample_times;             // all sample times
  std::vector<Eigen::VectorXd> sample_outputs;  // all model outputs at sample_times
  std::vector<Eigen::VectorXd> sample_states;

  // Nonlinear replay (GEO, if requested): window violation in degrees on
  // latitude/longitude relative to the station point, and the replay itself.
  bool nonlinear_checked = false;
  double max_window_violation_nonlinear_deg = std::numeric_limits<double>::quiet_NaN();
  double worst_time_nonlinear_s = std::numeric_limits<double>::quiet_NaN();
  double max_abs_lat_deg = std::numeric_limits<double>::quiet_NaN();
  double max_abs_lon_deg = std::numeric_limits<double>::quiet_NaN();
  double time_outside_window_nonlinear_s = 0.0;            // sampled estimate
  std::vector<Eigen::Matrix<double, 6, 1>> nonlinear_eci;  // at sample_times
  std::vector<Eigen::Vector3d> nonlinear_outputs;          // [dr_m, dlat_rad, dlon_rad]

  /// Path constraints (ScheduleProblem::state_constraints) on the linear
  /// re-propagation: the largest excess of a^T x(t) beyond its bounds, in the
  /// constraint's own unit (0 if all hold), and which one (-1: none).
  double max_state_constraint_violation = 0.0;
  int worst_state_constraint = -1;

  /// Terminal constraint satisfied by the re-propagated final state (fixed or
  /// box terminal kinds; true for free or polytope kinds) within tolerance.
  bool terminal_ok = true;
  double terminal_error = 0.0;

  std::string Summary() const;  // one line per finding
};

/// Full check. @throws std::invalid_argument if !problem.IsValid().
CheckReport CheckSchedule(const ScheduleProblem& problem, const std::vector<Burn>& burns,
                          const CheckOptions& options = {});

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_CHECKER_H_
