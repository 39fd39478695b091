// A MILP solved with its dense rows added only when a solution breaks them
// (row generation, as in cutting-plane methods: Nemhauser & Wolsey 1988,
// sec. II.6.3), exact whatever the rows left out.
//
//   milp::LazyRowReport lazy;
//   milp::SolveResult r = milp::SolveWithLazyRows(*solver, lp, options, {}, &lazy);
//   // r as solver->Solve(lp, options) would give it; lazy.rounds solves ran
//
// Why: a condensed schedule MILP keeps the window at every grid node as a row
// dense in every earlier slot, thousands of rows of which a few dozen bind.
// CBC's LP at every node then works on all of them. With the rows binding at
// the LP optimum (and the sparse rows) only, each solve is small; a solution
// that breaks a left-out row brings that row in and is solved again.
//
// Exact: every row set is a relaxation of the model, so an infeasible subset
// proves the model infeasible, a subset's bound is the model's bound, and a
// subset solution that satisfies every row is a solution of the model (its
// optimality carries over). After `max_rounds` solves the whole model is
// solved instead.
#ifndef THRUSTSCHED_MILP_LAZY_ROWS_H_
#define THRUSTSCHED_MILP_LAZY_ROWS_H_

#include <vector>

#include "milp/lp_data.h"
#include "milp/solver.h"

namespace thrustsched::milp {

struct LazyRowOptions {
  /// Rows with at least this many nonzeros may be left out; sparser rows are
  /// always in.
  int dense_row_min_nonzeros = 24;
  /// Solve the model whole when the rows that could be left out hold less
  /// than this share of its nonzeros (nothing to gain).
  double min_dense_share = 0.5;
  /// A dense row is in from the start when its slack at the LP optimum is at
  /// most this, relative to max(1, |bound|).
  double active_tolerance = 1e-6;
  /// A left-out row counts as broken when a solution violates it by more
  /// than this, relative to max(1, |bound|).
  double violation_tolerance = 1e-9;
  /// Subset solves before the whole model is solved instead.
  int max_rounds = 25;
  /// Presolve the LP relaxation that picks the first subset's dense rows
  /// (where SolveOptions::presolve allows it). Off: the dual simplex on the
  /// model as it is, and with presolve only if that does not end optimal.
  /// On a condensed restricted MILP CLP's presolve can cost far more than
  /// the simplex (docs/results.md, the ablations of the search). Either way
  /// the rows are those an LP optimum binds, and the result is exact
  /// whichever optimum it is (see above); but the optimum differs where the
  /// LP is degenerate, and so does the subset.
  bool presolve_lp_relaxation = true;
  /// That LP without the dense rows the column bounds imply (their activity
  /// over the bounds stays within the row's bounds: no point within the
  /// bounds breaks them, so the LP is the same). Why: CLP's presolve removes
  /// them one entry at a time from its column copy, slow on dense rows (on
  /// a restricted GEO week, the early window rows that the few free slots
  /// cannot move out of the box). They stay left out of the subsets and are
  /// checked like every left-out row. Off: every dense row in the first LP.
  bool skip_implied_rows_in_lp = true;
  /// Keep each subset incumbent that satisfies every row, as the solver
  /// reports it (SolveOptions::on_incumbent): a search that ends at a limit
  /// on a solution breaking a left-out row (or on none, or a worse one)
  /// then still returns the model's best solution found (status
  /// kFeasible). The rounds are solved as without it (the kept solution is
  /// no MIP start). Off: only a subset's final solution counts.
  bool keep_model_incumbents = true;

  bool IsValid(std::string* error) const;
};

struct LazyRowReport {
  bool used = false;     // false: the model was solved whole from the start
  int dense_rows = 0;    // rows that could be left out
  int implied_rows = 0;  // of those, left out of the first LP as implied (skip_implied_rows_in_lp)
  int initial_rows = 0;  // rows of the first subset
  int final_rows = 0;    // rows of the last subset
  int rounds = 0;        // subset solves
  /// The result is a model solution kept from a subset search that ended
  /// on one breaking a left-out row (LazyRowOptions::keep_model_incumbents).
  bool kept_incumbent = false;
  bool fell_back = false;  // max_rounds reached: the whole model was solved
};

/// The model with only the rows `rows` (ascending), names kept if present.
LpData SelectRows(const LpData& lp, const std::vector<int>& rows);

/// Solves `lp` as solver.Solve(lp, options) would, by row generation over its
/// dense rows. options.time_limit_s covers every solve; options.max_nodes
/// caps each one. options.initial_solution is handed to each subset solve
/// (it satisfies every subset if it satisfies the model). options.progress
/// hears the subset solves without their incumbents (which may break a
/// left-out row), then with new_incumbent for each solution of the model
/// (LazyRowOptions::keep_model_incumbents: as the subset search finds it;
/// otherwise once, at the end); options.on_incumbent likewise hears only
/// solutions of the model.
/// @throws std::invalid_argument as Solver::Solve, or for invalid `lazy`.
SolveResult SolveWithLazyRows(const Solver& solver, const LpData& lp, const SolveOptions& options,
                              const LazyRowOptions& lazy = {}, LazyRowReport* report = nullptr);

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_LAZY_ROWS_H_
