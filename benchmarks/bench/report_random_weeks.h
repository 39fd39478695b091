// Section 11 of report.md: the search on GEO weeks nobody chose
// (scripts/random_weeks.py from kRandomWeeksSeed), this release against the
// previous one in the same run: the distribution of the time to a proven
// 1 % gap (median, p90, max), how many weeks end without a schedule, how
// many are not within 1 % in the limit, the per-preset targets, the ratio
// of the two arms, and whether each arm's bound is consistent with the other
// arm's schedule (two LP solvers: a safe bound can never exceed a schedule).
//
//   std::ostringstream md;
//   bench::WriteRandomWeeks(md, rows);   // rows of results.csv
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_RANDOM_WEEKS_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_RANDOM_WEEKS_H_

#include <ostream>
#include <vector>

#include "benchmarks/bench/results.h"

namespace thrustsched::bench {

/// The value at quantile q in [0, 1] of `v` by nearest rank (the smallest
/// value with at least q of the values at or below it); +inf entries count
/// as the largest; NaN when `v` is empty.
double NearestRankQuantile(std::vector<double> v, double q);

/// Writes the section from the rows of section "random_weeks" ("Not run." if none).
void WriteRandomWeeks(std::ostream& md, const std::vector<Row>& rows);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_RANDOM_WEEKS_H_
