// CBC/CLP backend. The only translation unit (with mps_reader.cc) that sees
// COIN-OR headers.
//
// Design (guarantees in cbc_solver.h). MILPs go through the cbc driver
// (CbcMain0/CbcMain1 with "-solve"): its preprocessing, cut and heuristic
// settings are what make CBC strong, and with the default seeds
// (random_seed 0) a solve is the same run as the `cbc` program's on the
// exported MPS file. (A hand-assembled CbcModel::branchAndBound with the
// driver's generators and heuristics was tried first; matching the driver's
// many internal settings by hand proved fragile, so it was dropped.) The
// driver is not reentrant in the Debian build: it parses its arguments
// through process-wide globals (CbcOrClpRead_mode, CoinReadGetCommand:
// CbcSolver.o references them undefined, so the CBC_THREAD_SAFE copies are
// not compiled in), installs a process-wide SIGINT handler around the search,
// and CglZeroHalf's Cgl012cut keeps its tabu search in file-static arrays.
// Two unlocked concurrent driver calls were measured to corrupt each other
// (2 of 20 paired runs returned status -1). So driver calls are serialised by
// a process-wide mutex. Everything else (model building, LP relaxations and
// pure LPs through ClpSimplex/ClpPresolve, MIP-start polishing) runs
// concurrently.
#include "milp/cbc_solver.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <mutex>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

// COIN-OR.
#include "CbcConfig.h"
#include "CbcEventHandler.hpp"
#include "CbcModel.hpp"
#include "CbcSolver.hpp"
#include "ClpConfig.h"
#include "ClpEventHandler.hpp"
#include "ClpPresolve.hpp"
#include "ClpSimplex.hpp"
#include "ClpSolve.hpp"
#include "CoinError.hpp"
#include "CoinMessageHandler.hpp"
#include "CoinTypes.hpp"
#include "OsiClpSolverInterface.hpp"

namespace thrustsched::milp {
namespace {

static_assert(std::is_same<CoinBigIndex, int>::value,
              "CoinBigIndex must match Eigen's StorageIndex (int) of LpData::a_matrix");

using Clock = std::chrono::steady_clock;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Feasibility tolerance for accepting a point (MIP start, final solution).
constexpr double kFeasibilityTolerance = 1e-6;

// ----------------------------------------------------------------- logging

// Drops every message: nothing is printed at log_level 0.
class SilentHandler : public CoinMessageHandler {
 public:
  SilentHandler() { setLogLevel(0); }
  int print() override { return 0; }
  CoinMessageHandler* clone() const override { return new SilentHandler(*this); }
};

// ----------------------------------------------------------- stop control

// Shared by the event handlers of one solve (and their clones).
struct Control {
  Clock::time_point start;
  Clock::time_point deadline;
  bool has_deadline = false;
  const std::atomic<bool>* interrupt = nullptr;
  std::function<void(const SolveProgress&)> progress;
  double progress_interval_s = 5.0;
  double sign = 1.0;    // model objective = sign * (CBC objective) + offset
  double offset = 0.0;
  bool driver = false;  // the cbc driver is running
  CbcModel* main = nullptr;  // the driver's branch-and-cut model, once seen
  std::mutex mu;  // guards everything below
  double last_bound = -kInf;  // best CBC (minimisation) bound seen
  double last_recorded = kInf;  // best CBC (minimisation) objective recorded
  double last_progress = -kInf;
  std::vector<Incumbent> incumbents;
  std::exception_ptr callback_error;
  bool stopped_by_interrupt = false;
  // Set by the first CBC event of the driver's search (from then on CBC's
  // own time checks run); until then the root LP is stopped by
  // RootLpEventHandler, which records it in root_lp_stopped.
  std::atomic<bool> search_started{false};
  std::atomic<bool> root_lp_stopped{false};

  double Elapsed() const { return std::chrono::duration<double>(Clock::now() - start).count(); }
  double Remaining() const {
    if (!has_deadline) return kInf;
    return std::chrono::duration<double>(deadline - Clock::now()).count();
  }
  bool Interrupted() const {
    return interrupt != nullptr && interrupt->load(std::memory_order_relaxed);
  }
  bool ShouldStop() {
    if (Interrupted()) {
      stopped_by_interrupt = true;
      return true;
    }
    return callback_error != nullptr || (has_deadline && Clock::now() >= deadline);
  }
  double ToModel(double cbc_objective) const { return sign * cbc_objective + offset; }

