#include "app/fleet_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "app/fleet_scenario.h"
#include "app/format_units.h"
#include "app/interrupt.h"
#include "app/outputs.h"
#include "app/run_folder.h"
#include "common/format.h"
#include "milp/cbc_solver.h"

namespace thrustsched::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using common::FormatG;

double Since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

nlohmann::json PairJson(const FleetScenario& f, const transcription::PairDistance& p,
                        const transcription::PairDistance* planned,
                        const transcription::PairDistance* nonlinear) {
  nlohmann::json j;
  j["member_a"] = f.problem.members[p.a].name;
  j["member_b"] = f.problem.members[p.b].name;
  j["min_distance_m"] = FiniteOrNull(p.min_distance_m);
  j["min_box_distance_m"] = FiniteOrNull(p.min_box_distance_m);
  j["time_s"] = FiniteOrNull(p.time_s);
  j["planned_min_distance_m"] = planned ? FiniteOrNull(planned->min_distance_m) : nullptr;
  j["planned_min_box_distance_m"] = planned ? FiniteOrNull(planned->min_box_distance_m) : nullptr;
  j["nonlinear_min_distance_m"] = nonlinear ? FiniteOrNull(nonlinear->min_distance_m) : nullptr;
  j["nonlinear_min_box_distance_m"] =
      nonlinear ? FiniteOrNull(nonlinear->min_box_distance_m) : nullptr;
  return j;
}

// The same pair in `pairs` (the planned or the nonlinear ones), if any.
const transcription::PairDistance* SamePair(const std::vector<transcription::PairDistance>& pairs,
                                            const transcription::PairDistance& p) {
  for (const transcription::PairDistance& q : pairs) {
    if (q.a == p.a && q.b == p.b) return &q;
  }
  return nullptr;
}

// The smallest max-norm distance of any pair in `pairs`.
double Closest(const std::vector<transcription::PairDistance>& pairs) {
  double closest = std::numeric_limits<double>::infinity();
  for (const transcription::PairDistance& p : pairs)
    closest = std::min(closest, p.min_box_distance_m);
  return closest;
}

// The keep-out holds between the checks too: no pair inside the cube on the
// checker's fine samples (the MILP sees the check times only).
bool HeldOnSamples(const FleetScenario& f, double closest) {
  return !f.problem.keep_out || closest >= f.problem.keep_out->half_size_m * (1.0 - 1e-9) - 1e-9;
}

nlohmann::json MemberJson(const FleetScenario& f, const transcription::FleetResult& r, int k) {
  const Scenario& s = f.members[k];
  nlohmann::json j;
  j["name"] = f.problem.members[k].name;
  j["scenario"] = s.name;
  j["objective_kind"] = std::string(transcription::ToString(s.problem.objective.kind));
  if (!r.has_schedule()) return j;
  const transcription::Schedule& sch = r.schedules[k];
  j["consumption"] = FiniteOrNull(r.consumption[k]);
  j["consumption_l1_m_s"] = FiniteOrNull(sch.consumption_l1_m_s);
  j["delta_v_m_s"] = FiniteOrNull(sch.delta_v_m_s);
  j["propellant_kg"] = FiniteOrNull(sch.propellant_kg);
  j["n_burns"] = sch.burns.size();
  j["burns"] = BurnsJson(sch.burns, s.thruster_names());
  if (f.problem.assignment) {
    const auto& m = f.problem.assignment->members;
    for (size_t i = 0; i < m.size(); ++i) {
      if (m[i] == k && i < r.slots.size()) j["slot"] = r.slots[i];
    }
  }
  j["check"] = k < static_cast<int>(r.checks.size())
                   ? CheckJson(s, r.checks[k], Judge(s, r.checks[k]), 0.0)
                   : nlohmann::json(nullptr);
  return j;
}

nlohmann::json MonteCarloJson(const FleetScenario& f,
                              const transcription::FleetMonteCarloReport& mc) {
  nlohmann::json pairs = nlohmann::json::array();
  for (const transcription::FleetMonteCarloPair& p : mc.pairs) {
    pairs.push_back({{"member_a", f.problem.members[p.a].name},
                     {"member_b", f.problem.members[p.b].name},
                     {"collisions", p.collisions},
                     {"min_distance_m", FiniteOrNull(p.min_distance_m)}});
  }
  return {{"samples", mc.samples},
          {"seed", f.options.monte_carlo.seed},
          {"step_s", mc.step_s},
          {"radius_m", mc.radius_m},
          {"collisions", mc.collisions},
          {"min_distance_m", FiniteOrNull(mc.min_distance_m)},
          {"passed", mc.passed()},
          {"seconds", mc.seconds},
          {"pairs", pairs}};
}

