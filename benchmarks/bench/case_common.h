// Pieces shared by the case executors of thrustsched-bench (runner.cc,
// conjunction_case.cc, external_solvers.cc): the case's scenario with its
// merge patch applied, the columns every row of a case carries, file reading.
//
//   app::Scenario s = bench::LoadPatched(spec);
//   bench::Row r = bench::BaseRow(spec, repeat, s);
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_CASE_COMMON_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_CASE_COMMON_H_

#include <string>

#include <nlohmann/json.hpp>

#include "app/scenario.h"
#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/results.h"

namespace thrustsched::bench {

/// The scenario file of `spec` with spec.patch (then `extra`) merged in,
/// parsed by app::ParseScenario. @throws app::ScenarioError.
app::Scenario LoadPatched(const CaseSpec& spec, const nlohmann::json& extra = {});
/// The columns every row of a case has: section, case_id, repeat, variant
/// and scenario.
Row CaseHeaderRow(const CaseSpec& spec, int repeat);
/// CaseHeaderRow, then model, scheme, formulation,
/// encoding, step, horizon, thruster count, published value and note.
Row BaseRow(const CaseSpec& spec, int repeat, const app::Scenario& s);
/// The whole file as text. @throws std::runtime_error naming the path.
std::string ReadTextFile(const std::string& path);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_CASE_COMMON_H_
