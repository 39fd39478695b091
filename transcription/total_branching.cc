#include "transcription/total_branching.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "common/format.h"
#include "common/timing.h"
#include "milp/lp_bound.h"

namespace thrustsched::transcription {

using common::FormatG;

namespace {

// A leaf's bounds on the totals are elastic in its LP (WithGroupTotals):
// each slot short or over costs this many times the largest of the root
// bound, the incumbent and the step. So the LP is never infeasible. CLP's
// interior point does not converge on an infeasible LP: it stops at an
// infeasible point (whose safe bound is weak) or fails, and the simplex that
// then classifies the LP took 90-225 s with the `cbc` program and 540-730 s
// in the year loop on a leaf of week 37 of the six-thruster year (+N and -N
// <= 15, +N <= 7, +T <= 0); the same leaf with elastic bounds (10 m/s per
// slot) took 27 s and was bounded at 3.38 m/s, against an incumbent of
// 0.311 m/s. The elastic LP is a relaxation of the leaf's, so its safe bound
// is valid for the leaf whatever the penalty; a leaf whose LP needs a
// hundredth of a slot outside its bounds costs more than the incumbent.
constexpr double kElasticFactor = 100.0;
// The same in the warm tree, whose leaves are dual simplex solves from their
// parent's basis: there the penalty sets the work. On week 52 of
// data/scenarios/hard/ (six thrusters), the leaf +N and -N <= 77 of a root at
// 77.51 (no schedule fires them fewer times) took 3176 pivots (6.8 s) at
// 100 times the incumbent, 80 at 10 times and 9 (0.07 s) at once the
// incumbent, where its 0.49 slots outside cost 0.68 m/s, above the 1.41 m/s
// incumbent with the root's 1.31. A leaf that needs so little outside that
// its bound stays below the incumbent is not split (Take).
constexpr double kWarmElasticFactor = 1.0;

// The warm tree's pivot limit per leaf: as many as the root's basis took,
// and at least this. Week 45 of the six-thruster year (2034-11-05): the
// leaf -T <= 1 of a parent at 1.98 slots (its LP needs 0.29 slots outside
// its totals, bound 1.13 against an incumbent of 0.61) took 10-25 s of
// CLP's dual simplex, which passed the incumbent early but then went back
// and forth with its primal clean-up (the states' fake bounds), where every
// other leaf took under 0.7 s; three such leaves left the minute no time.
constexpr long long kMinLeafPivots = 1000;

long long LeafPivotLimit(long long root_pivots) { return std::max(kMinLeafPivots, root_pivots); }

constexpr const char* kPivotLimit = "pivot limit";  // milp::LpSession's detail

struct Leaf {
  std::vector<double> lower, upper;  // per group: bounds on its total
  double bound = -milp::kInfinity;
  Eigen::VectorXd x;                 // its LP point; empty when it has none (not split)
  int order = 0;                     // creation order, for ties
  std::string note;                  // why it has no point, for the detail
  Eigen::MatrixXi free_slots;        // OpenLeaf::free_slots
  std::vector<unsigned char> basis;  // its LP's final basis (warm tree), its children's start
  bool pivot_limited = false;        // its LP stopped at the leaf pivot limit (basis: its parent's)
};

// The thruster with the fewest slots at y (its level-1 windows' totals
// summed) among those with a fractional window total; -1 if none.
int FewestSlotsWithFractionalWindow(const std::vector<ThrusterGroup>& groups,
                                    const std::vector<double>& y) {
  int fewest = -1;
  double fewest_slots = milp::kInfinity;
  for (size_t g = 0; g < groups.size(); ++g) {
    if (groups[g].level == 0 || std::abs(y[g] - std::round(y[g])) <= kIntegralTotal) continue;
    const int i = groups[g].thrusters[0];
    double slots = 0.0;
    for (size_t h = 0; h < groups.size(); ++h)
      if (groups[h].level == 1 && groups[h].thrusters[0] == i) slots += y[h];
    if (slots < fewest_slots) {
      fewest_slots = slots;
      fewest = i;
    }
  }
  return fewest;
}

}  // namespace

// The aggregate before its members: thrusters that stand in for each other
// (+N at the ascending node, -N at the descending one, both turn the
// inclination vector the same way) trade a fractional slot at almost no
// cost in the LP, so bounding one alone moves the other and leaves the bound
// where it was (week 52 of data/scenarios/hard/: +N at 38.5 slots, then -N
// at 39.51, then -N at 38.51, six LPs and the lowest leaf still at the
// root's bound; +N and -N together at 77.51 slots, both children a step
// higher).
int SplitGroup(const std::vector<ThrusterGroup>& groups, const std::vector<double>& y,
               bool windows) {
  // Per thruster (every thruster has a group of its own, so fewer than
  // groups.size()): in a group of several whose total is fractional.
  std::vector<bool> in_fractional_group(groups.size(), false);
  for (size_t g = 0; g < groups.size(); ++g) {
    if (groups[g].level > 0 || groups[g].thrusters.size() < 2 ||
        std::abs(y[g] - std::round(y[g])) <= kIntegralTotal)
      continue;
    for (int i : groups[g].thrusters) in_fractional_group[static_cast<size_t>(i)] = true;
  }
  int best = -1;
  int best_level = 0;
  double best_distance = 0.5 - kIntegralTotal;
  const int fewest = windows ? FewestSlotsWithFractionalWindow(groups, y) : -1;
  for (size_t g = 0; g < groups.size(); ++g) {
    const std::vector<int>& members = groups[g].thrusters;
    if ((groups[g].level > 0) != windows) continue;
    if (fewest >= 0 && members[0] != fewest) continue;
    if (groups[g].level == 0 && members.size() == 1 &&
        in_fractional_group[static_cast<size_t>(members[0])])
      continue;
    if (best >= 0 && groups[g].level > best_level) continue;  // a coarser level is fractional
    const double distance = std::abs(y[g] - std::floor(y[g]) - 0.5);
    if (distance < best_distance ||
        (best >= 0 && groups[g].level < best_level && distance < 0.5 - kIntegralTotal)) {
      best = static_cast<int>(g);
      best_level = groups[g].level;
      best_distance = distance;
    }
  }
  return best;
}

namespace {

class Tree {
 public:
  Tree(const ScheduleMilp& milp, const milp::Solver& solver, const milp::SolveOptions& options,
       double incumbent, double step, const TreeOptions& tree, double elastic_cost_per_slot,
       const Eigen::VectorXd& root_duals)
      : warm_(tree.warm),
        leaf_pivot_limit_(tree.leaf_pivot_limit),
        root_duals_(root_duals),
        milp_(milp),
        solver_(solver),
        options_(options),
        incumbent_(incumbent),
        step_(step),
        elastic_cost_(elastic_cost_per_slot),
        groups_(TotalGroups(milp, tree.axis_groups)),
        window_levels_(tree.window_levels),
        max_window_lps_(tree.max_window_lps),
        clock_(options.time_limit_s, options.interrupt) {}

