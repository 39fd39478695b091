// Benchmark rows of the orbit transfers (transfer/, `thrustsched transfer`):
// the run of a transfer scenario (with the case's merge patch) timed whole,
// its figure (duration, or the two-impulse velocity) next to the published
// one, the feedback phase next to Bombrun 2007 Table 5.2's, and the
// propellant next to T t_f / (g0 Isp) of the published minimum time.
//
//   bench::CaseSpec c = ...;   // kind CaseKind::kTransfer, reference_id/_key set
//   std::vector<bench::Row> rows = bench::ExecuteTransfer(c, 0, ctx);
//
// Published values come from data/reference/transfers.json (the case
// spec.reference_id, the figure spec.reference_key), found next to the
// scenario directory (scenarios/transfer/../../reference).
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_TRANSFER_CASE_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_TRANSFER_CASE_H_

#include <vector>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/results.h"
#include "benchmarks/bench/runner.h"

namespace thrustsched::bench {

/// @throws on any failure (the runner turns it into an error row).
std::vector<Row> ExecuteTransfer(const CaseSpec& spec, int repeat, const RunContext& context);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_TRANSFER_CASE_H_
