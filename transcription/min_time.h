// Minimum time to a target set with on-off thrusters: the earliest grid node
// from which the state is in a box around a target (and, with `hold`, stays
// in it at every later node), by arrival indicator binaries (Richards & How
// 2002), then the least fuel among the schedules that arrive that early.
//
//   transcription::MinTimeSpec spec;
//   spec.target = Eigen::VectorXd::Zero(6);                  // model state units
//   spec.tolerance = Eigen::VectorXd::Constant(6, 1e-6);     // per component (inf: free)
//   transcription::MinTimeResult r =
//       transcription::SolveMinTime(problem, spec, *milp::MakeCbcSolver());
//   if (r.has_schedule()) use(r.arrival_time_s, r.schedule.burns);
//
// Formulation, on the sparse transcription of `problem`, whose grid is the
// latest arrival considered (Richards & How 2002): arrival binaries a_j
// (node j, j = 1..N), sum_j a_j = 1, g_j = a_j (reach) or a_1 + ... + a_j
// (hold); for each component c with a finite tolerance,
//   target_c - tol_c - L_jc (1 - g_j) <= x_jc <= target_c + tol_c + U_jc (1 - g_j),
// U_jc, L_jc the excess over the box of the range of x_jc reachable with
// every slot free in [0, 1] (the rules left out: a safe big-M); objective
// sum_j (t_j - t_0) a_j. A node from which the box is out of reach whatever
// fires gets a_j = 0.
// Then (minimise_fuel_after) the least fuel (problem.objective) arriving
// by that node, from the schedule found. The problem's own terminal set
// still applies at t_N; the fuel budget is a row on problem.objective; the
// operational rules, the window and the forced-off slots hold throughout.
//
// Contract: an arrival is reported only after the checker re-propagated the
// schedule with the continuous model (CheckSchedule) and the state at the
// arrival node (and at every later node with `hold`) is within tolerance
// (arrival_error, scaled by the model's state scale, below 1e-6); the
// arrival bound is the first MILP's proven bound, never a heuristic's.
#ifndef THRUSTSCHED_TRANSCRIPTION_MIN_TIME_H_
#define THRUSTSCHED_TRANSCRIPTION_MIN_TIME_H_

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "milp/solver.h"
#include "transcription/checker.h"
#include "transcription/problem.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"

namespace thrustsched::transcription {

struct MinTimeSpec {
  Eigen::VectorXd target;     // model state units (m, m/s, rad)
  Eigen::VectorXd tolerance;  // >= 0 per component; +inf leaves the component free
  /// Once reached, the box holds at every later grid node (a rendezvous that
  /// stays); false: reaching it at one node is enough (a fly-by).
  bool hold = true;
  /// Largest fuel of the schedule, in problem.objective's units (+inf: none).
  double fuel_budget = std::numeric_limits<double>::infinity();
  /// Then the least fuel among the earliest arrivals (a second MILP).
  bool minimise_fuel_after = true;

  /// Sizes match the problem's state, tolerances >= 0 (inf allowed) and at
  /// least one finite, the target finite, the budget > 0; on-off mode.
  /// On failure `*error` (if given) names the field and the value.
  bool IsValid(const ScheduleProblem& problem, std::string* error) const;
};

struct MinTimeResult {
  /// The first MILP's (objective: seconds). Its status is time_status:
  /// kOptimal, the earliest arrival is proven (arrival_bound_s equals it);
  /// kFeasible, an arrival with a lower bound below it (a limit stopped the
  /// MILP); kInfeasible, no arrival by t_N; kNoSolutionFound; kError.
  milp::SolveResult time_solve;
  milp::SolveStatus time_status = milp::SolveStatus::kError;
  std::optional<milp::SolveResult> fuel_solve;  // the least fuel at that arrival, if run
  /// Earliest arrival found: node index and seconds since grid.front()
  /// (-1 and NaN without a schedule).
  int arrival_node = -1;
  double arrival_time_s = std::numeric_limits<double>::quiet_NaN();
  /// Proven lower bound on the arrival (s since grid.front()): equal to
  /// arrival_time_s when stage 1 was proven optimal.
  double arrival_bound_s = std::numeric_limits<double>::quiet_NaN();
  /// problem.objective's value (its units: m/s or kg) at the schedule
  /// returned, whichever MILP found it (NaN without a schedule).
  double fuel = std::numeric_limits<double>::quiet_NaN();
  Schedule schedule;  // of stage 2 if it found one, else stage 1's
  CheckReport check;
  /// Re-propagated state's largest scaled excess over the tolerance at the
  /// arrival node (and every later node with hold); 0 inside.
  double arrival_error = std::numeric_limits<double>::quiet_NaN();
  /// Nodes at which arrival is possible at all (the rest fixed a_j = 0),
  /// indicator rows, and the big-M range (in scaled state units).
  int candidate_nodes = 0;
  int indicator_rows = 0;
  double big_m_max = 0.0;
  BuildStats stats;  // of the schedule MILP, before the arrival columns and rows
  std::vector<std::string> infeasibility_reasons;

  bool has_schedule() const { return arrival_node >= 0; }
  /// The checker passed and the re-propagated state meets the target.
  bool verified() const;
};

/// options.build (the formulation is always sparse), options.milp (both
/// MILPs; the time limit counts from the call) and options.check are used;
/// the schedule is always checked; the search is not used (its bounds
/// assume a fuel objective).
/// @throws std::invalid_argument if !problem.IsValid(), !spec.IsValid() or
///         the options are invalid (messages name the field).
MinTimeResult SolveMinTime(const ScheduleProblem& problem, const MinTimeSpec& spec,
                           const milp::Solver& solver, const SolveScheduleOptions& options = {});

/// The first MILP (arrival time in seconds as its objective), as
/// SolveMinTime builds it, for export (MPS, LP): the schedule MILP of
/// `problem` in the sparse formulation, the fuel budget row, the arrival
/// columns a_j (`arrive_at_<j>`), g_j (`arrived_by_<j>`) and their rows.
/// @throws std::invalid_argument as SolveMinTime.
milp::LpData MinTimeArrivalLp(const ScheduleProblem& problem, const MinTimeSpec& spec,
                              const BuildOptions& options = {});

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_MIN_TIME_H_
