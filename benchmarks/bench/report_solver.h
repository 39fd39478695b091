// The solver-speed section of report.md: the problem-aware search (this
// release) against the same search with one named switch off (`previous`)
// and CBC alone on the whole MILP, case by case from the same run, with the
// targets and by how much each is met or missed. The steps the search took
// go to one log per case (DIR/logs/<case id>.log), not into report.md.
//
//   std::ostringstream md;
//   bench::WriteSolverSpeed(md, rows, "docs/bench");   // rows of results.csv
//   for (const bench::SolverTarget& t : bench::SolverSpeedTargets(rows)) ...
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_SOLVER_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_SOLVER_H_

#include <ostream>
#include <string>
#include <vector>

#include "benchmarks/bench/results.h"

namespace thrustsched::bench {

/// One target of one solver-speed case, measured on the `search` arm.
struct SolverTarget {
  std::string case_id;  // without the arm's suffix, e.g. "solver_speed-geo_week_anzel4-2threads"
  std::string measure;  // "time to a proven 1 % gap", "within 2.00 % of its bound", ...
  bool gap_target = false;  // "within x % of its bound in limit_s"
  double limit_s = 0.0;
  double median_s = 0.0;  // median over the repeats; +inf: not reached in most
};

/// A solver-speed case id as the report prints it, without "solver_speed-".
std::string SolverCaseShortId(const std::string& case_id);

/// The targets of every solver-speed case in `rows`, in the order of the rows.
std::vector<SolverTarget> SolverSpeedTargets(const std::vector<Row>& rows);

/// Writes the section from the rows of section "solver_speed" ("Not run." if
/// none) and DIR/logs/<case id>.log (the search's steps, one per line, every
/// repeat of that arm; earlier *.log files in DIR/logs/ are removed).
/// @throws std::runtime_error naming the file if a log cannot be written.
void WriteSolverSpeed(std::ostream& md, const std::vector<Row>& rows, const std::string& dir);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_SOLVER_H_
