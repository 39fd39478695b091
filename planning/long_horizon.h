// Long-horizon GEO station keeping (thesis ch. 5): a chain of short-horizon
// MILPs (one per cycle, e.g. a week) closed through the nonlinear simulation
// model. Each cycle
//  1. takes the true state (ECI, from the nonlinear model) at the cycle start
//     t_k and converts it to the relative state of GeoLinearModel, which is
//     linearised about the station point for this cycle's own dates (the
//     model is valid at any absolute t, so the cycle grid [t_k, t_k + T] is
//     discretised as is);
//  2. builds the ScheduleProblem of the cycle: grid [t_k, t_k + T] at the
//     step, the operational history carried from the previous cycles, the
//     thrusters that are failed or switched off (outages) forced off, and in
//     fixed mode the end-of-horizon station-keeping sets (corrected polytopes,
//     TerminalKind::kStationKeepingSets);
//  3. solves it (milp::SolveOptions: time limit and gap per attempt); if the
//     cycle is infeasible or no schedule is found in time it falls back,
//     recording what happened: (1) soft window with a penalty, (2) soft window
//     and free terminal, (3) zero thrust for the cycle;
//  4. replays the applied part of the schedule through dynamics::GeoSimulator
//     from the true ECI state, with exact switch times, measuring max |lat|,
//     max |lon - station| and the time outside the window (the checker's
//     definitions, in degrees), and hands the end state and the thrusters'
//     last switch-off times to the next cycle.
// Modes:
//  kFixed     prediction = control = cycle_s; every burn ends inside its
//             cycle (allow_burn_across_end is forced false), so the history
//             is "thruster i last switched off at e_i" and the next cycle
//             sees off_for_s = t_k - e_i (same-thruster and other-thruster
//             gaps are enforced across the boundary).
//  kReceding  prediction cycle_s, only [t_k, t_k + control_s) is applied, the
//             next cycle starts at t_k + control_s (thesis sec. 5.4: 7 d and
//             3.5 d, no terminal sets). A burn may not cross the control
//             boundary: one row on[i][c-1] + on[i][c] <= 1 per thruster at the
//             boundary node c (so every applied burn is complete and has its
//             minimum duration; the history is the same as in fixed mode). The
//             thesis is silent here; carrying a cut burn as on_for_s would
//             also be possible but would make the applied part depend on a
//             plan that is then discarded.
// Uncontrollability: if the thrusters available during a cycle (enabled and
// not under an outage) cannot push both ways along the orbit normal, or both
// ways along-track, the inclination or the longitude drift cannot be
// corrected: the cycle is marked "uncontrollable: ..." and solved best effort
// (soft window, free terminal; zero thrust if even that fails), not reported
// as a solver error. Radial thrust is not required (the eccentricity can be
// controlled along-track).
//
//   auto geo = std::make_shared<dynamics::GeoLinearModel>(dynamics::GeoModelOptions{});
//   auto sim = std::make_shared<dynamics::GeoSimulator>(dynamics::GeoModelOptions{});
//   transcription::ScheduleProblem base;        // model, thrusters, rules, window, objective
//   base.model = geo;  base.thrusters = dynamics::ThrusterSet::Anzel4(0.265, 4850, 2005);
//   ...
//   planning::LongHorizonOptions o;
//   o.duration_s = 365 * 86400.0;  o.cycle_s = 7 * 86400.0;  o.step_s = 300;
//   o.terminal.kind = transcription::TerminalKind::kStationKeepingSets;
//   o.solve.milp.time_limit_s = 30;  o.solve.milp.relative_gap = 0.01;
//   planning::LongHorizonSimulation run(base, o, sim, milp::MakeCbcSolver());
//   planning::LongHorizonState state = run.InitialState();
//   std::vector<planning::CycleRecord> cycles;
//   while (state.next_cycle < run.num_cycles()) cycles.push_back(run.RunCycle(&state));
//   planning::LongHorizonSummary year = planning::Summarize(cycles, base.thrusters);
//
// Determinism: with threads = 1, cycles that reach the requested gap (or
// prove optimality) before the time limit give the same schedules on every
// run, so a run resumed from a LongHorizonState equals an uninterrupted one.
// A cycle stopped by the wall-clock time limit may differ between runs; set
// milp::SolveOptions::max_nodes for a node budget instead (deterministic).
// Units: SI; times are seconds since the model epoch; angles reported in deg.
#ifndef THRUSTSCHED_PLANNING_LONG_HORIZON_H_
#define THRUSTSCHED_PLANNING_LONG_HORIZON_H_

