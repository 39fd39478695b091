// CLP pieces of the CBC backend (see clp_lp.h).
#include "milp/internal/clp_lp.h"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "ClpEventHandler.hpp"
#include "ClpPresolve.hpp"
#include "ClpSimplex.hpp"
#include "ClpSolve.hpp"
#include "CoinMessageHandler.hpp"
#include "CoinTypes.hpp"
#include "OsiClpSolverInterface.hpp"

namespace thrustsched::milp::internal {
namespace {

static_assert(std::is_same<CoinBigIndex, int>::value,
              "CoinBigIndex must match Eigen's StorageIndex (int) of LpData::a_matrix");

constexpr double kInf = std::numeric_limits<double>::infinity();
const std::atomic<bool> kStopNow{true};  // an interrupt flag that is always set

// Drops every message: nothing is printed at log_level 0.
class SilentHandler : public CoinMessageHandler {
 public:
  SilentHandler() { setLogLevel(0); }
  int print() override { return 0; }
  CoinMessageHandler* clone() const override { return new SilentHandler(*this); }
};

// Stops CLP at the deadline or on interrupt, and reports progress (checked
// every 16 iterations, and every iteration of an interior point, whose
// iterations are few and long).
class LpStopHandler : public ClpEventHandler {
 public:
  // simplex_only: the LPs of a session (simplex solves whatever the
  // options' algorithm), reported but never under the interior point's cap.
  LpStopHandler(SolveClock* clock, const SolveOptions* options, bool simplex_only = false)
      : clock_(clock), options_(options), simplex_only_(simplex_only) {}
  int event(Event which) override {
    if (which != endOfIteration) return -1;
    ++count_;
    const bool interior = !simplex_only_ && options_ != nullptr &&
                          options_->lp_algorithm == LpAlgorithm::kBarrierNoCrossover;
    if (!interior && (count_ & 15) != 0) return -1;
    Progress();
    // CLP's interior point does not detect infeasibility: it iterates until
    // a limit (tens of seconds on a one-day HCW problem). A converging solve
    // of our models takes 40-120 iterations (a GEO week: about 70); past the cap the caller's
    // simplex fallback classifies the LP.
    if (interior && count_ > kMaxInteriorIterations) return 0;
    return clock_->ShouldStop() ? 0 : -1;
  }
  static constexpr unsigned kMaxInteriorIterations = 250;
  ClpEventHandler* clone() const override { return new LpStopHandler(*this); }

