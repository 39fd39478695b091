#include "milp/lazy_rows.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/format.h"
#include "milp/internal/column_writer.h"
#include "milp/internal/solve_clock.h"

namespace thrustsched::milp {
namespace {

using SparseCol = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

double Scale(double bound) { return std::max(1.0, std::abs(bound)); }

// How far the activity is beyond the row's bounds (<= 0: satisfied), and
// its slack to the nearer finite bound (>= 0 when satisfied).
double Violation(double activity, double lower, double upper) {
  double v = -std::numeric_limits<double>::infinity();
  if (std::isfinite(lower)) v = std::max(v, (lower - activity) / Scale(lower));
  if (std::isfinite(upper)) v = std::max(v, (activity - upper) / Scale(upper));
  return v;
}

// Rows not in `in` whose activity range over the column bounds lies
// within the row's bounds: no point within the bounds can break them.
std::vector<char> ImpliedByColumnBounds(const LpData& lp, const std::vector<char>& in) {
  const int m = lp.num_rows();
  std::vector<double> low(static_cast<size_t>(m), 0.0), high(static_cast<size_t>(m), 0.0);
  for (int j = 0; j < lp.num_cols(); ++j) {
    const double lo = lp.col_lower[j], hi = lp.col_upper[j];
    for (SparseCol::InnerIterator it(lp.a_matrix, j); it; ++it) {
      const double a = it.value();
      const size_t i = static_cast<size_t>(it.row());
      // a * (-inf) or a * (+inf) makes the range unbounded (never 0 * inf:
      // the matrix stores no zeros).
      low[i] += a > 0.0 ? a * lo : a * hi;
      high[i] += a > 0.0 ? a * hi : a * lo;
    }
  }
  std::vector<char> implied(static_cast<size_t>(m), 0);
  for (int i = 0; i < m; ++i) {
    const size_t k = static_cast<size_t>(i);
    if (in[k]) continue;
    // NaN (an infinite range on both sides) compares false: not implied.
    implied[k] = low[k] >= lp.row_lower[i] && high[k] <= lp.row_upper[i] ? 1 : 0;
  }
  return implied;
}

class LazySolve {
 public:
  LazySolve(const Solver& solver, const LpData& lp, const SolveOptions& options,
            const LazyRowOptions& lazy, LazyRowReport* report)
      : solver_(solver),
        lp_(lp),
        options_(options),
        lazy_(lazy),
        report_(report),
        clock_(options.time_limit_s, options.interrupt) {}

  SolveResult Run() {
    const long long dense_nonzeros = LeaveOutDenseRows();
    if (static_cast<double>(dense_nonzeros) < lazy_.min_dense_share * lp_.num_nonzeros()) {
      return Whole("few nonzeros in dense rows");
    }
    if (!AddRowsActiveAtTheLpOptimum()) return Whole(detail_);
    report_->used = true;
    report_->initial_rows = Count();
    double bound = -std::numeric_limits<double>::infinity() * Sign();
    long long nodes = 0;
    for (int round = 0; round < lazy_.max_rounds; ++round) {
      const SolveOptions o = RoundOptions();
      const LpData subset = SelectRows(lp_, Rows());
      SolveResult s = solver_.Solve(subset, o);
      ++report_->rounds;
      report_->final_rows = static_cast<int>(subset.num_rows());
      nodes += s.nodes;
      if (std::isfinite(s.best_bound) && Better(s.best_bound, bound)) bound = s.best_bound;
      s.nodes = nodes;
      s.wall_seconds = Elapsed();
      if (s.status == SolveStatus::kUnbounded) return Whole("a subset is unbounded");
      if (!s.has_solution()) {
        return best_x_.size() > 0 ? Kept(s, bound, nodes) : Finish(std::move(s), "");
      }
      const int added = AddBrokenRows(s.x);
      if (added == 0) {
        if (KeptIsBetter(s)) return Kept(s, bound, nodes);
        s.best_bound = bound;
        s.gap = RelativeGap(s.objective, s.best_bound);
        if (!(best_x_.size() > 0 && s.objective == best_objective_)) ReportSolution(s);
        return Finish(std::move(s), "");
      }
      if (Interrupted() || Remaining() <= 0.0) {
        if (best_x_.size() > 0) return Kept(s, bound, nodes);
        // The subset's solution breaks the model: no solution, only a bound.
        SolveResult r;
        r.status = SolveStatus::kNoSolutionFound;
        r.solver_version = s.solver_version;
        r.nodes = nodes;
        r.best_bound = bound;
        r.wall_seconds = Elapsed();
        return Finish(std::move(r), Interrupted() ? "interrupted" : "time limit");
      }
    }
    report_->fell_back = true;
    return Whole("still breaking rows after " + std::to_string(lazy_.max_rounds) + " rounds");
  }

