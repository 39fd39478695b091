// Section 10 of report.md: the orbit transfers (transfer/, docs/transfer.md)
// - each case's figure (duration, or the two-impulse velocity) against the
// published one, the feedback phase against Bombrun 2007 Table 5.2's, the
// propellant against T t_f / (g0 Isp) of the published minimum time, and the
// tool's time.
//
//   std::ostringstream md;
//   bench::WriteTransfers(md, rows);   // rows of results.csv
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_TRANSFER_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_TRANSFER_H_

#include <ostream>
#include <vector>

#include "benchmarks/bench/results.h"

namespace thrustsched::bench {

/// Writes the section from the rows of section "transfer" ("Not run." if none).
void WriteTransfers(std::ostream& md, const std::vector<Row>& rows);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_TRANSFER_H_
