// `thrustsched solve` and `export` on a fleet scenario (app/fleet_scenario.h):
// the members' schedules from one MILP (transcription/fleet.h).
//
//   app::SolveArgs a;  a.scenario = "data/scenarios/fleet/hcw_spread.json";  a.out_dir = "out/f";
//   int code = app::RunFleetSolve(a);   // RunSolve calls it for a file with a "fleet" section
//
// Writes into the output folder (one run's files, as `solve`): summary.json
// (the fleet's status, objective, bound, gap, model size and keep-out
// figures; per member its consumption, burns, slot and check; the pairwise
// minimum distances; the couplings' residuals), fleet.csv (one row per pair:
// `member_a,member_b,min_distance_m,min_box_distance_m,time_s,planned_min_distance_m,planned_min_box_distance_m,keep_out_half_size_m`),
// and per member schedule_<member>.csv and trajectory_<member>.csv (the
// single-scenario formats). The exit code follows the fleet's status as
// for `solve` (0 with schedules, 3 infeasible, 4 none found); bad input 2.
#ifndef THRUSTSCHED_APP_FLEET_COMMAND_H_
#define THRUSTSCHED_APP_FLEET_COMMAND_H_

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/fleet_scenario.h"
#include "transcription/fleet.h"

namespace thrustsched::app {

/// What a fleet solve produced, as the files' contents (no folder): what
/// `solve` writes and the Python package returns.
struct FleetRun {
  transcription::FleetResult result;
  bool interrupted = false;
  nlohmann::json summary;                   // summary.json
  std::string fleet_csv;                    // fleet.csv
  std::vector<std::string> schedule_csv;    // per member (empty without schedules)
  std::vector<std::string> trajectory_csv;  // per member (empty without schedules)
};

struct FleetRunHooks {
  const std::atomic<bool>* interrupt = nullptr;  // stops the solve, keeps the best schedules
  std::function<void(const milp::SolveProgress&)> progress;
  std::function<void(const std::string&)> announce;  // each step of the start, as it begins
  std::string command_line;                          // summary.json's
};

/// Solves, checks and formats (the fleet's own solver options).
FleetRun RunFleetScenario(const FleetScenario& fleet, const FleetRunHooks& hooks);

int RunFleetSolve(const SolveArgs& args);
/// The fleet MILP as MPS or LP (columns and rows named "<member>.<name>").
int RunFleetExport(const ExportArgs& args);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_FLEET_COMMAND_H_
