// Keep-out rows (Serra 2015 Problem 10) on a small avoidance problem
// (conjunction_test_util.h), against independent references:
//  - enumeration: the MILP optimum equals the cheapest of the LPs obtained by
//    fixing, at every check, which face is enforced (all combinations);
//  - the big-M is never too small: with its binary at 1, every keep-out row
//    holds for every plan within the budget (an LP minimises the row's
//    activity over the model without keep-out rows);
//  - the budget makes infeasibility a result with a reason; the condensed
//    formulation and unbounded impulses without budget are refused.
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "milp/cbc_solver.h"
#include "tests/transcription/conjunction_test_util.h"
#include "transcription/keep_out.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"

namespace thrustsched::transcription {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

milp::SolveOptions Exact() {
  milp::SolveOptions o;
  o.relative_gap = 1e-9;
  o.absolute_gap = 1e-12;
  return o;
}

TEST(KeepOutTest, MilpOptimumEqualsEnumerationOfFaceChoices) {
  const ScheduleMilp milp(testing::SmallAvoidance(), BuildOptions{});
  ASSERT_TRUE(milp.keep_out().has_value());
  const KeepOutStats& ko = *milp.keep_out();
  ASSERT_GE(ko.checks_with_binaries, 2) << "the case must have real disjunctions";
  const auto solver = milp::MakeCbcSolver();
  const milp::SolveResult mip = solver->Solve(milp.lp(), Exact());
  ASSERT_EQ(mip.status, milp::SolveStatus::kOptimal);
  ASSERT_GT(mip.objective, 1e-4) << "the secondary must force a manoeuvre";

  // Every combination of enforced faces, one LP each.
  std::vector<const KeepOutGroup*> groups;
  for (const KeepOutGroup& g : ko.groups) {
    if (!g.binaries.empty() && g.binaries[0] >= 0) groups.push_back(&g);
  }
  double best = kInf;
  int lps = 0;
  std::vector<int> pick(groups.size(), 0);
  std::function<void(size_t)> enumerate = [&](size_t level) {
    if (level == groups.size()) {
      milp::LpData lp = milp.lp();
      for (size_t k = 0; k < groups.size(); ++k) {
        for (size_t q = 0; q < groups[k]->binaries.size(); ++q) {
          const double v = static_cast<int>(q) == pick[k] ? 0.0 : 1.0;
          lp.col_lower[groups[k]->binaries[q]] = lp.col_upper[groups[k]->binaries[q]] = v;
        }
      }
      const milp::LpRelaxationResult r = solver->SolveLpRelaxation(lp, Exact());
      ++lps;
      if (r.status == milp::SolveStatus::kOptimal) best = std::min(best, r.objective);
      return;
    }
    for (size_t q = 0; q < groups[level]->binaries.size(); ++q) {
      pick[level] = static_cast<int>(q);
      enumerate(level + 1);
    }
  };
  enumerate(0);
  EXPECT_GT(lps, 8);
  EXPECT_NEAR(mip.objective, best, 1e-9 + 1e-7 * best);
  EXPECT_LT(mip.objective, ko.cost_budget)
      << "an optimum below the budget is the optimum without it";
}

TEST(KeepOutTest, BigMIsNeverTooSmall) {
  const ScheduleMilp milp(testing::SmallAvoidance(), BuildOptions{});
  const KeepOutStats& ko = *milp.keep_out();
  const auto solver = milp::MakeCbcSolver();
  // The model without its keep-out rows: every plan within the budget.
  milp::LpData free = milp.lp();
  for (const KeepOutGroup& g : ko.groups) {
    for (int r : g.rows) {
      free.row_lower[r] = -kInf;
      free.row_upper[r] = kInf;
    }
  }
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = milp.lp().a_matrix;
  int checked = 0;
  for (const KeepOutGroup& g : ko.groups) {
    for (size_t q = 0; q < g.rows.size(); ++q) {
      if (g.binaries[q] < 0) continue;
      milp::LpData lp = free;
      lp.col_cost.setZero();
      double m_coef = 0.0;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, g.rows[q]); it;
           ++it) {
        if (it.col() == g.binaries[q]) {
          m_coef = it.value();
        } else {
          lp.col_cost[it.col()] = it.value();
        }
      }
      ASSERT_GT(m_coef, 0.0);
      const milp::LpRelaxationResult r = solver->SolveLpRelaxation(lp, Exact());
      ASSERT_EQ(r.status, milp::SolveStatus::kOptimal);
      // Lowest activity of the row without its binary + M >= the row's bound.
      EXPECT_GE(r.objective + m_coef, milp.lp().row_lower[g.rows[q]] - 1e-9)
          << "t " << g.t << " face " << g.faces[q];
      ++checked;
    }
  }
  EXPECT_EQ(checked, ko.num_binaries);
  EXPECT_GT(ko.big_m_max_m, 0.0);
}

TEST(KeepOutTest, CompletedStartIsFeasible) {
  const ScheduleMilp milp(testing::SmallAvoidance(), BuildOptions{});
  const auto solver = milp::MakeCbcSolver();
  const milp::SolveResult mip = solver->Solve(milp.lp(), Exact());
  ASSERT_TRUE(mip.has_solution());
  Eigen::VectorXd x = mip.x;
  for (int j = milp.keep_out()->first_binary_column; j < x.size(); ++j) x[j] = 0.5;  // garbage
  CompleteKeepOut(milp.lp(), *milp.keep_out(), &x);
  EXPECT_LT(milp.lp().MaxViolation(x), 1e-6);
}

TEST(KeepOutTest, BudgetTooSmallIsInfeasibleWithAReason) {
  const ScheduleMilp milp(testing::SmallAvoidance(3, 1e-5), BuildOptions{});
  ASSERT_FALSE(milp.infeasibility_reasons().empty());
  EXPECT_NE(milp.infeasibility_reasons()[0].find("keep-out at t = "), std::string::npos);
  const auto solver = milp::MakeCbcSolver();
  EXPECT_EQ(solver->Solve(milp.lp(), Exact()).status, milp::SolveStatus::kInfeasible);
}

TEST(KeepOutTest, ThrustFreeMotionPassesWhenTheSecondaryIsFar) {
  ScheduleProblem p = testing::SmallAvoidance();
  p.conjunction->secondary_state[1] += 50000.0;  // 50 km along-track: never close
  const ScheduleMilp milp(p, BuildOptions{});
  EXPECT_EQ(milp.keep_out()->num_binaries, 0);
  EXPECT_EQ(milp.keep_out()->checks_clear, 3);
  const auto solver = milp::MakeCbcSolver();
  const milp::SolveResult r = solver->Solve(milp.lp(), Exact());
  ASSERT_EQ(r.status, milp::SolveStatus::kOptimal);
  EXPECT_NEAR(r.objective, 0.0, 1e-12);
}

TEST(KeepOutTest, RefusesWhatItCannotBound) {
  BuildOptions condensed;
  condensed.formulation = Formulation::kCondensed;
  EXPECT_THROW(ScheduleMilp(testing::SmallAvoidance(), condensed), std::invalid_argument);
  ScheduleProblem unbounded = testing::SmallAvoidance(3, kInf);
  try {
    ScheduleMilp milp(unbounded, BuildOptions{});
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("conjunction.cost_budget"), std::string::npos) << e.what();
  }
  unbounded.max_impulse_m_s = 0.01;  // bounded impulses: a big-M exists without budget
  EXPECT_NO_THROW(ScheduleMilp(unbounded, BuildOptions{}));
}

}  // namespace
}  // namespace thrustsched::transcription