  TotalBranching Run(const Eigen::VectorXd& root_x, double root_bound, int max_lps) {
    if (window_levels_ > 0 && root_x.size() == milp_.lp().num_cols()) {
      for (ThrusterGroup& g :
           WindowGroups(milp_.encoding(), milp_.problem().thrusters, root_x, window_levels_))
        groups_.push_back(std::move(g));
    }
    // Every group's total free: [0, intervals x its thrusters].
    std::vector<double> upper;
    for (const ThrusterGroup& g : groups_)
      upper.push_back(g.MaxTotal(milp_.encoding().num_intervals));
    leaves_.push_back({std::vector<double>(groups_.size(), 0.0),
                       std::move(upper),
                       root_bound,
                       root_x,
                       0,
                       {},
                       {},
                       {}});
    const std::string why = Search(max_lps);
    TotalBranching out;
    out.groups = groups_;
    out.lps = lps_;
    const Leaf& lowest = leaves_[static_cast<size_t>(Lowest())];
    out.bound = lowest.bound;
    if (lowest.order > 0 && Below(lowest.bound) && lowest.x.size() > 0) {
      out.lowest_leaf_x = lowest.x;
      out.lowest_leaf_lower = lowest.lower;
      out.lowest_leaf_upper = lowest.upper;
    }
    for (const Leaf& leaf : leaves_) out.open_leaves += Below(leaf.bound) ? 1 : 0;
    if (lps_ > 0) out.open = OpenLeaves();
    std::string splits;
    for (const std::string& line : splits_) splits += (splits.empty() ? " (" : "; ") + line;
    if (!splits.empty()) splits += ")";
    out.detail = "branching on thruster totals: " + std::to_string(lps_) + " LPs" + splits +
                 ", bound " + FormatG(out.bound, 8) + " (root " + FormatG(root_bound, 8) + "), " +
                 std::to_string(out.open_leaves) + " leaves below the incumbent; " + why +
                 (warm_ && session_ ? "; " + session_note_ : "");
    return out;
  }

