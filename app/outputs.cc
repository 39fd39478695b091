// The files of a solve: summary.json, schedule.csv, trajectory.csv and their
// readers. One file on purpose, ~700 lines: the writers and readers of each
// format sit together so that a column or field cannot change on one side only.
#include "app/outputs.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "app/conjunction_report.h"
#include "app/min_time_report.h"
#include "common/constants.h"
#include "common/format.h"
#include "dynamics/geo_simulator.h"
#include "dynamics/models.h"
#include "dynamics/propagation.h"
#include "dynamics/time.h"
#include "milp/model_io.h"

namespace thrustsched::app {

using common::FormatG;

namespace {

using common::kPi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A start_utc/end_utc cell names its time in seconds to this (s; 1 ms).
constexpr double kUtcLabelTolerance_s = 1e-3;
// A derived time cell (duration_s, an impulse's time_s) agrees with the
// times it is derived from to this, relative to max(1 s, |time|).
constexpr double kDerivedTimeRelativeTolerance = 1e-6;

// JSON number or null for non-finite values (nlohmann writes NaN/inf as null anyway;
// being explicit keeps the intent visible).
std::string Fmt(double v) {
  if (std::isnan(v)) return "nan";
  return FormatG(v, 15);
}

std::string Trim(const std::string& s) {
  size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r')) --b;
  return s.substr(a, b - a);
}

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',') {
      out.push_back(Trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(Trim(cur));
  return out;
}

// A CSV table with named columns; comments (#) and blank lines skipped.
struct CsvTable {
  std::map<std::string, int> column;  // name -> index
  struct Row {
    int line;
    std::vector<std::string> cells;
  };
  std::vector<Row> rows;
};

// `path` names the text in messages.
CsvTable ReadCsv(std::istream& in, const std::string& path,
                 const std::vector<std::string>& required,
                 const std::vector<std::string>& optional) {
  CsvTable t;
  std::string line;
  int number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    const std::string trimmed = Trim(line);
    if (trimmed.empty() || trimmed[0] == '#') continue;
    std::vector<std::string> cells = SplitCsv(trimmed);
    if (!header) {
      for (size_t i = 0; i < cells.size(); ++i) {
        bool known = false;
        for (const auto& r : required) known = known || r == cells[i];
        for (const auto& o : optional) known = known || o == cells[i];
        if (!known || t.column.count(cells[i]) > 0) {
          std::string expected;
          for (const auto& r : required) expected += (expected.empty() ? "" : ",") + r;
          for (const auto& o : optional) expected += ",[" + o + "]";
          throw ScenarioError(path + ":" + std::to_string(number) + ": header column \"" +
                              cells[i] + "\" is unknown or repeated (expected " + expected + ")");
        }
        t.column[cells[i]] = static_cast<int>(i);
      }
      for (const auto& r : required) {
        if (t.column.count(r) == 0) {
          throw ScenarioError(path + ":" + std::to_string(number) + ": header lacks column \"" + r +
                              "\"");
        }
      }
      header = true;
      continue;
    }
    if (cells.size() != t.column.size()) {
      throw ScenarioError(path + ":" + std::to_string(number) + ": expected " +
                          std::to_string(t.column.size()) + " fields, got " +
                          std::to_string(cells.size()));
    }
    t.rows.push_back({number, std::move(cells)});
  }
  if (in.bad()) throw ScenarioError(path + ": read error");
  if (!header) throw ScenarioError(path + ": empty file (no header line)");
  return t;
}

double CellNumber(const std::string& path, const CsvTable::Row& row, const std::string& name,
                  int index) {
  const std::string& s = row.cells[index];
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v)) {
    throw ScenarioError(path + ":" + std::to_string(row.line) + ": " + name +
                        " must be a finite number, got \"" + s + "\"");
  }
  return v;
}

int ThrusterOf(const std::string& path, const CsvTable::Row& row, const std::string& name,
               const Scenario& s) {
  const std::vector<std::string> names = s.thruster_names();
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  throw ScenarioError(path + ":" + std::to_string(row.line) + ": thruster \"" + name +
                      "\" is not in the scenario (thrusters: " + list + ")");
}

// A start_utc/end_utc cell, if present and not empty, must be the UTC label
// of the time in seconds (derived columns: the seconds are what is read).
void CheckUtcCell(const std::string& path, const CsvTable::Row& row, const CsvTable& t,
                  const std::string& column, double t_s, const Scenario& s) {
  auto c = t.column.find(column);
  if (c == t.column.end() || row.cells[c->second].empty()) return;
  const std::string& cell = row.cells[c->second];
  const std::string where =
      path + ":" + std::to_string(row.line) + ": " + column + " \"" + cell + "\"";
  if (!s.geo) throw ScenarioError(where + ": the scenario has no UTC epoch (GEO models only)");
  const dynamics::Epoch label = Wrap(where, [&] { return dynamics::Epoch::Parse(cell); });
  const double dt = label.SecondsSince(dynamics::Epoch::Parse(s.geo->epoch)) - t_s;
  if (std::abs(dt) > kUtcLabelTolerance_s) {
    throw ScenarioError(where + " is not the UTC time of " + Fmt(t_s) + " s after the epoch " +
                        s.geo->epoch + " (off by " + Fmt(dt) + " s)");
  }
}

