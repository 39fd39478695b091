// `thrustsched simulate`: the run (app/simulate.h). Its files: the
// long_horizon section (simulate_setup.cc), the checkpoint and crash guard
// (simulate_checkpoint.cc, simulate_crash_guard.cc), cycles.csv and year.json
// (simulate_records.cc), the plots (simulate_plots.cc).
#include "app/simulate.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>

#include "app/commands.h"
#include "app/format_units.h"
#include "app/html_report.h"
#include "app/interrupt.h"
#include "app/outputs.h"
#include "app/run_folder.h"
#include "app/simulate_internal.h"
#include "milp/cbc_solver.h"

namespace thrustsched::app {
namespace {

namespace fs = std::filesystem;
using namespace simulate_detail;
using planning::CycleRecord;
using planning::Fallback;

std::string ProgressLine(const CycleRecord& c, int total, const std::string& epoch, double consumed,
                         double eta) {
  std::ostringstream os;
  os << "cycle " << c.index + 1 << "/" << total << " " << Utc(epoch, c.start_s).substr(0, 10)
     << ": " << StatusName(c.status);
  if (c.fallback != Fallback::kNone) os << " (fallback " << ToString(c.fallback) << ")";
  os << ", solve " << G(c.solve_seconds, 3) << " s, gap "
     << (std::isfinite(c.gap) ? G(100.0 * c.gap, 3) + "%" : std::string("n/a")) << ", "
     << G(c.consumption_l1_m_s, 4) << " m/s (total " << G(consumed, 5) << " m/s L1), max |lat| "
     << G(c.max_abs_lat_deg, 3) << " |lon| " << G(c.max_abs_lon_deg, 3) << " deg"
     << (c.time_outside_window_s > 0 ? ", " + G(c.time_outside_window_s, 4) + " s OUTSIDE" : "")
     << (c.controllable ? "" : ", UNCONTROLLABLE") << "; ETA " << Hms(eta);
  return os.str();
}

// A folder holding an earlier run is continued (--resume) or started over
// (--force: the earlier run's files are removed first), never silently
// overwritten: hours of cycles would be lost.
void PrepareFolder(const std::string& dir, const SimulateArgs& a, std::ostream& err) {
  if (a.resume && a.force) {
    throw ScenarioError("--resume and --force: choose one (continue the run in " + dir +
                        ", or start it over)");
  }
  const FolderContents before = InspectFolder(dir);
  if (!before.holds_run() || a.resume) return;
  if (!a.force) {
    throw ScenarioError(
        dir + " holds an earlier run (" +
        (fs::exists(dir + "/checkpoint.json") ? std::string("checkpoint.json, ") : std::string()) +
        std::to_string(before.run_files.size()) +
        " file(s)): use --resume to continue it, or --force to start over");
  }
  RemoveEarlierRun(dir, before);
  if (!a.quiet) {
    err << "note: --force: removed the earlier run's " << before.run_files.size() << " file(s) in "
        << dir << "\n";
  }
}

// Everything one run of RunSimulate works on.
struct YearRun {
  explicit YearRun(const SimulateArgs& a) : args(a) {}
  const SimulateArgs& args;
  SimulationSetup setup;
  std::string dir;
  std::string checkpoint;
  std::string epoch;
  Clock::time_point started;
  std::shared_ptr<const dynamics::GeoSimulator> simulator;
  std::shared_ptr<const milp::Solver> solver;
  std::optional<planning::LongHorizonSimulation> run;
  int total = 0;   // cycles of the scenario
  int target = 0;  // cycles this run reaches
  planning::LongHorizonState state;
  std::vector<CycleRecord> cycles;
  std::ostream& err = std::cerr;

