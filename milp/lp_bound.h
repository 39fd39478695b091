// A bound on a MILP from any row duals of its LP relaxation, valid whatever
// the accuracy of the LP solver that produced them, and reduced-cost fixing.
//
//   milp::LpRelaxationResult lp = solver->SolveLpRelaxation(problem, options);
//   milp::DualBound b = milp::SafeDualBound(problem, lp.row_duals);
//   // every feasible x has objective >= b.bound (minimisation; <= for max)
//   int fixed = 0;
//   milp::LpData reduced = milp::FixByReducedCost(problem, b, incumbent, step, &fixed);
//
// The bound is the Lagrangian one (Neumaier & Shcherbina 2004, "Safe bounds
// in linear and mixed-integer linear programming", Math. Program. 99):
// for a minimisation min c'x, r_lo <= A x <= r_up, l <= x <= u and any y,
//   c'x = y'(A x) + d'x,  d = c - A'y,
// so c'x >= sum_i min(y_i r_lo_i, y_i r_up_i) + sum_j min(d_j l_j, d_j u_j).
// Each term is finite when the dual sign suits the finite side: duals of the
// wrong sign on one-sided rows are set to 0 first, and columns without a
// finite bound on the side their reduced cost needs must get a zero reduced
// cost: the duals of the rows those columns appear in (equality and ranged
// rows, whose dual sign is free) are corrected by the least-squares step that
// zeroes them (the state columns of the schedule MILPs: their dynamics rows).
// What is left (rounding, ~1e-15 relative) is reported, not hidden.
//
// A valid bound L with reduced costs d also fixes columns: a binary at 0 whose
// d_j > 0 would cost at least L + d_j if it were 1, so in every solution
// better than an incumbent z (by at least `step` when all objective values
// are multiples of it) it stays 0 if L + d_j > z - step (likewise at 1).
#ifndef THRUSTSCHED_MILP_LP_BOUND_H_
#define THRUSTSCHED_MILP_LP_BOUND_H_

#include <string>

#include <Eigen/Core>

#include "milp/lp_data.h"

namespace thrustsched::milp {

struct DualBound {
  /// The bound, in the model's sense and with its offset: every feasible
  /// point's objective is >= bound (minimisation) or <= bound (maximisation);
  /// -inf / +inf if the duals could not be made to give a finite one.
  double bound = 0.0;
  /// The duals actually used (signs corrected, free columns' reduced costs
  /// zeroed), in the model's sense like LpRelaxationResult::row_duals.
  Eigen::VectorXd row_duals;
  /// c - A' row_duals (model's sense).
  Eigen::VectorXd reduced_costs;
  /// Largest |reduced cost| left on a column with no finite bound on the side
  /// it needs (ideally 0; such a column makes the bound infinite if > 1e-9
  /// relative to the costs).
  double free_residual = 0.0;
  std::string detail;
  bool finite() const;
};

/// @throws std::invalid_argument if row_duals.size() != lp.num_rows() or
///         !lp.IsValid().
DualBound SafeDualBound(const LpData& lp, const Eigen::VectorXd& row_duals);

/// The model with every integer column that cannot move from the bound its
/// reduced cost pushes it to, in any solution whose objective improves on
/// `incumbent` by at least `step` (0: by any amount), fixed there (both its
/// bounds set to that value). `fixed` (if not null) receives the count.
/// A bound of the wrong sense (worse than the incumbent) fixes nothing.
LpData FixByReducedCost(const LpData& lp, const DualBound& bound, double incumbent, double step,
                        int* fixed = nullptr);

/// The bound rounded to the grid of attainable objective values: when every
/// feasible objective is offset + k * step (k integer), a minimisation's
/// bound can be raised to the next such value (a maximisation's lowered).
/// Returns `bound` unchanged if step <= 0. A tolerance of 1e-6 step keeps
/// rounding noise from jumping a whole step.
double RoundBoundToStep(const LpData& lp, double bound, double step);

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_LP_BOUND_H_