double OutputToWindow(const Scenario& s, double v) { return v * s.window_unit_per_output_unit; }

std::string OutputName(const Scenario& s, int output) {
  if (output < 0) return "";
  const std::vector<std::string> names = s.problem.model->output_names();
  return output < static_cast<int>(names.size()) ? names[output] : std::to_string(output);
}

double MeanMotion(const Scenario& s) {
  if (const auto* h = dynamic_cast<const dynamics::HcwModel*>(s.problem.model.get())) {
    return h->mean_motion();
  }
  return kNaN;
}

// Which thrusters are on at time t (burn [start, end)).
std::vector<int> OnFlags(const Scenario& s, const std::vector<transcription::Burn>& burns,
                         double t) {
  std::vector<int> on(s.problem.thrusters.size(), 0);
  for (const transcription::Burn& b : burns) {
    if (t >= b.start_s && t < b.end_s) on[b.thruster] = 1;
  }
  return on;
}

}  // namespace

nlohmann::json FiniteOrNull(double v) {
  if (!std::isfinite(v)) return nullptr;
  return v;
}

std::string StatusName(milp::SolveStatus status) {
  switch (status) {
    case milp::SolveStatus::kOptimal:
      return "optimal";
    case milp::SolveStatus::kFeasible:
      return "feasible";
    case milp::SolveStatus::kInfeasible:
      return "infeasible";
    case milp::SolveStatus::kUnbounded:
      return "unbounded";
    case milp::SolveStatus::kNoSolutionFound:
      return "no_solution";
    case milp::SolveStatus::kError:
      return "error";
  }
  return "error";
}

double HcwDriftTerm(const Scenario& s, const Eigen::VectorXd& x) {
  const double n = MeanMotion(s);
  if (!std::isfinite(n) || x.size() < 5) return kNaN;
  return 2.0 * x[0] + x[4] / n;
}

CheckVerdict Judge(const Scenario& s, const transcription::CheckReport& r) {
  CheckVerdict v;
  for (const transcription::RuleViolation& rv : r.rule_violations) {
    v.findings.push_back("rule " + rv.rule + " at t = " + Fmt(rv.time_s) + " s: " + rv.message);
  }
  if (s.problem.window.enabled()) {
    const double tol = s.verdict.window_tolerance;
    const double nodes = OutputToWindow(s, r.max_window_violation_at_nodes);
    const double all = OutputToWindow(s, r.max_window_violation);
    if (nodes > tol) {
      v.findings.push_back("window violated at grid nodes by " + Fmt(nodes) + " " + s.window_unit +
                           " (tolerance " + Fmt(tol) + " " + s.window_unit + ")");
    }
    if (s.verdict.include_intersample && all > tol) {
      v.findings.push_back("window violated between nodes by " + Fmt(all) + " " + s.window_unit +
                           " at t = " + Fmt(r.worst_time_s) + " s (tolerance " + Fmt(tol) + ")");
    }
    if (s.verdict.include_nonlinear && r.nonlinear_checked &&
        r.max_window_violation_nonlinear_deg > tol) {
      v.findings.push_back("window violated in the nonlinear replay by " +
                           Fmt(r.max_window_violation_nonlinear_deg) + " deg at t = " +
                           Fmt(r.worst_time_nonlinear_s) + " s (tolerance " + Fmt(tol) + " deg)");
    }
  }
  if (!r.terminal_ok) {
    v.findings.push_back("terminal constraint violated (scaled error " + Fmt(r.terminal_error) +
                         ")");
  }
  v.passed = v.findings.empty();
  return v;
}

CheckVerdict JudgeImpulsive(const Scenario& s, const transcription::ImpulsiveCheck& c) {
  CheckVerdict v;
  if (s.problem.window.enabled()) {
    const double w = OutputToWindow(s, c.max_window_violation);
    if (w > s.verdict.window_tolerance) {
      v.findings.push_back("window violated at grid nodes by " + Fmt(w) + " " + s.window_unit +
                           " (tolerance " + Fmt(s.verdict.window_tolerance) + ")");
    }
  }
  if (c.terminal_error > transcription::kTerminalTolerance) {
    v.findings.push_back("terminal constraint violated (scaled error " + Fmt(c.terminal_error) +
                         ", tolerance " + Fmt(transcription::kTerminalTolerance) + ")");
  }
  v.passed = v.findings.empty();
  return v;
}

