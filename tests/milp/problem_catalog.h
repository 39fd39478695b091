// Catalogue of small LPs and MILPs with optima derived by hand (in the
// comments), shared by the backend, round-trip and external-solver tests.
//
//   for (const CatalogProblem& p : Catalog()) {
//     LpData lp = p.build();
//     SolveResult r = solver->Solve(lp);
//     EXPECT_EQ(r.status, p.status);  EXPECT_NEAR(r.objective, p.objective, 1e-6);
//   }
//
// Objectives are in the model's own sense, offset included. `unique_x` is set
// only when the optimum is unique (degenerate ties are checked by objective).
#ifndef THRUSTSCHED_TESTS_MILP_PROBLEM_CATALOG_H_
#define THRUSTSCHED_TESTS_MILP_PROBLEM_CATALOG_H_

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "milp/lp_data.h"
#include "milp/model.h"
#include "milp/solver.h"

namespace thrustsched::milp::testing {

inline constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

struct CatalogProblem {
  std::string name;
  std::function<LpData()> build;
  SolveStatus status;
  double objective = kNoValue;     // model sense, with offset
  double lp_objective = kNoValue;  // LP relaxation optimum (if it has one)
  std::optional<Eigen::VectorXd> unique_x;
};

inline Eigen::VectorXd Vec(std::initializer_list<double> v) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double d : v) x[i++] = d;
  return x;
}