#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "dynamics/geo_simulator.h"
#include "dynamics/thrusters.h"
#include "milp/solver.h"
#include "transcription/problem.h"
#include "transcription/solve.h"

namespace thrustsched::transcription {
class ScheduleMilp;
}  // namespace thrustsched::transcription

namespace thrustsched::planning {

// The one-MILP vocabulary this loop plans with (transcription/).
using transcription::Burn;
using transcription::ScheduleMilp;
using transcription::ScheduleProblem;
using transcription::ScheduleResult;
using transcription::SolveScheduleOptions;
using transcription::TerminalKind;
using transcription::TerminalSpec;

enum class HorizonMode { kFixed, kReceding };
std::string_view ToString(HorizonMode mode);
/// "fixed" | "receding". @throws std::invalid_argument listing the names.
HorizonMode ParseHorizonMode(std::string_view name);

/// What a cycle had to do to get a schedule (in order of escalation).
enum class Fallback {
  kNone,                    // the nominal problem was solved
  kSoftWindow,              // window violations allowed at a penalty
  kSoftWindowFreeTerminal,  // ... and no end-of-horizon set
  kZeroThrust,              // no schedule at all: the cycle drifts freely
};
/// "none" | "soft_window" | "soft_window_free_terminal" | "zero_thrust".
std::string_view ToString(Fallback fallback);
/// @throws std::invalid_argument listing the names.
Fallback ParseFallback(std::string_view name);

/// Thruster `thruster` unavailable on [from_s, until_s) (a failure from a date
/// on, or a thruster switched off because its opposite failed).
struct ThrusterOutage {
  int thruster = -1;
  double from_s = 0.0;
  double until_s = std::numeric_limits<double>::infinity();
};

/// The thruster diametrically opposite to `thruster` on the spacecraft (thesis
/// sec. 5.3.7: NE <-> SW, SE <-> NW): the one whose along-track and normal
/// direction components are the negatives of this one's (to 1e-6); among
/// several, the one whose radial component is most nearly reversed (ideal6:
/// +R <-> -R, +T <-> -T, +N <-> -N).
/// @throws std::invalid_argument if the index is out of range or no thruster matches.
int OppositeThruster(const dynamics::ThrusterSet& thrusters, int thruster);

/// Station-keeping faces of a thruster from its direction d (RTN, pushing
/// along d): a thruster sits on the face opposite to its push, so "north"
/// means d_N < 0 (pushes south), "south" d_N > 0, "east" d_T < 0 (pushes
/// west: T points east on a prograde GEO orbit), "west" d_T > 0 (|d| > 1e-6
/// counts). For the Anzel set: north = NE + NW, south = SE + SW, east = NE + SE,
/// west = NW + SW (thesis Table 5.7); for ideal6: north = -N, south = +N,
/// east = -T, west = +T.
struct ThrusterFaces {
  bool north = false, south = false, east = false, west = false;
};
ThrusterFaces FacesOf(const dynamics::Thruster& thruster);

/// Controllability criterion above: some available thruster with d_N > 1e-6
/// and one with d_N < -1e-6, and likewise along-track. `available` has one
/// entry per thruster. Empty reason when controllable, else "uncontrollable:
/// no available thruster pushes south (-N); available: SE, SW".
struct Controllability {
  bool controllable = true;
  std::string reason;
};
Controllability CheckControllability(const dynamics::ThrusterSet& thrusters,
                                     const std::vector<bool>& available);

struct LongHorizonOptions {
  double start_s = 0.0;     // start of the first cycle (s since the model epoch)
  double duration_s = 0.0;  // simulated time (> 0); the run ends at start_s + duration_s
  double cycle_s = 0.0;     // prediction horizon of every MILP (> 0)
  HorizonMode mode = HorizonMode::kFixed;
  /// Receding: applied part of each cycle, 0 < control_s < cycle_s. Fixed:
  /// ignored (= cycle_s). The last cycle is shortened to end at the run end
  /// (fixed: its whole grid; receding: its applied part).
  double control_s = 0.0;
  double step_s = 0.0;  // grid step; must divide cycle_s, control_s and duration_s
  /// End-of-horizon constraint in fixed mode (typically kStationKeepingSets);
  /// receding mode drops it (thesis) unless terminal_in_receding.
  TerminalSpec terminal;
  bool terminal_in_receding = false;
  std::vector<ThrusterOutage> outages;
  /// Build, solve (time_limit_s, relative_gap per attempt; interrupt), check.
  /// The check (operational rules and linear re-propagation of the whole
  /// prediction) runs unless check_schedule is false; options.check.nonlinear
  /// must be null (the replay is done here, from the true state).
  SolveScheduleOptions solve;
  /// Penalty of the soft-window fallbacks (objective units per (violation /
  /// half width) per node and output).
  double soft_penalty = 1e3;
  /// Nonlinear replay samples per grid step (>= 1): the time outside the
  /// window and the max |lat|, |lon| are measured on them.
  int replay_samples_per_step = 2;
  /// Improvement passes: a nominal schedule accepted with a relative gap
  /// above improve_above_gap (typically after a node limit, with a poor first
  /// incumbent) is improved (1) by the same MILP from it (MIP start) with a
  /// budget of improve_max_nodes nodes, then, if the gap is still above, (2)
  /// by the elastic (soft-window) version of the MILP solved cold with the
  /// cycle's node budget. The elastic problem is a relaxation: a schedule of
  /// it with no window violation is a schedule of the cycle, and is kept if
  /// cheaper (its bound is valid too). Node budgets keep it deterministic. Off
  /// if improve_above_gap <= 0 or improve_max_nodes <= 0; improve_max_nodes < 0
  /// means 5 x the cycle's max_nodes (off when that is unlimited).
  double improve_above_gap = 0.1;
  long long improve_max_nodes = -1;
  /// Second CBC configuration for the hard weeks: with solve.presolve on, (a)
  /// a nominal attempt stopped by a limit without a schedule is solved again
  /// with CBC's preprocessing and presolve off (same limits) before the
  /// soft-window fallback, and (b) after the improvement passes a schedule
  /// still above improve_above_gap gets a third pass: the nominal MILP with
  /// preprocessing and presolve off, cold, with the cycle's node budget; kept if
  /// cheaper. A schedule accepted from (a) gets its improvement passes with
  /// preprocessing and presolve off too. Measured on the six-thruster year
  /// (2034, one thruster per face, 100 nodes per cycle): weeks that ended at
  /// 3.25 m/s (soft-window fallback) and 5.49 m/s (gap 94 %) cost 0.36 and
  /// 0.38 m/s this way. Off by default: the published year results
  /// (docs/year_results.md) were run without it.
  bool retry_without_preprocessing = false;

