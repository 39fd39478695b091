// CBC/CLP backend. With mps_reader.cc and milp/internal/*.cc, the only code
// that sees COIN-OR headers.
//
// A MILP solve (guarantees in cbc_solver.h):
//  1. a MIP start, if any, is polished (integers rounded, continuous columns
//     re-optimised) and kept as the first incumbent;
//  2. CBC's driver runs (internal/cbc_driver.cc), by default in a child
//     process (internal/cbc_child.cc) that streams every incumbent here;
//  3. the answer is the best of: the driver's final solution, the best
//     incumbent it reported on the way (completed in the original column
//     space), and the start; each is verified against the model
//     (LpData::MaxViolation) before it counts;
//  4. an infeasibility or "the start is optimal" claim of CBC is confirmed
//     before it is reported (VerifyInfeasibilityClaim).
// LP relaxations and models without integer columns are solved by CLP here.
#include "milp/cbc_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

// COIN-OR (version strings only).
#include "CbcConfig.h"
#include "ClpConfig.h"
#include "CoinError.hpp"
#include "common/format.h"
#include "common/timing.h"
#include "milp/internal/cbc_child.h"
#include "milp/internal/cbc_driver.h"
#include "milp/internal/clp_lp.h"
#include "milp/internal/lp_child.h"
#include "milp/internal/solve_clock.h"

namespace thrustsched::milp {

using common::FormatG;
using common::Since;

namespace {

using common::Clock;
using internal::CoinArrays;
using internal::DriverListener;
using internal::DriverOutcome;
using internal::DriverRequest;
using internal::SolveClock;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The driver of the Debian build keeps state in process-wide globals: in
// this process, one call at a time (a child process has its own).
std::timed_mutex& DriverMutex() {
  static std::timed_mutex mutex;
  return mutex;
}

// This process's side of a run: records incumbents (with their column values,
// original space), forwards progress to the caller's callback, and turns the
// interrupt flag and a throwing callback into a stop request.
class Recorder : public DriverListener {
 public:
  Recorder(const LpData& lp, const SolveOptions& options, SolveClock* clock)
      : lp_(lp), options_(options), clock_(clock), sign_(internal::ObjectiveSign(lp)) {}

  void OnProgress(const SolveProgress& progress) override {
    if (progress.new_incumbent && std::isfinite(progress.objective)) {
      last_reported_objective_ = progress.objective;
    }
    Report(progress);
  }
  void OnIncumbent(const Incumbent& incumbent, const Eigen::VectorXd& x_partial) override {
    incumbents_.push_back(incumbent);
    if (best_x_.size() == 0 || sign_ * incumbent.objective < sign_ * best_objective_) {
      best_x_ = x_partial;
      best_objective_ = incumbent.objective;
      best_wall_ = incumbent.wall_seconds;
    }
    if (options_.on_incumbent && !callback_error_) {
      Eigen::VectorXd x = x_partial;
      try {
        if (internal::CompletePartial(lp_, options_, &x)) options_.on_incumbent(x);
      } catch (...) {
        callback_error_ = std::current_exception();
      }
    }
  }
  bool StopRequested() override {
    clock_->ShouldStop();  // remembers an interrupt
    if (!std::isnan(options_.known_bound) && std::isfinite(best_objective_) &&
        GapClosed(best_objective_, options_.known_bound, options_)) {
      known_bound_reached_ = true;
    }
    return clock_->stopped_by_interrupt() || callback_error_ != nullptr || known_bound_reached_;
  }
  /// StopRequested stopped the solve: an incumbent within the gap of
  /// SolveOptions::known_bound.
  bool known_bound_reached() const { return known_bound_reached_; }

