#include "milp/solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "common/format.h"
#include "milp/allocator.h"
#include "milp/lp_bound.h"

namespace thrustsched::milp {

using common::FormatG;

namespace {

void Validate(const LpData& problem, const SolveOptions& options, const char* what) {
  std::string error;
  if (!problem.IsValid(&error)) {
    throw std::invalid_argument(std::string(what) + ": invalid problem: " + error);
  }
  if (!options.IsValid(&error)) {
    throw std::invalid_argument(std::string(what) + ": invalid options: " + error);
  }
  if (options.initial_solution.has_value()) {
    const Eigen::VectorXd& x0 = *options.initial_solution;
    if (x0.size() != problem.num_cols()) {
      throw std::invalid_argument(std::string(what) + ": initial_solution has size " +
                                  std::to_string(x0.size()) + ", expected " +
                                  std::to_string(problem.num_cols()));
    }
  }
}

}  // namespace

std::string_view ToString(SolveStatus status) {
  switch (status) {
    case SolveStatus::kOptimal:
      return "optimal";
    case SolveStatus::kFeasible:
      return "feasible";
    case SolveStatus::kInfeasible:
      return "infeasible";
    case SolveStatus::kUnbounded:
      return "unbounded";
    case SolveStatus::kNoSolutionFound:
      return "no_solution_found";
    case SolveStatus::kError:
      return "error";
  }
  return "unknown";
}

std::ostream& operator<<(std::ostream& os, SolveStatus status) { return os << ToString(status); }

double RelativeGap(double objective, double bound) {
  if (!std::isfinite(objective) || !std::isfinite(bound)) {
    return std::numeric_limits<double>::infinity();
  }
  return std::abs(objective - bound) / std::max(1e-10, std::abs(objective));
}

bool GapClosed(double objective, double bound, const SolveOptions& options) {
  if (!std::isfinite(objective) || !std::isfinite(bound)) return false;
  return std::abs(objective - bound) <= options.absolute_gap ||
         RelativeGap(objective, bound) <= options.relative_gap;
}

void SolveProgress::set_stage(std::string_view name) {
  const size_t n = std::min(name.size(), sizeof(stage_name_) - 1);
  std::copy_n(name.data(), n, stage_name_);
  stage_name_[n] = '\0';
}

std::string_view ToString(SolvePhase phase) {
  switch (phase) {
    case SolvePhase::kRootLp:
      return "root LP";
    case SolvePhase::kPresolve:
      return "preprocessing, root cuts and heuristics";
    case SolvePhase::kSearch:
      return "branch and bound";
    case SolvePhase::kFinishing:
      return "finishing";
  }
  return "unknown";
}

std::string_view ToString(LpAlgorithm algorithm) {
  switch (algorithm) {
    case LpAlgorithm::kPrimal:
      return "primal";
    case LpAlgorithm::kDual:
      return "dual";
    case LpAlgorithm::kBarrier:
      return "barrier";
    case LpAlgorithm::kBarrierNoCrossover:
      return "barrier_no_crossover";
  }
  return "unknown";
}

bool SolveOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = "SolveOptions: " + message;
    return false;
  };
  if (std::isnan(time_limit_s) || time_limit_s < 0.0) {
    return fail("time_limit_s must be >= 0 (or +inf), got " + FormatG(time_limit_s, 17));
  }
  if (!std::isfinite(relative_gap) || relative_gap < 0.0) {
    return fail("relative_gap must be finite and >= 0, got " + FormatG(relative_gap, 17));
  }
  if (!std::isfinite(absolute_gap) || absolute_gap < 0.0) {
    return fail("absolute_gap must be finite and >= 0, got " + FormatG(absolute_gap, 17));
  }
  if (!std::isfinite(objective_step) || objective_step < 0.0) {
    return fail("objective_step must be finite and >= 0, got " + FormatG(objective_step, 17));
  }
  if (threads < 1) return fail("threads must be >= 1, got " + std::to_string(threads));
  if (random_seed < 0) return fail("random_seed must be >= 0, got " + std::to_string(random_seed));
  if (log_level < 0) return fail("log_level must be >= 0, got " + std::to_string(log_level));
  if (std::isnan(progress_interval_s) || progress_interval_s <= 0.0) {
    return fail("progress_interval_s must be > 0, got " + FormatG(progress_interval_s, 17));
  }
  if (!std::isfinite(cbc.stop_grace_s) || cbc.stop_grace_s < 0.0) {
    return fail("cbc.stop_grace_s must be finite and >= 0, got " + FormatG(cbc.stop_grace_s, 17));
  }
  if (initial_solution.has_value()) {
    for (Eigen::Index j = 0; j < initial_solution->size(); ++j) {
      if (!std::isfinite((*initial_solution)[j])) {
        return fail("initial_solution[" + std::to_string(j) + "] must be finite, got " +
                    FormatG((*initial_solution)[j], 17));
      }
    }
  }
  return true;
}

