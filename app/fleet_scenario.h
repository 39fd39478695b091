// Fleet scenario files: several spacecraft planned in one MILP
// (transcription/fleet.h). A file with a top-level "fleet" section:
//
//   {"name": "swap", "fleet": {
//      "members": [{"name": "a", "scenario": "a.json"},          // path, relative to this file
//                  {"name": "b", "scenario": {...a scenario...}}], // or inline
//      "couplings": [{"member": "b", "reference": "a", "map": "position",
//                     "offset": [0, 200, 0], "tolerance": [1, 1, 1]}],
//      "balance": {"kind": "min_max"},
//      "keep_out": {"half_size_m": 20, "check_step_s": 60},
//      "assignment": {"members": ["b", "c"], "reference": "a", "map": "position",
//                     "slots": [[0, 200, 0], [0, -200, 0]]},
//      "solver": {"time_limit_s": 60, "relative_gap": 1e-4, "threads": 1}}}
//
//   app::FleetScenario f = app::LoadFleetScenario("data/scenarios/fleet/hcw_spread.json");
//   transcription::FleetResult r = transcription::SolveFleet(f.problem, *solver, f.options);
//
// Every member is a complete scenario (app/scenario.h) read with its own
// rules, window, terminal set and objective; its "solver" section is not
// used (the fleet's is). Members must share the grid, use on-off thrusters
// and the sparse formulation, have no conjunction section and no
// "min_time" objective. Positions: the first three states of the Cartesian
// models (HCW, Yamanaka-Ankersen, Schweighart-Sedwick, double integrator),
// which the "position" map names; GEO members (co-located: one station
// longitude and epoch) are positioned radial, east, north about the station
// point by the model's LocalPositionMap, and their couplings take "state" or
// a matrix. Fields are documented in
// data/scenarios/README.md ("fleet"); errors are ScenarioError naming the
// field ("fleet.members[1].scenario.horizon.step_s: ...") and the value.
#ifndef THRUSTSCHED_APP_FLEET_SCENARIO_H_
#define THRUSTSCHED_APP_FLEET_SCENARIO_H_

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/scenario.h"
#include "transcription/fleet.h"

namespace thrustsched::app {

struct FleetScenario {
  std::string name;
  std::string path;  // "" when parsed from a document
  nlohmann::json raw;
  std::vector<Scenario> members;  // in fleet.members order
  transcription::FleetProblem problem;
  transcription::FleetSolveOptions options;  // build: sparse; milp: the fleet's "solver"
};

/// True if `document` is a fleet file (an object with a "fleet" key).
bool IsFleetDocument(const nlohmann::json& document);
/// True if the file at `path` parses as JSON and is a fleet file (false on
/// any read or parse error: the scenario parser then reports it).
bool IsFleetFile(const std::string& path);

/// `base_dir`: where member scenario paths are resolved.
/// @throws ScenarioError naming the field.
FleetScenario ParseFleetScenario(const nlohmann::json& document, const std::string& base_dir);
/// @throws ScenarioError (also if the file cannot be read).
FleetScenario LoadFleetScenario(const std::string& path);

/// --time-limit, --gap, --threads on the fleet's solver options (the
/// scenario overrides that make sense for a fleet; the others are refused
/// naming the option). @throws ScenarioError.
void ApplyFleetOverrides(const ScenarioOverrides& overrides, FleetScenario* fleet);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_FLEET_SCENARIO_H_
