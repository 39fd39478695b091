// The exhaustive reference of random_problems.h (EnumerateOptimum): every
// on-off pattern, independent of the transcription and of
// dynamics::Discretize.
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <Eigen/Core>
#include <unsupported/Eigen/MatrixFunctions>

#include "common/constants.h"
#include "tests/transcription/random_problems.h"
#include "transcription/checker.h"

namespace thrustsched::transcription::soak {
namespace {

// x(t + tau) = phi x(t) + gamma a + delta for a constant acceleration a
// (m/s^2, model input frame) over tau: the exponential of the augmented
// matrix [A B d; 0 0 0] tau (exact for a time-invariant model).
struct Hold {
  Eigen::MatrixXd phi, gamma;
  Eigen::VectorXd delta;
};

Hold ExactHold(const dynamics::LinearModel& model, double tau) {
  const dynamics::ModelMatrices mm = model.Evaluate(0.0);
  const int n = model.num_states(), u = model.num_inputs();
  Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(n + u + 1, n + u + 1);
  aug.topLeftCorner(n, n) = mm.a;
  aug.block(0, n, n, u) = mm.b;
  aug.block(0, n + u, n, 1) = mm.d;
  const Eigen::MatrixXd e = (aug * tau).exp();
  return {e.topLeftCorner(n, n), e.block(0, n, n, u), e.block(0, n + u, n, 1)};
}

// One interval's holds: to each inter-sample point, then to the next node.
struct IntervalHolds {
  std::vector<Hold> interior;
  Hold node;
};

class Enumerator {
 public:
  explicit Enumerator(const ScheduleProblem& p) : p_(p), n_(p.num_intervals()) {
    const int m = p.thrusters.size();
    const double a = p.thrusters.acceleration();
    for (int i = 0; i < m; ++i) {
      const Eigen::Vector3d dir = p.thrusters.thruster(i).direction.normalized();
      accel_.push_back(a * dir);
      switch (p.objective.kind) {
        case ObjectiveKind::kL1:
          rate_.push_back(a * dir.lpNorm<1>());
          break;
        case ObjectiveKind::kDeltaV:
          rate_.push_back(a);
          break;
        case ObjectiveKind::kPropellant:
          rate_.push_back(p.thrusters.thrust_n() /
                          (common::kStandardGravity_m_s2 * p.thrusters.isp_s()));
          break;
      }
    }
    for (unsigned mask = 0; mask < (1u << m); ++mask) {
      if (__builtin_popcount(mask) <= p.rules.max_simultaneous) masks_.push_back(mask);
    }
    c_ = p.model->EvaluateOutput(0.0).c;
    for (int j = 0; j < n_; ++j) {
      const double h = p.grid[j + 1] - p.grid[j];
      if (holds_.count(h)) continue;
      IntervalHolds ih;
      const int q = p.window.intersample_points;
      for (int s = 1; s <= q; ++s) ih.interior.push_back(ExactHold(*p.model, h * s / (q + 1)));
      ih.node = ExactHold(*p.model, h);
      holds_[h] = ih;
    }
    pattern_.assign(n_, 0u);
  }

  Reference Run() {
    Reference ref;
    ref.kind = ReferenceKind::kEnumeration;
    ref.decided = true;
    Visit(0, p_.initial_state, 0.0);
    ref.feasible = std::isfinite(best_);
    ref.objective = best_;
    ref.leaves = leaves_;
    return ref;
  }

 private:
  // Window term of the state x at time t: false when a hard window is broken;
  // adds the soft window's penalty to *cost.
  bool Judge(const Eigen::VectorXd& x, double t, double* cost) const {
    const WindowSpec& w = p_.window;
    if (t < w.enforce_from_s - 1e-9) return true;
    const Eigen::VectorXd y = c_ * x;
    for (size_t k = 0; k < w.outputs.size(); ++k) {
      const double width = w.half_widths[k] * (1.0 - w.margin);
      const double excess = std::abs(y[w.outputs[k]]) / width - 1.0;
      if (!w.soft && excess > 1e-9) return false;
      if (w.soft) *cost += w.soft_penalty * std::max(0.0, excess);
    }
    return true;
  }

  void Leaf(const Eigen::VectorXd& x, double cost) {
    ++leaves_;
    if (p_.terminal.kind == TerminalKind::kStateBox) {
      for (int i = 0; i < x.size(); ++i) {
        if (std::abs(x[i] - p_.terminal.target[i]) > p_.terminal.tolerance[i] + 1e-9) return;
      }
    }
    std::vector<Burn> burns;
    for (int i = 0; i < p_.thrusters.size(); ++i) {
      for (int j = 0; j < n_;) {
        if (((pattern_[j] >> i) & 1u) == 0) {
          ++j;
          continue;
        }
        int k = j;
        while (k < n_ && ((pattern_[k] >> i) & 1u) != 0) ++k;
        burns.push_back({i, p_.grid[j], p_.grid[k]});
        j = k;
      }
    }
    if (!CheckOperationalRules(p_.rules, p_.history, p_.forced_off, p_.thrusters.size(),
                               p_.grid.front(), p_.grid.back(), burns)
             .empty()) {
      return;
    }
    best_ = cost;
  }

  void Visit(int j, const Eigen::VectorXd& x, double cost) {
    if (cost >= best_) return;  // every term of the cost is >= 0
    if (j == n_) {
      Leaf(x, cost);
      return;
    }
    const double h = p_.grid[j + 1] - p_.grid[j];
    const IntervalHolds& ih = holds_.at(h);
    for (unsigned mask : masks_) {
      Eigen::Vector3d acc = Eigen::Vector3d::Zero();
      double c = cost;
      for (int i = 0; i < p_.thrusters.size(); ++i) {
        if (((mask >> i) & 1u) == 0) continue;
        acc += accel_[i];
        c += rate_[i] * h;
        if (j == 0 || ((pattern_[j - 1] >> i) & 1u) == 0) c += p_.objective.burn_start_penalty;
      }
      bool ok = true;
      const int q = static_cast<int>(ih.interior.size());
      for (int s = 0; s < q && ok; ++s) {
        const Hold& hs = ih.interior[s];
        ok = Judge(hs.phi * x + hs.gamma * acc + hs.delta, p_.grid[j] + h * (s + 1) / (q + 1), &c);
      }
      if (!ok) continue;
      const Eigen::VectorXd next = ih.node.phi * x + ih.node.gamma * acc + ih.node.delta;
      if (!Judge(next, p_.grid[j + 1], &c)) continue;
      pattern_[j] = mask;
      Visit(j + 1, next, c);
      pattern_[j] = 0u;
    }
  }

  const ScheduleProblem& p_;
  const int n_;
  std::vector<Eigen::Vector3d> accel_;
  std::vector<double> rate_;
  std::vector<unsigned> masks_;
  Eigen::MatrixXd c_;
  std::map<double, IntervalHolds> holds_;
  std::vector<unsigned> pattern_;
  double best_ = std::numeric_limits<double>::infinity();
  long long leaves_ = 0;
};

}  // namespace

Reference EnumerateOptimum(const ScheduleProblem& p) { return Enumerator(p).Run(); }

}  // namespace thrustsched::transcription::soak
