// Scenario files: one JSON file describes a complete scheduling problem
// (model, spacecraft and thrusters, initial state, horizon, window,
// operational rules, objective, discretisation, solver and checker settings).
// Every field is documented in data/scenarios/README.md.
//
//   app::Scenario s = app::LoadScenario("data/scenarios/geo_week_anzel4.json");
//   transcription::ScheduleMilp milp(s.problem, s.build);
//   milp::SolveResult r = milp::MakeCbcSolver()->Solve(milp.lp(), s.solve);
//
// Parsing is strict: unknown keys (at every level), wrong types, missing
// required fields, non-finite numbers, non-positive durations, a step that
// does not divide the horizon, empty thruster sets and zero-width windows
// throw ScenarioError whose message starts with the full path of the field
// ("scenario.horizon.step_s: ...") and quotes the value.
//
// Other commands can declare extra top-level sections (e.g. "long_horizon")
// through ScenarioParseOptions::extra_sections: they are accepted, kept in
// Scenario::raw and left to the caller (parse them with app::JsonObject);
// any other unknown key is still rejected.
#ifndef THRUSTSCHED_APP_SCENARIO_H_
#define THRUSTSCHED_APP_SCENARIO_H_

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/initial_orbit.h"
#include "app/json_reader.h"
#include "dynamics/geo_model.h"
#include "milp/solver.h"
#include "transcription/checker.h"
#include "transcription/conjunction_check.h"
#include "transcription/conjunction_solve.h"
#include "transcription/min_time.h"
#include "transcription/problem.h"
#include "transcription/schedule_milp.h"
#include "transcription/search/search_options.h"

namespace thrustsched::app {

enum class ModelType { kHcw, kGeo, kDoubleIntegrator, kYamanakaAnkersen, kSchweighartSedwick };
/// "hcw" | "geo" | "double_integrator" | "yamanaka_ankersen" | "schweighart_sedwick".
std::string_view ToString(ModelType type);

/// Largest grid the CLI accepts (intervals), so that a typo in a duration
/// fails fast instead of exhausting memory.
inline constexpr int kMaxIntervals = 100000;

struct ScenarioParseOptions {
  /// Top-level sections the caller interprets itself; accepted, not read.
  std::vector<std::string> extra_sections;
  /// Used in messages when parsing text (LoadScenario sets the file path).
  std::string source = "scenario";

  /// extra_sections: names not empty, none a section the parser reads
  /// itself (ScenarioSections); source not empty. On failure `*error` (if
  /// given) names the field and the value.
  bool IsValid(std::string* error) const;
};

/// check.window_tolerance when the scenario gives none: this fraction of the
/// smaller window half width.
inline constexpr double kDefaultWindowToleranceFraction = 1e-3;

/// Checker verdict settings (see data/scenarios/README.md, "check").
struct VerdictOptions {
  /// Largest window violation (window unit: m, or deg for GEO) still passing.
  double window_tolerance = 0.0;
  /// Judge the window on every re-propagation sample, not only at grid nodes.
  bool include_intersample = false;
  /// GEO: the nonlinear replay's violation also decides the verdict.
  bool include_nonlinear = false;

  /// window_tolerance finite and >= 0. On failure `*error` (if given) names
  /// the field and the value.
  bool IsValid(std::string* error) const;
};

struct Scenario {
  std::string name;
  std::string path;    // file it was read from ("" if parsed from text)
  nlohmann::json raw;  // the whole file as parsed
  ModelType model_type = ModelType::kHcw;

  transcription::ScheduleProblem problem;
  transcription::BuildOptions build;
  milp::SolveOptions solve;           // no callbacks set
  transcription::CheckOptions check;  // .nonlinear set for GEO unless disabled
  /// solver.diagnosis_time_limit_s: after a solve that a limit stopped with
  /// no schedule, at most this long is spent looking for a proof of
  /// infeasibility (transcription::SolveScheduleOptions::prefix_diagnosis_s);
  /// 0 switches it off (as does --no-diagnose).
  double diagnosis_time_limit_s = 30.0;
  /// solver.search: the problem-aware search (transcription/search.h) in
  /// on-off mode; false hands the whole MILP to CBC (--no-search).
  bool search = true;
  /// solver.search as an object: the plan, the phases left out, each
  /// phase's options (app/search_section.h); `search` is its `enabled`.
  transcription::SearchOptions search_options;
  VerdictOptions verdict;

  /// Verification settings of the "conjunction" section (set iff
  /// problem.conjunction is).
  std::optional<transcription::ConjunctionCheckOptions> conjunction_check;
  /// Solve strategy of the "conjunction" section (budget rounds).
  transcription::ConjunctionSolveOptions conjunction_solve;

  /// objective "min_time" (set iff it is the objective): the earliest grid
  /// node from which the terminal section's set holds (its target and
  /// tolerance; the terminal constraint at t_N is then free), with
  /// problem.objective (objective.fuel) as the second MILP's fuel.
  std::optional<transcription::MinTimeSpec> min_time;
  /// GEO model options (set iff model_type == kGeo).
  std::optional<dynamics::GeoModelOptions> geo;
  /// GEO: the initial state when it was given as an orbit (OPM file, ECI
  /// state vector or Keplerian elements); problem.initial_state holds its
  /// conversion to the model state at the horizon start.
  std::optional<InitialOrbit> initial_orbit;
  /// Uniform grid description.
  double start_s = 0.0, step_s = 0.0;
  int num_intervals = 0;

  /// Window unit for reports: "m" (Cartesian models) or "deg" (GEO), "" if no window.
  std::string window_unit;
  /// Factor from model output units to the window unit (1, or 180/pi for GEO).
  double window_unit_per_output_unit = 1.0;
  /// Half widths in the window unit (same order as problem.window.outputs).
  std::vector<double> window_half_widths;

  std::vector<std::string> thruster_names() const { return problem.thrusters.names(); }
  bool impulsive() const { return problem.input_mode == transcription::InputMode::kImpulsive; }
};

/// Parses an already-parsed JSON document. @throws ScenarioError.
Scenario ParseScenario(const nlohmann::json& json, const ScenarioParseOptions& options = {});
/// Parses JSON text. @throws ScenarioError (also for malformed JSON and duplicate keys).
Scenario ParseScenarioText(std::string_view text, const ScenarioParseOptions& options = {});
/// Reads and parses a file. @throws ScenarioError (also if it cannot be read).
Scenario LoadScenario(const std::string& path, const ScenarioParseOptions& options = {});

/// The top-level sections ParseScenario understands, in documentation order.
std::vector<std::string> ScenarioSections();

/// Command-line overrides (each optional).
struct ScenarioOverrides {
  std::optional<double> time_limit_s;
  std::optional<double> relative_gap;
  std::optional<int> threads;
  std::optional<std::string> scheme;
  std::optional<std::string> formulation;
  std::optional<std::string> encoding;
  bool no_diagnose = false;  // --no-diagnose
  bool no_search = false;    // --no-search
};
/// Applies the overrides. @throws ScenarioError naming the option ("--gap: ...").
void ApplyOverrides(const ScenarioOverrides& overrides, Scenario* scenario);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_SCENARIO_H_
