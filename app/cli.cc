// The thrustsched command line (app/cli.h): parsing with CLI11, then the
// subcommand of commands.h or simulate.h, with the documented exit codes.
#include "app/cli.h"

#include <algorithm>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/json_reader.h"
#include "app/simulate.h"
#include "app/transfer_command.h"
#include "milp/cbc_solver.h"

#ifndef THRUSTSCHED_VERSION
#define THRUSTSCHED_VERSION "unknown"
#endif

namespace thrustsched::app {
namespace {

// Optional values from CLI11 (which fills plain variables) into the overrides.
struct OverrideFlags {
  double time_limit = 0, gap = 0;
  int threads = 0;
  std::string scheme, formulation, encoding;
  CLI::Option* o_time = nullptr;
  CLI::Option* o_gap = nullptr;
  CLI::Option* o_threads = nullptr;
  CLI::Option* o_scheme = nullptr;
  CLI::Option* o_formulation = nullptr;
  CLI::Option* o_encoding = nullptr;

  void AddModelOptions(CLI::App* app) {
    o_scheme = app->add_option("--scheme", scheme,
                               "discretisation scheme: exact_zoh, frozen_start, frozen_mid, "
                               "hermite_simpson, rk4, trapezoid, euler, reference");
    o_formulation = app->add_option("--formulation", formulation, "sparse | condensed");
    o_encoding =
        app->add_option("--encoding", encoding, "operational-rule encoding: thesis | tight");
  }
  void AddSolverOptions(CLI::App* app) {
    o_time = app->add_option("--time-limit", time_limit, "solver wall-clock limit (s)");
    o_gap = app->add_option("--gap", gap, "relative optimality gap at which the solver stops");
    o_threads = app->add_option("--threads", threads, "solver threads");
  }
  ScenarioOverrides Get() const {
    ScenarioOverrides o;
    if (o_time != nullptr && o_time->count() > 0) o.time_limit_s = time_limit;
    if (o_gap != nullptr && o_gap->count() > 0) o.relative_gap = gap;
    if (o_threads != nullptr && o_threads->count() > 0) o.threads = threads;
    if (o_scheme != nullptr && o_scheme->count() > 0) o.scheme = scheme;
    if (o_formulation != nullptr && o_formulation->count() > 0) o.formulation = formulation;
    if (o_encoding != nullptr && o_encoding->count() > 0) o.encoding = encoding;
    return o;
  }
};

// --oem FILE and --opm-maneuvers FILE (GEO scenarios).
void AddCcsdsOptions(CLI::App* app, FlightDynamicsFiles* files) {
  app->add_option(
      "--oem", files->oem,
      "also write the nonlinear replay as a CCSDS OEM 2.0 (KVN, EME2000, UTC; GEO only)");
  app->add_option(
      "--opm-maneuvers", files->opm_maneuvers,
      "also write the plan as a CCSDS OPM 2.0 with one maneuver block per burn (GEO only)");
}

std::string CommandLine(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

}  // namespace

int RunCli(int argc, char** argv, const RunHooks& hooks) {
  CLI::App cli{
      "thrustsched: minimum-fuel on-off thruster firing schedules (station keeping, rendezvous) "
      "by mixed-integer linear programming.\n"
      "Scenario files are JSON, documented in data/scenarios/README.md.\n"
      "Exit codes: 0 solved (optimal or feasible) or check passed, 1 internal error, 2 bad input, "
      "3 infeasible, 4 no solution within the time limit, 5 check failed."};
  cli.set_version_flag("-V,--version", std::string("thrustsched ") + THRUSTSCHED_VERSION + " (" +
                                           milp::CbcVersion() + ")");
  cli.require_subcommand(1);

  // solve
  SolveArgs solve;
  OverrideFlags solve_flags;
  bool solve_no_diagnose = false;
  bool solve_no_search = false;
  CLI::App* c_solve = cli.add_subcommand(
      "solve",
      "Build, solve, check and write results (summary.json, schedule.csv, trajectory.csv, SVG "
      "plots). Command-line options override the scenario.");
  c_solve->add_option("scenario", solve.scenario, "scenario file (JSON)")->required();
  c_solve->add_option("--out", solve.out_dir,
                      "output directory (default out/<scenario file stem>)");
  solve_flags.AddSolverOptions(c_solve);
  solve_flags.AddModelOptions(c_solve);
  c_solve->add_option("--export-mps", solve.export_mps, "also write the model as free MPS");
  c_solve->add_option("--export-lp", solve.export_lp, "also write the model as CPLEX LP");
  AddCcsdsOptions(c_solve, &solve.ccsds);
  c_solve->add_flag("--quiet", solve.quiet, "no progress messages on stderr");
  c_solve->add_flag("--no-plots", solve.no_plots,
                    "write the gnuplot scripts but do not run gnuplot");
  c_solve->add_flag("--no-report", solve.no_report,
                    "do not write report.html (the self-contained page with the scenario, result, "
                    "checker verdict, plots and schedule)");
  c_solve->add_flag("--force", solve.force,
                    "replace the files of an earlier run in the --out folder (without it, such a "
                    "folder is refused with exit 2)");
  c_solve->add_flag("--no-search", solve_no_search,
                    "hand the whole MILP to CBC, without the problem-aware search (scenario field "
                    "solver.search; for comparisons with the first release)");
  c_solve->add_flag("--no-diagnose", solve_no_diagnose,
                    "after a solve that stops with no schedule, do not look for a proof of "
                    "infeasibility (scenario field solver.diagnosis_time_limit_s, default 30 s)");

  // export
  ExportArgs exp;
  OverrideFlags export_flags;
  CLI::App* c_export = cli.add_subcommand(
      "export", "Write the model only, as free MPS (FILE.mps) or CPLEX LP (FILE.lp).");
  c_export->add_option("scenario", exp.scenario, "scenario file (JSON)")->required();
  c_export->add_option("file", exp.file, "output model file, .mps or .lp")->required();
  export_flags.AddModelOptions(c_export);
  c_export->add_flag("--obfuscate-names", exp.obfuscate_names,
                     "name columns/rows C000001/R000001 (import-solution needs the same flag)");

  // check
  CheckArgs check;
  CLI::App* c_check = cli.add_subcommand(
      "check",
      "Run the independent checker on a schedule (schedule.csv, or impulses.csv for impulsive "
      "scenarios), e.g. one produced by another solver. Exit 0 if it passes, 5 if not.");
  c_check->add_option("scenario", check.scenario, "scenario file (JSON)")->required();
  c_check->add_option("schedule", check.schedule, "schedule CSV")->required();
  c_check->add_option("--out", check.out_dir,
                      "also write check.json, trajectory.csv and plots to this directory");
  c_check->add_flag("--no-plots", check.no_plots, "with --out: do not run gnuplot");
  c_check->add_flag("--force", check.force,
                    "with --out: replace the files of an earlier run in that folder");
  AddCcsdsOptions(c_check, &check.ccsds);

  // import-solution
  ImportArgs imp;
  OverrideFlags import_flags;
  CLI::App* c_import = cli.add_subcommand(
      "import-solution",
      "Map another solver's solution of the exported model back to a schedule, by column names.\n"
      "  cbc model.mps sec 60 solve solu sol.txt            -> --format cbc\n"
      "  glpsol --freemps model.mps --tmlim 60 -o sol.txt   -> --format glpsol\n"
      "  glpsol --freemps model.mps --tmlim 60 -w sol.raw   -> --format glpsol-raw (full "
      "precision)\n"
      "Use the same --scheme/--formulation/--encoding as for the export.");
  c_import->add_option("scenario", imp.scenario, "scenario file (JSON)")->required();
  c_import->add_option("solution", imp.solution, "the solver's solution file")->required();
  c_import->add_option("--format", imp.format, "cbc | glpsol | glpsol-raw")->required();
  c_import->add_option("--out", imp.out, "schedule CSV to write")->required();
  import_flags.AddModelOptions(c_import);
  c_import->add_flag("--obfuscate-names", imp.obfuscate_names,
                     "the model was exported with --obfuscate-names");

  // validate
  ValidateArgs val;
  bool no_build = false;
  OverrideFlags validate_flags;
  CLI::App* c_validate = cli.add_subcommand(
      "validate", "Parse and validate a scenario and build its model (no solve); exit 0 or 2.");
  c_validate->add_option("scenario", val.scenario, "scenario file (JSON)")->required();
  c_validate->add_flag("--no-build", no_build, "only parse and validate");
  validate_flags.AddModelOptions(c_validate);

  // simulate
  SimulateArgs sim;
  CLI::App* c_simulate = cli.add_subcommand(
      "simulate",
      "Long station-keeping simulation (thesis ch. 5): chained cycle MILPs closed through the "
      "nonlinear GEO model, from the scenario's \"long_horizon\" section. Writes cycles.csv, "
      "year.json, trajectory.csv, per-cycle schedules, checkpoint.json and SVG plots. Exit 0 "
      "when every requested cycle ran (fallbacks are reported, not errors), 4 if interrupted "
      "(continue with --resume).");
  c_simulate
      ->add_option("scenario", sim.scenario, "scenario file (JSON) with a long_horizon section")
      ->required();
  c_simulate->add_option("--out", sim.out_dir,
                         "output directory (default out/<scenario file stem>)");
  c_simulate->add_option("--cycles", sim.cycles, "stop once this many cycles (in total) are done")
      ->check(CLI::PositiveNumber);
  c_simulate->add_flag("--resume", sim.resume,
                       "continue from the checkpoint in the output directory");
  c_simulate->add_flag("--force", sim.force,
                       "start over in an output directory that holds an earlier run (its files "
                       "are removed; without --resume or --force such a directory is refused "
                       "with exit 2)");
  c_simulate->add_flag("--quiet", sim.quiet, "no progress messages on stderr");
  c_simulate->add_flag("--no-plots", sim.no_plots,
                       "write the gnuplot scripts but do not run gnuplot");
  c_simulate->add_flag("--no-report", sim.no_report,
                       "do not write report.html (nor the year plots only it shows)");
  AddCcsdsOptions(c_simulate, &sim.ccsds);

  // transfer (orbit raising, app/transfer_command.h)
  TransferArgs transfer;
  CLI::App* c_transfer = cli.add_subcommand(
      "transfer",
      "Orbit transfer (minimum time by shooting, Lyapunov feedback, two impulses) "
      "from a transfer scenario; writes summary.json and trajectory.csv.");
  c_transfer->add_option("scenario", transfer.scenario, "transfer scenario file (JSON)")
      ->required();
  c_transfer->add_option("--out", transfer.out_dir, "output directory (default out/<file stem>)");
  c_transfer->add_option("--method", transfer.method, "minimum_time, feedback or two_impulse");
  c_transfer->add_flag("--force", transfer.force, "replace an earlier run's files in --out");
  c_transfer->add_flag("--quiet", transfer.quiet, "no progress messages on stderr");

  // `thrustsched help [command]`, and a misspelt command named as such.
  if (argc >= 2 && std::string(argv[1]) == "help") {
    if (argc >= 3) {
      for (CLI::App* sub : cli.get_subcommands({})) {
        if (sub->get_name() == argv[2]) {
          std::cout << sub->help();
          return kExitOk;
        }
      }
    }
    std::cout << cli.help();
    return kExitOk;
  }
  if (argc >= 2 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (CLI::App* sub : cli.get_subcommands({})) names.push_back(sub->get_name());
    const std::string word = argv[1];
    if (std::find(names.begin(), names.end(), word) == names.end()) {
      const std::string near = ClosestName(word, names);
      std::cerr << "error: unknown subcommand '" << word << "'"
                << (near.empty() ? "" : "; did you mean '" + near + "'?") << " (commands: ";
      for (size_t i = 0; i < names.size(); ++i) std::cerr << (i ? ", " : "") << names[i];
      std::cerr << "; thrustsched --help)\n";
      return kExitBadInput;
    }
  }

  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    cli.exit(e);  // prints the message
    return kExitBadInput;
  }

