// SolveLpByInteriorPoint against independent references: the catalogue's LP
// optima derived by hand, CLP's dual simplex (a second solver) on random LPs
// of every row and column kind and on a staircase LP shaped like a schedule
// (a double integrator's fuel over a horizon), the closed form of that
// staircase's bang-off-bang optimum; and its contract: a safe bound from its
// duals, no verdict on LPs without an optimum, stop requests, bad input,
// determinism.
#include "milp/interior_point.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "milp/cbc_solver.h"
#include "milp/lp_bound.h"
#include "milp/model.h"
#include "tests/milp/problem_catalog.h"

namespace thrustsched::milp {
namespace {

using testing::Catalog;

double Scale(double v) { return std::max(1.0, std::abs(v)); }

// The LP's bound and row violation at x, integrality ignored (a relaxation).
double RelaxedViolation(LpData lp, const Eigen::VectorXd& x) {
  std::fill(lp.col_type.begin(), lp.col_type.end(), VarType::kContinuous);
  return lp.MaxViolation(x);
}

LpRelaxationResult ClpDual(const LpData& lp) {
  auto solver = MakeCbcSolver();
  SolveOptions o;
  o.lp_algorithm = LpAlgorithm::kDual;
  return solver->SolveLpRelaxation(lp, o);
}

TEST(InteriorPoint, CatalogueOptimaAndNoVerdictWithoutOne) {
  int optimal = 0, without = 0;
  for (const auto& p : Catalog()) {
    SCOPED_TRACE(p.name);
    const LpData lp = p.build();
    const InteriorPointResult r = SolveLpByInteriorPoint(lp, {});
    if (std::isnan(p.lp_objective)) {
      EXPECT_NE(r.status, SolveStatus::kOptimal) << r.detail;
      ++without;
      continue;
    }
    ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.detail;
    EXPECT_NEAR(r.objective, p.lp_objective, 1e-6 * Scale(p.lp_objective));
    EXPECT_LE(RelaxedViolation(lp, r.x), 1e-6);
    const DualBound b = SafeDualBound(lp, r.row_duals);
    if (b.finite()) {
      const double sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
      EXPECT_LE(sign * b.bound, sign * p.lp_objective + 1e-9);
      EXPECT_NEAR(b.bound, p.lp_objective, 1e-6 * Scale(p.lp_objective));
    }
    ++optimal;
  }
  EXPECT_GE(optimal, 8);
  EXPECT_GE(without, 3);
}

// A random LP of n columns and m rows around a point x0 inside the bounds, so
// that it is feasible: every row kind (equality, <=, >=, ranged, free), every
// column kind (boxed, one-sided, free, fixed), both senses.
LpData RandomLp(int n, int m, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 9);
  Model model("random" + std::to_string(seed));
  std::vector<Variable> x;
  Eigen::VectorXd x0(n);
  for (int j = 0; j < n; ++j) {
    x0[j] = 3.0 * unit(rng);
    const int k = kind(rng);
    double lo = x0[j] - 1.0 - std::abs(unit(rng)), up = x0[j] + 1.0 + std::abs(unit(rng));
    if (k == 0) lo = -kInfinity;
    if (k == 1) up = kInfinity;
    if (k == 2) lo = -kInfinity, up = kInfinity;
    if (k == 3) lo = up = x0[j];
    x.push_back(model.AddContinuous(lo, up, "x" + std::to_string(j)));
  }
  for (int i = 0; i < m; ++i) {
    LinearExpr e;
    double activity = 0.0;
    for (int j = 0; j < n; ++j) {
      if (std::abs(unit(rng)) > 0.3) continue;
      const double a = unit(rng) * (i % 3 == 0 ? 100.0 : 1.0);  // badly scaled rows
      e.AddTerm(x[static_cast<size_t>(j)], a);
      activity += a * x0[j];
    }
    const double slack = std::abs(unit(rng)) * Scale(activity);
    switch (kind(rng) % 5) {
      case 0:
        model.AddConstraint(e, activity, activity);
        break;
      case 1:
        model.AddConstraint(e, -kInfinity, activity + slack);
        break;
      case 2:
        model.AddConstraint(e, activity - slack, kInfinity);
        break;
      case 3:
        model.AddConstraint(e, activity - slack, activity + 0.5 * slack);
        break;
      default:
        model.AddConstraint(e, -kInfinity, kInfinity);
        break;
    }
  }
  LinearExpr cost;
  for (int j = 0; j < n; ++j) cost.AddTerm(x[static_cast<size_t>(j)], unit(rng));
  cost.AddConstant(2.5);  // an offset, reported in the objective
  if (seed % 2 == 0) {
    model.Minimize(cost);
  } else {
    model.Maximize(cost);
  }
  return model.ToLpData();
}

TEST(InteriorPoint, MatchesClpOnRandomLps) {
  int compared = 0, without = 0;
  for (unsigned seed = 1; seed <= 60; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const LpData lp =
        RandomLp(12 + static_cast<int>(seed % 7) * 5, 8 + static_cast<int>(seed % 5) * 6, seed);
    const LpRelaxationResult clp = ClpDual(lp);
    const InteriorPointResult r = SolveLpByInteriorPoint(lp, {});
    if (clp.status != SolveStatus::kOptimal) {
      EXPECT_NE(r.status, SolveStatus::kOptimal) << ToString(clp.status);
      ++without;
      continue;
    }
    ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.detail;
    EXPECT_NEAR(r.objective, clp.objective, 1e-6 * Scale(clp.objective));
    EXPECT_LE(RelaxedViolation(lp, r.x), 1e-6 * Scale(lp.col_lower.cwiseAbs().maxCoeff()));
    const DualBound b = SafeDualBound(lp, r.row_duals);
    if (b.finite()) {
      const double sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
      EXPECT_LE(sign * b.bound, sign * clp.objective + 1e-9 * Scale(clp.objective));
      EXPECT_GE(sign * b.bound, sign * clp.objective - 1e-6 * Scale(clp.objective));
    }
    ++compared;
  }
  // Most random LPs have an optimum; the free columns leave a few unbounded.
  EXPECT_GE(compared, 40);
  EXPECT_GE(compared + without, 60);
}

// The least fuel sum |u_k| dt of a double integrator x'' = u, |u| <= U, from
// rest at 0 to rest at distance L in N steps of dt (zero-order hold, exact
// discretisation): a staircase like the schedule LPs. With L below the
// bang-bang reach, the optimum is bang-off-bang: accelerate for t1, coast,
// brake for t1, L = U t1 (T - t1) in continuous time, fuel 2 U t1; on the grid,
// with t1 a whole number of steps, the same (the discrete system is exact).
LpData DoubleIntegratorFuel(int steps, double dt, double accel_max, double distance) {
  Model m("double_integrator");
  VarBlock pos = m.AddVariables(steps + 1, -kInfinity, kInfinity, VarType::kContinuous, "p");
  VarBlock vel = m.AddVariables(steps + 1, -kInfinity, kInfinity, VarType::kContinuous, "v");
  VarBlock plus = m.AddVariables(steps, 0, accel_max, VarType::kContinuous, "up");
  VarBlock minus = m.AddVariables(steps, 0, accel_max, VarType::kContinuous, "um");
  m.AddConstraint(LinearExpr(pos[0]) == 0, "p0");
  m.AddConstraint(LinearExpr(vel[0]) == 0, "v0");
  LinearExpr fuel;
  for (int k = 0; k < steps; ++k) {
    const LinearExpr u = LinearExpr(plus[k]) - minus[k];
    m.AddConstraint(pos[k + 1] - pos[k] - dt * vel[k] - 0.5 * dt * dt * u == 0,
                    "p" + std::to_string(k + 1));
    m.AddConstraint(vel[k + 1] - vel[k] - dt * u == 0, "v" + std::to_string(k + 1));
    fuel += dt * (LinearExpr(plus[k]) + minus[k]);
  }
  m.AddConstraint(LinearExpr(pos[steps]) == distance, "pf");
  m.AddConstraint(LinearExpr(vel[steps]) == 0, "vf");
  m.Minimize(fuel);
  return m.ToLpData();
}

TEST(InteriorPoint, StaircaseMatchesTheBangOffBangOptimumAndClp) {
  const int steps = 400;
  const double dt = 0.5, accel_max = 0.01;
  const double t_total = steps * dt, t1 = 40 * dt;  // burns of 40 steps each
  const double distance = accel_max * t1 * (t_total - t1);
  const LpData lp = DoubleIntegratorFuel(steps, dt, accel_max, distance);
  const InteriorPointResult r = SolveLpByInteriorPoint(lp, {});
  ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.detail;
  const double fuel = 2.0 * accel_max * t1;
  EXPECT_NEAR(r.objective, fuel, 1e-6 * fuel);
  const DualBound b = SafeDualBound(lp, r.row_duals);
  ASSERT_TRUE(b.finite()) << b.detail;
  EXPECT_LE(b.bound, fuel * (1 + 1e-12));
  EXPECT_GE(b.bound, fuel * (1 - 1e-6));
  const LpRelaxationResult clp = ClpDual(lp);
  ASSERT_EQ(clp.status, SolveStatus::kOptimal);
  EXPECT_NEAR(clp.objective, fuel, 1e-7 * fuel);
  // The KKT system of a staircase keeps its band: the factor grows linearly.
  EXPECT_LT(r.factor_nonzeros, 40LL * r.kkt_dimension);
  EXPECT_LT(r.iterations, 60);
}

TEST(InteriorPoint, StopRequestAndIterationLimitGiveNoSolution) {
  const LpData lp = DoubleIntegratorFuel(100, 1.0, 0.01, 10.0);
  InteriorPointOptions o;
  int polls = 0;
  o.should_stop = [&polls] { return ++polls > 2; };
  InteriorPointResult r = SolveLpByInteriorPoint(lp, o);
  EXPECT_EQ(r.status, SolveStatus::kNoSolutionFound);
  EXPECT_NE(r.detail.find("stopped"), std::string::npos) << r.detail;
  EXPECT_EQ(r.iterations, 2);
  o.should_stop = nullptr;
  o.max_iterations = 1;
  r = SolveLpByInteriorPoint(lp, o);
  EXPECT_EQ(r.status, SolveStatus::kNoSolutionFound);
  EXPECT_NE(r.detail.find("no convergence"), std::string::npos) << r.detail;
  // Whatever ends it, the point is within the column bounds and the duals
  // still give a valid (if weak) bound.
  EXPECT_EQ(r.x.size(), lp.num_cols());
  for (int j = 0; j < lp.num_cols(); ++j) {
    EXPECT_GE(r.x[j], lp.col_lower[j]);
    EXPECT_LE(r.x[j], lp.col_upper[j]);
  }
  const DualBound b = SafeDualBound(lp, r.row_duals);
  if (b.finite()) {
    EXPECT_LE(b.bound, ClpDual(lp).objective + 1e-12);
  }
}

TEST(InteriorPoint, DeterministicAndRejectsInvalidInput) {
  const LpData lp = RandomLp(30, 20, 11);
  const InteriorPointResult a = SolveLpByInteriorPoint(lp, {});
  const InteriorPointResult b = SolveLpByInteriorPoint(lp, {});
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_TRUE(a.x == b.x);
  EXPECT_TRUE(a.row_duals == b.row_duals);
  LpData bad = lp;
  bad.col_lower[0] = 1.0;
  bad.col_upper[0] = 0.0;
  EXPECT_THROW(SolveLpByInteriorPoint(bad, {}), std::invalid_argument);
}

TEST(InteriorPoint, EmptyAndRowlessLps) {
  Model m("rowless");
  Variable x = m.AddContinuous(-1, 2, "x");
  Variable y = m.AddContinuous(0, 3, "y");
  m.Minimize(x - y + 1.0);  // x = -1, y = 3: -3
  const InteriorPointResult r = SolveLpByInteriorPoint(m.ToLpData(), {});
  ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.detail;
  EXPECT_NEAR(r.objective, -3.0, 1e-7);
  Model e("empty");
  e.Minimize(LinearExpr() + 4.0);
  const InteriorPointResult q = SolveLpByInteriorPoint(e.ToLpData(), {});
  ASSERT_EQ(q.status, SolveStatus::kOptimal) << q.detail;
  EXPECT_DOUBLE_EQ(q.objective, 4.0);
}

}  // namespace
}  // namespace thrustsched::milp