transcription::CheckReport CheckWithLinearFallback(const Scenario& s,
                                                   const std::vector<transcription::Burn>& burns,
                                                   std::string* nonlinear_error) {
  try {
    return transcription::CheckSchedule(s.problem, burns, s.check);
  } catch (const std::runtime_error& e) {
    if (!s.check.nonlinear) throw;
    *nonlinear_error = e.what();
    transcription::CheckOptions o = s.check;
    o.nonlinear.reset();
    return transcription::CheckSchedule(s.problem, burns, o);
  }
}

void AddRuleViolations(const std::vector<transcription::RuleViolation>& violations,
                       const std::vector<std::string>& names, nlohmann::json* j) {
  nlohmann::json msgs = nlohmann::json::array();
  nlohmann::json details = nlohmann::json::array();
  for (const transcription::RuleViolation& v : violations) {
    msgs.push_back(v.message);
    details.push_back({{"rule", v.rule},
                       {"thruster", v.thruster >= 0 && v.thruster < static_cast<int>(names.size())
                                        ? nlohmann::json(names[v.thruster])
                                        : nlohmann::json(nullptr)},
                       {"time_s", FiniteOrNull(v.time_s)},
                       {"message", v.message}});
  }
  (*j)["rule_violations"] = msgs;
  (*j)["rule_violation_details"] = details;
}

nlohmann::json CheckJson(const Scenario& s, const transcription::CheckReport& r,
                         const CheckVerdict& verdict, double check_seconds) {
  nlohmann::json j;
  j["passed"] = verdict.passed;
  j["findings"] = verdict.findings;
  j["operational_ok"] = r.operational_ok;
  AddRuleViolations(r.rule_violations, s.thruster_names(), &j);
  j["window_unit"] =
      s.window_unit.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.window_unit);
  j["window_tolerance"] =
      s.problem.window.enabled() ? FiniteOrNull(s.verdict.window_tolerance) : nullptr;
  j["max_window_violation"] = OutputToWindow(s, r.max_window_violation);
  j["max_window_violation_nodes"] = OutputToWindow(s, r.max_window_violation_at_nodes);
  j["worst_time_s"] = FiniteOrNull(r.worst_time_s);
  j["worst_output"] = r.worst_output >= 0 ? nlohmann::json(OutputName(s, r.worst_output)) : nullptr;
  j["samples"] = r.sample_times.size();
  j["samples_per_interval"] = s.check.samples_per_interval;
  j["terminal_ok"] = r.terminal_ok;
  j["terminal_error"] = r.terminal_error;
  std::vector<double> fs(r.final_state.data(), r.final_state.data() + r.final_state.size());
  j["final_state"] = fs;
  if (s.model_type == ModelType::kHcw && r.final_state.size() == 6) {
    j["final_drift_term_m"] = FiniteOrNull(HcwDriftTerm(s, r.final_state));
  }
  if (s.model_type == ModelType::kGeo) {
    j["nonlinear_checked"] = r.nonlinear_checked;
    j["max_window_violation_nonlinear_deg"] = FiniteOrNull(r.max_window_violation_nonlinear_deg);
    j["worst_time_nonlinear_s"] = FiniteOrNull(r.worst_time_nonlinear_s);
    j["max_abs_lat_deg"] = FiniteOrNull(r.max_abs_lat_deg);
    j["max_abs_lon_deg"] = FiniteOrNull(r.max_abs_lon_deg);
    j["time_outside_window_nonlinear_s"] =
        r.nonlinear_checked ? FiniteOrNull(r.time_outside_window_nonlinear_s) : nullptr;
  }
  j["check_seconds"] = check_seconds;
  return j;
}

nlohmann::json ImpulsiveCheckJson(const Scenario& s, const transcription::ImpulsiveCheck& c,
                                  const CheckVerdict& verdict, double check_seconds) {
  nlohmann::json j;
  j["passed"] = verdict.passed;
  j["findings"] = verdict.findings;
  j["operational_ok"] = true;  // impulsive problems have no operational rules
  j["rule_violations"] = nlohmann::json::array();
  j["window_unit"] =
      s.window_unit.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.window_unit);
  j["max_window_violation"] = OutputToWindow(s, c.max_window_violation);
  j["max_window_violation_nodes"] = OutputToWindow(s, c.max_window_violation);
  j["terminal_error"] = c.terminal_error;
  j["terminal_ok"] = c.terminal_error <= transcription::kTerminalTolerance;
  std::vector<double> fs(c.final_state.data(), c.final_state.data() + c.final_state.size());
  j["final_state"] = fs;
  j["check_seconds"] = check_seconds;
  return j;
}

