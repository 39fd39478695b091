// The published figures and the project's own targets that report.md
// compares against, read from data/reference/ (each figure there carries its
// table, section and line in the source), so no number of a paper lives in
// the report's code.
//
//   const bench::BenchReference ref = bench::LoadBenchReference("data/reference");
//   md << "Table 4.3: " << ref.table_4_3_tm_rules_on << " m/s";   // 4.596
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REFERENCE_FIGURES_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REFERENCE_FIGURES_H_

#include <string>

namespace thrustsched::bench {

struct BenchReference {
  // Gazzino 2018 sec. 4.4.3, the constrained-final-state week (m/s, L1):
  // Table 4.3 with/without the operational rules, Table 4.4 with a 10-min
  // minimum burn (p = 2), for transition matrices (TM) and Hermite-Simpson (HS).
  double table_4_3_tm_rules_on = 0.0;
  double table_4_3_tm_rules_off = 0.0;
  double table_4_3_hs_rules_on = 0.0;
  double table_4_3_hs_rules_off = 0.0;
  double table_4_4_tm_p2 = 0.0;
  double table_4_4_hs_p2 = 0.0;
  // Gazzino 2018 sec. 4.4.1: the free-final-state week, both methods (m/s).
  double free_final_week_m_s = 0.0;
  // Gazzino 2018 Table 5.2: the year with chebfun transition matrices and with
  // Hermite-Simpson (m/s).
  double table_5_2_chebfun_m_s = 0.0;
  double table_5_2_hermite_simpson_m_s = 0.0;
  // Gazzino 2018 Table 5.3, 7-day horizon: mean solve time per cycle (s, Gurobi).
  double thesis_seconds_per_cycle = 0.0;
  // The project's targets (data/reference/bench_targets.json), seconds.
  double target_discretise_week_s = 0.0;
  double target_build_week_s = 0.0;
  double target_table_4_2_within_1pct_s = 0.0;
  double target_geo_week_1pct_gap_s = 0.0;
  double target_year_wall_s = 0.0;
};

/// Reads thesis_tables.json, thesis_chapter5.json and bench_targets.json from
/// `reference_dir`. @throws std::runtime_error naming the file and the entry
/// when one is missing or not a number.
BenchReference LoadBenchReference(const std::string& reference_dir);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REFERENCE_FIGURES_H_
