// The phase "tree": branching on each thruster's number of on slots
// (transcription/total_branching.h) for a better bound, then the open
// leaves' MILPs (leaf_milps.h).
//
//   plan.push_back({MakeTreePhase(), "an incumbent one step above the bound", ...});
//
// Why: every schedule fires each thruster a whole number of slots, and the
// relaxation's bound rests on fractional totals; splitting them (the summed
// total of thrusters that stand in for each other first) raises the bound
// where CBC's branching on single slots does not. Where the tree leaves the
// incumbent one step above the bound, the phase "windows" comes between the
// tree and its leaves' MILPs (after a cheap MILP over the lowest leaf's LP
// slots): at one step the windows prove the incumbent optimal or change
// nothing, and the leaves' MILPs still look for schedules at the bound.
// Contract: yields bounds (the tree's leaves) and incumbents (the leaves'
// MILPs).
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_TREE_PHASE_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_TREE_PHASE_H_

#include <memory>

#include "transcription/search/phase.h"
#include "transcription/total_branching.h"

namespace thrustsched::transcription {

std::shared_ptr<SearchPhase> MakeTreePhase();

/// The tree with `window_levels` levels of windows, its bound raised into
/// the state and logged; false when no tree applies (tree.max_lps < 2 or
/// no relaxation).
bool SolveTree(SearchState& state, int window_levels, TotalBranching* t);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_TREE_PHASE_H_