 private:
  void Progress() {
    if (options_ == nullptr || !options_->progress) return;
    const double wall = clock_->Elapsed();
    if (wall - last_ < options_->progress_interval_s) return;
    last_ = wall;
    SolveProgress p;
    p.wall_seconds = wall;
    p.phase = SolvePhase::kRootLp;
    p.in_root_lp = true;
    p.lp_iterations = count_;
    if (model_ != nullptr &&
        (simplex_only_ || options_->lp_algorithm != LpAlgorithm::kBarrierNoCrossover)) {
      p.lp_objective = model_->objectiveValue();
      p.lp_primal_infeasibility = model_->sumPrimalInfeasibilities();
    }
    options_->progress(p);  // callers' progress does not throw into CLP (SolveLpCore)
  }
  SolveClock* clock_;
  const SolveOptions* options_;
  bool simplex_only_;
  unsigned count_ = 0;
  double last_ = 0.0;
};

void RunLp(ClpSimplex* model, LpAlgorithm algorithm) {
  switch (algorithm) {
    case LpAlgorithm::kPrimal:
      model->primal();
      break;
    case LpAlgorithm::kDual:
      model->dual();
      break;
    case LpAlgorithm::kBarrier: {
      ClpSolve how;
      how.setSolveType(ClpSolve::useBarrier);
      model->initialSolve(how);
      // Clean-up from the barrier's basis (usually no iterations); it also
      // classifies problems the barrier misjudges (it can call an unbounded
      // LP optimal).
      model->dual();
      break;
    }
    case LpAlgorithm::kBarrierNoCrossover: {
      // No presolve: ClpSolve would otherwise "clean up" the postsolved
      // interior point with a primal simplex, which takes longer than the
      // barrier itself (measured on the GEO week: 130 s against 4 s).
      ClpSolve how;
      how.setSolveType(ClpSolve::useBarrierNoCross);
      how.setPresolveType(ClpSolve::presolveOff);
      model->initialSolve(how);
      break;
    }
  }
}

// Solves with presolve; false if presolve found nothing to solve (or failed),
// so that the caller solves the original model.
bool SolvePresolved(ClpSimplex* model, const SolveOptions& options, CoinMessageHandler* silent,
                    LpStopHandler* events, SolveClock* clock) {
  auto set_time = [clock](ClpSimplex* m) {
    const double remaining = clock->Remaining();
    if (std::isfinite(remaining)) m->setMaximumWallSeconds(std::max(remaining, 1e-3));
  };
  ClpPresolve presolve;
  ClpSimplex* reduced = presolve.presolvedModel(*model, 1e-8, false, 5);
  if (reduced == nullptr) return false;
  Silence(reduced, silent, options.log_level);
  reduced->passInEventHandler(events);
  set_time(reduced);
  RunLp(reduced, options.lp_algorithm);
  if (reduced->status() != 0) {
    delete reduced;
    return false;
  }
  presolve.postsolve(true);
  delete reduced;
  model->checkSolution();
  set_time(model);
  if (model->numberPrimalInfeasibilities() > 0 || model->numberDualInfeasibilities() > 0) {
    model->primal(1);
  }
  return true;
}

// Status 2 (dual infeasible): unbounded if the primal is feasible.
void ClassifyDualInfeasible(const ClpSimplex& model, const LpData& lp, const SolveOptions& options,
                            CoinMessageHandler* silent, LpStopHandler* events, SolveClock* clock,
                            LpOutcome* out) {
  ClpSimplex feas(model);
  Silence(&feas, silent, options.log_level);
  feas.passInEventHandler(events);
  std::vector<double> zero(static_cast<size_t>(lp.num_cols()), 0.0);
  feas.chgObjCoefficients(zero.data());
  const double remaining = clock->Remaining();
  if (std::isfinite(remaining)) feas.setMaximumWallSeconds(std::max(remaining, 1e-3));
  feas.primal();
  if (feas.status() == 0) {
    out->status = SolveStatus::kUnbounded;
  } else if (feas.status() == 1) {
    out->status = SolveStatus::kInfeasible;
  } else {
    out->status = SolveStatus::kUnbounded;
    out->detail = "clp: dual infeasible; primal feasibility not established";
  }
}

// Fixes the integer columns of lp at x's (rounded) values and makes them
// continuous: the LP of the continuous part.
LpData FixIntegers(const LpData& lp, const Eigen::VectorXd& x) {
  LpData fixed = lp;
  for (int j = 0; j < lp.num_cols(); ++j) {
    if (!IsInteger(lp, j)) continue;
    fixed.col_type[static_cast<size_t>(j)] = VarType::kContinuous;
    if (std::isnan(x[j])) continue;
    fixed.col_lower[j] = x[j];
    fixed.col_upper[j] = x[j];
  }
  return fixed;
}

// An LP solved to the end (no deadline, no interrupt): presolve and dual
// simplex, then, if that did not end optimal, primal simplex without
// presolve. (Dual simplex without presolve has called feasible fixed-integer
// LPs of the HCW and GEO transcriptions infeasible; CLP's barrier aborts the
// process, "primal off to infinity", on some of them, seen on a GEO week with
// six thrusters.)
LpOutcome SolveFinishingLp(const LpData& lp, const SolveOptions& options) {
  SolveOptions o = options;
  o.interrupt = nullptr;
  o.presolve = true;
  o.lp_algorithm = LpAlgorithm::kDual;
  const CoinArrays arrays = MakeArrays(lp, ObjectiveSign(lp), false);
  SolveClock unlimited;
  LpOutcome r = SolveLpCore(lp, arrays, o, &unlimited);
  if (r.status == SolveStatus::kOptimal) return r;
  o.presolve = false;
  o.lp_algorithm = LpAlgorithm::kPrimal;
  return SolveLpCore(lp, arrays, o, &unlimited);
}

}  // namespace

double ObjectiveSign(const LpData& lp) {
  return lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
}

bool IsInteger(const LpData& lp, int column) {
  return lp.col_type[static_cast<size_t>(column)] != VarType::kContinuous;
}

CoinArrays MakeArrays(const LpData& lp, double sign, bool round_integer_bounds) {
  CoinArrays c;
  c.a = lp.a_matrix;
  c.a.makeCompressed();
  const int n = lp.num_cols(), m = lp.num_rows();
  auto coin = [](double v) {
    if (v == kInf) return COIN_DBL_MAX;
    if (v == -kInf) return -COIN_DBL_MAX;
    return v;
  };
  c.col_lower.resize(static_cast<size_t>(n));
  c.col_upper.resize(static_cast<size_t>(n));
  c.cost.resize(static_cast<size_t>(n));
  for (int j = 0; j < n; ++j) {
    double lo = lp.col_lower[j], up = lp.col_upper[j];
    if (round_integer_bounds && IsInteger(lp, j)) {
      lo = IntegerLowerBound(lo);
      up = IntegerUpperBound(up);
    }
    c.col_lower[static_cast<size_t>(j)] = coin(lo);
    c.col_upper[static_cast<size_t>(j)] = coin(up);
    c.cost[static_cast<size_t>(j)] = sign * lp.col_cost[j];
  }
  c.row_lower.resize(static_cast<size_t>(m));
  c.row_upper.resize(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) {
    c.row_lower[static_cast<size_t>(i)] = coin(lp.row_lower[i]);
    c.row_upper[static_cast<size_t>(i)] = coin(lp.row_upper[i]);
  }
  return c;
}

void LoadClp(ClpSimplex* clp, const CoinArrays& c) {
  clp->loadProblem(static_cast<int>(c.a.cols()), static_cast<int>(c.a.rows()), c.a.outerIndexPtr(),
                   c.a.innerIndexPtr(), c.a.valuePtr(), c.col_lower.data(), c.col_upper.data(),
                   c.cost.data(), c.row_lower.data(), c.row_upper.data());
}

void LoadOsi(OsiClpSolverInterface* si, const CoinArrays& c, const LpData& lp) {
  si->loadProblem(static_cast<int>(c.a.cols()), static_cast<int>(c.a.rows()), c.a.outerIndexPtr(),
                  c.a.innerIndexPtr(), c.a.valuePtr(), c.col_lower.data(), c.col_upper.data(),
                  c.cost.data(), c.row_lower.data(), c.row_upper.data());
  for (int j = 0; j < lp.num_cols(); ++j) {
    if (IsInteger(lp, j)) si->setInteger(j);
  }
}

std::unique_ptr<CoinMessageHandler> MakeSilentHandler() {
  return std::make_unique<SilentHandler>();
}

void Silence(ClpSimplex* clp, CoinMessageHandler* handler, int log_level) {
  if (log_level <= 0) {
    clp->passInMessageHandler(handler);
    clp->setLogLevel(0);
  } else {
    clp->setLogLevel(std::min(log_level - 1, 4));
  }
}

LpOutcome SolveLpCore(const LpData& lp, const CoinArrays& arrays, const SolveOptions& options,
                      SolveClock* clock) {
  LpOutcome out;
  const std::unique_ptr<CoinMessageHandler> silent = MakeSilentHandler();
  // A throwing progress callback stops the LP; the exception is rethrown here.
  std::exception_ptr progress_error;
  SolveOptions guarded = options;
  if (options.progress) {
    guarded.progress = [&](const SolveProgress& p) {
      if (progress_error) return;
      try {
        options.progress(p);
      } catch (...) {
        progress_error = std::current_exception();
        clock->set_interrupt(&kStopNow);
      }
    };
  }
  LpStopHandler events(clock, &guarded);
  ClpSimplex model;
  Silence(&model, silent.get(), options.log_level);
  LoadClp(&model, arrays);
  if (options.random_seed > 0) model.setRandomSeed(options.random_seed);
  model.passInEventHandler(&events);
  const bool solved = options.presolve && lp.num_rows() > 0 &&
                      options.lp_algorithm != LpAlgorithm::kBarrierNoCrossover &&
                      SolvePresolved(&model, options, silent.get(), &events, clock);
  if (!solved) {
    const double remaining = clock->Remaining();
    if (std::isfinite(remaining)) model.setMaximumWallSeconds(std::max(remaining, 1e-3));
    RunLp(&model, options.lp_algorithm);
  }
  out.iterations = model.numberIterations();
  const int status = model.status();
  if (status != 0 && options.lp_algorithm == LpAlgorithm::kBarrierNoCrossover &&
      ((status != 3 && status != 5) || !clock->ShouldStop())) {
    // The interior point does not classify infeasible or unbounded LPs well:
    // the simplex says what they are (primal: the dual simplex has called
    // feasible schedule LPs infeasible).
    SolveOptions simplex = options;
    simplex.lp_algorithm = LpAlgorithm::kPrimal;
    if (progress_error) std::rethrow_exception(progress_error);
    return SolveLpCore(lp, arrays, simplex, clock);
  }
  if (status == 0) {
    out.status = SolveStatus::kOptimal;
    out.min_objective = model.objectiveValue();
    out.x = Eigen::Map<const Eigen::VectorXd>(model.primalColumnSolution(), lp.num_cols());
    out.duals = Eigen::Map<const Eigen::VectorXd>(model.dualRowSolution(), lp.num_rows());
  } else if (status == 1) {
    out.status = SolveStatus::kInfeasible;
  } else if (status == 2) {
    ClassifyDualInfeasible(model, lp, options, silent.get(), &events, clock, &out);
  } else if (status == 3 || status == 5) {
    out.status = SolveStatus::kNoSolutionFound;
    out.detail = clock->stopped_by_interrupt() ? "interrupted" : "time limit";
  } else {
    out.status = SolveStatus::kError;
    out.detail = "clp status " + std::to_string(status) + " secondary " +
                 std::to_string(model.secondaryStatus());
  }
  if (progress_error) std::rethrow_exception(progress_error);
  return out;
}

bool Polish(const LpData& lp, const SolveOptions& options, Eigen::VectorXd* x) {
  bool any_continuous = false;
  bool costed_continuous = false;
  for (int j = 0; j < lp.num_cols(); ++j) {
    if (IsInteger(lp, j)) {
      (*x)[j] = std::round((*x)[j]);
    } else {
      any_continuous = true;
      costed_continuous = costed_continuous || lp.col_cost[j] != 0.0;
    }
  }
  // A feasible point whose continuous columns cost nothing cannot improve.
  const bool feasible = lp.MaxViolation(*x) <= kFeasibilityTolerance;
  if (any_continuous && lp.num_rows() > 0 && (!feasible || costed_continuous)) {
    const double sign = ObjectiveSign(lp);
    const LpOutcome r = SolveFinishingLp(FixIntegers(lp, *x), options);
    if (r.status == SolveStatus::kOptimal) {
      Eigen::VectorXd candidate = r.x;
      for (int j = 0; j < lp.num_cols(); ++j) {
        if (IsInteger(lp, j)) candidate[j] = (*x)[j];
      }
      // Keep the re-optimised point only if it is feasible and no worse.
      if (lp.MaxViolation(candidate) <= kFeasibilityTolerance &&
          (lp.MaxViolation(*x) > kFeasibilityTolerance ||
           sign * lp.Objective(candidate) <= sign * lp.Objective(*x) + 1e-9)) {
        *x = candidate;
      }
    }
  }
  return lp.MaxViolation(*x) <= kFeasibilityTolerance;
}

bool CompletePartial(const LpData& lp, const SolveOptions& options, Eigen::VectorXd* x) {
  if (options.complete_solution) {
    Eigen::VectorXd y = *x;
    for (int j = 0; j < lp.num_cols(); ++j) {
      if (IsInteger(lp, j) && !std::isnan(y[j])) y[j] = std::round(y[j]);
    }
    if (options.complete_solution(&y) && y.size() == lp.num_cols() &&
        lp.MaxViolation(y) <= kFeasibilityTolerance) {
      *x = y;
      return true;
    }
  }
  bool unknown_integer = false;
  for (int j = 0; j < lp.num_cols(); ++j) {
    if (std::isnan((*x)[j]) && IsInteger(lp, j)) unknown_integer = true;
  }
  if (unknown_integer) {
    // The removed columns were fixed by CBC's preprocessing (implied by the
    // others): the LP over them, with the known integers fixed, finds them.
    const LpOutcome r = SolveFinishingLp(FixIntegers(lp, *x), options);
    if (r.status != SolveStatus::kOptimal) return false;
    for (int j = 0; j < lp.num_cols(); ++j) {
      if (std::isnan((*x)[j])) (*x)[j] = r.x[j];
    }
  }
  for (int j = 0; j < lp.num_cols(); ++j) {
    if (std::isnan((*x)[j])) (*x)[j] = 0.0;  // continuous: re-optimised by Polish
  }
  return Polish(lp, options, x);
}

SolveResult SolveTrivial(const LpData& lp) {
  SolveResult r;
  const int n = lp.num_cols(), m = lp.num_rows();
  const double sign = ObjectiveSign(lp);
  if (n == 0) {
    for (int i = 0; i < m; ++i) {
      if (lp.row_lower[i] > kFeasibilityTolerance || lp.row_upper[i] < -kFeasibilityTolerance) {
        r.status = SolveStatus::kInfeasible;
        r.detail = "empty model: row " + std::to_string(i) + " cannot hold with no columns";
        return r;
      }
    }
    r.status = SolveStatus::kOptimal;
    r.x = Eigen::VectorXd(0);
    r.objective = r.best_bound = lp.objective_offset;
    r.gap = 0.0;
    r.detail = "empty model (no columns)";
    r.incumbents.push_back({0.0, r.objective, r.best_bound});
    return r;
  }
  // No rows: each column on its own.
  Eigen::VectorXd x(n);
  bool unbounded = false;
  for (int j = 0; j < n; ++j) {
    double lo = lp.col_lower[j], up = lp.col_upper[j];
    if (IsInteger(lp, j)) {
      lo = IntegerLowerBound(lo);
      up = IntegerUpperBound(up);
    }
    if (lo > up) {
      r.status = SolveStatus::kInfeasible;
      r.detail = "no rows: integer column " + std::to_string(j) + " has no integer value in [" +
                 std::to_string(lp.col_lower[j]) + ", " + std::to_string(lp.col_upper[j]) + "]";
      return r;
    }
    const double c = sign * lp.col_cost[j];
    if (c > 0.0) {
      x[j] = lo;
    } else if (c < 0.0) {
      x[j] = up;
    } else {
      x[j] = std::min(std::max(0.0, lo), up);
    }
    if (!std::isfinite(x[j])) unbounded = true;
  }
  if (unbounded) {
    r.status = SolveStatus::kUnbounded;
    r.detail = "no rows: a column with nonzero cost is unbounded in its improving direction";
    return r;
  }
  r.status = SolveStatus::kOptimal;
  r.x = x;
  r.objective = r.best_bound = lp.Objective(x);
  r.gap = 0.0;
  r.detail = "no rows: solved column by column";
  r.incumbents.push_back({0.0, r.objective, r.best_bound});
  return r;
}

namespace {

class ClpSession final : public LpSession {
 public:
  ClpSession(const LpData& lp, const SolveOptions& options)
      : lp_(lp),
        options_(options),
        clock_(options.time_limit_s, options.interrupt),
        silent_(MakeSilentHandler()),
        stop_(&clock_, &options_, /*simplex_only=*/true) {
    std::fill(lp_.col_type.begin(), lp_.col_type.end(), VarType::kContinuous);
    sign_ = ObjectiveSign(lp_);
    Silence(&model_, silent_.get(), options.log_level);
    LoadClp(&model_, MakeArrays(lp_, sign_, false));
    if (options.random_seed > 0) model_.setRandomSeed(options.random_seed);
    model_.passInEventHandler(&stop_);
  }

