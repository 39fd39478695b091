#include "transcription/total_branching.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

#include "common/format.h"
#include "milp/lp_bound.h"

namespace thrustsched::transcription {

using common::FormatG;

namespace {

using Clock = std::chrono::steady_clock;

// Totals closer than this to an integer are not branched on (the interior
// point stops short of exact vertices).
constexpr double kIntegralTotal = 1e-3;

struct Leaf {
  std::vector<double> lower, upper;  // per thruster: bounds on its total
  double bound = -milp::kInfinity;
  Eigen::VectorXd x;  // its LP point; empty when it has none (not split)
  int order = 0;      // creation order, for ties
};

// The thruster whose total is nearest to half a slot from an integer; -1 if
// every total is integral.
int MostFractional(const std::vector<double>& y) {
  int best = -1;
  double best_distance = 0.5 - kIntegralTotal;
  for (size_t i = 0; i < y.size(); ++i) {
    const double distance = std::abs(y[i] - std::floor(y[i]) - 0.5);
    if (distance < best_distance) {
      best = static_cast<int>(i);
      best_distance = distance;
    }
  }
  return best;
}

class Tree {
 public:
  Tree(const ScheduleMilp& milp, const milp::Solver& solver, const milp::SolveOptions& options,
       double incumbent, double step)
      : milp_(milp),
        solver_(solver),
        options_(options),
        incumbent_(incumbent),
        step_(step),
        start_(Clock::now()) {}

  TotalBranching Run(const Eigen::VectorXd& root_x, double root_bound, int max_lps) {
    const int m = milp_.encoding().num_thrusters;
    const double n = milp_.encoding().num_intervals;
    leaves_.push_back({std::vector<double>(static_cast<size_t>(m), 0.0),
                       std::vector<double>(static_cast<size_t>(m), n), root_bound, root_x, 0});
    const std::string why = Search(max_lps);
    TotalBranching out;
    out.lps = lps_;
    const Leaf& lowest = leaves_[static_cast<size_t>(Lowest())];
    out.bound = lowest.bound;
    if (lowest.order > 0 && Below(lowest.bound) && lowest.x.size() > 0) {
      out.lowest_leaf_x = lowest.x;
      out.lowest_leaf_lower = lowest.lower;
      out.lowest_leaf_upper = lowest.upper;
    }
    for (const Leaf& leaf : leaves_) out.open_leaves += Below(leaf.bound) ? 1 : 0;
    std::string splits;
    for (const std::string& line : splits_) splits += (splits.empty() ? " (" : "; ") + line;
    if (!splits.empty()) splits += ")";
    out.detail = "branching on thruster totals: " + std::to_string(lps_) + " LPs" + splits +
                 ", bound " + FormatG(out.bound, 8) + " (root " + FormatG(root_bound, 8) + "), " +
                 std::to_string(out.open_leaves) + " leaves below the incumbent; " + why;
    return out;
  }

 private:
  std::string Search(int max_lps) {
    for (;;) {
      const int k = Lowest();
      if (!Below(leaves_[static_cast<size_t>(k)].bound))
        return "every leaf at the incumbent or above";
      if (lps_ + 2 > max_lps) return "LP limit (" + std::to_string(max_lps) + ")";
      if (Interrupted()) return "interrupted";
      if (Remaining() <= 0.0) return "time limit";
      Leaf parent = std::move(leaves_[static_cast<size_t>(k)]);
      leaves_.erase(leaves_.begin() + k);
      const std::vector<double> y =
          parent.x.size() > 0 ? ThrusterTotals(milp_.encoding(), parent.x) : std::vector<double>{};
      const int i = y.empty() ? -1 : MostFractional(y);
      if (i < 0) {
        leaves_.push_back(std::move(parent));
        return "the lowest leaf fires each thruster a whole number of slots";
      }
      const size_t u = static_cast<size_t>(i);
      Leaf down = parent, up = parent;
      down.upper[u] = std::floor(y[u]);
      up.lower[u] = std::ceil(y[u]);
      down.order = ++created_;
      up.order = ++created_;
      const double t0 = Elapsed();
      SolvePair(&down, &up);
      splits_.push_back(milp_.problem().thrusters.thruster(i).name + " at " + FormatG(y[u], 4) +
                        " slots: " + BoundText(down) + " / " + BoundText(up) + ", " +
                        FormatG(Elapsed() - t0, 3) + " s");
      leaves_.push_back(std::move(down));
      leaves_.push_back(std::move(up));
    }
  }

  // The two children of a split, side by side when the caller allows two
  // threads (milp::Solver::SolveLpRelaxations: each LP in its own process).
  void SolvePair(Leaf* down, Leaf* up) {
    const milp::LpData down_lp = WithThrusterTotals(milp_, down->lower, down->upper);
    const milp::LpData up_lp = WithThrusterTotals(milp_, up->lower, up->upper);
    milp::SolveOptions o = options_;
    o.time_limit_s = std::max(0.0, Remaining());
    const std::vector<milp::LpRelaxationResult> r =
        solver_.SolveLpRelaxations({&down_lp, &up_lp}, o);
    Take(down_lp, r[0], down);
    Take(up_lp, r[1], up);
  }

