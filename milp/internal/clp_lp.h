// CLP pieces shared by the CBC backend's translation units: the model in
// COIN-OR's arrays, LP solves, and turning candidate points into verified
// solutions (internal; COIN-OR types are only forward-declared here).
//
//   CoinArrays a = MakeArrays(lp, sign, /*round_integer_bounds=*/true);
//   SolveClock clock(options.time_limit_s, options.interrupt);
//   LpOutcome o = SolveLpCore(lp, a, options, &clock);
//   Eigen::VectorXd x = candidate;
//   if (Polish(lp, options, &x)) use(x);   // integers rounded, continuous re-optimised
#ifndef THRUSTSCHED_MILP_INTERNAL_CLP_LP_H_
#define THRUSTSCHED_MILP_INTERNAL_CLP_LP_H_

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "milp/internal/solve_clock.h"
#include "milp/lp_data.h"
#include "milp/solver.h"

class ClpSimplex;
class CoinMessageHandler;
class OsiClpSolverInterface;

namespace thrustsched::milp::internal {

/// Feasibility tolerance for accepting a point (MIP start, final solution).
inline constexpr double kFeasibilityTolerance = 1e-6;

/// The model in CBC's minimisation form: cost = sign * c, integer bounds
/// rounded inward (if asked), infinities as COIN_DBL_MAX.
struct CoinArrays {
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> a;
  std::vector<double> col_lower, col_upper, cost, row_lower, row_upper;
};
CoinArrays MakeArrays(const LpData& lp, double sign, bool round_integer_bounds);
void LoadClp(ClpSimplex* clp, const CoinArrays& arrays);
void LoadOsi(OsiClpSolverInterface* si, const CoinArrays& arrays, const LpData& lp);

/// A message handler that prints nothing (one per model: handlers keep buffers).
std::unique_ptr<CoinMessageHandler> MakeSilentHandler();
/// Silences clp at log_level 0 (handler must outlive clp's use of it).
void Silence(ClpSimplex* clp, CoinMessageHandler* handler, int log_level);

double ObjectiveSign(const LpData& lp);
bool IsInteger(const LpData& lp, int column);

/// Outcome of an LP solve with CLP, in CLP's minimisation form.
struct LpOutcome {
  SolveStatus status = SolveStatus::kError;
  std::string detail;
  double min_objective = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd x;
  Eigen::VectorXd duals;  // CLP row duals (minimisation form)
  long long iterations = 0;
};

/// Solves the continuous relaxation of `lp` (as given in `arrays`) with CLP:
/// presolve (if options.presolve), options.lp_algorithm, primal and dual
/// infeasibility told apart. Stops (status kNoSolutionFound) when
/// clock->ShouldStop().
LpOutcome SolveLpCore(const LpData& lp, const CoinArrays& arrays, const SolveOptions& options,
                      SolveClock* clock);

/// Rounds the integer entries of x and, if there are continuous columns,
/// re-optimises them with the integers fixed. Returns false if the result is
/// not feasible within kFeasibilityTolerance. Runs to the end whatever the
/// time limit: it finishes a solution already found (an LP with every
/// integer fixed, a small part of any solve).
bool Polish(const LpData& lp, const SolveOptions& options, Eigen::VectorXd* x);

/// Like Polish for a point whose entries may be NaN (columns CBC's
/// preprocessing removed): the known integer entries are fixed, an LP over the
/// rest gives the unknown ones, which are rounded, then Polish. Returns false
/// if no feasible point results.
bool CompletePartial(const LpData& lp, const SolveOptions& options, Eigen::VectorXd* x);

/// Models without rows or without columns (CBC cannot take them).
SolveResult SolveTrivial(const LpData& lp);

/// The CLP LP session of Solver::OpenLpSession: the first Solve with presolve
/// and dual simplex (or the interior point and its crossover), or by the
/// crossover from a given point (CrossOverFrom), later ones by dual simplex
/// from the last basis.
std::unique_ptr<LpSession> OpenClpSession(const LpData& lp, const SolveOptions& options);

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_CLP_LP_H_