double SolveResult::TimeToGap(double rel_gap) const {
  if (!std::isfinite(best_bound)) return std::numeric_limits<double>::quiet_NaN();
  for (const Incumbent& inc : incumbents) {
    if (RelativeGap(inc.objective, best_bound) <= rel_gap) return inc.wall_seconds;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

SolveResult Solver::Solve(const LpData& problem, const SolveOptions& options) const {
  Validate(problem, options, "Solver::Solve");
  TuneAllocatorForLargeModels();  // milp/allocator.h
  const auto start = std::chrono::steady_clock::now();
  SolveResult result = DoSolve(problem, options);
  if (result.wall_seconds <= 0.0) {
    result.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return result;
}

namespace {

// The safe dual bound (milp/lp_bound.h) and the wall time, for every backend.
void CompleteRelaxationResult(const LpData& problem, std::chrono::steady_clock::time_point start,
                              LpRelaxationResult* result) {
  if (result->row_duals.size() == problem.num_rows() && problem.num_rows() > 0) {
    result->dual_bound = SafeDualBound(problem, result->row_duals).bound;
  } else if (result->status == SolveStatus::kOptimal) {
    result->dual_bound = result->objective;  // no rows: the optimum is exact
  }
  if (result->wall_seconds <= 0.0) {
    result->wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
}

}  // namespace

LpRelaxationResult Solver::SolveLpRelaxation(const LpData& problem,
                                             const SolveOptions& options) const {
  Validate(problem, options, "Solver::SolveLpRelaxation");
  TuneAllocatorForLargeModels();  // milp/allocator.h
  const auto start = std::chrono::steady_clock::now();
  LpRelaxationResult result = DoSolveLpRelaxation(problem, options);
  CompleteRelaxationResult(problem, start, &result);
  return result;
}

std::vector<LpRelaxationResult> Solver::SolveLpRelaxations(
    const std::vector<const LpData*>& problems, const SolveOptions& options) const {
  for (const LpData* p : problems) {
    if (p == nullptr) throw std::invalid_argument("Solver::SolveLpRelaxations: null problem");
    Validate(*p, options, "Solver::SolveLpRelaxations");
  }
  TuneAllocatorForLargeModels();  // milp/allocator.h
  const auto start = std::chrono::steady_clock::now();
  std::vector<LpRelaxationResult> results = DoSolveLpRelaxations(problems, options);
  for (size_t i = 0; i < problems.size(); ++i) {
    CompleteRelaxationResult(*problems[i], start, &results[i]);
  }
  return results;
}

std::vector<LpRelaxationResult> Solver::DoSolveLpRelaxations(
    const std::vector<const LpData*>& problems, const SolveOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  std::vector<LpRelaxationResult> results;
  for (const LpData* p : problems) {
    SolveOptions o = options;
    if (std::isfinite(options.time_limit_s)) {
      const double used =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      o.time_limit_s = std::max(0.0, options.time_limit_s - used);
    }
    results.push_back(DoSolveLpRelaxation(*p, o));
  }
  return results;
}

namespace {

// Solver::DoOpenLpSession's default: every Solve from scratch.
class ColdLpSession final : public LpSession {
 public:
  ColdLpSession(const Solver& solver, const LpData& lp, const SolveOptions& options)
      : solver_(solver), lp_(lp), options_(options) {}
  void SetColumnBounds(int column, double lower, double upper) override {
    lp_.col_lower[column] = lower;
    lp_.col_upper[column] = upper;
  }
  double column_lower(int column) const override { return lp_.col_lower[column]; }
  double column_upper(int column) const override { return lp_.col_upper[column]; }
  LpRelaxationResult Solve() override { return solver_.SolveLpRelaxation(lp_, options_); }

 private:
  const Solver& solver_;
  LpData lp_;
  SolveOptions options_;
};

}  // namespace

std::unique_ptr<LpSession> Solver::DoOpenLpSession(const LpData& problem,
                                                   const SolveOptions& options) const {
  return std::make_unique<ColdLpSession>(*this, problem, options);
}

std::unique_ptr<LpSession> Solver::OpenLpSession(const LpData& problem,
                                                 const SolveOptions& options) const {
  Validate(problem, options, "Solver::OpenLpSession");
  TuneAllocatorForLargeModels();  // milp/allocator.h
  return DoOpenLpSession(problem, options);
}

}  // namespace thrustsched::milp
