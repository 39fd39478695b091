// Keep-out rows of a conjunction (Serra 2015, Problem 10): at every check
// time t_k, "outside at least one face j of the polytope, with margin":
//
//   a_j^T r_p(t_k) + M_kj w_kj >= b_j + c_kj + a_j^T r_s(t_k),    sum_j w_kj <= |F_k| - 1,
//
// with r_p the primary's planned position (affine in the MILP's columns
// through the state at the start of the grid interval), r_s the secondary's
// mean position and c_kj the margin of transcription/conjunction_geometry.h.
//
// Big-M from bounds, not a guess. The objective is bounded by the
// conjunction's cost budget B (one row "objective <= B") and every thrust
// column by its own bounds, so the primary's reachable positions are bounded:
// the lowest value of a_j^T r_p(t_k) over {sum_c cost_c v_c <= B, 0 <= v_c <=
// ub_c} (a fractional knapsack, solved exactly by sorting) is L_kj, and
// M_kj = rhs_kj - L_kj (plus 1e-9 relative) can never be too small. The same
// bounds simplify the disjunction before any binary is made:
//   - a face that holds for every reachable position (L_kj >= rhs_kj): the
//     check is clear, no row at all;
//   - a face that no reachable position satisfies (upper bound < rhs): dropped;
//   - a single face left: one row, no binary; none left: infeasible, with
//     the check time as the reason.
// With a `bound_solver`, the faces the knapsack leaves undecided get the
// range of a^T r_p(t_k) over the budget, the bounds AND the terminal
// constraint (fixed state or state box), one small LP each (thrust columns
// only): what moves the primary away must bring it back, so M roughly halves
// and more faces are decided (transcription/internal/keep_out_bounds.h).
// A hard window bounds the along-track and normal positions exactly at the
// grid nodes where it is enforced; checks placed on those nodes use it too.
// Rows are in metres divided by their largest coefficient (M included).
//
//   KeepOutColumns cols{...};                 // filled by ScheduleMilp
//   KeepOutStats s = AddKeepOut(problem, discrete, options, cols, &model);
//   std::cout << s.num_binaries << " binaries, M in [" << s.big_m_min_m << ", "
//             << s.big_m_max_m << "] m\n";
#ifndef THRUSTSCHED_TRANSCRIPTION_KEEP_OUT_H_
#define THRUSTSCHED_TRANSCRIPTION_KEEP_OUT_H_

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/discretisation.h"
#include "milp/model.h"
#include "milp/solver.h"
#include "transcription/problem.h"

namespace thrustsched::transcription {

/// The transcription's columns the keep-out rows are written on.
struct KeepOutColumns {
  std::vector<std::vector<milp::Variable>> state;  // [node][component], x = scale .* column
  Eigen::VectorXd scale;
  /// [thruster][interval] on-off binaries, or [thruster][node] impulses (m/s).
  std::vector<std::vector<milp::Variable>> thrust;
  bool impulsive = false;
};

/// The rows and binaries of one check time with a disjunction (for MIP
/// starts and heuristics): face j is enforced where binaries[j] is 0.
struct KeepOutGroup {
  double t = 0.0;
  std::vector<int> faces;            // polytope face of each row
  std::vector<int> rows;             // row index in the model
  std::vector<int> binaries;         // column index of w (-1: single face, no binary)
  std::vector<double> free_slack_m;  // a_j^T r_p - rhs_j along the thrust-free path (m)
  std::vector<double> row_scale;     // the row is (its value in metres) times this
};

struct KeepOutStats {
  int num_checks = 0;
  int checks_clear = 0;        // a face holds for every reachable position: no row
  int checks_single_face = 0;  // one possible face: one row, no binary
  int checks_with_binaries = 0;
  int faces_impossible = 0;  // faces no reachable position satisfies (dropped)
  int num_binaries = 0;
  int num_rows = 0;  // keep-out rows (the budget row not counted)
  double big_m_min_m = std::numeric_limits<double>::quiet_NaN();
  double big_m_median_m = std::numeric_limits<double>::quiet_NaN();
  double big_m_max_m = std::numeric_limits<double>::quiet_NaN();
  double cost_budget = std::numeric_limits<double>::infinity();  // inf: no budget row
  double threshold = 0.0;                                        // eps'
  double quantile = 0.0;                                         // Phi^-1(1 - eps')
  double margin_max_m = 0.0;                                     // largest c_kj
  double covariance_min_eigenvalue = 0.0;  // as given, before any repair (m^2, EffectiveCovariance)
  bool covariance_repaired = false;
  std::vector<std::string> infeasibility_reasons;
  /// Index of the first keep-out binary column: every column before it is
  /// the transcription's own (the same in every build of the problem).
  int first_binary_column = -1;
  std::vector<KeepOutGroup> groups;
};

/// Sets the keep-out binaries of a full column vector whose other columns
/// hold a plan: at each check the face with the largest slack (scaled row
/// activity minus its lower bound) is enforced (w = 0), the others relaxed.
/// @throws std::invalid_argument if x does not have lp.num_cols() entries.
void CompleteKeepOut(const milp::LpData& lp, const KeepOutStats& stats, Eigen::VectorXd* x);

/// Adds the budget row, the binaries and the keep-out rows for
/// problem.conjunction to `model`, whose objective must already be set.
/// @throws std::invalid_argument if the conjunction is missing or invalid,
///         the geometry cannot be computed (see ComputeConjunctionGeometry),
///         or no finite big-M exists (an unbounded thrust column and no
///         cost_budget; the message says which field to set).
KeepOutStats AddKeepOut(const ScheduleProblem& problem, const dynamics::DiscreteModel& discrete,
                        const dynamics::DiscretizationOptions& options,
                        const KeepOutColumns& columns, milp::Model* model,
                        const milp::Solver* bound_solver = nullptr);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_KEEP_OUT_H_
