// SolveWithLazyRows (row generation over dense rows) against exhaustive
// enumeration of small multidimensional knapsacks: the optimum, the proof of
// infeasibility and the bound must be those of the whole model, whatever rows
// the generation leaves out; SelectRows against the rows it copies.
#include "milp/lazy_rows.h"

#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
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
// least one instance needs a second round (a left-out row broken). Each
// subset incumbent that keeps every row is the model's, reported as the
// solver finds it (SolveOptions::on_incumbent) and no other; the same
// optimum with LazyRowOptions::keep_model_incumbents off.
TEST(SolveWithLazyRows, FindsTheEnumeratedOptimumWithRowsLeftOut) {
  auto solver = MakeCbcSolver();
  int second_rounds = 0;
  int kept_before_the_end = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const LpData lp = RandomKnapsack(14, 40, seed, 0.35);
    const double expected = Enumerate(lp);
    ASSERT_FALSE(std::isnan(expected));
    LazyRowReport report;
    // Progress and on_incumbent name no incumbent of a subset that breaks a
    // left-out row: only the model's solutions, better and better.
    std::vector<double> reported;
    std::vector<Eigen::VectorXd> heard;
    SolveOptions o = Exact();
    o.progress = [&reported](const SolveProgress& p) {
      if (p.new_incumbent) reported.push_back(p.objective);
    };
    o.on_incumbent = [&heard](const Eigen::VectorXd& x) { heard.push_back(x); };
    const SolveResult r = SolveWithLazyRows(*solver, lp, o, SmallDense(), &report);
    ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.detail;
    ASSERT_FALSE(reported.empty());
    EXPECT_EQ(reported.back(), r.objective);
    for (size_t k = 1; k < reported.size(); ++k) EXPECT_GT(reported[k], reported[k - 1]);
    for (const Eigen::VectorXd& x : heard) EXPECT_LE(lp.MaxViolation(x), 1e-6);
    if (reported.size() >= 2) ++kept_before_the_end;
    if (seed <= 2) {  // (each solve costs minutes under ASan)
      LazyRowOptions off = SmallDense();
      off.keep_model_incumbents = false;
      EXPECT_NEAR(SolveWithLazyRows(*solver, lp, Exact(), off).objective, expected, 1e-6);
      LazyRowOptions unpresolved = SmallDense();
      unpresolved.presolve_lp_relaxation = false;
      EXPECT_NEAR(SolveWithLazyRows(*solver, lp, Exact(), unpresolved).objective, expected, 1e-6);
    }
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
  EXPECT_GE(kept_before_the_end, 1) << "no subset search reported a model solution before its end";
}

// Dense rows that every point within the column bounds keeps stay out of the
// first LP (LazyRowOptions::skip_implied_rows_in_lp), those it can break are
// not taken for them, and the optimum is the enumerated one either way.
TEST(SolveWithLazyRows, LeavesTheRowsTheColumnBoundsImplyOutOfTheFirstLp) {
  LpData lp = RandomKnapsack(12, 10, 3, 0.35);
  std::vector<int> all(12);
  std::vector<double> weight(12), mixed(12);
  double sum = 0.0, positive = 0.0, negative = 0.0;
  for (int j = 0; j < 12; ++j) {
    all[static_cast<size_t>(j)] = j;
    weight[static_cast<size_t>(j)] = 3.0 + j;
    mixed[static_cast<size_t>(j)] = (j % 2 == 0 ? 1.0 : -1.0) * (2.0 + j);
    sum += 3.0 + j;
    (j % 2 == 0 ? positive : negative) += mixed[static_cast<size_t>(j)];
  }
  std::vector<double> minus(weight);
  for (double& w : minus) w = -w;
  AppendRows(&lp, {{all, weight, -kInf, sum, "at_most_all"},  // implied (all ones: equal)
                   {all, minus, -sum - 1.0, kInf, "at_least_minus_all"},  // implied
                   {all, mixed, negative, positive, "mixed_range"},       // implied, both sides
                   {all, weight, -kInf, sum - 1.0, "not_all"}});          // all ones breaks it
  const double expected = Enumerate(lp);
  ASSERT_FALSE(std::isnan(expected));
  auto solver = MakeCbcSolver();
  LazyRowReport report;
  const SolveResult r = SolveWithLazyRows(*solver, lp, Exact(), SmallDense(), &report);
  ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.detail;
  EXPECT_EQ(report.implied_rows, 3);
  EXPECT_NEAR(r.objective, expected, 1e-6);
  EXPECT_LE(lp.MaxViolation(r.x), 1e-6);
  LazyRowOptions previous = SmallDense();
  previous.skip_implied_rows_in_lp = false;
  LazyRowReport previous_report;
  const SolveResult p = SolveWithLazyRows(*solver, lp, Exact(), previous, &previous_report);
  EXPECT_EQ(previous_report.implied_rows, 0);
  EXPECT_NEAR(p.objective, expected, 1e-6);
}