  // An incumbent of our own (the MIP start).
  void RecordOwn(double objective) {
    const double wall = clock_->Elapsed();
    incumbents_.push_back({wall, objective, sign_ > 0 ? -kInf : kInf});
    SolveProgress p;
    p.wall_seconds = wall;
    p.objective = objective;
    p.best_bound = sign_ > 0 ? -kInf : kInf;
    p.new_incumbent = true;
    p.phase = SolvePhase::kRootLp;
    p.in_root_lp = true;
    Report(p);
  }
  void RethrowCallbackError() const {
    if (callback_error_) std::rethrow_exception(callback_error_);
  }
  bool callback_failed() const { return callback_error_ != nullptr; }
  const std::vector<Incumbent>& incumbents() const { return incumbents_; }
  void AddIncumbent(const Incumbent& inc) { incumbents_.push_back(inc); }
  const Eigen::VectorXd& best_x() const { return best_x_; }
  double best_objective() const { return best_objective_; }
  double best_wall() const { return best_wall_; }

 private:
  void Report(const SolveProgress& p) {
    if (!options_.progress || callback_error_) return;
    try {
      options_.progress(p);
    } catch (...) {
      callback_error_ = std::current_exception();
    }
  }
  const LpData& lp_;
  const SolveOptions& options_;
  SolveClock* clock_;
  double sign_;
  std::exception_ptr callback_error_;
  std::vector<Incumbent> incumbents_;
  Eigen::VectorXd best_x_;
  double best_objective_ = std::numeric_limits<double>::quiet_NaN();
  double best_wall_ = 0.0;
  double last_reported_objective_ = std::numeric_limits<double>::quiet_NaN();
  bool known_bound_reached_ = false;
};

class CbcSolverImpl final : public Solver {
 public:
  std::string_view name() const override { return "cbc"; }
  std::string version() const override { return CbcVersion(); }

