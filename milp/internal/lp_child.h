// CLP's interior point in a child process (internal to the CBC backend).
//
//   LpChildOutcome c = SolveLpCoreInChild(lp, arrays, options, &clock);
//   if (c.died) { /* c.why names the signal; solve with the simplex instead */ }
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
#ifndef THRUSTSCHED_MILP_INTERNAL_LP_CHILD_H_
#define THRUSTSCHED_MILP_INTERNAL_LP_CHILD_H_

#include <string>

#include "milp/internal/clp_lp.h"

namespace thrustsched::milp::internal {

struct LpChildOutcome {
  LpOutcome outcome;  // valid unless died
  bool died = false;  // the child ended without an outcome (signal or exit)
  std::string why;    // e.g. "killed by signal 6 (Aborted)"
};

LpChildOutcome SolveLpCoreInChild(const LpData& lp, const CoinArrays& arrays,
                                  const SolveOptions& options, SolveClock* clock);

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_LP_CHILD_H_
