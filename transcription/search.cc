#include "transcription/search.h"

#include <stdexcept>
#include <string>

#include "transcription/search/search_state.h"

namespace thrustsched::transcription {

namespace {

void CheckArguments(const ScheduleMilp& milp, const milp::SolveOptions& options,
                    const SearchOptions& search) {
  std::string error;
  if (milp.problem().input_mode != InputMode::kOnOff) {
    throw std::invalid_argument("SearchSchedule: on-off problems only");
  }
  if (!search.IsValid(&error) || !options.IsValid(&error)) throw std::invalid_argument(error);
  const ObjectiveKind kind = milp.problem().objective.kind;
  if (kind != ObjectiveKind::kL1 && kind != ObjectiveKind::kDeltaV &&
      kind != ObjectiveKind::kPropellant) {
    throw std::invalid_argument("SearchSchedule: unknown objective");
  }
}

}  // namespace

milp::SolveResult SearchScheduleWithPlan(const SearchPlan& plan, const ScheduleMilp& milp,
                                         const milp::Solver& solver,
                                         const milp::SolveOptions& options,
                                         const SearchOptions& search,
                                         const std::vector<Eigen::VectorXd>& starts,
                                         SearchReport* report) {
  CheckArguments(milp, options, search);
  SearchState state(milp, solver, options, search, report);
  for (const Eigen::VectorXd& x : starts) state.Offer(x, "the given start");
  RunPlan(plan, state);
  return state.Result();
}

milp::SolveResult SearchSchedule(const ScheduleMilp& milp, const milp::Solver& solver,
                                 const milp::SolveOptions& options, const SearchOptions& search,
                                 const std::vector<Eigen::VectorXd>& starts, SearchReport* report) {
  CheckArguments(milp, options, search);
  return SearchScheduleWithPlan(SearchPlanByName(search.plan), milp, solver, options, search,
                                starts, report);
}

}  // namespace thrustsched::transcription
