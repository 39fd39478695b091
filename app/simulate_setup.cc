// The "long_horizon" section of a GEO scenario, parsed into the options of
// planning::LongHorizonSimulation (fields in data/scenarios/README.md).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/outputs.h"
#include "app/scenario.h"
#include "app/simulate.h"
#include "app/simulate_internal.h"

#include "app/json_reader.h"

namespace thrustsched::app {
namespace simulate_detail {

namespace fs = std::filesystem;
using planning::CycleRecord;
using planning::Fallback;

// ---------------------------------------------------------------------------
// Parsing of the long_horizon section.

void ParseLongHorizon(SimulationSetup* setup) {
  Scenario& s = setup->scenario;
  planning::LongHorizonOptions& o = setup->options;
  JsonObject lh(s.raw.at("long_horizon"), "scenario.long_horizon");
  o.start_s = s.start_s;
  o.step_s = s.step_s;
  o.duration_s = lh.Number("duration_s", Bound::kPositive);
  o.cycle_s = lh.OptionalNumber("cycle_s", Bound::kPositive).value_or(s.step_s * s.num_intervals);
  o.mode = planning::ParseHorizonMode(lh.Has("mode") ? lh.Choice("mode", {"fixed", "receding"})
                                                     : std::string("fixed"));
  if (o.mode == planning::HorizonMode::kReceding) {
    o.control_s = lh.Number("control_s", Bound::kPositive);
  } else if (lh.Has("control_s")) {
    lh.Fail("control_s", "is only used with \"mode\": \"receding\"");
  }
  // End-of-cycle sets: default K = 16 in fixed mode, none in receding mode (thesis 5.4).
  bool sets = o.mode == planning::HorizonMode::kFixed;
  int facets = 16;
  if (lh.Has("terminal")) {
    JsonObject t = lh.Object("terminal");
    if (t.Has("type"))
      sets = t.Choice("type", {"station_keeping", "free"}) == "station_keeping";
    else
      sets = true;
    if (auto k = t.OptionalInteger("facets", 3, 1000)) {
      if (!sets) t.Fail("facets", "is only used with \"type\": \"station_keeping\"");
      facets = *k;
    }
    if (t.Has("lookahead_s")) {
      if (!sets) t.Fail("lookahead_s", "is only used with \"type\": \"station_keeping\"");
      o.terminal.lookahead_s = t.NumberArray("lookahead_s", -1, Bound::kNonNegative);
    }
    if (auto mg = t.OptionalNumber("margin", Bound::kNonNegative)) {
      if (!sets) t.Fail("margin", "is only used with \"type\": \"station_keeping\"");
      if (*mg >= 1.0) t.Fail("margin", "must be in [0, 1), got " + FormatNumber(*mg));
      o.terminal.margin = *mg;
    }
    t.Finish();
  }
  if (sets) {
    o.terminal.kind = transcription::TerminalKind::kStationKeepingSets;
    o.terminal.facets_out_of_plane = o.terminal.facets_cone_plus = o.terminal.facets_cone_minus =
        facets;
    o.terminal_in_receding = o.mode == planning::HorizonMode::kReceding;
  } else {
    o.terminal = transcription::TerminalSpec{};
  }

  // Solver settings per cycle: the scenario's solver section, with the cycle
  // limits of this section.
  o.solve.build = s.build;
  o.solve.milp = s.solve;
  o.solve.check = s.check;
  o.solve.check.nonlinear.reset();  // the driver replays from the true state
  o.solve.check_schedule = true;
  o.solve.search = s.search_options;
  o.solve.search.enabled = s.search;
  // Inside each cycle's time limit (transcription::ShareTimeLimit).
  o.solve.prefix_diagnosis_s = s.diagnosis_time_limit_s;
  const nlohmann::json* solver = s.raw.contains("solver") ? &s.raw.at("solver") : nullptr;
  const bool solver_time = solver != nullptr && solver->contains("time_limit_s");
  const bool solver_gap = solver != nullptr && solver->contains("relative_gap");
  o.solve.milp.time_limit_s = lh.OptionalNumber("cycle_time_limit_s", Bound::kPositive)
                                  .value_or(solver_time ? s.solve.time_limit_s : 30.0);
  o.solve.milp.relative_gap = lh.OptionalNumber("cycle_relative_gap", Bound::kNonNegative)
                                  .value_or(solver_gap ? s.solve.relative_gap : 0.02);
  if (auto th = lh.OptionalInteger("cycle_threads", 1, 64)) o.solve.milp.threads = *th;
  if (auto nodes = lh.OptionalInteger("cycle_max_nodes", 0, 2000000000)) {
    o.solve.milp.max_nodes = *nodes;
  }
  const std::string lp = lh.Has("cycle_lp_algorithm")
                             ? lh.Choice("cycle_lp_algorithm", {"barrier", "primal", "dual"})
                             : std::string("barrier");
  o.solve.milp.lp_algorithm = lp == "barrier"  ? milp::LpAlgorithm::kBarrier
                              : lp == "primal" ? milp::LpAlgorithm::kPrimal
                                               : milp::LpAlgorithm::kDual;
  o.soft_penalty = lh.OptionalNumber("soft_penalty", Bound::kPositive).value_or(o.soft_penalty);
  o.improve_above_gap = lh.OptionalNumber("cycle_improve_above_gap", Bound::kNonNegative)
                            .value_or(o.improve_above_gap);
  if (auto nodes = lh.OptionalInteger("cycle_improve_max_nodes", 0, 2000000000)) {
    o.improve_max_nodes = *nodes;
  }
  o.retry_without_preprocessing =
      lh.OptionalBool("cycle_retry_without_preprocessing").value_or(o.retry_without_preprocessing);
  o.replay_samples_per_step =
      lh.OptionalInteger("replay_samples_per_step", 1, 1000).value_or(o.replay_samples_per_step);
  setup->trajectory_sample_s =
      lh.OptionalNumber("trajectory_sample_s", Bound::kPositive).value_or(3600.0);
  setup->timeline_cycle = lh.OptionalInteger("timeline_cycle", 1, 100000).value_or(0) - 1;

  // Failures: thrusters switched off from a date on.
  const dynamics::ThrusterSet& thr = s.problem.thrusters;
  std::vector<JsonObject> failures;
  if (lh.Has("failures")) failures = lh.ObjectArray("failures");
  for (size_t k = 0; k < failures.size(); ++k) {
    JsonObject& f = failures[k];
    FailureSpec spec;
    spec.thrusters = f.StringArray("thrusters");
    if (spec.thrusters.empty()) f.Fail("thrusters", "is empty (name at least one thruster)");
    spec.from_s = f.Number("from_s");
    spec.until_s = f.OptionalNumber("until_s").value_or(kInf);
    if (!(spec.until_s > spec.from_s)) {
      f.Fail("until_s", "must be after from_s (" + FormatNumber(spec.from_s) + " s), got " +
                            FormatNumber(spec.until_s) + " s");
    }
    spec.opposite_also_off = f.OptionalBool("opposite_also_off").value_or(false);
    std::vector<int> off;
    for (size_t i = 0; i < spec.thrusters.size(); ++i) {
      const std::string where = f.FieldPath("thrusters") + "[" + std::to_string(i) + "]";
      const int idx = Wrap(where, [&] { return thr.IndexOf(spec.thrusters[i]); });
      off.push_back(idx);
      if (spec.opposite_also_off) {
        off.push_back(Wrap(where, [&] { return planning::OppositeThruster(thr, idx); }));
      }
    }
    for (int idx : off) {
      bool dup = false;
      for (const std::string& n : spec.switched_off) dup = dup || n == thr.thruster(idx).name;
      if (dup) continue;
      spec.switched_off.push_back(thr.thruster(idx).name);
      o.outages.push_back({idx, spec.from_s, spec.until_s});
    }
    f.Finish();
    setup->failures.push_back(spec);
  }
  lh.Finish();
  std::string err;
  if (!o.IsValid(&err)) throw ScenarioError("scenario." + err);
}

}  // namespace simulate_detail

using namespace simulate_detail;
using planning::CycleRecord;

// ---------------------------------------------------------------------------

SimulationSetup ParseSimulationText(const std::string& text, const std::string& source) {
  SimulationSetup setup;
  ScenarioParseOptions po;
  po.extra_sections = {"long_horizon"};
  po.source = source;
  setup.scenario = ParseScenarioText(text, po);
  Scenario& s = setup.scenario;
  if (s.model_type != ModelType::kGeo) {
    throw ScenarioError("scenario.model.type: simulate needs a \"geo\" model, got \"" +
                        std::string(ToString(s.model_type)) + "\"");
  }
  if (s.impulsive()) {
    throw ScenarioError("scenario.input_mode: simulate needs on-off thrusters, got \"impulsive\"");
  }
  if (!s.raw.contains("long_horizon")) {
    throw ScenarioError("scenario.long_horizon: missing (simulate needs this section)");
  }
  if (s.raw.contains("terminal")) {
    throw ScenarioError(
        "scenario.terminal: not used by simulate; give the end-of-cycle sets in "
        "long_horizon.terminal");
  }
  if (s.raw.contains("conjunction")) {
    throw ScenarioError(
        "scenario.conjunction: not used by simulate (solve the encounter with `solve`)");
  }
  if (!s.problem.window.enabled()) {
    throw ScenarioError("scenario.window: missing (simulate keeps the satellite in a window)");
  }
  if (s.problem.window.soft) {
    throw ScenarioError(
        "scenario.window.soft: not used by simulate (the fallbacks soften the window "
        "themselves; see long_horizon.soft_penalty)");
  }
  for (int i = 0; i < s.problem.thrusters.size(); ++i) {
    if (s.problem.history.is_on(i)) {
      throw ScenarioError("scenario.history." + s.problem.thrusters.thruster(i).name +
                          ".on_for_s: simulate starts with every thruster off (use off_for_s)");
    }
  }
  ParseLongHorizon(&setup);
  setup.fingerprint = Fingerprint(s.raw.dump());
  return setup;
}

SimulationSetup LoadSimulation(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot open the scenario file");
  std::ostringstream ss;
  ss << in.rdbuf();
  SimulationSetup s = ParseSimulationText(ss.str(), path);
  s.scenario.path = path;
  return s;
}

}  // namespace thrustsched::app
