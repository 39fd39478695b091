// SafeDualBound, FixByReducedCost, RoundBoundToStep and RemoveFixedColumns
// against independent references: the catalogue's LP optima derived by hand,
// weak duality on perturbed duals (any duals give a bound below the optimum),
// and brute-force enumeration of the integer points of small knapsacks.
#include "milp/lp_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "milp/cbc_solver.h"
#include "milp/model.h"
#include "tests/milp/problem_catalog.h"

namespace thrustsched::milp {
namespace {

using testing::Catalog;
using testing::RandomKnapsack;

// With the exact duals of a simplex optimum, the bound is the LP optimum of
// the hand-derived catalogue; with any perturbation it is never above it.
TEST(SafeDualBound, ExactDualsGiveTheOptimumAndAnyDualsABound) {
  auto solver = MakeCbcSolver();
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  int checked = 0;
  for (const auto& p : Catalog()) {
    if (std::isnan(p.lp_objective)) continue;
    SCOPED_TRACE(p.name);
    const LpData lp = p.build();
    if (lp.num_rows() == 0) continue;
    SolveOptions o;
    o.lp_algorithm = LpAlgorithm::kDual;
    const LpRelaxationResult r = solver->SolveLpRelaxation(lp, o);
    ASSERT_EQ(r.status, SolveStatus::kOptimal);
    const DualBound b = SafeDualBound(lp, r.row_duals);
    const double sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
    if (b.finite()) {
      EXPECT_NEAR(b.bound, p.lp_objective, 1e-7 * std::max(1.0, std::abs(p.lp_objective)));
      EXPECT_NEAR(r.dual_bound, b.bound, 1e-12);
    }
    for (int k = 0; k < 20; ++k) {
      Eigen::VectorXd y = r.row_duals;
      for (int i = 0; i < y.size(); ++i) y[i] += 0.3 * noise(rng);
      const DualBound q = SafeDualBound(lp, y);
      if (q.finite()) {
        EXPECT_LE(sign * q.bound, sign * p.lp_objective + 1e-9);
      }
    }
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

// A free column (no finite bound) must end with a zero reduced cost: the
// duals of its equality rows are corrected, and the bound stays exact.
TEST(SafeDualBound, FreeColumnsAreProjectedOut) {
  // min x1 + 2 x2 s.t. s - x1 - x2 = 0 (s free), 1 <= s <= 3 via s in a
  // ranged row, x >= 0: the optimum puts s = 1 on x1: 1.
  Model m("free");
  Variable x1 = m.AddContinuous(0, kInfinity, "x1");
  Variable x2 = m.AddContinuous(0, kInfinity, "x2");
  Variable s = m.AddContinuous(-kInfinity, kInfinity, "s");
  m.AddConstraint(s - x1 - x2 == 0, "link");
  m.AddConstraint(LinearExpr(s) >= 1, "lo");
  m.Minimize(x1 + 2 * x2);
  const LpData lp = m.ToLpData();
  // Duals that leave s with a reduced cost (the link dual is off by 0.2).
  Eigen::VectorXd y(2);
  y << 0.8, 1.0;
  const DualBound b = SafeDualBound(lp, y);
  ASSERT_TRUE(b.finite()) << b.detail;
  EXPECT_LT(b.free_residual, 1e-12);
  EXPECT_LE(b.bound, 1.0 + 1e-12);
  EXPECT_NEAR(b.reduced_costs[2], 0.0, 1e-12);
  // With the right duals (link 1, lo 1) it is exactly the optimum.
  y << 1.0, 1.0;
  EXPECT_NEAR(SafeDualBound(lp, y).bound, 1.0, 1e-12);
}

// An LP without columns (a restricted MILP with every column fixed out;
// the random-problem soak met it: tests/transcription/random_problems.h,
// seed 9) has the offset as its exact bound, through SafeDualBound directly
// and through SolveLpRelaxation, which computes it (it used to read the
// largest cost of an empty vector and crash).
TEST(SafeDualBound, AnLpWithoutColumnsIsBoundedByItsOffset) {
  LpData lp;
  lp.objective_offset = 2.5;
  lp.col_cost.resize(0);
  lp.col_lower.resize(0);
  lp.col_upper.resize(0);
  lp.a_matrix.resize(1, 0);
  lp.row_lower = Eigen::VectorXd::Constant(1, -1.0);
  lp.row_upper = Eigen::VectorXd::Constant(1, 1.0);
  std::string error;
  ASSERT_TRUE(lp.IsValid(&error)) << error;
  // A zero dual gives the offset; a dual 0.3 on the row's lower side -1
  // gives 2.5 - 0.3, still a bound.
  const DualBound b = SafeDualBound(lp, Eigen::VectorXd::Zero(1));
  EXPECT_DOUBLE_EQ(b.bound, 2.5);
  EXPECT_EQ(b.reduced_costs.size(), 0);
  EXPECT_DOUBLE_EQ(SafeDualBound(lp, Eigen::VectorXd::Constant(1, 0.3)).bound, 2.2);
  const auto solver = MakeCbcSolver();
  const LpRelaxationResult r = solver->SolveLpRelaxation(lp);
  ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.detail;
  EXPECT_DOUBLE_EQ(r.objective, 2.5);
  EXPECT_DOUBLE_EQ(r.dual_bound, 2.5);
}

// Reduced-cost fixing never removes a point better than the incumbent:
// checked by enumerating every 0/1 point of small knapsacks.
TEST(FixByReducedCost, KeepsEveryBetterPoint) {
  auto solver = MakeCbcSolver();
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(seed);
    const LpData lp = RandomKnapsack(12, 3, seed);  // maximisation, binaries
    const LpRelaxationResult r = solver->SolveLpRelaxation(lp);
    ASSERT_EQ(r.status, SolveStatus::kOptimal);
    const DualBound b = SafeDualBound(lp, r.row_duals);
    // All feasible points by enumeration; the incumbent is a mediocre one.
    std::vector<std::pair<double, int>> points;
    for (int mask = 0; mask < (1 << 12); ++mask) {
      Eigen::VectorXd x(12);
      for (int j = 0; j < 12; ++j) x[j] = (mask >> j) & 1;
      if (lp.MaxViolation(x) <= 1e-9) points.emplace_back(lp.Objective(x), mask);
    }
    std::sort(points.begin(), points.end());
    const double best = points.back().first;
    EXPECT_GE(b.bound, best - 1e-9);  // an upper bound (maximisation)
    const double incumbent = points[points.size() * 3 / 4].first;
    int fixed = 0;
    const LpData reduced = FixByReducedCost(lp, b, incumbent, 0.0, &fixed);
    for (const auto& [value, mask] : points) {
      if (value <= incumbent + 1e-9) continue;
      Eigen::VectorXd x(12);
      for (int j = 0; j < 12; ++j) x[j] = (mask >> j) & 1;
      EXPECT_LE(reduced.MaxViolation(x), 1e-9) << "a better point was cut off";
    }
  }
}

TEST(RoundBoundToStep, RoundsTowardTheAttainableValues) {
  LpData lp;
  lp.objective_offset = 0.5;
  lp.sense = ObjectiveSense::kMinimize;
  EXPECT_DOUBLE_EQ(RoundBoundToStep(lp, 0.5 + 2.3 * 0.25, 0.25), 0.5 + 3 * 0.25);
  EXPECT_DOUBLE_EQ(RoundBoundToStep(lp, 0.5 + 3 * 0.25 - 1e-9, 0.25), 0.5 + 3 * 0.25);
  EXPECT_DOUBLE_EQ(RoundBoundToStep(lp, 1.3, 0.0), 1.3);
  lp.sense = ObjectiveSense::kMaximize;
  EXPECT_DOUBLE_EQ(RoundBoundToStep(lp, 0.5 + 2.7 * 0.25, 0.25), 0.5 + 2 * 0.25);
}

// Removing fixed columns keeps the optimum (the catalogue's MILPs with one
// column fixed at its optimal value), folds the constants into row bounds
// and the offset, and maps the remaining columns back.
TEST(RemoveFixedColumns, SameOptimumFewerColumns) {
  auto solver = MakeCbcSolver();
  for (const auto& p : Catalog()) {
    if (!p.unique_x.has_value() || p.status != SolveStatus::kOptimal) continue;
    SCOPED_TRACE(p.name);
    LpData lp = p.build();
    if (lp.num_cols() < 2) continue;
    lp.col_lower[0] = lp.col_upper[0] = (*p.unique_x)[0];
    std::vector<int> kept;
    bool feasible = false;
    const LpData small = RemoveFixedColumns(lp, &kept, &feasible);
    EXPECT_TRUE(feasible);
    EXPECT_EQ(small.num_cols(), lp.num_cols() - 1);
    ASSERT_EQ(static_cast<int>(kept.size()), small.num_cols());
    EXPECT_EQ(kept.front(), 1);
    const SolveResult r = solver->Solve(small);
    ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.detail;
    EXPECT_NEAR(r.objective, p.objective, 1e-6 * std::max(1.0, std::abs(p.objective)));
    Eigen::VectorXd full = *p.unique_x;
    for (size_t k = 0; k < kept.size(); ++k) full[kept[k]] = r.x[static_cast<Eigen::Index>(k)];
    EXPECT_LE(lp.MaxViolation(full), 1e-6);
  }
  // A fixed column that breaks a row it alone holds: reported infeasible.
  Model m("broken");
  Variable x = m.AddContinuous(2, 2, "x");
  Variable y = m.AddContinuous(0, 1, "y");
  m.AddConstraint(LinearExpr(x) <= 1, "only_x");
  m.AddConstraint(x + y <= 5, "both");
  bool feasible = true;
  const LpData small = RemoveFixedColumns(m.ToLpData(), nullptr, &feasible);
  EXPECT_FALSE(feasible);
  EXPECT_EQ(small.num_rows(), 1);
  EXPECT_DOUBLE_EQ(small.row_upper[0], 3.0);
}

// An LP session solves again from its basis after bound changes, with the
// same answers as a cold solve.
TEST(LpSession, WarmSolvesMatchColdOnes) {
  auto solver = MakeCbcSolver();
  const LpData lp = RandomKnapsack(200, 10, 3);
  std::unique_ptr<LpSession> s = solver->OpenLpSession(lp);
  LpRelaxationResult r = s->Solve();
  ASSERT_EQ(r.status, SolveStatus::kOptimal);
  LpData changed = lp;
  for (int j = 0; j < 20; ++j) {
    const double v = r.x[j] > 0.5 ? 1.0 : 0.0;
    s->SetColumnBounds(j, v, v);
    changed.col_lower[j] = changed.col_upper[j] = v;
    EXPECT_EQ(s->column_lower(j), v);
    r = s->Solve();
    ASSERT_EQ(r.status, SolveStatus::kOptimal);
  }
  const LpRelaxationResult cold = solver->SolveLpRelaxation(changed);
  ASSERT_EQ(cold.status, SolveStatus::kOptimal);
  EXPECT_NEAR(r.objective, cold.objective, 1e-7 * std::abs(cold.objective));
}

// A warm solve stops at its pivot limit (SetPivotLimit) without an answer,
// and within a limit above the pivots it needs gives the cold optimum.
TEST(LpSession, PivotLimitStopsAWarmSolve) {
  auto solver = MakeCbcSolver();
  const LpData lp = RandomKnapsack(200, 10, 3);
  std::unique_ptr<LpSession> s = solver->OpenLpSession(lp);
  const LpRelaxationResult root = s->Solve();
  ASSERT_EQ(root.status, SolveStatus::kOptimal);
  const std::vector<unsigned char> root_basis = s->SaveBasis();
  LpData changed = lp;
  for (int j = 0; j < 40; ++j) {  // every one of them flipped: many pivots
    const double v = root.x[j] > 0.5 ? 0.0 : 1.0;
    s->SetColumnBounds(j, v, v);
    changed.col_lower[j] = changed.col_upper[j] = v;
  }
  const LpRelaxationResult cold = solver->SolveLpRelaxation(changed);
  ASSERT_EQ(cold.status, SolveStatus::kOptimal);
  const LpRelaxationResult free_run = s->Solve();
  ASSERT_EQ(free_run.status, SolveStatus::kOptimal);
  EXPECT_NEAR(free_run.objective, cold.objective, 1e-7 * std::abs(cold.objective));
  ASSERT_GT(free_run.iterations, 2);

  s->RestoreBasis(root_basis);
  s->SetPivotLimit(2);
  const LpRelaxationResult stopped = s->Solve();
  EXPECT_EQ(stopped.status, SolveStatus::kNoSolutionFound);
  EXPECT_EQ(stopped.detail, "pivot limit");
  EXPECT_LE(stopped.iterations, 2);

  s->RestoreBasis(root_basis);
  s->SetPivotLimit(2 * free_run.iterations);
  const LpRelaxationResult within = s->Solve();
  ASSERT_EQ(within.status, SolveStatus::kOptimal) << within.detail;
  EXPECT_NEAR(within.objective, cold.objective, 1e-7 * std::abs(cold.objective));
}

// A tree's child solved from its parent's basis (SaveBasis, RestoreBasis),
// after a sibling moved the session elsewhere, gives the cold solve's
// optimum; so does a first solve by interior point and crossover.
TEST(LpSession, ChildFromItsParentsBasisMatchesAColdSolve) {
  auto solver = MakeCbcSolver();
  const LpData lp = RandomKnapsack(200, 10, 5);
  for (const LpAlgorithm first : {LpAlgorithm::kDual, LpAlgorithm::kBarrier}) {
    SolveOptions o;
    o.lp_algorithm = first;
    std::unique_ptr<LpSession> s = solver->OpenLpSession(lp, o);
    const LpRelaxationResult root = s->Solve();
    ASSERT_EQ(root.status, SolveStatus::kOptimal);
    const LpRelaxationResult cold_root = solver->SolveLpRelaxation(lp);
    EXPECT_NEAR(root.objective, cold_root.objective, 1e-7 * std::abs(cold_root.objective));
    const std::vector<unsigned char> parent = s->SaveBasis();
    EXPECT_EQ(parent.size(), static_cast<size_t>(lp.num_cols() + lp.num_rows()));
    int fractional = 0;  // a column the root uses in part
    while (fractional < lp.num_cols() &&
           (root.x[fractional] < 1e-6 || root.x[fractional] > 1.0 - 1e-6)) {
      ++fractional;
    }
    ASSERT_LT(fractional, lp.num_cols());
    for (const double fixed : {0.0, 1.0}) {  // the sibling, then the child
      s->RestoreBasis(parent);
      s->SetColumnBounds(fractional, fixed, fixed);
      const LpRelaxationResult warm = s->Solve();
      LpData child = lp;
      child.col_lower[fractional] = child.col_upper[fractional] = fixed;
      const LpRelaxationResult cold = solver->SolveLpRelaxation(child);
      ASSERT_EQ(warm.status, cold.status);
      if (cold.status == SolveStatus::kOptimal) {
        EXPECT_NEAR(warm.objective, cold.objective, 1e-7 * std::abs(cold.objective));
      }
    }
  }
}

// SolveLpRelaxation's interior point without crossover.
LpRelaxationResult InteriorPoint(const Solver& solver, const LpData& lp) {
  SolveOptions interior_point;
  interior_point.lp_algorithm = LpAlgorithm::kBarrierNoCrossover;
  return solver.SolveLpRelaxation(lp, interior_point);
}

// A session started from an interior point (CrossOverFrom with
// SolveLpRelaxation's point and duals without crossover) crosses over to a
// vertex with a basis: the cold simplex's optimum. So too for an LP grown by
// a column and a row that restate a sum of old columns, started from the
// point with the sum at its value (as the tree on thruster totals does), and
// then with that sum bounded, from the crossover's basis.
TEST(LpSession, CrossOverFromAnInteriorPointMatchesAColdSolve) {
  auto solver = MakeCbcSolver();
  const LpData lp = RandomKnapsack(200, 10, 9);
  constexpr int kSummed = 50;  // sum = x_0 + ... + x_49
  LpData grown = lp;
  const int sum = AppendColumns(&grown, {{0.0, kSummed, 0.0, VarType::kContinuous, "sum"}});
  SparseRow row;
  for (int j = 0; j < kSummed; ++j) {
    row.columns.push_back(j);
    row.coefficients.push_back(1.0);
  }
  row.columns.push_back(sum);
  row.coefficients.push_back(-1.0);
  row.lower = row.upper = 0.0;
  AppendRows(&grown, {row});
  const LpRelaxationResult cold = solver->SolveLpRelaxation(lp);
  ASSERT_EQ(cold.status, SolveStatus::kOptimal);
  const LpRelaxationResult interior = InteriorPoint(*solver, lp);
  ASSERT_EQ(interior.status, SolveStatus::kOptimal);
  EXPECT_NEAR(interior.objective, cold.objective, 1e-6 * std::abs(cold.objective));
  for (const bool with_sum : {false, true}) {
    SCOPED_TRACE(with_sum ? "the LP grown by a sum" : "the interior point's LP");
    const LpData& now = with_sum ? grown : lp;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(now.num_cols());
    Eigen::VectorXd duals = Eigen::VectorXd::Zero(now.num_rows());
    x.head(lp.num_cols()) = interior.x;
    duals.head(lp.num_rows()) = interior.row_duals;
    if (with_sum) x[sum] = interior.x.head(kSummed).sum();
    std::unique_ptr<LpSession> s = solver->OpenLpSession(now);
    s->CrossOverFrom(x, duals);
    const LpRelaxationResult crossed = s->Solve();
    ASSERT_EQ(crossed.status, SolveStatus::kOptimal);
    EXPECT_EQ(s->SaveBasis().size(), static_cast<size_t>(now.num_cols() + now.num_rows()));
    EXPECT_NEAR(crossed.objective, cold.objective, 1e-7 * std::abs(cold.objective));
    LpData relaxed = now;  // MaxViolation counts integrality too
    std::fill(relaxed.col_type.begin(), relaxed.col_type.end(), VarType::kContinuous);
    EXPECT_LE(relaxed.MaxViolation(crossed.x), 1e-7);
    // A vertex: at most one column strictly between its bounds per row.
    int between = 0;
    for (int j = 0; j < now.num_cols(); ++j)
      between += crossed.x[j] > 1e-9 && crossed.x[j] < now.col_upper[j] - 1e-9 ? 1 : 0;
    EXPECT_LE(between, now.num_rows());
    if (!with_sum) continue;
    // The sum bounded below its value: a dual simplex from that basis.
    LpData bounded = grown;
    bounded.col_upper[sum] = std::max(0.0, std::floor(crossed.x[sum]) - 1.0);
    s->SetColumnBounds(sum, 0.0, bounded.col_upper[sum]);
    const LpRelaxationResult warm = s->Solve();
    const LpRelaxationResult cold_bounded = solver->SolveLpRelaxation(bounded);
    ASSERT_EQ(warm.status, SolveStatus::kOptimal);
    ASSERT_EQ(cold_bounded.status, SolveStatus::kOptimal);
    EXPECT_NEAR(warm.objective, cold_bounded.objective, 1e-7 * std::abs(cold_bounded.objective));
    EXPECT_GT(std::abs(cold_bounded.objective - cold.objective), 1e-6);  // the bound mattered
  }
  // A point of the wrong size is refused, naming the sizes.
  std::unique_ptr<LpSession> s = solver->OpenLpSession(grown);
  try {
    s->CrossOverFrom(interior.x, interior.row_duals);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("200 values and 10 duals for an LP of 201 columns and "
                                         "11 rows"),
              std::string::npos)
        << e.what();
  }
}

// Columns the duals price out (reduced cost well above zero) go to their
// bound before the crossover's pivots, however far the point holds them from
// it: from a point halfway between the interior point and a point at 1e-3 in
// every column (every priced-out column off its bounds), the crossover
// still reaches the cold optimum, in fewer pivots than half those columns.
TEST(LpSession, CrossOverPutsPricedOutColumnsAtTheirBounds) {
  auto solver = MakeCbcSolver();
  const LpData lp = RandomKnapsack(200, 10, 9);
  const LpRelaxationResult cold = solver->SolveLpRelaxation(lp);
  ASSERT_EQ(cold.status, SolveStatus::kOptimal);
  const LpRelaxationResult interior = InteriorPoint(*solver, lp);
  ASSERT_EQ(interior.status, SolveStatus::kOptimal);
  const Eigen::VectorXd inside =
      0.5 * interior.x + 0.5 * Eigen::VectorXd::Constant(lp.num_cols(), 1e-3);
  LpData relaxed = lp;
  std::fill(relaxed.col_type.begin(), relaxed.col_type.end(), VarType::kContinuous);
  ASSERT_LE(relaxed.MaxViolation(inside), 1e-9);  // a feasible point, off every bound
  std::unique_ptr<LpSession> s = solver->OpenLpSession(lp);
  s->CrossOverFrom(inside, interior.row_duals);
  const LpRelaxationResult crossed = s->Solve();
  ASSERT_EQ(crossed.status, SolveStatus::kOptimal);
  EXPECT_NEAR(crossed.objective, cold.objective, 1e-7 * std::abs(cold.objective));
  EXPECT_LE(relaxed.MaxViolation(crossed.x), 1e-7);
  // Columns the duals price out: left superbasic, each would cost at least a
  // pivot (262 in all, measured with the rule off); at their bounds, 35.
  const DualBound duals = SafeDualBound(lp, interior.row_duals);
  const int priced_out = static_cast<int>((duals.reduced_costs.array().abs() > 1e-6).count());
  ASSERT_GE(priced_out, 150);
  EXPECT_LT(crossed.iterations, priced_out / 2);
}

}  // namespace
}  // namespace thrustsched::milp
