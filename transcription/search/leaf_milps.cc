#include "transcription/search/leaf_milps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/format.h"
#include "transcription/search/restricted_milp.h"
#include "transcription/search/slot_nets.h"

namespace thrustsched::transcription {

namespace {

using common::FormatG;
constexpr double kInf = std::numeric_limits<double>::infinity();

// "+N and -N <= 9, -T >= 2": the leaf's bounds on the totals it bounds.
std::string LeafText(const SearchState& state, const TotalBranching& t, const OpenLeaf& leaf) {
  std::string text;
  const int n = state.milp().encoding().num_intervals;
  for (size_t g = 0; g < t.groups.size(); ++g) {
    if (!TotalIsBounded(leaf.lower[g], leaf.upper[g], t.groups[g], n)) continue;
    std::string range = leaf.lower[g] > 0.0 ? FormatG(leaf.lower[g], 6) + " <= " : "";
    range += t.groups[g].name;
    if (leaf.upper[g] < t.groups[g].MaxTotal(n)) range += " <= " + FormatG(leaf.upper[g], 6);
    text += (text.empty() ? "" : ", ") + range;
  }
  return text;
}

// One leaf's exact MILP; returns a bound for the leaf.
double SolveLeaf(SearchState& state, const TotalBranching& t, const OpenLeaf& leaf) {
  const double before = state.objective();
  const RestrictedSolve rs = SolveOver(
      state, leaf.free_slots,
      {state.Cutoff(),
       [&](const Restriction& r) { return TotalRows(r, t.groups, leaf.lower, leaf.upper); }},
      [&] { return state.RestrictedOptions(); });
  const milp::SolveResult& s = rs.solve;
  const std::string what = "exact MILP of the leaf " + LeafText(state, t, leaf) + " over the " +
                           std::to_string(CountSlots(leaf.free_slots)) +
                           " slots reduced-cost fixing with its LP leaves free: ";
  if (!rs.restriction.feasible || s.status == milp::SolveStatus::kInfeasible) {
    state.Step(what + "no better schedule (" + FormatG(rs.seconds, 3) + " s)" + state.lazy_note());
    return before;
  }
  state.Step(what + StatusText(s) + " in " + FormatG(rs.seconds, 3) + " s" + state.lazy_note());
  if (s.has_solution()) state.Offer(Lift(state, rs.restriction, s.x), "an exact leaf MILP");
  if (s.status == milp::SolveStatus::kOptimal) return std::min(before, s.objective);
  return std::isfinite(s.best_bound) ? std::min(before, s.best_bound) : -kInf;
}

// The open leaves, lowest first, each solved exactly while reduced-cost
// fixing with its LP's duals leaves at most tree.max_exact_leaf_slots slots
// free. A leaf that holds no better schedule is closed at the incumbent;
// the bound is the lowest of the leaves' bounds after their solves (those
// not solved keep their LP's). Stops at the first leaf with too many free
// slots (the bound cannot pass it). True if the lowest leaf was solved.
bool CloseLeaves(SearchState& state, const TotalBranching& t) {
  const int max_slots = state.search().tree.max_exact_leaf_slots;
  double lowest = kInf;
  size_t k = 0;  // leaves solved
  for (; k < t.open.size() && !state.Stopped(); ++k) {
    const OpenLeaf& leaf = t.open[k];
    if (leaf.free_slots.size() == 0) {
      state.Step("the leaf " + LeafText(state, t, leaf) +
                 ": no reduced-cost fixing (its LP gave no point within its totals)");
      break;
    }
    if (CountSlots(leaf.free_slots) > max_slots) {
      state.Step("the leaf " + LeafText(state, t, leaf) + ": " +
                 std::to_string(CountSlots(leaf.free_slots)) +
                 " slots can still improve on the incumbent (more than " +
                 std::to_string(max_slots) + ")");
      break;
    }
    if (!TimeToBuild(state, leaf.free_slots)) break;
    lowest = std::min(lowest, std::max(leaf.bound, SolveLeaf(state, t, leaf)));
    if (state.Done()) {
      ++k;
      break;
    }
  }
  for (size_t rest = k; rest < t.open.size(); ++rest) lowest = std::min(lowest, t.open[rest].bound);
  if (k > 0) state.RaiseBound(lowest);
  return k > 0;
}

// Incumbents only: the MILP with the leaf's bounds on the totals,
// restricted to `mask`, with the cutoff.
void LeafRestricted(SearchState& state, const TotalBranching& t, const Eigen::MatrixXi& mask) {
  ImproveWithin(state, mask, "MILP restricted to the lowest leaf's ",
                "the lowest leaf's restricted MILP", state.search().nets.time_share,
                [&](const Restriction& r) {
                  return TotalRows(r, t.groups, t.lowest_leaf_lower, t.lowest_leaf_upper);
                });
}

Eigen::MatrixXi LeafCandidateSlots(const SearchState& state, const TotalBranching& t) {
  const NetOptions& nets = state.search().nets;
  return CandidateSlots(state, t.lowest_leaf_x, nets.candidate_threshold, nets.neighbourhood,
                        false);
}

// At one step above the bound, a better schedule is one at the bound: it
// lies in a leaf at the bound, not necessarily the lowest one (ties are
// kept in creation order). The MILP of each other leaf at the bound (its
// totals, the cutoff; at most tree.other_leaf_nets), restricted to its LP's
// candidate slots widened once: a leaf's LP point is the relaxation's with
// its totals whole, so its net is the first net that held a schedule.
void OtherLeafNets(SearchState& state, const TotalBranching& t) {
  const TreePhaseOptions& tree = state.search().tree;
  int solved = 0;
  for (const OpenLeaf& leaf : t.open) {
    if (solved >= tree.other_leaf_nets || state.Done() || state.Stopped() ||
        !state.OneStepAboveBound())
      return;
    const double bound = state.bound();
    const bool at_bound = leaf.bound <= bound + 1e-9 * std::max(1.0, std::abs(bound));
    if (leaf.x.size() == 0 || !at_bound ||
        (leaf.lower == t.lowest_leaf_lower && leaf.upper == t.lowest_leaf_upper))
      continue;
    const Eigen::MatrixXi mask = WideningMask(state, leaf.x, 1);
    if (CountSlots(mask) > tree.max_leaf_net_slots) continue;
    ++solved;
    ImproveWithin(
        state, mask, "MILP restricted to the leaf " + LeafText(state, t, leaf) + "'s widened ",
        "another leaf's restricted MILP", state.search().nets.time_share,
        [&](const Restriction& r) { return TotalRows(r, t.groups, leaf.lower, leaf.upper); });
  }
}

// The lowest leaf is where a better schedule would be: the MILP with the
// leaf's bounds on the totals, restricted to every slot of the thrusters
// its LP fires when they are few enough, else to the slots its LP uses;
// with the cutoff. A leaf that fires a few slots of one thruster spread
// thin over the horizon may hold no schedule in the nets around them.
void LeafHeuristic(SearchState& state, const TotalBranching& t, bool candidates_tried) {
  const int max_slots = state.search().tree.max_leaf_net_slots;
  Eigen::MatrixXi mask = FiredThrusterSlots(state, t.lowest_leaf_x);
  if (CountSlots(mask) > max_slots) {
    if (candidates_tried) return;
    mask = LeafCandidateSlots(state, t);
  }
  if (CountSlots(mask) <= max_slots) LeafRestricted(state, t, mask);
  // After LeafCandidates the other leaves' MILPs ran against this same
  // incumbent (one step above the bound; a better one would be at it).
  if (!candidates_tried) OtherLeafNets(state, t);
}

}  // namespace

void LeafCandidates(SearchState& state, const TotalBranching& t) {
  const Eigen::MatrixXi mask = LeafCandidateSlots(state, t);
  if (CountSlots(mask) <= state.search().tree.max_leaf_net_slots) LeafRestricted(state, t, mask);
  OtherLeafNets(state, t);
}

void CloseOrSearchLeaves(SearchState& state, const TotalBranching& t, bool candidates_tried) {
  const bool lowest_solved = !state.Done() && !state.Stopped() && CloseLeaves(state, t);
  if (!state.Done() && !state.Stopped() && t.lowest_leaf_x.size() > 0 && !lowest_solved)
    LeafHeuristic(state, t, candidates_tried);
}

}  // namespace thrustsched::transcription