inline std::vector<CatalogProblem> Catalog() {
  std::vector<CatalogProblem> c;

  // max 3x + 2y  s.t.  r1: x + y <= 4,  r2: x + 3y <= 7,  0 <= x <= 3, y >= 0.
  // Vertices: (3,1) -> 11; r1&r2 -> (2.5,1.5) -> 10.5; (0,7/3) -> 4.67.
  // Optimum 11 at (3,1) (r1 and the bound x <= 3 binding; r2 slack 1).
  c.push_back({"lp_max_two_rows",
               [] {
                 Model m("lp_max_two_rows");
                 Variable x = m.AddContinuous(0, 3, "x");
                 Variable y = m.AddContinuous(0, kInfinity, "y");
                 m.AddConstraint(x + y <= 4, "r1");
                 m.AddConstraint(x + 3 * y <= 7, "r2");
                 m.Maximize(3 * x + 2 * y);
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, 11.0, 11.0, Vec({3, 1})});

  // min x + 2y  s.t.  r1: x + y >= 2,  r2: x - y <= 1,  x, y >= 0.
  // y = 0 would need x >= 2 > 1: r1 and r2 both bind: x = 1.5, y = 0.5, obj 2.5.
  c.push_back({"lp_min_duals",
               [] {
                 Model m("lp_min_duals");
                 Variable x = m.AddContinuous(0, kInfinity, "x");
                 Variable y = m.AddContinuous(0, kInfinity, "y");
                 m.AddConstraint(x + y >= 2, "r1");
                 m.AddConstraint(x - y <= 1, "r2");
                 m.Minimize(x + 2 * y);
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, 2.5, 2.5, Vec({1.5, 0.5})});

  // Binaries x, y with x + y >= 3: infeasible (already as an LP).
  c.push_back({"infeasible_binaries",
               [] {
                 Model m("infeasible_binaries");
                 Variable x = m.AddBinary("x");
                 Variable y = m.AddBinary("y");
                 m.AddConstraint(x + y >= 3, "need3");
                 m.Minimize(x + y);
                 return m.ToLpData();
               },
               SolveStatus::kInfeasible, kNoValue, kNoValue, std::nullopt});

  // Integer x in [0, 5] with 2x = 1: the LP has x = 0.5 (objective 0.5 for
  // min x), the MILP no solution.
  c.push_back({"parity_infeasible",
               [] {
                 Model m("parity_infeasible");
                 Variable x = m.AddInteger(0, 5, "x");
                 m.AddConstraint(2 * x == 1, "odd");
                 m.Minimize(LinearExpr(x));
                 return m.ToLpData();
               },
               SolveStatus::kInfeasible, kNoValue, 0.5, std::nullopt});

  // min -x  s.t.  x - y <= 1,  x, y >= 0: x = y + 1 grows without bound.
  c.push_back({"unbounded_lp",
               [] {
                 Model m("unbounded_lp");
                 Variable x = m.AddContinuous(0, kInfinity, "x");
                 Variable y = m.AddContinuous(0, kInfinity, "y");
                 m.AddConstraint(x - y <= 1, "r");
                 m.Minimize(-LinearExpr(x));
                 return m.ToLpData();
               },
               SolveStatus::kUnbounded, kNoValue, kNoValue, std::nullopt});

  // max x + y, integers x, y >= 0, x - y <= 0.5: x = y = k for every k.
  c.push_back({"unbounded_mip",
               [] {
                 Model m("unbounded_mip");
                 Variable x = m.AddInteger(0, kInfinity, "x");
                 Variable y = m.AddInteger(0, kInfinity, "y");
                 m.AddConstraint(x - y <= 0.5, "r");
                 m.Maximize(x + y);
                 return m.ToLpData();
               },
               SolveStatus::kUnbounded, kNoValue, kNoValue, std::nullopt});

  // min x + 2y + z,  x in [0, 2.5], y integer >= 0, z >= 0,
  //   eq:  x + y = 3            (equality row)
  //   rng: 1 <= y - z <= 2      (ranged row)
  // obj = 3 + y + z; y >= 1 + z and x = 3 - y <= 2.5 => y >= 1: y = 1, z = 0,
  // x = 2, obj 4 (unique). LP: same (y = 1 is already integral).
  c.push_back({"equality_and_ranged",
               [] {
                 Model m("equality_and_ranged");
                 Variable x = m.AddContinuous(0, 2.5, "x");
                 Variable y = m.AddInteger(0, kInfinity, "y");
                 Variable z = m.AddContinuous(0, kInfinity, "z");
                 m.AddConstraint(x + y == 3, "eq");
                 m.AddConstraint(y - z, 1, 2, "rng");
                 m.Minimize(x + 2 * y + z);
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, 4.0, 4.0, Vec({2, 1, 0})});

  // min x + y, integers x in [-5, 5], y in [-3.5, 2.7] (i.e. -3..2),
  //   a: x + 2y >= -4.5,  b: x - y <= 1.5.
  // By y: -3, -2 infeasible; -1 -> x = -2, obj -3; 0 -> x = -4, obj -4;
  // 1 -> x = -5, obj -4; 2 -> x = -5, obj -3. Optimum -4, a tie between
  // (-4, 0) and (-5, 1): degenerate, checked by objective only.
  // LP: x = -5 (bound), y >= 0.25 from a: obj -4.75.
  c.push_back({"negative_bounds_tie",
               [] {
                 Model m("negative_bounds_tie");
                 Variable x = m.AddInteger(-5, 5, "x");
                 Variable y = m.AddInteger(-3.5, 2.7, "y");
                 m.AddConstraint(x + 2 * y >= -4.5, "a");
                 m.AddConstraint(x - y <= 1.5, "b");
                 m.Minimize(x + y);
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, -4.0, -4.75, std::nullopt});

  // min 2x - y + 10, x free, y <= 4 (lower -inf): a: x - y >= -3, b: x + y >= 1.
  // x >= max(y - 3, 1 - y): for y >= 2 obj >= y - 6, for y <= 2 obj >= 2 - 3y;
  // both give -4 at y = 2, x = -1. Objective with offset: 6 (unique).
  c.push_back({"free_variable_offset",
               [] {
                 Model m("free_variable_offset");
                 Variable x = m.AddContinuous(-kInfinity, kInfinity, "x");
                 Variable y = m.AddContinuous(-kInfinity, 4, "y");
                 m.AddConstraint(x - y >= -3, "a");
                 m.AddConstraint(x + y >= 1, "b");
                 m.Minimize(2 * x - y + 10);
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, 6.0, 6.0, Vec({-1, 2})});

  // max 5a + 4b + 3c - 2.5, binaries, w1: 2a + 3b + c <= 5, w2: 4a + b + 2c <= 11,
  // w3: 3a + 4b + 2c <= 8. Enumeration: (1,1,0) -> 9 (weights 5, 5, 7);
  // (1,0,1) -> 8; (0,1,1) -> 7; (1,1,1) violates w1. Optimum 9 - 2.5 = 6.5.
  // LP: a = 1, b = 2/3 (w1 gives 3b <= 3 - c ...): c = 1, b = 2/3 -> w3: 3 + 8/3 +
  // 2 = 7.67 <= 8, obj 5 + 8/3 + 3 = 10.67 - 2.5 = 8.1667 (derived with w1
  // binding: b = (3 - c)/3; at c = 1, b = 2/3; c = 1 is best since its ratio
  // 3 per unit of w1 beats b's 4/3).
  c.push_back({"max_knapsack_offset",
               [] {
                 Model m("max_knapsack_offset");
                 Variable a = m.AddBinary("a");
                 Variable b = m.AddBinary("b");
                 Variable cc = m.AddBinary("c");
                 m.AddConstraint(2 * a + 3 * b + cc <= 5, "w1");
                 m.AddConstraint(4 * a + b + 2 * cc <= 11, "w2");
                 m.AddConstraint(3 * a + 4 * b + 2 * cc <= 8, "w3");
                 m.Maximize(5 * a + 4 * b + 3 * cc - 2.5);
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, 6.5, 5.0 + 8.0 / 3.0 + 3.0 - 2.5, Vec({1, 1, 0})});

  // max 8x + 11y + 6z + 4w, binaries, 5x + 7y + 4z + 3w <= 14.
  // LP (greedy by ratio 1.6, 1.57, 1.5, 1.33): x, y, half of z: 22.
  // MILP: {y, z, w} weight 14 -> 21 (x + y = 12 leaves 2: 19; x + z + w = 12: 18).
  c.push_back({"integer_gap_knapsack",
               [] {
                 Model m("integer_gap_knapsack");
                 VarBlock v = m.AddVariables(4, 0, 1, VarType::kBinary, "v");
                 m.AddConstraint(LinearExpr::InnerProduct(Vec({5, 7, 4, 3}), v) <= 14, "cap");
                 m.Maximize(LinearExpr::InnerProduct(Vec({8, 11, 6, 4}), v));
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, 21.0, 22.0, Vec({0, 1, 1, 1})});

  // Integer x in [0, 3.5] (i.e. 0..3): max x + 0.5y, y in [0, 10] continuous,
  // r: x + y <= 3.25. obj = x + 0.5(3.25 - x) = 1.625 + 0.5x: x = 3, y = 0.25,
  // obj 3.125. (A reader that made x binary would give 1 + 1.125 = 2.125.)
  c.push_back({"integer_fractional_bound",
               [] {
                 Model m("integer_fractional_bound");
                 Variable x = m.AddInteger(0, 3.5, "x");
                 Variable y = m.AddContinuous(0, 10, "y");
                 m.AddConstraint(x + y <= 3.25, "r");
                 m.Maximize(x + 0.5 * y);
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, 3.125, 3.125 + 0.5 * 0.25, Vec({3, 0.25})});

  // min x + y, x fixed to 2, y >= 0, free row (x - y, no bounds), s: x + y >= 3.
  // y = 1, obj 3.
  c.push_back({"fixed_and_free_row",
               [] {
                 Model m("fixed_and_free_row");
                 Variable x = m.AddContinuous(2, 2, "x");
                 Variable y = m.AddInteger(0, 10, "y");
                 m.AddConstraint(x - y, -kInfinity, kInfinity, "free");
                 m.AddConstraint(x + y >= 3, "s");
                 m.Minimize(x + y);
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, 3.0, 3.0, Vec({2, 1})});

  // Negative upper bound: min -z, z in [-5, -3] continuous, integer k in
  // [-4, -1], r: z - k <= -1.5 -> z <= k - 1.5 <= -2.5; with z <= -3:
  // z = -3 needs k >= -1.5 -> k = -1. obj 3 (unique).
  c.push_back({"negative_upper_bound",
               [] {
                 Model m("negative_upper_bound");
                 Variable z = m.AddContinuous(-5, -3, "z");
                 Variable k = m.AddInteger(-4, -1, "k");
                 m.AddConstraint(z - k <= -1.5, "r");
                 m.Minimize(-LinearExpr(z));
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, 3.0, 3.0, Vec({-3, -1})});

  // Empty model (no rows, no columns), offset 3.5: optimum 3.5.
  c.push_back({"empty_model",
               [] {
                 Model m("empty_model");
                 m.Minimize(LinearExpr(3.5));
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, 3.5, 3.5, Eigen::VectorXd(0)});

  // No rows: min x - 2y + z, x in [1, 4], integer y in [0, 2.5], z in [-1, 3]:
  // x = 1, y = 2, z = -1, obj -4.
  c.push_back({"bounds_only",
               [] {
                 Model m("bounds_only");
                 Variable x = m.AddContinuous(1, 4, "x");
                 Variable y = m.AddInteger(0, 2.5, "y");
                 Variable z = m.AddContinuous(-1, 3, "z");
                 m.Minimize(x - 2 * y + z);
                 return m.ToLpData();
               },
               SolveStatus::kOptimal, -4.0, -4.0 - 1.0, Vec({1, 2, -1})});
  return c;
}

/// The same model with 1..n binary columns, for names and sizes that have to
/// be larger: a multi-dimensional knapsack with deterministic data (LCG).
inline LpData RandomKnapsack(int n, int m, unsigned seed, double capacity_fraction = 0.25) {
  Model model("mkp_" + std::to_string(n) + "_" + std::to_string(m));
  VarBlock x = model.AddVariables(n, 0, 1, VarType::kBinary, "x");
  unsigned state = seed;
  auto next = [&state](int lo, int hi) {
    state = state * 1664525u + 1013904223u;
    return lo + static_cast<int>((state >> 8) % static_cast<unsigned>(hi - lo + 1));
  };
  std::vector<double> value(static_cast<size_t>(n), 0.0);
  for (int i = 0; i < m; ++i) {
    LinearExpr row;
    double total = 0.0;
    for (int j = 0; j < n; ++j) {
      const int w = next(1, 1000);
      row.AddTerm(x[j], w);
      total += w;
      value[static_cast<size_t>(j)] += static_cast<double>(w) / m;
    }
    model.AddConstraint(row <= std::floor(capacity_fraction * total), "cap" + std::to_string(i));
  }
  LinearExpr objective;
  for (int j = 0; j < n; ++j) {
    objective.AddTerm(x[j], std::round(value[static_cast<size_t>(j)]) + next(1, 500));
  }
  model.Maximize(objective);
  return model.ToLpData();
}

}  // namespace thrustsched::milp::testing

#endif  // THRUSTSCHED_TESTS_MILP_PROBLEM_CATALOG_H_
