// One run of CBC's driver in this process (see cbc_driver.h).
//
// The driver (CbcMain0/CbcMain1 with "-solve": CglPreProcess, the default cut
// generators and heuristics, branch and cut) is what makes CBC strong, and
// with the default seeds (random_seed 0) a solve is the same run as the `cbc`
// program's on the exported MPS file. (A hand-assembled
// CbcModel::branchAndBound with the driver's generators and heuristics was
// tried first; matching the driver's many internal settings by hand proved
// fragile.) The driver's own LP solves ignore its time limit
// (coin-or/Cbc#231, #514): an event handler on its CLP model (cloned into
// the LPs of the root and of CglPreProcess) reports iterations and objective
// as progress and stops them at the deadline or on request. (Solving the
// root LP here first does not help: the driver solves it again from scratch
// whatever basis it is given.)
#include "milp/internal/cbc_driver.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "CbcEventHandler.hpp"
#include "CbcModel.hpp"
#include "CbcSolver.hpp"
#include "ClpEventHandler.hpp"
#include "ClpSimplex.hpp"
#include "CoinMessageHandler.hpp"
#include "OsiClpSolverInterface.hpp"
#include "milp/internal/clp_lp.h"

namespace thrustsched::milp::internal {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Shared by the event handlers of one run (and their clones).
class DriverState {
 public:
  DriverState(const DriverRequest& request, DriverListener* listener)
      : request_(request), clock_(request.clock), listener_(listener) {
    sign_ = ObjectiveSign(request.lp);
    offset_ = request.lp.objective_offset;
    last_recorded_ = request.start_x.size() > 0 ? request.start_min : kInf;
  }

  SolveClock& clock() { return clock_; }
  double ToModel(double cbc_objective) const { return sign_ * cbc_objective + offset_; }
  double BoundModel() const {
    return std::isfinite(last_bound_) ? ToModel(last_bound_) : (sign_ > 0 ? -kInf : kInf);
  }
  double last_bound() const {
    std::lock_guard<std::mutex> lock(mu_);
    return last_bound_;
  }

  bool ShouldStop() {
    if (listener_->StopRequested()) {
      stopped_by_request_ = true;
      return true;
    }
    return clock_.DeadlinePassed();
  }
  bool stopped_by_request() const { return stopped_by_request_; }

  std::atomic<bool> search_started{false};
  std::atomic<bool> root_lp_stopped{false};

  // Root LP heartbeat: iterations, objective and infeasibility of the iterate.
  void RootLpProgress(const ClpSimplex& clp) {
    std::lock_guard<std::mutex> lock(mu_);
    const double wall = clock_.Elapsed();
    if (wall - last_progress_ < request_.options.progress_interval_s) return;
    last_progress_ = wall;
    SolveProgress p;
    p.wall_seconds = wall;
    p.in_root_lp = true;
    p.phase = SolvePhase::kRootLp;
    p.lp_iterations = clp.numberIterations();
    p.lp_objective = ToModel(clp.objectiveValue());
    p.lp_primal_infeasibility = clp.sumPrimalInfeasibilities();
    listener_->OnProgress(p);
  }

  // Any event of a CBC model. Only the driver's main branch-and-cut model
  // (no parent; heuristics' sub-searches have one) gives incumbents, bounds
  // and progress.
  void Observe(CbcModel* model, CbcEventHandler::CbcEvent which) {
    if (model == nullptr || model->parentModel() != nullptr) return;
    search_started.store(true);
    std::lock_guard<std::mutex> lock(mu_);
    const double best = model->getMinimizationObjValue();
    const double wall = clock_.Elapsed();
    const bool improved =
        best < kCbcInfinity && best < last_recorded_ - 1e-12 * std::max(1.0, std::abs(best));
    const bool final_event = which == CbcEventHandler::endSearch;
    // The bound walks the whole tree: only on news, on the progress clock and
    // at the end of the search.
    const bool due = wall - last_progress_ >= request_.options.progress_interval_s;
    if (!improved && !final_event && !due) return;
    const double bound = model->getBestPossibleObjValue();
    if (std::abs(bound) < kCbcInfinity && bound > last_bound_) last_bound_ = bound;
    const double obj_model = best < kCbcInfinity ? ToModel(best) : kNaN;
    if (improved) {
      last_recorded_ = best;
      listener_->OnIncumbent({wall, obj_model, BoundModel()}, OriginalSpace(*model));
    }
    if (improved || due) {
      last_progress_ = wall;
      SolveProgress p;
      p.wall_seconds = wall;
      p.objective = obj_model;
      p.best_bound = BoundModel();
      if (std::isfinite(obj_model)) p.gap = RelativeGap(obj_model, p.best_bound);
      p.nodes = model->getNodeCount();
      p.new_incumbent = improved;
      p.phase = model->getNodeCount() > 0 ? SolvePhase::kSearch : SolvePhase::kPresolve;
      listener_->OnProgress(p);
    }
  }