// CBC, except that once a solve ends on a solution that breaks a row of
// `full` after it reported one that keeps every row, it raises `stop` (the
// caller's interrupt) and reports "feasible": what a subset search does when
// its share runs out after its schedules moved beyond the rows left out.
class StopsOnABrokenRowSolver final : public Solver {
 public:
  StopsOnABrokenRowSolver(const LpData& full, std::atomic<bool>* stop) : full_(full), stop_(stop) {}
  std::string_view name() const override { return "stops-on-a-broken-row"; }
  std::string version() const override { return "0"; }
  mutable int solves = 0;
  mutable int stopped = 0;

 private:
  SolveResult DoSolve(const LpData& lp, const SolveOptions& o) const override {
    ++solves;
    SolveOptions inner = o;
    bool reported_a_model_solution = false;
    Eigen::VectorXd last;
    inner.on_incumbent = [&](const Eigen::VectorXd& x) {
      if (o.on_incumbent) o.on_incumbent(x);
      last = x;
      if (full_.MaxViolation(x) <= 1e-9) reported_a_model_solution = true;
    };
    SolveResult r = cbc_->Solve(lp, inner);
    if (stopped == 0 && reported_a_model_solution && r.has_solution() &&
        full_.MaxViolation(r.x) > 1e-9) {
      // As if the limit came now: CBC's result stands, but "feasible".
      ++stopped;
      stop_->store(true);
      r.status = SolveStatus::kFeasible;
      r.detail += "; test: interrupted";
    }
    return r;
  }
  LpRelaxationResult DoSolveLpRelaxation(const LpData& lp, const SolveOptions& o) const override {
    return cbc_->SolveLpRelaxation(lp, o);
  }
  const LpData& full_;
  std::atomic<bool>* stop_;
  std::unique_ptr<Solver> cbc_ = MakeCbcSolver();
};

// Never lose a schedule: a subset search that ends at a limit on a solution
// breaking a left-out row returns the model's best incumbent it reported
// before (status kFeasible, every row kept), where the option off returns
// nothing.
TEST(SolveWithLazyRows, ALimitOnABrokenRowReturnsTheModelsBestIncumbent) {
  int cases = 0;
  for (unsigned seed = 1; seed <= 12 && cases < 2; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const LpData lp = RandomKnapsack(14, 40, seed, 0.35);
    std::atomic<bool> stop{false};
    SolveOptions o = Exact();
    o.interrupt = &stop;
    const StopsOnABrokenRowSolver on(lp, &stop);
    LazyRowReport report;
    const SolveResult r = SolveWithLazyRows(on, lp, o, SmallDense(), &report);
    if (on.stopped == 0) continue;  // no subset search got there
    ++cases;
    ASSERT_EQ(r.status, SolveStatus::kFeasible) << r.detail;
    EXPECT_TRUE(report.kept_incumbent);
    EXPECT_LE(lp.MaxViolation(r.x), 1e-6);
    EXPECT_LE(r.objective, Enumerate(lp) + 1e-6);  // maximisation
    EXPECT_NE(r.detail.find("the model's best solution"), std::string::npos) << r.detail;
    stop = false;
    const StopsOnABrokenRowSolver off_solver(lp, &stop);
    LazyRowOptions off = SmallDense();
    off.keep_model_incumbents = false;
    const SolveResult r_off = SolveWithLazyRows(off_solver, lp, o, off);
    EXPECT_EQ(off_solver.stopped, 1);
    EXPECT_FALSE(r_off.has_solution()) << r_off.detail;
  }
  EXPECT_GE(cases, 1) << "no knapsack reached the path under test";
}