  void SetColumnBounds(int j, double lower, double upper) override {
    lp_.col_lower[j] = lower;
    lp_.col_upper[j] = upper;
    model_.setColumnBounds(j, lower == -kInf ? -COIN_DBL_MAX : lower,
                           upper == kInf ? COIN_DBL_MAX : upper);
  }
  void SetPivotLimit(long long pivots) override { pivot_limit_ = pivots; }
  double column_lower(int j) const override { return lp_.col_lower[j]; }
  double column_upper(int j) const override { return lp_.col_upper[j]; }
  void CrossOverFrom(const Eigen::VectorXd& x, const Eigen::VectorXd& row_duals) override {
    if (x.size() != lp_.num_cols() || row_duals.size() != lp_.num_rows())
      throw std::invalid_argument("LpSession::CrossOverFrom: " + std::to_string(x.size()) +
                                  " values and " + std::to_string(row_duals.size()) +
                                  " duals for an LP of " + std::to_string(lp_.num_cols()) +
                                  " columns and " + std::to_string(lp_.num_rows()) + " rows");
    start_x_ = x;
    start_duals_ = sign_ * row_duals;  // CLP's minimisation form
  }

  // CLP's status of each column and row (basic, at a bound, ...): the dual
  // simplex factorises the basis it names at its start.
  std::vector<unsigned char> SaveBasis() const override {
    if (first_ || !model_.statusExists()) return {};
    const unsigned char* status = const_cast<ClpSimplex&>(model_).statusArray();
    return {status, status + model_.numberColumns() + model_.numberRows()};
  }
  void RestoreBasis(const std::vector<unsigned char>& basis) override {
    if (basis.size() != static_cast<size_t>(model_.numberColumns() + model_.numberRows())) return;
    model_.copyinStatus(basis.data());
  }

