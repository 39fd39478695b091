// An interior point method for the LP relaxation, of our own: Mehrotra's
// predictor-corrector on the regularised KKT system of the bounded LP,
// factored by a sparse LDL' with an approximate-minimum-degree ordering.
//
//   milp::InteriorPointOptions options;
//   options.should_stop = [&] { return clock.ShouldStop(); };   // optional
//   milp::InteriorPointResult r = milp::SolveLpByInteriorPoint(lp, options);
//   if (r.status == milp::SolveStatus::kOptimal) {
//     milp::DualBound b = milp::SafeDualBound(lp, r.row_duals);   // a safe bound
//   }
//
// Why: the schedule LPs are staircases (the dynamics couple step k to k+1,
// the rules reach a few steps), so the augmented system
//   [ -(D + rho I)   M'      ] [dz]   [r_d]
//   [  M             delta I ] [dl] = [r_p]
// (M = [A_eq 0; A_in -I] on z = (x, row activities of the inequality rows),
// D the barrier's diagonal) keeps the band of the staircase under a
// minimum-degree ordering: one symbolic analysis, then per iteration one
// numeric factorisation and a few solves. The regularisations rho, delta > 0
// make it quasi-definite, so LDL' without pivoting is stable for any ordering
// (Vanderbei 1995, SIAM J. Optim. 5) and free columns need no splitting; each
// step is then the exact Newton step of the proximal problem, which converges
// to the LP's optimum all the same (Friedlander & Orban 2012), so no
// iterative refinement is needed.
//
// Contract:
//  * Integrality is ignored (the relaxation). The model's sense is honoured;
//    row_duals follow LpRelaxationResult's convention (model's sense).
//  * kOptimal: the relative primal and dual residuals and the relative gap are
//    all <= tolerance (after the Ruiz scaling is undone, in the model's units).
//    The point is interior (not a vertex); x within its column bounds exactly.
//  * Anything else (no convergence in max_iterations, a stop request, a
//    factorisation failure, a diverging iterate on an infeasible or unbounded
//    LP) is kNoSolutionFound with `detail`: this method never declares an LP
//    infeasible or unbounded; a caller wanting a verdict asks a simplex.
//  * Deterministic: the same LpData and options give the same bits.
//  * A fixed column (lower == upper) stays at its value; free rows are ignored
//    (dual 0).
#ifndef THRUSTSCHED_MILP_INTERIOR_POINT_H_
#define THRUSTSCHED_MILP_INTERIOR_POINT_H_

#include <functional>
#include <string>

#include <Eigen/Core>

#include "milp/lp_data.h"
#include "milp/solver.h"

namespace thrustsched::milp {

struct InteriorPointOptions {
  /// Relative primal residual, dual residual and gap at which the point is
  /// called optimal.
  double tolerance = 1e-8;
  int max_iterations = 150;
  /// Polled once per iteration: true stops with kNoSolutionFound, "stopped".
  std::function<bool()> should_stop;
  /// Called after each iteration with its number (from 1), the primal
  /// objective at the iterate (model sense, with offset; not a bound) and
  /// the relative primal residual: for progress reports.
  std::function<void(int iteration, double objective, double primal_residual)> on_iteration;
};

struct InteriorPointResult {
  SolveStatus status = SolveStatus::kError;
  std::string detail;
  Eigen::VectorXd x;          // column values, within the column bounds
  Eigen::VectorXd row_duals;  // LpRelaxationResult's convention
  double objective = 0.0;     // c'x + offset at x
  int iterations = 0;
  double primal_residual = 0.0;  // relative, as in the stopping test
  double dual_residual = 0.0;
  double relative_gap = 0.0;
  /// Nonzeros of the LDL' factor, and the KKT dimension.
  long long factor_nonzeros = 0;
  int kkt_dimension = 0;
  double seconds_analysis = 0.0;  // ordering and symbolic factorisation
  double seconds = 0.0;           // all of it
};

/// @throws std::invalid_argument if !lp.IsValid().
InteriorPointResult SolveLpByInteriorPoint(const LpData& lp, const InteriorPointOptions& options);

/// The result as a backend's SolveLpRelaxation gives it (dual_bound from
/// SafeDualBound on `lp`, the LP it solved), for callers that take either.
LpRelaxationResult ToLpRelaxationResult(const LpData& lp, InteriorPointResult result);

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_INTERIOR_POINT_H_
