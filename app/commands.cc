#include "app/commands.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "app/conjunction_report.h"
#include "app/fleet_command.h"
#include "app/fleet_scenario.h"
#include "app/format_units.h"
#include "app/html_report.h"
#include "app/interrupt.h"
#include "app/min_time_report.h"
#include "app/outputs.h"
#include "app/plots.h"
#include "app/run_folder.h"
#include "app/solution_import.h"
#include "common/format.h"
#include "common/timing.h"
#include "milp/cbc_solver.h"
#include "milp/model_io.h"
#include "transcription/export_lp.h"
#include "transcription/solve.h"

namespace thrustsched::app {

using common::FormatG;
using common::Since;

namespace {

namespace fs = std::filesystem;
using common::Clock;

std::string F(double v, int digits = 6) {
  if (std::isnan(v)) return "n/a";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return FormatG(v, digits);
}

std::string Secs(double v) {
  char buf[48];
  std::snprintf(buf, sizeof(buf), "%.2f s", v);
  return buf;
}

std::string JoinNames(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

Scenario LoadWithOverrides(const std::string& path, const ScenarioOverrides& ov) {
  Scenario s = LoadScenario(path);
  ApplyOverrides(ov, &s);
  return s;
}

std::string ModelLine(const Scenario& s) {
  std::ostringstream os;
  os << ToString(s.model_type) << ", " << s.num_intervals << " intervals of " << F(s.step_s)
     << " s from t = " << F(s.start_s) << " s, " << s.problem.thrusters.size() << " thrusters ("
     << JoinNames(s.thruster_names());
  std::vector<std::string> disabled;
  for (const auto& t : s.problem.thrusters.thrusters()) {
    if (!t.enabled) disabled.push_back(t.name);
  }
  os << ")";
  if (!disabled.empty()) os << ", disabled: " << JoinNames(disabled);
  if (s.impulsive()) os << ", impulsive";
  return os.str();
}

std::string MilpLine(const transcription::ScheduleMilp& m, const Scenario& s) {
  const transcription::BuildStats& st = m.stats();
  std::ostringstream os;
  os << st.num_binaries << " binaries, " << st.num_columns << " columns, " << st.num_rows
     << " rows, " << st.num_nonzeros << " nonzeros (" << ToString(s.build.formulation) << ", "
     << ToString(s.build.encoding) << ", " << dynamics::ToString(s.build.discretisation.scheme)
     << ")";
  return os.str();
}

// ".mps" or ".lp" (lower case) from the file name. `option` names the flag
// that asked for a given format ("--export-mps"), empty for `export`.
// @throws ScenarioError if the extension is neither, or not the flag's.
std::string ModelFileExtension(const std::string& path, const std::string& option = "") {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (option == "--export-mps" && ext != ".mps") {
    throw ScenarioError("--export-mps " + path + ": the file name must end in .mps");
  }
  if (option == "--export-lp" && ext != ".lp") {
    throw ScenarioError("--export-lp " + path + ": the file name must end in .lp");
  }
  if (ext != ".mps" && ext != ".lp") {
    throw ScenarioError(path + ": the model file must end in .mps or .lp");
  }
  return ext;
}

// The model file of a scenario: its NAME is the scenario's name; every
// failure is bad input (exit code 2).
void WriteScenarioModelFile(const std::string& path, const milp::LpData& model,
                            const std::string& name, bool obfuscate) {
  milp::LpData lp = model;
  lp.name = name;
  ModelFileExtension(path);  // a ScenarioError for a name ending in neither .mps nor .lp
  try {
    WriteModelFile(path, lp, obfuscate);
  } catch (const std::runtime_error& e) {
    throw ScenarioError(e.what());
  }
}

void PrintCheck(std::ostream& os, const Scenario& s, const transcription::CheckReport& r,
                const CheckVerdict& v) {
  const double k = s.window_unit_per_output_unit;
  os << "check         " << (v.passed ? "PASSED" : "FAILED") << ": rules "
     << (r.operational_ok ? "ok" : std::to_string(r.rule_violations.size()) + " violation(s)");
  if (s.problem.window.enabled()) {
    os << ", window violation " << F(r.max_window_violation_at_nodes * k, 4) << " " << s.window_unit
       << " at nodes, " << F(r.max_window_violation * k, 4) << " " << s.window_unit
       << " on all samples";
  }
  if (s.problem.terminal.kind == transcription::TerminalKind::kFixedState ||
      s.problem.terminal.kind == transcription::TerminalKind::kStateBox) {
    os << ", terminal " << (r.terminal_ok ? "ok" : "VIOLATED");
  }
  os << "\n";
  if (r.nonlinear_checked) {
    os << "nonlinear     window violation " << F(r.max_window_violation_nonlinear_deg, 4)
       << " deg, max |lat| " << F(r.max_abs_lat_deg, 4) << " deg, max |lon - station| "
       << F(r.max_abs_lon_deg, 4) << " deg, ~" << FormatDuration(r.time_outside_window_nonlinear_s)
       << " outside\n";
  }
  for (const std::string& f : v.findings) os << "  finding: " << f << "\n";
}

void PrintImpulsiveCheck(std::ostream& os, const Scenario& s,
                         const transcription::ImpulsiveCheck& c, const CheckVerdict& v) {
  os << "check         " << (v.passed ? "PASSED" : "FAILED");
  if (s.problem.window.enabled()) {
    os << ": window violation " << F(c.max_window_violation * s.window_unit_per_output_unit, 4)
       << " " << s.window_unit << " at nodes";
  }
  os << ", terminal error " << F(c.terminal_error, 4) << " (state-scale units)\n";
  for (const std::string& f : v.findings) os << "  finding: " << f << "\n";
}

std::string BurnCounts(const Scenario& s, const transcription::Schedule& sch) {
  std::map<int, int> count;
  for (const auto& b : sch.burns) ++count[b.thruster];
  for (const auto& i : sch.impulses) ++count[i.thruster];
  std::string out;
  const auto names = s.thruster_names();
  for (const auto& [i, c] : count)
    out += (out.empty() ? "" : ", ") + names[i] + " " + std::to_string(c);
  return out;
}

// The flight-dynamics files of a run: those asked for inside the output
// folder are written into its temporary folder (moved into place with the
// rest), the others where they were asked for.
FlightDynamicsFiles InFolder(const FlightDynamicsFiles& files, const RunFolder& folder) {
  const fs::path target = fs::absolute(folder.target()).lexically_normal();
  auto map = [&](const std::string& path) {
    if (path.empty()) return path;
    const fs::path p = fs::absolute(path).lexically_normal();
    if (p.parent_path() != target && p.parent_path() != target.parent_path() / target.filename()) {
      return path;
    }
    return (fs::path(folder.path()) / p.filename()).string();
  };
  FlightDynamicsFiles out = files;
  out.oem = map(files.oem);
  out.opm_maneuvers = map(files.opm_maneuvers);
  return out;
}

// A path as the user will find it once the run folder is committed.
std::string ShownPath(const RunFolder& folder, const std::string& path) {
  if (path.compare(0, folder.path().size(), folder.path()) != 0) return path;
  return (fs::path(folder.target()) / path.substr(folder.path().size() + 1)).string();
}

// Plots of a run written into `folder` (messages name its final place).
void WritePlotsReport(const RunFolder& folder, const Scenario& s, bool nonlinear, bool no_plots,
                      std::vector<std::string>* files, std::ostream& err) {
  PlotOptions po;
  po.run_gnuplot = !no_plots;
  const PlotResult p = WritePlots(folder.path(), s, nonlinear, po);
  for (const auto& f : p.images) files->push_back(f);
  if (!p.ok && !p.message.empty()) {
    std::string message = p.message;
    for (size_t at; (at = message.find(folder.path())) != std::string::npos;) {
      message.replace(at, folder.path().size(), folder.target());
    }
    err << "note: " << message << "\n";
  }
}

// One progress line: the search's phase (if any), the solver's phase, then what is known (root LP
// iterate, or incumbent, bound, gap and nodes). `best` is the best incumbent seen so far.
std::string ProgressLine(const milp::SolveProgress& p, double best) {
  std::ostringstream os;
  if (!p.stage().empty()) os << p.stage() << ": ";
  if (p.stage_begins) {
    os << "begins; incumbent " << F(std::isfinite(p.objective) ? p.objective : best) << ", bound "
       << F(p.best_bound);
    return os.str();
  }
  if (p.phase == milp::SolvePhase::kRootLp && !p.new_incumbent) {
    os << "root LP relaxation";
    if (p.lp_iterations >= 0) {
      os << ": " << p.lp_iterations << " iterations, objective " << F(p.lp_objective)
         << ", primal infeasibility " << F(p.lp_primal_infeasibility, 3);
    }
    return os.str();
  }
  const double inc = std::isfinite(p.objective) ? p.objective : best;
  double gap = p.gap;
  if (std::isnan(gap) && std::isfinite(inc) && std::isfinite(p.best_bound)) {
    gap = milp::RelativeGap(inc, p.best_bound);
  }
  os << milp::ToString(p.phase) << ": incumbent " << F(inc) << ", bound " << F(p.best_bound)
     << ", gap " << FormatPercent(gap) << ", " << p.nodes << " nodes"
     << (p.new_incumbent ? " (new incumbent)" : "");
  return os.str();
}

// What a solve run produced besides the model.
struct SolveRun {
  transcription::ScheduleResult result;
  std::optional<transcription::ConjunctionSolve> rounds;  // budget rounds of a conjunction
  std::optional<transcription::ConjunctionCheckReport> conjunction;  // the plan's verification
  std::optional<transcription::MinTimeResult> min_time;              // "objective": "min_time"
  std::string nonlinear_error;  // the nonlinear replay failed (the linear check kept)
  bool interrupted = false;
};

// The model `export-mps` and `--export-*` write: the schedule MILP, or the
// first MILP of a minimum-time scenario (arrival time as its objective).
milp::LpData ScenarioExportLp(const Scenario& s, const transcription::ScheduleMilp& milp) {
  if (s.min_time) return transcription::MinTimeArrivalLp(s.problem, *s.min_time, s.build);
  return transcription::ExportLp(milp);
}

// The built model's size and notes on stderr, and the --export-* files.
void ReportBuild(const SolveArgs& a, const Scenario& s, const transcription::ScheduleMilp& milp,
                 std::ostream& err) {
  if (!a.quiet) {
    err << "model: " << MilpLine(milp, s) << "; discretised in "
        << Secs(milp.stats().discretise_seconds) << ", built in "
        << Secs(milp.stats().build_seconds) << "\n";
  }
  for (const std::string& reason : milp.infeasibility_reasons()) {
    err << "note: infeasible by construction: " << reason << "\n";
  }
  if (!a.export_mps.empty() || !a.export_lp.empty()) {
    const milp::LpData exported = ScenarioExportLp(s, milp);
    if (!a.export_mps.empty()) WriteScenarioModelFile(a.export_mps, exported, s.name, false);
    if (!a.export_lp.empty()) WriteScenarioModelFile(a.export_lp, exported, s.name, false);
  }
}

// The scenario's solve options with the CLI's observers: progress on stderr
// once the solve has run for a few seconds, Ctrl-C, the diagnosis notice.
transcription::SolveScheduleOptions CliSolveOptions(const SolveArgs& a, const Scenario& s,
                                                    std::ostream& err) {
  transcription::SolveScheduleOptions opt{};
  opt.build = s.build;
  opt.milp = s.solve;
  opt.check_schedule = false;  // checked by CheckRun, with its own timing and messages
  opt.search = s.search_options;
  opt.search.enabled = s.search;
  const bool quiet = a.quiet;
  opt.milp.progress = CliProgress(quiet, err, a.hooks.on_progress);
  opt.milp.interrupt = InterruptWatcher::flag();
  opt.prefix_diagnosis_s = s.diagnosis_time_limit_s;
  opt.announce = [quiet, &err](const std::string& what) {
    if (!quiet) err << what << " (--no-diagnose skips this)\n";
  };
  return opt;
}

// Solves under the Ctrl-C watcher (budget rounds for a conjunction).
void SolveUnderWatcher(const SolveArgs& a, const Scenario& s,
                       const transcription::ScheduleMilp& milp,
                       const transcription::SolveScheduleOptions& opt, Clock::time_point t_start,
                       SolveRun* run, std::ostream& err) {
  if (!a.quiet) {
    err << "solving with " << milp::CbcVersion() << " (time limit " << F(s.solve.time_limit_s)
        << " s, relative gap " << F(s.solve.relative_gap) << ", " << s.solve.threads
        << " thread(s)); Ctrl-C stops and keeps the best schedule found\n";
  }
  const std::unique_ptr<milp::Solver> solver = milp::MakeCbcSolver();
  {
    InterruptWatcher watcher;
    if (s.min_time) {
      run->min_time = SolveScenarioMinTime(s, *solver, opt);
      run->result = MinTimeScheduleResult(*run->min_time, *s.min_time);
    } else if (s.problem.conjunction) {
      run->rounds = transcription::SolveConjunction(milp, *solver, opt, s.conjunction_solve);
      run->result = run->rounds->result;
    } else {
      run->result = transcription::SolveBuilt(milp, *solver, opt);
    }
  }
  run->interrupted = InterruptWatcher::interrupted();
  if (run->interrupted) {
    err << "interrupted (" << InterruptWatcher::signal_name() << ") after " << Secs(Since(t_start))
        << ": "
        << (run->result.has_schedule() ? "checking and writing the best schedule found"
                                       : "no schedule was found; writing the summary")
        << "\n";
  }
}

// The checker on the schedule found, and the conjunction's verification.
void CheckRun(const SolveArgs& a, const Scenario& s, SolveRun* run, std::ostream& err) {
  transcription::ScheduleResult& r = run->result;
  if (!r.has_schedule()) return;
  if (!a.quiet) {
    err << "checking the schedule"
        << (s.check.nonlinear ? " (linear re-propagation and nonlinear replay)" : "") << "\n";
  }
  const Clock::time_point tc = Clock::now();
  if (s.impulsive()) {
    r.impulsive_check = transcription::CheckImpulses(s.problem, r.schedule.impulses);
  } else {
    r.check = CheckWithLinearFallback(s, r.schedule.burns, &run->nonlinear_error);
  }
  r.checked = true;
  r.check_seconds = Since(tc);
  if (s.problem.conjunction) {
    if (!a.quiet) err << "verifying the conjunction (computed risk, Monte Carlo)\n";
    run->conjunction = VerifyConjunction(s, r.schedule.burns, r.schedule.impulses);
  }
}

// schedule.csv (impulses.csv), trajectory.csv, the plots and the CCSDS
// files of a run with a schedule; appends their names to `files`.
void WriteScheduleFiles(const SolveArgs& a, const Scenario& s, const RunFolder& folder,
                        const transcription::ScheduleResult& r, std::vector<std::string>* files,
                        std::ostream& err) {
  if (!r.has_schedule()) return;
  const std::string& dir = folder.path();
  if (s.impulsive()) {
    WriteImpulsesCsv(dir + "/impulses.csv", s, r.schedule.impulses);
    WriteScheduleCsv(dir + "/schedule.csv", s, {});
    WriteImpulsiveTrajectoryCsv(dir + "/trajectory.csv", s, r.schedule.impulses);
    files->insert(files->end(), {"schedule.csv", "impulses.csv", "trajectory.csv"});
  } else {
    WriteScheduleCsv(dir + "/schedule.csv", s, r.schedule.burns);
    WriteTrajectoryCsv(dir + "/trajectory.csv", s, r.check, r.schedule.burns);
    files->insert(files->end(), {"schedule.csv", "trajectory.csv"});
  }
  WritePlotsReport(folder, s, r.check.nonlinear_checked, a.no_plots, files, err);
  if (a.ccsds.any()) {
    for (const std::string& f :
         WriteFlightDynamicsFiles(s, InFolder(a.ccsds, folder),
                                  {ScenarioReplayLeg(s, r.schedule.burns, r.check.sample_times)})) {
      files->push_back(ShownPath(folder, f));
    }
  }
}

// summary.json and report.html (a report that fails is a note, not an error).
void WriteSummaryAndReport(const SolveArgs& a, const Scenario& s, const std::string& dir,
                           const nlohmann::json& summary, std::vector<std::string>* files,
                           std::ostream& err) {
  WriteJsonFile(dir + "/summary.json", summary);
  if (a.no_report) return;
  try {
    WriteSolveReport(dir, s, summary);
    files->push_back(kReportName);
  } catch (const std::exception& e) {
    err << "note: " << kReportName << " not written: " << e.what() << "\n";
  }
}

// The status, objective, consumption and burns lines of the human summary.
void PrintOutcome(std::ostream& out, const Scenario& s, const SolveRun& run) {
  const transcription::ScheduleResult& r = run.result;
  const milp::SolveResult& sr = r.solve;
  out << "status        " << StatusName(sr.status);
  if (run.interrupted) out << " (interrupted)";
  if (sr.has_solution()) {
    out << ", objective " << F(sr.objective, 8) << " (" << ToString(s.problem.objective.kind)
        << "), best bound " << F(sr.best_bound, 8) << ", gap " << FormatPercent(sr.gap);
  }
  out << "\n";
  if (run.rounds) PrintConjunctionSolve(out, *run.rounds);
  if (run.min_time) PrintMinTime(out, *run.min_time);
  if (!sr.detail.empty() && !sr.has_solution()) out << "solver says   " << sr.detail << "\n";
  for (const std::string& reason : r.infeasibility_reasons)
    out << "reason        " << reason << "\n";
  if (!r.has_schedule()) return;
  const transcription::Schedule& sch = r.schedule;
  out << "consumption   " << F(sch.consumption_l1_m_s, 6) << " m/s (L1 thesis metric), delta-v "
      << F(sch.delta_v_m_s, 6) << " m/s, propellant " << F(sch.propellant_kg, 6) << " kg\n";
  if (s.impulsive()) {
    out << "impulses      " << sch.impulses.size()
        << (sch.impulses.empty() ? "" : ": " + BurnCounts(s, sch)) << "\n";
  } else {
    out << "burns         " << sch.burns.size()
        << (sch.burns.empty() ? "" : ": " + BurnCounts(s, sch)) << "\n";
  }
}

// The times line and the checker's lines of the human summary.
void PrintTimesAndCheck(std::ostream& out, const Scenario& s, const SolveRun& run,
                        double total_seconds) {
  const transcription::ScheduleResult& r = run.result;
  const milp::SolveResult& sr = r.solve;
  out << "times         discretise " << Secs(r.stats.discretise_seconds) << ", build "
      << Secs(r.stats.build_seconds) << ", solve " << Secs(sr.wall_seconds);
  if (!sr.incumbents.empty())
    out << " (first solution " << Secs(sr.incumbents.front().wall_seconds) << ")";
  if (r.diagnosis_seconds > 0.0) out << ", diagnose " << Secs(r.diagnosis_seconds);
  if (r.checked) out << ", check " << Secs(r.check_seconds);
  out << ", total " << Secs(total_seconds) << "\n";
  if (r.checked) {
    if (s.impulsive()) {
      PrintImpulsiveCheck(out, s, r.impulsive_check, JudgeImpulsive(s, r.impulsive_check));
    } else {
      PrintCheck(out, s, r.check, Judge(s, r.check));
    }
    if (!run.nonlinear_error.empty())
      out << "note          nonlinear replay failed: " << run.nonlinear_error << "\n";
  }
  if (run.conjunction) PrintConjunctionCheck(out, *run.conjunction);
}

}  // namespace

std::function<void(const milp::SolveProgress&)> CliProgress(
    bool quiet, std::ostream& err, std::function<void(const milp::SolveProgress&)> hook) {
  // The best incumbent seen so far: progress reports between incumbents may
  // carry NaN for it, and the line should still show it.
  auto best = std::make_shared<double>(std::nan(""));
  return [quiet, best, &err, hook = std::move(hook)](const milp::SolveProgress& p) {
    if (hook) hook(p);
    if (std::isfinite(p.objective) && !(p.objective >= *best)) *best = p.objective;
    if (quiet || p.wall_seconds < 3.0) return;
    err << "  [" << Secs(p.wall_seconds) << "] " << ProgressLine(p, *best) << "\n";
  };
}

int SolveExitCode(milp::SolveStatus status) {
  switch (status) {
    case milp::SolveStatus::kOptimal:
    case milp::SolveStatus::kFeasible:
      return kExitOk;
    case milp::SolveStatus::kInfeasible:
      return kExitInfeasible;
    case milp::SolveStatus::kNoSolutionFound:
      return kExitNoSolution;
    case milp::SolveStatus::kUnbounded:
    case milp::SolveStatus::kError:
      return kExitInternal;
  }
  return kExitInternal;
}

int RunSolve(const SolveArgs& a) {
  if (IsFleetFile(a.scenario)) return RunFleetSolve(a);
  const Clock::time_point t_start = Clock::now();
  Scenario s = LoadWithOverrides(a.scenario, a.overrides);
  if (!a.export_mps.empty()) ModelFileExtension(a.export_mps, "--export-mps");
  if (!a.export_lp.empty()) ModelFileExtension(a.export_lp, "--export-lp");
  CheckFlightDynamicsFiles(s, a.ccsds, s.problem.grid.front(), s.problem.grid.back());
  const std::string target =
      a.out_dir.empty() ? "out/" + fs::path(a.scenario).stem().string() : a.out_dir;
  RunFolder folder(target, a.force, a.command_line);
  std::ostream& err = std::cerr;
  if (!a.quiet) err << "building the model: " << ModelLine(s) << "\n";
  const transcription::ScheduleMilp milp(s.problem, s.build);
  ReportBuild(a, s, milp, err);

  SolveRun run;
  SolveUnderWatcher(a, s, milp, CliSolveOptions(a, s, err), t_start, &run, err);
  CheckRun(a, s, &run, err);

  std::vector<std::string> files = {"summary.json"};
  WriteScheduleFiles(a, s, folder, run.result, &files, err);
  RunFacts facts;
  facts.interrupted = run.interrupted;
  facts.command_line = a.command_line;
  facts.total_seconds = Since(t_start);
  facts.nonlinear_error = run.nonlinear_error;
  facts.conjunction_solve = run.rounds ? &*run.rounds : nullptr;
  facts.conjunction_check = run.conjunction ? &*run.conjunction : nullptr;
  facts.min_time = run.min_time ? &*run.min_time : nullptr;
  WriteSummaryAndReport(a, s, folder.path(), SummaryJson(s, milp, run.result, facts), &files, err);
  const std::string replaced = folder.Commit();
  if (!replaced.empty()) err << "note: " << replaced << "\n";

  std::ostream& out = std::cout;
  out << "scenario      " << s.name << " (" << a.scenario << ")\n";
  out << "model         " << ModelLine(s) << "\n";
  out << "MILP          " << MilpLine(milp, s) << "\n";
  if (milp.keep_out()) PrintKeepOut(out, *milp.keep_out());
  PrintOutcome(out, s, run);
  PrintTimesAndCheck(out, s, run, facts.total_seconds);
  out << "output        " << target << " (" << JoinNames(files) << ")\n";
  out.flush();
  return SolveExitCode(run.result.solve.status);
}

int RunExport(const ExportArgs& a) {
  if (IsFleetFile(a.scenario)) return RunFleetExport(a);
  const Scenario s = LoadWithOverrides(a.scenario, a.overrides);
  const transcription::ScheduleMilp milp(s.problem, s.build);
  const milp::LpData exported = ScenarioExportLp(s, milp);
  WriteScenarioModelFile(a.file, exported, s.name, a.obfuscate_names);
  std::cout << "wrote " << a.file << ": ";
  if (s.min_time) {
    std::cout << exported.num_cols() << " columns, " << exported.num_rows()
              << " rows (the schedule MILP with the arrival indicators arrive_at_<node>)\n"
              << "objective: arrival time (s from the horizon start), minimisation; the fuel ("
              << ToString(s.problem.objective.kind)
              << ") at that arrival is a second MILP, not exported; binaries named "
                 "on_<thruster index>_<interval> (thrusters: "
              << JoinNames(s.thruster_names()) << ")\n";
    return kExitOk;
  }
  std::cout << MilpLine(milp, s) << "\n"
            << "objective: " << ToString(s.problem.objective.kind)
            << (s.problem.objective.kind == transcription::ObjectiveKind::kPropellant ? " (kg)"
                                                                                      : " (m/s)")
            << ", minimisation; binaries named on_<thruster index>_<interval> (thrusters: "
            << JoinNames(s.thruster_names()) << ")\n";
  return kExitOk;
}

int RunCheck(const CheckArgs& a) {
  const Scenario s = LoadScenario(a.scenario);
  CheckFlightDynamicsFiles(s, a.ccsds, s.problem.grid.front(), s.problem.grid.back());
  std::ostream& out = std::cout;
  std::vector<std::string> files;
  bool passed = false;
  std::optional<RunFolder> folder;
  if (!a.out_dir.empty()) folder.emplace(a.out_dir, a.force, a.command_line);
  const std::string dir = folder ? folder->path() : "";
  const Clock::time_point tc = Clock::now();
  if (s.impulsive()) {
    const std::vector<transcription::Impulse> imp = ReadImpulsesCsv(a.schedule, s);
    const transcription::ImpulsiveCheck c = transcription::CheckImpulses(s.problem, imp);
    const CheckVerdict v = JudgeImpulsive(s, c);
    transcription::Schedule sch;
    sch.impulses = imp;
    double dv = 0.0;
    for (const auto& i : imp) dv += i.delta_v_m_s;
    out << "schedule      " << a.schedule << ": " << imp.size() << " impulses, total " << F(dv, 8)
        << " m/s\n";
    PrintImpulsiveCheck(out, s, c, v);
    const auto conjunction = VerifyConjunction(s, {}, imp);
    if (conjunction) PrintConjunctionCheck(out, *conjunction);
    passed = v.passed && (!conjunction || conjunction->passed());
    if (folder) {
      nlohmann::json j = ImpulsiveCheckJson(s, c, v, Since(tc));
      if (conjunction) j["conjunction"] = ConjunctionJson(std::nullopt, nullptr, &*conjunction);
      WriteJsonFile(dir + "/check.json", j);
      WriteImpulsesCsv(dir + "/impulses.csv", s, imp);
      WriteScheduleCsv(dir + "/schedule.csv", s, {});
      WriteImpulsiveTrajectoryCsv(dir + "/trajectory.csv", s, imp);
      files = {"check.json", "impulses.csv", "trajectory.csv"};
      WritePlotsReport(*folder, s, false, a.no_plots, &files, std::cerr);
    }
  } else {
    const std::vector<transcription::Burn> burns = ReadScheduleCsv(a.schedule, s);
    std::string nonlinear_error;
    const transcription::CheckReport r = CheckWithLinearFallback(s, burns, &nonlinear_error);
    const CheckVerdict v = Judge(s, r);
    transcription::Schedule sch;
    sch.burns = burns;
    transcription::ComputeTotals(s.problem.thrusters, &sch);
    out << "schedule      " << a.schedule << ": " << burns.size() << " burns"
        << (burns.empty() ? "" : " (" + BurnCounts(s, sch) + ")") << ", consumption "
        << F(sch.consumption_l1_m_s, 8) << " m/s (L1), delta-v " << F(sch.delta_v_m_s, 8)
        << " m/s, propellant " << F(sch.propellant_kg, 8) << " kg\n";
    PrintCheck(out, s, r, v);
    if (!nonlinear_error.empty())
      out << "note          nonlinear replay failed: " << nonlinear_error << "\n";
    const auto conjunction = VerifyConjunction(s, burns, {});
    if (conjunction) PrintConjunctionCheck(out, *conjunction);
    passed = v.passed && (!conjunction || conjunction->passed());
    if (folder) {
      nlohmann::json j = CheckJson(s, r, v, Since(tc));
      if (conjunction) j["conjunction"] = ConjunctionJson(std::nullopt, nullptr, &*conjunction);
      j["consumption_l1_m_s"] = sch.consumption_l1_m_s;
      j["delta_v_m_s"] = sch.delta_v_m_s;
      j["propellant_kg"] = sch.propellant_kg;
      j["n_burns"] = burns.size();
      if (!nonlinear_error.empty()) j["nonlinear_error"] = nonlinear_error;
      WriteJsonFile(dir + "/check.json", j);
      WriteScheduleCsv(dir + "/schedule.csv", s, burns);
      WriteTrajectoryCsv(dir + "/trajectory.csv", s, r, burns);
      files = {"check.json", "schedule.csv", "trajectory.csv"};
      WritePlotsReport(*folder, s, r.nonlinear_checked, a.no_plots, &files, std::cerr);
    }
    if (a.ccsds.any()) {
      const FlightDynamicsFiles where = folder ? InFolder(a.ccsds, *folder) : a.ccsds;
      for (const std::string& f :
           WriteFlightDynamicsFiles(s, where, {ScenarioReplayLeg(s, burns, r.sample_times)})) {
        out << "wrote         " << (folder ? ShownPath(*folder, f) : f) << "\n";
      }
    }
  }
  if (folder) {
    const std::string replaced = folder->Commit();
    if (!replaced.empty()) std::cerr << "note: " << replaced << "\n";
    out << "output        " << a.out_dir << " (" << JoinNames(files) << ")\n";
  }
  return passed ? kExitOk : kExitCheckFailed;
}

int RunImportSolution(const ImportArgs& a) {
  const SolutionFormat format = ParseSolutionFormat(a.format);
  const Scenario s = LoadWithOverrides(a.scenario, a.overrides);
  if (s.min_time) {
    throw ScenarioError(
        "scenario.objective: import-solution reads solutions of the schedule "
        "MILP; a \"min_time\" scenario's exported MILP is its arrival MILP "
        "(solve the scenario with `thrustsched solve`)");
  }
  const ImportedSolution sol = ReadSolutionFile(a.solution, format);
  std::ostream& out = std::cout;
  out << "solution      " << a.solution << ": status \"" << sol.status << "\", objective "
      << F(sol.objective, 10) << "\n";
  if (!sol.has_solution) {
    std::cerr << "error: the solution file holds no feasible solution (status \"" << sol.status
              << "\")\n";
    return sol.status.find("nfeasible") != std::string::npos ||
                   sol.status.find("EMPTY") != std::string::npos ||
                   sol.status.find("infeasible") != std::string::npos
               ? kExitInfeasible
               : kExitNoSolution;
  }
  const transcription::ScheduleMilp milp(s.problem, s.build);
  const std::vector<std::string> names = milp::ExportedColumnNames(milp.lp(), a.obfuscate_names);
  const Eigen::VectorXd x = ToColumnVector(sol, names);
  const transcription::Schedule sch = milp.Decode(x);
  const double objective = milp.lp().Objective(x);
  const double violation = milp.lp().MaxViolation(x);
  if (s.impulsive()) {
    WriteImpulsesCsv(a.out, s, sch.impulses);
  } else {
    WriteScheduleCsv(a.out, s, sch.burns);
  }
  out << "model         " << MilpLine(milp, s) << "\n"
      << "objective     " << F(objective, 10) << " recomputed on our model ("
      << ToString(s.problem.objective.kind) << "); largest row/bound/integrality violation "
      << F(violation, 3) << "\n";
  if (s.impulsive()) {
    out << "impulses      " << sch.impulses.size() << ", total " << F(sch.consumption_l1_m_s, 8)
        << " m/s (L1)\n";
  } else {
    out << "burns         " << sch.burns.size() << ", consumption " << F(sch.consumption_l1_m_s, 8)
        << " m/s (L1)\n";
  }
  out << "wrote         " << a.out << " (check it with: thrustsched check " << a.scenario << " "
      << a.out << ")\n";
  return kExitOk;
}

int RunValidate(const ValidateArgs& a) {
  if (IsFleetFile(a.scenario)) {
    FleetScenario f = LoadFleetScenario(a.scenario);
    ApplyFleetOverrides(a.overrides, &f);
    std::cout << "fleet         " << f.name << ": valid, " << f.members.size() << " members\n";
    if (a.build) {
      const transcription::FleetMilp milp(f.problem, f.options.build);
      std::cout << "MILP          " << milp.stats().num_binaries << " binaries, "
                << milp.stats().num_columns << " columns, " << milp.stats().num_rows << " rows\n";
    }
    return kExitOk;
  }
  const Scenario s = LoadWithOverrides(a.scenario, a.overrides);
  std::cout << "scenario      " << s.name << ": valid\n"
            << "model         " << ModelLine(s) << "\n";
  if (a.build) {
    const transcription::ScheduleMilp milp(s.problem, s.build);
    std::cout << "MILP          " << MilpLine(milp, s) << "\n";
    if (milp.keep_out()) PrintKeepOut(std::cout, *milp.keep_out());
    for (const std::string& reason : milp.infeasibility_reasons()) {
      std::cout << "reason        infeasible by construction: " << reason << "\n";
    }
  }
  return kExitOk;
}

}  // namespace thrustsched::app
