#include "benchmarks/bench/transfer_case.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "app/json_reader.h"
#include "app/transfer_run.h"
#include "app/transfer_scenario.h"
#include "benchmarks/bench/case_common.h"
#include "common/constants.h"
#include "common/timing.h"

namespace thrustsched::bench {
namespace {

using nlohmann::json;

// The case `id` of data/reference/transfers.json.
json ReferenceCase(const std::string& scenario_path, const std::string& id) {
  namespace fs = std::filesystem;
  const fs::path ref = fs::path(scenario_path).parent_path().parent_path().parent_path() /
                       "reference" / "transfers.json";
  std::ifstream in(ref);
  if (!in) throw std::runtime_error("cannot read " + ref.string());
  const json all = json::parse(in);
  for (const json& c : all.at("cases")) {
    if (c.value("id", "") == id) return c;
  }
  throw std::runtime_error(ref.string() + ": no case " + id);
}

// The unit of a reference key by its suffix, and the run's figure in it.
std::string UnitOf(const std::string& key) {
  for (const char* u : {"_km_s", "_h", "_d"}) {
    const std::string s(u);
    if (key.size() > s.size() && key.compare(key.size() - s.size(), s.size(), s) == 0) {
      return s.substr(1);
    }
  }
  throw std::invalid_argument("transfer case: no unit suffix (_h, _d, _km_s) in " + key);
}

double FigureIn(const json& summary, const std::string& unit) {
  if (unit == "km_s") return summary.at("two_impulse").at("total_dv_m_s").get<double>() / 1e3;
  const double s = summary.at("duration_s").get<double>();
  return unit == "h" ? s / 3600 : s / common::kSecondsPerDay;
}

void SetPublished(const CaseSpec& spec, const std::string& unit, Row* r) {
  const json ref = ReferenceCase(spec.scenario_path, spec.reference_id);
  const json* v = &ref;
  if (ref.contains(spec.reference_key)) {
    v = &ref.at(spec.reference_key);
  } else if (ref.contains("derived") && ref.at("derived").contains(spec.reference_key)) {
    v = &ref.at("derived").at(spec.reference_key);
  } else {
    throw std::runtime_error("transfers.json: case " + spec.reference_id + " has no " +
                             spec.reference_key);
  }
  r->Set("published", v->get<double>());
  r->Set("published_source", spec.reference_id + "." + spec.reference_key + " (" + unit + ")");
  if (ref.contains("feedback_phase_d")) {
    r->Set("published_feedback_phase", ref.at("feedback_phase_d").get<double>());
  }
  if (ref.contains("propellant_kg_derived")) {
    r->Set("propellant_limit_kg", ref.at("propellant_kg_derived").get<double>());
  }
}

}  // namespace

std::vector<Row> ExecuteTransfer(const CaseSpec& spec, int repeat, const RunContext& /*context*/) {
  json j = app::ParseJsonText(ReadTextFile(spec.scenario_path), spec.scenario_path);
  j = MergePatch(j, spec.patch);
  const app::TransferScenario sc = app::ParseTransferScenario(j, spec.scenario_path);
  Row r = CaseHeaderRow(spec, repeat);
  if (!spec.note.empty()) r.Set("note", spec.note);
  const std::string unit = UnitOf(spec.reference_key);
  SetPublished(spec, unit, &r);
  const auto t0 = common::Clock::now();
  const app::TransferRun run = app::RunTransferScenario(sc, spec.scenario_path, /*quiet=*/true);
  r.Set("solve_s", common::Since(t0));
  const json& s = run.summary;
  r.Set("status", s.at("status").get<std::string>());
  r.Set("transfer_method", s.at("method").get<std::string>());
  r.Set("transfer_unit", unit);
  r.Set("transfer_figure", FigureIn(s, unit));
  r.Set("ratio", r.Num("transfer_figure") / r.Num("published"));
  r.Set("propellant_kg", s.at("propellant_kg").get<double>());
  r.Set("revolutions", s.at("revolutions").get<double>());
  if (s.contains("feedback")) {
    r.Set("feedback_phase",
          s.at("feedback").at("duration_s").get<double>() / common::kSecondsPerDay);
  }
  if (s.contains("optimal_end") && s.at("optimal_end").contains("switch")) {
    r.Set("switch_rule", s.at("optimal_end").at("switch").at("rule").get<std::string>());
  }
  return {r};
}

}  // namespace thrustsched::bench