  int num_cycles() const;  // 0 if the options are invalid
  /// Checks signs, finiteness and divisibility; fills *error naming the field.
  bool IsValid(std::string* error) const;
};

/// One attempt to solve a cycle.
struct CycleAttempt {
  Fallback level = Fallback::kNone;
  milp::SolveStatus status = milp::SolveStatus::kError;
  double solve_seconds = 0.0;
  std::string detail;  // solver detail, exception text or reasons
};

/// Everything that happened in one cycle.
struct CycleRecord {
  int index = 0;
  double start_s = 0.0;
  double applied_end_s = 0.0;     // next cycle's start
  double prediction_end_s = 0.0;  // end of the MILP grid
  Fallback fallback = Fallback::kNone;
  std::vector<CycleAttempt> attempts;
  milp::SolveStatus status = milp::SolveStatus::kError;         // of the accepted attempt
  double objective = std::numeric_limits<double>::quiet_NaN();  // accepted MILP
  double best_bound = std::numeric_limits<double>::quiet_NaN();
  double gap = std::numeric_limits<double>::quiet_NaN();
  long long nodes = 0;
  double solve_seconds = 0.0;                                                // all attempts
  double first_solution_seconds = std::numeric_limits<double>::quiet_NaN();  // accepted attempt
  double build_seconds = 0.0;  // discretise + build, all attempts
  double check_seconds = 0.0;
  double replay_seconds = 0.0;
  double wall_seconds = 0.0;  // the whole cycle
  double cpu_seconds = 0.0;   // process CPU time of the cycle (load-independent)
  bool controllable = true;
  std::string note;  // "uncontrollable: ...", reasons, failures

