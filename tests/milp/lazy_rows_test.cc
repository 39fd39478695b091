// SolveWithLazyRows (row generation over dense rows) against exhaustive
// enumeration of small multidimensional knapsacks: the optimum, the proof of
// infeasibility and the bound must be those of the whole model, whatever rows
// the generation leaves out; SelectRows against the rows it copies.
#include "milp/lazy_rows.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "milp/cbc_solver.h"
#include "milp/model.h"
#include "tests/milp/problem_catalog.h"

namespace thrustsched::milp {
namespace {

using testing::RandomKnapsack;

constexpr double kInf = std::numeric_limits<double>::infinity();

// The best objective over every 0/1 point that satisfies all rows (maximised
// or minimised as the model says); NaN if none does.
double Enumerate(const LpData& lp) {
  const int n = lp.num_cols();
  const double sign = lp.sense == ObjectiveSense::kMaximize ? 1.0 : -1.0;
  double best = -kInf;
  Eigen::VectorXd x(n);
  for (long mask = 0; mask < (1L << n); ++mask) {
    for (int j = 0; j < n; ++j) x[j] = (mask >> j) & 1;
    if (lp.MaxViolation(x) > 1e-9) continue;
    best = std::max(best, sign * lp.Objective(x));
  }
  return std::isfinite(best) ? sign * best : std::numeric_limits<double>::quiet_NaN();
}

SolveOptions Exact() {
  SolveOptions o;
  o.relative_gap = 0.0;
  o.absolute_gap = 1e-6;  // integer objectives
  return o;
}

LazyRowOptions SmallDense() {
  LazyRowOptions lazy;
  lazy.dense_row_min_nonzeros = 4;  // every knapsack row is "dense"
  return lazy;
}

// Knapsacks with 40 capacity rows over 14 items: the optimum found with rows
// left out is the enumerated one, the solution satisfies every row, and at
// least one instance needs a second round (a left-out row broken).
TEST(SolveWithLazyRows, FindsTheEnumeratedOptimumWithRowsLeftOut) {
  auto solver = MakeCbcSolver();
  int second_rounds = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const LpData lp = RandomKnapsack(14, 40, seed, 0.35);
    const double expected = Enumerate(lp);
    ASSERT_FALSE(std::isnan(expected));
    LazyRowReport report;
    // Progress names no incumbent of a subset (it may break a left-out row):
    // one report, of the model's solution.
    std::vector<double> reported;
    SolveOptions o = Exact();
    o.progress = [&reported](const SolveProgress& p) {
      if (p.new_incumbent) reported.push_back(p.objective);
    };
    const SolveResult r = SolveWithLazyRows(*solver, lp, o, SmallDense(), &report);
    ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.detail;
    ASSERT_EQ(reported.size(), 1u);
    EXPECT_EQ(reported[0], r.objective);
    EXPECT_NEAR(r.objective, expected, 1e-6);
    EXPECT_NEAR(r.best_bound, expected, 1e-6);
    EXPECT_LE(lp.MaxViolation(r.x), 1e-6);
    EXPECT_TRUE(report.used);
    EXPECT_LT(report.initial_rows, lp.num_rows());
    EXPECT_LE(report.initial_rows, report.final_rows);
    EXPECT_FALSE(report.fell_back);
    if (report.rounds >= 2) ++second_rounds;
  }
  EXPECT_GE(second_rounds, 1)
      << "no instance broke a left-out row: the generation loop is untested";
}

// Integer-infeasible but LP-feasible (an odd right-hand side for an even
// row): the verdict comes from a subset and holds for the whole model.
TEST(SolveWithLazyRows, ProvesInfeasibilityFromASubset) {
  Model model("odd");
  VarBlock x = model.AddVariables(10, 0, 1, VarType::kBinary, "x");
  LinearExpr twice, objective;
  for (int j = 0; j < 10; ++j) {
    twice.AddTerm(x[j], 2.0);
    objective.AddTerm(x[j], 1.0 + j);
  }
  model.AddConstraint(twice == 9.0, "odd");
  for (int i = 0; i < 20; ++i) {
    LinearExpr row;
    for (int j = 0; j < 10; ++j) row.AddTerm(x[j], 1.0 + ((i + j) % 7));
    model.AddConstraint(row <= 60.0, "cap" + std::to_string(i));
  }
  model.Minimize(objective);
  const LpData lp = model.ToLpData();
  ASSERT_TRUE(std::isnan(Enumerate(lp)));
  auto solver = MakeCbcSolver();
  LazyRowReport report;
  const SolveResult r = SolveWithLazyRows(*solver, lp, Exact(), SmallDense(), &report);
  EXPECT_EQ(r.status, SolveStatus::kInfeasible) << r.detail;
}

// A model whose nonzeros sit mostly in sparse rows is solved whole.
TEST(SolveWithLazyRows, SolvesAModelWithoutDenseRowsWhole) {
  const LpData lp = RandomKnapsack(10, 3, 5);
  auto solver = MakeCbcSolver();
  LazyRowReport report;
  const SolveResult r = SolveWithLazyRows(*solver, lp, Exact(), {}, &report);  // 24-nonzero rows
  ASSERT_EQ(r.status, SolveStatus::kOptimal);
  EXPECT_NEAR(r.objective, Enumerate(lp), 1e-6);
  EXPECT_FALSE(report.used);
  EXPECT_NE(r.detail.find("whole model"), std::string::npos) << r.detail;
}

TEST(SelectRows, CopiesTheChosenRowsAndRefusesUnorderedOnes) {
  const LpData lp = RandomKnapsack(6, 5, 3);
  const LpData sub = SelectRows(lp, {1, 3});
  ASSERT_EQ(sub.num_rows(), 2);
  ASSERT_EQ(sub.num_cols(), lp.num_cols());
  EXPECT_EQ(sub.row_names, (std::vector<std::string>{lp.row_names[1], lp.row_names[3]}));
  const Eigen::MatrixXd full = Eigen::MatrixXd(lp.a_matrix);
  const Eigen::MatrixXd part = Eigen::MatrixXd(sub.a_matrix);
  EXPECT_EQ(part.row(0), full.row(1));
  EXPECT_EQ(part.row(1), full.row(3));
  EXPECT_EQ(sub.row_upper[1], lp.row_upper[3]);
  EXPECT_THROW(SelectRows(lp, {3, 1}), std::invalid_argument);
  EXPECT_THROW(SelectRows(lp, {5}), std::invalid_argument);
}

TEST(LazyRowOptions, InvalidValuesAreNamed) {
  LazyRowOptions lazy;
  lazy.max_rounds = 0;
  std::string error;
  EXPECT_FALSE(lazy.IsValid(&error));
  EXPECT_NE(error.find("max_rounds must be >= 1, got 0"), std::string::npos) << error;
  lazy = LazyRowOptions{};
  lazy.min_dense_share = 1.5;
  EXPECT_FALSE(lazy.IsValid(&error));
  EXPECT_NE(error.find("min_dense_share"), std::string::npos) << error;
  auto solver = MakeCbcSolver();
  EXPECT_THROW(SolveWithLazyRows(*solver, RandomKnapsack(4, 2, 1), {}, lazy),
               std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::milp