// CBC, except that its LP relaxations without presolve are called
// infeasible: what CLP's dual simplex without presolve has said of feasible
// schedule LPs (milp/internal/clp_lp.cc).
class NoPresolveLpSaysInfeasible final : public Solver {
 public:
  std::string_view name() const override { return "no-presolve-lp-says-infeasible"; }
  std::string version() const override { return "0"; }
  mutable int lps_without_presolve = 0;
  mutable int lps_with_presolve = 0;

 private:
  SolveResult DoSolve(const LpData& lp, const SolveOptions& o) const override {
    return cbc_->Solve(lp, o);
  }
  LpRelaxationResult DoSolveLpRelaxation(const LpData& lp, const SolveOptions& o) const override {
    if (o.presolve) {
      ++lps_with_presolve;
      return cbc_->SolveLpRelaxation(lp, o);
    }
    ++lps_without_presolve;
    LpRelaxationResult r;
    r.status = SolveStatus::kInfeasible;
    return r;
  }
  std::unique_ptr<Solver> cbc_ = MakeCbcSolver();
};

// The first LP without presolve (LazyRowOptions::presolve_lp_relaxation
// off) is not taken at its word when it does not end optimal: the LP again
// with presolve picks the rows, and the enumerated optimum follows, by row
// generation (not the whole model). On (the default), no LP without it;
// with SolveOptions::presolve off, none with it.
TEST(SolveWithLazyRows, AFirstLpWithoutPresolveThatFailsIsSolvedAgainWithPresolve) {
  const LpData lp = RandomKnapsack(14, 40, 1, 0.35);
  const NoPresolveLpSaysInfeasible solver;
  LazyRowOptions lazy = SmallDense();
  lazy.presolve_lp_relaxation = false;
  LazyRowReport report;
  const SolveResult r = SolveWithLazyRows(solver, lp, Exact(), lazy, &report);
  ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.detail;
  EXPECT_NEAR(r.objective, Enumerate(lp), 1e-6);
  EXPECT_EQ(solver.lps_without_presolve, 1);
  EXPECT_EQ(solver.lps_with_presolve, 1);
  EXPECT_TRUE(report.used);
  EXPECT_LT(report.initial_rows, lp.num_rows());
  // By default the first LP is presolved: solved once, never without it.
  const NoPresolveLpSaysInfeasible presolving;
  EXPECT_NEAR(SolveWithLazyRows(presolving, lp, Exact(), SmallDense()).objective, Enumerate(lp),
              1e-6);
  EXPECT_EQ(presolving.lps_without_presolve, 0);
  EXPECT_EQ(presolving.lps_with_presolve, 1);
  // Where the caller's options forbid presolve, neither LP has it: the
  // failed LP leaves the whole model to solve.
  const NoPresolveLpSaysInfeasible forbidden;
  SolveOptions no_presolve = Exact();
  no_presolve.presolve = false;
  LazyRowReport whole;
  EXPECT_NEAR(SolveWithLazyRows(forbidden, lp, no_presolve, lazy, &whole).objective, Enumerate(lp),
              1e-6);
  EXPECT_EQ(forbidden.lps_without_presolve, 1);
  EXPECT_EQ(forbidden.lps_with_presolve, 0);
  EXPECT_FALSE(whole.used);
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