nlohmann::json BurnsJson(const std::vector<transcription::Burn>& burns,
                         const std::vector<std::string>& thruster_names) {
  nlohmann::json out = nlohmann::json::array();
  for (const transcription::Burn& b : burns) {
    out.push_back({{"thruster", thruster_names.at(b.thruster)},
                   {"start_s", b.start_s},
                   {"duration_s", b.duration_s()},
                   {"end_s", b.end_s}});
  }
  return out;
}

nlohmann::json SolveResultJson(const transcription::ScheduleResult& r,
                               const std::vector<std::string>& names,
                               transcription::ObjectiveKind objective_kind, bool interrupted,
                               double total_seconds) {
  nlohmann::json j;
  const milp::SolveResult& sr = r.solve;
  const transcription::Schedule& sch = r.schedule;
  j["status"] = StatusName(sr.status);
  j["solver_detail"] = sr.detail;
  j["solver_version"] = sr.solver_version;
  j["interrupted"] = interrupted;
  j["objective_kind"] = std::string(transcription::ToString(objective_kind));
  j["objective"] = sr.has_solution() ? FiniteOrNull(sr.objective) : nullptr;
  j["best_bound"] = FiniteOrNull(sr.best_bound);
  j["gap"] = FiniteOrNull(sr.gap);
  j["nodes"] = sr.nodes;
  const bool has = r.has_schedule();
  j["consumption_l1_m_s"] = has ? FiniteOrNull(sch.consumption_l1_m_s) : nullptr;
  j["delta_v_m_s"] = has ? FiniteOrNull(sch.delta_v_m_s) : nullptr;
  j["propellant_kg"] = has ? FiniteOrNull(sch.propellant_kg) : nullptr;
  j["n_burns"] = sch.burns.size();
  j["burns"] = BurnsJson(sch.burns, names);
  j["n_binaries"] = r.stats.num_binaries;
  j["n_columns"] = r.stats.num_columns;
  j["n_rows"] = r.stats.num_rows;
  j["n_nonzeros"] = r.stats.num_nonzeros;
  j["discretise_seconds"] = r.stats.discretise_seconds;
  j["build_seconds"] = r.stats.build_seconds;
  j["solve_seconds"] = sr.wall_seconds;
  j["diagnosis_seconds"] = r.diagnosis_seconds;
  j["check_seconds"] = r.check_seconds;
  j["total_seconds"] = total_seconds;
  // The time limit's shares (transcription::ShareTimeLimit): null = none.
  j["solve_time_limit_s"] = FiniteOrNull(r.solve_time_limit_s);
  j["diagnosis_time_limit_s"] = FiniteOrNull(r.diagnosis_time_limit_s);
  nlohmann::json inc = nlohmann::json::array();
  for (const milp::Incumbent& c : sr.incumbents) {
    inc.push_back({{"wall_seconds", c.wall_seconds},
                   {"objective", FiniteOrNull(c.objective)},
                   {"best_bound", FiniteOrNull(c.best_bound)}});
  }
  j["incumbents"] = inc;
  j["infeasibility_reasons"] = r.infeasibility_reasons;
  return j;
}

