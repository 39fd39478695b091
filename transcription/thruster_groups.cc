// The groups of thrusters whose totals the tree bounds (axes, stand-ins,
// windows) and the LPs with bounds on those totals (total_branching.h).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "milp/lp_bound.h"
#include "transcription/total_branching.h"

namespace thrustsched::transcription {

namespace {
// Directions whose cosine is within this of +-1 share an axis.
constexpr double kSameAxisTolerance = 1e-9;
// Firings whose final-state effects have a cosine within this of 1 stand in
// for each other.
constexpr double kStandInTolerance = 1e-3;
}  // namespace

std::vector<double> ThrusterTotals(const OperationalEncoding& enc, const Eigen::VectorXd& x) {
  std::vector<double> y(static_cast<size_t>(enc.num_thrusters), 0.0);
  for (int i = 0; i < enc.num_thrusters; ++i) {
    for (int j = 0; j < enc.num_intervals; ++j)
      y[static_cast<size_t>(i)] += x[enc.on[i][j].index()];
  }
  return y;
}

std::vector<double> GroupTotalsAt(const std::vector<ThrusterGroup>& groups,
                                  const OperationalEncoding& enc, const Eigen::VectorXd& x) {
  std::vector<double> y(groups.size(), 0.0);
  for (size_t g = 0; g < groups.size(); ++g) {
    for (int i : groups[g].thrusters) {
      for (int j = groups[g].first_interval; j < groups[g].End(enc.num_intervals); ++j)
        y[g] += x[enc.on[i][j].index()];
    }
  }
  return y;
}

std::vector<ThrusterGroup> WindowGroups(const OperationalEncoding& enc,
                                        const dynamics::ThrusterSet& thrusters,
                                        const Eigen::VectorXd& x, int levels) {
  const int n = enc.num_intervals;
  const std::vector<double> totals = ThrusterTotals(enc, x);
  std::vector<ThrusterGroup> windows;
  for (int i = 0; i < enc.num_thrusters; ++i) {
    if (totals[static_cast<size_t>(i)] <= kIntegralTotal) continue;
    for (int level = 1; level <= levels && (1 << level) <= n; ++level) {
      const int parts = 1 << level;
      for (int k = 0; k < parts; ++k) {
        ThrusterGroup g;
        g.thrusters = {i};
        g.first_interval = k * n / parts;
        g.end_interval = (k + 1) * n / parts;
        g.level = level;
        g.name = thrusters.thruster(i).name + " in slots " + std::to_string(g.first_interval) +
                 "-" + std::to_string(g.end_interval - 1);
        windows.push_back(std::move(g));
      }
    }
  }
  return windows;
}

Eigen::MatrixXi SlotsFreeByReducedCost(const OperationalEncoding& enc, const milp::LpData& lp,
                                       const milp::DualBound& bound, double incumbent,
                                       double step) {
  const milp::LpData fixed = milp::FixByReducedCost(lp, bound, incumbent, step);
  Eigen::MatrixXi mask(enc.num_thrusters, enc.num_intervals);
  for (int i = 0; i < enc.num_thrusters; ++i) {
    for (int j = 0; j < enc.num_intervals; ++j)
      mask(i, j) = fixed.col_upper[enc.on[i][j].index()] > 0.5 ? 1 : 0;
  }
  return mask;
}

namespace {

// Each thruster's effect on the final state of a unit firing in each slot,
// Phi(t_N, t_{j+1}) Gamma_j e_i, scaled by the model's state scales and
// normalised: column j of element i.
std::vector<Eigen::MatrixXd> FinalStateEffects(const ScheduleMilp& milp) {
  const dynamics::DiscreteModel& d = milp.discrete();
  const int n = d.num_states(), N = d.num_intervals(), m = milp.encoding().num_thrusters;
  const Eigen::VectorXd scale = milp.problem().model->state_scale();
  std::vector<Eigen::MatrixXd> effects(static_cast<size_t>(m), Eigen::MatrixXd(n, N));
  Eigen::MatrixXd to_end = Eigen::MatrixXd::Identity(n, n);  // Phi(t_N, t_{j+1})
  for (int j = N - 1; j >= 0; --j) {
    const Eigen::MatrixXd moved = to_end * d.gamma[static_cast<size_t>(j)];
    for (int i = 0; i < m; ++i) {
      Eigen::VectorXd e = moved.col(i).cwiseQuotient(scale);
      const double norm = e.norm();
      effects[static_cast<size_t>(i)].col(j) = norm > 0.0 ? Eigen::VectorXd(e / norm) : e;
    }
    to_end = to_end * d.phi[static_cast<size_t>(j)];
  }
  return effects;
}

// Whether thruster b can stand in for thruster a: for every slot of a, some
// slot of b moves the final state the same way (cosine of the effects). By
// blocks of a's slots: the cosines of all pairs of slots would take
// N^2 doubles (3 GB for two weeks of 1-min slots).
bool StandsIn(const std::vector<Eigen::MatrixXd>& effects, int a, int b) {
  const Eigen::MatrixXd& ea = effects[static_cast<size_t>(a)];
  const Eigen::MatrixXd& eb = effects[static_cast<size_t>(b)];
  constexpr Eigen::Index kBlock = 256;
  for (Eigen::Index first = 0; first < ea.cols(); first += kBlock) {
    const Eigen::Index size = std::min(kBlock, ea.cols() - first);
    const Eigen::MatrixXd cosines = ea.middleCols(first, size).transpose() * eb;
    if (cosines.rowwise().maxCoeff().minCoeff() <= 1.0 - kStandInTolerance) return false;
  }
  return true;
}

}  // namespace

std::vector<ThrusterGroup> ThrusterAxes(const dynamics::ThrusterSet& thrusters) {
  std::vector<ThrusterGroup> axes;
  for (int i = 0; i < thrusters.size(); ++i) {
    auto same = [&](const ThrusterGroup& axis) {
      const double cosine =
          thrusters.thruster(i).direction.dot(thrusters.thruster(axis.thrusters.front()).direction);
      return std::abs(cosine) > 1.0 - kSameAxisTolerance;
    };
    const auto axis = std::find_if(axes.begin(), axes.end(), same);
    if (axis == axes.end()) {
      axes.push_back({{i}, thrusters.thruster(i).name});
    } else {
      axis->thrusters.push_back(i);
      axis->name += " and " + thrusters.thruster(i).name;
    }
  }
  return axes;
}

std::vector<ThrusterGroup> TotalGroups(const ScheduleMilp& milp, bool axis_groups) {
  const dynamics::ThrusterSet& thrusters = milp.problem().thrusters;
  if (milp.discrete().gamma.empty()) axis_groups = false;  // no slots to compare
  const int m = thrusters.size();
  std::vector<Eigen::MatrixXd> effects;
  // The first thruster of i's group: an earlier one on its axis (ThrusterAxes)
  // that stands in for it both ways, else i.
  std::vector<int> axis(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) axis[static_cast<size_t>(i)] = i;
  for (const ThrusterGroup& on_axis :
       axis_groups ? ThrusterAxes(thrusters) : std::vector<ThrusterGroup>{}) {
    const std::vector<int>& t = on_axis.thrusters;
    for (size_t b = 1; b < t.size(); ++b) {
      for (size_t a = 0; a < b; ++a) {
        if (effects.empty()) effects = FinalStateEffects(milp);
        const int first = axis[static_cast<size_t>(t[a])];
        if (StandsIn(effects, first, t[b]) && StandsIn(effects, t[b], first)) {
          axis[static_cast<size_t>(t[b])] = first;
          break;
        }
      }
    }
  }
  std::vector<ThrusterGroup> groups;
  for (int first = 0; first < m; ++first) {
    ThrusterGroup g;
    for (int i = first; i < m; ++i) {
      if (axis[static_cast<size_t>(i)] != first) continue;
      g.thrusters.push_back(i);
      g.name += (g.name.empty() ? "" : " and ") + thrusters.thruster(i).name;
    }
    if (g.thrusters.size() > 1) groups.push_back(std::move(g));
  }
  for (int i = 0; i < m; ++i) groups.push_back({{i}, thrusters.thruster(i).name});
  return groups;
}

namespace {

// Appends group g's running totals p_j = p_{j-1} + sum over the group of
// on[i][j] (columns, bounded by [0, (j + 1) x its thrusters], and their
// defining rows to `rows`); returns the column of p_last, its total.
int AppendGroupTotal(milp::LpData* lp, const OperationalEncoding& enc, const ThrusterGroup& group,
                     const std::string& tag, std::vector<milp::SparseRow>* rows) {
  const int begin = group.first_interval, n = group.End(enc.num_intervals) - begin;
  const int size = static_cast<int>(group.thrusters.size());
  std::vector<milp::ColumnSpec> sums(static_cast<size_t>(n));
  for (int j = 0; j < n; ++j) {
    sums[static_cast<size_t>(j)] = {0.0, (j + 1.0) * size, 0.0, milp::VarType::kContinuous,
                                    tag + "_" + std::to_string(j)};
  }
  const int first = milp::AppendColumns(lp, sums);
  for (int j = 0; j < n; ++j) {
    milp::SparseRow row;  // p_j - p_{j-1} - sum over the group of on[i][begin + j] = 0
    row.columns = {first + j};
    row.coefficients = {1.0};
    for (int i : group.thrusters) {
      row.columns.push_back(enc.on[i][begin + j].index());
      row.coefficients.push_back(-1.0);
    }
    if (j > 0) {
      row.columns.push_back(first + j - 1);
      row.coefficients.push_back(-1.0);
    }
    row.lower = row.upper = 0.0;
    row.name = tag + "_" + std::to_string(j);
    rows->push_back(std::move(row));
  }
  return first + n - 1;
}

// Appends a group's elastic slots: the columns short and over, each in
// [0, most] and costing `cost_per_slot` (in the LP's sense); returns the
// first one's index (over is the next).
int AppendShortAndOver(milp::LpData* lp, double most, double cost_per_slot,
                       const std::string& tag) {
  const double cost = (lp->sense == milp::ObjectiveSense::kMaximize ? -1.0 : 1.0) * cost_per_slot;
  return milp::AppendColumns(lp, {{0.0, most, cost, milp::VarType::kContinuous, tag + "_short"},
                                  {0.0, most, cost, milp::VarType::kContinuous, tag + "_over"}});
}

}  // namespace

milp::LpData WithGroupTotals(const ScheduleMilp& milp, const std::vector<ThrusterGroup>& groups,
                             const std::vector<double>& lower, const std::vector<double>& upper,
                             double elastic_cost_per_slot) {
  milp::LpData lp = milp.lp();
  const OperationalEncoding& enc = milp.encoding();
  const int n = enc.num_intervals;
  std::vector<milp::SparseRow> rows;
  for (size_t g = 0; g < groups.size(); ++g) {
    const int most = groups[g].MaxTotal(n);
    if (!TotalIsBounded(lower[g], upper[g], groups[g], n)) continue;
    const double lo = std::max(0.0, lower[g]), hi = std::min(static_cast<double>(most), upper[g]);
    const std::string tag = "total_" + std::to_string(g);
    const int total = AppendGroupTotal(&lp, enc, groups[g], tag, &rows);
    if (elastic_cost_per_slot > 0.0) {
      // lower <= total + short - over <= upper: never infeasible.
      const int slack = AppendShortAndOver(&lp, most, elastic_cost_per_slot, tag);
      milp::SparseRow row;
      row.columns = std::vector<int>{total, slack, slack + 1};
      row.coefficients = {1.0, 1.0, -1.0};
      row.lower = lo;
      row.upper = hi;
      row.name = tag + "_bounds";
      rows.push_back(std::move(row));
    } else {
      lp.col_lower[total] = lo;
      lp.col_upper[total] = hi;
    }
  }
  milp::AppendRows(&lp, rows);
  return lp;
}

GroupTotalsLp WithGroupTotalColumns(const ScheduleMilp& milp,
                                    const std::vector<ThrusterGroup>& groups,
                                    double elastic_cost_per_slot) {
  GroupTotalsLp out{milp.lp(), {}, {}};
  milp::LpData& lp = out.lp;
  const OperationalEncoding& enc = milp.encoding();
  std::vector<milp::SparseRow> rows;
  for (size_t g = 0; g < groups.size(); ++g) {
    const double most = groups[g].MaxTotal(enc.num_intervals);
    const std::string tag = "total_" + std::to_string(g);
    // One row per group (the interior point runs once, on the root, whose
    // totals are free; with crossover it took 11 s on a six-thruster GEO
    // week with these seven rows).
    const int bound =
        milp::AppendColumns(&lp, {{0.0, most, 0.0, milp::VarType::kContinuous, tag + "_bounded"}});
    milp::SparseRow row;  // sum over the group of on[i][j] (+ short - over) - bounded = 0
    for (int i : groups[g].thrusters) {
      for (int j = groups[g].first_interval; j < groups[g].End(enc.num_intervals); ++j) {
        row.columns.push_back(enc.on[i][j].index());
        row.coefficients.push_back(1.0);
      }
    }
    if (elastic_cost_per_slot > 0.0) {
      const int slack = AppendShortAndOver(&lp, most, elastic_cost_per_slot, tag);
      row.columns.insert(row.columns.end(), {slack, slack + 1});
      row.coefficients.insert(row.coefficients.end(), {1.0, -1.0});
      out.elastic_column.insert(out.elastic_column.end(), {slack, slack + 1});
    }
    row.columns.push_back(bound);
    row.coefficients.push_back(-1.0);
    row.lower = row.upper = 0.0;
    row.name = tag;
    rows.push_back(std::move(row));
    out.bound_column.push_back(bound);
  }
  milp::AppendRows(&lp, rows);
  return out;
}

milp::LpData WithThrusterTotals(const ScheduleMilp& milp, const std::vector<double>& lower,
                                const std::vector<double>& upper) {
  std::vector<ThrusterGroup> singles;
  for (int i = 0; i < milp.encoding().num_thrusters; ++i) singles.push_back({{i}, ""});
  return WithGroupTotals(milp, singles, lower, upper);
}

}  // namespace thrustsched::transcription