  LpRelaxationResult Solve() override {
    const double start = clock_.Elapsed();
    const double remaining = clock_.Remaining();
    if (std::isfinite(remaining)) model_.setMaximumWallSeconds(std::max(remaining, 1e-3));
    // Each of CLP's primal() and dual() counts its pivots from zero.
    int pivots = 0;
    if (start_x_.size() > 0) {
      pivots = CrossOver() + Dual();  // the dual simplex: clean-up (usually no pivots)
    } else if (first_) {
      // From scratch: presolve and dual simplex (or an interior point and
      // its crossover) leave an optimal basis on the original model, the warm
      // start of the next solves. The interior point on request: on a
      // six-thruster GEO week (289 k nonzeros) barrier and crossover take
      // 11 s where the dual simplex from scratch takes minutes.
      ClpSolve how;
      const bool barrier = options_.lp_algorithm == LpAlgorithm::kBarrier ||
                           options_.lp_algorithm == LpAlgorithm::kBarrierNoCrossover;
      how.setSolveType(barrier ? ClpSolve::useBarrier : ClpSolve::useDual);
      how.setPresolveType(options_.presolve ? ClpSolve::presolveOn : ClpSolve::presolveOff);
      model_.initialSolve(how);
      pivots = model_.numberIterations();
      if (barrier && model_.status() == 0) pivots += Dual();  // clean-up (usually no pivots)
    } else {
      // CLP counts each dual()'s pivots from zero.
      if (pivot_limit_ >= 0)
        model_.setMaximumIterations(static_cast<int>(std::min<long long>(pivot_limit_, INT_MAX)));
      pivots = Dual();
      model_.setMaximumIterations(INT_MAX);
    }
    first_ = false;
    LpRelaxationResult r;
    r.iterations = pivots;
    const int status = model_.status();
    if (status == 0) {
      r.status = SolveStatus::kOptimal;
      r.x = Eigen::Map<const Eigen::VectorXd>(model_.primalColumnSolution(), lp_.num_cols());
      r.objective = lp_.Objective(r.x);
      r.row_duals =
          sign_ * Eigen::Map<const Eigen::VectorXd>(model_.dualRowSolution(), lp_.num_rows());
      r.detail = "clp";
    } else if (status == 1) {
      r.status = SolveStatus::kInfeasible;
      r.detail = "clp: infeasible";
    } else if (status == 2) {
      r.status = SolveStatus::kUnbounded;
      r.detail = "clp: dual infeasible";
    } else if (status == 3 || status == 5) {
      r.status = SolveStatus::kNoSolutionFound;
      r.detail = clock_.stopped_by_interrupt()                 ? "interrupted"
                 : pivot_limit_ >= 0 && pivots >= pivot_limit_ ? "pivot limit"
                                                               : "time limit";
    } else {
      r.status = SolveStatus::kError;
      r.detail = "clp status " + std::to_string(status);
    }
    r.wall_seconds = clock_.Elapsed() - start;
    return r;
  }