 private:
  // The model's best solution in the original column space: CBC's
  // preprocessing keeps a subset of the columns, listed by originalColumns().
  Eigen::VectorXd OriginalSpace(const CbcModel& model) const {
    const int n_orig = request_.lp.num_cols();
    Eigen::VectorXd x = Eigen::VectorXd::Constant(n_orig, kNaN);
    const double* solution = model.bestSolution();
    if (solution == nullptr) return x;
    const int n = model.getNumCols();
    const int* original = model.originalColumns();
    if (original != nullptr) {
      for (int i = 0; i < n; ++i) {
        if (original[i] >= 0 && original[i] < n_orig) x[original[i]] = solution[i];
      }
    } else if (n == n_orig) {
      x = Eigen::Map<const Eigen::VectorXd>(solution, n);
    }
    return x;
  }

  const DriverRequest& request_;
  SolveClock clock_;
  DriverListener* listener_;
  double sign_ = 1.0, offset_ = 0.0;
  mutable std::mutex mu_;        // guards what follows and serialises listener calls
  double last_bound_ = -kInf;    // best CBC (minimisation) bound seen
  double last_recorded_ = kInf;  // best CBC (minimisation) objective handed over
  double last_progress_ = -kInf;
  std::atomic<bool> stopped_by_request_{false};
};

class EventHandler : public CbcEventHandler {
 public:
  explicit EventHandler(DriverState* state) : state_(state) {}
  CbcAction event(CbcEvent which) override { return Handle(which); }
  CbcAction event(CbcEvent which, void* /*data*/) override { return Handle(which); }
  CbcEventHandler* clone() const override { return new EventHandler(*this); }

 private:
  CbcAction Handle(CbcEvent which) {
    // beforeSolution1/2 ask whether to accept a solution: never interfere.
    if (which == beforeSolution1 || which == beforeSolution2) return noAction;
    state_->Observe(model_, which);
    return state_->ShouldStop() ? stop : noAction;
  }
  DriverState* state_;
};

// On the driver's CLP models (clones inherit it): heartbeat and stop during
// the root LP (ours) and CglPreProcess's LPs. Once the search has started
// (first CBC event) it never interferes, since stopping a node LP could make
// CBC prune that node as if it were infeasible. A stopped root LP proves
// nothing (root_lp_stopped).
class RootLpHandler : public ClpEventHandler {
 public:
  explicit RootLpHandler(DriverState* state) : state_(state) {}
  int event(Event which) override {
    if (which != endOfIteration) return -1;
    if ((++count_ & 15) != 0) return -1;
    if (state_->search_started.load()) return -1;
    if (model_ != nullptr) state_->RootLpProgress(*model_);
    if (!state_->ShouldStop()) return -1;
    state_->root_lp_stopped.store(true);
    return 0;
  }
  ClpEventHandler* clone() const override { return new RootLpHandler(*this); }

