// The MILP that `thrustsched export` (and `solve --export-mps/--export-lp`,
// Python's ts.export) writes for other solvers: ScheduleMilp::lp() with every
// state column of the sparse formulation boxed by the range the dynamics and
// the input bounds imply, widened by half its width so that the bounds never
// bind (milp/chain_bounds.h).
//
//   const transcription::ScheduleMilp milp(problem, options);
//   milp::WriteMpsFile("week.mps", transcription::ExportLp(milp));
//
// Contract: the same columns, names, rows, objective and feasible set (LP
// relaxation and MILP) as milp.lp(); only the bounds of the state columns,
// free in milp.lp(), are finite where the inputs are bounded (on-off
// binaries in [0, 1], impulses in [0, max]). A solution of the exported
// model is therefore one of milp.lp(), column for column, and
// `import-solution` maps it back by name onto milp.lp() unchanged.
// The condensed formulation has no state columns: its lp() is returned as is.
//
// Why: free state columns chained by equality rows make a solver's bound
// propagation blow up (GLPK 5.0's node preprocessing derives bounds beyond
// 1e20, then declares feasible models infeasible; data/scenarios/README.md,
// section 7); thrustsched's own solve does not need the bounds and is left
// as it is.
#ifndef THRUSTSCHED_TRANSCRIPTION_EXPORT_LP_H_
#define THRUSTSCHED_TRANSCRIPTION_EXPORT_LP_H_

#include "milp/lp_data.h"
#include "transcription/schedule_milp.h"

namespace thrustsched::transcription {

milp::LpData ExportLp(const ScheduleMilp& milp);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_EXPORT_LP_H_
