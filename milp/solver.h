// Solver interface, options and results (solver-independent).
//
//   std::unique_ptr<milp::Solver> solver = milp::MakeCbcSolver();   // milp/cbc_solver.h
//   milp::SolveOptions options;
//   options.time_limit_s = 60;            // wall clock
//   options.relative_gap = 1e-4;
//   milp::SolveResult result = solver->Solve(lp, options);
//   if (result.has_solution()) use(result.x, result.objective);
//
// An infeasible or unbounded model is a result (status), not an error. Invalid
// input (LpData::IsValid false, options invalid) throws std::invalid_argument.
// Same input and options (threads == 1) give the same answer. Distinct Solver
// instances, or one instance called from several threads, may solve in parallel.
// For several LP relaxations at once prefer one SolveLpRelaxations call from
// one thread: the CBC backend forks a child process per solve, and a fork from
// one thread while another holds a lock of the allocator (ASan's does not
// reset its locks at fork) can leave the child stuck.
#ifndef THRUSTSCHED_MILP_SOLVER_H_
#define THRUSTSCHED_MILP_SOLVER_H_

#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "milp/lp_data.h"

namespace thrustsched::milp {

enum class SolveStatus {
  kOptimal,   // proven optimal within the requested gap
  kFeasible,  // stopped by a limit with an incumbent; see gap
  kInfeasible,
  kUnbounded,
  kNoSolutionFound,  // stopped by a limit (time, interrupt) without incumbent
  kError,            // solver failure; see detail
};
std::string_view ToString(SolveStatus status);
std::ostream& operator<<(std::ostream& os, SolveStatus status);

/// |objective - bound| / max(1e-10, |objective|): the relative gap used
/// everywhere (stopping rule, reports); +inf if either is not finite.
double RelativeGap(double objective, double bound);

/// What a MILP solve is doing when it reports progress.
enum class SolvePhase {
  kRootLp,     // the LP relaxation at the root (no incumbent, no bound yet)
  kPresolve,   // the solver's preprocessing, root cuts and heuristics
  kSearch,     // branch and bound
  kFinishing,  // stopped; the best solution is being completed and verified
};
std::string_view ToString(SolvePhase phase);

/// Reported to SolveOptions::progress during a solve.
struct SolveProgress {
  double wall_seconds = 0.0;
  double objective = std::numeric_limits<double>::quiet_NaN();  // incumbent, NaN if none
  double best_bound = std::numeric_limits<double>::quiet_NaN();
  double gap = std::numeric_limits<double>::quiet_NaN();
  long long nodes = 0;
  bool new_incumbent = false;
  /// True while the MILP's root LP relaxation is being solved (before the
  /// search: no incumbent, no bound yet); reported every progress_interval_s.
  bool in_root_lp = false;
  SolvePhase phase = SolvePhase::kSearch;
  /// True on the one report that announces stage() has begun.
  bool stage_begins = false;

  /// The step of the caller's algorithm this progress belongs to (the
  /// schedule search names its phases), empty when there is none. Held in a
  /// fixed array, cut at 31 characters: the struct stays trivially copyable
  /// (backends pass it between processes as bytes).
  std::string_view stage() const { return std::string_view(stage_name_); }
  void set_stage(std::string_view name);

  /// In the root LP: simplex iterations so far, and the current objective
  /// (model sense, with offset; not a bound until the LP is optimal) and sum
  /// of primal infeasibilities of the iterate. -1 / NaN when not known.
  long long lp_iterations = -1;
  double lp_objective = std::numeric_limits<double>::quiet_NaN();
  double lp_primal_infeasibility = std::numeric_limits<double>::quiet_NaN();

