// FleetMilp: several spacecraft planned in one MILP (formation deployment and
// reconfiguration, Epenoy 2006; co-located satellites sharing one box, Soop,
// Handbook of Geostationary Orbits, ch. 7).
//
//   transcription::FleetProblem fleet;
//   fleet.members = {{"chief", chief_problem}, {"deputy", deputy_problem}};
//   transcription::TerminalCoupling c;                    // x_d(t_N) - x_c(t_N) = b
//   c.member = 1; c.reference = 0;
//   c.map = Eigen::MatrixXd::Identity(6, 6); c.offset = Eigen::VectorXd::Zero(6);
//   c.offset[1] = 200;                                     // 200 m along-track
//   fleet.couplings.push_back(c);
//   fleet.keep_out = transcription::FleetKeepOut{50.0, check_times};  // 50 m cube
//   fleet.balance.kind = transcription::FuelBalanceKind::kMinMax;
//   transcription::FleetResult r = transcription::SolveFleet(fleet, *milp::MakeCbcSolver());
//   for (size_t k = 0; k < r.schedules.size(); ++k)
//     std::cout << fleet.members[k].name << ": " << r.consumption[k] << "\n";
//
// The model is one milp::Model with one block per member (the member's own
// ScheduleMilp, columns and rows named "<member>.<name>") plus the coupling
// rows, solved by any milp::Solver:
//   - terminal couplings  A x_k(t_N) - A x_l(t_N) = b (l = -1: A x_k(t_N) = b),
//     the formation geometry (Epenoy's coupled terminal conditions phi = 0);
//   - fuel balance, the linear analogue of Epenoy's mass-balancing function:
//     kMaxExcessOverMean  J_k <= (1 + f) (1/K) sum_l J_l for every member, or
//     kMinMax             minimise  max_k J_k + w sum_k J_k  (epigraph column);
//     J_k is member k's own objective (its ObjectiveKind, burn-start penalty
//     included);
//   - pairwise keep-out on a check grid: at each check time t and pair (k, l),
//     the relative position r_k(t) - r_l(t) lies outside the cube of half-size R,
//     the disjunction of Serra 2015 (Problem 10) over the six faces
//     a^T (r_k - r_l) + M w_a >= R,  sum_a w_a <= 5, with M derived from the
//     reachable sets of both members (every on-off binary in [0, 1]: the exact
//     range of a^T r over the box of binaries, as transcription/keep_out.h),
//     faces no plan can satisfy dropped, checks every plan clears left out;
//     with initial-state covariances, each face grown by its chance-constraint
//     margin (Serra 2015 (4.19));
//   - slot assignment (Richards, Schouwenaars, How & Feron 2002): binaries
//     z_is, each listed member takes one slot and each slot one member, and
//     |A x_i(t_N) - A x_ref(t_N) - slot_s| <= M_is (1 - z_is) with M from the
//     same reachable ranges.
// SolveFleet first plans the members alone (transcription/fleet_start.h):
// their plans are the solver's MIP start and their proven bounds bound the
// fleet; after the solve it checks every member and, with covariances, runs
// the Monte Carlo of the initial states (transcription/fleet_monte_carlo.h).
// Members must share the grid, use the on-off input mode and the sparse
// formulation (the couplings are written on the state columns).
// Positions: `position_map` (3 x n, metres) maps a member's state to its
// position; empty means the model's own local position map where it has one
// (GEO: radial, east, north about the station point, time-varying; members
// then share the station point) and the first three state components
// otherwise (HCW, YA, Schweighart-Sedwick, the double integrators).
#ifndef THRUSTSCHED_TRANSCRIPTION_FLEET_H_
#define THRUSTSCHED_TRANSCRIPTION_FLEET_H_

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "milp/model.h"
#include "milp/solver.h"
#include "transcription/checker.h"
#include "transcription/fleet_monte_carlo.h"
#include "transcription/keep_out.h"
#include "transcription/problem.h"
#include "transcription/schedule_milp.h"

