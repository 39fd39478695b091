#include "transcription/search/exact_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/format.h"
#include "transcription/search/restricted_milp.h"
#include "transcription/search/search_report.h"
#include "transcription/total_branching.h"

namespace thrustsched::transcription {

namespace {

using common::FormatG;

// Before a tree has run, the exact MILP gets a share of the time left: the
// tree often proves what it cannot.
milp::SolveOptions ExactOptionsFor(const SearchState& state) {
  milp::SolveOptions o = state.RestrictedOptions();
  const SearchOptions& search = state.search();
  const bool tree_to_come =
      !state.tree_ran() && search.tree.max_lps >= 2 && search.PhaseEnabled("tree");
  if (tree_to_come && std::isfinite(o.time_limit_s))
    o.time_limit_s *= search.exact.time_share_before_tree;
  return o;
}

// One round. Returns false when it cannot help (too many free slots) or
// proved or settled the incumbent.
bool ExactRestricted(SearchState& state) {
  if (!state.dual().finite()) return false;
  const Eigen::MatrixXi mask = SlotsFreeByReducedCost(
      state.milp().encoding(), state.lp(), state.dual(), state.objective(), state.step());
  const int slots = CountSlots(mask);
  if (state.report() != nullptr) state.report()->exact_slots = slots;
  const int max_slots = state.search().exact.max_slots;
  if (slots > max_slots) {
    state.Step(std::to_string(slots) + " slots can still improve on the incumbent (more than " +
               std::to_string(max_slots) + "): the whole MILP instead");
    return false;
  }
  if (!TimeToBuild(state, mask)) return false;
  const double before = state.objective();
  const RestrictedSolve rs =
      SolveOver(state, mask, {state.Cutoff(), {}}, [&] { return ExactOptionsFor(state); });
  const milp::SolveResult& s = rs.solve;
  const std::string what =
      "exact MILP over the " + std::to_string(slots) + " slots reduced-cost fixing leaves free";
  if (!rs.restriction.feasible || s.status == milp::SolveStatus::kInfeasible) {
    // No schedule better than the incumbent: it is optimal.
    state.RaiseBoundTo(state.objective());
    state.Step(what + ": no better schedule (" + FormatG(rs.seconds, 3) +
               " s): the incumbent is optimal");
    return true;
  }
  if (s.has_solution()) {
    state.Offer(Lift(state, rs.restriction, s.x), "the exact restricted MILP");
  }
  // Every better schedule lies in the restriction: the bound is the
  // smaller of the old incumbent and the restricted solve's bound.
  const double restricted_bound = s.has_solution() || std::isfinite(s.best_bound)
                                      ? s.best_bound
                                      : -std::numeric_limits<double>::infinity();
  if (s.status == milp::SolveStatus::kOptimal) {
    state.RaiseBoundTo(std::min(before, state.objective()));
  } else if (std::isfinite(restricted_bound)) {
    state.RaiseBoundTo(std::min(before, restricted_bound));
  }
  state.Step(what + ": " + StatusText(s) + " in " + FormatG(rs.seconds, 3) + " s, bound " +
             FormatG(state.bound(), 8) + state.lazy_note());
  return s.status != milp::SolveStatus::kOptimal && state.objective() < before;
}

class ExactPhase : public SearchPhase {
 public:
  std::string name() const override { return "exact"; }
  PhaseYield yields() const override { return PhaseYield::kBoth; }
  void Run(SearchState& state) override { ExactRounds(state); }
};

}  // namespace

void ExactRounds(SearchState& state) {
  for (int round = 0; round < 3 && !state.Done() && !state.Stopped() && state.has_incumbent();
       ++round) {
    if (!ExactRestricted(state)) break;
  }
}

std::shared_ptr<SearchPhase> MakeExactPhase() { return std::make_shared<ExactPhase>(); }

}  // namespace thrustsched::transcription