 private:
  char stage_name_[32] = {};
};

/// Options of a solve. IsValid() rules: time_limit_s >= 0 (not NaN, may be
/// +inf); relative_gap, absolute_gap finite and >= 0; threads >= 1;
/// random_seed >= 0; log_level >= 0; progress_interval_s > 0;
/// initial_solution entries finite.
/// Algorithm for LP relaxations (and the root LP of a MILP).
enum class LpAlgorithm {
  kPrimal,   // primal simplex: the fastest simplex on the station-keeping
             // transcriptions (free state columns, equality dynamics rows);
             // measurements in docs/bench/report.md, section 3
  kDual,     // dual simplex: CLP's and the cbc program's default
  kBarrier,  // interior point + crossover
  /// Interior point without crossover, without presolve: a near-optimal,
  /// near-feasible point (not a vertex) and near-optimal duals, in a fraction
  /// of a simplex's time on the schedule MILPs' relaxations (measured in
  /// docs/bench/report.md, section 8); its bound comes from the duals through SafeDualBound
  /// (LpRelaxationResult::dual_bound), valid whatever its accuracy. LP
  /// relaxations only: a MILP's root falls back to primal simplex.
  kBarrierNoCrossover,
};
std::string_view ToString(LpAlgorithm algorithm);

struct SolveOptions {
  double time_limit_s = std::numeric_limits<double>::infinity();  // wall clock
  double relative_gap = 1e-4;  // |obj - bound| / max(1e-10, |obj|)
  double absolute_gap = 1e-9;
  int threads = 1;  // > 1 may make CBC non-deterministic
  /// 0 (default): the solver's own default seeds (for CBC: the same run as
  /// the `cbc` program); > 0: this seed for all random choices.
  int random_seed = 0;
  int log_level = 0;  // 0 silent (default); 1 summary; 2+ solver log
  bool presolve = true;
  /// If > 0: every feasible objective value (minus the offset) is an integer
  /// multiple of this step, e.g. when the only costed columns are binaries of
  /// equal cost. The solver may then prune any node that cannot improve the
  /// incumbent by (almost) a full step, which closes gaps the LP bound alone
  /// cannot. A wrong step can cut off the optimum: pass it only when it is true.
  double objective_step = 0.0;
  /// A bound on the optimum proven elsewhere (model sense; NaN: none), e.g.
  /// by a relaxation the caller solved with more knowledge of the problem:
  /// the MILP solve stops, as at a limit, once an incumbent closes the gap
  /// to it (GapClosed), and its result's best_bound is the better of the
  /// solver's and this one. Its status stays kFeasible: the proof is not the
  /// solver's, and a caller that reads kOptimal as "this model is solved"
  /// (the search's exact restricted MILP) is not misled.
  double known_bound = std::numeric_limits<double>::quiet_NaN();
  LpAlgorithm lp_algorithm = LpAlgorithm::kPrimal;
  /// MIP start: a full column vector; integer entries are rounded and the
  /// continuous ones re-optimised with the integers fixed. If the result is
  /// feasible it is the first incumbent (and a cutoff); otherwise it is
  /// ignored and SolveResult::detail says so.
  std::optional<Eigen::VectorXd> initial_solution;
  /// Called on each new incumbent and otherwise at most every
  /// progress_interval_s, from the solving thread. An exception thrown by it
  /// stops the solve and is rethrown by Solve().
  std::function<void(const SolveProgress&)> progress;
  /// Optional, problem-aware completion of a solution: given x whose integer
  /// entries are set (the others may be NaN, e.g. columns the solver's
  /// preprocessing removed), fill in every entry and return true, or return
  /// false if it cannot. The solver verifies the result against the model
  /// and otherwise completes x by an LP over the continuous columns, which is
  /// what it does without this function (e.g. the schedule MILPs propagate
  /// their states from the on-off pattern instead).
  std::function<bool(Eigen::VectorXd* x)> complete_solution;
  /// Optional: called with the column values of each incumbent the search
  /// finds, as soon as it is reported (completed as a result's x is, and
  /// feasible for the model; the MIP start is not reported), from the
  /// solving thread. For a caller that may want an incumbent the search
  /// later replaces, e.g. milp::SolveWithLazyRows, whose subset's later
  /// incumbents may break a row left out. An exception thrown by it stops
  /// the solve and is rethrown by Solve(), as for `progress`.
  std::function<void(const Eigen::VectorXd& x)> on_incumbent;
  double progress_interval_s = 5.0;
  /// If set and becomes true, the solve stops as at a time limit.
  const std::atomic<bool>* interrupt = nullptr;
  /// >= 0: stop after this many branch-and-bound nodes (status kFeasible or
  /// kNoSolutionFound, like a time limit). Unlike the wall-clock limit it
  /// gives the same result on every run (threads == 1). < 0: no limit.
  long long max_nodes = -1;

