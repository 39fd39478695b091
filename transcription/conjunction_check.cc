#include "transcription/conjunction_check.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

#include <Eigen/LU>

#include "common/error.h"
#include "common/format.h"
#include "dynamics/geo_model.h"
#include "dynamics/geo_simulator.h"
#include "dynamics/models.h"
#include "dynamics/propagation.h"
#include "dynamics/two_body.h"
#include "transcription/collision_probability.h"
#include "transcription/terminal_sets.h"

namespace thrustsched::transcription {
namespace {

using Clock = std::chrono::steady_clock;
// The Monte Carlo grid's number of steps is whole up to this (rounding of the
// window's length over the step).
constexpr double kStepCountSlack = 1e-9;

// Sorted union of time lists; Index() finds a member exactly.
struct Timeline {
  std::vector<double> t;
  int Index(double v) const {
    return static_cast<int>(std::lower_bound(t.begin(), t.end(), v) - t.begin());
  }
};

Timeline Merge(std::vector<std::vector<double>> lists) {
  Timeline out;
  for (const auto& l : lists) out.t.insert(out.t.end(), l.begin(), l.end());
  std::sort(out.t.begin(), out.t.end());
  out.t.erase(std::unique(out.t.begin(), out.t.end()), out.t.end());
  return out;
}

// The planned primary at every time (after the impulse of a node at that node).
std::vector<Eigen::VectorXd> PrimaryPath(const ScheduleProblem& p, const std::vector<Burn>& burns,
                                         const std::vector<Impulse>& impulses,
                                         const std::vector<double>& times, double tol) {
  const dynamics::LinearModel& model = *p.model;
  if (p.input_mode == InputMode::kOnOff) {
    std::vector<dynamics::InputPulse> pulses;
    for (const Burn& b : burns) pulses.push_back({b.thruster, b.start_s, b.end_s});
    return dynamics::PropagateLinear(model, p.thrusters.AccelerationMatrix(), p.initial_state,
                                     p.grid.front(), pulses, times, tol);
  }
  const int nn = p.num_intervals();
  std::vector<Eigen::Vector3d> kick(nn + 1, Eigen::Vector3d::Zero());
  for (const Impulse& im : impulses) {
    if (im.node < 0 || im.node > nn || im.thruster < 0 || im.thruster >= p.thrusters.size()) {
      throw std::invalid_argument("CheckConjunction: impulse out of range (node " +
                                  std::to_string(im.node) + ")");
    }
    kick[im.node] += im.delta_v_m_s * p.thrusters.thruster(im.thruster).direction;
  }
  const Eigen::MatrixXd none = Eigen::MatrixXd::Zero(3, 1);
  std::vector<Eigen::VectorXd> out(times.size());
  Eigen::VectorXd x = p.initial_state;
  size_t i = 0;
  for (int j = 0; j <= nn && i < times.size(); ++j) {
    x += model.Evaluate(p.grid[j]).b * kick[j];
    std::vector<double> seg;
    const double end = j < nn ? p.grid[j + 1] : p.grid[j];
    size_t first = i;
    for (; i < times.size() && (times[i] < end || (j == nn && times[i] <= end)); ++i)
      seg.push_back(times[i]);
    if (j < nn) seg.push_back(end);
    const auto xs = dynamics::PropagateLinear(model, none, x, p.grid[j], {}, seg, tol);
    for (size_t q = first; q < i; ++q) out[q] = xs[q - first];
    if (j < nn) x = xs.back();
  }
  return out;
}

// Relative-state data on the timeline (model states, local positions).
struct Relative {
  Eigen::VectorXd secondary0;                  // model state at t0
  Eigen::MatrixXd covariance0;                 // at t0, model state
  std::vector<Eigen::VectorXd> secondary;      // mean, model state
  std::vector<Eigen::VectorXd> primary, free;  // planned and unmanoeuvred
  std::vector<Eigen::MatrixXd> position;       // 3 x n local position map
  dynamics::LinearFlow f;
};

Relative BuildRelative(const ScheduleProblem& p, const std::vector<Burn>& burns,
                       const std::vector<Impulse>& impulses, const Timeline& tl, double tol) {
  const ConjunctionSpec& c = *p.conjunction;
  const dynamics::LinearModel& model = *p.model;
  Relative r;
  r.f = dynamics::PropagateFlow(model, p.grid.front(), tl.t, tol);
  const Eigen::MatrixXd sigma = EffectiveCovariance(c, model.time_scale());
  const AffineMap local = HcwCoordinates(model, c.state_time_s);
  const Eigen::MatrixXd to_state = local.map.inverse();
  const int it = tl.Index(c.state_time_s);
  const Eigen::MatrixXd back = r.f.phi[it].inverse();
  r.secondary0 = back * (to_state * (c.secondary_state - local.offset) - r.f.drift[it]);
  r.covariance0 = back * to_state * sigma * to_state.transpose() * back.transpose();
  r.covariance0 = ClipToPositiveSemidefinite(r.covariance0);  // roundoff of a singular matrix
  r.primary = PrimaryPath(p, burns, impulses, tl.t, tol);
  for (size_t i = 0; i < tl.t.size(); ++i) {
    r.secondary.push_back(r.f.phi[i] * r.secondary0 + r.f.drift[i]);
    r.free.push_back(r.f.phi[i] * p.initial_state + r.f.drift[i]);
    r.position.push_back(HcwCoordinates(model, tl.t[i]).map.topRows(3));
  }
  return r;
}

// ---------------------------------------------------------------- nonlinear

// Inertial positions of the primary on the fine grid and the inertial state
// of a secondary sample at the window start, for the models with an exact
// inertial meaning. Empty `primary` = not available (note says why).
struct Inertial {
  std::vector<Eigen::Vector3d> primary;
  std::function<dynamics::Vector6d(const Eigen::VectorXd&)> secondary_eci;  // model state at a
  double mu = 0.0;
  std::string note;
};

Inertial YaInertial(const ScheduleProblem& p, const dynamics::YamanakaAnkersenModel& ya,
                    const std::vector<Impulse>& impulses, const Eigen::VectorXd& x_start,
                    const std::vector<double>& fine) {
  Inertial out;
  const double a = fine.front();
  out.mu = ya.mu();
  out.secondary_eci = [&ya, a](const Eigen::VectorXd& x) {
    return dynamics::EciFromRelative(ya, x, a);
  };
  std::vector<std::pair<double, Eigen::Vector3d>> kicks;  // inertial delta-v after the start
  for (const Impulse& im : impulses) {
    const double t = p.grid[im.node];
    if (t <= a || t > fine.back()) continue;
    kicks.push_back({t, dynamics::RelativeFrameBasis(ya, t) *
                            (im.delta_v_m_s * p.thrusters.thruster(im.thruster).direction)});
  }
  std::sort(kicks.begin(), kicks.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  dynamics::KeplerOrbit arc(dynamics::EciFromRelative(ya, x_start, a), a, ya.mu());
  size_t next = 0;
  for (double t : fine) {
    while (next < kicks.size() && kicks[next].first <= t) {
      dynamics::Vector6d s = arc.At(kicks[next].first);
      double when = kicks[next].first;
      for (; next < kicks.size() && kicks[next].first == when; ++next)
        s.tail<3>() += kicks[next].second;
      arc = dynamics::KeplerOrbit(s, when, ya.mu());
    }
    out.primary.push_back(arc.At(t).head<3>());
  }
  return out;
}

Inertial GeoInertial(const ScheduleProblem& p, const dynamics::GeoLinearModel& geo,
                     const std::vector<Burn>& burns, const Eigen::VectorXd& x_start,
                     const std::vector<double>& fine) {
  Inertial out;
  dynamics::GeoModelOptions kepler = geo.options();
  kepler.j2 = kepler.tesseral = kepler.sun = kepler.moon = kepler.srp = false;
  auto sim = std::make_shared<const dynamics::GeoSimulator>(kepler);
  const double a = fine.front(), b = fine.back();
  out.mu = dynamics::geo::kEarthMu;
  out.secondary_eci = [sim, a](const Eigen::VectorXd& x) { return sim->EciFromRelative(x, a); };
  std::vector<dynamics::InputPulse> pulses;
  for (const Burn& bu : burns) {
    const double s = std::max(bu.start_s, a), e = std::min(bu.end_s, b);
    if (e > s) pulses.push_back({bu.thruster, s, e});
  }
  const auto xs = sim->Propagate(sim->EciFromRelative(x_start, a), a,
                                 p.thrusters.AccelerationMatrix(), pulses, fine);
  for (const auto& x : xs) out.primary.push_back(x.head<3>());
  return out;
}

Inertial MakeInertial(const ScheduleProblem& p, const std::vector<Burn>& burns,
                      const std::vector<Impulse>& impulses, const Eigen::VectorXd& x_start,
                      const std::vector<double>& fine) {
  const bool impulsive = p.input_mode == InputMode::kImpulsive;
  if (const auto* ya = dynamic_cast<const dynamics::YamanakaAnkersenModel*>(p.model.get())) {
    if (impulsive) return YaInertial(p, *ya, impulses, x_start, fine);
  }
  if (const auto* geo = dynamic_cast<const dynamics::GeoLinearModel*>(p.model.get())) {
    if (!impulsive) return GeoInertial(p, *geo, burns, x_start, fine);
  }
  Inertial out;
  out.note = "no nonlinear two-body counterpart for the " + std::string(p.model->name()) +
             " model in " + (impulsive ? "impulsive" : "on-off") +
             " mode (available: yamanaka_ankersen impulsive, geo on-off)";
  return out;
}

}  // namespace

bool ConjunctionCheckOptions::IsValid(std::string* error) const {
  if (monte_carlo_samples < 0) {
    return common::Fail(
        error, "monte_carlo_samples must be >= 0, got " + std::to_string(monte_carlo_samples));
  }
  if (!(sample_step_s >= 0.0) || !std::isfinite(sample_step_s)) {
    return common::Fail(
        error, "sample_step_s must be finite and >= 0, got " + common::FormatG(sample_step_s, 10));
  }
  if (!(propagation_tolerance > 0.0) || !std::isfinite(propagation_tolerance)) {
    return common::Fail(error, "propagation_tolerance must be finite and > 0, got " +
                                   common::FormatG(propagation_tolerance, 10));
  }
  return true;
}

ConjunctionCheckReport CheckConjunction(const ScheduleProblem& p, const std::vector<Burn>& burns,
                                        const std::vector<Impulse>& impulses,
                                        const ConjunctionCheckOptions& o) {
  const Clock::time_point start = Clock::now();
  std::string err;
  if (!p.IsValid(&err)) throw std::invalid_argument(err);
  if (!p.conjunction)
    throw std::invalid_argument("CheckConjunction: the problem has no conjunction");
  if (!o.IsValid(&err)) throw std::invalid_argument("CheckConjunction: " + err);
  const ConjunctionSpec& c = *p.conjunction;
  const std::vector<double> checks = c.CheckTimes(p.grid.front(), p.grid.back());
  const double a = std::isnan(c.check_start_s) ? p.grid.front() : c.check_start_s;
  const double b = std::isnan(c.check_end_s) ? p.grid.back() : c.check_end_s;
  const double step = o.sample_step_s > 0.0 ? o.sample_step_s : (b - a) / 2000.0;
  const int steps = std::max(1, static_cast<int>(std::ceil((b - a) / step - kStepCountSlack)));
  std::vector<double> fine(steps + 1);
  for (int k = 0; k <= steps; ++k) fine[k] = a + (b - a) * k / steps;
  const Timeline tl = Merge({fine, checks, {c.state_time_s}});
  const Relative rel = BuildRelative(p, burns, impulses, tl, o.propagation_tolerance);

  ConjunctionCheckReport r;
  r.threshold = c.instantaneous_threshold;
  r.step_s = (b - a) / steps;
  for (double t : checks) {
    const int i = tl.Index(t);
    const Eigen::MatrixXd g = rel.position[i] * rel.f.phi[i];
    const Eigen::Matrix3d cov = g * rel.covariance0 * g.transpose();
    const Eigen::Matrix3d sym = 0.5 * (cov + cov.transpose());
    const double risk =
        BallProbability(rel.position[i] * (rel.primary[i] - rel.secondary[i]), sym, c.radius_m);
    const double free =
        BallProbability(rel.position[i] * (rel.free[i] - rel.secondary[i]), sym, c.radius_m);
    if (risk >= r.max_risk) r.max_risk = risk, r.max_risk_time_s = t;
    if (free >= r.max_risk_unmanoeuvred)
      r.max_risk_unmanoeuvred = free, r.max_risk_unmanoeuvred_time_s = t;
  }
  r.risk_ok = r.max_risk <= r.threshold;

  // Mean relative positions and sample maps on the fine grid.
  const int nf = static_cast<int>(fine.size());
  std::vector<Eigen::Vector3d> mu_plan(nf), mu_free(nf);
  std::vector<Eigen::Matrix<double, 3, Eigen::Dynamic>> g(nf);
  r.min_mean_distance_m = r.min_mean_distance_unmanoeuvred_m =
      std::numeric_limits<double>::infinity();
  for (int k = 0; k < nf; ++k) {
    const int i = tl.Index(fine[k]);
    mu_plan[k] = rel.position[i] * (rel.primary[i] - rel.secondary[i]);
    mu_free[k] = rel.position[i] * (rel.free[i] - rel.secondary[i]);
    g[k] = rel.position[i] * rel.f.phi[i];
    if (mu_plan[k].norm() < r.min_mean_distance_m) {
      r.min_mean_distance_m = mu_plan[k].norm();
      r.min_mean_distance_time_s = fine[k];
    }
    r.min_mean_distance_unmanoeuvred_m =
        std::min(r.min_mean_distance_unmanoeuvred_m, mu_free[k].norm());
  }

  r.samples = o.monte_carlo_samples;
  if (r.samples > 0) {
    const Eigen::MatrixXd factor = CovarianceFactor(rel.covariance0);
    const int ia = tl.Index(a);
    const Eigen::VectorXd primary_a = rel.primary[ia], secondary_a = rel.secondary[ia];
    Inertial inertial;
    if (o.nonlinear) inertial = MakeInertial(p, burns, impulses, primary_a, fine);
    r.nonlinear_checked = !inertial.primary.empty();
    r.nonlinear_note = inertial.note;
    GaussianSampler gauss(o.seed);
    const int n = p.model->num_states();
    Eigen::VectorXd z(n);
    double min_lin = std::numeric_limits<double>::infinity(), min_nl = min_lin;
    for (int s = 0; s < r.samples; ++s) {
      for (int q = 0; q < n; ++q) z[q] = gauss.Next();
      const Eigen::VectorXd delta = factor * z;  // relative state deviation at t0
      double d_plan = std::numeric_limits<double>::infinity(), d_free = d_plan;
      Eigen::Vector3d prev_plan, prev_free;
      for (int k = 0; k < nf; ++k) {
        const Eigen::Vector3d dev = g[k] * delta;
        const Eigen::Vector3d now_plan = mu_plan[k] + dev, now_free = mu_free[k] + dev;
        if (k > 0) {
          d_plan = std::min(d_plan, SegmentDistanceToOrigin(prev_plan, now_plan));
          d_free = std::min(d_free, SegmentDistanceToOrigin(prev_free, now_free));
        }
        prev_plan = now_plan;
        prev_free = now_free;
      }
      min_lin = std::min(min_lin, d_plan);
      if (d_plan < c.radius_m) ++r.collisions_linear;
      if (d_free < c.radius_m) ++r.collisions_unmanoeuvred_linear;
      if (!r.nonlinear_checked) continue;
      // The secondary sample: relative deviation delta moves the secondary by -delta.
      const Eigen::VectorXd x_s = secondary_a - rel.f.phi[ia] * delta;
      const dynamics::KeplerOrbit orbit(inertial.secondary_eci(x_s), a, inertial.mu);
      double d_nl = std::numeric_limits<double>::infinity();
      Eigen::Vector3d prev;
      for (int k = 0; k < nf; ++k) {
        const Eigen::Vector3d now = inertial.primary[k] - orbit.At(fine[k]).head<3>();
        if (k > 0) d_nl = std::min(d_nl, SegmentDistanceToOrigin(prev, now));
        prev = now;
      }
      min_nl = std::min(min_nl, d_nl);
      if (d_nl < c.radius_m) ++r.collisions_nonlinear;
    }
    r.min_distance_linear_m = min_lin;
    if (r.nonlinear_checked) r.min_distance_nonlinear_m = min_nl;
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return r;
}

}  // namespace thrustsched::transcription