  // Caller holds mu.
  void Report(double wall, double objective, double bound, long long nodes, bool incumbent) {
    if (!progress || callback_error != nullptr) return;
    SolveProgress p;
    p.wall_seconds = wall;
    p.objective = objective;
    p.best_bound = bound;
    if (std::isfinite(objective) && std::isfinite(bound)) {
      p.gap = std::abs(objective - bound) / std::max(1e-10, std::abs(objective));
    }
    p.nodes = nodes;
    p.new_incumbent = incumbent;
    last_progress = wall;
    try {
      progress(p);
    } catch (...) {
      callback_error = std::current_exception();
    }
  }

  // Progress while the driver is still in its root LP (no CBC event yet).
  void RootHeartbeat() {
    if (!progress) return;
    std::lock_guard<std::mutex> lock(mu);
    const double wall = Elapsed();
    if (callback_error != nullptr || wall - last_progress < progress_interval_s) return;
    last_progress = wall;
    SolveProgress p;
    p.wall_seconds = wall;
    p.in_root_lp = true;
    try {
      progress(p);
    } catch (...) {
      callback_error = std::current_exception();
    }
  }

  // Records an incumbent found by our own code (MIP start, polishing).
  void RecordOwn(double cbc_objective, double bound_model) {
    std::lock_guard<std::mutex> lock(mu);
    last_recorded = cbc_objective;
    const double wall = Elapsed();
    const double obj = ToModel(cbc_objective);
    incumbents.push_back({wall, obj, bound_model});
    Report(wall, obj, bound_model, 0, true);
  }

  // Looks at the model that raised an event: the driver's main branch-and-cut
  // model (no parent; sub-searches of heuristics have one) gives incumbents,
  // bounds and progress.
  void Observe(CbcModel* model, bool final_event) {
    search_started.store(true);
    std::lock_guard<std::mutex> lock(mu);
    if (!driver || model == nullptr || model->parentModel() != nullptr) return;
    main = model;
    const double best = model->getMinimizationObjValue();
    const double wall = Elapsed();
    const bool improved =
        best < 1e50 && best < last_recorded - 1e-12 * std::max(1.0, std::abs(best));
    // The bound walks the whole tree: only on news, on the progress clock and
    // at the end of the search.
    if (!improved && !final_event && wall - last_progress < progress_interval_s) return;
    const double bound = model->getBestPossibleObjValue();
    if (std::abs(bound) < 1e50 && bound > last_bound) last_bound = bound;
    const double bound_model =
        std::isfinite(last_bound) ? ToModel(last_bound) : (sign > 0 ? -kInf : kInf);
    double obj_model = kNaN;
    if (best < 1e50) obj_model = ToModel(best);
    if (improved) {
      last_recorded = best;
      incumbents.push_back({wall, obj_model, bound_model});
    }
    if (improved || wall - last_progress >= progress_interval_s) {
      Report(wall, obj_model, bound_model, model->getNodeCount(), improved);
    }
  }
};

class EventHandler : public CbcEventHandler {
 public:
  explicit EventHandler(Control* control) : control_(control) {}
  CbcAction event(CbcEvent which) override { return Handle(which); }
  CbcAction event(CbcEvent which, void* /*data*/) override { return Handle(which); }
  CbcEventHandler* clone() const override { return new EventHandler(*this); }

 private:
  CbcAction Handle(CbcEvent which) {
    // beforeSolution1/2 ask whether to accept a solution: never interfere.
    if (which == beforeSolution1 || which == beforeSolution2) return noAction;
    control_->Observe(model_, which == endSearch);
    if (control_->ShouldStop()) return stop;
    return noAction;
  }
  Control* control_;
};

// Stops CLP (root LP, LP relaxations) at the deadline or on interrupt.
class LpEventHandler : public ClpEventHandler {
 public:
  explicit LpEventHandler(Control* control) : control_(control) {}
  int event(Event which) override {
    if (which != endOfIteration) return -1;
    if ((++count_ & 15) != 0) return -1;
    return control_->ShouldStop() ? 0 : -1;
  }
  ClpEventHandler* clone() const override { return new LpEventHandler(*this); }

 private:
  Control* control_;
  unsigned count_ = 0;
};

// The cbc driver solves the root LP (and CglPreProcess's LPs) before its
// search starts, without looking at its time limit or at our interrupt flag
// (coin-or/Cbc#231, #514): on the larger scheduling models that is minutes.
// This handler, on the driver's CLP model (its clones inherit it), stops
// those LPs at the deadline or on interrupt; once the search has started
// (first CBC event) it never interferes, since stopping a node LP could make
// CBC prune that node as if it were infeasible. A stopped root LP proves
// nothing, so the result is then "no solution" (see root_lp_stopped).
class RootLpEventHandler : public ClpEventHandler {
 public:
  explicit RootLpEventHandler(Control* control) : control_(control) {}
  int event(Event which) override {
    if (which != endOfIteration) return -1;
    if ((++count_ & 15) != 0) return -1;
    if (control_->search_started.load()) return -1;
    control_->RootHeartbeat();
    if (!control_->ShouldStop()) return -1;
    control_->root_lp_stopped.store(true);
    return 0;
  }
  ClpEventHandler* clone() const override { return new RootLpEventHandler(*this); }