  /// Settings only the CBC backend reads.
  struct Cbc {
    /// Run CBC's driver in a child process (fork) that streams every
    /// incumbent to this one, rather than in this process. The child can be
    /// stopped at any moment (inside an LP, a cut round or a heuristic), a
    /// crash of CBC does not take this process down, and solves from several
    /// threads run in parallel. Off: in this process, one solve at a time.
    bool separate_process = true;
    /// After an interrupt or the deadline, how long the child may take to
    /// stop by itself (and hand over its final answer) before it is killed;
    /// the incumbents it already reported are kept either way.
    double stop_grace_s = 0.5;
    /// Switch CBC's knapsack cover cuts off (used by the second run that checks
    /// an infeasibility claim; see cbc_solver.cc).
    bool disable_knapsack_cuts = false;
  } cbc;

  bool IsValid(std::string* error) const;
};

/// True when `objective` is within options.absolute_gap or
/// options.relative_gap (RelativeGap) of `bound`: the stopping rule of a
/// solve. False if either is not finite.
bool GapClosed(double objective, double bound, const SolveOptions& options);

/// One improving solution found during the search (objective and best bound
/// in the model's own sense, with the offset; wall seconds since Solve()).
struct Incumbent {
  double wall_seconds;
  double objective;
  double best_bound;
};

struct SolveResult {
  SolveStatus status = SolveStatus::kError;
  std::string detail;  // solver-specific explanation, raw codes
  // objective, best_bound and gap are set when has_solution(); gap is
  // |objective - best_bound| / max(1e-10, |objective|).
  std::string solver_version;                                   // e.g. "CBC 2.10.8"
  double objective = std::numeric_limits<double>::quiet_NaN();  // model sense, with offset
  double best_bound = std::numeric_limits<double>::quiet_NaN();
  double gap = std::numeric_limits<double>::quiet_NaN();  // relative, >= 0
  long long nodes = 0;
  double wall_seconds = 0.0;
  Eigen::VectorXd x;                  // column values; empty unless has_solution()
  std::vector<Incumbent> incumbents;  // in time order

