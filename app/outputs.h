// Result files of the thrustsched CLI (formats documented in
// data/scenarios/README.md, "Output directory"): summary.json,
// schedule.csv / impulses.csv, trajectory.csv, and the checker verdict.
//
//   app::CheckVerdict v = app::Judge(scenario, report);      // pass/fail + findings
//   app::WriteScheduleCsv(dir + "/schedule.csv", scenario, schedule.burns);
//   app::WriteTrajectoryCsv(dir + "/trajectory.csv", scenario, report);
//   std::vector<transcription::Burn> burns = app::ReadScheduleCsv("other.csv", scenario);
//
// Units: times in seconds since the model epoch (the grid's clock), windows in
// the scenario's window unit (m for Cartesian models, deg for GEO).
#ifndef THRUSTSCHED_APP_OUTPUTS_H_
#define THRUSTSCHED_APP_OUTPUTS_H_

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/geo_products.h"
#include "app/scenario.h"
#include "transcription/checker.h"
#include "transcription/conjunction_check.h"
#include "transcription/conjunction_solve.h"
#include "transcription/min_time.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"

namespace thrustsched::app {

/// Pass/fail of a checked schedule and the reasons, one line each.
struct CheckVerdict {
  bool passed = false;
  std::vector<std::string> findings;  // empty when passed
};

/// On-off schedules: passes iff the operational rules hold, the terminal
/// constraint holds (checker tolerance), and the window violation (at grid
/// nodes; at every sample if verdict.include_intersample; also the nonlinear
/// replay if verdict.include_nonlinear) is <= verdict.window_tolerance.
CheckVerdict Judge(const Scenario& scenario, const transcription::CheckReport& report);
/// Impulsive schedules: window at nodes <= tolerance and terminal error
/// (state-scale units) <= transcription::kTerminalTolerance.
CheckVerdict JudgeImpulsive(const Scenario& scenario, const transcription::ImpulsiveCheck& check);

/// The scenario's checker on burns (its CheckOptions); a failing nonlinear
/// replay (e.g. the orbit leaves the model's validity) is reported in
/// `*nonlinear_error` and the linear check kept: the check of `solve`,
/// `check` and the Python package.
transcription::CheckReport CheckWithLinearFallback(const Scenario& scenario,
                                                   const std::vector<transcription::Burn>& burns,
                                                   std::string* nonlinear_error);

/// Sets j["rule_violations"] (the messages) and j["rule_violation_details"]
/// (rule, thruster name or null, time_s, message), as in the "check" object.
void AddRuleViolations(const std::vector<transcription::RuleViolation>& violations,
                       const std::vector<std::string>& thruster_names, nlohmann::json* j);

/// The "check" object of summary.json (and of check.json).
nlohmann::json CheckJson(const Scenario& scenario, const transcription::CheckReport& report,
                         const CheckVerdict& verdict, double check_seconds);
nlohmann::json ImpulsiveCheckJson(const Scenario& scenario,
                                  const transcription::ImpulsiveCheck& check,
                                  const CheckVerdict& verdict, double check_seconds);

/// Extra facts of a solve run that the library result does not hold.
struct RunFacts {
  bool interrupted = false;    // SIGINT stopped the solve
  double total_seconds = 0.0;  // whole command, wall clock
  std::string command_line;
  /// The nonlinear replay failed (CheckWithLinearFallback): check.nonlinear_error.
  std::string nonlinear_error;
  /// Scenarios with a conjunction: the budget rounds (null: solved without
  /// them) and the plan's verification (null: no schedule).
  const transcription::ConjunctionSolve* conjunction_solve = nullptr;
  const transcription::ConjunctionCheckReport* conjunction_check = nullptr;
  /// Scenarios with "objective": "min_time": the minimum-time solve (null:
  /// none ran, e.g. a schedule read back by import-solution).
  const transcription::MinTimeResult* min_time = nullptr;
};

/// summary.json content (field list in the README), the one writer of the
/// CLI's `solve` and the Python package. `result.checked` decides whether a
/// "check" object is included (null otherwise); scenarios with a
/// conjunction get its "conjunction" object.
nlohmann::json SummaryJson(const Scenario& scenario, const transcription::ScheduleMilp& milp,
                           const transcription::ScheduleResult& result, const RunFacts& facts);

/// summary.json's "burns": {thruster (name), start_s, duration_s, end_s} per burn.
nlohmann::json BurnsJson(const std::vector<transcription::Burn>& burns,
                         const std::vector<std::string>& thruster_names);

/// The fields of summary.json that need no scenario (status, objective,
/// bound, gap, nodes, consumption, burns, model size, times, incumbents,
/// infeasibility reasons): SummaryJson's start, and the whole summary of
/// the Python package's problems from arrays. `thruster_names` name the
/// burns' thrusters.
nlohmann::json SolveResultJson(const transcription::ScheduleResult& result,
                               const std::vector<std::string>& thruster_names,
                               transcription::ObjectiveKind objective_kind, bool interrupted,
                               double total_seconds);

/// Status name used in summary.json: optimal, feasible, infeasible, unbounded,
/// no_solution, error.
std::string StatusName(milp::SolveStatus status);

/// `v` as a JSON number, or null when it is not finite (JSON has no NaN or
/// infinity): the rule of every JSON file the CLI writes.
nlohmann::json FiniteOrNull(double v);

/// @throws std::runtime_error naming the path on I/O failure.
void WriteTextFile(const std::string& path, const std::string& text);
void WriteJsonFile(const std::string& path, const nlohmann::json& json);
/// Writes `lp` as free MPS (a name ending in .mps, any case) or CPLEX LP
/// (.lp): the one model-file writer of the CLI's `export`/`--export-*` and of
/// Python's `milp.write`.
/// @throws std::invalid_argument naming the path if the name ends in neither;
/// std::runtime_error naming the path on I/O failure.
void WriteModelFile(const std::string& path, const milp::LpData& lp, bool obfuscate_names);

/// Header "thruster,start_s,end_s,duration_s", one row per burn. GEO
/// scenarios append "start_utc,end_utc,dir_r,dir_t,dir_n,delta_v_m_s" (UTC
/// times, the thruster's RTN direction, the delta-v delivered on the
/// nonlinear replay: app/geo_products.h) computed from `replay` (the
/// scenario's own initial state at the horizon start if null).
void WriteScheduleCsv(const std::string& path, const Scenario& scenario,
                      const std::vector<transcription::Burn>& burns,
                      const ReplayLeg* replay = nullptr);
/// The text WriteScheduleCsv writes (for callers that keep it in memory,
/// e.g. the Python package's DataFrames).
std::string ScheduleCsvText(const Scenario& scenario, const std::vector<transcription::Burn>& burns,
                            const ReplayLeg* replay = nullptr);
/// Header "thruster,node,time_s,delta_v_m_s", one row per impulse (impulsive mode).
void WriteImpulsesCsv(const std::string& path, const Scenario& scenario,
                      const std::vector<transcription::Impulse>& impulses);
/// The text WriteImpulsesCsv writes.
std::string ImpulsesCsvText(const Scenario& scenario,
                            const std::vector<transcription::Impulse>& impulses);

/// Reads a schedule written by WriteScheduleCsv or by hand (duration_s and
/// the GEO columns optional; blank lines and lines starting with '#' ignored).
/// @throws ScenarioError naming the file, line and field on a bad header, an
/// unknown thruster, a non-finite time, end < start, a duration that
/// disagrees with end - start, or a start_utc/end_utc that is not the UTC
/// label of start_s/end_s (to 1 ms).
std::vector<transcription::Burn> ReadScheduleCsv(const std::string& path, const Scenario& scenario);
/// Reads impulses.csv. The node must be a grid node index; time_s, if not
/// empty, must equal the node's time. @throws ScenarioError as ReadScheduleCsv.
std::vector<transcription::Impulse> ReadImpulsesCsv(const std::string& path,
                                                    const Scenario& scenario);
/// ReadScheduleCsv and ReadImpulsesCsv of text already read; `source`
/// names it in messages.
std::vector<transcription::Burn> ParseScheduleCsv(std::string_view text, const std::string& source,
                                                  const Scenario& scenario);
std::vector<transcription::Impulse> ParseImpulsesCsv(std::string_view text,
                                                     const std::string& source,
                                                     const Scenario& scenario);

/// Columns of trajectory.csv for the scenario (see the README).
std::vector<std::string> TrajectoryColumns(const Scenario& scenario, bool with_nonlinear);
/// One row per checker sample (grid nodes and inner samples): linear
/// re-propagation, and for GEO the nonlinear replay when it was run.
/// `burns` give the on_<thruster> columns.
void WriteTrajectoryCsv(const std::string& path, const Scenario& scenario,
                        const transcription::CheckReport& report,
                        const std::vector<transcription::Burn>& burns);
/// The text WriteTrajectoryCsv writes.
std::string TrajectoryCsvText(const Scenario& scenario, const transcription::CheckReport& report,
                              const std::vector<transcription::Burn>& burns);
/// Impulsive mode: free motion between nodes with the impulses applied at the
/// nodes, `samples_per_interval` inner samples per interval.
void WriteImpulsiveTrajectoryCsv(const std::string& path, const Scenario& scenario,
                                 const std::vector<transcription::Impulse>& impulses);
/// The text WriteImpulsiveTrajectoryCsv writes.
std::string ImpulsiveTrajectoryCsvText(const Scenario& scenario,
                                       const std::vector<transcription::Impulse>& impulses);

/// The thesis drift term 2x + vy/n (m) of an HCW state (Table 4.1), NaN for
/// other models.
double HcwDriftTerm(const Scenario& scenario, const Eigen::VectorXd& state);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_OUTPUTS_H_
