// The solver-speed section of report.md: the problem-aware search (this
// release) against CBC on the whole MILP (the first release's path), case by
// case from the same run, with the targets and by how much each is met or
// missed.
//
//   std::ostringstream md;
//   bench::WriteSolverSpeed(md, rows);   // rows of results.csv
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_SOLVER_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_SOLVER_H_

#include <ostream>
#include <vector>

#include "benchmarks/bench/results.h"

namespace thrustsched::bench {

/// Writes the section from the rows of section "solver_speed" ("Not run." if none).
void WriteSolverSpeed(std::ostream& md, const std::vector<Row>& rows);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_SOLVER_H_