 private:
  Control* control_;
  unsigned count_ = 0;
};

// The cbc driver (CbcMain0/CbcMain1) keeps state in process-wide globals:
// one call at a time.
std::timed_mutex& DriverMutex() {
  static std::timed_mutex mutex;
  return mutex;
}

// ------------------------------------------------------------- problem data

double IntegerLower(double lo) {
  if (!std::isfinite(lo)) return lo;
  return std::ceil(lo - 1e-9 * std::max(1.0, std::abs(lo))) + 0.0;  // + 0.0: no -0
}
double IntegerUpper(double up) {
  if (!std::isfinite(up)) return up;
  return std::floor(up + 1e-9 * std::max(1.0, std::abs(up))) + 0.0;
}
bool IsInteger(const LpData& lp, int j) {
  return lp.col_type[static_cast<size_t>(j)] != VarType::kContinuous;
}

// Dense arrays in CBC's minimisation form: cost = sign * c, integer bounds
// rounded inward, infinities as COIN_DBL_MAX.
struct CoinArrays {
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> a;
  std::vector<double> col_lower, col_upper, cost, row_lower, row_upper;
};

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
      lo = IntegerLower(lo);
      up = IntegerUpper(up);
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
  clp->loadProblem(static_cast<int>(c.a.cols()), static_cast<int>(c.a.rows()),
                   c.a.outerIndexPtr(), c.a.innerIndexPtr(), c.a.valuePtr(), c.col_lower.data(),
                   c.col_upper.data(), c.cost.data(), c.row_lower.data(), c.row_upper.data());
}

void LoadOsi(OsiClpSolverInterface* si, const CoinArrays& c, const LpData& lp) {
  si->loadProblem(static_cast<int>(c.a.cols()), static_cast<int>(c.a.rows()),
                  c.a.outerIndexPtr(), c.a.innerIndexPtr(), c.a.valuePtr(), c.col_lower.data(),
                  c.col_upper.data(), c.cost.data(), c.row_lower.data(), c.row_upper.data());
  for (int j = 0; j < lp.num_cols(); ++j) {
    if (IsInteger(lp, j)) si->setInteger(j);
  }
}

std::string Num(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

// ------------------------------------------------------------------ LP core

struct LpOutcome {
  SolveStatus status = SolveStatus::kError;
  std::string detail;
  double min_objective = kNaN;  // CLP objective (minimisation form)
  Eigen::VectorXd x;
  Eigen::VectorXd duals;  // CLP row duals (minimisation form)
};

void Silence(ClpSimplex* clp, SilentHandler* handler, int log_level) {
  if (log_level <= 0) {
    clp->passInMessageHandler(handler);
    clp->setLogLevel(0);
  } else {
    clp->setLogLevel(std::min(log_level - 1, 4));
  }
}

// CbcMain1 calls this at fixed points of its actions; some actions (e.g.
// -primalS) call it without checking for null.
int DriverCallback(CbcModel* /*model*/, int /*where_from*/) { return 0; }

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
  }
}

