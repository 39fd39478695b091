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
    o_time = app->add_option("--time-limit", time_limit,
                             "wall-clock limit (s) of the solve and the infeasibility diagnosis "
                             "together (see --no-diagnose)");
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

// The subcommands' arguments, filled by CLI11 while parsing.
struct Subcommands {
  SolveArgs solve;
  OverrideFlags solve_flags;
  bool solve_no_diagnose = false;
  bool solve_no_search = false;
  CLI::App* c_solve = nullptr;
  ExportArgs exp;
  OverrideFlags export_flags;
  CLI::App* c_export = nullptr;
  CheckArgs check;
  CLI::App* c_check = nullptr;
  ImportArgs imp;
  OverrideFlags import_flags;
  CLI::App* c_import = nullptr;
  ValidateArgs val;
  bool no_build = false;
  OverrideFlags validate_flags;
  CLI::App* c_validate = nullptr;
  SimulateArgs sim;
  CLI::App* c_simulate = nullptr;
  TransferArgs transfer;
  CLI::App* c_transfer = nullptr;
};

// `solve`: build, solve, check, write.
void AddSolveCommand(CLI::App* cli, Subcommands* c) {
  c->c_solve = cli->add_subcommand(
      "solve",
      "Build, solve, check and write results (summary.json, schedule.csv, trajectory.csv, SVG "
      "plots). Command-line options override the scenario. A file with a \"fleet\" section "
      "plans its members in one MILP (fleet.csv, schedule_<member>.csv).");
  c->c_solve->add_option("scenario", c->solve.scenario, "scenario file (JSON)")->required();
  c->c_solve->add_option("--out", c->solve.out_dir,
                         "output directory (default out/<scenario file stem>)");
  c->solve_flags.AddSolverOptions(c->c_solve);
  c->solve_flags.AddModelOptions(c->c_solve);
  c->c_solve->add_option("--export-mps", c->solve.export_mps, "also write the model as free MPS");
  c->c_solve->add_option("--export-lp", c->solve.export_lp, "also write the model as CPLEX LP");
  AddCcsdsOptions(c->c_solve, &c->solve.ccsds);
  c->c_solve->add_flag("--quiet", c->solve.quiet, "no progress messages on stderr");
  c->c_solve->add_flag("--no-plots", c->solve.no_plots,
                       "write the gnuplot scripts but do not run gnuplot");
  c->c_solve->add_flag(
      "--no-report", c->solve.no_report,
      "do not write report.html (the self-contained page with the scenario, result, "
      "checker verdict, plots and schedule)");
  c->c_solve->add_flag(
      "--force", c->solve.force,
      "replace the files of an earlier run in the --out folder (without it, such a "
      "folder is refused with exit 2)");
  c->c_solve->add_flag(
      "--no-search", c->solve_no_search,
      "hand the whole MILP to CBC, without the problem-aware search (scenario field "
      "solver.search; for comparisons with the first release)");
  c->c_solve->add_flag(
      "--no-diagnose", c->solve_no_diagnose,
      "after a solve that stops with no schedule, do not look for a proof of "
      "infeasibility; the solve then has the whole --time-limit (by default the diagnosis "
      "runs inside the limit: it keeps the smaller of a quarter of the limit and the "
      "scenario field solver.diagnosis_time_limit_s, default 30 s)");
}

// `export`: the model file only.
void AddExportCommand(CLI::App* cli, Subcommands* c) {
  c->c_export = cli->add_subcommand(
      "export", "Write the model only, as free MPS (FILE.mps) or CPLEX LP (FILE.lp).");
  c->c_export->add_option("scenario", c->exp.scenario, "scenario file (JSON)")->required();
  c->c_export->add_option("file", c->exp.file, "output model file, .mps or .lp")->required();
  c->export_flags.AddModelOptions(c->c_export);
  c->c_export->add_flag("--obfuscate-names", c->exp.obfuscate_names,
                        "name columns/rows C000001/R000001 (import-solution needs the same flag)");
}