 private:
  // The warm tree's LP session and its root basis, before the first split:
  // the crossover from the relaxation's interior point when the caller gave
  // its duals, or else an interior point and its crossover. False if the
  // root stops short (time limit, interrupt): no leaf then.
  bool OpenSession(const Eigen::VectorXd& root_x) {
    totals_lp_ = WithGroupTotalColumns(milp_, groups_, elastic_cost_);
    milp::SolveOptions o = options_;
    o.time_limit_s = std::max(0.0, Remaining());
    o.lp_algorithm = milp::LpAlgorithm::kBarrier;
    const double t0 = Elapsed();
    // The root without its elastic slots (at the root every total is free,
    // so they are zero anyway): their penalty, four orders of magnitude above
    // the slots' costs, slowed CLP's interior point from 11 s to minutes on a
    // six-thruster GEO week. Restored for the leaves, whose dual simplex
    // minds no cost scale.
    milp::LpData root_lp = totals_lp_.lp;
    for (int column : totals_lp_.elastic_column) root_lp.col_upper[column] = 0.0;
    session_ = solver_.OpenLpSession(root_lp, o);
    std::string how = "interior point and crossover";
    if (root_duals_.size() == milp_.lp().num_rows()) {
      // The relaxation's point with each group's total at it (its slots
      // short and over 0), the groups' rows' duals 0.
      const int n = milp_.lp().num_cols(), m = milp_.lp().num_rows();
      Eigen::VectorXd x = Eigen::VectorXd::Zero(root_lp.num_cols());
      Eigen::VectorXd duals = Eigen::VectorXd::Zero(root_lp.num_rows());
      x.head(n) = root_x;
      duals.head(m) = root_duals_;
      const std::vector<double> y = GroupTotalsAt(groups_, milp_.encoding(), root_x);
      for (size_t g = 0; g < groups_.size(); ++g) x[totals_lp_.bound_column[g]] = y[g];
      session_->CrossOverFrom(x, duals);
      how = "crossover from the relaxation's interior point";
    }
    const milp::LpRelaxationResult root = session_->Solve();
    for (int column : totals_lp_.elastic_column) {
      session_->SetColumnBounds(column, totals_lp_.lp.col_lower[column],
                                totals_lp_.lp.col_upper[column]);
    }
    // A leaf changes a bound or two of its parent: its dual simplex takes
    // tens to hundreds of pivots. One that needs more than the root took
    // keeps its parent's bound (LeafPivotLimit).
    if (leaf_pivot_limit_) {
      pivot_limit_ = LeafPivotLimit(root.iterations);
      session_->SetPivotLimit(pivot_limit_);
    }
    session_note_ = "leaves by dual simplex from their parent's basis, the root's by " + how +
                    " in " + FormatG(Elapsed() - t0, 3) + " s";
    if (root.status == milp::SolveStatus::kOptimal) return true;
    session_note_ = "the root basis was not found (" + root.detail + ")";
    session_.reset();
    return false;
  }