  bool has_solution() const {
    return status == SolveStatus::kOptimal || status == SolveStatus::kFeasible;
  }
  /// Seconds to the first incumbent whose gap to the final best bound is
  /// <= rel_gap; NaN if none.
  double TimeToGap(double rel_gap) const;
};

/// Result of solving the continuous relaxation (integrality dropped).
struct LpRelaxationResult {
  SolveStatus status = SolveStatus::kError;
  std::string detail;
  double objective = std::numeric_limits<double>::quiet_NaN();
  double wall_seconds = 0.0;
  Eigen::VectorXd x;  // primal column values
  /// One per row: the derivative of the optimal objective (in the model's own
  /// sense, offset irrelevant) with respect to the row's active bound. For a
  /// minimisation, a binding ">= lower" row has a dual >= 0 and a binding
  /// "<= upper" row a dual <= 0; for a maximisation the signs flip. Inactive
  /// rows have dual 0.
  Eigen::VectorXd row_duals;
  /// A bound on the LP optimum, hence on the MILP (>= for a maximisation's
  /// upper bound), computed from row_duals alone (milp/lp_bound.h): valid
  /// whatever the accuracy of the algorithm; equal to `objective` up to the
  /// solver's tolerances after a simplex. NaN when there are no duals.
  double dual_bound = std::numeric_limits<double>::quiet_NaN();
  /// CLP iterations (simplex pivots or interior-point steps).
  long long iterations = 0;
};

/// A continuous relaxation kept between solves, for searches that change
/// column bounds and solve again from the last basis (dual simplex), e.g. a
/// dive or a tree. The first Solve starts from scratch: by the dual simplex,
/// or (options.lp_algorithm kBarrier or kBarrierNoCrossover) by the interior
/// point with its crossover to a basis; or from a point the caller has
/// (CrossOverFrom). Not thread-safe; one per thread.
///
///   std::unique_ptr<LpSession> s = solver->OpenLpSession(lp, options);
///   LpRelaxationResult r = s->Solve();          // from scratch
///   s->SetColumnBounds(j, 1.0, 1.0);
///   r = s->Solve();                             // warm: a few pivots
class LpSession {
 public:
  virtual ~LpSession() = default;
  virtual void SetColumnBounds(int column, double lower, double upper) = 0;
  /// The next Solve starts from this point of the session's LP and its row
  /// duals (in the model's own sense, as LpRelaxationResult::row_duals): a
  /// crossover to a basis, then the dual simplex, instead of a solve from
  /// scratch. For a near-optimal point, e.g. SolveLpRelaxation's interior
  /// point without crossover (kBarrierNoCrossover), extended to the
  /// session's LP: on a six-thruster GEO week a few times faster than a
  /// second interior point with its crossover (docs/search.md). The
  /// crossover first puts every column the duals price out at its bound (a
  /// central point holds thousands of them strictly inside). Default:
  /// ignored (the next Solve as without it); the CBC backend's session
  /// throws std::invalid_argument unless one value per column and one dual
  /// per row.
  virtual void CrossOverFrom(const Eigen::VectorXd& x, const Eigen::VectorXd& row_duals) {
    (void)x;
    (void)row_duals;
  }
  /// Each later warm Solve (the dual simplex from the current basis: not
  /// the first solve, nor one after CrossOverFrom) stops after this many
  /// pivots (status kNoSolutionFound, detail "pivot limit"): a
  /// deterministic cap, where a time limit is not. < 0: none (the default).
  /// Default implementation: ignored.
  virtual void SetPivotLimit(long long pivots) { (void)pivots; }
  /// The current column bounds (as set, not the original ones).
  virtual double column_lower(int column) const = 0;
  virtual double column_upper(int column) const = 0;
  /// Solves; stops as at a time limit at options.time_limit_s (from the
  /// session's opening) or on options.interrupt (status kNoSolutionFound).
  /// dual_bound is not computed here (SafeDualBound on the result's duals).
  virtual LpRelaxationResult Solve() = 0;
  /// The basis the last Solve left (opaque), to start a later Solve from it
  /// (RestoreBasis), e.g. a tree's child from its parent's basis rather than
  /// its sibling's. Empty when the session keeps none (every Solve from
  /// scratch); RestoreBasis of an empty one does nothing.
  virtual std::vector<unsigned char> SaveBasis() const { return {}; }
  virtual void RestoreBasis(const std::vector<unsigned char>& basis) { (void)basis; }
};

class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string_view name() const = 0;
  virtual std::string version() const = 0;
  /// @throws std::invalid_argument if !problem.IsValid() or !options.IsValid(),
  ///         or options.initial_solution has the wrong size.
  SolveResult Solve(const LpData& problem, const SolveOptions& options = {}) const;
  /// Solves the LP relaxation. @throws as Solve.
  LpRelaxationResult SolveLpRelaxation(const LpData& problem,
                                       const SolveOptions& options = {}) const;
  /// Solves the LP relaxations of several problems with the same options;
  /// result i belongs to *problems[i], and is what SolveLpRelaxation gives
  /// for it. options.time_limit_s is for the whole call. With
  /// options.threads >= 2 a backend may solve up to `threads` of them at once
  /// (the CBC backend does for its interior point, each LP in a child
  /// process, all started from the calling thread). @throws as Solve.
  std::vector<LpRelaxationResult> SolveLpRelaxations(const std::vector<const LpData*>& problems,
                                                     const SolveOptions& options = {}) const;
  /// Opens an LP session on the continuous relaxation of `problem` (copied).
  /// @throws as Solve.
  std::unique_ptr<LpSession> OpenLpSession(const LpData& problem,
                                           const SolveOptions& options = {}) const;

 private:
  virtual SolveResult DoSolve(const LpData& problem, const SolveOptions& options) const = 0;
  virtual LpRelaxationResult DoSolveLpRelaxation(const LpData& problem,
                                                 const SolveOptions& options) const = 0;
  /// Default: one after another through DoSolveLpRelaxation, each with the
  /// time left.
  virtual std::vector<LpRelaxationResult> DoSolveLpRelaxations(
      const std::vector<const LpData*>& problems, const SolveOptions& options) const;
  /// Default: a session that solves each time from scratch through
  /// DoSolveLpRelaxation (backends override it with a warm-started one).
  virtual std::unique_ptr<LpSession> DoOpenLpSession(const LpData& problem,
                                                     const SolveOptions& options) const;
};

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_SOLVER_H_