// `check`: the independent checker on a schedule file.
void AddCheckCommand(CLI::App* cli, Subcommands* c) {
  c->c_check = cli->add_subcommand(
      "check",
      "Run the independent checker on a schedule (schedule.csv, or impulses.csv for impulsive "
      "scenarios), e.g. one produced by another solver. Exit 0 if it passes, 5 if not.");
  c->c_check->add_option("scenario", c->check.scenario, "scenario file (JSON)")->required();
  c->c_check->add_option("schedule", c->check.schedule, "schedule CSV")->required();
  c->c_check->add_option("--out", c->check.out_dir,
                         "also write check.json, trajectory.csv and plots to this directory");
  c->c_check->add_flag("--no-plots", c->check.no_plots, "with --out: do not run gnuplot");
  c->c_check->add_flag("--force", c->check.force,
                       "with --out: replace the files of an earlier run in that folder");
  AddCcsdsOptions(c->c_check, &c->check.ccsds);
}

// `import-solution`: another solver's solution back to a schedule.
void AddImportCommand(CLI::App* cli, Subcommands* c) {
  c->c_import = cli->add_subcommand(
      "import-solution",
      "Map another solver's solution of the exported model back to a schedule, by column names.\n"
      "  cbc model.mps sec 60 solve solu sol.txt            -> --format cbc\n"
      "  glpsol --freemps model.mps --tmlim 60 -o sol.txt   -> --format glpsol\n"
      "  glpsol --freemps model.mps --tmlim 60 -w sol.raw   -> --format glpsol-raw (full "
      "precision)\n"
      "Use the same --scheme/--formulation/--encoding as for the export.");
  c->c_import->add_option("scenario", c->imp.scenario, "scenario file (JSON)")->required();
  c->c_import->add_option("solution", c->imp.solution, "the solver's solution file")->required();
  c->c_import->add_option("--format", c->imp.format, "cbc | glpsol | glpsol-raw")->required();
  c->c_import->add_option("--out", c->imp.out, "schedule CSV to write")->required();
  c->import_flags.AddModelOptions(c->c_import);
  c->c_import->add_flag("--obfuscate-names", c->imp.obfuscate_names,
                        "the model was exported with --obfuscate-names");
}

// `validate`: parse and build, no solve.
void AddValidateCommand(CLI::App* cli, Subcommands* c) {
  c->c_validate = cli->add_subcommand(
      "validate", "Parse and validate a scenario and build its model (no solve); exit 0 or 2.");
  c->c_validate->add_option("scenario", c->val.scenario, "scenario file (JSON)")->required();
  c->c_validate->add_flag("--no-build", c->no_build, "only parse and validate");
  c->validate_flags.AddModelOptions(c->c_validate);
}

// `simulate`: the long-horizon loop.
void AddSimulateCommand(CLI::App* cli, Subcommands* c) {
  c->c_simulate = cli->add_subcommand(
      "simulate",
      "Long station-keeping simulation (thesis ch. 5): chained cycle MILPs closed through the "
      "nonlinear GEO model, from the scenario's \"long_horizon\" section. Writes cycles.csv, "
      "year.json, trajectory.csv, per-cycle schedules, checkpoint.json and SVG plots. Exit 0 "
      "when every requested cycle ran (fallbacks are reported, not errors), 4 if interrupted "
      "(continue with --resume).");
  c->c_simulate
      ->add_option("scenario", c->sim.scenario, "scenario file (JSON) with a long_horizon section")
      ->required();
  c->c_simulate->add_option("--out", c->sim.out_dir,
                            "output directory (default out/<scenario file stem>)");
  c->c_simulate
      ->add_option("--cycles", c->sim.cycles, "stop once this many cycles (in total) are done")
      ->check(CLI::PositiveNumber);
  c->c_simulate->add_flag("--resume", c->sim.resume,
                          "continue from the checkpoint in the output directory");
  c->c_simulate->add_flag("--force", c->sim.force,
                          "start over in an output directory that holds an earlier run (its files "
                          "are removed; without --resume or --force such a directory is refused "
                          "with exit 2)");
  c->c_simulate->add_flag("--quiet", c->sim.quiet, "no progress messages on stderr");
  c->c_simulate->add_flag("--no-plots", c->sim.no_plots,
                          "write the gnuplot scripts but do not run gnuplot");
  c->c_simulate->add_flag("--no-report", c->sim.no_report,
                          "do not write report.html (nor the year plots only it shows)");
  AddCcsdsOptions(c->c_simulate, &c->sim.ccsds);
}