 private:
  SolveResult DoSolve(const LpData& problem, const SolveOptions& options) const override;
  /// One CBC run. *cbc_claim is set when the status rests on CBC's "proven
  /// infeasible" (kInfeasible, or a MIP start declared optimal because
  /// nothing better was found under its cutoff).
  SolveResult SolveOnce(const LpData& problem, const SolveOptions& options,
                        bool* cbc_claim = nullptr) const;
  /// SolveOnce, repeated once without CBC's preprocessing if CBC throws while
  /// carrying a MIP start through it.
  SolveResult SolveOnceGuarded(const LpData& problem, const SolveOptions& options,
                               bool* cbc_claim) const;
  SolveResult VerifyInfeasibilityClaim(const LpData& problem, const SolveOptions& options,
                                       SolveResult claimed) const;
  LpRelaxationResult DoSolveLpRelaxation(const LpData& problem,
                                         const SolveOptions& options) const override;
  std::vector<LpRelaxationResult> DoSolveLpRelaxations(const std::vector<const LpData*>& problems,
                                                       const SolveOptions& options) const override;
  std::unique_ptr<LpSession> DoOpenLpSession(const LpData& problem,
                                             const SolveOptions& options) const override {
    return internal::OpenClpSession(problem, options);
  }
};

// One LP relaxation on its way through CLP: the continuous copy and its arrays.
struct RelaxedLp {
  const LpData* lp = nullptr;
  LpData relaxed;
  double sign = 1.0;
  internal::CoinArrays arrays;
  internal::LpOutcome outcome;
  std::string note;  // why the interior point was not the one that answered
};

LpRelaxationResult ToRelaxationResult(const RelaxedLp& p, double wall_seconds) {
  const internal::LpOutcome& o = p.outcome;
  LpRelaxationResult r;
  r.status = o.status;
  std::string words = p.note + (p.note.empty() || o.detail.empty() ? "" : "; ") + o.detail;
  r.detail = words.empty() ? "clp" : "clp: " + words;
  r.iterations = o.iterations;
  if (o.status == SolveStatus::kOptimal) {
    r.x = o.x;
    r.objective = p.lp->Objective(o.x);
    // CLP's duals are d(min objective)/d(rhs); the model's objective is
    // sign * (min objective) + offset.
    r.row_duals = p.sign * o.duals;
  }
  r.wall_seconds = wall_seconds;
  return r;
}

LpRelaxationResult TrivialRelaxation(const LpData& lp, double wall_seconds) {
  LpData relaxed = lp;
  std::fill(relaxed.col_type.begin(), relaxed.col_type.end(), VarType::kContinuous);
  const SolveResult t = internal::SolveTrivial(relaxed);
  LpRelaxationResult r;
  r.status = t.status;
  r.detail = t.detail;
  r.objective = t.objective;
  r.x = t.x;
  if (t.status == SolveStatus::kOptimal) r.row_duals = Eigen::VectorXd::Zero(lp.num_rows());
  r.wall_seconds = wall_seconds;
  return r;
}

// CLP's interior point for every LP of `batch`, each in its own child process,
// all at once (see lp_child.h: it may abort()); an LP whose child died is
// solved again by the primal simplex, here.
void SolveInChildren(const std::vector<RelaxedLp*>& batch, const SolveOptions& options,
                     SolveClock* clock) {
  std::vector<internal::LpCoreJob> jobs;
  for (const RelaxedLp* p : batch) jobs.push_back({&p->relaxed, &p->arrays});
  std::vector<internal::LpChildOutcome> got =
      internal::SolveLpCoresInChildren(jobs, options, clock);
  for (size_t i = 0; i < batch.size(); ++i) {
    RelaxedLp& p = *batch[i];
    if (!got[i].died) {
      p.outcome = std::move(got[i].outcome);
      continue;
    }
    SolveOptions simplex = options;
    simplex.lp_algorithm = LpAlgorithm::kPrimal;
    p.note = "interior point " + got[i].why + ", primal simplex instead";
    p.outcome = internal::SolveLpCore(p.relaxed, p.arrays, simplex, clock);
  }
}

LpRelaxationResult CbcSolverImpl::DoSolveLpRelaxation(const LpData& lp,
                                                      const SolveOptions& options) const {
  return DoSolveLpRelaxations({&lp}, options).front();
}

std::vector<LpRelaxationResult> CbcSolverImpl::DoSolveLpRelaxations(
    const std::vector<const LpData*>& lps, const SolveOptions& options) const {
  SolveClock clock(options.time_limit_s, options.interrupt);
  std::vector<LpRelaxationResult> out(lps.size());
  if (clock.ShouldStop()) {
    // Stopped before it started: CLP polls its event handler (and the child
    // process's parent its flag) only now and then, and a small LP would run
    // to the end past an interrupt raised before the call.
    for (LpRelaxationResult& r : out) {
      r.status = SolveStatus::kNoSolutionFound;
      r.detail = clock.stopped_by_interrupt() ? "clp: interrupted" : "clp: time limit";
    }
    return out;
  }
  std::vector<RelaxedLp> prepared(lps.size());
  std::vector<size_t> todo;  // indices of the LPs for CLP
  for (size_t i = 0; i < lps.size(); ++i) {
    const LpData& lp = *lps[i];
    if (lp.num_cols() == 0 || lp.num_rows() == 0) {
      out[i] = TrivialRelaxation(lp, clock.Elapsed());
      continue;
    }
    RelaxedLp& p = prepared[i];
    p.lp = &lp;
    p.relaxed = lp;
    std::fill(p.relaxed.col_type.begin(), p.relaxed.col_type.end(), VarType::kContinuous);
    p.sign = internal::ObjectiveSign(lp);
    p.arrays = internal::MakeArrays(p.relaxed, p.sign, false);
    todo.push_back(i);
  }
  const bool interior = options.lp_algorithm == LpAlgorithm::kBarrier ||
                        options.lp_algorithm == LpAlgorithm::kBarrierNoCrossover;
  const bool in_children = interior && options.cbc.separate_process;
  // Children run `threads` at a time; in this process, one LP at a time.
  const size_t at_once = in_children ? static_cast<size_t>(std::max(1, options.threads)) : 1;
  for (size_t first = 0; first < todo.size(); first += at_once) {
    const size_t last = std::min(todo.size(), first + at_once);
    std::vector<RelaxedLp*> batch;
    for (size_t k = first; k < last; ++k) batch.push_back(&prepared[todo[k]]);
    if (in_children) {
      SolveInChildren(batch, options, &clock);
    } else {
      for (RelaxedLp* p : batch) {
        p->outcome = internal::SolveLpCore(p->relaxed, p->arrays, options, &clock);
      }
    }
    for (size_t k = first; k < last; ++k) {
      out[todo[k]] = ToRelaxationResult(prepared[todo[k]], clock.Elapsed());
    }
  }
  return out;
}

// A model without integer columns: CLP alone.
SolveResult SolveContinuous(const LpData& lp, const SolveOptions& options, SolveClock* clock) {
  SolveOptions o_lp = options;
  // A model's solution must be a feasible vertex, not an interior point.
  if (o_lp.lp_algorithm == LpAlgorithm::kBarrierNoCrossover)
    o_lp.lp_algorithm = LpAlgorithm::kBarrier;
  const internal::LpOutcome o = internal::SolveLpCore(
      lp, internal::MakeArrays(lp, internal::ObjectiveSign(lp), true), o_lp, clock);
  SolveResult r;
  r.status = o.status;
  r.detail = o.detail.empty() ? "clp (no integer columns)" : "clp: " + o.detail;
  if (o.status == SolveStatus::kOptimal) {
    r.x = o.x;
    r.objective = lp.Objective(o.x);
    r.best_bound = r.objective;
    r.gap = 0.0;
    r.incumbents.push_back({clock->Elapsed(), r.objective, r.best_bound});
  }
  return r;
}

// CBC 2.10.8's driver can throw when it carries a MIP start through its
// preprocessing (CoinError "Illegal index N in ClpModel::getColumnName", N
// the column count: seen on on-off models with keep-out rows). The solve is
// then repeated once with the preprocessing and presolve off, start kept.
SolveResult CbcSolverImpl::SolveOnceGuarded(const LpData& lp, const SolveOptions& options,
                                            bool* cbc_claim) const {
  const Clock::time_point start = Clock::now();
  const bool may_retry = options.initial_solution.has_value() && options.presolve;
  std::string why;
  try {
    SolveResult r = SolveOnce(lp, options, cbc_claim);
    // In its child process the driver's CoinError becomes an error outcome.
    if (!may_retry || r.status != SolveStatus::kError ||
        r.detail.find("CoinError") == std::string::npos) {
      return r;
    }
    why = r.detail;
  } catch (const CoinError& e) {
    if (!may_retry) throw;
    why = "CoinError " + e.className() + "::" + e.methodName() + ": " + e.message();
  }
  SolveOptions again = options;
  again.presolve = false;
  if (std::isfinite(again.time_limit_s)) {
    again.time_limit_s = std::max(0.0, options.time_limit_s - Since(start));
  }
  SolveResult r = SolveOnce(lp, again, cbc_claim);
  r.detail = "CBC threw with the MIP start through its preprocessing (" + why +
             "): solved again without preprocessing; " + r.detail;
  r.wall_seconds = Since(start);
  return r;
}

SolveResult CbcSolverImpl::DoSolve(const LpData& lp, const SolveOptions& options) const {
  const Clock::time_point start = Clock::now();
  bool claim = false;
  SolveResult r = SolveOnceGuarded(lp, options, &claim);
  // CLP's barrier misclassifies some unbounded problems (reported optimal or
  // infeasible); an infeasible/unbounded verdict reached through it is
  // confirmed with the dual simplex, which classifies them correctly.
  if (options.lp_algorithm == LpAlgorithm::kBarrier &&
      (r.status == SolveStatus::kInfeasible || r.status == SolveStatus::kUnbounded)) {
    SolveOptions dual = options;
    dual.lp_algorithm = LpAlgorithm::kDual;
    if (std::isfinite(dual.time_limit_s)) {
      dual.time_limit_s = std::max(0.0, options.time_limit_s - Since(start));
    }
    SolveResult confirmed = SolveOnceGuarded(lp, dual, &claim);
    confirmed.detail = "barrier verdict re-checked with dual simplex; " + confirmed.detail;
    confirmed.wall_seconds += r.wall_seconds;
    r = std::move(confirmed);
  }
  if (claim && lp.is_mip()) {
    SolveOptions rest = options;
    if (std::isfinite(rest.time_limit_s)) {
      rest.time_limit_s = std::max(0.0, options.time_limit_s - Since(start));
    }
    const double before = r.wall_seconds;
    const Clock::time_point verify = Clock::now();
    r = VerifyInfeasibilityClaim(lp, rest, std::move(r));
    r.wall_seconds = before + Since(verify);
  }
  return r;
}

// CBC 2.10 has been seen to "prove" feasible scheduling models infeasible
// (a knapsack column cut, strong branching on an ill-conditioned root LP;
// docs/bench/report.md and coin-or/Cbc#186 show the same kind), and to declare
// a MIP start optimal that way. So a claim is not reported until it is
// confirmed:
//  1. by the LP relaxation, solved here by CLP without CBC's preprocessing:
//     an infeasible relaxation proves infeasibility; a relaxation bound no
//     better than the start (less one objective step) proves the start optimal;
//  2. otherwise by a second CBC run with CBC's preprocessing and the knapsack
//     cuts off, a different random seed and no cutoff: if it finds a better
//     schedule that is the result; if it says infeasible again the claim
//     stands (two different proofs agree); if it runs out of time the result
//     is "no solution" (or the start, "feasible"), with the reason in detail.
SolveResult CbcSolverImpl::VerifyInfeasibilityClaim(const LpData& lp, const SolveOptions& options,
                                                    SolveResult claimed) const {
  const Clock::time_point start = Clock::now();
  const bool start_claim = claimed.status == SolveStatus::kOptimal;  // a start, kept by cutoff
  const double sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
  // 1. The LP relaxation (at least 30 s, so that a claim made just before the
  // deadline can still be confirmed).
  SolveOptions lo = options;
  lo.lp_algorithm = LpAlgorithm::kPrimal;
  lo.progress = nullptr;
  lo.time_limit_s = std::max(30.0, options.time_limit_s);
  const LpRelaxationResult relaxed = DoSolveLpRelaxation(lp, lo);
  if (relaxed.status == SolveStatus::kInfeasible && !start_claim) {
    claimed.detail += "; infeasibility confirmed: the LP relaxation is infeasible";
    return claimed;
  }
  if (start_claim && relaxed.status == SolveStatus::kOptimal) {
    const double step = std::max(options.objective_step, 0.0);
    const double tol =
        std::max({options.absolute_gap, options.relative_gap * std::abs(claimed.objective), 1e-9}) +
        step;
    if (sign * relaxed.objective >= sign * claimed.objective - tol) {
      claimed.detail +=
          "; optimality confirmed by the LP relaxation bound " + FormatG(relaxed.objective, 10);
      claimed.best_bound = relaxed.objective;
      return claimed;
    }
  }
  std::string why = "CBC reported " +
                    std::string(start_claim ? "the start optimal" : "infeasible") +
                    " but the LP relaxation is " +
                    (relaxed.status == SolveStatus::kOptimal
                         ? "feasible with bound " + FormatG(relaxed.objective, 10)
                         : std::string(ToString(relaxed.status)) + " (" + relaxed.detail + ")");
  // 2. A second, differently configured CBC run (without the start: it must
  // find its own solutions).
  SolveOptions second = options;
  second.presolve = false;
  second.cbc.disable_knapsack_cuts = true;
  second.random_seed = options.random_seed + 7919;
  second.initial_solution.reset();
  if (std::isfinite(second.time_limit_s)) {
    second.time_limit_s = std::max(0.0, options.time_limit_s - Since(start));
  }
  bool claim_again = false;
  SolveResult retry = SolveOnce(lp, second, &claim_again);
  const std::string second_run = "a second CBC run (preprocessing and knapsack cuts off)";
  if (!start_claim) {
    if (claim_again) {
      claimed.detail +=
          "; " + why + "; " + second_run + " reached the same verdict: " + retry.detail;
      return claimed;
    }
    if (retry.has_solution()) {
      retry.detail = why + "; " + second_run + ": " + retry.detail;
      return retry;
    }
  } else {
    // Any better schedule is the result: keeping the start while taking the
    // second run's bound would report a gap above the one asked for.
    const double tol = 1e-9 * std::max(1.0, std::abs(claimed.objective));
    if (retry.has_solution() && sign * retry.objective < sign * claimed.objective - tol) {
      retry.detail = why + "; " + second_run + " found better: " + retry.detail;
      return retry;
    }
    if (retry.status == SolveStatus::kOptimal && !claim_again) {
      claimed.detail +=
          "; " + why + "; " + second_run + " proved nothing better exists: " + retry.detail;
      claimed.best_bound = retry.best_bound;
      claimed.gap = RelativeGap(claimed.objective, claimed.best_bound);
      return claimed;
    }
  }
  SolveResult undecided;
  undecided.status = SolveStatus::kNoSolutionFound;
  if (start_claim) {
    undecided = claimed;
    undecided.status = SolveStatus::kFeasible;
    // The claim's own bound is its objective, unconfirmed: without the
    // relaxation's bound there is none.
    undecided.best_bound = relaxed.status == SolveStatus::kOptimal
                               ? relaxed.objective
                               : -sign * std::numeric_limits<double>::infinity();
    undecided.gap = RelativeGap(undecided.objective, undecided.best_bound);
  }
  undecided.nodes = claimed.nodes + retry.nodes;
  undecided.incumbents = claimed.incumbents;
  undecided.solver_version = claimed.solver_version;
  undecided.detail = why + "; unconfirmed: " + second_run + " ended " +
                     std::string(ToString(retry.status)) + " (" + retry.detail + ")";
  return undecided;
}

// The MIP start, polished; empty if none, or rejected (detail says why).
Eigen::VectorXd PrepareStart(const LpData& lp, const SolveOptions& options, std::string* detail) {
  if (!options.initial_solution.has_value()) return {};
  Eigen::VectorXd x0 = *options.initial_solution;
  if (internal::Polish(lp, options, &x0)) {
    *detail += "initial solution accepted; ";
    return x0;
  }
  *detail += "initial solution rejected (violation " + FormatG(lp.MaxViolation(x0), 10) + "); ";
  return {};
}

// Runs the driver in a child process, or here (one at a time per process:
// the wait is not charged to this solve, so its result does not depend on
// other threads; the interrupt flag is honoured while waiting).
DriverOutcome RunDriver(DriverRequest* request, Recorder* recorder, std::string* detail) {
  const SolveOptions& options = request->options;
  if (options.cbc.separate_process) {
    return internal::RunDriverInChild(*request, recorder, options.cbc.stop_grace_s);
  }
  std::unique_lock<std::timed_mutex> lock(DriverMutex(), std::defer_lock);
  const Clock::time_point wait_start = Clock::now();
  while (!lock.try_lock_for(std::chrono::milliseconds(50))) {
    if (recorder->StopRequested()) break;
  }
  const Clock::duration waited = Clock::now() - wait_start;
  if (waited > std::chrono::milliseconds(10)) {
    request->clock.Shift(waited);
    *detail += "waited " + FormatG(SolveClock::Seconds(waited), 10) +
               " s for the CBC driver (another solve held it; not counted); ";
  }
  if (!lock.owns_lock()) {
    DriverOutcome out;
    out.stopped = out.stopped_by_request = out.root_lp_stopped = true;
    out.detail = "stopped before the solve started";
    return out;
  }
  return internal::RunDriverHere(*request, recorder);
}

// The best verified point among the driver's final solution, the best
// incumbent it reported on the way and the start. The driver drops its
// incumbent when a limit falls in its root heuristics or before its
// post-processing; the reported one is then completed in the original
// column space (CBC's preprocessing removed some columns).
Eigen::VectorXd ChooseSolution(const LpData& lp, const SolveOptions& options,
                               const DriverOutcome& out, const Recorder& recorder,
                               const Eigen::VectorXd& start_x, std::string* detail) {
  const double sign = internal::ObjectiveSign(lp);
  auto better = [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return b.size() == 0 || sign * lp.Objective(a) < sign * lp.Objective(b) - 1e-9;
  };
  Eigen::VectorXd x;
  if (out.x.size() > 0) {
    x = out.x;
    if (!internal::CompletePartial(lp, options, &x)) {
      *detail += "; CBC solution violates the model by " + FormatG(lp.MaxViolation(x), 10);
      x.resize(0);
    }
  }
  const Eigen::VectorXd& reported = recorder.best_x();
  const bool reported_better =
      reported.size() > 0 &&
      (x.size() == 0 || sign * recorder.best_objective() < sign * lp.Objective(x) - 1e-9);
  if (reported_better) {
    Eigen::VectorXd y = reported;
    if (internal::CompletePartial(lp, options, &y) && better(y, x)) {
      x = y;
      *detail += "; kept the incumbent CBC reported at " + FormatG(recorder.best_wall(), 10) +
                 " s (its driver " + (out.x.size() > 0 ? "ended with a worse one)" : "lost it)");
    } else {
      *detail += "; the incumbent CBC reported at " + FormatG(recorder.best_wall(), 10) +
                 " s could not be completed into a feasible point";
    }
  }
  if (start_x.size() > 0 && better(start_x, x)) x = start_x;
  return x;
}

// An unbounded relaxation: the MILP is unbounded if it has an integer point
// (rational data). Looks for one with a zero objective.
SolveStatus ClassifyUnbounded(const Solver& solver, const LpData& lp, const SolveOptions& options,
                              const SolveClock& clock, std::string* detail) {
  LpData feasibility = lp;
  feasibility.col_cost.setZero();
  feasibility.objective_offset = 0.0;
  feasibility.sense = ObjectiveSense::kMinimize;
  SolveOptions o = options;
  o.progress = nullptr;
  o.initial_solution.reset();
  o.time_limit_s = std::max(0.0, clock.Remaining());
  const SolveResult f = solver.Solve(feasibility, o);
  if (f.status == SolveStatus::kInfeasible) {
    *detail += "; LP relaxation unbounded but no integer point";
    return SolveStatus::kInfeasible;
  }
  *detail += f.has_solution() ? "; LP relaxation unbounded and an integer point exists"
                              : "; LP relaxation unbounded, integer feasibility not established";
  return SolveStatus::kUnbounded;
}

// The bound to report with a solution of objective `objective`: CBC's best
// bound, kept on the right side of the objective. When CBC ends its search
// "optimal", its last reported bound may predate the end; the claim itself
// says the gap is within the tolerances, so the bound is at least the
// objective less the allowed gap (and the objective itself when the search
// was exhausted under a cutoff at the start).
double FinalBound(const LpData& lp, const SolveOptions& options, const DriverOutcome& out,
                  SolveStatus status, double objective) {
  const double sign = internal::ObjectiveSign(lp);
  double bound = std::abs(out.bound_min) < internal::kCbcInfinity
                     ? sign * out.bound_min + lp.objective_offset
                     : (sign > 0 ? -kInf : kInf);
  if (status == SolveStatus::kOptimal) {
    const double allowed =
        out.proven_optimal ? std::max(options.absolute_gap,
                                      options.relative_gap * std::max(1e-10, std::abs(objective)))
                           : 0.0;
    const double claimed = objective - sign * allowed;
    if (!std::isfinite(bound) || sign * bound < sign * claimed) bound = claimed;
  }
  if (std::isfinite(bound) && sign * bound > sign * objective) bound = objective;
  return bound;
}

SolveResult CbcSolverImpl::SolveOnce(const LpData& lp, const SolveOptions& options,
                                     bool* cbc_claim) const {
  if (cbc_claim != nullptr) *cbc_claim = false;
  SolveClock clock(options.time_limit_s, options.interrupt);
  Recorder recorder(lp, options, &clock);
  auto finish = [&](SolveResult r) {
    r.solver_version = CbcVersion();
    r.wall_seconds = clock.Elapsed();
    recorder.RethrowCallbackError();
    return r;
  };
  if (lp.num_cols() == 0 || lp.num_rows() == 0) {
    SolveResult r = internal::SolveTrivial(lp);
    if (r.has_solution()) recorder.RecordOwn(r.objective);
    return finish(r);
  }
  if (!lp.is_mip()) return finish(SolveContinuous(lp, options, &clock));

  std::string detail;
  const Eigen::VectorXd start_x = PrepareStart(lp, options, &detail);
  const bool have_start = start_x.size() > 0;
  const double sign = internal::ObjectiveSign(lp);
  if (have_start) recorder.RecordOwn(lp.Objective(start_x));

  DriverRequest request{lp, options, clock, start_x,
                        have_start ? sign * lp.col_cost.dot(start_x) : kInf};
  DriverOutcome out;
  if (recorder.StopRequested()) {
    out.stopped = out.stopped_by_request = out.root_lp_stopped = true;
    out.detail = "stopped before the solve started";
  } else {
    out = RunDriver(&request, &recorder, &detail);
  }
  detail += out.detail;
  const Eigen::VectorXd x = ChooseSolution(lp, options, out, recorder, start_x, &detail);
  const bool has_x = x.size() > 0;
  auto limit = [&]() -> std::string {
    if (recorder.known_bound_reached()) return "an incumbent within the gap of the known bound";
    if (clock.stopped_by_interrupt()) return "interrupted";
    if (options.max_nodes >= 0 && !clock.DeadlinePassed() && out.status == 1) return "node limit";
    return "time limit";
  };

  SolveResult r;
  r.nodes = out.nodes;
  const bool limited = out.stopped || clock.DeadlinePassed() || clock.stopped_by_interrupt();
  if (!out.completed || out.root_lp_stopped || (limited && !out.proven_optimal)) {
    // Whatever CBC concluded from a run that a limit stopped (an LP cut short
    // reads as infeasible) or that we lost, it proves nothing.
    r.status = has_x ? SolveStatus::kFeasible : SolveStatus::kNoSolutionFound;
    if (!out.completed && !limited && !has_x) r.status = SolveStatus::kError;
    if (out.root_lp_stopped) {
      detail += "; " + limit() + " in the root LP relaxation";
    } else if (limited) {
      detail += "; " + limit();
    }
  } else if (out.proven_optimal || (out.status == 0 && out.proven_infeasible && has_x)) {
    // (With the start as cutoff, "infeasible" means nothing better than it.)
    r.status = has_x ? SolveStatus::kOptimal : SolveStatus::kInfeasible;
    if (cbc_claim != nullptr && !out.proven_optimal) *cbc_claim = true;
  } else if (out.continuous_unbounded) {
    r.status =
        has_x ? SolveStatus::kUnbounded : ClassifyUnbounded(*this, lp, options, clock, &detail);
  } else if (out.proven_infeasible) {
    r.status = SolveStatus::kInfeasible;
    if (cbc_claim != nullptr) *cbc_claim = true;
  } else {
    r.status = SolveStatus::kError;
  }
  if (has_x && r.has_solution()) {
    r.x = x;
    r.objective = lp.Objective(x);
    r.best_bound = FinalBound(lp, options, out, r.status, r.objective);
    if (!std::isnan(options.known_bound) && sign * options.known_bound > sign * r.best_bound) {
      r.best_bound =
          sign * options.known_bound > sign * r.objective ? r.objective : options.known_bound;
    }
    r.gap = RelativeGap(r.objective, r.best_bound);
  }
  r.incumbents = recorder.incumbents();
  if (r.has_solution() &&
      (r.incumbents.empty() || std::abs(r.incumbents.back().objective - r.objective) >
                                   1e-9 * std::max(1.0, std::abs(r.objective)))) {
    r.incumbents.push_back({clock.Elapsed(), r.objective, r.best_bound});
  }
  r.detail = detail;
  return finish(r);
}

}  // namespace

std::string CbcVersion() { return std::string("CBC ") + CBC_VERSION + " / CLP " + CLP_VERSION; }

std::unique_ptr<Solver> MakeCbcSolver() { return std::make_unique<CbcSolverImpl>(); }

}  // namespace thrustsched::milp