  std::string Search(int max_lps) {
    for (;;) {
      const int k = Lowest();
      if (!Below(leaves_[static_cast<size_t>(k)].bound))
        return "every leaf at the incumbent or above";
      if (std::isfinite(incumbent_) &&
          milp::GapClosed(incumbent_, leaves_[static_cast<size_t>(k)].bound, options_))
        return "the incumbent within the requested gap";
      const std::string lp_limit = "LP limit (" + std::to_string(max_lps) + ")";
      const bool windows = WindowsAllowed(leaves_[static_cast<size_t>(k)].bound);
      if (whole_lps_ + 2 > max_lps && !windows) return lp_limit;
      if (windows && window_lps_ + 2 > max_window_lps_)
        return "window LP limit (" + std::to_string(max_window_lps_) + ")";
      if (Interrupted()) return "interrupted";
      if (Remaining() <= 0.0) return "time limit";
      if (warm_ && !session_) {
        // The lowest leaf is the root: no session before the first split.
        if (!OpenSession(leaves_[static_cast<size_t>(k)].x)) return session_note_;
        leaves_[static_cast<size_t>(k)].basis = session_->SaveBasis();
      }
      if (windows && RetryWithoutPivotLimit(&leaves_[static_cast<size_t>(k)])) continue;
      Leaf parent = std::move(leaves_[static_cast<size_t>(k)]);
      leaves_.erase(leaves_.begin() + k);
      const std::vector<double> y = parent.x.size() > 0
                                        ? GroupTotalsAt(groups_, milp_.encoding(), parent.x)
                                        : std::vector<double>{};
      int i = y.empty() ? -1 : SplitGroup(groups_, y, false);
      const bool window_split = i < 0 && windows && !y.empty();
      if (window_split) i = SplitGroup(groups_, y, true);
      if (i < 0 || (!window_split && whole_lps_ + 2 > max_lps)) {
        const std::string why =
            i >= 0      ? lp_limit
            : y.empty() ? "the lowest leaf has no LP point to split" +
                              (parent.note.empty() ? "" : " (" + parent.note + ")")
            : window_split ? "the lowest leaf fires each thruster a whole number of slots in "
                             "each window"
                           : "the lowest leaf fires each thruster a whole number of slots";
        leaves_.push_back(std::move(parent));
        return why;
      }
      (window_split ? window_lps_ : whole_lps_) += 2;
      const size_t u = static_cast<size_t>(i);
      Leaf down = parent, up = parent;
      down.upper[u] = std::floor(y[u]);
      up.lower[u] = std::ceil(y[u]);
      down.order = ++created_;
      up.order = ++created_;
      const double t0 = Elapsed();
      SolvePair(&down, &up);
      splits_.push_back(groups_[u].name + " at " + FormatG(y[u], 4) + " slots: " + BoundText(down) +
                        " / " + BoundText(up) + ", " + FormatG(Elapsed() - t0, 3) + " s");
      leaves_.push_back(std::move(down));
      leaves_.push_back(std::move(up));
    }
  }

  // A lowest leaf whose LP stopped at the pivot limit, where the windows
  // would go on: its LP again from its parent's basis without the limit
  // (once). The limit puts off the slow LPs; the windows' proof cannot go
  // on without this one. On year_ideal6_fixed_windowed_c41 of
  // data/scenarios/hard/ the leaf with no -T in slots 0-125 stopped at the
  // limit; solved again (0.3 s) it was closed, and the tree proved the
  // incumbent optimal (23 LPs, 21 s). True if it was solved again.
  bool RetryWithoutPivotLimit(Leaf* leaf) {
    if (!leaf->pivot_limited || !session_ || leaf->basis.empty()) return false;
    session_->SetPivotLimit(-1);
    const double t0 = Elapsed();
    SolveWarm(leaf);
    leaf->pivot_limited = false;
    session_->SetPivotLimit(pivot_limit_);
    if (leaf->x.size() > 0) leaf->note.clear();
    splits_.push_back("a leaf's LP again without the pivot limit: " + BoundText(*leaf) + ", " +
                      FormatG(Elapsed() - t0, 3) + " s");
    return true;
  }

  // The two children of a split, side by side when the caller allows two
  // threads (milp::Solver::SolveLpRelaxations: each LP in its own process).
  void SolvePair(Leaf* down, Leaf* up) {
    if (warm_) {
      SolveWarm(down);
      SolveWarm(up);
      return;
    }
    const milp::LpData down_lp =
        WithGroupTotals(milp_, groups_, down->lower, down->upper, elastic_cost_);
    const milp::LpData up_lp = WithGroupTotals(milp_, groups_, up->lower, up->upper, elastic_cost_);
    milp::SolveOptions o = options_;
    o.time_limit_s = std::max(0.0, Remaining());
    const std::vector<milp::LpRelaxationResult> r =
        solver_.SolveLpRelaxations({&down_lp, &up_lp}, o);
    Take(down_lp, r[0], down);
    Take(up_lp, r[1], up);
  }

