#include "transcription/search/plan.h"

#include <stdexcept>
#include <string>

#include "transcription/search/exact_phase.h"
#include "transcription/search/exchange_phase.h"
#include "transcription/search/improvement_phase.h"
#include "transcription/search/nets_phase.h"
#include "transcription/search/relaxation_phase.h"
#include "transcription/search/tree_phase.h"
#include "transcription/search/whole_milp_phase.h"
#include "transcription/search/windows_phase.h"

namespace thrustsched::transcription {

namespace {

bool Always(const SearchState&) { return true; }
bool HasRelaxation(const SearchState& s) { return s.has_relaxation(); }
bool HasIncumbent(const SearchState& s) { return s.has_relaxation() && s.has_incumbent(); }
bool AtOneStep(const SearchState& s) { return s.has_relaxation() && s.OneStepAboveBound(); }
bool NoTreeYet(const SearchState& s) { return HasIncumbent(s) && !s.tree_ran(); }
bool Improved(const SearchState& s) { return HasIncumbent(s) && s.ImprovedBy("improvement"); }
bool NotInfeasible(const SearchState& s) { return !s.proven_infeasible(); }

// The steps after the first incumbent's, common to both plans. The first
// improvement net is cheap and often finds the optimum; the tree is the
// proof; the exchange and the wider nets cost more and come after it.
void AppendAfterFirstIncumbent(SearchPlan* plan) {
  const auto exact = MakeExactPhase();
  plan->push_back({exact, "an incumbent", HasIncumbent});
  plan->push_back({MakeImprovementPhase(1), "an incumbent", HasIncumbent});
  plan->push_back({MakeTreePhase(), "an incumbent, no tree yet", NoTreeYet});
  plan->push_back({MakeExchangePhase(), "an incumbent", HasIncumbent});
  plan->push_back({MakeWindowsPhase(), "an incumbent one step above the bound", AtOneStep});
  plan->push_back({MakeImprovementPhase(), "an incumbent", HasIncumbent});
  plan->push_back({exact, "the improvement nets found a better schedule", Improved});
  plan->push_back({MakeWholeMilpPhase(), "not proven infeasible", NotInfeasible});
}

}  // namespace

SearchPlan DefaultSearchPlan() {
  SearchPlan plan = {
      {MakeRelaxationPhase(), "always", Always},
      {MakeNetsPhase(), "a relaxation", HasRelaxation},
      // One step above the bound, the question left is whether a schedule
      // at the bound exists: the tree (with the windows) answers it by proof,
      // cheaper than the exact MILP's search.
      {MakeTreePhase(), "an incumbent one step above the bound", AtOneStep},
  };
  AppendAfterFirstIncumbent(&plan);
  return plan;
}

SearchPlan ExactFirstSearchPlan() {
  SearchPlan plan = {
      {MakeRelaxationPhase(), "always", Always},
      {MakeNetsPhase(), "a relaxation", HasRelaxation},
  };
  AppendAfterFirstIncumbent(&plan);
  return plan;
}

SearchPlan SearchPlanByName(const std::string& name) {
  if (name == "default") return DefaultSearchPlan();
  if (name == "exact_first") return ExactFirstSearchPlan();
  throw std::invalid_argument("search.plan: unknown plan \"" + name + "\"");
}

void RunPlan(const SearchPlan& plan, SearchState& state) {
  for (size_t k = 0; k < plan.size(); ++k) {
    if (k > 0 && (state.Done() || state.Stopped())) break;
    const PlanStep& step = plan[k];
    if (!state.search().PhaseEnabled(step.phase->name()) || !step.when(state)) continue;
    state.BeginPhase(step.phase->name());
    step.phase->Run(state);
  }
  state.BeginPhase("");
}

}  // namespace thrustsched::transcription
