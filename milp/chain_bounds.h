// Bounds on the columns of a chain of equality rows (a discretised linear
// system written as x_{j+1} = P_j x_j + G_j u_j + d_j), implied by the
// bounds of the chain's first block and of the other columns of its rows.
//
//   milp::EqualityChain chain;
//   chain.blocks = {{x0a, x0b}, {x1a, x1b}, {x2a, x2b}};   // column indices
//   chain.rows = {{r0a, r0b}, {r1a, r1b}};   // rows[j][k] defines blocks[j+1][k]
//   milp::TightenToChainBounds(&lp, chain);  // free x1, x2 now boxed (widened)
//
// Contract: rows[j][k] is an equality row of `lp` whose columns are
// blocks[j+1][k] (nonzero coefficient), columns of blocks[j], and any other
// columns ("inputs", e.g. binaries) that belong to no block; then
//   x_{j+1,k} = (b - sum a_c x_{j,c} - sum a_i u_i) / a_lead,
// and by superposition each x_{j,k} is the free response (every input at its
// lower bound) plus one term per earlier input, linear in that input. Its
// bound is the sum of each term's extreme over the input's range (and over
// the first block's range): the exact range of x_{j,k} over the box of the
// inputs, in exact arithmetic, so every point that satisfies the chain's rows
// and the inputs' bounds (in particular every point of the LP relaxation)
// satisfies the bounds, and adding them changes neither the LP's nor the
// MILP's feasible set. A column that an unbounded input reaches stays
// unbounded on that side.
//
// Why: a solver's bound propagation over such a chain of free columns works
// in interval arithmetic, whose widths multiply by |P| at every step (the
// wrapping effect) and can grow to 1e20 and beyond: GLPK 5.0's node
// preprocessing (glpios02.c), which glpsol cannot switch off, sets those
// widths as column bounds, and its dual simplex then declares feasible
// subproblems infeasible. With bounds of the order of the reachable range,
// propagation only tightens what is already moderate.
//
// Cost: O(N^2 n^2 m) for N steps, n components and m inputs per step (well
// under a second for a week of 5-minute steps).
#ifndef THRUSTSCHED_MILP_CHAIN_BOUNDS_H_
#define THRUSTSCHED_MILP_CHAIN_BOUNDS_H_

#include <vector>

#include <Eigen/Core>

#include "milp/lp_data.h"

namespace thrustsched::milp {

struct EqualityChain {
  /// blocks[j]: the columns of node j; every block has the same size n.
  std::vector<std::vector<int>> blocks;
  /// rows[j][k]: the equality row that defines blocks[j+1][k];
  /// rows.size() == blocks.size() - 1.
  std::vector<std::vector<int>> rows;
};

struct ChainBounds {
  /// [j](k): the implied bound of blocks[j][k]; block 0 holds its own
  /// column bounds. +-kInfinity where an unbounded input reaches.
  std::vector<Eigen::VectorXd> lower, upper;
};

/// Relative (and absolute, for values below 1) widening of every implied
/// bound, far above the rounding of the superposition sums (~1e-13) and far
/// below anything a solver's tolerances resolve.
inline constexpr double kChainBoundPadding = 1e-7;

/// The implied bounds, widened by kChainBoundPadding.
/// @throws std::invalid_argument if the chain does not have the structure
/// of the contract (sizes, a row that is not an equality, a block column
/// missing from its row, a column of another block in a row), naming the row.
ChainBounds ChainImpliedBounds(const LpData& lp, const EqualityChain& chain);

/// How far TightenToChainBounds sets a bound beyond the implied range
/// [L, U]: widen_fraction (U - L) + 1e-3 (1 + max(|L|, |U|)) on each side.
/// Exact bounds bind in the LP relaxation (a state at the extreme of its
/// reachable range is a vertex of both), which changes the simplex path and
/// the branching, and made glpsol's tree on the double integrator export
/// more than twice as large as with free states (data/scenarios/README.md,
/// section 7). Widened bounds lie strictly outside every point of the LP
/// relaxation, never bind, and still keep a solver's propagation within a
/// few times the reachable range.
inline constexpr double kChainBoundWidening = 0.5;

/// Intersects the bounds of the chain's continuous columns with
/// ChainImpliedBounds widened by widen_fraction (kChainBoundWidening); a
/// column whose own bounds do not meet them (a model that is infeasible
/// anyway, e.g. an unreachable fixed terminal state) keeps its own.
/// @throws as ChainImpliedBounds; std::invalid_argument if widen_fraction is
/// negative or not finite.
void TightenToChainBounds(LpData* lp, const EqualityChain& chain,
                          double widen_fraction = kChainBoundWidening);

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_CHAIN_BOUNDS_H_
