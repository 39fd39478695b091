// ScheduleProblem: everything that defines a minimum-fuel on-off scheduling
// problem, independent of how it is transcribed (formulation, encoding,
// discretisation scheme are BuildOptions in transcription/schedule_milp.h).
//
//   auto hcw = std::make_shared<dynamics::HcwModel>(7.2921159e-5);
//   transcription::ScheduleProblem p;
//   p.model = hcw;
//   p.thrusters = dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005);
//   p.grid = dynamics::UniformGrid(0, 86400, 288);            // 5-min intervals
//   p.initial_state = (Eigen::VectorXd(6) << 1000, 0, 0, 0, 0, 0).finished();
//   p.rules.min_burn_s = 300; p.rules.min_off_same_s = 1200; p.rules.min_gap_other_s = 300;
//   p.window.outputs = {1, 2};  p.window.half_widths = {36800, 36800};   // y, z in m
//   p.objective.kind = transcription::ObjectiveKind::kL1;
//
// Units are SI at this API (states and outputs in the model's units: m, m/s,
// rad). Times are seconds since the model epoch; the horizon is [grid.front(),
// grid.back()].
#ifndef THRUSTSCHED_TRANSCRIPTION_PROBLEM_H_
#define THRUSTSCHED_TRANSCRIPTION_PROBLEM_H_

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "dynamics/linear_model.h"
#include "dynamics/thrusters.h"
#include "transcription/conjunction.h"
#include "transcription/operations.h"

namespace thrustsched::transcription {

/// Box on model outputs at grid nodes: |y_k(t_j)| <= half_widths[k] for the
/// nodes j >= 1 with t_j >= enforce_from_s (the initial node is data, not a
/// decision, so it is never constrained; the checker still reports it).
struct WindowSpec {
  std::vector<int> outputs;         // indices into the model outputs
  std::vector<double> half_widths;  // > 0, output units (m or rad)
  double enforce_from_s = -std::numeric_limits<double>::infinity();
  /// Soft window: violations allowed at a cost of `soft_penalty` objective
  /// units per (violation / half_width) per node and output.
  bool soft = false;
  double soft_penalty = 1e3;
  /// Extra constrained points strictly inside each interval (0 = nodes only).
  int intersample_points = 0;
  /// Planning margin, a fraction in [0, 1): the MILP keeps the outputs within
  /// (1 - margin) x half_widths (and the terminal sets within that), so that
  /// what it does not model (motion between nodes, linearisation error) has
  /// room; the checker still judges the full half_widths.
  double margin = 0.0;

  bool enabled() const { return !outputs.empty(); }
};

enum class TerminalKind {
  kFree,                // no terminal constraint
  kFixedState,          // x_N == target
  kStateBox,            // |x_N - target| <= tolerance componentwise (inf = free)
  kStationKeepingSets,  // thesis ch. 5 end-of-horizon polytopes (corrected)
};

struct TerminalSpec {
  TerminalKind kind = TerminalKind::kFree;
  Eigen::VectorXd target;     // model state units
  Eigen::VectorXd tolerance;  // kStateBox
  // kStationKeepingSets: facets of the inner polygons of the out-of-plane
  // disk and of the two in-plane cones (thesis K_z, K_xy+, K_xy-), and the
  // look-ahead times (s after t_N) at which the drifting in-plane ellipse must
  // fit the window (the set is convex in t, so {0, T} covers [0, T]). Empty
  // lookahead = {0, horizon length}. The window half-width used is
  // (1 - margin) times the window's.
  int facets_out_of_plane = 16;
  int facets_cone_plus = 16;
  int facets_cone_minus = 16;
  std::vector<double> lookahead_s;
  double margin = 0.0;
};

enum class ObjectiveKind {
  kL1,          // thesis metric: sum_i ||Gamma_i||_1 * on-time (m/s)
  kDeltaV,      // Euclidean: (F/m) * on-time (m/s)
  kPropellant,  // F / (g0 Isp) * on-time (kg)
};
std::string_view ToString(ObjectiveKind kind);
ObjectiveKind ParseObjectiveKind(std::string_view name);  // "l1" | "delta_v" | "propellant"

struct ObjectiveSpec {
  ObjectiveKind kind = ObjectiveKind::kL1;
  double burn_start_penalty = 0.0;  // objective units per burn start
};

enum class InputMode {
  kOnOff,      // one binary per thruster and interval, full thrust when on
  kImpulsive,  // continuous delta-v >= 0 per thruster at nodes 0..N (L1 cost), no binaries
};

/// A linear constraint on the state at one time inside the horizon (a path
/// constraint): lower <= a^T x(t_s) <= upper, x(t_s) the model state (model
/// units) with the plan's thrust, between nodes held as the on-off input is.
/// Serves keep-out against a known trajectory (a fleet member planned before,
/// one face of its keep-out cube per check), corridors, any affine state
/// bound at chosen times. On-off input mode only.
///
///   p.state_constraints.push_back({3600.0, a, 5000.0 + a.dot(other), kInf, "clear_q12"});
struct StateConstraint {
  double t_s = 0.0;   // seconds since the model epoch, inside [grid.front(), grid.back()]
  Eigen::VectorXd a;  // one coefficient per state component (per model unit)
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  std::string name;  // its row is "state_<name>" in exported models; empty: "state_<index>"
};

struct ScheduleProblem {
  std::shared_ptr<const dynamics::LinearModel> model;
  dynamics::ThrusterSet thrusters;
  std::vector<double> grid;       // t_0 < ... < t_N (s since model epoch)
  Eigen::VectorXd initial_state;  // x(t_0), model state units
  OperationalRules rules;
  BoundaryHistory history;  // empty vectors = all off, never fired
  std::vector<ForcedOff> forced_off;
  WindowSpec window;
  TerminalSpec terminal;
  ObjectiveSpec objective;
  InputMode input_mode = InputMode::kOnOff;
  /// Impulsive mode: largest delta-v per thruster and node (m/s).
  double max_impulse_m_s = std::numeric_limits<double>::infinity();
  /// Impulsive mode, optional: per-thruster bounds (m/s, one per thruster),
  /// e.g. per-axis bounds with the ideal six thrusters; overrides
  /// max_impulse_m_s where given. Empty: max_impulse_m_s for all.
  std::vector<double> max_impulse_per_thruster_m_s;
  /// A secondary object to keep out of (chance-constrained keep-out rows,
  /// transcription/keep_out.h); sparse formulation only.
  std::optional<ConjunctionSpec> conjunction;
  /// Path constraints on the state (StateConstraint), any order.
  std::vector<StateConstraint> state_constraints;

  /// Upper bound of thruster i's impulses (impulsive mode, m/s).
  double MaxImpulse(int thruster) const {
    return max_impulse_per_thruster_m_s.empty() ? max_impulse_m_s
                                                : max_impulse_per_thruster_m_s[thruster];
  }

  int num_intervals() const { return static_cast<int>(grid.size()) - 1; }
  double horizon_s() const { return grid.back() - grid.front(); }
  /// Checks sizes, finiteness, signs, rules, history, window and terminal
  /// data; fills *error naming the field and the value.
  bool IsValid(std::string* error) const;
};

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_PROBLEM_H_
