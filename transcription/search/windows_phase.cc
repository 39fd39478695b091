#include "transcription/search/windows_phase.h"

#include <string>

#include "transcription/search/leaf_milps.h"
#include "transcription/search/tree_phase.h"

namespace thrustsched::transcription {

bool WindowsApply(const SearchState& state) {
  return state.search().PhaseEnabled("windows") && state.search().tree.window_levels > 0;
}

void RunWindows(SearchState& state, bool with_leaves) {
  if (!WindowsApply(state) || !(state.objective() < state.windows_at())) return;
  state.set_windows_at(state.objective());
  TotalBranching t;
  if (SolveTree(state, state.search().tree.window_levels, &t) && with_leaves)
    CloseOrSearchLeaves(state, t, false);
}

namespace {

class WindowsPhase : public SearchPhase {
 public:
  std::string name() const override { return "windows"; }
  PhaseYield yields() const override { return PhaseYield::kBoth; }
  void Run(SearchState& state) override { RunWindows(state, /*with_leaves=*/true); }
};

}  // namespace

std::shared_ptr<SearchPhase> MakeWindowsPhase() { return std::make_shared<WindowsPhase>(); }

}  // namespace thrustsched::transcription
