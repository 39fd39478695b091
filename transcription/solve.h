// One call from a problem to a verified schedule: discretise, build, solve,
// decode, check.
//
//   auto solver = milp::MakeCbcSolver();
//   transcription::SolveScheduleOptions opt;
//   opt.milp.time_limit_s = 60;
//   transcription::ScheduleResult r = transcription::SolveSchedule(problem, *solver, opt);
//   if (r.has_schedule()) {
//     std::cout << r.schedule.consumption_l1_m_s << " m/s, window violation "
//               << r.check.max_window_violation << "\n";
//   }
//
// The solver's word alone is not evidence: unless disabled, every schedule
// goes through CheckSchedule (operational rules in continuous time, linear
// re-propagation between nodes, nonlinear replay for GEO when requested).
#ifndef THRUSTSCHED_TRANSCRIPTION_SOLVE_H_
#define THRUSTSCHED_TRANSCRIPTION_SOLVE_H_

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "milp/solver.h"
#include "transcription/checker.h"
#include "transcription/problem.h"
#include "transcription/schedule_milp.h"
#include "transcription/search.h"

namespace thrustsched::transcription {

struct SolveScheduleOptions {
  BuildOptions build;
  milp::SolveOptions milp;
  /// On-off mode: the problem-aware search (search.h) unless disabled; then
  /// the whole MILP goes to the solver.
  SearchOptions search;
  CheckOptions check;
  bool check_schedule = true;
  /// Optional MIP start (on-off mode): a burn list, e.g. the previous cycle's
  /// schedule shifted, or a heuristic.
  std::vector<Burn> warm_start;
  /// Infeasibility diagnosis, after a solve that stopped at its time limit
  /// with no schedule and no proof (on-off mode, hard window): the first
  /// 1/32, 1/8 and 1/2 of the horizon are solved alone, each with a burn
  /// allowed to run past its end and no terminal constraint. Every schedule
  /// of the whole problem restricted to such a prefix is feasible for it, so
  /// an infeasible prefix proves the whole problem infeasible (status
  /// kInfeasible, the reason in infeasibility_reasons). It spends at most
  /// this many seconds (0: off), inside milp.time_limit_s: see
  /// ShareTimeLimit. Not after an interrupt.
  double prefix_diagnosis_s = 30.0;
  /// The largest fraction of a finite milp.time_limit_s kept for the
  /// diagnosis when it may run (ShareTimeLimit); in [0, 1).
  double diagnosis_share = 0.25;
  /// Called (from the calling thread) when a phase after the solve starts,
  /// with a sentence saying what it does and how long it may take (e.g. the
  /// infeasibility diagnosis), so that a user is told why the work goes on.
  std::function<void(const std::string&)> announce;

  /// build and milp are valid, search when it is enabled and check when
  /// check_schedule is set (neither is read otherwise). prefix_diagnosis_s
  /// takes any value (<= 0 or NaN: off); diagnosis_share is in [0, 1). On
  /// failure `*error` (if given) names the field and the value.
  bool IsValid(std::string* error) const;
};

/// A time limit shared between the solve and the infeasibility diagnosis.
struct TimeLimitShares {
  double solve_s = std::numeric_limits<double>::infinity();
  double diagnosis_s = 0.0;
};

/// The time limit bounds the solve and the diagnosis together: with a
/// diagnosis of at most `diagnosis_cap_s` (<= 0 or NaN: none) the solve
/// stops at time_limit_s minus min(diagnosis_cap_s, diagnosis_share *
/// time_limit_s), which is kept for the diagnosis. An infinite limit is not
/// shared (the solve has no limit, the diagnosis its cap).
///   ShareTimeLimit(5, 30, 0.25)  -> {3.75, 1.25}
///   ShareTimeLimit(600, 30, 0.25) -> {570, 30}
TimeLimitShares ShareTimeLimit(double time_limit_s, double diagnosis_cap_s, double diagnosis_share);

/// The diagnosis's limit once the solve has used `used_s` of time_limit_s:
/// what is left of the limit, at most diagnosis_cap_s, never below 0 (so a
/// solve that stopped early, e.g. on a node limit, leaves the diagnosis more
/// than its share). DiagnosisTimeLeft(5, 30, 3.8) -> 1.2.
double DiagnosisTimeLeft(double time_limit_s, double diagnosis_cap_s, double used_s);

/// Check of an impulsive schedule: impulses applied to the continuous model
/// (adaptive propagation between nodes), window at nodes, terminal error.
struct ImpulsiveCheck {
  double max_window_violation = 0.0;
  double terminal_error = 0.0;  // max |x_N+ - target| / state_scale (fixed/box kinds)
  Eigen::VectorXd final_state;
};
ImpulsiveCheck CheckImpulses(const ScheduleProblem& problem, const std::vector<Impulse>& impulses);

struct ScheduleResult {
  BuildStats stats;
  milp::SolveResult solve;
  Schedule schedule;  // valid if has_schedule()
  bool checked = false;
  CheckReport check;               // on-off mode
  ImpulsiveCheck impulsive_check;  // impulsive mode
  double check_seconds = 0.0;
  double diagnosis_seconds = 0.0;  // the infeasibility diagnosis (0 if it did not run)
  /// The limits the solve and the diagnosis were given (ShareTimeLimit,
  /// DiagnosisTimeLeft): their sum is at most milp.time_limit_s.
  /// diagnosis_time_limit_s is its share when it did not run, 0 when it
  /// could not (impulsive, soft or no window, prefix_diagnosis_s off).
  double solve_time_limit_s = std::numeric_limits<double>::infinity();
  double diagnosis_time_limit_s = 0.0;
  SearchReport search;  // what the search did (on-off mode, search enabled)
  std::vector<std::string> infeasibility_reasons;  // from the rules, known before solving
  bool has_schedule() const { return solve.has_solution(); }
};

/// @throws std::invalid_argument if !problem.IsValid() or the options are invalid.
ScheduleResult SolveSchedule(const ScheduleProblem& problem, const milp::Solver& solver,
                             const SolveScheduleOptions& options = {});

/// Same, on an already built transcription (e.g. to solve one model with
/// several solvers or options).
ScheduleResult SolveBuilt(const ScheduleMilp& milp, const milp::Solver& solver,
                          const SolveScheduleOptions& options = {});

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SOLVE_H_