 private:
  DriverState* state_;
  unsigned count_ = 0;
};

// CbcMain1 calls this at fixed points of its actions; some actions call it
// without checking for null.
int DriverCallback(CbcModel* /*model*/, int /*where_from*/) { return 0; }

std::string Num17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

std::vector<std::string> DriverArguments(const DriverRequest& request, const SolveClock& clock,
                                         std::string* detail) {
  const SolveOptions& options = request.options;
  const bool quiet = options.log_level <= 0;
  std::vector<std::string> args = {"thrustsched", "-log",
                                   std::to_string(quiet ? 0 : options.log_level)};
  if (clock.has_deadline()) {
    args.insert(args.end(),
                {"-seconds", Num17(std::max(clock.Remaining(), 1e-3)), "-timeMode", "elapsed"});
  }
  args.insert(args.end(), {"-ratioGap", Num17(options.relative_gap), "-allowableGap",
                           Num17(options.absolute_gap)});
  if (options.random_seed > 0) {
    // 0 keeps CBC's own default seeds (then results equal the cbc program's).
    args.insert(args.end(), {"-randomCbcSeed", std::to_string(options.random_seed), "-randomSeed",
                             std::to_string(options.random_seed)});
  }
  if (request.start_x.size() > 0) {
    // Everything not better than the start is pruned; a completed search that
    // finds nothing proves the start optimal.
    const double m = request.start_min;
    args.insert(args.end(), {"-cutoff", Num17(m + 1e-9 * std::max(1.0, std::abs(m)))});
  }
  if (options.objective_step > 0.0) {
    // CBC prunes nodes whose bound exceeds incumbent - increment: stay just
    // below the step so a solution exactly one step better is never cut off.
    args.insert(args.end(), {"-increment", Num17(options.objective_step * (1.0 - 1e-4))});
  }
  if (!options.presolve) {
    args.insert(args.end(), {"-preprocess", "off", "-presolve", "off"});
  }
  if (options.cbc.disable_knapsack_cuts) args.insert(args.end(), {"-knapsackCuts", "off"});
  if (options.max_nodes >= 0) {
    args.insert(args.end(), {"-maxNodes", std::to_string(options.max_nodes)});
  }
  if (options.threads > 1) {
    if (CbcModel::haveMultiThreadSupport()) {
      args.insert(args.end(), {"-threads", std::to_string(options.threads)});
      *detail += "threads=" + std::to_string(options.threads) +
                 " (CBC parallel mode, not deterministic); ";
    } else {
      *detail += "threads>1 ignored (CBC built without thread support); ";
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
    case LpAlgorithm::kBarrierNoCrossover:
      args.push_back("-primalS");  // CBC needs a vertex at its root
      break;
  }
  args.insert(args.end(), {"-solve", "-quit"});
  return args;
}

void SetMipStart(CbcModel* model, const Eigen::VectorXd& start_x) {
  std::vector<std::pair<std::string, double>> mip_start;
  mip_start.reserve(static_cast<size_t>(start_x.size()));
  for (int j = 0; j < start_x.size(); ++j) {
    mip_start.emplace_back(model->solver()->getColName(j), start_x[j]);
  }
  model->setMIPStart(mip_start);
}

void ReadOutcome(const CbcModel& model, const DriverState& state, int num_cols,
                 DriverOutcome* out) {
  out->status = model.status();
  out->secondary = model.secondaryStatus();
  out->proven_optimal = model.isProvenOptimal();
  out->proven_infeasible = model.isProvenInfeasible();
  out->continuous_unbounded = model.isContinuousUnbounded();
  out->nodes = model.getNodeCount();
  out->bound_min = state.last_bound();
  // After a completed search the driver's final bound is CBC's proof; after a
  // stopped one it may be the incumbent itself (no bound recorded), so only
  // the bounds seen during the search count.
  const double final_bound = model.getBestPossibleObjValue();
  if (model.isProvenOptimal() && std::abs(final_bound) < kCbcInfinity &&
      final_bound > out->bound_min) {
    out->bound_min = final_bound;
  }
  if (model.bestSolution() != nullptr && model.getMinimizationObjValue() < kCbcInfinity) {
    out->x = Eigen::Map<const Eigen::VectorXd>(model.bestSolution(), num_cols);
  }
  out->detail += "cbc status " + std::to_string(out->status) + " secondary " +
                 std::to_string(out->secondary) + ", nodes " + std::to_string(out->nodes);
}

}  // namespace

DriverOutcome RunDriverHere(const DriverRequest& request, DriverListener* listener) {
  const LpData& lp = request.lp;
  const SolveOptions& options = request.options;
  DriverOutcome out;
  DriverState state(request, listener);
  const bool quiet = options.log_level <= 0;
  const std::unique_ptr<CoinMessageHandler> silent = MakeSilentHandler();

  const CoinArrays arrays = MakeArrays(lp, ObjectiveSign(lp), true);
  OsiClpSolverInterface base;
  LoadOsi(&base, arrays, lp);
  RootLpHandler root_lp_events(&state);
  base.getModelPtr()->passInEventHandler(&root_lp_events);  // cloned
  if (quiet) {
    base.passInMessageHandler(silent.get());
    base.getModelPtr()->passInMessageHandler(silent.get());
    base.messageHandler()->setLogLevel(0);
    base.getModelPtr()->setLogLevel(0);
  }
  base.setHintParam(OsiDoReducePrint, quiet, OsiHintTry);

  CbcModel model(base);
  if (quiet) {
    model.passInMessageHandler(silent.get());
    model.setLogLevel(0);
  }
  EventHandler events(&state);
  model.passInEventHandler(&events);
  if (request.start_x.size() > 0) SetMipStart(&model, request.start_x);
  const std::vector<std::string> args = DriverArguments(request, state.clock(), &out.detail);
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  CbcSolverUsefulData driver_data;
  CbcMain0(model, driver_data);
  if (quiet) {
    model.passInMessageHandler(silent.get());
    model.setLogLevel(0);
  }
  CbcMain1(static_cast<int>(argv.size()), argv.data(), model, DriverCallback, driver_data);

  ReadOutcome(model, state, lp.num_cols(), &out);
  out.root_lp_stopped = state.root_lp_stopped.load();
  out.stopped_by_request = state.stopped_by_request();
  out.stopped = out.status == 1 || out.stopped_by_request || state.clock().DeadlinePassed();
  return out;
}

}  // namespace thrustsched::milp::internal
