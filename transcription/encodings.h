// MILP encodings of the operational rules (operations.h) over a time grid.
//
// Variables: on[i][j] in {0,1}, thruster i on during interval j = [t_j, t_{j+1}).
// Two encodings accept exactly the same binary patterns (tested exhaustively
// against the independent checker) but differ in LP-relaxation strength:
//
//  kThesis  Gazzino (2018) sec. 4.2.1, (4.6)-(4.33), corrected as noted below and
//           generalised to non-uniform grids: gamma_j = sum_i on[i][j]
//           (the printed "Xi_1 F + gamma = 0" loses the minus sign);
//           minimum burn  on[l][a] - on[l][b] - gamma_{a-1} <= 0     (4.11)
//           same-thruster gap  on[l][a-1] - on[l][a] + on[l][b] <= 1 (4.16)
//           other-thruster gap on[l][a-1] - on[l][a] + gamma_b <= 1  ((4.19) corrected:
//           the printed gamma_j would forbid switching off) — the gamma forms are used
//           only where they are valid (K = 1, positive gap, gap window within the
//           same-thruster window), otherwise the pairwise per-thruster forms.
//  kTight   unit-commitment minimum up/down-time polytope (Rajan & Takriti 2005):
//           start v[i][j] and stop w[i][j] in [0,1] (continuous; integral once on is),
//           on[i][j] - on[i][j-1] = v - w,  sum_{a in up(b)} v[i][a] <= on[i][b],
//           sum_{a in down(b)} w[i][a] <= 1 - on[i][b], and an aggregated other-thruster
//           gap row  sum_{a in gap(b)} w[i][a] + sum_{l != i} v[l][b] <= 1  (K = 1).
//
// A duration T is applied at node a to the intervals b >= a with t_b < t_a + T:
// on a uniform grid that is ceil(T / dt) intervals (thesis (4.9)).
// Both encodings share the fixings derived from the boundary history,
// forced-off windows and disabled thrusters (column bounds, or rows that make
// the problem infeasible with a stated reason).
//
//   milp::Model model;
//   transcription::EncodingInput in{grid, rules, history, forced_off, enabled};
//   transcription::OperationalEncoding enc =
//       transcription::AddOperationalConstraints(&model, in, transcription::Encoding::kTight);
//   model.AddConstraint(milp::LinearExpr(enc.on[0][3]) == 1.0);
#ifndef THRUSTSCHED_TRANSCRIPTION_ENCODINGS_H_
#define THRUSTSCHED_TRANSCRIPTION_ENCODINGS_H_

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "milp/model.h"
#include "transcription/operations.h"

namespace thrustsched::transcription {

enum class Encoding { kThesis, kTight };
std::string_view ToString(Encoding encoding);
/// "thesis" | "tight". @throws std::invalid_argument listing the valid names.
Encoding ParseEncoding(std::string_view name);

struct EncodingInput {
  std::vector<double> grid;  // t_0 < ... < t_N
  OperationalRules rules;
  BoundaryHistory history;  // empty = all off, never fired
  std::vector<ForcedOff> forced_off;
  std::vector<bool> enabled;  // empty = all enabled; disabled = forced off
  int num_thrusters = 0;
  /// Add start indicators (for a per-start objective penalty) even if the
  /// encoding does not need them.
  bool need_starts = false;
};

/// Number of whole intervals a duration T spans from node a (smallest k with
/// t_{a+k} - t_a >= T - kTimeTolerance; N - a + 1 if the horizon is too short).
int IntervalsSpanning(const std::vector<double>& grid, int a, double duration_s);

struct OperationalEncoding {
  Encoding encoding = Encoding::kTight;
  int num_thrusters = 0;
  int num_intervals = 0;
  std::vector<std::vector<milp::Variable>> on;     // [i][j], binary
  std::vector<std::vector<milp::Variable>> start;  // [i][j], empty if not created
  std::vector<std::vector<milp::Variable>> stop;   // [i][j], tight only
  std::vector<milp::Variable> gamma;               // [j], thesis only
  std::vector<int> prev_on;                        // [i], 1 if on at t0 (history)
  /// Reasons the rules cannot be met whatever the dynamics (from the history,
  /// forced-off windows and horizon length); the model is then infeasible.
  std::vector<std::string> infeasibility_reasons;
  /// Effective durations on the grid (uniform grid: p, m, q of the thesis and
  /// the durations p*dt ...; non-uniform: the smallest and largest over nodes).
  int min_burn_intervals_min = 0, min_burn_intervals_max = 0;
  int min_off_same_intervals_min = 0, min_off_same_intervals_max = 0;
  int min_gap_other_intervals_min = 0, min_gap_other_intervals_max = 0;
  double effective_min_burn_s = 0, effective_min_off_same_s = 0, effective_min_gap_other_s = 0;

  /// Writes the canonical auxiliary values (start/stop/gamma) implied by the
  /// binary pattern `pattern` (num_thrusters x num_intervals, 0/1) into x,
  /// together with the pattern itself. They are the unique feasible values
  /// for start/stop/gamma (and the smallest for thesis start indicators), so
  /// `pattern` is accepted iff the rows hold at x. Used for MIP starts.
  void Complete(const Eigen::MatrixXi& pattern, Eigen::VectorXd* x) const;
  /// The on-off pattern (num_thrusters x num_intervals, 0/1) of a point of
  /// the MILP: slot (i, j) is on when on[i][j] > 0.5.
  Eigen::MatrixXi OnPattern(const Eigen::VectorXd& x) const;
};

/// Adds the on/off variables (named "<prefix>on[i][j]" etc.) and the rows of
/// the chosen encoding. @throws std::invalid_argument on invalid input
/// (rules, history, grid, forced-off thruster indices).
OperationalEncoding AddOperationalConstraints(milp::Model* model, const EncodingInput& input,
                                              Encoding encoding, std::string_view prefix = "");

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_ENCODINGS_H_
