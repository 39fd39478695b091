// The search's plan: its phases in order, each with the condition under
// which it runs, written as the principle it is. RunPlan is the only loop.
//
//   SearchState state(milp, solver, options, search, &report);
//   RunPlan(SearchPlanByName(search.plan), state);   // or a plan of one's own
//   milp::SolveResult r = state.Result();
//
// Contract: RunPlan runs the steps in order, skips a step whose phase is
// disabled (SearchOptions::disabled_phases) or whose condition is false,
// and stops before any step but the first once the gap is closed or the
// time limit or an interrupt is reached. Deterministic: no condition reads
// the clock.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_PLAN_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_PLAN_H_

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "transcription/search/phase.h"
#include "transcription/search/search_state.h"

namespace thrustsched::transcription {

struct PlanStep {
  std::shared_ptr<SearchPhase> phase;
  std::string when_text;  // the condition in words ("an incumbent one step above the bound")
  std::function<bool(const SearchState&)> when;
};

using SearchPlan = std::vector<PlanStep>;

/// "default": the tree first where the first incumbent is one step above
/// the bound (the question left is then whether a schedule at the bound
/// exists, which the tree answers by proof). "exact_first": the exact MILP
/// and the first improvement net before the tree, whatever the gap.
SearchPlan DefaultSearchPlan();
SearchPlan ExactFirstSearchPlan();
/// One of SearchPlanNames(); @throws std::invalid_argument otherwise.
SearchPlan SearchPlanByName(const std::string& name);

void RunPlan(const SearchPlan& plan, SearchState& state);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_PLAN_H_