 private:
  // The dual simplex from the current basis; returns its pivots.
  int Dual() {
    model_.dual();
    return model_.numberIterations();
  }

  // From the start point (CrossOverFrom) to a basis, as CLP's own crossover
  // after its interior point (ClpSolve, useBarrier): columns within 10 primal
  // tolerances of a bound at it, the others superbasic, the farthest from
  // their bounds (those with a zero reduced cost first) basic as far as
  // there are rows, every row superbasic; then the primal simplex. On week
  // 10 of data/scenarios/hard/ (six thrusters, 285 k nonzeros) 1.4-2 s in
  // the tree's session (`thrustsched solve` prints it), where the interior
  // point and its crossover took 11-13 s.
  //
  // Unlike CLP's, first every column whose reduced cost exceeds 10 dual
  // tolerances goes to the bound it prices toward, however far the point
  // is from it: by complementary slackness every optimum for these duals
  // holds it there. A central interior point leaves such columns strictly
  // inside, and the primal simplex then works them out pivot by pivot. On
  // week 33 of data/scenarios/hard/ the search's point left 17,490 columns
  // off their bounds (CLP's own point on the exported model 12,274) and the
  // crossover took 15,400 pivots and 61-71 s; with those columns at their
  // bounds 3,840 pivots and 1.2 s (thresholds from 1e-8 to 1e-5: 1.2-2.1 s).
  // Returns the primal simplex's pivots.
  int CrossOver() {
    const int n = model_.numberColumns(), m = model_.numberRows();
    const double* lower = model_.columnLower();
    const double* upper = model_.columnUpper();
    double* x = model_.primalColumnSolution();
    std::copy(start_x_.data(), start_x_.data() + n, x);
    std::copy(start_duals_.data(), start_duals_.data() + m, model_.dualRowSolution());
    double* reduced_cost = model_.dualColumnSolution();  // cost - A' duals
    std::copy(model_.objective(), model_.objective() + n, reduced_cost);
    model_.clpMatrix()->transposeTimes(-1.0, model_.dualRowSolution(), reduced_cost);
    start_x_.resize(0);
    start_duals_.resize(0);
    const double tolerance = model_.primalTolerance();
    const double priced_out = 10.0 * model_.dualTolerance();
    model_.createStatus();
    for (int i = 0; i < m; ++i) model_.setRowStatus(i, ClpSimplex::superBasic);
    std::vector<std::pair<double, int>> interior;  // (-distance, column)
    for (int j = 0; j < n; ++j) {
      double distance = std::min(upper[j] - x[j], x[j] - lower[j]);
      if (reduced_cost[j] > priced_out && lower[j] > -COIN_DBL_MAX) {
        model_.setColumnStatus(j, ClpSimplex::atLowerBound);
        x[j] = lower[j];
      } else if (reduced_cost[j] < -priced_out && upper[j] < COIN_DBL_MAX) {
        model_.setColumnStatus(j, ClpSimplex::atUpperBound);
        x[j] = upper[j];
      } else if (distance > 10.0 * tolerance) {
        if (std::abs(reduced_cost[j]) < 1e-5) distance *= 100.0;
        interior.push_back({-distance, j});
        model_.setColumnStatus(j, ClpSimplex::superBasic);
      } else if (distance > tolerance) {
        model_.setColumnStatus(j, ClpSimplex::superBasic);
      } else if (x[j] <= lower[j] + tolerance) {
        model_.setColumnStatus(j, ClpSimplex::atLowerBound);
        x[j] = lower[j];
      } else {
        model_.setColumnStatus(j, ClpSimplex::atUpperBound);
        x[j] = upper[j];
      }
    }
    std::sort(interior.begin(), interior.end());
    const size_t basic = std::min(interior.size(), static_cast<size_t>(m));
    for (size_t k = 0; k < basic; ++k)
      model_.setColumnStatus(interior[k].second, ClpSimplex::basic);
    const int perturbation = model_.perturbation();
    model_.setPerturbation(100);  // off, as CLP's crossover
    model_.primal(1);
    model_.setPerturbation(perturbation);
    return model_.numberIterations();
  }

  LpData lp_;
  SolveOptions options_;
  SolveClock clock_;
  std::unique_ptr<CoinMessageHandler> silent_;
  LpStopHandler stop_;
  ClpSimplex model_;
  double sign_ = 1.0;
  bool first_ = true;
  long long pivot_limit_ = -1;             // SetPivotLimit, warm solves
  Eigen::VectorXd start_x_, start_duals_;  // CrossOverFrom's point, until the next Solve
};

}  // namespace

std::unique_ptr<LpSession> OpenClpSession(const LpData& lp, const SolveOptions& options) {
  return std::make_unique<ClpSession>(lp, options);
}

}  // namespace thrustsched::milp::internal
