// The one path by which the search solves a MILP restricted to a set of
// free slots: the mask, the condensed restriction, its extra rows (the
// cutoff, a leaf's totals), row generation over its dense rows, the lift
// of its solution back to the full MILP.
//
//   if (!TimeToBuild(state, mask)) return;
//   RestrictedSolve rs = SolveOver(state, mask, {state.Cutoff(), {}},
//                                  [&] { return state.HeuristicOptions(share); });
//   if (rs.solve.has_solution()) state.Offer(Lift(state, rs.restriction, rs.solve.x), "...");
//
// Contract: a restricted solve's verdict holds for the restriction only;
// its schedule counts once Offer has verified it in the full MILP, and a
// bound from it holds for the MILP only where the caller proves that every
// better schedule lies in the restriction (reduced-cost fixing).
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_RESTRICTED_MILP_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_RESTRICTED_MILP_H_

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "milp/solver.h"
#include "transcription/schedule_milp.h"
#include "transcription/search/search_state.h"
#include "transcription/total_branching.h"

namespace thrustsched::transcription {

/// The schedule MILP restricted to a set of free slots, condensed over them.
struct Restriction {
  ScheduleMilp milp;
  milp::LpData small;     // without its fixed columns
  std::vector<int> kept;  // column of `milp` of each column of `small`
  bool feasible = true;   // false: the fixed slots alone break a row
};

/// Rows added to a restriction before its solve: an objective cutoff
/// (+inf: none) and rows built on its model (a leaf's totals, say).
struct RestrictionRows {
  double cutoff = std::numeric_limits<double>::infinity();
  std::function<std::vector<milp::SparseRow>(const Restriction&)> extra;
};

struct RestrictedSolve {
  Restriction restriction;
  milp::SolveResult solve;  // default (no solution) when the restriction is infeasible
  double seconds = 0.0;     // building and solving
};

int CountSlots(const Eigen::MatrixXi& mask);

/// Whether a restriction over `mask` would be condensed before the time
/// limit (estimated from the largest built so far); logs why not.
bool TimeToBuild(SearchState& state, const Eigen::MatrixXi& mask);

/// Builds the restriction over `mask`, adds `rows`, solves it (not when
/// infeasible by its fixed slots) with the options `options()` gives once
/// it is built (the time left then), counts its nodes.
RestrictedSolve SolveOver(SearchState& state, const Eigen::MatrixXi& mask,
                          const RestrictionRows& rows,
                          const std::function<milp::SolveOptions()>& options);

/// The full MILP's point of a restricted solution (its on-off pattern).
Eigen::VectorXd Lift(const SearchState& state, const Restriction& r,
                     const Eigen::VectorXd& small_x);

/// A sub-solve's status for the step log; an error with its reason.
std::string StatusText(const milp::SolveResult& s);

/// Rows lower[g] <= (group g's number of on slots) <= upper[g] on a
/// restriction's model, for the groups whose total is bounded.
std::vector<milp::SparseRow> TotalRows(const Restriction& r,
                                       const std::vector<ThrusterGroup>& groups,
                                       const std::vector<double>& lower,
                                       const std::vector<double>& upper);

/// An incumbent-only restricted MILP: over `mask`, with the cutoff one step
/// below the incumbent and `extra` rows, within `time_share` of the time
/// left; logs "<what><slots> slots: <status>" and offers its schedule as
/// `source`. False if it was not solved (no time to build it, or infeasible
/// by its fixed slots).
bool ImproveWithin(
    SearchState& state, const Eigen::MatrixXi& mask, const std::string& what,
    const std::string& source, double time_share,
    const std::function<std::vector<milp::SparseRow>(const Restriction&)>& extra = {});

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_RESTRICTED_MILP_H_