  // Applied schedule (burns inside [start_s, applied_end_s)) and its totals.
  std::vector<Burn> burns;
  int planned_burns = 0;  // in the whole prediction
  double consumption_l1_m_s = 0.0;
  double delta_v_m_s = 0.0;
  double propellant_kg = 0.0;
  double normal_delta_v_m_s = 0.0;  // sum |a_N| x duration
  std::vector<double> on_time_s;    // per thruster

  // Check of the accepted plan on the synthesis model (whole prediction).
  bool checked = false;
  bool rules_ok = true;
  double linear_window_violation_deg = std::numeric_limits<double>::quiet_NaN();  // nodes
  double soft_violation_deg = 0.0;  // soft fallbacks: largest planned violation at nodes

  // Nonlinear replay of the applied part, from the true state.
  double max_abs_lat_deg = 0.0;
  double max_abs_lon_deg = 0.0;
  double max_window_violation_deg = 0.0;  // max(|lat|, |lon|) - half width, 0 if inside
  double worst_time_s = std::numeric_limits<double>::quiet_NaN();
  double time_outside_window_s = 0.0;  // trapezoid rule on the samples (as the checker)
  /// Largest |linear plan - nonlinear replay| of lat and lon at grid nodes of
  /// the applied part (deg): the synthesis-model error over the cycle.
  double prediction_error_deg = 0.0;

  dynamics::Vector6d eci_start = dynamics::Vector6d::Zero();
  dynamics::Vector6d eci_end = dynamics::Vector6d::Zero();
  Eigen::VectorXd initial_state;  // relative state at start_s
  Eigen::VectorXd final_state;    // relative state at applied_end_s (replay)

  /// Replay samples (not needed for resuming): times, outputs [dr_m, lat_rad,
  /// lon_rad] and relative states [da_m, ex, ey, ix, iy, dl_rad].
  std::vector<double> sample_times;
  std::vector<Eigen::Vector3d> sample_outputs;
  std::vector<Eigen::VectorXd> sample_states;

  /// The interrupt flag was raised: the cycle is incomplete, the state was not advanced.
  bool interrupted = false;
};

/// What a run needs to continue at cycle next_cycle (and nothing else: the
/// cycle records are the caller's).
struct LongHorizonState {
  int next_cycle = 0;
  double time_s = 0.0;                                  // start of cycle next_cycle
  dynamics::Vector6d eci = dynamics::Vector6d::Zero();  // true state at time_s
  /// Per thruster: end of its last burn (s), -inf if it never fired.
  std::vector<double> last_burn_end_s;
};

/// Per-cycle statistics of a run.
struct Distribution {
  double median = std::numeric_limits<double>::quiet_NaN();
  double p90 = std::numeric_limits<double>::quiet_NaN();  // nearest rank
  double max = std::numeric_limits<double>::quiet_NaN();
  double mean = std::numeric_limits<double>::quiet_NaN();
  int count = 0;  // finite values used
};
Distribution Distribute(std::vector<double> values);

struct LongHorizonSummary {
  int cycles = 0;
  double simulated_s = 0.0;
  double consumption_l1_m_s = 0.0;
  double delta_v_m_s = 0.0;
  double propellant_kg = 0.0;
  double normal_delta_v_m_s = 0.0;
  int burns = 0;
  std::vector<double> on_time_s;                                        // per thruster
  std::vector<double> thrust_days;                                      // per thruster
  double north_days = 0, south_days = 0, east_days = 0, west_days = 0;  // FacesOf
  double time_outside_window_s = 0.0;
  double max_abs_lat_deg = 0.0;
  double max_abs_lon_deg = 0.0;
  double max_window_violation_deg = 0.0;
  double worst_time_s = std::numeric_limits<double>::quiet_NaN();
  int fallback_soft_window = 0, fallback_free_terminal = 0, fallback_zero_thrust = 0;
  int uncontrollable_cycles = 0;
  int time_limited_cycles = 0;  // accepted with status feasible (gap not reached)
  bool rules_ok = true;
  Distribution solve_seconds, gap, wall_seconds, cpu_seconds;
  double wall_seconds_total = 0.0;
  double cpu_seconds_total = 0.0;
};
LongHorizonSummary Summarize(const std::vector<CycleRecord>& cycles,
                             const dynamics::ThrusterSet& thrusters);
/// The name before the C++ API settled on -ize.
[[deprecated("renamed Summarize")]] inline LongHorizonSummary Summarise(
    const std::vector<CycleRecord>& cycles, const dynamics::ThrusterSet& thrusters) {
  return Summarize(cycles, thrusters);
}

class LongHorizonSimulation {
 public:
  /// `base` gives the model (dynamics::GeoLinearModel, same station and epoch
  /// as `simulator`), thrusters, rules, window (hard; lat and lon), objective
  /// and the fixed forced-off windows; its grid, initial_state (the state at
  /// options.start_s), history (off_for_s only), terminal and window
  /// soft/enforce settings are replaced per cycle.
  /// @throws std::invalid_argument if the options or the base problem are
  ///         invalid (message names the field), the model is not GEO, the
  ///         simulator does not match it, an outage names an unknown thruster,
  ///         the history has a thruster on at the start, the input mode is
  ///         impulsive, or options.solve.check.nonlinear is set.
  LongHorizonSimulation(ScheduleProblem base, LongHorizonOptions options,
                        std::shared_ptr<const dynamics::GeoSimulator> simulator,
                        std::shared_ptr<const milp::Solver> solver);

