// The subcommands of the thrustsched executable (internal to app/; the
// reusable pieces are in scenario.h, outputs.h, plots.h, solution_import.h).
//
//   app::SolveArgs a;  a.scenario = "data/scenarios/geo_week_anzel4.json";  a.out_dir = "out/demo";
//   int exit_code = app::RunSolve(a);
#ifndef THRUSTSCHED_APP_COMMANDS_H_
#define THRUSTSCHED_APP_COMMANDS_H_

#include <functional>
#include <ostream>
#include <string>

#include "app/geo_products.h"
#include "app/run_hooks.h"
#include "app/scenario.h"

namespace thrustsched::app {

/// Exit codes of the CLI: a contract scripts rely on (README.md,
/// data/scenarios/README.md section 1).
inline constexpr int kExitOk = 0;          // solved (optimal or feasible) / check passed
inline constexpr int kExitInternal = 1;    // internal error
inline constexpr int kExitBadInput = 2;    // bad input (scenario, files, options)
inline constexpr int kExitInfeasible = 3;  // proven infeasible
inline constexpr int kExitNoSolution = 4;  // no solution within the limits
/// `simulate` stopped by a signal before every requested cycle ran (continue
/// with --resume). The same number as kExitNoSolution because the documented
/// contract gives 4 to both (data/scenarios/README.md section 1); a name of its
/// own so that the code says which case it means.
inline constexpr int kExitInterrupted = 4;
inline constexpr int kExitCheckFailed = 5;  // `check`: the schedule fails the checks

struct SolveArgs {
  std::string scenario;
  std::string out_dir;  // empty: out/<scenario file stem>
  ScenarioOverrides overrides;
  std::string export_mps, export_lp;
  bool quiet = false;
  bool no_plots = false;
  bool no_report = false;  // skip report.html
  bool force = false;      // replace an earlier run's files in out_dir
  std::string command_line;
  FlightDynamicsFiles ccsds;  // --oem, --opm-maneuvers (GEO)
  RunHooks hooks;             // observers (tests, embedding programs): app/run_hooks.h
};
/// A file with a "fleet" section is solved as a fleet (app/fleet_command.h).
int RunSolve(const SolveArgs& args);
/// The CLI's progress observer: `hook` (if set) on every report, and once a
/// solve has run 3 s a line on `err` (unless quiet) naming the phase, the
/// best incumbent so far, the bound and the gap.
std::function<void(const milp::SolveProgress&)> CliProgress(
    bool quiet, std::ostream& err, std::function<void(const milp::SolveProgress&)> hook = {});
/// The exit code of a solve that ended with `status`: 0 optimal or
/// feasible, 3 infeasible, 4 no solution found, 1 unbounded or error.
int SolveExitCode(milp::SolveStatus status);

struct ExportArgs {
  std::string scenario;
  std::string file;  // .mps or .lp
  ScenarioOverrides overrides;
  bool obfuscate_names = false;
};
int RunExport(const ExportArgs& args);

struct CheckArgs {
  std::string scenario;
  std::string schedule;  // schedule.csv (on-off) or impulses.csv (impulsive)
  std::string out_dir;   // optional: check.json, trajectory.csv, plots
  bool no_plots = false;
  bool force = false;  // replace an earlier run's files in out_dir
  std::string command_line;
  FlightDynamicsFiles ccsds;  // --oem, --opm-maneuvers (GEO)
};
int RunCheck(const CheckArgs& args);

struct ImportArgs {
  std::string scenario;
  std::string solution;
  std::string format;  // cbc | glpsol | glpsol-raw
  std::string out;     // schedule.csv (or impulses.csv)
  ScenarioOverrides overrides;
  bool obfuscate_names = false;
};
int RunImportSolution(const ImportArgs& args);

struct ValidateArgs {
  std::string scenario;
  bool build = true;
  ScenarioOverrides overrides;
};
int RunValidate(const ValidateArgs& args);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_COMMANDS_H_
