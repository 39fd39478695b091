// A lower bound for an on-off schedule MILP from branching on each
// thruster's number of on slots.
//
//   TotalBranching t = BranchOnThrusterTotals(milp, solver, lp_options, root.x,
//                                             root_bound, incumbent, /*max_lps=*/8);
//   // t.bound: every schedule costs at least this (rounded to the objective
//   // step); t.bound >= incumbent proves the incumbent optimal
//
// Why: when every slot costs one objective step (ScheduleMilp::objective_step),
// a schedule costs a whole number of steps, and the LP relaxation of a GEO
// week reaches its bound with thrusters fired for a fractional number of
// slots. The total S_i = sum_j on[i][j] of each thruster is an integer in
// every schedule, so S_i <= floor(y_i) or S_i >= ceil(y_i) for the
// relaxation's y_i: two LPs, each the relaxation with that total bounded,
// each usually needing a costlier mix of thrusters; CBC's branching on
// single slots does not move this bound (aggregated branching, as on the
// number of vehicles in routing). The summed total of thrusters that stand
// in for each other (TotalGroups: +N and -N) is an integer too, and is
// split before its members: the LP trades a fractional slot between them at
// no cost, so a bound on one alone moves the other.
//
// Windows: where the incumbent is one step above the lowest leaf and every
// total is whole, the tree goes on with the number of slots each fired
// thruster is on in each half, quarter, ... of the horizon (WindowGroups),
// an integer in every schedule too: whether a leaf's few whole slots can
// fall where its LP spreads them.
//
// The tree is searched best first: the open leaf with the lowest bound is
// split on its most fractional total. With `warm`, its two children's LPs
// are dual simplex solves in one LP session (milp::LpSession;
// WithGroupTotalColumns: a leaf only changes the bounds of one column per
// group), each from its parent's basis; the root's basis comes from the
// crossover from the relaxation's interior point when the caller gives its
// duals, or else from CLP's interior point with its crossover. Without
// `warm`, each leaf LP from scratch by lp_options' algorithm
// (WithGroupTotals), the two of a split side by side when
// lp_options.threads >= 2 (milp::Solver::SolveLpRelaxations).
// Each leaf's bound is the safe dual bound of its LP (milp/lp_bound.h,
// valid whatever the LP's accuracy), rounded up to the step and at least
// its parent's. The LP's bounds on the totals are elastic (a penalty per
// slot outside them: 100 times the objective's scale, once it in the warm
// tree), so an infeasible leaf is cut off by a high bound rather than by an
// LP that CLP takes minutes to call infeasible. The leaves cover every
// schedule, so the lowest leaf bound is a bound of the MILP. Stops when
// that bound reaches the incumbent (proof) or is within lp_options' gap of
// it, after max_lps LPs (on the totals; window splits have
// TreeOptions::max_window_lps more), on the time limit or interrupt of
// lp_options (the bound of what was solved stays valid), or when the lowest
// leaf has integral totals (and windows, where split). Deterministic for
// the same input (no wall-clock decision) unless a time limit or an
// interrupt cuts it. Measurements: docs/search.md.
#ifndef THRUSTSCHED_TRANSCRIPTION_TOTAL_BRANCHING_H_
#define THRUSTSCHED_TRANSCRIPTION_TOTAL_BRANCHING_H_

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "milp/lp_bound.h"
#include "milp/solver.h"
#include "transcription/schedule_milp.h"

namespace thrustsched::transcription {

/// Thrusters whose number of on slots the tree bounds together (their sum
/// is an integer in every schedule too), over the whole horizon or over a
/// window of its slots.
struct ThrusterGroup {
  std::vector<int> thrusters;  // indices in the ThrusterSet
  std::string name;            // "+N and -N", the thruster's name, "+T in slots 0-1007"
  /// The window: slots [first_interval, end_interval); end_interval < 0 is
  /// the horizon's end.
  int first_interval = 0;
  int end_interval = -1;
  /// 0 for the whole horizon; a window of level l is one of the 2^l equal
  /// parts of the horizon (WindowGroups). The tree splits a level only once
  /// every total of the levels above is whole.
  int level = 0;