 private:
  // Marks the rows with at least dense_row_min_nonzeros entries as left out
  // (in_ 0), the others as in; returns the left-out rows' nonzeros.
  long long LeaveOutDenseRows() {
    std::vector<int> nonzeros(static_cast<size_t>(lp_.num_rows()), 0);
    for (int j = 0; j < lp_.num_cols(); ++j) {
      for (SparseCol::InnerIterator it(lp_.a_matrix, j); it; ++it) ++nonzeros[it.row()];
    }
    in_.assign(static_cast<size_t>(lp_.num_rows()), 0);
    int dense = 0;
    long long dense_nonzeros = 0;
    for (int i = 0; i < lp_.num_rows(); ++i) {
      const int count = nonzeros[static_cast<size_t>(i)];
      const bool is_dense = count >= lazy_.dense_row_min_nonzeros;
      in_[static_cast<size_t>(i)] = is_dense ? 0 : 1;
      dense += is_dense ? 1 : 0;
      dense_nonzeros += is_dense ? count : 0;
    }
    report_->dense_rows = dense;
    return dense_nonzeros;
  }

  // The options of one round's subset solve: the time left, and the
  // callbacks that keep the model's own solutions only.
  SolveOptions RoundOptions() {
    SolveOptions o = options_;
    o.time_limit_s = std::max(0.0, Remaining());
    // A kept solution is a fallback only, not the next subset's MIP start:
    // with a start CBC searches differently (a cutoff, fewer heuristics),
    // and on a six-thruster week of the year (node limits) the next
    // round then ended one step above the optimum it found without one.
    o.on_incumbent = nullptr;
    if (lazy_.keep_model_incumbents) {
      o.on_incumbent = [this](const Eigen::VectorXd& x) { KeepIfTheModelsSolution(x); };
    }
    // A subset's incumbent may break a left-out row: not the model's, so
    // not reported as one (the caller would count on a schedule it cannot
    // have); a solution that keeps every row is reported by
    // KeepIfTheModelsSolution or, at the end, ReportSolution.
    if (options_.progress) {
      const double offset = Elapsed();
      o.progress = [this, offset](const SolveProgress& sub) {
        SolveProgress p = sub;
        p.wall_seconds += offset;
        p.new_incumbent = false;
        p.objective = p.gap = std::numeric_limits<double>::quiet_NaN();
        options_.progress(p);
      };
    }
    return o;
  }

  double Elapsed() const { return clock_.Elapsed(); }
  double Remaining() const { return clock_.Remaining(); }
  bool Interrupted() const { return clock_.Interrupted(); }
  double Sign() const { return lp_.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0; }
  bool Better(double bound, double than) const { return Sign() * bound > Sign() * than; }
  int Count() const { return static_cast<int>(std::count(in_.begin(), in_.end(), 1)); }
  std::vector<int> Rows() const {
    std::vector<int> rows;
    for (int i = 0; i < lp_.num_rows(); ++i) {
      if (in_[static_cast<size_t>(i)]) rows.push_back(i);
    }
    return rows;
  }

  // A subset incumbent, as the solver reports it: kept (and reported as the
  // model's) when it breaks no left-out row and improves on the best kept.
  // The rows in the subset are those of the running solve (in_ changes only
  // between solves).
  void KeepIfTheModelsSolution(const Eigen::VectorXd& x) {
    if (!BrokenRows(x).empty()) return;
    const double objective = lp_.Objective(x);
    if (best_x_.size() > 0 && !(Sign() * objective < Sign() * best_objective_)) return;
    best_x_ = x;
    best_objective_ = objective;
    best_wall_seconds_ = Elapsed();
    SolveProgress p;
    p.wall_seconds = best_wall_seconds_;
    p.objective = objective;
    Announce(p, x);
  }

  // Whether the kept solution beats `s`, a solution of the model that a
  // search stopped at a limit ended on (a completed search cannot end
  // worse: an optimal `s` stands).
  bool KeptIsBetter(const SolveResult& s) const {
    if (best_x_.size() == 0) return false;
    if (!s.has_solution()) return true;
    if (s.status == SolveStatus::kOptimal) return false;
    const double margin = 1e-9 * std::max(1.0, std::abs(s.objective));
    return Sign() * best_objective_ < Sign() * s.objective - margin;
  }

  // The model's best kept solution, when the last search ended without a
  // better one (a limit or an interrupt, on a solution breaking a left-out
  // row, a worse one or none): status kFeasible.
  SolveResult Kept(const SolveResult& last, double bound, long long nodes) {
    report_->kept_incumbent = true;
    SolveResult r;
    r.status = SolveStatus::kFeasible;
    r.solver_version = last.solver_version;
    r.x = best_x_;
    r.objective = best_objective_;
    r.best_bound = bound;
    r.gap = RelativeGap(r.objective, r.best_bound);
    r.nodes = nodes;
    r.incumbents = {{best_wall_seconds_, best_objective_, bound}};
    r.wall_seconds = Elapsed();
    return Finish(std::move(r), std::string(Interrupted() ? "interrupted" : "limit") +
                                    ", on the model's best solution of the subset searches");
  }