namespace thrustsched::transcription {

struct FleetMember {
  std::string name;  // unique, non-empty: the prefix of the member's columns and rows
  ScheduleProblem problem;
  /// Covariance (n x n, the state's SI units) of the member's initial state
  /// at the grid start, independent between members; empty: known exactly.
  /// Symmetric, positive semi-definite.
  Eigen::MatrixXd initial_covariance{};
};

/// map * x_member(t_N) - map * x_reference(t_N) = offset, within +-tolerance
/// per row (empty tolerance: equality). reference = -1: no reference term.
struct TerminalCoupling {
  int member = 0;
  int reference = -1;
  Eigen::MatrixXd map;        // rows x n (state units)
  Eigen::VectorXd offset;     // rows
  Eigen::VectorXd tolerance;  // rows, >= 0, or empty
};

enum class FuelBalanceKind { kNone, kMaxExcessOverMean, kMinMax };
std::string_view ToString(FuelBalanceKind kind);
/// "none" | "max_excess_over_mean" | "min_max". @throws std::invalid_argument.
FuelBalanceKind ParseFuelBalanceKind(std::string_view name);

struct FuelBalance {
  FuelBalanceKind kind = FuelBalanceKind::kNone;
  double max_excess_fraction = 0.1;  // f >= 0 (kMaxExcessOverMean)
  double sum_weight = 1e-3;          // w >= 0 (kMinMax): ties broken by the total
};

struct FleetKeepOut {
  double half_size_m = 0.0;           // R > 0: |r_k - r_l|_inf >= R at every check
  std::vector<double> check_times_s;  // sorted, inside the grid (a node or between)
  /// eps' in (0, 0.5): each face row holds with probability >= 1 - eps' under
  /// the members' initial covariances (the chance constraint of Serra 2015
  /// (4.19) for a pair: margin c = Phi^-1(1 - eps') sqrt(a^T Sigma_kl(t) a),
  /// Sigma_kl = P Phi(t) (Sigma_k + Sigma_l) Phi(t)^T P^T, control-independent);
  /// 0: no margin (the planned positions only).
  double instantaneous_threshold = 0.0;
};

/// Members `members[i]` take the slots: map x_i(t_N) - map x_ref(t_N) = slots[s]
/// (within +-tolerance per row) for the slot s assigned to i (a permutation:
/// as many slots as members).
struct SlotAssignment {
  std::vector<int> members;
  int reference = -1;                  // the chief (not among `members`), or -1
  Eigen::MatrixXd map;                 // rows x n
  std::vector<Eigen::VectorXd> slots;  // rows each
  Eigen::VectorXd tolerance;           // rows, >= 0 (within +-tolerance per row), or empty
};

struct FleetProblem {
  std::vector<FleetMember> members;
  std::vector<TerminalCoupling> couplings;
  FuelBalance balance;
  std::optional<FleetKeepOut> keep_out;
  std::optional<SlotAssignment> assignment;
  Eigen::MatrixXd position_map;  // 3 x n or empty (see FleetPositionMap)

  /// Index of the member named `name`, -1 if none.
  int MemberIndex(std::string_view name) const;
  /// Some member has an initial_covariance.
  bool HasInitialCovariance() const;
  /// Every member valid (ScheduleProblem::IsValid, message prefixed by
  /// "members[k]."), the same grid and state size, on-off mode, names unique,
  /// couplings, balance, keep-out and assignment of consistent sizes and
  /// finite values. On failure fills *error naming the field and the value.
  bool IsValid(std::string* error) const;
};

struct FleetBuildStats {
  int num_columns = 0, num_rows = 0, num_binaries = 0;
  long long num_nonzeros = 0;
  int keep_out_checks = 0;            // (pair, time) checks
  int keep_out_checks_clear = 0;      // every reachable pair of plans clears: no row
  int keep_out_single_face = 0;       // one face possible: one row, no binary
  int keep_out_faces_impossible = 0;  // dropped
  int keep_out_binaries = 0;
  int assignment_binaries = 0;
  double big_m_min_m = std::numeric_limits<double>::quiet_NaN();  // keep-out big-M
  double big_m_max_m = std::numeric_limits<double>::quiet_NaN();
  double assignment_big_m_max = std::numeric_limits<double>::quiet_NaN();  // map units
  double keep_out_quantile = 0.0;                  // Phi^-1(1 - eps'), 0 without a risk threshold
  double keep_out_margin_max_m = 0.0;              // largest chance-constraint margin c
  std::vector<std::string> infeasibility_reasons;  // found while building
};

class FleetMilp {
 public:
  /// Builds every member's ScheduleMilp with `options` (sparse formulation
  /// required), then the fleet model.
  /// @throws std::invalid_argument if !fleet.IsValid() (message names the
  ///         field) or options.formulation is not kSparse.
  FleetMilp(const FleetProblem& fleet, const BuildOptions& options);

  const FleetProblem& fleet() const { return fleet_; }
  const milp::Model& model() const { return model_; }
  const milp::LpData& lp() const { return lp_; }
  const FleetBuildStats& stats() const { return stats_; }
  int num_members() const { return static_cast<int>(members_.size()); }
  const ScheduleMilp& member(int k) const { return *members_.at(k); }
  /// First fleet column of member k's block (its columns are contiguous).
  int column_offset(int k) const { return offsets_.at(k); }

