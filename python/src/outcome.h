// Solve and check results of the Python bindings: one code path for
// scenarios (app::Scenario, the CLI's outputs), problems built from numpy
// arrays and schedule MILPs the user modified.
//
//   ProblemContext ctx = ScenarioContext(scenario);
//   std::shared_ptr<SolveOutcome> r = SolveAndCheck(ctx, [&] { return BuildMilp(ctx); },
//                                                   options, /*check=*/true, job);
//   std::string csv = r->checked.ScheduleCsv();     // schedule.csv's text
//
// Scenario problems give exactly the CLI's results: the same build, solve
// (SolveBuilt, or SolveConjunction with a conjunction), checker (with the
// CLI's fallback when the nonlinear replay fails), verdict (app::Judge) and
// files' contents (summary.json, schedule.csv, trajectory.csv as text).
// Array problems have no continuous-time model: their check is the
// operational rules in continuous time (transcription::CheckOperationalRules)
// and the user's discrete model propagated through the on-off pattern, with
// the window judged at the grid nodes (DiscreteCheck).
#ifndef THRUSTSCHED_PYTHON_OUTCOME_H_
#define THRUSTSCHED_PYTHON_OUTCOME_H_

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "app/scenario.h"
#include "dynamics/discretisation.h"
#include "runner.h"
#include "transcription/checker.h"
#include "transcription/conjunction_check.h"
#include "transcription/conjunction_solve.h"
#include "transcription/problem.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"

namespace thrustsched::python {

/// What a problem is, for the results made from it.
struct ProblemContext {
  /// From a scenario (null for array problems).
  std::shared_ptr<const app::Scenario> scenario;
  /// Always set (the scenario's problem for scenario problems).
  std::shared_ptr<const transcription::ScheduleProblem> problem;
  /// Array problems: the user's discretisation (Phi, Gamma, drift).
  std::shared_ptr<const dynamics::DiscreteModel> discrete;
  /// Array problems: names of the model's states and outputs.
  std::vector<std::string> state_names, output_names;

  std::vector<std::string> thruster_names() const { return problem->thrusters.names(); }
  bool impulsive() const { return problem->input_mode == transcription::InputMode::kImpulsive; }
};

ProblemContext ScenarioContext(std::shared_ptr<const app::Scenario> scenario);

/// The check of an array problem's schedule (see the file comment).
struct DiscreteCheck {
  bool operational_ok = true;
  std::vector<transcription::RuleViolation> rule_violations;
  double max_window_violation_at_nodes = 0.0;  // output units
  double worst_time_s = 0.0;
  int worst_output = -1;
  bool terminal_ok = true;
  double terminal_error = 0.0;  // max |x_N - target| / tolerance (box), or / state scale (fixed)
  std::vector<Eigen::VectorXd> states;   // at grid nodes
  std::vector<Eigen::VectorXd> outputs;  // at grid nodes
  std::vector<std::string> findings;     // empty iff passed
  bool passed() const { return findings.empty(); }
};
/// @throws std::invalid_argument for a burn of an unknown thruster.
DiscreteCheck CheckDiscrete(const transcription::ScheduleProblem& problem,
                            const dynamics::DiscreteModel& discrete,
                            const std::vector<transcription::Burn>& burns);

/// A schedule and its check.
struct CheckedSchedule {
  ProblemContext ctx;
  std::vector<transcription::Burn> burns;        // on-off mode
  std::vector<transcription::Impulse> impulses;  // impulsive mode
  bool checked = false;
  transcription::CheckReport report;              // scenario, on-off
  transcription::ImpulsiveCheck impulsive_check;  // scenario, impulsive
  std::optional<DiscreteCheck> discrete;          // array problems
  std::optional<transcription::ConjunctionCheckReport> conjunction;
  std::string nonlinear_error;  // the nonlinear replay failed (linear check kept)
  double check_seconds = 0.0;

  /// The checker's verdict as summary.json's "check" object (JSON text).
  std::string CheckJson() const;
  /// schedule.csv (or impulses.csv in impulsive mode) as text.
  std::string ScheduleCsv() const;
  /// trajectory.csv as text (array problems: one row per grid node).
  std::string TrajectoryCsv() const;
};

/// Runs the checker (scenario problems: as the CLI's `check`; arrays: CheckDiscrete).
void RunCheck(CheckedSchedule* c);

struct SolveOutcome {
  transcription::ScheduleResult result;
  std::shared_ptr<CheckedSchedule> checked =
      std::make_shared<CheckedSchedule>();  // burns, impulses, check
  bool interrupted = false;
  double total_seconds = 0.0;
  std::string summary_json;  // summary.json's content (scenario problems) or its subset
  Eigen::VectorXd x;         // the MILP's column values (empty without a solution)
};

/// Options of SolveAndCheck.
struct SolveRequest {
  transcription::SolveScheduleOptions options;  // interrupt/progress set by SolveAndCheck
  bool check = true;
  /// Scenario problems with a conjunction section: budget rounds.
  std::optional<transcription::ConjunctionSolveOptions> conjunction;
};

/// Builds (in the worker: discretisation and build are part of the work),
/// solves, decodes and checks, with the job's stop flag and progress events.
std::shared_ptr<SolveOutcome> SolveAndCheck(
    const ProblemContext& ctx,
    std::function<std::shared_ptr<const transcription::ScheduleMilp>()> build, SolveRequest request,
    const std::shared_ptr<Job>& job, py::object callback);

}  // namespace thrustsched::python

#endif  // THRUSTSCHED_PYTHON_OUTCOME_H_