nlohmann::json FleetSummaryJson(const FleetScenario& f, const transcription::FleetResult& r,
                                const std::string& command_line, double total_seconds,
                                bool interrupted) {
  nlohmann::json j;
  j["name"] = f.name;
  j["scenario_file"] = f.path;
  j["command_line"] = command_line;
  j["status"] = StatusName(r.status);
  j["interrupted"] = interrupted;
  j["objective"] = r.has_schedule() ? FiniteOrNull(r.objective) : nullptr;
  j["best_bound"] = FiniteOrNull(r.best_bound);
  j["gap"] = FiniteOrNull(r.gap);
  j["solver_detail"] = r.detail;
  j["solve_seconds"] = r.solve_seconds;
  j["total_seconds"] = total_seconds;
  j["time_limit_s"] = FiniteOrNull(f.options.milp.time_limit_s);
  j["relative_gap"] = f.options.milp.relative_gap;
  j["balance"] = std::string(transcription::ToString(f.problem.balance.kind));
  const transcription::FleetBuildStats& st = r.stats;
  j["n_columns"] = st.num_columns;
  j["n_rows"] = st.num_rows;
  j["n_binaries"] = st.num_binaries;
  j["n_nonzeros"] = st.num_nonzeros;
  const double closest = Closest(r.checked_pairs);
  const double closest_nonlinear = Closest(r.nonlinear_pairs);
  j["keep_out"] =
      f.problem.keep_out
          ? nlohmann::json{{"half_size_m", f.problem.keep_out->half_size_m},
                           {"min_box_distance_on_samples_m", FiniteOrNull(closest)},
                           {"held_on_samples", r.has_schedule() && HeldOnSamples(f, closest)},
                           {"min_box_distance_nonlinear_m", FiniteOrNull(closest_nonlinear)},
                           {"held_nonlinear",
                            r.nonlinear_pairs.empty()
                                ? nlohmann::json(nullptr)
                                : nlohmann::json(HeldOnSamples(f, closest_nonlinear))},
                           {"checks", st.keep_out_checks},
                           {"checks_clear", st.keep_out_checks_clear},
                           {"single_face", st.keep_out_single_face},
                           {"faces_impossible", st.keep_out_faces_impossible},
                           {"binaries", st.keep_out_binaries},
                           {"big_m_min_m", FiniteOrNull(st.big_m_min_m)},
                           {"big_m_max_m", FiniteOrNull(st.big_m_max_m)},
                           {"instantaneous_threshold", f.problem.keep_out->instantaneous_threshold},
                           {"quantile", st.keep_out_quantile},
                           {"margin_max_m", st.keep_out_margin_max_m}}
          : nlohmann::json(nullptr);
  j["monte_carlo"] = r.monte_carlo ? MonteCarloJson(f, *r.monte_carlo) : nlohmann::json(nullptr);
  const transcription::FleetStart& start = r.start;
  j["start"] =
      start.tried
          ? nlohmann::json{{"built", start.built},
                           {"accepted", start.accepted},
                           {"note", start.note},
                           {"objective", FiniteOrNull(start.objective)},
                           {"bound", FiniteOrNull(start.bound)},
                           {"member_solves", start.member_solves},
                           {"assignments_tried", start.tries},
                           {"neighbourhood",
                            start.neighbourhood_tried
                                ? nlohmann::json{{"repaired", start.repaired},
                                                 {"radius_intervals",
                                                  start.neighbourhood_radius_intervals},
                                                 {"free_binaries",
                                                  start.neighbourhood_free_binaries},
                                                 {"seconds", start.neighbourhood_seconds}}
                                : nlohmann::json(nullptr)},
                           {"in_turn", start.in_turn_tried
                                           ? nlohmann::json{{"found", start.in_turn_found},
                                                            {"members_replanned",
                                                             start.in_turn_members_replanned},
                                                            {"searches", start.in_turn_searches},
                                                            {"keep_out_faces",
                                                             start
                                                                 .in_turn_constraints},
                                                            {"seconds", start.in_turn_seconds}}
                                           : nlohmann::json(nullptr)},
                           {"seconds", start.seconds}}
          : nlohmann::json(nullptr);
  j["assignment_binaries"] = st.assignment_binaries;
  j["infeasibility_reasons"] = st.infeasibility_reasons;
  j["members"] = nlohmann::json::array();
  for (int k = 0; k < static_cast<int>(f.members.size()); ++k)
    j["members"].push_back(MemberJson(f, r, k));
  j["pairs"] = nlohmann::json::array();
  for (const transcription::PairDistance& p : r.checked_pairs)
    j["pairs"].push_back(
        PairJson(f, p, SamePair(r.planned_pairs, p), SamePair(r.nonlinear_pairs, p)));
  j["coupling_residuals"] = r.coupling_residuals;
  return j;
}

