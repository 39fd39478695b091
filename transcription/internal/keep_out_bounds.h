// Bounds on the primary's reachable positions, from which the keep-out big-M
// and its pruning are derived (transcription/keep_out.h):
//
//   - the effect of every thrust column on a linear map of the state at a
//     time (a backward sweep of the MILP's own transition maps);
//   - the exact range of a^T (sum of effects) over {sum cost_c v_c <= B,
//     0 <= v_c <= ub_c} (a fractional knapsack, solved by sorting);
//   - optionally, the range over that set intersected with the terminal
//     constraint (fixed state or state box), by one small LP per question
//     (thrust columns only, a row per terminal component and the budget row):
//     tighter, since whatever moves the primary away must bring it back.
//
//   internal::ThrustBounds b = internal::ReadBounds(cols, model);
//   auto effects = internal::Effects(problem, discrete, kick, map, position, cols, b);
//   auto [low, high] = internal::KnapsackRange(effects, a, budget);
//   internal::ReachLp lp(problem, discrete, kick, cols, b, budget, solver);
//   auto [low2, high2] = lp.Range(effects, a);     // within [low, high]
#ifndef THRUSTSCHED_TRANSCRIPTION_INTERNAL_KEEP_OUT_BOUNDS_H_
#define THRUSTSCHED_TRANSCRIPTION_INTERNAL_KEEP_OUT_BOUNDS_H_

#include <utility>
#include <vector>

#include <Eigen/Core>

#include "dynamics/discretisation.h"
#include "milp/lp_data.h"
#include "milp/model.h"
#include "milp/solver.h"
#include "transcription/keep_out.h"
#include "transcription/partial_maps.h"
#include "transcription/problem.h"

namespace thrustsched::transcription::internal {

/// One thrust column: its objective cost, upper bound, and effect on a
/// linear map of the state (per unit of the column).
struct Effect {
  int column;
  double cost;
  double upper;
  Eigen::VectorXd e;
};

/// Costs and upper bounds of the thrust columns, [thruster][interval or node].
struct ThrustBounds {
  std::vector<std::vector<double>> cost, upper;
};
ThrustBounds ReadBounds(const KeepOutColumns& cols, const milp::Model& model);

/// Effects of every thrust column applied at or before `at.t` on map * x(at.t)
/// (map: rows x n). `kick[j]` = B(t_j) D (impulsive mode, n x m per node).
std::vector<Effect> Effects(const ScheduleProblem& p, const dynamics::DiscreteModel& d,
                            const std::vector<Eigen::MatrixXd>& kick, const PartialMap& at,
                            const Eigen::MatrixXd& map, const KeepOutColumns& cols,
                            const ThrustBounds& b);

/// Lowest and highest a^T sum_c e_c v_c over the budget and bounds (exact).
std::pair<double, double> KnapsackRange(const std::vector<Effect>& effects,
                                        const Eigen::VectorXd& a, double budget);

/// The same with the terminal constraint of a fixed-state or state-box
/// problem added (other terminal kinds: none, a valid relaxation), by LP.
class ReachLp {
 public:
  ReachLp(const ScheduleProblem& p, const dynamics::DiscreteModel& d,
          const std::vector<Eigen::MatrixXd>& kick, const KeepOutColumns& cols,
          const ThrustBounds& b, double budget, const milp::Solver& solver);
  /// {low, high}; {-inf, inf} where an LP does not end optimal (no tightening).
  std::pair<double, double> Range(const std::vector<Effect>& effects,
                                  const Eigen::VectorXd& a) const;

 private:
  const milp::Solver& solver_;
  milp::LpData lp_;
  std::vector<int> lp_column_;  // model column -> LP column (-1: none)
};

}  // namespace thrustsched::transcription::internal

#endif  // THRUSTSCHED_TRANSCRIPTION_INTERNAL_KEEP_OUT_BOUNDS_H_
