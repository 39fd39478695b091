#include "transcription/search/whole_milp_phase.h"

#include <cmath>
#include <string>

#include "common/format.h"
#include "transcription/search/restricted_milp.h"
#include "transcription/search/search_report.h"

namespace thrustsched::transcription {

namespace {

class WholeMilpPhase : public SearchPhase {
 public:
  std::string name() const override { return "whole_milp"; }
  PhaseYield yields() const override { return PhaseYield::kBoth; }

  void Run(SearchState& state) override {
    milp::SolveOptions o = state.SubOptions(true);
    const ScheduleMilp& milp = state.milp();
    o.complete_solution = [&milp](Eigen::VectorXd* x) { return milp.CompleteFromPattern(x); };
    const double t0 = state.Elapsed();
    const milp::SolveResult s = state.solver().Solve(state.lp(), o);
    state.AddNodes(s.nodes);
    if (state.report() != nullptr) state.report()->whole_milp = true;
    if ((s.status == milp::SolveStatus::kInfeasible || s.status == milp::SolveStatus::kError) &&
        !state.has_incumbent()) {
      state.SetFailed(s.status);
    }
    const std::string solver(state.solver().name());
    if (s.has_solution()) {
      state.Offer(s.x, solver + " on the whole MILP");
      if (std::isfinite(s.best_bound)) state.RaiseBound(s.best_bound);
    }
    state.SetSolverDetail(s.detail);
    state.Step("whole MILP (" + solver + "): " + StatusText(s) + " in " +
               common::FormatG(state.Elapsed() - t0, 3) + " s");
  }
};

}  // namespace

std::shared_ptr<SearchPhase> MakeWholeMilpPhase() { return std::make_shared<WholeMilpPhase>(); }

}  // namespace thrustsched::transcription