  // A leaf's LP in the session: its bounds on the totals' columns, then the
  // dual simplex from its parent's basis (a leaf changes bounds, not costs,
  // so that basis stays dual feasible). From the sibling's basis instead,
  // the leaf +N and -N >= 48 of week 47 of data/scenarios/hard/ (six
  // thrusters) ran out of the minute after its sibling <= 47 needed the
  // elastic slots.
  void SolveWarm(Leaf* leaf) {
    session_->RestoreBasis(leaf->basis);
    const int n = milp_.encoding().num_intervals;
    milp::LpData& lp = totals_lp_.lp;
    for (size_t g = 0; g < groups_.size(); ++g) {
      const int column = totals_lp_.bound_column[g];
      const double lo = std::max(0.0, leaf->lower[g]);
      const double hi = std::min<double>(groups_[g].MaxTotal(n), leaf->upper[g]);
      lp.col_lower[column] = lo;
      lp.col_upper[column] = hi;
      session_->SetColumnBounds(column, lo, hi);
    }
    const milp::LpRelaxationResult r = session_->Solve();
    leaf->pivot_limited = r.detail == kPivotLimit;
    if (r.status == milp::SolveStatus::kOptimal) {
      leaf->basis = session_->SaveBasis();
    } else if (!leaf->pivot_limited) {
      leaf->basis.clear();
    }
    Take(lp, r, leaf);
  }

  void Take(const milp::LpData& lp, const milp::LpRelaxationResult& r, Leaf* leaf) {
    ++lps_;
    leaf->x.resize(0);
    if (r.status == milp::SolveStatus::kInfeasible) {
      leaf->bound = milp::kInfinity;
    } else if (r.status == milp::SolveStatus::kOptimal) {
      const milp::DualBound b = milp::SafeDualBound(lp, r.row_duals);
      leaf->bound = std::max(leaf->bound, milp::RoundBoundToStep(lp, b.bound, step_));
      leaf->x = r.x.head(milp_.lp().num_cols());
      const double outside = Outside(*leaf, GroupTotalsAt(groups_, milp_.encoding(), leaf->x));
      if (outside > kIntegralTotal) {
        // Its point is not in the leaf: bound kept, not split further.
        leaf->x.resize(0);
        leaf->note = "its LP needs " + FormatG(outside, 3) + " slots outside its totals";
      } else if (Below(leaf->bound) && std::isfinite(incumbent_) && b.finite()) {
        leaf->free_slots = SlotsFreeByReducedCost(milp_.encoding(), lp, b, incumbent_, step_);
      }
    } else {
      leaf->note = r.detail == kPivotLimit ? "LP stopped at its pivot limit, parent's bound"
                                           : "LP stopped, parent's bound";
    }
  }

  // The leaves below the incumbent, lowest first.
  std::vector<OpenLeaf> OpenLeaves() const {
    std::vector<const Leaf*> below;
    for (const Leaf& leaf : leaves_)
      if (Below(leaf.bound)) below.push_back(&leaf);
    std::sort(below.begin(), below.end(),
              [](const Leaf* a, const Leaf* b) { return LowerThan(*a, *b); });
    std::vector<OpenLeaf> open;
    for (const Leaf* leaf : below)
      open.push_back({leaf->lower, leaf->upper, leaf->bound, leaf->free_slots, leaf->x});
    return open;
  }

  // Slots by which totals y lie outside the leaf's bounds, summed.
  static double Outside(const Leaf& leaf, const std::vector<double>& y) {
    double sum = 0.0;
    for (size_t g = 0; g < y.size(); ++g)
      sum += std::max({0.0, leaf.lower[g] - y[g], y[g] - leaf.upper[g]});
    return sum;
  }