namespace {

// summary.json's impulses and on-times (SummaryJson).
void AddScheduleDetails(const Scenario& s, const transcription::Schedule& sch,
                        const std::vector<std::string>& names, nlohmann::json* j) {
  if (s.impulsive()) {
    nlohmann::json imp = nlohmann::json::array();
    for (const transcription::Impulse& i : sch.impulses) {
      imp.push_back({{"thruster", names[i.thruster]},
                     {"node", i.node},
                     {"time_s", i.time_s},
                     {"delta_v_m_s", i.delta_v_m_s}});
    }
    (*j)["n_impulses"] = sch.impulses.size();
    (*j)["impulses"] = imp;
  }
  nlohmann::json on_time = nlohmann::json::object();
  for (size_t i = 0; i < sch.on_time_s.size() && i < names.size(); ++i) {
    on_time[names[i]] = sch.on_time_s[i];
  }
  (*j)["on_time_s"] = on_time;
}

// summary.json's settings: scheme, formulation, encoding, solver limits, grid, window.
void AddSettings(const Scenario& s, nlohmann::json* j) {
  (*j)["scheme"] = std::string(dynamics::ToString(s.build.discretisation.scheme));
  (*j)["formulation"] = std::string(ToString(s.build.formulation));
  (*j)["encoding"] = std::string(ToString(s.build.encoding));
  (*j)["threads"] = s.solve.threads;
  (*j)["time_limit_s"] = FiniteOrNull(s.solve.time_limit_s);
  (*j)["relative_gap"] = s.solve.relative_gap;
  (*j)["grid"] = {{"start_s", s.problem.grid.front()},
                  {"end_s", s.problem.grid.back()},
                  {"step_s", s.step_s},
                  {"num_intervals", s.num_intervals}};
  if (s.problem.window.enabled()) {
    (*j)["window"] = {
        {"unit", s.window_unit},
        {"half_widths", s.window_half_widths},
        {"outputs",
         {OutputName(s, s.problem.window.outputs[0]), OutputName(s, s.problem.window.outputs[1])}},
        {"enforce_from_s", FiniteOrNull(s.problem.window.enforce_from_s)},
        {"soft", s.problem.window.soft}};
  } else {
    (*j)["window"] = nullptr;
  }
}

// summary.json's "effective_rules": the rules as the grid encodes them, and as asked.
nlohmann::json EffectiveRulesJson(const Scenario& s, const transcription::ScheduleMilp& milp) {
  const transcription::OperationalEncoding& e = milp.encoding();
  const transcription::OperationalRules& rules = s.problem.rules;
  return {
      {"max_simultaneous", rules.max_simultaneous},
      {"min_burn_s", e.effective_min_burn_s},
      {"min_off_same_s", e.effective_min_off_same_s},
      {"min_gap_other_s", e.effective_min_gap_other_s},
      {"min_burn_intervals", {e.min_burn_intervals_min, e.min_burn_intervals_max}},
      {"min_off_same_intervals", {e.min_off_same_intervals_min, e.min_off_same_intervals_max}},
      {"min_gap_other_intervals", {e.min_gap_other_intervals_min, e.min_gap_other_intervals_max}},
      {"requested",
       {{"min_burn_s", rules.min_burn_s},
        {"min_off_same_s", rules.min_off_same_s},
        {"min_gap_other_s", rules.min_gap_other_s},
        {"max_burn_s", FiniteOrNull(rules.max_burn_s)},
        {"max_burns_per_thruster", rules.max_burns_per_thruster}}}};
}

// summary.json's "check" object (null when the schedule was not checked).
nlohmann::json SummaryCheckJson(const Scenario& s, const transcription::ScheduleResult& r,
                                const std::string& nonlinear_error) {
  if (!r.checked) return nullptr;
  nlohmann::json j = s.impulsive()
                         ? ImpulsiveCheckJson(s, r.impulsive_check,
                                              JudgeImpulsive(s, r.impulsive_check), r.check_seconds)
                         : CheckJson(s, r.check, Judge(s, r.check), r.check_seconds);
  if (!nonlinear_error.empty()) j["nonlinear_error"] = nonlinear_error;
  return j;
}

}  // namespace

nlohmann::json SummaryJson(const Scenario& s, const transcription::ScheduleMilp& milp,
                           const transcription::ScheduleResult& r, const RunFacts& facts) {
  const std::vector<std::string> names = s.thruster_names();
  const transcription::Schedule& sch = r.schedule;
  nlohmann::json j =
      SolveResultJson(r, names, s.problem.objective.kind, facts.interrupted, facts.total_seconds);
  j["name"] = s.name;
  j["scenario_file"] = s.path;
  j["command_line"] = facts.command_line;
  j["model"] = std::string(ToString(s.model_type));
  j["input_mode"] = s.impulsive() ? "impulsive" : "on_off";
  AddScheduleDetails(s, sch, names, &j);
  j["time_to_first_s"] = r.solve.incumbents.empty()
                             ? nlohmann::json(nullptr)
                             : FiniteOrNull(r.solve.incumbents.front().wall_seconds);
  AddSettings(s, &j);
  if (!s.impulsive()) j["effective_rules"] = EffectiveRulesJson(s, milp);
  if (r.has_schedule() && !sch.states.empty()) {
    const Eigen::VectorXd& xf = sch.states.back();
    j["final_state_discrete"] = std::vector<double>(xf.data(), xf.data() + xf.size());
    if (s.model_type == ModelType::kHcw)
      j["final_drift_term_m"] = FiniteOrNull(HcwDriftTerm(s, xf));
  }
  j["check"] = SummaryCheckJson(s, r, facts.nonlinear_error);
  if (s.problem.conjunction) {
    j["conjunction"] =
        ConjunctionJson(milp.keep_out(), facts.conjunction_solve, facts.conjunction_check);
  }
  if (s.min_time && facts.min_time != nullptr)
    j["min_time"] = MinTimeJson(*facts.min_time, *s.min_time);
  return j;
}