  void ReportSolution(const SolveResult& s) const {
    SolveProgress p;
    p.wall_seconds = Elapsed();
    p.objective = s.objective;
    p.best_bound = s.best_bound;
    p.gap = s.gap;
    p.nodes = s.nodes;
    Announce(p, s.x);
  }

  // A solution of the model, to the caller's progress and on_incumbent.
  void Announce(SolveProgress p, const Eigen::VectorXd& x) const {
    p.new_incumbent = true;
    if (options_.progress) options_.progress(p);
    if (options_.on_incumbent) options_.on_incumbent(x);
  }

  // The LP relaxation by dual simplex; its binding dense rows join the
  // subset. False (detail_ set) when it did not end optimal, with presolve
  // too where the caller's options allow it and
  // LazyRowOptions::presolve_lp_relaxation left it out first. Without the
  // dense rows the column bounds imply (LazyRowOptions::
  // skip_implied_rows_in_lp): every point within the bounds keeps them, so
  // the LP is the same; they stay left out and checked like the others.
  bool AddRowsActiveAtTheLpOptimum() {
    std::vector<int> lp_rows;
    if (lazy_.skip_implied_rows_in_lp) {
      const std::vector<char> implied = ImpliedByColumnBounds(lp_, in_);
      for (int i = 0; i < lp_.num_rows(); ++i) {
        if (!implied[static_cast<size_t>(i)]) lp_rows.push_back(i);
      }
      report_->implied_rows = lp_.num_rows() - static_cast<int>(lp_rows.size());
    }
    const bool all_rows = report_->implied_rows == 0;
    const LpData reduced = all_rows ? LpData() : SelectRows(lp_, lp_rows);
    const LpData& relaxed = all_rows ? lp_ : reduced;
    SolveOptions o = options_;
    o.time_limit_s = std::max(0.0, Remaining());
    o.lp_algorithm = LpAlgorithm::kDual;
    o.presolve = options_.presolve && lazy_.presolve_lp_relaxation;
    LpRelaxationResult r = solver_.SolveLpRelaxation(relaxed, o);
    if (r.status != SolveStatus::kOptimal && options_.presolve && !o.presolve &&
        Remaining() > 0.0 && !Interrupted()) {
      // The dual simplex without presolve has called feasible schedule LPs
      // infeasible (milp/internal/clp_lp.cc): its word is not final.
      o.presolve = true;
      o.time_limit_s = std::max(0.0, Remaining());
      r = solver_.SolveLpRelaxation(relaxed, o);
    }
    if (r.status != SolveStatus::kOptimal) {
      detail_ = "LP relaxation " + std::string(ToString(r.status));
      return false;
    }
    const Eigen::VectorXd activity = relaxed.a_matrix * r.x;
    for (int k = 0; k < relaxed.num_rows(); ++k) {
      const size_t i = all_rows ? static_cast<size_t>(k) : static_cast<size_t>(lp_rows[k]);
      if (in_[i]) continue;
      const double v = Violation(activity[k], relaxed.row_lower[k], relaxed.row_upper[k]);
      if (v >= -lazy_.active_tolerance || std::abs(r.row_duals[k]) > 0.0) in_[i] = 1;
    }
    return true;
  }

  // The left-out rows `x` breaks, ascending.
  std::vector<int> BrokenRows(const Eigen::VectorXd& x) const {
    const Eigen::VectorXd activity = lp_.a_matrix * x;
    std::vector<int> broken;
    for (int i = 0; i < lp_.num_rows(); ++i) {
      if (in_[static_cast<size_t>(i)]) continue;
      if (Violation(activity[i], lp_.row_lower[i], lp_.row_upper[i]) > lazy_.violation_tolerance) {
        broken.push_back(i);
      }
    }
    return broken;
  }

  int AddBrokenRows(const Eigen::VectorXd& x) {
    const std::vector<int> broken = BrokenRows(x);
    for (int i : broken) in_[static_cast<size_t>(i)] = 1;
    return static_cast<int>(broken.size());
  }

  SolveResult Whole(const std::string& why) {
    SolveOptions o = options_;
    o.time_limit_s = std::max(0.0, Remaining());
    SolveResult s = solver_.Solve(lp_, o);
    s.wall_seconds = Elapsed();
    if (KeptIsBetter(s)) {
      const double bound = std::isfinite(s.best_bound)
                               ? s.best_bound
                               : -std::numeric_limits<double>::infinity() * Sign();
      return Kept(s, bound, s.nodes);
    }
    return Finish(std::move(s), why.empty() ? "" : "whole model (" + why + ")");
  }