// `transfer`: orbit raising (app/transfer_command.h).
void AddTransferCommand(CLI::App* cli, Subcommands* c) {
  c->c_transfer = cli->add_subcommand(
      "transfer",
      "Orbit transfer (minimum time by shooting, Lyapunov feedback, two impulses) "
      "from a transfer scenario; writes summary.json (with the end state as a station-keeping "
      "initial_state), trajectory.csv, orbit.csv, SVG plots and report.html. Ctrl-C stops it and "
      "writes the best result so far (exit 4).");
  c->c_transfer->add_option("scenario", c->transfer.scenario, "transfer scenario file (JSON)")
      ->required();
  c->c_transfer->add_option("--out", c->transfer.out_dir,
                            "output directory (default out/<file stem>)");
  c->c_transfer->add_option("--method", c->transfer.method,
                            "minimum_time, feedback or two_impulse");
  c->c_transfer->add_flag("--force", c->transfer.force, "replace an earlier run's files in --out");
  c->c_transfer->add_flag("--quiet", c->transfer.quiet, "no progress messages on stderr");
  c->c_transfer->add_flag("--no-plots", c->transfer.no_plots,
                          "write the gnuplot scripts but do not run gnuplot");
  c->c_transfer->add_flag("--no-report", c->transfer.no_report,
                          "do not write report.html (the self-contained page with the scenario, "
                          "result, convergence figures and plots)");
  c->c_transfer->add_option("--oem", c->transfer.oem,
                            "also write the trajectory as a CCSDS OEM 2.0 (EME2000, UTC; needs "
                            "the scenario's transfer.epoch)");
}

// `thrustsched help [command]`, and a misspelt command named as such: the
// exit code, or nothing when the command line is for CLI11.
std::optional<int> AnswerHelpOrUnknown(CLI::App* cli, int argc, char** argv) {
  if (argc >= 2 && std::string(argv[1]) == "help") {
    if (argc >= 3) {
      for (CLI::App* sub : cli->get_subcommands({})) {
        if (sub->get_name() == argv[2]) {
          std::cout << sub->help();
          return kExitOk;
        }
      }
    }
    std::cout << cli->help();
    return kExitOk;
  }
  if (argc >= 2 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (CLI::App* sub : cli->get_subcommands({})) names.push_back(sub->get_name());
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
  return std::nullopt;
}

// Runs the subcommand CLI11 parsed; bad input (ScenarioError and the
// library's invalid-input exceptions) exits 2, other failures 1.
int RunParsed(Subcommands* c, int argc, char** argv, const RunHooks& hooks) {
  try {
    if (c->c_solve->parsed()) {
      c->solve.overrides = c->solve_flags.Get();
      c->solve.overrides.no_diagnose = c->solve_no_diagnose;
      c->solve.overrides.no_search = c->solve_no_search;
      c->solve.command_line = CommandLine(argc, argv);
      c->solve.hooks = hooks;
      return RunSolve(c->solve);
    }
    if (c->c_export->parsed()) {
      c->exp.overrides = c->export_flags.Get();
      return RunExport(c->exp);
    }
    if (c->c_check->parsed()) {
      c->check.command_line = CommandLine(argc, argv);
      return RunCheck(c->check);
    }
    if (c->c_import->parsed()) {
      c->imp.overrides = c->import_flags.Get();
      return RunImportSolution(c->imp);
    }
    if (c->c_simulate->parsed()) {
      c->sim.command_line = CommandLine(argc, argv);
      c->sim.hooks = hooks;
      return RunSimulate(c->sim);
    }
    if (c->c_transfer->parsed()) {
      c->transfer.command_line = CommandLine(argc, argv);
      return RunTransfer(c->transfer);
    }
    if (c->c_validate->parsed()) {
      c->val.build = !c->no_build;
      c->val.overrides = c->validate_flags.Get();
      return RunValidate(c->val);
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
  Subcommands c;
  AddSolveCommand(&cli, &c);
  AddExportCommand(&cli, &c);
  AddCheckCommand(&cli, &c);
  AddImportCommand(&cli, &c);
  AddValidateCommand(&cli, &c);
  AddSimulateCommand(&cli, &c);
  AddTransferCommand(&cli, &c);
  if (const std::optional<int> code = AnswerHelpOrUnknown(&cli, argc, argv)) return *code;
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
  return RunParsed(&c, argc, argv, hooks);
}

int RunCli(const std::vector<std::string>& args, const RunHooks& hooks) {
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  return RunCli(static_cast<int>(copy.size()), argv.data(), hooks);
}

}  // namespace thrustsched::app