  const Scenario& scenario() const { return setup.scenario; }
  bool quiet() const { return args.quiet; }
};

// The folder, the solver and the stop request; the run's first state (from
// the checkpoint with --resume) and cycles.csv regenerated from it.
void StartRun(YearRun* y) {
  const SimulateArgs& a = y->args;
  PrepareFolder(y->dir, a, y->err);
  MakeDirectory(y->dir);
  MakeDirectory(y->dir + "/cycles");
  std::vector<std::string> manifest = {
      "checkpoint.json", kInProgressFile, "cycles.csv",     "cycles",          "year.json",
      "trajectory.csv",  "gnuplot.log",   "consumption.gp", "consumption.svg", "vectors.gp",
      "vectors.svg",     "latlon.gp",     "latlon.svg",     "timeline.gp",     "timeline.svg"};
  for (const std::string& f : YearReportFiles()) manifest.push_back(f);
  WriteManifest(y->dir, manifest, a.command_line);
  const Scenario& s = y->scenario();
  y->epoch = s.geo->epoch;
  CheckFlightDynamicsFiles(s, a.ccsds, y->setup.options.start_s,
                           y->setup.options.start_s + y->setup.options.duration_s);

  // Ctrl-C stops the running solve; that unfinished cycle is not recorded.
  milp::SolveOptions& solve = y->setup.options.solve.milp;
  solve.interrupt = a.interrupt != nullptr ? a.interrupt : InterruptWatcher::flag();
  if (a.hooks.on_progress) solve.progress = a.hooks.on_progress;
  y->simulator = std::make_shared<const dynamics::GeoSimulator>(*s.geo);
  y->solver = std::shared_ptr<const milp::Solver>(milp::MakeCbcSolver().release());
  y->run.emplace(s.problem, y->setup.options, y->simulator, y->solver);
  y->total = y->run->num_cycles();
  y->target = a.cycles > 0 ? std::min(a.cycles, y->total) : y->total;

  if (a.resume && fs::exists(y->checkpoint)) {
    ReadCheckpoint(y->checkpoint, y->setup, s.problem.thrusters.size(), &y->state, &y->cycles);
    if (!y->quiet()) {
      y->err << "resuming " << s.name << " after cycle " << y->state.next_cycle << "/" << y->total
             << " (" << Utc(y->epoch, y->state.time_s) << ")\n";
    }
  } else {
    if (a.resume && !y->quiet()) {
      y->err << "note: no checkpoint in " << y->dir << ": starting at cycle 1\n";
    }
    y->state = y->run->InitialState();
    WriteAtomically(y->checkpoint, CheckpointJson(y->setup, y->state, y->cycles).dump(1) + "\n");
  }
  // cycles.csv is regenerated from the checkpoint's records (so a row
  // appended by a cycle whose checkpoint was never written disappears).
  std::string text = CyclesCsvHeader();
  for (const CycleRecord& c : y->cycles) text += CyclesCsvRow(c, y->epoch);
  WriteAtomically(y->dir + "/cycles.csv", text);
}

void Announce(const YearRun& y) {
  if (y.quiet()) return;
  const planning::LongHorizonOptions& o = y.setup.options;
  y.err << y.scenario().name << ": " << y.total << " " << ToString(o.mode) << " cycles of "
        << G(o.cycle_s / common::kSecondsPerDay, 4) << " d"
        << (o.mode == planning::HorizonMode::kReceding
                ? " (applied " + G(o.control_s / common::kSecondsPerDay, 4) + " d)"
                : std::string())
        << " at " << G(o.step_s) << " s, time limit " << G(o.solve.milp.time_limit_s) << " s, gap "
        << G(o.solve.milp.relative_gap) << " per cycle; running cycles " << y.state.next_cycle + 1
        << ".." << y.target
        << "; Ctrl-C stops (finished cycles are kept, continue with --resume)\n";
}

// Solves cycle k inside the crash guard; `retry`: an earlier process died in
// it, so CBC's preprocessing and presolve are off this time.
CycleRecord SolveCycle(YearRun* y, int k, bool retry) {
  const std::string in_progress = y->dir + "/" + kInProgressFile;
  InProgressGuard guard(in_progress, y->setup.fingerprint, k + 1, retry);
  if (y->args.hooks.in_cycle) y->args.hooks.in_cycle(k + 1);
  if (!retry) return y->run->RunCycle(&y->state);
  planning::LongHorizonOptions safe = y->setup.options;
  safe.solve.milp.presolve = false;
  CycleRecord rec =
      planning::LongHorizonSimulation(y->scenario().problem, safe, y->simulator, y->solver)
          .RunCycle(&y->state);
  rec.note += std::string(rec.note.empty() ? "" : "; ") +
              "an earlier run died inside this cycle's solve (solver crash); solved with "
              "CBC preprocessing and presolve off";
  return rec;
}

// The finished cycle's files, then the checkpoint and the totals so far.
void RecordCycle(YearRun* y, CycleRecord rec) {
  const int k = rec.index;
  const std::string& dir = y->dir;
  const ReplayLeg leg = CycleReplayLeg(rec, y->setup.options.step_s);
  WriteScheduleCsv(dir + "/cycles/" + CycleTag(k) + ".csv", y->scenario(), rec.burns, &leg);
  WriteTextFile(dir + "/cycles/" + CycleTag(k) + "_trajectory.csv",
                TrajectoryHeader() + TrajectoryRows(y->setup, rec, k + 1 == y->total));
  {
    std::ofstream out(dir + "/cycles.csv", std::ios::app | std::ios::binary);
    out << CyclesCsvRow(rec, y->epoch);
    out.flush();
    if (!out) throw std::runtime_error(dir + "/cycles.csv: write failed");
  }
  rec.sample_times.clear();
  rec.sample_outputs.clear();
  rec.sample_states.clear();
  y->cycles.push_back(std::move(rec));
  WriteAtomically(y->checkpoint, CheckpointJson(y->setup, y->state, y->cycles).dump(1) + "\n");
  // The totals so far ("complete": false until the last cycle).
  WriteAtomically(dir + "/year.json",
                  YearJson(y->setup, y->cycles, y->total, Since(y->started)).dump(2) + "\n");
}

void ReportCycle(const YearRun& y, double consumed, double eta_s) {
  if (y.quiet()) return;
  const CycleRecord& last = y.cycles.back();
  y.err << ProgressLine(last, y.total, y.epoch, consumed, eta_s) << "\n";
  for (const planning::CycleAttempt& at : last.attempts) {
    if (at.level != Fallback::kNone || at.status != last.status) {
      y.err << "  attempt " << ToString(at.level) << ": " << StatusName(at.status) << " after "
            << G(at.solve_seconds, 3) << " s (" << at.detail.substr(0, 160) << ")\n";
    }
  }
}

// Runs the cycles up to the target; true when a stop request ended the run.
bool RunCycles(YearRun* y) {
  const SimulateArgs& a = y->args;
  auto stop_requested = [&a] {
    return a.interrupt != nullptr ? a.interrupt->load() : InterruptWatcher::interrupted();
  };
  // Crash guard: only an earlier process can have left a marker, and only for
  // the first cycle this run solves (each cycle's guard removes its own).
  const std::string in_progress = y->dir + "/" + kInProgressFile;
  const std::optional<InProgress> died = ReadInProgress(in_progress, y->setup.fingerprint);
  const int first_cycle = y->state.next_cycle;
  double consumed = 0;
  for (const CycleRecord& c : y->cycles) consumed += c.consumption_l1_m_s;
  double this_run_cycles_wall = 0;
  int this_run_cycles = 0;
  std::optional<InterruptWatcher> watcher;
  if (a.interrupt == nullptr) watcher.emplace();
  while (y->state.next_cycle < y->target) {
    const int k = y->state.next_cycle;
    if (!y->quiet()) {
      y->err << "cycle " << k + 1 << "/" << y->total << " "
             << Utc(y->epoch, y->run->Times(k).start_s) << ": solving...\n";
    }
    const bool retry = k == first_cycle && died.has_value() && died->cycle == k + 1;
    if (retry && died->safe) {
      throw std::runtime_error("cycle " + std::to_string(k + 1) +
                               " ended the process twice (the second time with "
                               "CBC preprocessing off): the solver crashes on this cycle's MILP; " +
                               in_progress + " records it (remove that file to try again)");
    }
    if (retry && !y->quiet()) {
      y->err << "note: an earlier run died while solving cycle " << k + 1
             << " (a crash inside the solver); solving it with CBC preprocessing off (if that run "
                "was killed from outside instead, stop, remove "
             << in_progress << " and resume to solve it as configured)\n";
    }
    CycleRecord rec = SolveCycle(y, k, retry);
    // Ctrl-C during the solve: the cycle is incomplete and not recorded.
    // Ctrl-C after it (replay): the cycle is complete and recorded.
    const bool interrupted = rec.interrupted || stop_requested();
    if (rec.interrupted) return true;
    consumed += rec.consumption_l1_m_s;
    this_run_cycles_wall += rec.wall_seconds;
    ++this_run_cycles;
    RecordCycle(y, std::move(rec));
    if (a.on_cycle) a.on_cycle(y->cycles.back(), y->state.next_cycle, y->target);
    const double per = this_run_cycles_wall / this_run_cycles;
    ReportCycle(*y, consumed, per * (y->target - y->state.next_cycle));
    if (interrupted) return true;
  }
  return false;
}

// trajectory.csv, year.json, the flight-dynamics files and the plots, from
// all finished cycles; returns the names of the files written.
std::vector<std::string> WriteRunFiles(const YearRun& y) {
  const std::string& dir = y.dir;
  std::string text = TrajectoryHeader();
  for (const CycleRecord& c : y.cycles) {
    std::ifstream in(dir + "/cycles/" + CycleTag(c.index) + "_trajectory.csv", std::ios::binary);
    std::string line;
    bool first = true;
    while (std::getline(in, line)) {
      if (first) {
        first = false;
        continue;
      }
      text += line + "\n";
    }
  }
  WriteTextFile(dir + "/trajectory.csv", text);
  const nlohmann::json year = YearJson(y.setup, y.cycles, y.total, Since(y.started));
  WriteJsonFile(dir + "/year.json", year);
  std::vector<std::string> files = {"cycles.csv", "year.json", "trajectory.csv", "checkpoint.json",
                                    "cycles/"};
  if (y.args.ccsds.any() && !y.cycles.empty()) {
    std::vector<ReplayLeg> legs;
    for (const CycleRecord& c : y.cycles) legs.push_back(CycleReplayLeg(c, y.setup.options.step_s));
    for (const std::string& f : WriteFlightDynamicsFiles(y.scenario(), y.args.ccsds, legs)) {
      files.push_back(f);
    }
  }
  if (!y.cycles.empty()) {
    const PlotFiles p = WriteYearPlots(dir, y.setup, y.cycles, !y.args.no_plots);
    files.insert(files.end(), p.images.begin(), p.images.end());
    if (!p.message.empty()) y.err << "note: " << p.message << "\n";
    if (!y.args.no_report) {
      const YearReport rep = WriteYearReport(dir, y.scenario(), year, !y.args.no_plots);
      files.insert(files.end(), rep.images.begin(), rep.images.end());
      files.push_back(kReportName);
      if (!rep.message.empty()) y.err << "note: " << rep.message << "\n";
    }
  }
  return files;
}

// The human summary on stdout.
void PrintSummary(const YearRun& y, const std::vector<std::string>& files, bool interrupted) {
  std::ostream& out = std::cout;
  const Scenario& s = y.scenario();
  const planning::LongHorizonSummary sum = planning::Summarize(y.cycles, s.problem.thrusters);
  out << "scenario      " << s.name << " (" << y.args.scenario << ")\n"
      << "cycles        " << sum.cycles << "/" << y.total << " (" << ToString(y.setup.options.mode)
      << ", " << G(sum.simulated_s / common::kSecondsPerDay, 6) << " days simulated)"
      << (interrupted ? ", interrupted" : "") << "\n"
      << "consumption   " << G(sum.consumption_l1_m_s, 6) << " m/s (L1 thesis metric), delta-v "
      << G(sum.delta_v_m_s, 6) << " m/s, normal delta-v " << G(sum.normal_delta_v_m_s, 5)
      << " m/s, propellant " << G(sum.propellant_kg, 5) << " kg, " << sum.burns
      << " burns\n"
      // The total is over the thrusters (as year.json's thrust_days.total):
      // N + S covers every thruster only in the thesis's four-thruster layout
      // (one per face gives ±R thrusters on neither face).
      << "thrust days   total "
      << G(std::accumulate(sum.thrust_days.begin(), sum.thrust_days.end(), 0.0), 5) << "; N "
      << G(sum.north_days, 4) << ", S " << G(sum.south_days, 4) << ", E " << G(sum.east_days, 4)
      << ", W " << G(sum.west_days, 4) << "\n"
      << "window        max |lat| " << G(sum.max_abs_lat_deg, 4) << " deg, max |lon| "
      << G(sum.max_abs_lon_deg, 4) << " deg; "
      << (sum.max_window_violation_deg > 0
              ? "OUTSIDE by up to " + G(sum.max_window_violation_deg, 3) + " deg for " +
                    FormatDuration(sum.time_outside_window_s) + " (first worst at " +
                    Utc(y.epoch, sum.worst_time_s) + ")"
              : std::string("inside the box for the whole run (nonlinear replay)"))
      << "\n"
      << "fallbacks     " << sum.fallback_soft_window << " soft window, "
      << sum.fallback_free_terminal << " soft window + free terminal, " << sum.fallback_zero_thrust
      << " zero thrust; " << sum.uncontrollable_cycles << " uncontrollable cycle(s); "
      << sum.time_limited_cycles
      << " cycle(s) stopped by a limit (node budget or time) above the gap\n"
      << "solve time    median " << G(sum.solve_seconds.median, 3) << " s, p90 "
      << G(sum.solve_seconds.p90, 3) << " s, max " << G(sum.solve_seconds.max, 3)
      << " s; gap median " << FormatPercent(sum.gap.median) << ", max "
      << FormatPercent(sum.gap.max) << "; wall " << Hms(sum.wall_seconds_total)
      << " over all cycles\n"
      << "output        " << y.dir << " (";
  for (size_t i = 0; i < files.size(); ++i) out << (i ? ", " : "") << files[i];
  out << ")\n";
  out.flush();
}

}  // namespace

int RunSimulate(const SimulateArgs& a) {
  YearRun y(a);
  y.started = Clock::now();
  y.setup = a.scenario_text.empty() ? LoadSimulation(a.scenario)
                                    : ParseSimulationText(a.scenario_text, a.scenario);
  if (!a.scenario_text.empty()) y.setup.scenario.path = a.scenario;
  y.dir = a.out_dir.empty() ? "out/" + fs::path(a.scenario).stem().string() : a.out_dir;
  y.checkpoint = y.dir + "/checkpoint.json";
  StartRun(&y);
  Announce(y);
  const bool interrupted = RunCycles(&y);
  if (interrupted && !a.quiet) {
    y.err << "interrupted: cycles 1.." << y.state.next_cycle << " are saved in " << y.dir
          << "; continue with: thrustsched simulate " << a.scenario << " --out " << y.dir
          << " --resume\n";
  }
  const std::vector<std::string> files = WriteRunFiles(y);
  if (a.print_summary) PrintSummary(y, files, interrupted);
  return interrupted ? kExitInterrupted : kExitOk;
}

}  // namespace thrustsched::app
