// Benchmark rows of the collision-avoidance cases (Serra 2015 ch. 4; any
// scenario with a conjunction, impulsive or on-off): the whole
// SolveConjunction (start and budget rounds) timed from the first build to
// the proven optimum, next to the published cost and Gurobi 5.6 time, and
// the plan's verification (computed maximum instantaneous risk, with and
// without manoeuvre, and the Monte Carlo of the scenario's own size, linear
// and two-body).
//
//   bench::CaseSpec c = ...;              // kind CaseKind::kConjunction
//   std::vector<bench::Row> rows = bench::ExecuteConjunction(c, 0, ctx);
//
// Published values come from data/reference/serra_avoidance.json (the case
// whose scenario_file is the case's scenario), found next to the scenario
// directory; cases without one have none.
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_CONJUNCTION_CASE_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_CONJUNCTION_CASE_H_

#include <vector>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/results.h"
#include "benchmarks/bench/runner.h"

namespace thrustsched::bench {

/// @throws on any failure (the runner turns it into an error row).
std::vector<Row> ExecuteConjunction(const CaseSpec& spec, int repeat, const RunContext& context);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_CONJUNCTION_CASE_H_