  try {
    if (c_solve->parsed()) {
      solve.overrides = solve_flags.Get();
      solve.overrides.no_diagnose = solve_no_diagnose;
      solve.overrides.no_search = solve_no_search;
      solve.command_line = CommandLine(argc, argv);
      solve.hooks = hooks;
      return RunSolve(solve);
    }
    if (c_export->parsed()) {
      exp.overrides = export_flags.Get();
      return RunExport(exp);
    }
    if (c_check->parsed()) {
      check.command_line = CommandLine(argc, argv);
      return RunCheck(check);
    }
    if (c_import->parsed()) {
      imp.overrides = import_flags.Get();
      return RunImportSolution(imp);
    }
    if (c_simulate->parsed()) {
      sim.command_line = CommandLine(argc, argv);
      sim.hooks = hooks;
      return RunSimulate(sim);
    }
    if (c_transfer->parsed()) {
      transfer.command_line = CommandLine(argc, argv);
      return RunTransfer(transfer);
    }
    if (c_validate->parsed()) {
      val.build = !no_build;
      val.overrides = validate_flags.Get();
      return RunValidate(val);
    }
  } catch (const std::invalid_argument& e) {
    // ScenarioError and the library's documented invalid-input exceptions.
    std::cerr << "error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory (is the model too large? try a longer step_s)\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitInternal;
}

int RunCli(const std::vector<std::string>& args, const RunHooks& hooks) {
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  return RunCli(static_cast<int>(copy.size()), argv.data(), hooks);
}

}  // namespace thrustsched::app