  void Take(const milp::LpData& lp, const milp::LpRelaxationResult& r, Leaf* leaf) {
    ++lps_;
    leaf->x.resize(0);
    if (r.status == milp::SolveStatus::kInfeasible) {
      leaf->bound = milp::kInfinity;
    } else if (r.status == milp::SolveStatus::kOptimal) {
      const milp::DualBound b = milp::SafeDualBound(lp, r.row_duals);
      leaf->bound = std::max(leaf->bound, milp::RoundBoundToStep(lp, b.bound, step_));
      leaf->x = r.x.head(milp_.lp().num_cols());
    }  // otherwise (a limit): the parent's bound, not split further
  }

  // A leaf whose LP stopped at a limit keeps its parent's bound and no point.
  static std::string BoundText(const Leaf& leaf) {
    return FormatG(leaf.bound, 6) + (leaf.x.size() == 0 && leaf.bound < milp::kInfinity
                                         ? " (LP stopped, parent's bound)"
                                         : "");
  }

  int Lowest() const {
    int best = 0;
    for (size_t k = 1; k < leaves_.size(); ++k) {
      const Leaf& a = leaves_[k];
      const Leaf& b = leaves_[static_cast<size_t>(best)];
      if (a.bound < b.bound || (a.bound == b.bound && a.order < b.order))
        best = static_cast<int>(k);
    }
    return best;
  }

  bool Below(double bound) const {
    if (!std::isfinite(incumbent_)) return bound < milp::kInfinity;  // no incumbent
    return bound < incumbent_ - 1e-7 * std::max(1.0, std::abs(incumbent_));
  }
  double Elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  double Remaining() const { return options_.time_limit_s - Elapsed(); }
  bool Interrupted() const {
    return options_.interrupt != nullptr && options_.interrupt->load(std::memory_order_relaxed);
  }

  const ScheduleMilp& milp_;
  const milp::Solver& solver_;
  const milp::SolveOptions& options_;
  double incumbent_;
  double step_;
  Clock::time_point start_;
  std::vector<Leaf> leaves_;
  int lps_ = 0;
  int created_ = 0;
  std::vector<std::string> splits_;  // "+N at 0.4513 slots: down / up bound"
};

}  // namespace

std::vector<double> ThrusterTotals(const OperationalEncoding& enc, const Eigen::VectorXd& x) {
  std::vector<double> y(static_cast<size_t>(enc.num_thrusters), 0.0);
  for (int i = 0; i < enc.num_thrusters; ++i) {
    for (int j = 0; j < enc.num_intervals; ++j)
      y[static_cast<size_t>(i)] += x[enc.on[i][j].index()];
  }
  return y;
}

milp::LpData WithThrusterTotals(const ScheduleMilp& milp, const std::vector<double>& lower,
                                const std::vector<double>& upper) {
  milp::LpData lp = milp.lp();
  const OperationalEncoding& enc = milp.encoding();
  const int n = enc.num_intervals;
  std::vector<milp::SparseRow> rows;
  for (int i = 0; i < enc.num_thrusters; ++i) {
    const size_t u = static_cast<size_t>(i);
    if (!TotalIsBounded(lower[u], upper[u], n)) continue;
    std::vector<milp::ColumnSpec> sums(static_cast<size_t>(n));
    for (int j = 0; j < n; ++j) {
      sums[static_cast<size_t>(j)] = {0.0, j + 1.0, 0.0, milp::VarType::kContinuous,
                                      "total_" + std::to_string(i) + "_" + std::to_string(j)};
    }
    sums.back().lower = std::max(0.0, lower[u]);
    sums.back().upper = std::min(static_cast<double>(n), upper[u]);
    const int first = milp::AppendColumns(&lp, sums);
    for (int j = 0; j < n; ++j) {
      milp::SparseRow row;  // p_j - p_{j-1} - on[i][j] = 0
      row.columns = {first + j, enc.on[i][j].index()};
      row.coefficients = {1.0, -1.0};
      if (j > 0) {
        row.columns.push_back(first + j - 1);
        row.coefficients.push_back(-1.0);
      }
      row.lower = row.upper = 0.0;
      row.name = "total_" + std::to_string(i) + "_" + std::to_string(j);
      rows.push_back(std::move(row));
    }
  }
  milp::AppendRows(&lp, rows);
  return lp;
}

TotalBranching BranchOnThrusterTotals(const ScheduleMilp& milp, const milp::Solver& solver,
                                      const milp::SolveOptions& lp_options,
                                      const Eigen::VectorXd& root_x, double root_bound,
                                      double incumbent, double step, int max_lps) {
  return Tree(milp, solver, lp_options, incumbent, step).Run(root_x, root_bound, max_lps);
}

}  // namespace thrustsched::transcription
