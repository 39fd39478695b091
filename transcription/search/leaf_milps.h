// The MILPs of a tree's open leaves (transcription/total_branching.h),
// after the phase "tree" or "windows": exact where reduced-cost fixing with
// a leaf's duals leaves few slots free, else incumbent-only nets.
//
//   TotalBranching t;
//   if (SolveTree(state, 0, &t)) CloseOrSearchLeaves(state, t, false);
//
// Contract: CloseLeaves' exact solves (the MILP with the leaf's totals over
// its free slots, with the cutoff) close a leaf or improve the incumbent;
// the bound rises to the lowest leaf bound after them. The nets (the lowest
// leaf's and, one step above the bound, the other leaves' at the bound)
// yield incumbents only.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_LEAF_MILPS_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_LEAF_MILPS_H_

#include "transcription/search/search_state.h"
#include "transcription/total_branching.h"

namespace thrustsched::transcription {

/// The open leaves' exact MILPs, else the lowest leaf's nets.
/// `candidates_tried`: LeafCandidates ran against this incumbent already.
void CloseOrSearchLeaves(SearchState& state, const TotalBranching& t, bool candidates_tried);

/// The lowest leaf's MILP over its LP's candidate slots, then the other
/// leaves' at the bound: a cheap look for a schedule at the bound.
void LeafCandidates(SearchState& state, const TotalBranching& t);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_LEAF_MILPS_H_