std::string FleetCsv(const FleetScenario& f, const transcription::FleetResult& r) {
  std::ostringstream os;
  os << "member_a,member_b,min_distance_m,min_box_distance_m,time_s,planned_min_distance_m,"
        "planned_min_box_distance_m,keep_out_half_size_m\n";
  const auto num = [](double v) { return std::isfinite(v) ? FormatG(v, 17) : std::string(); };
  for (const transcription::PairDistance& p : r.checked_pairs) {
    const transcription::PairDistance* q = SamePair(r.planned_pairs, p);
    os << f.problem.members[p.a].name << "," << f.problem.members[p.b].name << ","
       << num(p.min_distance_m) << "," << num(p.min_box_distance_m) << "," << num(p.time_s) << ","
       << (q ? num(q->min_distance_m) : "") << "," << (q ? num(q->min_box_distance_m) : "") << ","
       << (f.problem.keep_out ? num(f.problem.keep_out->half_size_m) : "") << "\n";
  }
  return os.str();
}

void PrintFleet(std::ostream& out, const FleetScenario& f, const transcription::FleetResult& r,
                bool interrupted) {
  out << "fleet         " << f.name << " (" << f.members.size() << " members, balance "
      << transcription::ToString(f.problem.balance.kind) << ")\n";
  out << "MILP          " << r.stats.num_binaries << " binaries, " << r.stats.num_columns
      << " columns, " << r.stats.num_rows << " rows";
  if (f.problem.keep_out) {
    out << "; keep-out " << r.stats.keep_out_checks << " checks (" << r.stats.keep_out_checks_clear
        << " clear), " << r.stats.keep_out_binaries << " binaries";
  }
  if (r.start.tried) {
    out << "\nstart         members alone: " << r.start.note;
    if (r.start.built) {
      out << ", objective " << FormatG(r.start.objective, 8) << ", bound "
          << FormatG(r.start.bound, 8)
          << (r.start.accepted ? ", accepted" : ", rejected by the fleet rows");
    }
  }
  out << "\nstatus        " << StatusName(r.status) << (interrupted ? " (interrupted)" : "");
  if (r.has_schedule()) {
    out << ", objective " << FormatG(r.objective, 8) << ", best bound " << FormatG(r.best_bound, 8)
        << ", gap " << FormatPercent(r.gap);
  }
  out << "\n";
  for (const std::string& reason : r.stats.infeasibility_reasons)
    out << "reason        " << reason << "\n";
  if (!r.has_schedule()) return;
  for (size_t k = 0; k < f.members.size(); ++k) {
    const bool passed = k < r.checks.size() && Judge(f.members[k], r.checks[k]).passed;
    out << "member        " << f.problem.members[k].name << ": " << FormatG(r.consumption[k], 8)
        << " (" << transcription::ToString(f.members[k].problem.objective.kind) << "), "
        << r.schedules[k].burns.size() << " burns, check " << (passed ? "PASSED" : "FAILED")
        << "\n";
  }
  if (f.problem.keep_out) {
    const double closest = Closest(r.checked_pairs);
    const bool held = HeldOnSamples(f, closest);
    out << "keep-out      " << (held ? "HELD" : "BROKEN")
        << " on the checker's samples: closest pair " << FormatG(closest, 6) << " m (max norm) "
        << (held ? ">=" : "<") << " " << FormatG(f.problem.keep_out->half_size_m, 6) << " m"
        << (held ? "" : ": pairs cross between checks (a finer check grid)") << "\n";
    if (!r.nonlinear_pairs.empty()) {
      const double exact = Closest(r.nonlinear_pairs);
      const bool kept = HeldOnSamples(f, exact);
      out << "keep-out      " << (kept ? "HELD" : "BROKEN")
          << " in the nonlinear replays: closest pair " << FormatG(exact, 6) << " m (max norm) "
          << (kept ? ">=" : "<") << " " << FormatG(f.problem.keep_out->half_size_m, 6) << " m\n";
    }
  }
  if (r.monte_carlo) {
    const transcription::FleetMonteCarloReport& mc = *r.monte_carlo;
    out << "Monte Carlo   " << mc.collisions << " of " << mc.samples
        << " samples with a pair closer than " << FormatG(mc.radius_m, 6) << " m (closest "
        << FormatG(mc.min_distance_m, 6) << " m): " << (mc.passed() ? "PASSED" : "FAILED") << "\n";
  }
  for (const transcription::PairDistance& p : r.checked_pairs) {
    out << "pair          " << f.problem.members[p.a].name << "-" << f.problem.members[p.b].name
        << ": min distance " << FormatG(p.min_distance_m, 6) << " m (box "
        << FormatG(p.min_box_distance_m, 6) << " m) at t = " << FormatG(p.time_s, 8) << " s";
    if (const transcription::PairDistance* nl = SamePair(r.nonlinear_pairs, p)) {
      out << "; nonlinear " << FormatG(nl->min_distance_m, 6) << " m (box "
          << FormatG(nl->min_box_distance_m, 6) << " m)";
    }
    out << "\n";
  }
}

}  // namespace

