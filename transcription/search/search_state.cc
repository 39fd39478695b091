#include "transcription/search/search_state.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "common/format.h"
#include "transcription/search/search_report.h"
#include "transcription/total_branching.h"

namespace thrustsched::transcription {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

SearchState::SearchState(const ScheduleMilp& milp, const milp::Solver& solver,
                         const milp::SolveOptions& options, const SearchOptions& search,
                         SearchReport* report)
    : milp_(milp),
      lp_(milp.lp()),
      solver_(solver),
      options_(options),
      search_(search),
      report_(report),
      clock_(options.time_limit_s, options.interrupt),
      bound_(-kInf),
      objective_(kInf) {
  step_ = options.objective_step > 0.0 ? options.objective_step : milp.objective_step();
}

void SearchState::SetRelaxation(milp::LpRelaxationResult relaxation, milp::DualBound dual) {
  relaxation_ = std::move(relaxation);
  dual_ = dual;
}

bool SearchState::Dormant(int thruster) const {
  return !dormant_.thruster.empty() && dormant_.thruster[static_cast<size_t>(thruster)];
}

bool SearchState::Offer(Eigen::VectorXd x, const std::string& source) {
  if (x.size() != lp_.num_cols()) return false;
  if (!milp_.CompleteFromPattern(&x) ||
      lp_.MaxViolation(x) > ScheduleMilp::kPatternFeasibilityTolerance)
    return false;
  const double obj = lp_.Objective(x);
  if (has_incumbent() && !(obj < objective_ - 1e-12 * std::max(1.0, std::abs(obj)))) return false;
  x_ = std::move(x);
  objective_ = obj;
  incumbents_.push_back({Elapsed(), objective_, bound_});
  improved_by_.push_back(phase_);
  if (bound_ > objective_) bound_ = objective_;
  Step("incumbent " + common::FormatG(objective_, 6) + " from " + source);
  Report(milp::SolvePhase::kPresolve, true);
  return true;
}

void SearchState::RaiseBound(double bound) {
  double rounded = milp::RoundBoundToStep(lp_, bound, step_);
  // Above the zero schedule's objective (with a margin far below any slot's
  // cost), every schedule fires: at least the least firing objective.
  const double least = milp_.least_firing_objective();
  if (std::isfinite(least) && least > rounded &&
      bound > lp_.objective_offset + 1e-6 * (least - lp_.objective_offset)) {
    rounded = least;
  }
  if (rounded > bound_) bound_ = rounded;
  if (has_incumbent() && bound_ > objective_) bound_ = objective_;
}

void SearchState::RaiseBoundTo(double bound) {
  bound_ = std::max(bound_, bound);
  if (has_incumbent() && bound_ > objective_) bound_ = objective_;
}

bool SearchState::Done() const {
  return has_incumbent() && milp::GapClosed(objective_, bound_, options_);
}

bool SearchState::OneStepAboveBound() const {
  return has_incumbent() && OneStepAbove(objective_, bound_, step_);
}

double SearchState::Cutoff() const {
  return objective_ - std::max(step_, 0.0) + 1e-7 * std::max(1.0, std::abs(objective_));
}

bool SearchState::ImprovedBy(const std::string& phase) const {
  return std::find(improved_by_.begin(), improved_by_.end(), phase) != improved_by_.end();
}

void SearchState::NoteBuilt(int slots, double seconds) {
  if (slots < largest_built_slots_) return;
  largest_built_slots_ = slots;
  largest_built_seconds_ = seconds;
}

void SearchState::Step(const std::string& line) {
  const std::string named = phase_.empty() ? line : phase_ + ": " + line;
  detail_ += (detail_.empty() ? "" : "; ") + named;
  if (report_ != nullptr) report_->steps.push_back(named);
}

void SearchState::BeginPhase(const std::string& name) {
  phase_ = name;
  if (!options_.progress || name.empty()) return;
  milp::SolveProgress p = Progress(milp::SolvePhase::kSearch, false);
  p.stage_begins = true;
  options_.progress(p);
}

void SearchState::Report(milp::SolvePhase phase, bool new_incumbent) const {
  if (options_.progress) options_.progress(Progress(phase, new_incumbent));
}

milp::SolveProgress SearchState::Progress(milp::SolvePhase phase, bool new_incumbent) const {
  milp::SolveProgress p;
  p.set_stage(phase_);
  p.wall_seconds = Elapsed();
  p.phase = phase;
  p.in_root_lp = phase == milp::SolvePhase::kRootLp;
  p.objective = has_incumbent() ? objective_ : kNaN;
  p.best_bound = bound_;
  p.gap = has_incumbent() ? milp::RelativeGap(objective_, bound_) : kNaN;
  p.new_incumbent = new_incumbent;
  p.nodes = nodes_;
  return p;
}

milp::SolveOptions SearchState::SubOptions(bool global_bound) const {
  milp::SolveOptions o = options_;
  o.time_limit_s = std::max(0.0, Remaining());
  o.initial_solution.reset();
  o.complete_solution = nullptr;
  o.objective_step = step_;
  // An incumbent within the gap of the search's bound ends the search, so
  // it ends the sub-solve too (CBC alone would go on for its own bound).
  o.known_bound = std::isfinite(bound_) ? bound_ : kNaN;
  const double offset = Elapsed();
  o.progress = nullptr;
  if (options_.progress) {
    o.progress = [this, offset, global_bound, stage = phase_](const milp::SolveProgress& sub) {
      milp::SolveProgress p = sub;
      p.set_stage(stage);
      p.wall_seconds += offset;
      if (has_incumbent() && !(p.objective < objective_)) p.objective = objective_;
      if (!global_bound || !(p.best_bound > bound_)) p.best_bound = bound_;
      p.gap = std::isfinite(p.objective) ? milp::RelativeGap(p.objective, p.best_bound) : kNaN;
      options_.progress(p);
    };
  }
  return o;
}

milp::SolveOptions SearchState::RestrictedOptions() const {
  milp::SolveOptions o = SubOptions(false);
  o.lp_algorithm = milp::LpAlgorithm::kDual;
  return o;
}

milp::SolveOptions SearchState::HeuristicOptions(double time_share) const {
  milp::SolveOptions o = RestrictedOptions();
  const long long limit = search_.restricted.max_nodes;
  o.max_nodes = options_.max_nodes >= 0 ? std::min(options_.max_nodes, limit) : limit;
  if (std::isfinite(o.time_limit_s)) o.time_limit_s *= time_share;
  return o;
}

milp::SolveResult SearchState::Result() const {
  milp::SolveResult r;
  r.solver_version = solver_.version();
  r.nodes = nodes_;
  r.incumbents = incumbents_;
  if (has_incumbent()) {
    r.status = Done() ? milp::SolveStatus::kOptimal : milp::SolveStatus::kFeasible;
    r.x = x_;
    r.objective = objective_;
    r.best_bound = bound_;
    r.gap = milp::RelativeGap(objective_, bound_);
  } else if (status_ == milp::SolveStatus::kInfeasible || status_ == milp::SolveStatus::kError) {
    r.status = status_;
  } else {
    r.status = milp::SolveStatus::kNoSolutionFound;
  }
  std::string why;
  if (!Done()) {
    if (Interrupted()) {
      why = "; interrupted";
    } else if (Remaining() <= 0.0) {
      why = "; time limit";
    }
  }
  r.detail = "search: " + detail_ + why +
             (solver_detail_.empty() ? std::string()
                                     : "; " + std::string(solver_.name()) + ": " + solver_detail_);
  r.wall_seconds = Elapsed();
  return r;
}

}  // namespace thrustsched::transcription
