// Section 7 of report.md: collision avoidance (Serra 2015 ch. 4) - the
// cost and the time to proven optimality with CBC next to the published cost
// and Gurobi 5.6's time, and the verification of each plan.
//
//   std::ostringstream md;
//   bench::WriteCollisionAvoidance(md, rows);   // rows of results.csv
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_CONJUNCTION_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_CONJUNCTION_H_

#include <ostream>
#include <vector>

#include "benchmarks/bench/results.h"

namespace thrustsched::bench {

/// Writes the section from the rows of section "collision_avoidance" ("Not run." if none).
void WriteCollisionAvoidance(std::ostream& md, const std::vector<Row>& rows);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_CONJUNCTION_H_
