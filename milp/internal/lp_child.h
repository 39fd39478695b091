// CLP's interior point in a child process (internal to the CBC backend).
//
//   LpChildOutcome c = SolveLpCoreInChild(lp, arrays, options, &clock);
//   if (c.died) { /* c.why names the signal; solve with the simplex instead */ }
//   std::vector<LpChildOutcome> two =
//       SolveLpCoresInChildren({{&lp_a, &arrays_a}, {&lp_b, &arrays_b}}, options, &clock);
//
// Why: CLP 1.17's predictor-corrector calls abort() when its iterate diverges
// ("primal off to infinity", ClpPredictorCorrector::updateSolution), which
// would take the whole program down with it. In a child (fork) that abort
// costs only the attempt; the caller falls back to the simplex. The child also
// stops at once when the clock says so (it is killed).
//
// The child runs SolveLpCore and sends through a pipe its progress reports
// (the interior point's iterations and objective) and then its outcome
// (status, iterations, objective, x, duals, detail); the parent hands the
// reports to options.progress as they come, and adds a heartbeat in the
// root-LP phase when the child has been silent for options.progress_interval_s.
// Several LPs run at once as several children, all forked from the calling
// thread (never fork from two threads at once: see lp_child.cc).
#ifndef THRUSTSCHED_MILP_INTERNAL_LP_CHILD_H_
#define THRUSTSCHED_MILP_INTERNAL_LP_CHILD_H_

#include <string>
#include <vector>

#include "milp/internal/clp_lp.h"

namespace thrustsched::milp::internal {

struct LpChildOutcome {
  LpOutcome outcome;  // valid unless died
  bool died = false;  // the child ended without an outcome (signal or exit)
  std::string why;    // e.g. "killed by signal 6 (Aborted)"
};

struct LpCoreJob {
  const LpData* lp = nullptr;
  const CoinArrays* arrays = nullptr;
};

/// One child per job, all running at once; outcome i belongs to jobs[i].
/// The clock's stop ends them all (status kNoSolutionFound).
std::vector<LpChildOutcome> SolveLpCoresInChildren(const std::vector<LpCoreJob>& jobs,
                                                   const SolveOptions& options, SolveClock* clock);

LpChildOutcome SolveLpCoreInChild(const LpData& lp, const CoinArrays& arrays,
                                  const SolveOptions& options, SolveClock* clock);

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_LP_CHILD_H_