  const LongHorizonOptions& options() const { return options_; }
  const ScheduleProblem& base() const { return base_; }
  int num_cycles() const { return num_cycles_; }

  struct CycleTimes {
    double start_s, applied_end_s, prediction_end_s;
  };
  /// @throws std::out_of_range if k is not in [0, num_cycles()).
  CycleTimes Times(int k) const;

  /// State at options.start_s: base.initial_state converted to ECI, history
  /// from base.history.
  LongHorizonState InitialState() const;

  /// The nominal problem of cycle state.next_cycle (before fallbacks).
  /// @throws std::invalid_argument if the state is inconsistent (cycle index
  ///         out of range, time not the cycle start, wrong history size).
  ScheduleProblem CycleProblem(const LongHorizonState& state) const;

  /// Availability of each thruster during cycle k's prediction (enabled and
  /// not under an outage at any time of it).
  std::vector<bool> Available(int k) const;

  /// Runs cycle state->next_cycle and advances *state (unless interrupted).
  /// Never throws for an infeasible or unsolved cycle (fallbacks); throws as
  /// CycleProblem for an inconsistent state, and std::runtime_error if the
  /// nonlinear propagation fails (orbit leaves the model's validity).
  CycleRecord RunCycle(LongHorizonState* state) const;

 private:
  // An attempt of a cycle: the nominal problem or a fallback, and whether
  // CBC's preprocessing and presolve are off (`raw`).
  struct Level {
    Fallback level;
    bool raw;
  };
  /// The attempts of a cycle in order of escalation.
  std::vector<Level> Levels(bool controllable, const ScheduleProblem& nominal) const;
  /// Builds and solves one attempt; fills *attempt and the build/check times of *rec.
  ScheduleResult Attempt(const ScheduleProblem& p, const Level& level, int control_node,
                         CycleAttempt* attempt, CycleRecord* rec) const;
  /// Runs the attempts until one has a schedule (then improves it); false
  /// when none has or the run was interrupted (rec->interrupted).
  bool SolveCycle(const ScheduleProblem& nominal, bool controllable, int control_node,
                  ScheduleResult* accepted, CycleRecord* rec) const;
  /// The cycle MILP of `p` (with the receding mode's control-boundary rows).
  ScheduleMilp BuildCycleMilp(const ScheduleProblem& p, int control_node) const;
  /// The improvement pass (LongHorizonOptions::improve_above_gap) on an
  /// accepted schedule; records the attempt in *rec.
  /// accepted_raw: the schedule comes from the preprocessing-off retry.
  void ImproveAccepted(const ScheduleProblem& p, int control_node, bool accepted_raw,
                       ScheduleResult* accepted, CycleRecord* rec) const;

  ScheduleProblem base_;
  LongHorizonOptions options_;
  std::shared_ptr<const dynamics::GeoSimulator> simulator_;
  std::shared_ptr<const milp::Solver> solver_;
  int num_cycles_ = 0;
};

}  // namespace thrustsched::planning

#endif  // THRUSTSCHED_PLANNING_LONG_HORIZON_H_
