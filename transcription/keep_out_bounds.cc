#include "transcription/internal/keep_out_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace thrustsched::transcription::internal {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Item {
  double coef, cost, upper;
};

// Exact minimum of sum_c coef_c v_c (all coef_c < 0) over {sum_c cost_c v_c
// <= budget, 0 <= v_c <= upper_c}: a fractional knapsack, most negative
// coefficient per unit cost first. -inf if a column without bound can go down.
double KnapsackMin(std::vector<Item> items, double budget) {
  auto ratio = [](const Item& x) { return x.cost > 0.0 ? x.coef / x.cost : -kInf; };
  std::sort(items.begin(), items.end(),
            [&](const Item& a, const Item& b) { return ratio(a) < ratio(b); });
  double total = 0.0, left = budget;
  for (const Item& x : items) {
    if (left <= 0.0 && x.cost > 0.0) break;
    const double take = x.cost > 0.0 ? std::min(x.upper, left / x.cost) : x.upper;
    if (std::isinf(take)) return -kInf;
    total += x.coef * take;
    left -= take * x.cost;
  }
  return total;
}

}  // namespace

std::pair<double, double> KnapsackRange(const std::vector<Effect>& effects,
                                        const Eigen::VectorXd& a, double budget) {
  std::vector<Item> down, up;
  for (const Effect& f : effects) {
    const double coef = a.dot(f.e);
    if (coef == 0.0 || f.upper <= 0.0) continue;
    (coef < 0.0 ? down : up).push_back({coef < 0.0 ? coef : -coef, f.cost, f.upper});
  }
  return {KnapsackMin(down, budget), -KnapsackMin(up, budget)};
}

ThrustBounds ReadBounds(const KeepOutColumns& cols, const milp::Model& model) {
  ThrustBounds b;
  for (const auto& row : cols.thrust) {
    b.cost.emplace_back();
    b.upper.emplace_back();
    for (const milp::Variable& v : row) {
      b.cost.back().push_back(model.objective_coefficient(v));
      b.upper.back().push_back(model.upper_bound(v));
    }
  }
  return b;
}

std::vector<Effect> Effects(const ScheduleProblem& p, const dynamics::DiscreteModel& d,
                            const std::vector<Eigen::MatrixXd>& kick, const PartialMap& at,
                            const Eigen::MatrixXd& map, const KeepOutColumns& cols,
                            const ThrustBounds& b) {
  std::vector<Effect> out;
  const int m = p.thrusters.size();
  const int last = at.interval;
  Eigen::MatrixXd r = map * at.phi;  // map Phi(t, t_last)
  auto push = [&](int i, int slot, const Eigen::VectorXd& e) {
    out.push_back({cols.thrust[i][slot].index(), b.cost[i][slot], b.upper[i][slot], e});
  };
  for (int i = 0; i < m; ++i) {
    push(i, last,
         cols.impulsive ? Eigen::VectorXd(r * kick[last].col(i))
                        : Eigen::VectorXd(map * at.gamma.col(i)));
  }
  for (int j = last - 1; j >= 0; --j) {
    if (cols.impulsive) {
      r = r * d.phi[j];  // P Phi(t_k, t_j): x(t_j+1) = Phi_j (x_j + kick_j dv_j) + d_j
      for (int i = 0; i < m; ++i) push(i, j, Eigen::VectorXd(r * kick[j].col(i)));
    } else {
      for (int i = 0; i < m; ++i) push(i, j, Eigen::VectorXd(r * d.gamma[j].col(i)));
      r = r * d.phi[j];
    }
  }
  return out;
}

ReachLp::ReachLp(const ScheduleProblem& p, const dynamics::DiscreteModel& d,
                 const std::vector<Eigen::MatrixXd>& kick, const KeepOutColumns& cols,
                 const ThrustBounds& b, double budget, const milp::Solver& solver)
    : solver_(solver) {
  const int n = p.model->num_states();
  const int nn = p.num_intervals();
  // Effects of every thrust column on the final state (after the last impulse).
  PartialMap end;
  end.t = p.grid.back();
  end.interval = nn - 1;
  end.phi = d.phi[nn - 1];
  end.gamma = d.gamma[nn - 1];
  end.drift = d.drift[nn - 1];
  std::vector<Effect> final_effects =
      Effects(p, d, kick, end, Eigen::MatrixXd::Identity(n, n), cols, b);
  if (cols.impulsive) {
    for (int i = 0; i < p.thrusters.size(); ++i) {
      final_effects.push_back(
          {cols.thrust[i][nn].index(), b.cost[i][nn], b.upper[i][nn], kick[nn].col(i)});
    }
  }
  Eigen::VectorXd free = p.initial_state;
  for (int j = 0; j < nn; ++j) free = d.phi[j] * free + d.drift[j];

  milp::Model model("keep_out_reach");
  int largest = 0;
  for (const auto& row : cols.thrust) {
    for (const milp::Variable& v : row) largest = std::max(largest, v.index());
  }
  lp_column_.assign(largest + 1, -1);
  std::vector<milp::Variable> vars;
  for (const Effect& f : final_effects) {
    lp_column_[f.column] = static_cast<int>(vars.size());
    vars.push_back(model.AddContinuous(0.0, f.upper));
  }
  const TerminalSpec& term = p.terminal;
  if (term.kind == TerminalKind::kFixedState || term.kind == TerminalKind::kStateBox) {
    const Eigen::VectorXd s = p.model->state_scale();
    for (int c = 0; c < n; ++c) {
      const double tol = term.kind == TerminalKind::kStateBox ? term.tolerance[c] : 0.0;
      if (std::isinf(tol)) continue;
      milp::LinearExpr row;
      for (const Effect& f : final_effects) row.AddTerm(vars[lp_column_[f.column]], f.e[c] / s[c]);
      model.AddConstraint(row, (term.target[c] - tol - free[c]) / s[c],
                          (term.target[c] + tol - free[c]) / s[c]);
    }
  }
  if (std::isfinite(budget)) {
    milp::LinearExpr row;
    for (const Effect& f : final_effects) row.AddTerm(vars[lp_column_[f.column]], f.cost);
    model.AddConstraint(row, -kInf, budget);
  }
  lp_ = model.ToLpData();
}

std::pair<double, double> ReachLp::Range(const std::vector<Effect>& effects,
                                         const Eigen::VectorXd& a) const {
  milp::LpData lp = lp_;
  lp.col_cost.setZero();
  for (const Effect& f : effects) {
    const int col = f.column < static_cast<int>(lp_column_.size()) ? lp_column_[f.column] : -1;
    if (col >= 0) lp.col_cost[col] += a.dot(f.e);
  }
  const milp::LpRelaxationResult low = solver_.SolveLpRelaxation(lp);
  lp.col_cost = -lp.col_cost;
  const milp::LpRelaxationResult high = solver_.SolveLpRelaxation(lp);
  return {low.status == milp::SolveStatus::kOptimal ? low.objective : -kInf,
          high.status == milp::SolveStatus::kOptimal ? -high.objective : kInf};
}

}  // namespace thrustsched::transcription::internal
