#include "benchmarks/bench/reference_figures.h"

#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace thrustsched::bench {
namespace {

nlohmann::json ReadJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

// The number at a JSON pointer such as "/table_4_3/hermite_simpson/rules_on".
double Figure(const nlohmann::json& j, const std::string& path, const std::string& pointer) {
  const nlohmann::json::json_pointer p(pointer);
  if (!j.contains(p) || !j.at(p).is_number()) {
    throw std::runtime_error(path + ": no number at " + pointer);
  }
  return j.at(p).get<double>();
}

}  // namespace

BenchReference LoadBenchReference(const std::string& reference_dir) {
  BenchReference r;
  const std::string ch4 = reference_dir + "/thesis_tables.json";
  const nlohmann::json t = ReadJson(ch4);
  const std::string w = "/constrained_final_week_ch4";
  r.table_4_3_tm_rules_on = Figure(t, ch4, w + "/table_4_3/transition_matrices/rules_on");
  r.table_4_3_tm_rules_off = Figure(t, ch4, w + "/table_4_3/transition_matrices/rules_off");
  r.table_4_3_hs_rules_on = Figure(t, ch4, w + "/table_4_3/hermite_simpson/rules_on");
  r.table_4_3_hs_rules_off = Figure(t, ch4, w + "/table_4_3/hermite_simpson/rules_off");
  r.table_4_4_tm_p2 = Figure(t, ch4, w + "/table_4_4/transition_matrices/p2");
  r.table_4_4_hs_p2 = Figure(t, ch4, w + "/table_4_4/hermite_simpson/p2");
  r.free_final_week_m_s = Figure(t, ch4, "/perturbed_week_ch4/free_final_state_consumption_m_s");

  const std::string ch5 = reference_dir + "/thesis_chapter5.json";
  const nlohmann::json y = ReadJson(ch5);
  r.table_5_2_chebfun_m_s = Figure(y, ch5, "/results/nominal_anzel_fixed/also/table_5_2_chebfun");
  r.table_5_2_hermite_simpson_m_s =
      Figure(y, ch5, "/results/nominal_anzel_fixed/also/table_5_2_hermite_simpson");
  r.thesis_seconds_per_cycle = Figure(y, ch5, "/other_published/mean_solve_time_per_cycle_s/value");

  const std::string tg = reference_dir + "/bench_targets.json";
  const nlohmann::json g = ReadJson(tg);
  r.target_discretise_week_s = Figure(g, tg, "/discretise_geo_week_s");
  r.target_build_week_s = Figure(g, tg, "/build_geo_week_milp_s");
  r.target_table_4_2_within_1pct_s = Figure(g, tg, "/table_4_2_t1_2d_within_1pct_of_optimum_s");
  r.target_geo_week_1pct_gap_s = Figure(g, tg, "/geo_week_anzel4_proven_1pct_gap_s");
  r.target_year_wall_s = Figure(g, tg, "/year_anzel4_fixed_wall_s");
  return r;
}

}  // namespace thrustsched::bench
