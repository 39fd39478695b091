#include "transcription/keep_out.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "common/format.h"
#include "transcription/conjunction_geometry.h"
#include "transcription/internal/keep_out_bounds.h"
#include "transcription/internal/row_buffer.h"
#include "transcription/operations.h"

namespace thrustsched::transcription {
namespace {

using common::FormatG;

constexpr double kInf = std::numeric_limits<double>::infinity();

void AddBudgetRow(double budget, milp::Model* model) {
  milp::LinearExpr objective;
  for (int c = 0; c < model->num_variables(); ++c) {
    const milp::Variable v = model->variable(c);
    const double cost = model->objective_coefficient(v);
    if (cost == 0.0) continue;
    if (cost < 0.0 || model->lower_bound(v) < 0.0) {
      throw std::invalid_argument(
          "conjunction.cost_budget: the objective has a term that can be "
          "negative (column " +
          model->variable_name(v) + ")");
    }
    objective.AddTerm(v, cost);
  }
  model->AddConstraint(objective, -kInf, budget - model->objective_offset(), "keep_out_budget");
}

// Bounds |r_i| <= W_i that the hard window gives the local position at a
// check on a grid node where it is enforced: an axis whose position row is a
// multiple s of a windowed output's row (HCW/YA: y, z; GEO: y = rho lon,
// z = rho lat) gets |s| times the planned half width. Infinite elsewhere
// (between nodes the window is not a constraint).
Eigen::Vector3d WindowBounds(const ScheduleProblem& p, const CheckGeometry& k) {
  Eigen::Vector3d w = Eigen::Vector3d::Constant(kInf);
  const WindowSpec& win = p.window;
  const int node = k.map.interval;
  const bool at_node = std::abs(k.t() - p.grid[node]) <= 1e-9 * (p.grid[1] - p.grid[0]);
  if (!win.enabled() || win.soft || !at_node || node < 1 ||
      k.t() < win.enforce_from_s - kTimeTolerance) {
    return w;
  }
  const Eigen::MatrixXd c = p.model->EvaluateOutput(k.t()).c;
  for (int i = 0; i < 3; ++i) {
    const Eigen::RowVectorXd row = k.position.row(i);
    for (size_t q = 0; q < win.outputs.size(); ++q) {
      const Eigen::RowVectorXd out = c.row(win.outputs[q]);
      const double s = row.dot(out) / out.squaredNorm();
      if ((row - s * out).norm() <= 1e-12 * row.norm() && s != 0.0) {
        w[i] = std::min(w[i], std::abs(s) * win.half_widths[q] * (1.0 - win.margin));
      }
    }
  }
  return w;
}

double Median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

KeepOutStats AddKeepOut(const ScheduleProblem& p, const dynamics::DiscreteModel& d,
                        const dynamics::DiscretizationOptions& options, const KeepOutColumns& cols,
                        milp::Model* model, const milp::Solver* bound_solver) {
  if (!p.conjunction) throw std::invalid_argument("AddKeepOut: the problem has no conjunction");
  const ConjunctionSpec& c = *p.conjunction;
  const ConjunctionGeometry g = ComputeConjunctionGeometry(p, d, options);
  const dynamics::LinearModel& dyn = *p.model;
  const int n = dyn.num_states();
  const int m = p.thrusters.size();
  const int nn = p.num_intervals();
  KeepOutStats s;
  s.num_checks = static_cast<int>(g.checks.size());
  s.threshold = c.instantaneous_threshold;
  s.quantile = g.quantile;
  s.covariance_min_eigenvalue = g.covariance_min_eigenvalue;
  s.covariance_repaired = g.covariance_repaired;
  s.cost_budget = c.cost_budget;
  const internal::ThrustBounds bounds = internal::ReadBounds(cols, *model);
  s.first_binary_column = model->num_variables();
  if (std::isfinite(c.cost_budget)) AddBudgetRow(c.cost_budget, model);

  // Impulse directions in the state (B(t_j) D) and the thrust-free path.
  std::vector<Eigen::MatrixXd> kick;
  if (cols.impulsive) {
    Eigen::MatrixXd dirs(3, m);
    for (int i = 0; i < m; ++i) dirs.col(i) = p.thrusters.thruster(i).direction;
    for (int j = 0; j <= nn; ++j) kick.push_back(dyn.Evaluate(p.grid[j]).b * dirs);
  }
  std::optional<internal::ReachLp> reach;
  if (bound_solver != nullptr)
    reach.emplace(p, d, kick, cols, bounds, c.cost_budget, *bound_solver);
  std::vector<Eigen::VectorXd> free(nn + 1);
  free[0] = p.initial_state;
  for (int j = 0; j < nn; ++j) free[j + 1] = d.phi[j] * free[j] + d.drift[j];

  internal::RowBuffer rows(/*scale=*/true);
  std::vector<double> big_ms;
  for (size_t kk = 0; kk < g.checks.size(); ++kk) {
    const CheckGeometry& k = g.checks[kk];
    const int j = k.map.interval;
    s.margin_max_m = std::max(s.margin_max_m, k.margins.maxCoeff());
    const std::vector<internal::Effect> effects =
        internal::Effects(p, d, kick, k.map, k.position, cols, bounds);
    const Eigen::Vector3d drift_pos = k.position * k.map.drift + k.position_offset;
    const Eigen::Vector3d r_free = k.position * (k.map.phi * free[j]) + drift_pos;
    const Eigen::Vector3d window = WindowBounds(p, k);
    struct Face {
      int f;
      double rhs, big_m;
    };
    std::vector<Face> faces;
    Face closest{-1, 0.0, 0.0};  // the impossible face missed by the least
    double closest_miss = kInf;
    bool clear = false;
    for (int f = 0; f < g.polytope.size() && !clear; ++f) {
      const Eigen::Vector3d a = g.polytope.faces.row(f).transpose();
      const double rhs = g.polytope.offsets[f] + k.margins[f] + a.dot(k.secondary);
      auto [lo, hi] = internal::KnapsackRange(effects, a, c.cost_budget);
      if (reach && a.dot(r_free) + lo < rhs &&
          a.dot(r_free) + hi >= rhs) {  // undecided: ask the LP
        const auto [lp_lo, lp_hi] = reach->Range(effects, a);
        lo = std::max(lo, lp_lo);
        hi = std::min(hi, lp_hi);
      }
      double low = a.dot(r_free) + lo, high = a.dot(r_free) + hi;
      double reach = 0.0;  // inf unless the window bounds every axis a uses
      for (int i = 0; i < 3; ++i) {
        if (a[i] != 0.0) reach += std::abs(a[i]) * window[i];
      }
      if (std::isfinite(reach)) {
        low = std::max(low, -reach);
        high = std::min(high, reach);
      }
      if (std::isinf(low)) {
        throw std::invalid_argument(
            "conjunction.cost_budget: an impulse column has no upper bound, so the keep-out big-M "
            "has no finite value; give conjunction.cost_budget (or max_impulse_m_s)");
      }
      if (low >= rhs) {
        clear = true;
      } else if (high < rhs) {
        ++s.faces_impossible;
        if (rhs - high < closest_miss) {
          closest_miss = rhs - high;
          closest = {f, rhs, 0.0};
        }
      } else {
        faces.push_back({f, rhs, (rhs - low) * (1.0 + 1e-9) + 1e-9 * std::abs(rhs)});
      }
    }
    if (clear) {
      ++s.checks_clear;
      continue;
    }
    if (faces.empty()) {
      // Infeasible by construction; the closest face stays as a hard row so
      // that the model itself is infeasible too.
      s.infeasibility_reasons.push_back(
          "keep-out at t = " + FormatG(k.t(), 10) +
          " s: no face of the polytope can be left with margin within "
          "the cost budget and thrust bounds (the closest is missed by " +
          FormatG(closest_miss, 10) + " m)");
      faces.push_back(closest);
    }
    KeepOutGroup group;
    group.t = k.t();
    std::vector<milp::Variable> w;
    if (faces.size() > 1) {
      ++s.checks_with_binaries;
      for (const Face& f : faces) {
        w.push_back(
            model->AddBinary("keep_out_w_" + std::to_string(kk) + "_" + std::to_string(f.f)));
        big_ms.push_back(f.big_m);
      }
      s.num_binaries += static_cast<int>(faces.size());
    } else {
      ++s.checks_single_face;
    }
    // a^T P [Phi (S x~_j + kick_j dv_j) + Gamma u_j + drift] + M w >= rhs.
    for (size_t q = 0; q < faces.size(); ++q) {
      const Eigen::Vector3d a = g.polytope.faces.row(faces[q].f).transpose();
      const Eigen::RowVectorXd on_state = a.transpose() * k.position * k.map.phi;
      rows.Begin();
      for (int col = 0; col < n; ++col)
        rows.Coef(cols.state[j][col].index(), on_state[col] * cols.scale[col]);
      for (int i = 0; i < m; ++i) {
        const double coef =
            cols.impulsive ? on_state.dot(kick[j].col(i)) : a.dot(k.position * k.map.gamma.col(i));
        rows.Coef(cols.thrust[i][j].index(), coef);
      }
      if (!w.empty()) rows.Coef(w[q].index(), faces[q].big_m);
      group.row_scale.push_back(
          rows.End(faces[q].rhs - a.dot(drift_pos), kInf,
                   "keep_out_" + std::to_string(kk) + "_" + std::to_string(faces[q].f)));
      group.faces.push_back(faces[q].f);
      group.rows.push_back(s.num_rows++);  // relative to the buffered block, fixed below
      group.binaries.push_back(w.empty() ? -1 : w[q].index());
      group.free_slack_m.push_back(a.dot(r_free) - faces[q].rhs);
    }
    s.groups.push_back(std::move(group));
    if (!w.empty()) {
      milp::LinearExpr sum;
      for (const milp::Variable& v : w) sum.AddTerm(v, 1.0);
      model->AddConstraint(sum, -kInf, static_cast<double>(w.size()) - 1.0,
                           "keep_out_pick_" + std::to_string(kk));
    }
  }
  const int base = model->num_constraints();
  rows.Flush(model);
  for (KeepOutGroup& grp : s.groups) {
    for (int& r : grp.rows) r += base;
  }
  if (!big_ms.empty()) {
    s.big_m_min_m = *std::min_element(big_ms.begin(), big_ms.end());
    s.big_m_max_m = *std::max_element(big_ms.begin(), big_ms.end());
    s.big_m_median_m = Median(big_ms);
  }
  return s;
}

void CompleteKeepOut(const milp::LpData& lp, const KeepOutStats& stats, Eigen::VectorXd* x) {
  if (x->size() != lp.num_cols()) {
    throw std::invalid_argument("CompleteKeepOut: the vector has " + std::to_string(x->size()) +
                                " entries, the model " + std::to_string(lp.num_cols()) +
                                " columns");
  }
  for (const KeepOutGroup& g : stats.groups) {
    for (int w : g.binaries) {
      if (w >= 0) (*x)[w] = 0.0;
    }
  }
  const Eigen::VectorXd act = lp.a_matrix * *x;  // keep-out binaries at 0
  for (const KeepOutGroup& g : stats.groups) {
    if (g.binaries.empty() || g.binaries[0] < 0) continue;
    size_t best = 0;
    double best_slack = -kInf;
    for (size_t q = 0; q < g.rows.size(); ++q) {
      const double slack = act[g.rows[q]] - lp.row_lower[g.rows[q]];
      if (slack > best_slack) best_slack = slack, best = q;
    }
    for (size_t q = 0; q < g.binaries.size(); ++q) (*x)[g.binaries[q]] = q == best ? 0.0 : 1.0;
  }
}

}  // namespace thrustsched::transcription