  /// Member k's columns of a fleet solution. @throws std::invalid_argument on size.
  Eigen::VectorXd MemberColumns(const Eigen::VectorXd& x, int k) const;
  /// One schedule per member. @throws std::invalid_argument on size.
  std::vector<Schedule> Decode(const Eigen::VectorXd& x) const;
  /// Member objectives J_k of a fleet solution (model units).
  std::vector<double> Consumptions(const Eigen::VectorXd& x) const;
  /// Slot of each assigned member (order of assignment.members); empty without one.
  std::vector<int> Slots(const Eigen::VectorXd& x) const;
  /// A full column vector (MIP start) from one on-off pattern per member
  /// (thrusters x intervals) and, with an assignment, the slot of each
  /// assigned member: each block by ScheduleMilp::StartFromPattern, the slot
  /// binaries set, at each keep-out check the face with the largest slack
  /// enforced (CompleteKeepOut), the min-max column at the largest member
  /// objective. Not necessarily feasible (members alone may collide).
  /// @throws std::invalid_argument on sizes.
  Eigen::VectorXd StartFromPatterns(const std::vector<Eigen::MatrixXi>& patterns,
                                    const std::vector<int>& slots) const;
  /// Rows of lp() that keep members k and l apart (faces and pick), per
  /// keep-out check time (empty for a clear check); k, l in any order.
  std::vector<std::vector<int>> KeepOutRows(int k, int l) const;
  /// The right-hand sides (metres: the half-size plus each face's chance
  /// margin) of the keep-out check q between members k < l, by face f:
  /// face f holds when s (r_k - r_l)[f / 2] >= rhs[f], s = +1 for even f and
  /// -1 for odd. @throws std::out_of_range without a keep-out or k >= l.
  Eigen::Matrix<double, 6, 1> KeepOutFaceRhs(int k, int l, int q) const;

 private:
  void Compose();
  void AddObjectiveAndBalance();
  void AddCouplings();
  void AddKeepOut();
  void AddAssignment();
  void IndexKeepOutGroups();
  milp::LinearExpr ConsumptionOf(int k) const;
  milp::Variable StateColumn(int k, int node, int component) const;