// Solves min cost'x over the continuous relaxation with CLP. Primal and dual
// infeasibility are told apart by a zero-objective feasibility solve.
LpOutcome SolveLpCore(const LpData& lp, const CoinArrays& arrays, const SolveOptions& options,
                      Control* control) {
  LpOutcome out;
  SilentHandler silent;
  LpEventHandler events(control);
  ClpSimplex model;
  Silence(&model, &silent, options.log_level);
  LoadClp(&model, arrays);
  if (options.random_seed > 0) model.setRandomSeed(options.random_seed);
  model.passInEventHandler(&events);
  auto set_time = [&](ClpSimplex* m) {
    const double remaining = control->Remaining();
    if (std::isfinite(remaining)) m->setMaximumWallSeconds(std::max(remaining, 1e-3));
  };
  set_time(&model);
  bool solved = false;
  if (options.presolve && lp.num_rows() > 0) {
    ClpPresolve presolve;
    ClpSimplex* reduced = presolve.presolvedModel(model, 1e-8, false, 5);
    if (reduced != nullptr) {
      Silence(reduced, &silent, options.log_level);
      reduced->passInEventHandler(&events);
      set_time(reduced);
      RunLp(reduced, options.lp_algorithm);
      if (reduced->status() == 0) {
        presolve.postsolve(true);
        delete reduced;
        model.checkSolution();
        set_time(&model);
        if (model.numberPrimalInfeasibilities() > 0 || model.numberDualInfeasibilities() > 0) {
          model.primal(1);
        }
        solved = true;
      } else {
        delete reduced;
      }
    }
  }
  if (!solved) {
    set_time(&model);
    RunLp(&model, options.lp_algorithm);
  }
  const int status = model.status();
  if (status == 0) {
    out.status = SolveStatus::kOptimal;
    out.min_objective = model.objectiveValue();
    out.x = Eigen::Map<const Eigen::VectorXd>(model.primalColumnSolution(), lp.num_cols());
    out.duals = Eigen::Map<const Eigen::VectorXd>(model.dualRowSolution(), lp.num_rows());
  } else if (status == 1) {
    out.status = SolveStatus::kInfeasible;
  } else if (status == 2) {
    // Dual infeasible: unbounded if the primal is feasible.
    ClpSimplex feas(model);
    Silence(&feas, &silent, options.log_level);
    feas.passInEventHandler(&events);
    std::vector<double> zero(static_cast<size_t>(lp.num_cols()), 0.0);
    feas.chgObjCoefficients(zero.data());
    set_time(&feas);
    feas.primal();
    if (feas.status() == 0) {
      out.status = SolveStatus::kUnbounded;
    } else if (feas.status() == 1) {
      out.status = SolveStatus::kInfeasible;
    } else {
      out.status = SolveStatus::kUnbounded;
      out.detail = "clp: dual infeasible; primal feasibility not established";
    }
  } else if (status == 3 || status == 5) {
    out.status = SolveStatus::kNoSolutionFound;
    out.detail = control->stopped_by_interrupt ? "interrupted" : "time limit";
  } else {
    out.status = SolveStatus::kError;
    out.detail = "clp status " + std::to_string(status) + " secondary " +
                 std::to_string(model.secondaryStatus());
  }
  return out;
}

// ------------------------------------------------------------ small helpers

