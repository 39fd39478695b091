#include "benchmarks/bench/conjunction_case.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>

#include <nlohmann/json.hpp>

#include "benchmarks/bench/case_common.h"
#include "common/timing.h"
#include "milp/cbc_solver.h"
#include "transcription/conjunction_check.h"
#include "transcription/conjunction_solve.h"

namespace thrustsched::bench {

using common::Since;

namespace {

using common::Clock;

// The reference case whose scenario_file ends with the case's file name.
nlohmann::json ReferenceCase(const CaseSpec& spec) {
  namespace fs = std::filesystem;
  const fs::path scenario(spec.scenario_path);
  const fs::path ref = scenario.parent_path().parent_path() / "reference" / "serra_avoidance.json";
  std::ifstream in(ref);
  if (!in) return nullptr;
  const nlohmann::json all = nlohmann::json::parse(in);
  for (const nlohmann::json& c : all.at("cases")) {
    if (fs::path(c.value("scenario_file", "")).filename() == scenario.filename()) return c;
  }
  return nullptr;
}

}  // namespace

std::vector<Row> ExecuteConjunction(const CaseSpec& spec, int repeat,
                                    const RunContext& /*context*/) {
  const app::Scenario s = LoadPatched(spec);
  Row r = BaseRow(spec, repeat, s);
  const nlohmann::json ref = ReferenceCase(spec);
  if (!ref.is_null()) {
    const nlohmann::json& rs = ref.at("risk_selection");
    r.Set("published", rs.at("cost_mm_s").get<double>() * 1e-3);
    r.Set("published_source", "Serra 2015 " + rs.at("table").get<std::string>() + " (" +
                                  rs.at("solver").get<std::string>() + ")");
    r.Set("published_time_s", rs.at("cpu_s").get<double>());
    r.Set("published_risk_unmanoeuvred", ref.at("unmanoeuvred_max_risk").get<double>());
  }
  const auto t0 = Clock::now();
  const transcription::ScheduleMilp milp(s.problem, s.build);
  const std::unique_ptr<milp::Solver> solver = milp::MakeCbcSolver();
  transcription::SolveScheduleOptions so{};
  so.build = s.build;
  so.milp = s.solve;
  so.milp.time_limit_s = spec.time_limit_s;
  so.milp.relative_gap = spec.relative_gap;
  so.milp.threads = spec.threads;
  so.milp.log_level = 0;
  so.check = s.check;
  const transcription::ConjunctionSolve cs =
      transcription::SolveConjunction(milp, *solver, so, s.conjunction_solve);
  const double total = Since(t0);
  const transcription::ScheduleResult& res = cs.result;
  r.Set("threads", spec.threads);
  r.Set("time_limit_s", spec.time_limit_s);
  r.Set("relative_gap", spec.relative_gap);
  r.Set("n_binaries", milp.stats().num_binaries);
  r.Set("n_rows", milp.stats().num_rows);
  r.Set("n_columns", milp.stats().num_columns);
  r.Set("n_nonzeros", milp.stats().num_nonzeros);
  r.Set("build_s", milp.stats().build_seconds);
  r.Set("start_objective", cs.start_objective);
  r.Set("budget_rounds", static_cast<int>(cs.rounds.size()));
  if (!cs.rounds.empty()) r.Set("keep_out_binaries", cs.rounds.back().binaries);
  r.Set("status", std::string(milp::ToString(res.solve.status)));
  r.Set("solve_s", total);  // start + every round (builds included)
  r.Set("nodes", res.solve.nodes);
  if (res.has_schedule()) {
    r.Set("objective", res.solve.objective);
    r.Set("best_bound", res.solve.best_bound);
    r.Set("gap", res.solve.gap);
    if (res.solve.status == milp::SolveStatus::kOptimal) r.Set("time_to_opt_s", total);
    if (r.Has("published")) r.Set("ratio", res.solve.objective / r.Num("published"));
    r.Set("consumption_l1_m_s", res.schedule.consumption_l1_m_s);
    r.Set("delta_v_m_s", res.schedule.delta_v_m_s);
    r.Set("n_burns", s.impulsive() ? static_cast<int>(res.schedule.impulses.size())
                                   : res.schedule.num_burns());
    if (s.impulsive()) {
      r.Set("terminal_error", res.impulsive_check.terminal_error);
    } else {
      r.Set("operational_ok", res.check.operational_ok);
      r.Set("terminal_ok", res.check.terminal_ok);
      r.Set("max_window_violation", res.check.max_window_violation * s.window_unit_per_output_unit);
      if (res.check.nonlinear_checked) {
        r.Set("max_window_violation_nonlinear_deg", res.check.max_window_violation_nonlinear_deg);
      }
    }
    const transcription::ConjunctionCheckOptions check_options =
        s.conjunction_check.value_or(transcription::ConjunctionCheckOptions{});
    const auto tv = Clock::now();
    const transcription::ConjunctionCheckReport v = transcription::CheckConjunction(
        s.problem, res.schedule.burns, res.schedule.impulses, check_options);
    r.Set("verify_s", Since(tv));
    if (cs.without_x.size() > 0) {
      // The plan without the conjunction, against it: what the avoidance buys.
      const transcription::Schedule without = milp.Decode(cs.without_x);
      const transcription::ConjunctionCheckReport w =
          transcription::CheckConjunction(s.problem, without.burns, {}, check_options);
      r.Set("without_conjunction", cs.without_objective);
      r.Set("extra_cost", cs.extra_cost());
      r.Set("without_max_risk", w.max_risk);
      r.Set("without_mc_collisions_linear", w.collisions_linear);
      if (w.nonlinear_checked) r.Set("without_mc_collisions_nonlinear", w.collisions_nonlinear);
    }
    r.Set("max_risk", v.max_risk);
    r.Set("max_risk_unmanoeuvred", v.max_risk_unmanoeuvred);
    r.Set("mc_samples", v.samples);
    r.Set("mc_collisions_linear", v.collisions_linear);
    if (v.nonlinear_checked) {
      r.Set("mc_collisions_nonlinear", v.collisions_nonlinear);
      r.Set("mc_min_distance_m", v.min_distance_nonlinear_m);
    }
  } else if (!res.solve.detail.empty()) {
    r.Set("note", res.solve.detail);
  }
  return {r};
}

}  // namespace thrustsched::bench