void WriteModelFile(const std::string& path, const milp::LpData& lp, bool obfuscate_names) {
  const size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".mps") {
    milp::MpsOptions o;
    o.obfuscate_names = obfuscate_names;
    milp::WriteMpsFile(path, lp, o);
  } else if (ext == ".lp") {
    milp::LpFormatOptions o;
    o.obfuscate_names = obfuscate_names;
    milp::WriteLpFile(path, lp, o);
  } else {
    throw std::invalid_argument(path + ": the model file must end in .mps or .lp");
  }
}

void WriteTextFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  out << text;
  out.close();
  if (!out) throw std::runtime_error(path + ": write failed");
}

void WriteJsonFile(const std::string& path, const nlohmann::json& json) {
  WriteTextFile(path, json.dump(2) + "\n");
}

std::string ScheduleCsvText(const Scenario& s, const std::vector<transcription::Burn>& burns,
                            const ReplayLeg* replay) {
  std::ostringstream os;
  os << "thruster,start_s,end_s,duration_s";
  std::vector<BurnFacts> facts;
  if (s.geo) {
    os << ",start_utc,end_utc,dir_r,dir_t,dir_n,delta_v_m_s";
    facts =
        ComputeBurnFacts(s, burns, replay != nullptr ? *replay : ScenarioReplayLeg(s, burns, {}));
  }
  os << "\n";
  const std::vector<std::string> names = s.thruster_names();
  for (size_t k = 0; k < burns.size(); ++k) {
    const transcription::Burn& b = burns[k];
    os << names.at(b.thruster) << "," << Fmt(b.start_s) << "," << Fmt(b.end_s) << ","
       << Fmt(b.duration_s());
    if (s.geo) {
      const BurnFacts& f = facts[k];
      os << "," << f.start_utc << "," << f.end_utc << "," << Fmt(f.direction_rtn.x()) << ","
         << Fmt(f.direction_rtn.y()) << "," << Fmt(f.direction_rtn.z()) << ","
         << Fmt(f.delta_v_m_s);
    }
    os << "\n";
  }
  return os.str();
}

void WriteScheduleCsv(const std::string& path, const Scenario& s,
                      const std::vector<transcription::Burn>& burns, const ReplayLeg* replay) {
  WriteTextFile(path, ScheduleCsvText(s, burns, replay));
}

std::string ImpulsesCsvText(const Scenario& s,
                            const std::vector<transcription::Impulse>& impulses) {
  std::ostringstream os;
  os << "thruster,node,time_s,delta_v_m_s\n";
  const std::vector<std::string> names = s.thruster_names();
  for (const transcription::Impulse& i : impulses) {
    os << names.at(i.thruster) << "," << i.node << "," << Fmt(i.time_s) << ","
       << FormatG(i.delta_v_m_s, 17) << "\n";
  }
  return os.str();
}

void WriteImpulsesCsv(const std::string& path, const Scenario& s,
                      const std::vector<transcription::Impulse>& impulses) {
  WriteTextFile(path, ImpulsesCsvText(s, impulses));
}

namespace {

std::string ReadCsvFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ScenarioError(path + ": read error");
  return text.str();
}

}  // namespace

std::vector<transcription::Burn> ReadScheduleCsv(const std::string& path, const Scenario& s) {
  return ParseScheduleCsv(ReadCsvFile(path), path, s);
}

std::vector<transcription::Impulse> ReadImpulsesCsv(const std::string& path, const Scenario& s) {
  return ParseImpulsesCsv(ReadCsvFile(path), path, s);
}

std::vector<transcription::Burn> ParseScheduleCsv(std::string_view text, const std::string& path,
                                                  const Scenario& s) {
  std::istringstream in{std::string(text)};
  const CsvTable t =
      ReadCsv(in, path, {"thruster", "start_s", "end_s"},
              {"duration_s", "start_utc", "end_utc", "dir_r", "dir_t", "dir_n", "delta_v_m_s"});
  std::vector<transcription::Burn> burns;
  for (const CsvTable::Row& row : t.rows) {
    transcription::Burn b;
    b.thruster = ThrusterOf(path, row, row.cells[t.column.at("thruster")], s);
    b.start_s = CellNumber(path, row, "start_s", t.column.at("start_s"));
    b.end_s = CellNumber(path, row, "end_s", t.column.at("end_s"));
    if (b.end_s < b.start_s) {
      throw ScenarioError(path + ":" + std::to_string(row.line) + ": end_s " + Fmt(b.end_s) +
                          " is before start_s " + Fmt(b.start_s));
    }
    auto d = t.column.find("duration_s");
    if (d != t.column.end()) {
      const double dur = CellNumber(path, row, "duration_s", d->second);
      if (std::abs(dur - b.duration_s()) >
          kDerivedTimeRelativeTolerance * std::max(1.0, std::abs(b.end_s))) {
        throw ScenarioError(path + ":" + std::to_string(row.line) + ": duration_s " + Fmt(dur) +
                            " disagrees with end_s - start_s = " + Fmt(b.duration_s()));
      }
    }
    CheckUtcCell(path, row, t, "start_utc", b.start_s, s);
    CheckUtcCell(path, row, t, "end_utc", b.end_s, s);
    burns.push_back(b);
  }
  return burns;
}

