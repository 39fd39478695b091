// The phase "windows": the tree again (tree_phase.h), on to the number of
// slots of each fired thruster in each half, quarter, ... of the horizon
// once every total is whole, the thruster with the fewest slots first
// (TreeOptions::window_levels).
//
//   plan.push_back({MakeWindowsPhase(), "an incumbent one step above the bound", ...});
//
// Why: at one step above the bound the question is whether a leaf's whole
// slots can fall where its LP spreads them; each window's total is an
// integer in every schedule too. Contract: a proof only: at one step it
// proves the incumbent optimal or changes nothing; the phase then runs the
// new tree's leaves' MILPs. Runs at most once per incumbent.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_WINDOWS_PHASE_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_WINDOWS_PHASE_H_

#include <memory>

#include "transcription/search/phase.h"

namespace thrustsched::transcription {

std::shared_ptr<SearchPhase> MakeWindowsPhase();

/// Whether the windows may run: the phase is enabled and has levels.
bool WindowsApply(const SearchState& state);

/// The windowed tree (once per incumbent), and with `with_leaves` its
/// leaves' MILPs; for the phase "tree", which runs it between its own tree
/// and leaves.
void RunWindows(SearchState& state, bool with_leaves);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_WINDOWS_PHASE_H_