  int End(int num_intervals) const { return end_interval < 0 ? num_intervals : end_interval; }
  /// The most slots the group can be on: its total lies in [0, this].
  int MaxTotal(int num_intervals) const {
    return (End(num_intervals) - first_interval) * static_cast<int>(thrusters.size());
  }
};

/// Thrusters on one axis (directions parallel or opposite), in order of
/// their first thruster: the ideal six's "+R and -R", "+T and -T", "+N and
/// -N"; each of the thesis' four Anzel thrusters alone.
std::vector<ThrusterGroup> ThrusterAxes(const dynamics::ThrusterSet& thrusters);

/// The groups the tree splits on: each set of two or more thrusters on one
/// axis (directions parallel or opposite) that stand in for each other, then
/// each thruster alone. Two thrusters stand in for each other when for every
/// slot of one some slot of the other moves the final state the same way
/// (Phi(t_N, t_j+1) Gamma_j, scaled; cosine within 1e-3 of 1): +N and -N
/// of the ideal six (the out-of-plane motion is an oscillator, -N half an
/// orbit later does what +N does), not +T and -T (opposite drifts) nor +R
/// and -R (opposite along-track offsets). The thesis' four Anzel thrusters
/// share no axis: one group per thruster. Without `axis_groups`, single
/// thrusters only.
std::vector<ThrusterGroup> TotalGroups(const ScheduleMilp& milp, bool axis_groups = true);

/// The group the tree splits a leaf on, given each group's total y[g] at
/// the leaf's LP point; -1 if none is fractional. Whole-horizon groups
/// (level 0): the one whose total is nearest to half a slot from an
/// integer, a thruster of an axis group only once that group's total is
/// whole. With `windows`, the windows (level >= 1) instead: those of the
/// thruster with the fewest slots among the thrusters with a fractional
/// window, the coarsest level with a fractional total, nearest to half a
/// slot there. A thruster's few whole slots are the hardest to place.
int SplitGroup(const std::vector<ThrusterGroup>& groups, const std::vector<double>& y,
               bool windows);

/// Windows of each thruster the point x fires (its total above a thousandth
/// of a slot): for each level l = 1..levels, the horizon cut into 2^l equal
/// windows (the last ones a slot longer when it does not divide). Why: a
/// week that needs a few slots of one thruster has an LP that spreads them
/// thin over the days; once the thruster's total is whole (k slots), the
/// leaf's LP bound is k slots exactly, and whether k whole slots keep the
/// satellite in its window is a question of where they fall. Bounding the
/// number of slots in each half, quarter, ... of the week asks it by
/// bisection, each window's total an integer in every schedule.
std::vector<ThrusterGroup> WindowGroups(const OperationalEncoding& enc,
                                        const dynamics::ThrusterSet& thrusters,
                                        const Eigen::VectorXd& x, int levels);

/// Each group's number of on slots at x (a column vector of milp.lp(),
/// fractional at a relaxation's point), over its window.
std::vector<double> GroupTotalsAt(const std::vector<ThrusterGroup>& groups,
                                  const OperationalEncoding& enc, const Eigen::VectorXd& x);

/// A leaf of the tree whose bound is below the incumbent when it stopped.
struct OpenLeaf {
  std::vector<double> lower, upper;  // per group (TotalBranching::groups): bounds on its total
  double bound = -milp::kInfinity;   // its LP's safe bound, rounded to the step
  /// Slots (thrusters x intervals, 1 = free) that can be on in a schedule of
  /// this leaf better than the incumbent by a step: reduced-cost fixing
  /// (milp::FixByReducedCost) with the duals of the leaf's LP, valid for the
  /// leaf as the root's is for the MILP. The MILP with the leaf's totals,
  /// restricted to these slots, is exact for the leaf. Empty when its LP gave
  /// no point (or there is no incumbent).
  Eigen::MatrixXi free_slots;
  /// Its LP point; empty when it has none within its totals.
  Eigen::VectorXd x;
};

struct TotalBranching {
  double bound = -milp::kInfinity;  // in the MILP's objective, rounded to the step
  int lps = 0;                      // LPs solved
  int open_leaves = 0;              // leaves below the incumbent when it stopped
  std::string detail;               // one line: what it did and why it stopped
  /// LP point of the lowest leaf below the incumbent (where a better
  /// schedule would be); empty when none has one or the root is that leaf.
  Eigen::VectorXd lowest_leaf_x;
  /// The groups split on (TotalGroups), and the lowest leaf's bounds on each
  /// group's number of on slots (empty with lowest_leaf_x).
  std::vector<ThrusterGroup> groups;
  std::vector<double> lowest_leaf_lower, lowest_leaf_upper;
  /// Every leaf below the incumbent, lowest bound first (ties: creation
  /// order); the tree's bound is the first one's. Empty when the root is the
  /// only leaf.
  std::vector<OpenLeaf> open;
};

/// The tree's shape.
struct TreeOptions {
  /// As in TotalGroups.
  bool axis_groups = true;
  /// Off: the leaves' bounds on the totals are hard (an infeasible leaf LP
  /// then takes CLP minutes).
  bool elastic = true;
  /// Off: each leaf's LP from scratch by lp_options' algorithm, two side by
  /// side, instead of one LP session whose root basis comes from the
  /// interior point and its crossover and whose leaves are dual simplex
  /// solves from their parent's basis.
  bool warm = true;
  /// Warm tree: each leaf's dual simplex stops after as many pivots as the
  /// root's basis took (at least 1000), the leaf keeping its parent's bound
  /// (where windows may be split, the lowest such leaf is solved again
  /// without the limit, once, rather than end the tree).
  /// Off: no limit.
  bool leaf_pivot_limit = true;
  /// Levels of windows (WindowGroups) the tree splits once every thruster's
  /// total is whole, where the incumbent is one objective step above the
  /// lowest leaf's bound, those of the thruster with the fewest slots first
  /// (SplitGroup); 0: whole-horizon totals only.
  int window_levels = 5;
  /// LPs of window splits, on top of the call's max_lps for the totals.
  int max_window_lps = 1000;
};

/// As above. `root_x` and `root_bound` are the relaxation's point and its
/// (safe, rounded) bound; `incumbent` the best known schedule's objective
/// (+inf if none); `lp_options` the LP options (algorithm, threads, time
/// limit from the call, interrupt). On-off mode only; without an objective
/// step (<= 0) the bound is not rounded. `root_duals` (warm tree; optional):
/// the relaxation's row duals at root_x (an interior point without
/// crossover, say). The tree's root basis then comes from the crossover
/// from that point (milp::LpSession::CrossOverFrom, each group's total at
/// root_x), not from a second interior point with its crossover.
TotalBranching BranchOnThrusterTotals(const ScheduleMilp& milp, const milp::Solver& solver,
                                      const milp::SolveOptions& lp_options,
                                      const Eigen::VectorXd& root_x, double root_bound,
                                      double incumbent, double step, int max_lps,
                                      const TreeOptions& tree = {},
                                      const Eigen::VectorXd& root_duals = Eigen::VectorXd());

/// Whether every schedule better than `incumbent` costs exactly `bound`:
/// the incumbent at most one objective step above it (and a step known).
/// Where the tree splits windows, and where the search runs them (the phase
/// "windows", docs/search.md).
inline bool OneStepAbove(double incumbent, double bound, double step) {
  return std::isfinite(incumbent) && step > 0.0 && incumbent - bound <= step * (1.0 + 1e-6);
}

/// Totals closer than this to an integer are not branched on (the interior
/// point stops short of exact vertices) and count as whole.
inline constexpr double kIntegralTotal = 1e-3;

/// Whether bounds [lower, upper] on a group's total cut anything: a total
/// lies in [0, group.MaxTotal(num_intervals)] anyway.
inline bool TotalIsBounded(double lower, double upper, const ThrusterGroup& group,
                           int num_intervals) {
  return lower > 0.0 || upper < group.MaxTotal(num_intervals);
}

/// Each thruster's number of on slots at x, a column vector of milp.lp()
/// (fractional at a relaxation's point).
std::vector<double> ThrusterTotals(const OperationalEncoding& enc, const Eigen::VectorXd& x);

/// The slots (thrusters x intervals, 1 = free) that can be on in a schedule
/// better than `incumbent` by `step`: milp::FixByReducedCost with `bound`, the
/// safe dual bound of `lp` (the MILP's relaxation, or a leaf's LP: its first
/// columns are the MILP's, in order).
Eigen::MatrixXi SlotsFreeByReducedCost(const OperationalEncoding& enc, const milp::LpData& lp,
                                       const milp::DualBound& bound, double incumbent, double step);

/// The LP of a leaf: the relaxation of `milp` (its columns first, in order)
/// with thruster i's number of on slots within [lower[i], upper[i]] (one
/// entry per thruster; [0, intervals] leaves it free). The total is the last
/// of the partial sums p_j = p_{j-1} + on[i][j], new columns and rows: the
/// same polytope as one row over all the thruster's slots, but CLP's interior
/// point does not converge with that dense row where it does with the
/// partial sums.
milp::LpData WithThrusterTotals(const ScheduleMilp& milp, const std::vector<double>& lower,
                                const std::vector<double>& upper);

/// The same with the bounds on groups' totals: group g's summed number of on
/// slots within [lower[g], upper[g]] ([0, intervals x its thrusters] leaves
/// it free). With `elastic_cost_per_slot` > 0 the bounds are elastic: two
/// more columns per bounded group, the slots short of lower[g] and over
/// upper[g], each costing that much in the objective. A relaxation of the
/// bounded LP (equal to it where the penalty exceeds the bound rows' duals)
/// that is never infeasible.
milp::LpData WithGroupTotals(const ScheduleMilp& milp, const std::vector<ThrusterGroup>& groups,
                             const std::vector<double>& lower, const std::vector<double>& upper,
                             double elastic_cost_per_slot = 0.0);

/// The LP of the warm tree: every group's total present, its bounds on one
/// column per group (`bound_column[g]`, free at [0, the group's MaxTotal]),
/// so that a leaf is a change of column bounds (milp::LpSession). Elastic as
/// above when `elastic_cost_per_slot` > 0: total + short - over equals that
/// column; otherwise the column is the total itself.
struct GroupTotalsLp {
  milp::LpData lp;
  std::vector<int> bound_column;
  std::vector<int> elastic_column;  // the short and over slots' columns (elastic only)
};
GroupTotalsLp WithGroupTotalColumns(const ScheduleMilp& milp,
                                    const std::vector<ThrusterGroup>& groups,
                                    double elastic_cost_per_slot = 0.0);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_TOTAL_BRANCHING_H_