  SolveResult Finish(SolveResult s, const std::string& note) {
    std::string what;
    if (report_->used) {
      what = "lazy rows: " + std::to_string(report_->initial_rows) + " -> " +
             std::to_string(report_->final_rows) + " of " + std::to_string(lp_.num_rows()) +
             " rows in " + std::to_string(report_->rounds) + " solve(s)";
    }
    for (const std::string& part : {note, s.detail}) {
      if (part.empty()) continue;
      what += (what.empty() ? "" : "; ") + part;
    }
    s.detail = what;
    return s;
  }

  const Solver& solver_;
  const LpData& lp_;
  const SolveOptions& options_;
  const LazyRowOptions& lazy_;
  LazyRowReport* report_;
  internal::SolveClock clock_;
  std::vector<char> in_;
  std::string detail_;
  // The best subset incumbent that breaks no row (keep_model_incumbents).
  Eigen::VectorXd best_x_;
  double best_objective_ = std::numeric_limits<double>::quiet_NaN();
  double best_wall_seconds_ = 0.0;
};

}  // namespace

bool LazyRowOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& m) {
    if (error != nullptr) *error = "LazyRowOptions: " + m;
    return false;
  };
  if (dense_row_min_nonzeros < 1) {
    return fail("dense_row_min_nonzeros must be >= 1, got " +
                std::to_string(dense_row_min_nonzeros));
  }
  if (!(min_dense_share >= 0.0 && min_dense_share <= 1.0)) {
    return fail("min_dense_share must be in [0, 1], got " + common::FormatG(min_dense_share, 6));
  }
  if (!(active_tolerance >= 0.0 && std::isfinite(active_tolerance))) {
    return fail("active_tolerance must be finite and >= 0, got " +
                common::FormatG(active_tolerance, 6));
  }
  if (!(violation_tolerance >= 0.0 && std::isfinite(violation_tolerance))) {
    return fail("violation_tolerance must be finite and >= 0, got " +
                common::FormatG(violation_tolerance, 6));
  }
  if (max_rounds < 1) return fail("max_rounds must be >= 1, got " + std::to_string(max_rounds));
  return true;
}

LpData SelectRows(const LpData& lp, const std::vector<int>& rows) {
  std::vector<int> position(static_cast<size_t>(lp.num_rows()), -1);
  for (size_t k = 0; k < rows.size(); ++k) {
    const int i = rows[k];
    if (i < 0 || i >= lp.num_rows() || (k > 0 && rows[k - 1] >= i)) {
      throw std::invalid_argument("SelectRows: rows must be ascending indices below " +
                                  std::to_string(lp.num_rows()));
    }
    position[static_cast<size_t>(i)] = static_cast<int>(k);
  }
  LpData out;
  out.name = lp.name;
  out.sense = lp.sense;
  out.col_cost = lp.col_cost;
  out.objective_offset = lp.objective_offset;
  out.col_lower = lp.col_lower;
  out.col_upper = lp.col_upper;
  out.col_type = lp.col_type;
  out.col_names = lp.col_names;
  const int m = static_cast<int>(rows.size());
  out.row_lower.resize(m);
  out.row_upper.resize(m);
  for (int k = 0; k < m; ++k) {
    out.row_lower[k] = lp.row_lower[rows[static_cast<size_t>(k)]];
    out.row_upper[k] = lp.row_upper[rows[static_cast<size_t>(k)]];
    if (!lp.row_names.empty()) out.row_names.push_back(lp.row_names[rows[static_cast<size_t>(k)]]);
  }
  // position is increasing, so each column's selected rows stay sorted.
  internal::ColumnWriter matrix(&out.a_matrix, m, lp.num_cols(), lp.a_matrix.nonZeros());
  for (int j = 0; j < lp.num_cols(); ++j) {
    for (SparseCol::InnerIterator it(lp.a_matrix, j); it; ++it) {
      const int k = position[static_cast<size_t>(it.row())];
      if (k >= 0) matrix.Push(k, it.value());
    }
    matrix.EndColumn();
  }
  matrix.Finish();
  return out;
}

SolveResult SolveWithLazyRows(const Solver& solver, const LpData& lp, const SolveOptions& options,
                              const LazyRowOptions& lazy, LazyRowReport* report) {
  std::string error;
  if (!lazy.IsValid(&error)) throw std::invalid_argument(error);
  if (!lp.IsValid(&error)) throw std::invalid_argument("SolveWithLazyRows: " + error);
  if (!options.IsValid(&error)) throw std::invalid_argument("SolveWithLazyRows: " + error);
  LazyRowReport local;
  LazyRowReport* r = report != nullptr ? report : &local;
  *r = LazyRowReport{};
  return LazySolve(solver, lp, options, lazy, r).Run();
}

}  // namespace thrustsched::milp