  FleetProblem fleet_;
  BuildOptions options_;
  std::vector<std::unique_ptr<ScheduleMilp>> members_;
  std::vector<int> offsets_;
  milp::Model model_;
  milp::LpData lp_;
  FleetBuildStats stats_;
  std::vector<std::vector<milp::Variable>> slot_binaries_;  // [member i][slot s]
  std::vector<std::string> keep_out_tags_;                  // name tag of each check with binaries
  KeepOutStats keep_out_groups_;                            // their binaries, and rows in lp_
  /// [pair][check] of KeepOutFaceRhs, pairs in the order (0, 1), (0, 2), ..., (1, 2), ...
  std::vector<std::vector<Eigen::Matrix<double, 6, 1>>> keep_out_rhs_;
  int balance_column_ = -1;  // kMinMax: the epigraph column
};

/// Minimum distance of one pair over a set of times.
struct PairDistance {
  int a = 0, b = 1;                                                     // member indices, a < b
  double min_distance_m = std::numeric_limits<double>::infinity();      // Euclidean
  double min_box_distance_m = std::numeric_limits<double>::infinity();  // max-norm (the cube's)
  double time_s = std::numeric_limits<double>::quiet_NaN();             // of the Euclidean minimum
};

struct FleetSolveOptions {
  BuildOptions build;
  milp::SolveOptions milp;
  bool check = true;  // CheckSchedule per member and the fleet re-checks below
  CheckOptions checker;
  /// With the check, a keep-out and an initial covariance on some member:
  /// the Monte Carlo of the initial states (monte_carlo.samples = 0: none).
  FleetMonteCarloOptions monte_carlo;
  /// A first incumbent from the members planned alone by the search
  /// (transcription/fleet_start.h), given to the solver as a MIP start. It
  /// spends at most start_time_share of a finite milp.time_limit_s.
  bool decoupled_start = true;
  double start_time_share = 0.25;
  /// A start the keep-out rejects is re-planned member by member, each by the
  /// search against the fixed plans of those before it
  /// (transcription/fleet_in_turn.h), in at most in_turn_time_share of a
  /// finite milp.time_limit_s; where that fails, repaired over the thrust
  /// slots within neighbourhood_radius_intervals of each member's own burns
  /// (0: not repaired), in at most neighbourhood_time_share of it.
  /// Called (calling thread) as each step of the start begins, with a
  /// sentence saying what it does (members alone, in turn, repair), so that
  /// a user is told why the work goes on before the solver reports.
  std::function<void(const std::string&)> announce;
  bool in_turn = true;
  double in_turn_time_share = 0.4;
  int neighbourhood_radius_intervals = 12;
  double neighbourhood_time_share = 0.5;
};

/// Largest row or bound violation (model units) at which a start counts as
/// feasible for the fleet MILP (ScheduleMilp's pattern tolerance).
inline constexpr double kStartFeasibility = ScheduleMilp::kPatternFeasibilityTolerance;

/// True, with *objective set, if the fleet column vector x keeps every row
/// of the fleet MILP (within kStartFeasibility): a start the solver may take.
bool KeepsFleetRows(const FleetMilp& milp, const Eigen::VectorXd& x, double* objective);

/// The first plan from the members alone (transcription/fleet_start.h).
struct FleetStart {
  bool tried = false;
  bool built = false;
  /// x keeps every row of the fleet MILP (the keep-out, the balance): the
  /// solver's first incumbent.
  bool accepted = false;
  std::string note;  // why not built, or what was done
  Eigen::VectorXd x;
  std::vector<int> slots;                 // per assigned member
  std::vector<double> member_objectives;  // J_k of each member's schedule alone
  double objective = std::numeric_limits<double>::quiet_NaN();  // the fleet objective of x
  /// A lower bound on the fleet MILP's objective: the fleet without its
  /// keep-out and balance rows separates into the members alone, so the
  /// members' proven bounds (the least over the assignments, with the
  /// fleet's balance objective) bound it. NaN when not built.
  double bound = std::numeric_limits<double>::quiet_NaN();
  int member_solves = 0;
  int tries = 0;  // assignments tried until one kept every fleet row (0: none did, or none tried)
  /// Rejected by the fleet rows: the fleet MILP over the thrust slots near
  /// the members' own burns (transcription/fleet_neighbourhood.h) was solved;
  /// `repaired`: its plan replaced x (then accepted, objective its own).
  bool neighbourhood_tried = false;
  bool repaired = false;
  /// Rejected by the keep-out: the members re-planned in turn
  /// (transcription/fleet_in_turn.h); `in_turn_found`: its plan replaced x.
  bool in_turn_tried = false;
  bool in_turn_found = false;
  int in_turn_members_replanned = 0;
  int in_turn_searches = 0;
  int in_turn_constraints = 0;
  double in_turn_seconds = 0.0;
  int neighbourhood_radius_intervals = 0;
  int neighbourhood_free_binaries = 0;
  double neighbourhood_seconds = 0.0;
  double seconds = 0.0;  // everything above, the neighbourhood included
};

struct FleetResult {
  milp::SolveStatus status = milp::SolveStatus::kError;
  std::string detail;
  double objective = std::numeric_limits<double>::quiet_NaN();
  double best_bound = std::numeric_limits<double>::quiet_NaN();
  double gap = std::numeric_limits<double>::quiet_NaN();
  double solve_seconds = 0.0;
  FleetBuildStats stats;
  std::vector<Schedule> schedules;  // per member
  std::vector<double> consumption;  // J_k per member
  std::vector<CheckReport> checks;  // per member (if options.check)
  std::vector<int> slots;           // assignment: slot per assigned member
  /// On the MILP's check grid, from the decoded (discrete) states.
  std::vector<PairDistance> planned_pairs;
  /// On the checker's fine sample grid (linear re-propagation of each member).
  std::vector<PairDistance> checked_pairs;
  /// GEO: on the same samples, from every member's nonlinear replay (the
  /// checker's), the exact separation in the radial, east, north axes of the
  /// pair's midpoint. Empty without the replay.
  std::vector<PairDistance> nonlinear_pairs;
  /// Largest |residual| per coupling (couplings, then the assignment if any),
  /// from the checker's re-propagated final states (or the decoded ones
  /// without the check), in the map's units (beyond the tolerance: > 0).
  std::vector<double> coupling_residuals;
  std::optional<FleetMonteCarloReport> monte_carlo;  // see FleetSolveOptions::monte_carlo
  FleetStart start;
  bool has_schedule() const {
    return status == milp::SolveStatus::kOptimal || status == milp::SolveStatus::kFeasible;
  }
};

/// Builds, solves, decodes and (by default) checks the fleet.
/// @throws as FleetMilp's constructor.
FleetResult SolveFleet(const FleetProblem& fleet, const milp::Solver& solver,
                       const FleetSolveOptions& options = {});

/// P(t) (3 x n, metres) of member k: fleet.position_map where given, else
/// its model's LocalPositionMap(t) (the GEO model's radial, east, north about
/// the station point), else the first three state components.
Eigen::MatrixXd FleetPositionMap(const FleetProblem& fleet, int k, double t);
/// FleetPositionMap at each time, or one matrix when it does not depend on t
/// (the form internal::MemberReach takes). `times` non-empty.
std::vector<Eigen::MatrixXd> FleetPositionMaps(const FleetProblem& fleet, int k,
                                               const std::vector<double>& times);
/// Position (metres) of member k's state at t: FleetPositionMap(fleet, k, t) * state.
Eigen::Vector3d FleetPosition(const FleetProblem& fleet, int k, double t,
                              const Eigen::VectorXd& state);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_FLEET_H_