FleetRun RunFleetScenario(const FleetScenario& f, const FleetRunHooks& hooks) {
  const Clock::time_point t_start = Clock::now();
  transcription::FleetSolveOptions opt = f.options;
  opt.milp.interrupt = hooks.interrupt;
  opt.milp.progress = hooks.progress;
  opt.announce = hooks.announce;
  const std::unique_ptr<milp::Solver> solver = milp::MakeCbcSolver();
  FleetRun run;
  run.result = transcription::SolveFleet(f.problem, *solver, opt);
  run.interrupted = hooks.interrupt != nullptr && hooks.interrupt->load();
  const transcription::FleetResult& r = run.result;
  if (r.has_schedule()) {
    for (size_t k = 0; k < f.members.size(); ++k) {
      run.schedule_csv.push_back(ScheduleCsvText(f.members[k], r.schedules[k].burns));
      run.trajectory_csv.push_back(
          k < r.checks.size() ? TrajectoryCsvText(f.members[k], r.checks[k], r.schedules[k].burns)
                              : std::string());
    }
  }
  run.fleet_csv = FleetCsv(f, r);
  run.summary = FleetSummaryJson(f, r, hooks.command_line, Since(t_start), run.interrupted);
  return run;
}

int RunFleetSolve(const SolveArgs& a) {
  FleetScenario f = LoadFleetScenario(a.scenario);
  ApplyFleetOverrides(a.overrides, &f);
  if (!a.export_mps.empty() || !a.export_lp.empty() || a.ccsds.any()) {
    throw ScenarioError(
        "--export-mps, --export-lp and the CCSDS options are not available for a "
        "fleet yet (use `thrustsched export` for its MILP)");
  }
  const std::string target =
      a.out_dir.empty() ? "out/" + fs::path(a.scenario).stem().string() : a.out_dir;
  RunFolder folder(target, a.force, a.command_line);
  std::ostream& err = std::cerr;
  if (!a.quiet) {
    err << "solving the fleet " << f.name << " (" << f.members.size() << " members) with "
        << milp::CbcVersion() << "; Ctrl-C stops and keeps the best schedules found\n";
  }
  FleetRunHooks hooks;
  hooks.interrupt = InterruptWatcher::flag();
  hooks.command_line = a.command_line;
  hooks.progress = CliProgress(a.quiet, err);
  if (!a.quiet) hooks.announce = [&err](const std::string& step) { err << "  " << step << "\n"; };
  FleetRun run;
  {
    InterruptWatcher watcher;
    run = RunFleetScenario(f, hooks);
  }
  std::vector<std::string> files = {"summary.json", "fleet.csv"};
  const std::string& dir = folder.path();
  for (size_t k = 0; k < run.schedule_csv.size(); ++k) {
    const std::string& name = f.problem.members[k].name;
    WriteTextFile(dir + "/schedule_" + name + ".csv", run.schedule_csv[k]);
    WriteTextFile(dir + "/trajectory_" + name + ".csv", run.trajectory_csv[k]);
    files.insert(files.end(), {"schedule_" + name + ".csv", "trajectory_" + name + ".csv"});
  }
  WriteTextFile(dir + "/fleet.csv", run.fleet_csv);
  WriteJsonFile(dir + "/summary.json", run.summary);
  const std::string replaced = folder.Commit();
  if (!replaced.empty()) err << "note: " << replaced << "\n";

  std::ostream& out = std::cout;
  out << "scenario      " << f.name << " (" << a.scenario << ")\n";
  PrintFleet(out, f, run.result, run.interrupted);
  std::string listed;
  for (const std::string& file : files) listed += (listed.empty() ? "" : ", ") + file;
  out << "output        " << target << " (" << listed << ")\n";
  out.flush();
  return SolveExitCode(run.result.status);
}

int RunFleetExport(const ExportArgs& a) {
  FleetScenario f = LoadFleetScenario(a.scenario);
  ApplyFleetOverrides(a.overrides, &f);
  const transcription::FleetMilp milp(f.problem, f.options.build);
  WriteModelFile(a.file, milp.lp(), a.obfuscate_names);
  std::cout << "wrote " << a.file << ": the fleet MILP of " << f.members.size() << " members, "
            << milp.stats().num_binaries << " binaries, " << milp.stats().num_columns
            << " columns, " << milp.stats().num_rows
            << " rows; columns and rows named <member>.<name>\n";
  return kExitOk;
}

}  // namespace thrustsched::app
