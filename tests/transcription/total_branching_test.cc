// BranchOnThrusterTotals against CBC alone on the whole MILP (search off,
// gap 1e-9), the independent reference: its bound never exceeds the proven
// optimum, never falls below the relaxation's, and rises above it where the
// relaxation fires thrusters for a fractional number of slots. LP limits, not
// the wall clock, end every tree here.
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/thrusters.h"
#include "milp/cbc_solver.h"
#include "milp/lp_bound.h"
#include "tests/transcription/thesis_cases.h"
#include "transcription/search.h"
#include "transcription/solve.h"
#include "transcription/total_branching.h"

namespace thrustsched::transcription {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Thesis Table 4.1 (Gazzino 2018, sec. 4.3.3), one day at 10-min steps, the
// start moved along x and drifting along y: small enough for CBC alone to
// prove in a second or two.
ScheduleProblem HcwDay(double x0_m, double vy0_m_s, double vz0_m_s = 0.0) {
  ScheduleProblem p = ThesisTable41(1.0);
  p.grid = dynamics::UniformGrid(0.0, 86400.0, 144);
  p.initial_state[0] = x0_m;
  p.initial_state[4] = vy0_m_s;
  p.initial_state[5] = vz0_m_s;
  return p;
}

// CBC alone on the whole MILP, to a proven optimum.
SolveScheduleOptions CbcAlone() {
  SolveScheduleOptions o;
  o.milp.relative_gap = 1e-9;
  o.milp.absolute_gap = 1e-9;
  o.milp.threads = 1;
  o.milp.max_nodes = 200000;
  o.search.enabled = false;
  return o;
}

double CbcOptimum(const ScheduleProblem& p, const milp::Solver& solver) {
  const ScheduleResult r = SolveSchedule(p, solver, CbcAlone());
  EXPECT_EQ(r.solve.status, milp::SolveStatus::kOptimal) << r.solve.detail;
  return r.solve.objective;
}

struct Root {
  milp::SolveOptions options;
  Eigen::VectorXd x;
  double bound = -kInf;  // rounded to the step
};

Root Relaxation(const ScheduleMilp& milp, const milp::Solver& solver) {
  Root root;
  root.options.threads = 1;
  root.options.lp_algorithm = milp::LpAlgorithm::kBarrierNoCrossover;
  const milp::LpRelaxationResult r = solver.SolveLpRelaxation(milp.lp(), root.options);
  EXPECT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
  root.x = r.x;
  root.bound = milp::RoundBoundToStep(milp.lp(), milp::SafeDualBound(milp.lp(), r.row_duals).bound,
                                      milp.objective_step());
  return root;
}

TEST(BranchOnThrusterTotals, NeverAboveTheProvenOptimumAndRaisesTheRelaxationsBound) {
  auto solver = milp::MakeCbcSolver();
  const double slot = 0.265 / 4850 * 600;  // one 10-min slot, m/s
  struct Case {
    double x0_m, vy0_m_s, vz0_m_s;
    int optimum_slots, root_slots;  // CBC alone; the rounded relaxation
    int single_slots, axis_slots;   // the tree's bound: single thrusters, axes first
  };
  // Where the relaxation's rounded bound is the optimum the tree keeps it;
  // the next two start far out and the rounded relaxation is 1 and 3 slots
  // short: the tree gains one slot on the drifting start; the last one also
  // leaves the plane (its tree splits +N and -N together after -T) and the
  // tree proves the optimum. Splitting +N and -N together first gives the
  // same bounds as single thrusters here.
  for (const Case& c : std::vector<Case>{{3000, 0, 0, 9, 9, 9, 9},
                                         {4500, 0.05, 0, 19, 19, 19, 19},
                                         {6000, 0, 0, 36, 35, 35, 35},
                                         {6000, 0.05, 0, 47, 44, 45, 45},
                                         {3000, 0, 2.75, 12, 11, 12, 12}}) {
    SCOPED_TRACE("x0 " + std::to_string(c.x0_m) + " m, vy0 " + std::to_string(c.vy0_m_s) +
                 " m/s, vz0 " + std::to_string(c.vz0_m_s) + " m/s");
    const ScheduleProblem p = HcwDay(c.x0_m, c.vy0_m_s, c.vz0_m_s);
    const ScheduleMilp milp(p, BuildOptions{});
    ASSERT_NEAR(milp.objective_step(), slot, 1e-15);
    const double optimum = CbcOptimum(p, *solver);
    EXPECT_NEAR(optimum / slot, c.optimum_slots, 1e-6);
    const Root root = Relaxation(milp, *solver);
    EXPECT_NEAR(root.bound / slot, c.root_slots, 1e-6);
    // Without an incumbent: the tree only raises the bound, never above the
    // proven optimum, by whole slots; the same bounds with each leaf LP from
    // scratch (interior point) as from its parent's basis (dual simplex).
    for (const bool axis_groups : {false, true}) {
      for (const bool warm : {false, true}) {
        TreeOptions tree;
        tree.axis_groups = axis_groups;
        tree.warm = warm;
        const TotalBranching t = BranchOnThrusterTotals(milp, *solver, root.options, root.x,
                                                        root.bound, kInf, slot, 12, tree);
        EXPECT_LE(t.lps, 12);
        EXPECT_GE(t.bound, root.bound - 1e-12) << t.detail;
        EXPECT_LE(t.bound, optimum + 1e-9) << t.detail;
        EXPECT_NEAR(t.bound / slot, axis_groups ? c.axis_slots : c.single_slots, 1e-6) << t.detail;
        if (warm && t.lps > 0) {
          EXPECT_NE(t.detail.find("from their parent's basis"), std::string::npos) << t.detail;
        }
      }
    }
    // With the optimum as incumbent: still never above it; where the
    // relaxation already reaches it nothing is solved.
    const TotalBranching proof =
        BranchOnThrusterTotals(milp, *solver, root.options, root.x, root.bound, optimum, slot, 12);
    EXPECT_LE(proof.bound, optimum + 1e-9) << proof.detail;
    EXPECT_GE(proof.bound, root.bound - 1e-12) << proof.detail;
    if (c.root_slots == c.optimum_slots) {
      EXPECT_EQ(proof.lps, 0) << proof.detail;
    }
  }
}

TEST(BranchOnThrusterTotals, StopsAtItsLpLimit) {
  auto solver = milp::MakeCbcSolver();
  const ScheduleProblem p = HcwDay(6000.0, 0.05);
  const ScheduleMilp milp(p, BuildOptions{});
  const Root root = Relaxation(milp, *solver);
  const TotalBranching none = BranchOnThrusterTotals(milp, *solver, root.options, root.x,
                                                     root.bound, kInf, milp.objective_step(), 1);
  EXPECT_EQ(none.lps, 0);
  EXPECT_EQ(none.bound, root.bound);
  EXPECT_NE(none.detail.find("LP limit (1)"), std::string::npos) << none.detail;
  const TotalBranching two = BranchOnThrusterTotals(milp, *solver, root.options, root.x, root.bound,
                                                    kInf, milp.objective_step(), 2);
  EXPECT_LE(two.lps, 2);
}

// Each open leaf's free slots (reduced-cost fixing with its LP's duals and
// the incumbent) hold every schedule of the leaf better than the incumbent
// by a step. With the proven optimum plus one slot as the incumbent, the
// optimum lies in one of the open leaves (the others are at the incumbent or
// above) and within its free slots: CBC on the MILP with the leaf's totals
// as hard rows and every other slot off finds it; no leaf's MILP beats it
// or its leaf's bound.
TEST(BranchOnThrusterTotals, OpenLeavesFreeSlotsHoldTheOptimum) {
  auto solver = milp::MakeCbcSolver();
  const ScheduleProblem p = HcwDay(6000.0, 0.05);
  const ScheduleMilp milp(p, BuildOptions{});
  const OperationalEncoding& enc = milp.encoding();
  const double slot = milp.objective_step();
  const double optimum = CbcOptimum(p, *solver);
  const Root root = Relaxation(milp, *solver);
  const TotalBranching t = BranchOnThrusterTotals(milp, *solver, root.options, root.x, root.bound,
                                                  optimum + slot, slot, 4);
  ASSERT_FALSE(t.open.empty()) << t.detail;
  EXPECT_EQ(t.open.front().bound, t.bound) << t.detail;
  milp::SolveOptions exact;
  exact.relative_gap = 1e-9;
  exact.absolute_gap = 1e-9;
  exact.threads = 1;
  exact.max_nodes = 200000;
  double best = kInf;
  int best_free = 0;
  int with_point = 0;  // open leaves with an LP point
  for (size_t k = 0; k < t.open.size(); ++k) {
    const OpenLeaf& leaf = t.open[k];
    SCOPED_TRACE("open leaf " + std::to_string(k) + " of " + t.detail);
    if (k > 0) {
      EXPECT_GE(leaf.bound, t.open[k - 1].bound);
    }
    ASSERT_EQ(leaf.free_slots.rows(), enc.num_thrusters);
    ASSERT_EQ(leaf.free_slots.cols(), enc.num_intervals);
    const int free = leaf.free_slots.sum();
    EXPECT_GT(free, 0);
    // Its LP point, where it has one, lies within its totals (the search
    // widens a net around it, SearchOptions::other_leaf_nets).
    if (leaf.x.size() > 0) {
      ++with_point;
      ASSERT_EQ(leaf.x.size(), milp.lp().num_cols());
      const std::vector<double> totals = GroupTotalsAt(t.groups, enc, leaf.x);
      for (size_t g = 0; g < totals.size(); ++g) {
        EXPECT_GE(totals[g], leaf.lower[g] - 1e-3) << t.groups[g].name;
        EXPECT_LE(totals[g], leaf.upper[g] + 1e-3) << t.groups[g].name;
      }
    }
    milp::LpData restricted = WithGroupTotals(milp, t.groups, leaf.lower, leaf.upper);
    for (int i = 0; i < enc.num_thrusters; ++i) {
      for (int j = 0; j < enc.num_intervals; ++j) {
        if (leaf.free_slots(i, j) == 0) restricted.col_upper[enc.on[i][j].index()] = 0.0;
      }
    }
    const milp::SolveResult r = solver->Solve(restricted, exact);
    if (r.status == milp::SolveStatus::kInfeasible) continue;
    ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
    EXPECT_GE(r.objective, leaf.bound - 1e-9);
    EXPECT_GE(r.objective, optimum - 1e-9);
    if (r.objective < best) {
      best = r.objective;
      best_free = free;
    }
  }
  EXPECT_NEAR(best, optimum, 1e-9);
  // Found in a leaf where the fixing left slots out (a real restriction).
  EXPECT_LT(best_free, enc.num_thrusters * enc.num_intervals);
  EXPECT_GT(with_point, 0);
}

// With two threads the children of each split are solved side by side: the
// same tree, split for split, as one after the other.
TEST(BranchOnThrusterTotals, TwoThreadsGiveTheSameTree) {
  auto solver = milp::MakeCbcSolver();
  const ScheduleProblem p = HcwDay(6000.0, 0.05);
  const ScheduleMilp milp(p, BuildOptions{});
  const Root root = Relaxation(milp, *solver);
  milp::SolveOptions two = root.options;
  two.threads = 2;
  const double step = milp.objective_step();
  const TotalBranching a =
      BranchOnThrusterTotals(milp, *solver, root.options, root.x, root.bound, kInf, step, 8);
  const TotalBranching b =
      BranchOnThrusterTotals(milp, *solver, two, root.x, root.bound, kInf, step, 8);
  EXPECT_GT(a.lps, 0) << a.detail;
  EXPECT_EQ(a.lps, b.lps) << a.detail << "\n" << b.detail;
  EXPECT_EQ(a.bound, b.bound) << a.detail << "\n" << b.detail;
  EXPECT_EQ(a.open_leaves, b.open_leaves);
  EXPECT_EQ(a.lowest_leaf_lower, b.lowest_leaf_lower);
  EXPECT_EQ(a.lowest_leaf_upper, b.lowest_leaf_upper);
}

// In the Hill-Clohessy-Wiltshire equations +N fired half an orbit after -N
// moves the final state the same way (the out-of-plane motion is an
// oscillator): one group. +R and -R, +T and -T share an axis but not their
// effect (a radial firing shifts the mean along-track position, a tangential
// one the drift, each with its sign): single thrusters. The thesis' four
// Anzel thrusters (all tilted towards -R) share no axis.
TEST(TotalGroups, ThrustersThatStandInForEachOtherFirst) {
  auto names = [](const std::vector<ThrusterGroup>& groups) {
    std::vector<std::string> out;
    for (const ThrusterGroup& g : groups) out.push_back(g.name);
    return out;
  };
  ScheduleProblem p = HcwDay(6000.0, 0.05);
  const std::vector<ThrusterGroup> groups = TotalGroups(ScheduleMilp(p, BuildOptions{}));
  EXPECT_EQ(names(groups),
            (std::vector<std::string>{"+N and -N", "+R", "+T", "+N", "-R", "-T", "-N"}));
  EXPECT_EQ(groups[0].thrusters, (std::vector<int>{2, 5}));
  EXPECT_EQ(groups[1].thrusters, (std::vector<int>{0}));
  EXPECT_EQ(names(TotalGroups(ScheduleMilp(p, BuildOptions{}), false)),
            (std::vector<std::string>{"+R", "+T", "+N", "-R", "-T", "-N"}));
  p.thrusters = dynamics::ThrusterSet::Anzel4(0.265, 4850, 2005);
  EXPECT_EQ(names(TotalGroups(ScheduleMilp(p, BuildOptions{}))),
            (std::vector<std::string>{"NE", "SE", "NW", "SW"}));
  // Three thrusters on the N axis, one of them reversed, and one along R.
  p.thrusters = dynamics::ThrusterSet({{"a", Eigen::Vector3d(0, 0, 2), true},
                                       {"b", Eigen::Vector3d(1, 0, 0), true},
                                       {"c", Eigen::Vector3d(0, 0, -1), true},
                                       {"d", Eigen::Vector3d(0, 0, 0.5), true}},
                                      0.265, 4850, 2005);
  EXPECT_EQ(names(TotalGroups(ScheduleMilp(p, BuildOptions{}))),
            (std::vector<std::string>{"a and c and d", "a", "b", "c", "d"}));
}

// A group's bounded total is the relaxation with one dense row over all its
// thrusters' slots (the same polytope): the same primal simplex optimum, and
// the interior point's safe bound is that optimum.
TEST(WithGroupTotals, IsTheRelaxationWithTheGroupTotalBounded) {
  auto solver = milp::MakeCbcSolver();
  ScheduleProblem p = HcwDay(6000.0, 0.05);
  p.initial_state[5] = 2.75;  // m/s: out of plane by 37.7 km, the box is 36.8
  const ScheduleMilp milp(p, BuildOptions{});
  const OperationalEncoding& enc = milp.encoding();
  const Root root = Relaxation(milp, *solver);
  const std::vector<ThrusterGroup> groups = TotalGroups(milp);
  const std::vector<double> totals = ThrusterTotals(enc, root.x);
  // The first group of several thrusters with a fractional total, held to at
  // least its rounding up.
  std::vector<double> lower(groups.size(), 0.0), upper(groups.size());
  int bounded = -1;
  for (size_t g = 0; g < groups.size(); ++g) {
    upper[g] = static_cast<double>(enc.num_intervals) * groups[g].thrusters.size();
    double total = 0.0;
    for (int i : groups[g].thrusters) total += totals[static_cast<size_t>(i)];
    const double frac = total - std::floor(total);
    if (bounded < 0 && groups[g].thrusters.size() > 1 && frac > 1e-3 && frac < 1 - 1e-3) {
      lower[g] = std::ceil(total);
      bounded = static_cast<int>(g);
    }
  }
  ASSERT_GE(bounded, 0) << "every axis total is whole at the relaxation";
  const milp::LpData chained = WithGroupTotals(milp, groups, lower, upper);
  EXPECT_EQ(chained.num_cols(), milp.lp().num_cols() + enc.num_intervals);
  milp::LpData dense = milp.lp();
  milp::SparseRow row;
  for (int i : groups[static_cast<size_t>(bounded)].thrusters) {
    for (int j = 0; j < enc.num_intervals; ++j) row.columns.push_back(enc.on[i][j].index());
  }
  row.coefficients.assign(row.columns.size(), 1.0);
  row.lower = lower[static_cast<size_t>(bounded)];
  milp::AppendRows(&dense, {row});

  milp::SolveOptions simplex;
  simplex.lp_algorithm = milp::LpAlgorithm::kPrimal;
  const milp::LpRelaxationResult a = solver->SolveLpRelaxation(chained, simplex);
  const milp::LpRelaxationResult b = solver->SolveLpRelaxation(dense, simplex);
  const milp::LpRelaxationResult relaxed = solver->SolveLpRelaxation(milp.lp(), simplex);
  ASSERT_EQ(a.status, milp::SolveStatus::kOptimal) << a.detail;
  ASSERT_EQ(b.status, milp::SolveStatus::kOptimal) << b.detail;
  EXPECT_NEAR(a.objective, b.objective, 1e-7 * b.objective);
  EXPECT_GT(a.objective, relaxed.objective + 1e-6);  // the bound bites
  double total = 0.0;
  for (int i : groups[static_cast<size_t>(bounded)].thrusters) {
    for (int j = 0; j < enc.num_intervals; ++j) total += a.x[enc.on[i][j].index()];
  }
  EXPECT_NEAR(a.x[chained.num_cols() - 1], total, 1e-7);
  EXPECT_GE(total, lower[static_cast<size_t>(bounded)] - 1e-7);
  const milp::LpRelaxationResult interior = solver->SolveLpRelaxation(chained, root.options);
  ASSERT_EQ(interior.status, milp::SolveStatus::kOptimal) << interior.detail;
  const double safe = milp::SafeDualBound(chained, interior.row_duals).bound;
  EXPECT_LE(safe, b.objective + 1e-7 * b.objective);
  EXPECT_GE(safe, b.objective - 1e-5 * b.objective);
}

// Elastic bounds (the tree's leaves): the LP is never infeasible, and its
// optimum is the bounded LP's where that one is feasible. Every thruster held
// to 0 slots is infeasible for a start 6 km out; elastic, each slot costs the
// step plus the penalty, so the optimum is (1 + penalty / step) times the
// relaxation's (every slot costs one step, ScheduleMilp::objective_step), and
// the interior point's safe bound is that too.
TEST(WithGroupTotals, ElasticBoundsAreNeverInfeasibleAndCostThePenaltyPerSlot) {
  auto solver = milp::MakeCbcSolver();
  const ScheduleProblem p = HcwDay(6000.0, 0.05);
  const ScheduleMilp milp(p, BuildOptions{});
  const OperationalEncoding& enc = milp.encoding();
  const double step = milp.objective_step();
  ASSERT_GT(step, 0.0);
  const Root root = Relaxation(milp, *solver);
  milp::SolveOptions simplex;
  simplex.lp_algorithm = milp::LpAlgorithm::kPrimal;
  const milp::LpRelaxationResult relaxed = solver->SolveLpRelaxation(milp.lp(), simplex);
  ASSERT_EQ(relaxed.status, milp::SolveStatus::kOptimal) << relaxed.detail;
  // One group per thruster: each slot is over exactly one bound.
  const std::vector<ThrusterGroup> groups = TotalGroups(milp, /*axis_groups=*/false);
  const double penalty = 100.0 * relaxed.objective;  // per slot, as the tree's
  const std::vector<double> none(groups.size(), 0.0);

  const milp::LpData hard = WithGroupTotals(milp, groups, none, none);
  EXPECT_EQ(solver->SolveLpRelaxation(hard, simplex).status, milp::SolveStatus::kInfeasible);
  const milp::LpData elastic = WithGroupTotals(milp, groups, none, none, penalty);
  EXPECT_EQ(elastic.num_cols(), hard.num_cols() + 2 * static_cast<int>(groups.size()));
  EXPECT_EQ(elastic.num_rows(), hard.num_rows() + static_cast<int>(groups.size()));
  const milp::LpRelaxationResult off = solver->SolveLpRelaxation(elastic, simplex);
  ASSERT_EQ(off.status, milp::SolveStatus::kOptimal) << off.detail;
  const double expected = (1.0 + penalty / step) * relaxed.objective;
  EXPECT_NEAR(off.objective, expected, 1e-6 * expected);
  const milp::LpRelaxationResult interior = solver->SolveLpRelaxation(elastic, root.options);
  ASSERT_EQ(interior.status, milp::SolveStatus::kOptimal) << interior.detail;
  const double safe = milp::SafeDualBound(elastic, interior.row_duals).bound;
  EXPECT_LE(safe, expected * (1 + 1e-7));
  EXPECT_GE(safe, expected * (1 - 1e-5));

  // A feasible leaf (a thruster the relaxation fires fractionally, held to
  // at least its rounding up): the elastic LP has the bounded LP's optimum.
  const std::vector<double> totals = ThrusterTotals(enc, root.x);
  std::vector<double> lower(groups.size(), 0.0), upper(groups.size());
  int bounded = -1;
  for (size_t g = 0; g < groups.size(); ++g) {
    upper[g] = groups[g].MaxTotal(enc.num_intervals);
    const double total = totals[static_cast<size_t>(groups[g].thrusters[0])];
    const double frac = total - std::floor(total);
    if (bounded < 0 && frac > 1e-3 && frac < 1 - 1e-3) {
      lower[g] = std::ceil(total);
      bounded = static_cast<int>(g);
    }
  }
  ASSERT_GE(bounded, 0) << "the relaxation fires every thruster a whole number of slots";
  const milp::LpRelaxationResult a =
      solver->SolveLpRelaxation(WithGroupTotals(milp, groups, lower, upper), simplex);
  const milp::LpRelaxationResult b =
      solver->SolveLpRelaxation(WithGroupTotals(milp, groups, lower, upper, penalty), simplex);
  ASSERT_EQ(a.status, milp::SolveStatus::kOptimal) << a.detail;
  ASSERT_EQ(b.status, milp::SolveStatus::kOptimal) << b.detail;
  EXPECT_GT(a.objective, relaxed.objective + 1e-6);  // the bound bites
  EXPECT_NEAR(b.objective, a.objective, 1e-7 * a.objective);
}

// Bounds that cut nothing add nothing to a leaf's LP; one bounded thruster
// adds its chain of partial sums (one column and one row per slot).
TEST(WithThrusterTotals, AddsAChainOnlyForABoundedTotal) {
  const ScheduleProblem p = HcwDay(6000.0, 0.05);
  const ScheduleMilp milp(p, BuildOptions{});
  const OperationalEncoding& enc = milp.encoding();
  const int n = enc.num_intervals;
  const size_t m = static_cast<size_t>(enc.num_thrusters);
  const ThrusterGroup single{{1}, ""}, pair{{0, 1}, ""};
  EXPECT_EQ(single.MaxTotal(n), n);
  EXPECT_EQ(pair.MaxTotal(n), 2 * n);
  EXPECT_FALSE(TotalIsBounded(0.0, n, single, n));
  EXPECT_FALSE(TotalIsBounded(-1.0, n + 1.0, single, n));
  EXPECT_TRUE(TotalIsBounded(1.0, n, single, n));
  EXPECT_TRUE(TotalIsBounded(0.0, n - 1.0, single, n));
  EXPECT_FALSE(TotalIsBounded(0.0, 2.0 * n, pair, n));
  EXPECT_TRUE(TotalIsBounded(0.0, 2.0 * n - 1.0, pair, n));
  std::vector<double> lower(m, 0.0), upper(m, n);
  const milp::LpData same = WithThrusterTotals(milp, lower, upper);
  EXPECT_EQ(same.num_cols(), milp.lp().num_cols());
  EXPECT_EQ(same.num_rows(), milp.lp().num_rows());
  upper[1] = 3.0;
  const milp::LpData one = WithThrusterTotals(milp, lower, upper);
  EXPECT_EQ(one.num_cols(), milp.lp().num_cols() + n);
  EXPECT_EQ(one.num_rows(), milp.lp().num_rows() + n);
  EXPECT_EQ(one.col_upper[one.num_cols() - 1], 3.0);
}

// A leaf's LP against the same bounds on the totals written as one row per
// thruster (milp::AppendRows), both by primal simplex: the same optimum; and
// by the interior point the tree uses, whose safe bound is that optimum.
TEST(WithThrusterTotals, IsTheRelaxationWithTheTotalsBounded) {
  auto solver = milp::MakeCbcSolver();
  const ScheduleProblem p = HcwDay(6000.0, 0.05);
  const ScheduleMilp milp(p, BuildOptions{});
  const OperationalEncoding& enc = milp.encoding();
  const Root root = Relaxation(milp, *solver);
  const size_t m = static_cast<size_t>(enc.num_thrusters);
  const std::vector<double> totals = ThrusterTotals(enc, root.x);
  // Every thruster held to at most its relaxation's total rounded down, and
  // the first thruster with a fractional total to at least its rounding up.
  std::vector<double> lower(m, 0.0), upper(m, enc.num_intervals);
  bool raised = false;
  for (size_t i = 0; i < m; ++i) {
    const double frac = totals[i] - std::floor(totals[i]);
    if (frac < 1e-3 || frac > 1 - 1e-3) continue;
    if (!raised) {
      lower[i] = std::ceil(totals[i]);
      raised = true;
    } else {
      upper[i] = std::floor(totals[i]);
    }
  }
  ASSERT_TRUE(raised) << "the relaxation fires every thruster a whole number of slots";
  const milp::LpData chained = WithThrusterTotals(milp, lower, upper);
  milp::LpData dense = milp.lp();
  std::vector<milp::SparseRow> rows;
  for (int i = 0; i < enc.num_thrusters; ++i) {
    const size_t u = static_cast<size_t>(i);
    if (lower[u] <= 0.0 && upper[u] >= enc.num_intervals) continue;
    milp::SparseRow row;
    for (int j = 0; j < enc.num_intervals; ++j) row.columns.push_back(enc.on[i][j].index());
    row.coefficients.assign(row.columns.size(), 1.0);
    row.lower = lower[u];
    row.upper = upper[u];
    rows.push_back(row);
  }
  milp::AppendRows(&dense, rows);
  std::string error;
  ASSERT_TRUE(chained.IsValid(&error)) << error;
  EXPECT_EQ(chained.num_cols(),
            milp.lp().num_cols() + static_cast<int>(rows.size()) * enc.num_intervals);

  milp::SolveOptions simplex;
  simplex.lp_algorithm = milp::LpAlgorithm::kPrimal;
  const milp::LpRelaxationResult a = solver->SolveLpRelaxation(chained, simplex);
  const milp::LpRelaxationResult b = solver->SolveLpRelaxation(dense, simplex);
  ASSERT_EQ(a.status, milp::SolveStatus::kOptimal) << a.detail;
  ASSERT_EQ(b.status, milp::SolveStatus::kOptimal) << b.detail;
  EXPECT_NEAR(a.objective, b.objective, 1e-7 * b.objective);
  const milp::LpRelaxationResult relaxed = solver->SolveLpRelaxation(milp.lp(), simplex);
  EXPECT_GT(a.objective, relaxed.objective + 1e-6);  // the bounds bite
  // The chain's last column is the total, within its bounds.
  for (size_t i = 0, k = 0; i < m; ++i) {
    if (lower[i] <= 0.0 && upper[i] >= enc.num_intervals) continue;
    const int last = milp.lp().num_cols() + static_cast<int>(k + 1) * enc.num_intervals - 1;
    double total = 0.0;
    for (int j = 0; j < enc.num_intervals; ++j)
      total += a.x[enc.on[static_cast<int>(i)][j].index()];
    EXPECT_NEAR(a.x[last], total, 1e-7);
    EXPECT_GE(total, lower[i] - 1e-7);
    EXPECT_LE(total, upper[i] + 1e-7);
    ++k;
  }
  const milp::LpRelaxationResult interior = solver->SolveLpRelaxation(chained, root.options);
  ASSERT_EQ(interior.status, milp::SolveStatus::kOptimal) << interior.detail;
  const double safe = milp::SafeDualBound(chained, interior.row_duals).bound;
  EXPECT_LE(safe, b.objective + 1e-7 * b.objective);
  EXPECT_GE(safe, b.objective - 1e-5 * b.objective);
}

// Windows: HcwDay(6000, 0) needs 36 slots (CBC alone proves it) where its
// rounded relaxation needs 35. With the optimum as the incumbent, one step
// above, the tree on whole-day totals stops at 35 with its lowest leaf firing
// each thruster a whole number of slots; with windows down to one or two
// slots (7 levels: 128 windows of the 144 slots) it proves 36, every leaf
// at the incumbent or above, and never passes it. With 5 levels (windows of
// 4-5 slots) it stops at 35, its lowest leaf whole in every window.
TEST(BranchOnThrusterTotals, WindowsProveTheOptimumWholeTotalsCannot) {
  auto solver = milp::MakeCbcSolver();
  const ScheduleProblem p = HcwDay(6000.0, 0.0);
  const ScheduleMilp milp(p, BuildOptions{});
  const double slot = milp.objective_step();
  const double optimum = CbcOptimum(p, *solver);
  ASSERT_NEAR(optimum / slot, 36.0, 1e-6);
  const Root root = Relaxation(milp, *solver);
  ASSERT_NEAR(root.bound / slot, 35.0, 1e-6);
  auto tree = [&](int levels, double incumbent) {
    TreeOptions o;
    o.window_levels = levels;
    return BranchOnThrusterTotals(milp, *solver, root.options, root.x, root.bound, incumbent, slot,
                                  12, o);
  };
  const TotalBranching whole = tree(0, optimum);
  EXPECT_NEAR(whole.bound / slot, 35.0, 1e-6) << whole.detail;
  EXPECT_NE(whole.detail.find("the lowest leaf fires each thruster a whole number of slots"),
            std::string::npos)
      << whole.detail;
  const TotalBranching fine = tree(7, optimum);
  EXPECT_NEAR(fine.bound, optimum, 1e-9) << fine.detail;
  EXPECT_EQ(fine.open_leaves, 0) << fine.detail;
  EXPECT_NE(fine.detail.find("every leaf at the incumbent or above"), std::string::npos)
      << fine.detail;
  EXPECT_NE(fine.detail.find(" in slots "), std::string::npos) << fine.detail;
  const TotalBranching coarse = tree(5, optimum);
  EXPECT_NEAR(coarse.bound / slot, 35.0, 1e-6) << coarse.detail;
  EXPECT_NE(coarse.detail.find("a whole number of slots in each window"), std::string::npos)
      << coarse.detail;
  // Two steps above the bound: no window is split (the leaves a step below
  // the incumbent would stay open), the same tree as without windows.
  const TotalBranching wide = tree(7, optimum + slot);
  EXPECT_EQ(wide.detail.find(" in slots "), std::string::npos) << wide.detail;
  EXPECT_EQ(wide.bound, tree(0, optimum + slot).bound) << wide.detail;
}

// The day above with CBC alone's optimum (36 slots), the start of the two
// search tests below.
struct HcwDayOptimum {
  std::unique_ptr<milp::Solver> solver = milp::MakeCbcSolver();
  ScheduleProblem problem = HcwDay(6000.0, 0.0);
  ScheduleMilp milp{problem, BuildOptions{}};
  double slot = milp.objective_step();
  SolveScheduleOptions cbc = CbcAlone();
  ScheduleResult ref = SolveSchedule(problem, *solver, cbc);
};

std::string StepLines(const SearchReport& report) {
  std::string steps;
  for (const std::string& step : report.steps) steps += step + "\n";
  return steps;
}

// Step 4d of the search, on the day above: given CBC alone's optimum (36
// slots) as its start, with the steps that could prove it otherwise off
// (the exact MILPs, the wider nets), the phase "tree" ends one step
// above its bound (35). With 7 levels of windows the phase "windows" proves the start
// optimal, and CBC on the whole MILP never runs: right after the tree,
// before the exchange; with 5 levels
// (windows of 4-5 slots) or none the proof is left to CBC on the whole MILP.
TEST(SearchSchedule, StepFourDProvesTheOptimumOneStepAboveTheTreesBound) {
  const HcwDayOptimum day;
  ASSERT_EQ(day.ref.solve.status, milp::SolveStatus::kOptimal) << day.ref.solve.detail;
  ASSERT_NEAR(day.ref.solve.objective / day.slot, 36.0, 1e-6);
  for (const int levels : {7, 5, 0}) {
    SearchOptions search;
    search.exact.max_slots = 0;
    search.tree.max_exact_leaf_slots = 0;
    search.nets.improvement_rounds = 0;
    search.tree.window_levels = levels;
    SearchReport report;
    const milp::SolveResult r =
        SearchSchedule(day.milp, *day.solver, day.cbc.milp, search, {day.ref.solve.x}, &report);
    const std::string steps = StepLines(report);
    const std::string which = std::to_string(levels) + " levels";
    ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << which << "\n" << steps;
    EXPECT_NEAR(r.objective / day.slot, 36.0, 1e-6) << steps;
    EXPECT_NEAR(r.best_bound / day.slot, 36.0, 1e-6) << steps;
    const size_t windows = steps.find(" in slots ");
    const size_t exchange = steps.find("exchange along");
    const bool whole_milp = steps.find("whole MILP (cbc)") != std::string::npos;
    EXPECT_EQ(windows != std::string::npos, levels > 0) << which << "\n" << steps;
    EXPECT_EQ(whole_milp, levels != 7) << which << "\n" << steps;
    // Before the exchange, which then never runs.
    if (levels == 7) {
      EXPECT_EQ(exchange, std::string::npos) << which << "\n" << steps;
    }
  }
}

// The order of steps 4 and 4b on the day above, started from CBC alone's
// optimum (36 slots, one step above the rounded LP bound), with the
// exact MILP allowed: by the plan "default", the tree and the
// windows prove the start optimal and the exact MILP never runs; by the
// plan "exact_first", the exact MILP runs first and proves it by itself.
TEST(SearchSchedule, TreeFirstWhereTheFirstIncumbentIsOneStepAboveTheBound) {
  const HcwDayOptimum day;
  ASSERT_EQ(day.ref.solve.status, milp::SolveStatus::kOptimal) << day.ref.solve.detail;
  ASSERT_NEAR(day.ref.solve.objective / day.slot, 36.0, 1e-6);
  for (const bool tree_first : {true, false}) {
    SearchOptions search;
    search.tree.window_levels = 7;
    search.plan = tree_first ? "default" : "exact_first";
    SearchReport report;
    const milp::SolveResult r =
        SearchSchedule(day.milp, *day.solver, day.cbc.milp, search, {day.ref.solve.x}, &report);
    const std::string steps = StepLines(report);
    ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << steps;
    EXPECT_NEAR(r.objective / day.slot, 36.0, 1e-6) << steps;
    EXPECT_NEAR(r.best_bound / day.slot, 36.0, 1e-6) << steps;
    const size_t tree = steps.find("branching on thruster totals");
    const size_t exact = steps.find("exact MILP over the");
    if (tree_first) {
      EXPECT_NE(steps.find(" in slots "), std::string::npos) << steps;
      EXPECT_EQ(exact, std::string::npos) << steps;
    } else {
      ASSERT_NE(exact, std::string::npos) << steps;
      EXPECT_NE(steps.find("the incumbent is optimal"), std::string::npos) << steps;
      EXPECT_EQ(tree, std::string::npos) << steps;
    }
  }
}

// The windows of each fired thruster: level l cuts the horizon into 2^l
// windows that tile it; their totals at a point add up to the thruster's.
TEST(WindowGroups, TileTheHorizonOfEachFiredThrusterAtEveryLevel) {
  auto solver = milp::MakeCbcSolver();
  const ScheduleMilp milp(HcwDay(6000.0, 0.05), BuildOptions{});
  const OperationalEncoding& enc = milp.encoding();
  const Root root = Relaxation(milp, *solver);
  const std::vector<double> totals = ThrusterTotals(enc, root.x);
  const std::vector<ThrusterGroup> windows = WindowGroups(enc, milp.problem().thrusters, root.x, 3);
  const std::vector<double> y = GroupTotalsAt(windows, enc, root.x);
  int fired = 0;
  for (int i = 0; i < enc.num_thrusters; ++i) {
    if (totals[static_cast<size_t>(i)] <= 1e-3) continue;
    ++fired;
    for (int level = 1; level <= 3; ++level) {
      int next = 0;  // the first slot the next window must start at
      double sum = 0.0;
      for (size_t g = 0; g < windows.size(); ++g) {
        if (windows[g].thrusters != std::vector<int>{i} || windows[g].level != level) continue;
        EXPECT_EQ(windows[g].first_interval, next) << windows[g].name;
        next = windows[g].End(enc.num_intervals);
        EXPECT_EQ(windows[g].MaxTotal(enc.num_intervals),
                  windows[g].end_interval - windows[g].first_interval);
        sum += y[g];
      }
      EXPECT_EQ(next, enc.num_intervals) << "level " << level;
      EXPECT_NEAR(sum, totals[static_cast<size_t>(i)], 1e-9) << "level " << level;
    }
  }
  EXPECT_GT(fired, 0);
  EXPECT_EQ(windows.size(), static_cast<size_t>(fired * (2 + 4 + 8)));
}

// Which group a leaf is split on. Whole-horizon totals: the most fractional,
// an axis group before its members. Windows: those of the thruster with the
// fewest slots (-T's 3 below, against +N's 11 whose windows are more
// fractional), its coarsest fractional level; none once all are whole.
TEST(SplitGroup, AxisGroupsFirstThenTheWindowsOfTheThrusterWithTheFewestSlots) {
  auto group = [](std::vector<int> thrusters, int first, int end, int level) {
    ThrusterGroup g;
    g.thrusters = std::move(thrusters);
    g.first_interval = first;
    g.end_interval = end;
    g.level = level;
    return g;
  };
  const int n_plus = 0, t_minus = 1, n_minus = 2;
  const std::vector<ThrusterGroup> groups = {
      group({n_plus, n_minus}, 0, -1, 0),  // 0: +N and -N
      group({n_plus}, 0, -1, 0),           // 1
      group({t_minus}, 0, -1, 0),          // 2
      group({n_minus}, 0, -1, 0),          // 3
      group({n_plus}, 0, 50, 1),           // 4: +N, first half
      group({n_plus}, 50, -1, 1),          // 5
      group({t_minus}, 0, 50, 1),          // 6: -T, first half
      group({t_minus}, 50, -1, 1),         // 7
      group({t_minus}, 0, 25, 2),          // 8: -T, first quarter
      group({t_minus}, 25, 50, 2),         // 9
  };
  // +N and -N fractional: the pair, not +N (more fractional) alone.
  EXPECT_EQ(SplitGroup(groups, {10.7, 5.5, 3.0, 5.2, 2.5, 3.0, 1.0, 2.0, 0.5, 0.5}, false), 0);
  // The pair whole: the most fractional thruster (+N and -N equally here,
  // the first), then -T.
  EXPECT_EQ(SplitGroup(groups, {11.0, 5.6, 3.0, 5.4, 2.5, 3.1, 1.0, 2.0, 0.5, 0.5}, false), 1);
  EXPECT_EQ(SplitGroup(groups, {11.0, 6.0, 2.6, 5.0, 2.5, 3.5, 1.0, 1.6, 0.5, 0.5}, false), 2);
  // Every total whole: windows of -T (3 slots), its coarsest fractional
  // level, although +N's halves are nearer to half a slot.
  const std::vector<double> whole = {11.0, 6.0, 3.0, 5.0, 2.5, 3.5, 1.2, 1.8, 0.6, 0.6};
  EXPECT_EQ(SplitGroup(groups, whole, false), -1);
  EXPECT_EQ(SplitGroup(groups, whole, true), 6);
  // -T whole in its halves: a quarter of it (0.3 and 0.7 slots, equally
  // fractional), still before +N.
  const int quarter = SplitGroup(groups, {11.0, 6.0, 3.0, 5.0, 2.5, 3.5, 1.0, 2.0, 0.3, 0.7}, true);
  EXPECT_TRUE(quarter == 8 || quarter == 9) << quarter;
  // -T whole in every window: +N's.
  EXPECT_EQ(SplitGroup(groups, {11.0, 6.0, 3.0, 5.0, 2.5, 3.5, 1.0, 2.0, 0.0, 1.0}, true), 4);
  EXPECT_EQ(SplitGroup(groups, {11.0, 6.0, 3.0, 5.0, 2.0, 4.0, 1.0, 2.0, 0.0, 1.0}, true), -1);
}

}  // namespace
}  // namespace thrustsched::transcription
