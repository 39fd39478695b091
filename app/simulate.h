// `thrustsched simulate`: a long station-keeping simulation (thesis ch. 5) of
// chained cycle MILPs closed through the nonlinear GEO model
// (planning/long_horizon.h), driven by the "long_horizon" section of a
// GEO scenario file (fields in data/scenarios/README.md, "long_horizon").
//
//   app::SimulateArgs a;
//   a.scenario = "data/scenarios/year/year_anzel4_fixed.json";
//   a.out_dir = "out/year";            // cycles.csv, year.json, checkpoint.json, plots
//   int exit_code = app::RunSimulate(a);
//
// Every finished cycle is written at once (a row appended to cycles.csv and
// flushed, cycles/cycle_NNN.csv with its burns, cycles/cycle_NNN_trajectory.csv
// with the replay, and checkpoint.json rewritten atomically with the exact
// true state and every cycle's record); `resume` continues from the
// checkpoint and gives the same files as an uninterrupted run (see the
// determinism note in planning/long_horizon.h). Ctrl-C stops the
// current cycle's solve and exits without recording that cycle.
#ifndef THRUSTSCHED_APP_SIMULATE_H_
#define THRUSTSCHED_APP_SIMULATE_H_

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/geo_products.h"
#include "app/run_hooks.h"
#include "app/scenario.h"
#include "planning/long_horizon.h"

namespace thrustsched::app {

struct SimulateArgs {
  std::string scenario;
  std::string out_dir;     // empty: out/<scenario file stem>
  int cycles = -1;         // > 0: stop once this many cycles (in total) are done
  bool resume = false;     // continue from out_dir/checkpoint.json
  bool force = false;      // start over in a folder holding an earlier run (its files removed)
  bool quiet = false;      // no progress on stderr
  bool no_plots = false;   // write the gnuplot scripts but do not run gnuplot
  bool no_report = false;  // skip report.html (and the year plots only it shows)
  std::string command_line;
  FlightDynamicsFiles ccsds;  // --oem, --opm-maneuvers: the whole run's replay and burns

  // For callers other than the CLI (the Python package):
  /// Non-empty: the scenario's JSON text, parsed instead of reading `scenario`
  /// (which still names it in messages, resolves its relative paths and gives
  /// the default output folder).
  std::string scenario_text;
  /// Set: the stop request (the solve of the running cycle stops and the run
  /// ends as on Ctrl-C); no signal watcher is installed. Null: the CLI's
  /// watcher (app/interrupt.h).
  const std::atomic<bool>* interrupt = nullptr;
  /// Called after each finished cycle (from the calling thread) with its
  /// record, the number of cycles done and the number this run will reach.
  std::function<void(const planning::CycleRecord&, int done, int target)> on_cycle;
  /// False: nothing is written to stdout (the human summary).
  bool print_summary = true;
  /// Observers for tests and embedding programs (app/run_hooks.h): every
  /// solver progress report, and the start of each cycle's solve.
  RunHooks hooks;
};

/// Exit codes: 0 every requested cycle ran (fallbacks included: see year.json),
/// 2 bad input (scenario, section, checkpoint of another scenario, a folder
///   holding an earlier run without --resume or --force),
/// 4 interrupted (kExitInterrupted: resume with --resume), 1 internal error.
int RunSimulate(const SimulateArgs& args);

/// A failure entry of long_horizon.failures, as written in the scenario.
struct FailureSpec {
  std::vector<std::string> thrusters;  // names
  double from_s = 0.0;
  double until_s = 0.0;  // +inf = never repaired
  bool opposite_also_off = false;
  std::vector<std::string> switched_off;  // all names forced off (with the opposites)
};

/// The parsed "long_horizon" section and the matching library inputs.
struct SimulationSetup {
  Scenario scenario;
  planning::LongHorizonOptions options;
  std::vector<FailureSpec> failures;
  double trajectory_sample_s = 3600.0;  // spacing of trajectory.csv (s)
  int timeline_cycle = -1;              // cycle (0-based) of timeline.svg; -1: busiest
  std::string fingerprint;              // identifies the inputs (for --resume)
};

/// Loads the scenario (GEO only) with its "long_horizon" section.
/// @throws ScenarioError naming the field and value.
SimulationSetup LoadSimulation(const std::string& path);
/// Same from JSON text (`source` names it in messages).
SimulationSetup ParseSimulationText(const std::string& text, const std::string& source);

/// One cycle as stored in checkpoint.json (no replay samples), and back.
nlohmann::json CycleRecordJson(const planning::CycleRecord& record);
/// @throws ScenarioError naming the field on malformed input.
planning::CycleRecord CycleRecordFromJson(const nlohmann::json& json, const std::string& path);

/// Header and row of cycles.csv.
std::string CyclesCsvHeader();
std::string CyclesCsvRow(const planning::CycleRecord& record, const std::string& epoch);

/// year.json content.
nlohmann::json YearJson(const SimulationSetup& setup,
                        const std::vector<planning::CycleRecord>& cycles, int cycles_total,
                        double this_run_wall_seconds);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_SIMULATE_H_