// Rounds the integer entries of x and, if there are continuous columns,
// re-optimises them with the integers fixed. Returns false if the result is
// not feasible within kFeasibilityTolerance.
bool Polish(const LpData& lp, const SolveOptions& options, Control* control, Eigen::VectorXd* x) {
  bool any_continuous = false;
  for (int j = 0; j < lp.num_cols(); ++j) {
    if (IsInteger(lp, j)) {
      (*x)[j] = std::round((*x)[j]);
    } else {
      any_continuous = true;
    }
  }
  if (any_continuous && lp.num_rows() > 0) {
    LpData fixed = lp;
    for (int j = 0; j < lp.num_cols(); ++j) {
      if (IsInteger(lp, j)) {
        fixed.col_lower[j] = (*x)[j];
        fixed.col_upper[j] = (*x)[j];
        fixed.col_type[static_cast<size_t>(j)] = VarType::kContinuous;
      }
    }
    const double sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
    SolveOptions lp_options = options;
    lp_options.presolve = false;
    // Dual simplex whatever the root LP algorithm: CLP's barrier aborts the
    // process ("primal off to infinity") on some of these fixed-integer LPs
    // (seen on a GEO week with six thrusters).
    lp_options.lp_algorithm = LpAlgorithm::kDual;
    const LpOutcome r = SolveLpCore(fixed, MakeArrays(fixed, sign, false), lp_options, control);
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

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double RelativeGap(double objective, double bound) {
  if (!std::isfinite(objective) || !std::isfinite(bound)) return kInf;
  return std::abs(objective - bound) / std::max(1e-10, std::abs(objective));
}

// Handles models without rows or without columns (CBC cannot).
SolveResult SolveTrivial(const LpData& lp) {
  SolveResult r;
  const int n = lp.num_cols(), m = lp.num_rows();
  const double sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
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
      lo = IntegerLower(lo);
      up = IntegerUpper(up);
    }
    if (lo > up) {
      r.status = SolveStatus::kInfeasible;
      r.detail = "no rows: integer column " + std::to_string(j) + " has no integer value in [" +
                 Num(lp.col_lower[j]) + ", " + Num(lp.col_upper[j]) + "]";
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

// ------------------------------------------------------------ the backend

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
};

void InitControl(Control* control, const LpData& lp, const SolveOptions& options) {
  control->start = Clock::now();
  control->has_deadline = std::isfinite(options.time_limit_s);
  if (control->has_deadline) {
    control->deadline =
        control->start + std::chrono::duration_cast<Clock::duration>(
                             std::chrono::duration<double>(options.time_limit_s));
  }
  control->interrupt = options.interrupt;
  control->progress = options.progress;
  control->progress_interval_s = options.progress_interval_s;
  control->sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
  control->offset = lp.objective_offset;
}

LpRelaxationResult CbcSolverImpl::DoSolveLpRelaxation(const LpData& lp,
                                                      const SolveOptions& options) const {
  Control control;
  InitControl(&control, lp, options);
  LpRelaxationResult r;
  LpData relaxed = lp;
  std::fill(relaxed.col_type.begin(), relaxed.col_type.end(), VarType::kContinuous);
  if (lp.num_cols() == 0 || lp.num_rows() == 0) {
    const SolveResult t = SolveTrivial(relaxed);
    r.status = t.status;
    r.detail = t.detail;
    r.objective = t.objective;
    r.x = t.x;
    if (t.status == SolveStatus::kOptimal) r.row_duals = Eigen::VectorXd::Zero(lp.num_rows());
    r.wall_seconds = control.Elapsed();
    return r;
  }
  const LpOutcome o = SolveLpCore(relaxed, MakeArrays(relaxed, control.sign, false), options,
                                  &control);
  r.status = o.status;
  r.detail = o.detail.empty() ? "clp" : "clp: " + o.detail;
  if (o.status == SolveStatus::kOptimal) {
    r.x = o.x;
    r.objective = lp.Objective(o.x);
    // CLP's duals are d(min objective)/d(rhs); the model's objective is
    // sign * (min objective) + offset.
    r.row_duals = control.sign * o.duals;
  }
  r.wall_seconds = control.Elapsed();
  return r;
}

SolveResult FromLpOutcome(const LpData& lp, const LpOutcome& o, Control* control) {
  SolveResult r;
  r.status = o.status;
  r.detail = o.detail.empty() ? "clp (no integer columns)" : "clp: " + o.detail;
  if (o.status == SolveStatus::kOptimal) {
    r.x = o.x;
    r.objective = lp.Objective(o.x);
    r.best_bound = r.objective;
    r.gap = 0.0;
    r.incumbents.push_back({control->Elapsed(), r.objective, r.best_bound});
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
  try {
    return SolveOnce(lp, options, cbc_claim);
  } catch (const CoinError& e) {
    if (!options.initial_solution.has_value() || !options.presolve) throw;
    SolveOptions again = options;
    again.presolve = false;
    if (std::isfinite(again.time_limit_s)) {
      again.time_limit_s = std::max(0.0, options.time_limit_s - Since(start));
    }
    SolveResult r = SolveOnce(lp, again, cbc_claim);
    r.detail = "CBC threw with the MIP start through its preprocessing (" + e.className() +
               "::" + e.methodName() + ": " + e.message() + "): solved again without preprocessing; " + r.detail;
    r.wall_seconds = Since(start);
    return r;
  }
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
    const double tol = std::max({options.absolute_gap,
                                 options.relative_gap * std::abs(claimed.objective), 1e-9}) + step;
    if (sign * relaxed.objective >= sign * claimed.objective - tol) {
      claimed.detail += "; optimality confirmed by the LP relaxation bound " +
                        Num(relaxed.objective);
      claimed.best_bound = relaxed.objective;
      return claimed;
    }
  }
  std::string why = "CBC reported " + std::string(start_claim ? "the start optimal" : "infeasible") +
                    " but the LP relaxation is " +
                    (relaxed.status == SolveStatus::kOptimal
                         ? "feasible with bound " + Num(relaxed.objective)
                         : std::string(ToString(relaxed.status)) + " (" + relaxed.detail + ")");
  // 2. A second, differently configured CBC run (without the start: it must
  // find its own solutions).
  SolveOptions second = options;
  second.presolve = false;
  second.disable_knapsack_cuts = true;
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
      claimed.detail += "; " + why + "; " + second_run + " reached the same verdict: " +
                        retry.detail;
      return claimed;
    }
    if (retry.has_solution()) {
      retry.detail = why + "; " + second_run + ": " + retry.detail;
      return retry;
    }
  } else {
    const double step = std::max(options.objective_step, 0.0);
    const double tol = std::max({options.absolute_gap,
                                 options.relative_gap * std::abs(claimed.objective), 1e-9}) + step;
    if (retry.has_solution() && sign * retry.objective < sign * claimed.objective - tol) {
      retry.detail = why + "; " + second_run + " found better: " + retry.detail;
      return retry;
    }
    if (retry.status == SolveStatus::kOptimal && !claim_again) {
      claimed.detail += "; " + why + "; " + second_run + " proved nothing better exists: " +
                        retry.detail;
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
    undecided.best_bound = relaxed.status == SolveStatus::kOptimal ? relaxed.objective
                                                                    : claimed.best_bound;
    undecided.gap = RelativeGap(undecided.objective, undecided.best_bound);
  }
  undecided.nodes = claimed.nodes + retry.nodes;
  undecided.incumbents = claimed.incumbents;
  undecided.solver_version = claimed.solver_version;
  undecided.detail = why + "; unconfirmed: " + second_run + " ended " +
                     std::string(ToString(retry.status)) + " (" + retry.detail + ")";
  return undecided;
}

SolveResult CbcSolverImpl::SolveOnce(const LpData& lp, const SolveOptions& options,
                                     bool* cbc_claim) const {
  if (cbc_claim != nullptr) *cbc_claim = false;
  Control control;
  InitControl(&control, lp, options);
  const double sign = control.sign;
  auto finish = [&](SolveResult r) {
    r.solver_version = CbcVersion();
    r.wall_seconds = control.Elapsed();
    if (control.callback_error) std::rethrow_exception(control.callback_error);
    return r;
  };
  if (lp.num_cols() == 0 || lp.num_rows() == 0) {
    SolveResult r = SolveTrivial(lp);
    if (r.has_solution() && options.progress) {
      std::lock_guard<std::mutex> lock(control.mu);
      control.Report(0.0, r.objective, r.best_bound, 0, true);
    }
    return finish(r);
  }
  const CoinArrays arrays = MakeArrays(lp, sign, true);
  if (!lp.is_mip()) {
    return finish(FromLpOutcome(lp, SolveLpCore(lp, arrays, options, &control), &control));
  }

  std::string detail;
  SilentHandler silent;
  const bool quiet = options.log_level <= 0;

  // ---- MIP start: round, re-optimise continuous part, check.
  Eigen::VectorXd start_x;
  double start_min = kInf;  // CBC objective of the start (minimisation form)
  if (options.initial_solution.has_value()) {
    Eigen::VectorXd x0 = *options.initial_solution;
    if (Polish(lp, options, &control, &x0)) {
      start_x = x0;
      start_min = sign * lp.col_cost.dot(x0);
      control.RecordOwn(start_min, sign > 0 ? -kInf : kInf);
      detail += "initial solution accepted; ";
    } else {
      detail += "initial solution rejected (violation " + Num(lp.MaxViolation(x0)) + "); ";
    }
  }
  const bool have_start = start_x.size() > 0;
  auto start_result = [&](SolveStatus status, const std::string& why) {
    SolveResult r;
    r.status = status;
    r.x = start_x;
    r.objective = lp.Objective(start_x);
    r.best_bound = status == SolveStatus::kOptimal ? r.objective : (sign > 0 ? -kInf : kInf);
    r.gap = RelativeGap(r.objective, r.best_bound);
    r.detail = detail + why;
    {
      std::lock_guard<std::mutex> lock(control.mu);
      r.incumbents = control.incumbents;
    }
    return r;
  };
  auto limit_status = [&]() {
    if (control.stopped_by_interrupt) return std::string("interrupted");
    return options.max_nodes >= 0 && !control.ShouldStop() ? std::string("node limit")
                                                           : std::string("time limit");
  };

  // ---- The cbc driver, one call at a time in this process. The time spent
  // waiting for it is not charged to this solve (the clock and the deadline
  // move by the wait), so a solve's result does not depend on what other
  // threads are doing; the interrupt flag is still honoured while waiting.
  std::unique_lock<std::timed_mutex> driver_lock(DriverMutex(), std::defer_lock);
  {
    const Clock::time_point wait_start = Clock::now();
    while (!driver_lock.try_lock_for(std::chrono::milliseconds(50))) {
      if (control.Interrupted()) break;
    }
    const Clock::duration waited = Clock::now() - wait_start;
    if (waited > std::chrono::milliseconds(10)) {
      std::lock_guard<std::mutex> lock(control.mu);
      control.start += waited;
      control.deadline += waited;
      detail += "waited " + Num(std::chrono::duration<double>(waited).count()) +
                " s for the CBC driver (another solve held it; not counted); ";
    }
  }
  if (!driver_lock.owns_lock() || control.ShouldStop()) {
    if (have_start) return finish(start_result(SolveStatus::kFeasible, limit_status()));
    SolveResult r;
    r.status = SolveStatus::kNoSolutionFound;
    r.detail = detail + limit_status() + " before the solve started";
    return finish(r);
  }
  OsiClpSolverInterface base;
  LoadOsi(&base, arrays, lp);
  if (control.has_deadline || control.interrupt != nullptr || control.progress) {
    RootLpEventHandler root_lp_events(&control);
    base.getModelPtr()->passInEventHandler(&root_lp_events);  // cloned
  }
  if (quiet) {
    base.passInMessageHandler(&silent);
    base.getModelPtr()->passInMessageHandler(&silent);
    base.messageHandler()->setLogLevel(0);
    base.getModelPtr()->setLogLevel(0);
  }
  base.setHintParam(OsiDoReducePrint, quiet, OsiHintTry);
  CbcModel model(base);
  if (quiet) {
    model.passInMessageHandler(&silent);
    model.setLogLevel(0);
  }
  EventHandler events(&control);
  model.passInEventHandler(&events);
  if (have_start) {
    std::vector<std::pair<std::string, double>> mip_start;
    mip_start.reserve(static_cast<size_t>(lp.num_cols()));
    for (int j = 0; j < lp.num_cols(); ++j) {
      mip_start.emplace_back(model.solver()->getColName(j), start_x[j]);
    }
    model.setMIPStart(mip_start);
  }
  // Arguments of the driver. Numbers with 17 digits.
  auto num = [](double v) {
    char buf[40];
    std::snprintf(buf, sizeof(buf), "%.17g", v);
    return std::string(buf);
  };
  std::vector<std::string> args = {"thrustsched", "-log", std::to_string(quiet ? 0 : options.log_level)};
  if (control.has_deadline) {
    args.insert(args.end(), {"-seconds", num(std::max(control.Remaining(), 1e-3)), "-timeMode",
                             "elapsed"});
  }
  args.insert(args.end(), {"-ratioGap", num(options.relative_gap), "-allowableGap",
                           num(options.absolute_gap)});
  if (options.random_seed > 0) {
    // 0 keeps CBC's own default seeds (then results equal the cbc program's).
    args.insert(args.end(), {"-randomCbcSeed", std::to_string(options.random_seed),
                             "-randomSeed", std::to_string(options.random_seed)});
  }
  if (have_start) {
    // Everything not better than the start is pruned; a completed search that
    // finds nothing proves the start optimal.
    args.insert(args.end(),
                {"-cutoff", num(start_min + 1e-9 * std::max(1.0, std::abs(start_min)))});
  }
  if (options.objective_step > 0.0) {
    // CBC prunes nodes whose bound exceeds incumbent - increment: stay just
    // below the step so a solution exactly one step better is never cut off.
    args.insert(args.end(), {"-increment", num(options.objective_step * (1.0 - 1e-4))});
  }
  if (!options.presolve) args.insert(args.end(), {"-preprocess", "off", "-presolve", "off"});
  if (options.disable_knapsack_cuts) args.insert(args.end(), {"-knapsackCuts", "off"});
  if (options.max_nodes >= 0) {
    args.insert(args.end(), {"-maxNodes", std::to_string(options.max_nodes)});
  }
  if (options.threads > 1) {
    if (CbcModel::haveMultiThreadSupport()) {
      args.insert(args.end(), {"-threads", std::to_string(options.threads)});
      detail += "threads=" + std::to_string(options.threads) +
                " (CBC parallel mode, not deterministic); ";
    } else {
      detail += "threads>1 ignored (CBC built without thread support); ";
    }
  }
  // The root LP is solved first as a separate driver action; the search then
  // starts from its basis.
  switch (options.lp_algorithm) {
    case LpAlgorithm::kPrimal:
      args.push_back("-primalS");
      break;
    case LpAlgorithm::kDual:
      break;  // the driver's default
    case LpAlgorithm::kBarrier:
      args.push_back("-barrier");
      break;
  }
  args.insert(args.end(), {"-solve", "-quit"});
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  {
    std::lock_guard<std::mutex> lock(control.mu);
    control.driver = true;
  }
  CbcSolverUsefulData driver_data;
  CbcMain0(model, driver_data);
  if (quiet) {
    model.passInMessageHandler(&silent);
    model.setLogLevel(0);
  }
  CbcMain1(static_cast<int>(argv.size()), argv.data(), model, DriverCallback, driver_data);
  {
    std::lock_guard<std::mutex> lock(control.mu);
    control.main = nullptr;
    control.driver = false;
  }
  driver_lock.unlock();

  // ---- Map the result back (the driver has undone its preprocessing).
  const int status = model.status();
  const int secondary = model.secondaryStatus();
  detail += "cbc status " + std::to_string(status) + " secondary " + std::to_string(secondary) +
            ", nodes " + std::to_string(model.getNodeCount());
  Eigen::VectorXd x;
  if (model.bestSolution() != nullptr && model.getMinimizationObjValue() < 1e50) {
    x = Eigen::Map<const Eigen::VectorXd>(model.bestSolution(), lp.num_cols());
    if (!Polish(lp, options, &control, &x)) {
      detail += "; CBC solution violates the model by " + Num(lp.MaxViolation(x));
      x.resize(0);
    }
  }
  // Prefer whichever of CBC's solution and the start is better.
  if (have_start && (x.size() == 0 || sign * lp.Objective(start_x) < sign * lp.Objective(x))) {
    x = start_x;
  }
  double bound_min;
  {
    std::lock_guard<std::mutex> lock(control.mu);
    bound_min = control.last_bound;
  }
  SolveResult r;
  r.nodes = model.getNodeCount();
  const bool has_x = x.size() > 0;
  const bool stopped = status == 1 || control.ShouldStop();
  if (control.root_lp_stopped.load()) {
    // Whatever CBC concluded from a root LP we stopped, it proves nothing.
    r.status = has_x ? SolveStatus::kFeasible : SolveStatus::kNoSolutionFound;
    detail += "; " + limit_status() + " in the root LP relaxation";
  } else if (model.isProvenOptimal() || (status == 0 && model.isProvenInfeasible() && has_x)) {
    // (With the start as cutoff, "infeasible" means nothing better than it.)
    r.status = SolveStatus::kOptimal;
    if (!has_x) r.status = SolveStatus::kInfeasible;
    if (cbc_claim != nullptr && !model.isProvenOptimal()) *cbc_claim = true;
  } else if (model.isContinuousUnbounded()) {
    r.status = SolveStatus::kUnbounded;
  } else if (model.isProvenInfeasible()) {
    r.status = SolveStatus::kInfeasible;
    if (cbc_claim != nullptr) *cbc_claim = true;
  } else if (stopped) {
    r.status = has_x ? SolveStatus::kFeasible : SolveStatus::kNoSolutionFound;
    detail += "; " + limit_status();
  } else {
    r.status = SolveStatus::kError;
  }
  if (r.status == SolveStatus::kUnbounded && !has_x) {
    // Unbounded relaxation: the MILP is unbounded if it has an integer point
    // (rational data). Look for one with a zero objective.
    LpData feasibility = lp;
    feasibility.col_cost.setZero();
    feasibility.objective_offset = 0.0;
    feasibility.sense = ObjectiveSense::kMinimize;
    SolveOptions o = options;
    o.progress = nullptr;
    o.initial_solution.reset();
    o.time_limit_s = std::max(0.0, control.Remaining());
    const SolveResult f = Solve(feasibility, o);
    if (f.status == SolveStatus::kInfeasible) {
      r.status = SolveStatus::kInfeasible;
      detail += "; LP relaxation unbounded but no integer point";
    } else {
      detail += f.has_solution() ? "; LP relaxation unbounded and an integer point exists"
                                 : "; LP relaxation unbounded, integer feasibility not established";
    }
  }
  if (has_x && (r.status == SolveStatus::kOptimal || r.status == SolveStatus::kFeasible)) {
    r.x = x;
    r.objective = lp.Objective(x);
    double bound_model = std::abs(bound_min) < 1e50 ? control.ToModel(bound_min)
                                                    : (sign > 0 ? -kInf : kInf);
    if (r.status == SolveStatus::kOptimal) {
      // Proven optimal within the gap tolerances. A bound outside them (or
      // none) was not the final one (e.g. the start was proven optimal by the
      // cutoff): the optimum itself is then the bound.
      const double diff = std::abs(r.objective - bound_model);
      if (!std::isfinite(bound_model) || sign * bound_model > sign * r.objective ||
          (diff > options.absolute_gap &&
           diff > options.relative_gap * std::max(1e-10, std::abs(r.objective)) * (1 + 1e-9))) {
        bound_model = r.objective;
      }
    } else if (std::isfinite(bound_model) && sign * bound_model > sign * r.objective) {
      bound_model = r.objective;
    }
    r.best_bound = bound_model;
    r.gap = RelativeGap(r.objective, r.best_bound);
    std::lock_guard<std::mutex> lock(control.mu);
    const double last = control.incumbents.empty() ? kNaN : control.incumbents.back().objective;
    if (control.incumbents.empty() ||
        std::abs(last - r.objective) > 1e-9 * std::max(1.0, std::abs(r.objective))) {
      control.incumbents.push_back({control.Elapsed(), r.objective, r.best_bound});
    }
  }
  {
    std::lock_guard<std::mutex> lock(control.mu);
    r.incumbents = control.incumbents;
  }
  r.detail = detail;
  return finish(r);
}

}  // namespace

std::string CbcVersion() {
  return std::string("CBC ") + CBC_VERSION + " / CLP " + CLP_VERSION;
}

std::unique_ptr<Solver> MakeCbcSolver() { return std::make_unique<CbcSolverImpl>(); }

}  // namespace thrustsched::milp