std::vector<transcription::Impulse> ParseImpulsesCsv(std::string_view text, const std::string& path,
                                                     const Scenario& s) {
  std::istringstream in{std::string(text)};
  const CsvTable t = ReadCsv(in, path, {"thruster", "node", "delta_v_m_s"}, {"time_s"});
  std::vector<transcription::Impulse> out;
  const int nn = s.problem.num_intervals();
  for (const CsvTable::Row& row : t.rows) {
    transcription::Impulse im;
    im.thruster = ThrusterOf(path, row, row.cells[t.column.at("thruster")], s);
    const double node = CellNumber(path, row, "node", t.column.at("node"));
    if (node != std::floor(node) || node < 0 || node > nn) {
      throw ScenarioError(path + ":" + std::to_string(row.line) +
                          ": node must be an integer in [0, " + std::to_string(nn) + "], got " +
                          Fmt(node));
    }
    im.node = static_cast<int>(node);
    im.time_s = s.problem.grid[im.node];
    auto tc = t.column.find("time_s");
    if (tc != t.column.end() && !row.cells[tc->second].empty()) {
      const double time = CellNumber(path, row, "time_s", tc->second);
      if (std::abs(time - im.time_s) >
          kDerivedTimeRelativeTolerance * std::max(1.0, std::abs(im.time_s))) {
        throw ScenarioError(path + ":" + std::to_string(row.line) + ": time_s " + Fmt(time) +
                            " is not the time of node " + std::to_string(im.node) + " (" +
                            Fmt(im.time_s) + ")");
      }
    }
    im.delta_v_m_s = CellNumber(path, row, "delta_v_m_s", t.column.at("delta_v_m_s"));
    if (im.delta_v_m_s < 0.0) {
      throw ScenarioError(path + ":" + std::to_string(row.line) +
                          ": delta_v_m_s must be >= 0, got " + Fmt(im.delta_v_m_s));
    }
    out.push_back(im);
  }
  return out;
}

std::vector<std::string> TrajectoryColumns(const Scenario& s, bool with_nonlinear) {
  std::vector<std::string> c = {"t_s"};
  const dynamics::LinearModel& m = *s.problem.model;
  if (s.model_type == ModelType::kGeo) {
    c.push_back("utc");
    for (const std::string& n : m.state_names()) c.push_back(n);
    for (const std::string& n : m.output_names()) c.push_back(n);
    c.push_back("lin_lat_deg");
    c.push_back("lin_dlon_deg");
    if (with_nonlinear) {
      for (const char* n : {"x_m", "y_m", "z_m", "vx_m_s", "vy_m_s", "vz_m_s", "r_m", "lat_deg",
                            "lon_deg", "dlon_deg", "dr_nl_m"}) {
        c.push_back(n);
      }
    }
  } else {
    for (const std::string& n : m.state_names()) c.push_back(n);
    if (s.model_type == ModelType::kHcw) c.push_back("drift_m");
  }
  for (const std::string& n : s.thruster_names()) c.push_back("on_" + n);
  return c;
}

std::string TrajectoryCsvText(const Scenario& s, const transcription::CheckReport& r,
                              const std::vector<transcription::Burn>& burns) {
  // The nonlinear columns need the scenario's simulator (for the geographic
  // position): a report replayed by another simulator, with the scenario's
  // switched off, gets the linear columns only.
  const bool nl = s.model_type == ModelType::kGeo && r.nonlinear_checked &&
                  s.check.nonlinear != nullptr && r.nonlinear_eci.size() == r.sample_times.size();
  const std::vector<std::string> cols = TrajectoryColumns(s, nl);
  std::ostringstream os;
  for (size_t i = 0; i < cols.size(); ++i) os << (i ? "," : "") << cols[i];
  os << "\n";
  std::optional<dynamics::Epoch> epoch;
  if (s.geo) epoch = dynamics::Epoch::Parse(s.geo->epoch);
  const double rad2deg = 180.0 / kPi;
  for (size_t k = 0; k < r.sample_times.size(); ++k) {
    const double t = r.sample_times[k];
    const Eigen::VectorXd& x = r.sample_states[k];
    os << Fmt(t);
    if (s.model_type == ModelType::kGeo) {
      os << "," << epoch->PlusSeconds(t).ToIso8601();
      for (int i = 0; i < x.size(); ++i) os << "," << Fmt(x[i]);
      const Eigen::VectorXd& y = r.sample_outputs[k];
      for (int i = 0; i < y.size(); ++i) os << "," << Fmt(y[i]);
      os << "," << Fmt(y[1] * rad2deg) << "," << Fmt(y[2] * rad2deg);
      if (nl) {
        const dynamics::Vector6d& e = r.nonlinear_eci[k];
        for (int i = 0; i < 6; ++i) os << "," << Fmt(e[i]);
        const dynamics::GeoPoint g = s.check.nonlinear->Geographic(e, t);
        const Eigen::Vector3d& yn = r.nonlinear_outputs[k];
        os << "," << Fmt(g.r_m) << "," << Fmt(g.lat_rad * rad2deg) << ","
           << Fmt(g.lon_rad * rad2deg) << "," << Fmt(yn[2] * rad2deg) << "," << Fmt(yn[0]);
      }
    } else {
      for (int i = 0; i < x.size(); ++i) os << "," << Fmt(x[i]);
      if (s.model_type == ModelType::kHcw) os << "," << Fmt(HcwDriftTerm(s, x));
    }
    for (int f : OnFlags(s, burns, t)) os << "," << f;
    os << "\n";
  }
  return os.str();
}