  // A leaf without a point says why (its LP stopped at a limit, or needed
  // its totals relaxed).
  static std::string BoundText(const Leaf& leaf) {
    return FormatG(leaf.bound, 6) + (leaf.note.empty() ? "" : " (" + leaf.note + ")");
  }

  // Leaves in best-first order: lower bound first, then those with an LP
  // point (a leaf without one cannot be split), then creation order.
  static bool LowerThan(const Leaf& a, const Leaf& b) {
    if (a.bound != b.bound) return a.bound < b.bound;
    const bool a_point = a.x.size() > 0, b_point = b.x.size() > 0;
    if (a_point != b_point) return a_point;
    return a.order < b.order;
  }

  int Lowest() const {
    int best = 0;
    for (size_t k = 1; k < leaves_.size(); ++k) {
      if (LowerThan(leaves_[k], leaves_[static_cast<size_t>(best)])) best = static_cast<int>(k);
    }
    return best;
  }

  // Windows are split only where every better schedule costs exactly the
  // leaf's bound, the incumbent one step above it: the question is then
  // whether the leaf's whole slots can fall where its LP spreads them, and
  // each window leaf whose LP needs one more step is closed. With a wider
  // gap the leaves a step or more below the incumbent stay open whatever
  // the windows, and the time is better spent finding a schedule (the
  // leaves' MILPs): on weeks 2 and 10 of data/scenarios/hard/ (incumbents 4
  // and 2 steps above the bound) window splits took 13 and 38 s, and week 10
  // then ended at 10.5 % instead of proven optimal.
  bool WindowsAllowed(double bound) const {
    return window_levels_ > 0 && OneStepAbove(incumbent_, bound, step_);
  }

  bool Below(double bound) const {
    if (!std::isfinite(incumbent_)) return bound < milp::kInfinity;  // no incumbent
    return bound < incumbent_ - 1e-7 * std::max(1.0, std::abs(incumbent_));
  }
  double Elapsed() const { return clock_.Elapsed(); }
  double Remaining() const { return clock_.Remaining(); }
  bool Interrupted() const { return clock_.Interrupted(); }

  bool warm_;
  bool leaf_pivot_limit_;
  Eigen::VectorXd root_duals_;  // the relaxation's row duals, if the caller gave them
  GroupTotalsLp totals_lp_;     // the warm tree's LP, with the last leaf's bounds
  std::unique_ptr<milp::LpSession> session_;
  long long pivot_limit_ = -1;  // the leaves' (LeafPivotLimit), -1: none
  std::string session_note_;
  const ScheduleMilp& milp_;
  const milp::Solver& solver_;
  const milp::SolveOptions& options_;
  double incumbent_;
  double step_;
  double elastic_cost_;  // per slot outside a leaf's totals (0: hard bounds)
  std::vector<ThrusterGroup> groups_;
  int window_levels_;
  int max_window_lps_;
  common::SolveClock clock_;
  std::vector<Leaf> leaves_;
  int lps_ = 0;
  int whole_lps_ = 0;   // LPs of splits on whole-horizon totals (max_lps)
  int window_lps_ = 0;  // LPs of splits on windows (TreeOptions::max_window_lps)
  int created_ = 0;
  std::vector<std::string> splits_;  // "+N at 0.4513 slots: down / up bound"
};

}  // namespace

TotalBranching BranchOnThrusterTotals(const ScheduleMilp& milp, const milp::Solver& solver,
                                      const milp::SolveOptions& lp_options,
                                      const Eigen::VectorXd& root_x, double root_bound,
                                      double incumbent, double step, int max_lps,
                                      const TreeOptions& tree, const Eigen::VectorXd& root_duals) {
  double elastic_cost = 0.0;  // hard bounds
  if (tree.elastic) {
    const double factor = tree.warm ? kWarmElasticFactor : kElasticFactor;
    elastic_cost = factor * std::max(step, std::abs(root_bound));
    if (std::isfinite(incumbent))
      elastic_cost = std::max(elastic_cost, factor * std::abs(incumbent));
  }
  return Tree(milp, solver, lp_options, incumbent, step, tree, elastic_cost, root_duals)
      .Run(root_x, root_bound, max_lps);
}

}  // namespace thrustsched::transcription
