// Runs one benchmark case. RunCase forks a child process per run, so that
//  - peak memory (ru_maxrss of the child) belongs to that configuration only
//    (it includes the few MB the parent had mapped at fork time);
//  - a crash or a runaway solve loses one row, not the benchmark (the parent
//    kills the child at a deadline well past its time limit);
//  - CBC's process-wide state starts fresh for every solve.
// The child executes ExecuteCase and writes its rows (JSON) to
// DIR/runs/<case id>-r<repeat>.json, plus the solver progress trace
// (<...>.trace.csv: wall_s, objective, best_bound) and, for the external
// cross-check, the exported MPS file and the other solvers' logs.
//
//   bench::RunContext ctx{"out/bench/runs"};
//   std::vector<bench::Row> rows = bench::RunCase(spec, /*repeat=*/0, ctx);
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_RUNNER_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_RUNNER_H_

#include <string>
#include <vector>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/results.h"

namespace thrustsched::bench {

struct RunContext {
  std::string runs_dir;   // must exist
  bool fork = true;       // false: run in-process (debugging)
  bool keep_mps = false;  // keep exported MPS files after the cross-check
  /// Phases of the search left out in every search case (--disable-phases).
  std::vector<std::string> disabled_phases;
};

/// Runs `spec` (repeat number `repeat`, 0-based) in a child process and
/// returns its rows, with wall_s, exit and peak_rss_mb filled by the parent.
/// Never throws for a failing case: the row then has status "error" (or
/// "killed" / "crashed") and the reason in `note`.
std::vector<Row> RunCase(const CaseSpec& spec, int repeat, const RunContext& context);

/// The work itself (in the child). @throws on any failure (caught by RunCase).
std::vector<Row> ExecuteCase(const CaseSpec& spec, int repeat, const RunContext& context);

/// True if `program` is found in PATH (for the external cross-check).
bool ProgramAvailable(const std::string& program);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_RUNNER_H_
