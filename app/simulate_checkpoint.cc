// checkpoint.json of `thrustsched simulate`: the exact state after the last
// finished cycle and every cycle's record, read back by --resume.
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

// A status of checkpoint.json. The checkpoint writes milp::ToString's names
// ("no_solution_found"), summary.json and cycles.csv write StatusName's
// ("no_solution"): both are contracts with outside readers, so neither file
// changes; this reader accepts both spellings instead, so a checkpoint edited
// or produced with the summary's names still resumes.
milp::SolveStatus ParseStatus(const std::string& name, const std::string& path) {
  if (name == StatusName(milp::SolveStatus::kNoSolutionFound))
    return milp::SolveStatus::kNoSolutionFound;
  for (milp::SolveStatus s : {milp::SolveStatus::kOptimal, milp::SolveStatus::kFeasible,
                              milp::SolveStatus::kInfeasible, milp::SolveStatus::kUnbounded,
                              milp::SolveStatus::kNoSolutionFound, milp::SolveStatus::kError}) {
    if (name == milp::ToString(s)) return s;
  }
  throw ScenarioError(path + ": unknown solver status \"" + name + "\"");
}

// JSON helpers for the checkpoint (numbers round-trip exactly: nlohmann
// writes the shortest representation that reads back to the same double).

double GetNumber(const nlohmann::json& j, const char* key, const std::string& path) {
  if (!j.contains(key)) throw ScenarioError(path + "." + key + ": missing");
  const nlohmann::json& v = j.at(key);
  if (v.is_null()) return kNaN;
  if (!v.is_number())
    throw ScenarioError(path + "." + key + ": expected a number, got " + DescribeJson(v));
  return v.get<double>();
}

double GetInteger(const nlohmann::json& j, const char* key, const std::string& path, double min,
                  double max) {
  const double v = GetNumber(j, key, path);
  if (!(v >= min && v <= max && v == std::floor(v))) {  // also rejects null (NaN)
    throw ScenarioError(path + "." + key + ": expected an integer in [" + FormatNumber(min) + ", " +
                        FormatNumber(max) + "], got " + DescribeJson(j.at(key)));
  }
  return v;
}

std::vector<double> GetNumbers(const nlohmann::json& j, const char* key, const std::string& path,
                               double null_value) {
  if (!j.contains(key) || !j.at(key).is_array()) {
    throw ScenarioError(path + "." + key + ": expected an array");
  }
  std::vector<double> out;
  for (const nlohmann::json& v : j.at(key)) {
    if (v.is_null()) {
      out.push_back(null_value);
    } else if (v.is_number()) {
      out.push_back(v.get<double>());
    } else {
      throw ScenarioError(path + "." + key + ": expected numbers, got " + DescribeJson(v));
    }
  }
  return out;
}

nlohmann::json VectorJson(const Eigen::VectorXd& v) {
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < v.size(); ++i) a.push_back(FiniteOrNull(v(i)));
  return a;
}

Eigen::VectorXd ToVector(const std::vector<double>& v) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(v.size()));
  for (size_t i = 0; i < v.size(); ++i) x(static_cast<Eigen::Index>(i)) = v[i];
  return x;
}

dynamics::Vector6d ToVector6(const std::vector<double>& v, const std::string& path) {
  if (v.size() != 6)
    throw ScenarioError(path + ": expected 6 numbers, got " + std::to_string(v.size()));
  dynamics::Vector6d x;
  for (int i = 0; i < 6; ++i) {
    if (!std::isfinite(v[i]))
      throw ScenarioError(path + ": non-finite component " + std::to_string(i));
    x(i) = v[i];
  }
  return x;
}

nlohmann::json CheckpointJson(const SimulationSetup& setup, const planning::LongHorizonState& st,
                              const std::vector<CycleRecord>& cycles) {
  nlohmann::json j;
  j["format"] = kCheckpointFormat;
  j["scenario"] = setup.scenario.path;
  j["fingerprint"] = setup.fingerprint;
  j["next_cycle"] = st.next_cycle;
  j["time_s"] = st.time_s;
  j["eci"] = VectorJson(st.eci);
  nlohmann::json last = nlohmann::json::array();
  for (double e : st.last_burn_end_s) last.push_back(FiniteOrNull(e));  // null = never fired
  j["last_burn_end_s"] = last;
  nlohmann::json c = nlohmann::json::array();
  for (const CycleRecord& r : cycles) c.push_back(CycleRecordJson(r));
  j["cycles"] = c;
  return j;
}

void ReadCheckpoint(const std::string& path, const SimulationSetup& setup, int num_thrusters,
                    planning::LongHorizonState* st, std::vector<CycleRecord>* cycles) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot open the checkpoint");
  std::ostringstream ss;
  ss << in.rdbuf();
  ParseCheckpoint(ss.str(), path, setup, num_thrusters, st, cycles);
}

void ParseCheckpoint(const std::string& text, const std::string& path, const SimulationSetup& setup,
                     int num_thrusters, planning::LongHorizonState* st,
                     std::vector<CycleRecord>* cycles) {
  const nlohmann::json j = ParseJsonText(text, path);
  // j.value(key, "") throws a JSON type_error (exit 1) on a non-string.
  auto text_of = [&j](const char* key, const char* absent) {
    return j.contains(key) && j.at(key).is_string() ? j.at(key).get<std::string>()
                                                    : std::string(absent);
  };
  if (!j.is_object() || text_of("format", "") != kCheckpointFormat) {
    throw ScenarioError(path + ": not a thrustsched year checkpoint (format " +
                        std::string(kCheckpointFormat) + ")");
  }
  if (text_of("fingerprint", "") != setup.fingerprint) {
    throw ScenarioError(path +
                        ": the checkpoint was written for another scenario or other "
                        "settings (fingerprint " +
                        text_of("fingerprint", "?") + ", this scenario " + setup.fingerprint +
                        "); run without --resume to start again");
  }
  st->next_cycle = static_cast<int>(GetInteger(j, "next_cycle", path, 0, kMaxCheckpointCycles));
  st->time_s = GetNumber(j, "time_s", path);
  st->eci = ToVector6(GetNumbers(j, "eci", path), path + ".eci");
  st->last_burn_end_s = GetNumbers(j, "last_burn_end_s", path, -kInf);
  if (static_cast<int>(st->last_burn_end_s.size()) != num_thrusters) {
    throw ScenarioError(path + ".last_burn_end_s: " + std::to_string(st->last_burn_end_s.size()) +
                        " entries for " + std::to_string(num_thrusters) + " thrusters");
  }
  if (!j.contains("cycles") || !j.at("cycles").is_array()) {
    throw ScenarioError(path + ".cycles: expected an array");
  }
  cycles->clear();
  for (size_t k = 0; k < j.at("cycles").size(); ++k) {
    const std::string at = path + ".cycles[" + std::to_string(k) + "]";
    cycles->push_back(CycleRecordFromJson(j.at("cycles")[k], at));
    for (const transcription::Burn& b : cycles->back().burns) {
      if (b.thruster < 0 || b.thruster >= num_thrusters) {
        throw ScenarioError(at + ".burns: thruster " + std::to_string(b.thruster) +
                            " is not one of the scenario's " + std::to_string(num_thrusters));
      }
    }
  }
  if (static_cast<int>(cycles->size()) != st->next_cycle) {
    throw ScenarioError(path + ": " + std::to_string(cycles->size()) +
                        " cycle records for next_cycle " + std::to_string(st->next_cycle));
  }
}

}  // namespace simulate_detail

}  // namespace thrustsched::app