void WriteTrajectoryCsv(const std::string& path, const Scenario& s,
                        const transcription::CheckReport& r,
                        const std::vector<transcription::Burn>& burns) {
  WriteTextFile(path, TrajectoryCsvText(s, r, burns));
}

std::string ImpulsiveTrajectoryCsvText(const Scenario& s,
                                       const std::vector<transcription::Impulse>& impulses) {
  const transcription::ScheduleProblem& p = s.problem;
  const dynamics::LinearModel& model = *p.model;
  const int nn = p.num_intervals();
  const int m = p.thrusters.size();
  std::vector<Eigen::Vector3d> kick(nn + 1, Eigen::Vector3d::Zero());
  std::vector<std::vector<int>> fired(nn + 1, std::vector<int>(m, 0));
  for (const transcription::Impulse& im : impulses) {
    kick.at(im.node) += im.delta_v_m_s * p.thrusters.thruster(im.thruster).direction;
    fired.at(im.node).at(im.thruster) = 1;
  }
  const std::vector<std::string> cols = TrajectoryColumns(s, false);
  std::ostringstream os;
  for (size_t i = 0; i < cols.size(); ++i) os << (i ? "," : "") << cols[i];
  os << "\n";
  std::optional<dynamics::Epoch> epoch;
  if (s.geo) epoch = dynamics::Epoch::Parse(s.geo->epoch);
  const int q = std::max(0, s.check.samples_per_interval);
  const Eigen::MatrixXd no_input = Eigen::MatrixXd::Zero(3, 1);
  auto write_row = [&](double t, const Eigen::VectorXd& x, const std::vector<int>& on) {
    os << Fmt(t);
    if (s.model_type == ModelType::kGeo) {
      os << "," << epoch->PlusSeconds(t).ToIso8601();
      for (int i = 0; i < x.size(); ++i) os << "," << Fmt(x[i]);
      const Eigen::VectorXd y = model.EvaluateOutput(t).c * x;
      for (int i = 0; i < y.size(); ++i) os << "," << Fmt(y[i]);
      os << "," << Fmt(y[1] * 180.0 / kPi) << "," << Fmt(y[2] * 180.0 / kPi);
    } else {
      for (int i = 0; i < x.size(); ++i) os << "," << Fmt(x[i]);
      if (s.model_type == ModelType::kHcw) os << "," << Fmt(HcwDriftTerm(s, x));
    }
    for (int f : on) os << "," << f;
    os << "\n";
  };
  Eigen::VectorXd x = p.initial_state;
  const std::vector<int> none(m, 0);
  for (int j = 0; j <= nn; ++j) {
    x += model.Evaluate(p.grid[j]).b * kick[j];  // state just after the impulse
    write_row(p.grid[j], x, fired[j]);
    if (j == nn) break;
    std::vector<double> samples;
    const double h = p.grid[j + 1] - p.grid[j];
    for (int k = 1; k <= q; ++k) samples.push_back(p.grid[j] + h * k / (q + 1));
    samples.push_back(p.grid[j + 1]);
    const std::vector<Eigen::VectorXd> xs = dynamics::PropagateLinear(
        model, no_input, x, p.grid[j], {}, samples, s.check.propagation_tolerance);
    for (int k = 0; k < q; ++k) write_row(samples[k], xs[k], none);
    x = xs.back();
  }
  return os.str();
}

void WriteImpulsiveTrajectoryCsv(const std::string& path, const Scenario& s,
                                 const std::vector<transcription::Impulse>& impulses) {
  WriteTextFile(path, ImpulsiveTrajectoryCsvText(s, impulses));
}

}  // namespace thrustsched::app
