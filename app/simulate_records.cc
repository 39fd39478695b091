// One cycle's record as stored in checkpoint.json and as a row of cycles.csv,
// and year.json (the totals of the run).
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

namespace thrustsched::app {
namespace simulate_detail {

namespace fs = std::filesystem;
using planning::CycleRecord;
using planning::Fallback;

}  // namespace simulate_detail

using namespace simulate_detail;
using planning::CycleRecord;

nlohmann::json CycleRecordJson(const CycleRecord& r) {
  nlohmann::json j;
  j["index"] = r.index;
  j["start_s"] = r.start_s;
  j["applied_end_s"] = r.applied_end_s;
  j["prediction_end_s"] = r.prediction_end_s;
  j["fallback"] = std::string(ToString(r.fallback));
  j["status"] = std::string(milp::ToString(r.status));
  nlohmann::json attempts = nlohmann::json::array();
  for (const planning::CycleAttempt& a : r.attempts) {
    attempts.push_back({{"level", std::string(ToString(a.level))},
                        {"status", std::string(milp::ToString(a.status))},
                        {"solve_seconds", a.solve_seconds},
                        {"detail", a.detail}});
  }
  j["attempts"] = attempts;
  j["objective"] = FiniteOrNull(r.objective);
  j["best_bound"] = FiniteOrNull(r.best_bound);
  j["gap"] = FiniteOrNull(r.gap);
  j["nodes"] = r.nodes;
  j["solve_seconds"] = r.solve_seconds;
  j["first_solution_seconds"] = FiniteOrNull(r.first_solution_seconds);
  j["build_seconds"] = r.build_seconds;
  j["check_seconds"] = r.check_seconds;
  j["replay_seconds"] = r.replay_seconds;
  j["wall_seconds"] = r.wall_seconds;
  j["cpu_seconds"] = r.cpu_seconds;
  j["controllable"] = r.controllable;
  j["note"] = r.note;
  nlohmann::json burns = nlohmann::json::array();
  for (const transcription::Burn& b : r.burns) burns.push_back({b.thruster, b.start_s, b.end_s});
  j["burns"] = burns;
  j["planned_burns"] = r.planned_burns;
  j["consumption_l1_m_s"] = r.consumption_l1_m_s;
  j["delta_v_m_s"] = r.delta_v_m_s;
  j["propellant_kg"] = r.propellant_kg;
  j["normal_delta_v_m_s"] = r.normal_delta_v_m_s;
  j["on_time_s"] = r.on_time_s;
  j["checked"] = r.checked;
  j["rules_ok"] = r.rules_ok;
  j["linear_window_violation_deg"] = FiniteOrNull(r.linear_window_violation_deg);
  j["soft_violation_deg"] = FiniteOrNull(r.soft_violation_deg);
  j["max_abs_lat_deg"] = r.max_abs_lat_deg;
  j["max_abs_lon_deg"] = r.max_abs_lon_deg;
  j["max_window_violation_deg"] = r.max_window_violation_deg;
  j["worst_time_s"] = FiniteOrNull(r.worst_time_s);
  j["time_outside_window_s"] = r.time_outside_window_s;
  j["prediction_error_deg"] = FiniteOrNull(r.prediction_error_deg);
  j["eci_start"] = VectorJson(r.eci_start);
  j["eci_end"] = VectorJson(r.eci_end);
  j["initial_state"] = VectorJson(r.initial_state);
  j["final_state"] = VectorJson(r.final_state);
  return j;
}

CycleRecord CycleRecordFromJson(const nlohmann::json& j, const std::string& path) {
  if (!j.is_object()) throw ScenarioError(path + ": expected an object");
  auto str = [&](const char* key) {
    if (!j.contains(key) || !j.at(key).is_string()) {
      throw ScenarioError(path + "." + key + ": expected a string");
    }
    return j.at(key).get<std::string>();
  };
  auto boolean = [&](const char* key) {
    if (!j.contains(key) || !j.at(key).is_boolean()) {
      throw ScenarioError(path + "." + key + ": expected a boolean");
    }
    return j.at(key).get<bool>();
  };
  CycleRecord r;
  r.index = static_cast<int>(GetInteger(j, "index", path, 0, kMaxCheckpointCycles));
  r.start_s = GetNumber(j, "start_s", path);
  r.applied_end_s = GetNumber(j, "applied_end_s", path);
  r.prediction_end_s = GetNumber(j, "prediction_end_s", path);
  r.fallback = Wrap(path + ".fallback", [&] { return planning::ParseFallback(str("fallback")); });
  r.status = ParseStatus(str("status"), path + ".status");
  if (!j.contains("attempts") || !j.at("attempts").is_array()) {
    throw ScenarioError(path + ".attempts: expected an array");
  }
  for (size_t k = 0; k < j.at("attempts").size(); ++k) {
    const nlohmann::json& a = j.at("attempts")[k];
    const std::string ap = path + ".attempts[" + std::to_string(k) + "]";
    if (!a.is_object() || !a.contains("level") || !a.at("level").is_string() ||
        !a.contains("status") || !a.at("status").is_string() || !a.contains("detail") ||
        !a.at("detail").is_string()) {
      throw ScenarioError(ap + ": expected {level, status, solve_seconds, detail}");
    }
    planning::CycleAttempt at;
    at.level = Wrap(ap + ".level",
                    [&] { return planning::ParseFallback(a.at("level").get<std::string>()); });
    at.status = ParseStatus(a.at("status").get<std::string>(), ap + ".status");
    at.solve_seconds = GetNumber(a, "solve_seconds", ap);
    at.detail = a.at("detail").get<std::string>();
    r.attempts.push_back(at);
  }
  r.objective = GetNumber(j, "objective", path);
  r.best_bound = GetNumber(j, "best_bound", path);
  r.gap = GetNumber(j, "gap", path);
  r.nodes = static_cast<long long>(GetInteger(j, "nodes", path, -1, 9.0e15));
  r.solve_seconds = GetNumber(j, "solve_seconds", path);
  r.first_solution_seconds = GetNumber(j, "first_solution_seconds", path);
  r.build_seconds = GetNumber(j, "build_seconds", path);
  r.check_seconds = GetNumber(j, "check_seconds", path);
  r.replay_seconds = GetNumber(j, "replay_seconds", path);
  r.wall_seconds = GetNumber(j, "wall_seconds", path);
  r.cpu_seconds = GetNumber(j, "cpu_seconds", path);
  r.controllable = boolean("controllable");
  r.note = str("note");
  if (!j.contains("burns") || !j.at("burns").is_array()) {
    throw ScenarioError(path + ".burns: expected an array");
  }
  for (size_t k = 0; k < j.at("burns").size(); ++k) {
    const nlohmann::json& b = j.at("burns")[k];
    if (!b.is_array() || b.size() != 3 || !b[0].is_number_integer() || !b[1].is_number() ||
        !b[2].is_number()) {
      throw ScenarioError(path + ".burns[" + std::to_string(k) +
                          "]: expected [thruster, start_s, end_s], got " + DescribeJson(b));
    }
    r.burns.push_back({b[0].get<int>(), b[1].get<double>(), b[2].get<double>()});
  }
  r.planned_burns = static_cast<int>(GetInteger(j, "planned_burns", path, 0, 2.0e9));
  r.consumption_l1_m_s = GetNumber(j, "consumption_l1_m_s", path);
  r.delta_v_m_s = GetNumber(j, "delta_v_m_s", path);
  r.propellant_kg = GetNumber(j, "propellant_kg", path);
  r.normal_delta_v_m_s = GetNumber(j, "normal_delta_v_m_s", path);
  r.on_time_s = GetNumbers(j, "on_time_s", path);
  r.checked = boolean("checked");
  r.rules_ok = boolean("rules_ok");
  r.linear_window_violation_deg = GetNumber(j, "linear_window_violation_deg", path);
  r.soft_violation_deg = GetNumber(j, "soft_violation_deg", path);
  r.max_abs_lat_deg = GetNumber(j, "max_abs_lat_deg", path);
  r.max_abs_lon_deg = GetNumber(j, "max_abs_lon_deg", path);
  r.max_window_violation_deg = GetNumber(j, "max_window_violation_deg", path);
  r.worst_time_s = GetNumber(j, "worst_time_s", path);
  r.time_outside_window_s = GetNumber(j, "time_outside_window_s", path);
  r.prediction_error_deg = GetNumber(j, "prediction_error_deg", path);
  r.eci_start = ToVector6(GetNumbers(j, "eci_start", path), path + ".eci_start");
  r.eci_end = ToVector6(GetNumbers(j, "eci_end", path), path + ".eci_end");
  r.initial_state = ToVector(GetNumbers(j, "initial_state", path));
  r.final_state = ToVector(GetNumbers(j, "final_state", path));
  return r;
}

std::string CyclesCsvHeader() {
  return "cycle,start_utc,start_s,end_s,status,fallback,objective,best_bound,gap,solve_s,"
         "first_solution_s,wall_s,cpu_s,consumption_l1_m_s,delta_v_m_s,propellant_kg,"
         "normal_delta_v_m_s,burns,max_abs_lat_deg,max_abs_lon_deg,max_window_violation_deg,"
         "time_outside_window_s,prediction_error_deg,rules_ok,controllable,note\n";
}

std::string CyclesCsvRow(const CycleRecord& r, const std::string& epoch) {
  std::ostringstream os;
  os << r.index + 1 << "," << Utc(epoch, r.start_s) << "," << G(r.start_s, 15) << ","
     << G(r.applied_end_s, 15) << "," << StatusName(r.status) << "," << ToString(r.fallback) << ","
     << G(r.objective) << "," << G(r.best_bound) << "," << G(r.gap) << "," << G(r.solve_seconds, 6)
     << "," << G(r.first_solution_seconds, 6) << "," << G(r.wall_seconds, 6) << ","
     << G(r.cpu_seconds, 6) << "," << G(r.consumption_l1_m_s) << "," << G(r.delta_v_m_s) << ","
     << G(r.propellant_kg) << "," << G(r.normal_delta_v_m_s) << "," << r.burns.size() << ","
     << G(r.max_abs_lat_deg) << "," << G(r.max_abs_lon_deg) << "," << G(r.max_window_violation_deg)
     << "," << G(r.time_outside_window_s) << "," << G(r.prediction_error_deg) << ","
     << (r.rules_ok ? "true" : "false") << "," << (r.controllable ? "true" : "false") << ","
     << CsvQuote(r.note) << "\n";
  return os.str();
}

nlohmann::json YearJson(const SimulationSetup& setup, const std::vector<CycleRecord>& cycles,
                        int cycles_total, double this_run_wall_seconds) {
  const dynamics::ThrusterSet& thr = setup.scenario.problem.thrusters;
  const planning::LongHorizonSummary s = planning::Summarize(cycles, thr);
  const planning::LongHorizonOptions& o = setup.options;
  const std::string epoch = setup.scenario.geo->epoch;
  nlohmann::json j;
  j["scenario"] = setup.scenario.name;
  j["scenario_file"] = setup.scenario.path;
  j["complete"] = s.cycles == cycles_total;
  j["cycles"] = s.cycles;
  j["cycles_total"] = cycles_total;
  j["mode"] = std::string(ToString(o.mode));
  j["start_utc"] = Utc(epoch, o.start_s);
  j["simulated_days"] = s.simulated_s / common::kSecondsPerDay;
  j["consumption_l1_m_s"] = s.consumption_l1_m_s;
  j["delta_v_m_s"] = s.delta_v_m_s;
  j["propellant_kg"] = s.propellant_kg;
  j["normal_delta_v_m_s"] = s.normal_delta_v_m_s;
  j["burns"] = s.burns;
  nlohmann::json per = nlohmann::json::object();
  double total_days = 0;
  for (int i = 0; i < thr.size(); ++i) {
    per[thr.thruster(i).name] = s.thrust_days[i];
    total_days += s.thrust_days[i];
  }
  j["thrust_days"] = {{"per_thruster", per},   {"total", total_days}, {"north", s.north_days},
                      {"south", s.south_days}, {"east", s.east_days}, {"west", s.west_days}};
  j["thrust_days_faces_rule"] =
      "a thruster sits on the face opposite to its push: north = pushes -N, south = pushes +N, "
      "east = pushes -T (westward), west = pushes +T (Anzel: N = NE+NW, S = SE+SW, E = NE+SE, "
      "W = NW+SW, thesis Table 5.7)";
  j["time_outside_window_s"] = s.time_outside_window_s;
  j["max_abs_lat_deg"] = s.max_abs_lat_deg;
  j["max_abs_lon_deg"] = s.max_abs_lon_deg;
  j["max_window_violation_deg"] = s.max_window_violation_deg;
  j["worst_time_s"] = FiniteOrNull(s.worst_time_s);
  j["worst_time_utc"] = std::isfinite(s.worst_time_s) ? nlohmann::json(Utc(epoch, s.worst_time_s))
                                                      : nlohmann::json(nullptr);
  j["box_held"] = s.max_window_violation_deg <= 0.0;
  j["window_half_width_deg"] =
      setup.scenario.window_half_widths.empty() ? 0.0 : setup.scenario.window_half_widths[0];
  j["rules_ok"] = s.rules_ok;
  nlohmann::json fb_cycles = nlohmann::json::array();
  nlohmann::json unctl = nlohmann::json::array();
  std::vector<double> pred;
  for (const CycleRecord& c : cycles) {
    if (c.fallback != Fallback::kNone) {
      fb_cycles.push_back({{"cycle", c.index + 1},
                           {"start_utc", Utc(epoch, c.start_s)},
                           {"fallback", std::string(ToString(c.fallback))}});
    }
    if (!c.controllable) unctl.push_back({{"cycle", c.index + 1}, {"reason", c.note}});
    pred.push_back(c.prediction_error_deg);
  }
  j["fallbacks"] = {
      {"soft_window", s.fallback_soft_window},
      {"soft_window_free_terminal", s.fallback_free_terminal},
      {"zero_thrust", s.fallback_zero_thrust},
      {"total", s.fallback_soft_window + s.fallback_free_terminal + s.fallback_zero_thrust},
      {"cycles", fb_cycles}};
  j["uncontrollable"] = {{"cycles", s.uncontrollable_cycles}, {"list", unctl}};
  j["time_limited_cycles"] = s.time_limited_cycles;
  auto dist = [](const planning::Distribution& d) {
    return nlohmann::json{{"median", FiniteOrNull(d.median)},
                          {"p90", FiniteOrNull(d.p90)},
                          {"max", FiniteOrNull(d.max)},
                          {"mean", FiniteOrNull(d.mean)},
                          {"count", d.count}};
  };
  j["solve_seconds"] = dist(s.solve_seconds);
  j["gap"] = dist(s.gap);
  j["cycle_wall_seconds"] = dist(s.wall_seconds);
  j["cycle_cpu_seconds"] = dist(s.cpu_seconds);
  j["cpu_seconds"] = s.cpu_seconds_total;
  j["prediction_error_deg"] = dist(planning::Distribute(pred));
  j["wall_seconds"] = s.wall_seconds_total;
  j["this_run_wall_seconds"] = this_run_wall_seconds;
  nlohmann::json fails = nlohmann::json::array();
  for (const FailureSpec& f : setup.failures) {
    fails.push_back({{"thrusters", f.thrusters},
                     {"from_s", f.from_s},
                     {"from_utc", Utc(epoch, f.from_s)},
                     {"until_s", FiniteOrNull(f.until_s)},
                     {"opposite_also_off", f.opposite_also_off},
                     {"switched_off", f.switched_off}});
  }
  j["failures"] = fails;
  std::vector<std::string> disabled;
  for (const auto& t : thr.thrusters()) {
    if (!t.enabled) disabled.push_back(t.name);
  }
  j["disabled"] = disabled;
  j["settings"] = {
      {"cycle_s", o.cycle_s},
      {"control_s", o.mode == planning::HorizonMode::kReceding ? o.control_s : o.cycle_s},
      {"step_s", o.step_s},
      {"duration_s", o.duration_s},
      {"cycle_time_limit_s", FiniteOrNull(o.solve.milp.time_limit_s)},
      {"cycle_relative_gap", o.solve.milp.relative_gap},
      {"threads", o.solve.milp.threads},
      {"cycle_max_nodes", o.solve.milp.max_nodes >= 0 ? nlohmann::json(o.solve.milp.max_nodes)
                                                      : nlohmann::json(nullptr)},
      {"lp_algorithm", std::string(milp::ToString(o.solve.milp.lp_algorithm))},
      {"scheme", std::string(dynamics::ToString(o.solve.build.discretisation.scheme))},
      {"terminal", o.terminal.kind == transcription::TerminalKind::kStationKeepingSets
                       ? nlohmann::json{{"type", "station_keeping"},
                                        {"facets", o.terminal.facets_out_of_plane},
                                        {"lookahead_s", o.terminal.lookahead_s.empty()
                                                            ? std::vector<double>{0.0, o.cycle_s}
                                                            : o.terminal.lookahead_s},
                                        {"margin", o.terminal.margin}}
                       : nlohmann::json{{"type", "free"}}},
      {"soft_penalty", o.soft_penalty},
      {"cycle_improve_above_gap", o.improve_above_gap},
      {"cycle_improve_max_nodes",
       o.improve_max_nodes >= 0 ? nlohmann::json(o.improve_max_nodes)
                                : (o.solve.milp.max_nodes >= 0
                                       ? nlohmann::json(5 * std::max(o.solve.milp.max_nodes, 1LL))
                                       : nlohmann::json(nullptr))},
      {"cycle_retry_without_preprocessing", o.retry_without_preprocessing},
      {"replay_samples_per_step", o.replay_samples_per_step}};
  return j;
}

}  // namespace thrustsched::app
