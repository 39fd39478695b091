#include "transcription/search/tree_phase.h"

#include <string>

#include "common/format.h"
#include "transcription/search/leaf_milps.h"
#include "transcription/search/windows_phase.h"

namespace thrustsched::transcription {

bool SolveTree(SearchState& state, int window_levels, TotalBranching* t) {
  const TreePhaseOptions& options = state.search().tree;
  if (options.max_lps < 2 || !state.has_relaxation()) return false;
  state.set_tree_ran();
  milp::SolveOptions o = state.SubOptions(true);
  o.lp_algorithm = milp::LpAlgorithm::kBarrierNoCrossover;
  const double t0 = state.Elapsed();
  TreeOptions shape = options.shape;
  shape.window_levels = window_levels;
  *t = BranchOnThrusterTotals(
      state.milp(), state.solver(), o, state.relaxation().x, state.bound(), state.objective(),
      state.step(), options.max_lps, shape,
      options.root_from_relaxation ? state.relaxation().row_duals : Eigen::VectorXd());
  state.RaiseBound(t->bound);
  state.Step((window_levels > 0 ? "the tree again, with windows: " : "") + t->detail + " (" +
             common::FormatG(state.Elapsed() - t0, 3) + " s)");
  state.Report(milp::SolvePhase::kSearch, false);
  return true;
}

namespace {

class TreePhase : public SearchPhase {
 public:
  std::string name() const override { return "tree"; }
  PhaseYield yields() const override { return PhaseYield::kBoth; }

  void Run(SearchState& state) override {
    TotalBranching t;
    if (!SolveTree(state, 0, &t)) return;
    bool candidates_tried = false;
    if (WindowsApply(state) && !state.Done() && !state.Stopped() && state.OneStepAboveBound()) {
      candidates_tried = t.lowest_leaf_x.size() > 0;
      if (candidates_tried) LeafCandidates(state, t);
      if (!state.Done() && !state.Stopped() && state.OneStepAboveBound()) {
        RunWindows(state, /*with_leaves=*/false);
      }
    }
    CloseOrSearchLeaves(state, t, candidates_tried);
  }
};

}  // namespace

std::shared_ptr<SearchPhase> MakeTreePhase() { return std::make_shared<TreePhase>(); }

}  // namespace thrustsched::transcription
