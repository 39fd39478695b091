#include "transfer/lyapunov_feedback.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/constants.h"
#include "common/error.h"
#include "common/format.h"
#include "transfer/force_model.h"
#include "transfer/internal/elements_mass.h"
#include "transfer/internal/integrator.h"

namespace thrustsched::transfer {
namespace {

using common::FormatG;

// The inclination vector is kappa(|h|) h with kappa(r) = 2 atan(r) / r;
// kappa and kappa'(r) / r (both regular at r = 0).
void Kappa(double r, double* kappa, double* dkappa_over_r) {
  if (r < 1e-4) {
    *kappa = 2 * (1 - r * r / 3);
    *dkappa_over_r = 2 * (-2.0 / 3 + 4 * r * r / 5);
  } else {
    *kappa = 2 * std::atan(r) / r;
    *dkappa_over_r = (2 * r / (1 + r * r) - 2 * std::atan(r)) / (r * r * r);
  }
}

struct Deviations {
  double a_ratio = 0;  // a / a_t - 1
  double ex = 0, ey = 0, ix = 0, iy = 0;
  double a = 0, a_t = 0, one_minus_e2 = 0;
  double kappa = 0, dkappa_over_r = 0;
};

Deviations DeviationsOf(const Vector6& x, const TargetElements& t, const ScaledUnits& u) {
  Deviations d;
  const double e2 = x(1) * x(1) + x(2) * x(2);
  d.one_minus_e2 = 1 - e2;
  d.a = x(0) / d.one_minus_e2;
  const double et2 = t.value[1] * t.value[1] + t.value[2] * t.value[2];
  d.a_t = t.value[0] / u.length_m / (1 - et2);
  d.a_ratio = d.a / d.a_t - 1;
  d.ex = x(1) - t.value[1];
  d.ey = x(2) - t.value[2];
  Kappa(std::hypot(x(3), x(4)), &d.kappa, &d.dkappa_over_r);
  double kt = 0, unused = 0;
  Kappa(std::hypot(t.value[3], t.value[4]), &kt, &unused);
  d.ix = d.kappa * x(3) - kt * t.value[3];
  d.iy = d.kappa * x(4) - kt * t.value[4];
  return d;
}

}  // namespace

double LyapunovValue(const Vector6& x, const TargetElements& t, const LyapunovWeights& w,
                     const ScaledUnits& u) {
  const Deviations d = DeviationsOf(x, t, u);
  double v = 0;
  if (!t.free[0]) v += w.a * d.a_ratio * d.a_ratio;
  if (!t.free[1]) v += w.e * d.ex * d.ex;
  if (!t.free[2]) v += w.e * d.ey * d.ey;
  if (!t.free[3]) v += w.i * d.ix * d.ix;
  if (!t.free[4]) v += w.i * d.iy * d.iy;
  return v;
}

Vector6 LyapunovGradient(const Vector6& x, const TargetElements& t, const LyapunovWeights& w,
                         const ScaledUnits& u) {
  const Deviations d = DeviationsOf(x, t, u);
  Vector6 g = Vector6::Zero();
  if (!t.free[0]) {
    const double k = 2 * w.a * d.a_ratio / d.a_t;  // dV/da
    g(0) += k / d.one_minus_e2;
    g(1) += k * 2 * x(0) * x(1) / (d.one_minus_e2 * d.one_minus_e2);
    g(2) += k * 2 * x(0) * x(2) / (d.one_minus_e2 * d.one_minus_e2);
  }
  if (!t.free[1]) g(1) += 2 * w.e * d.ex;
  if (!t.free[2]) g(2) += 2 * w.e * d.ey;
  const double cx = t.free[3] ? 0 : 2 * w.i * d.ix, cy = t.free[4] ? 0 : 2 * w.i * d.iy;
  const double hx = x(3), hy = x(4), k = d.kappa, q = d.dkappa_over_r;
  g(3) += cx * (k + q * hx * hx) + cy * q * hx * hy;
  g(4) += cx * q * hx * hy + cy * (k + q * hy * hy);
  return g;
}

bool FeedbackOptions::IsValid(std::string* error) const {
  if (!(weights.a >= 0 && weights.e >= 0 && weights.i >= 0)) {
    return common::Fail(error, "weights must be >= 0");
  }
  if (!(delta > 0)) return common::Fail(error, "delta must be > 0, got " + FormatG(delta, 10));
  if (!(v_stop > 0)) return common::Fail(error, "v_stop must be > 0, got " + FormatG(v_stop, 10));
  if (!(max_duration_s > 0)) {
    return common::Fail(error, "max_duration_s must be > 0, got " + FormatG(max_duration_s, 10));
  }
  if (!(on_off_p >= 0 && on_off_p <= 1)) {
    return common::Fail(error, "on_off_p must be in [0, 1], got " + FormatG(on_off_p, 10));
  }
  if (!(integration_tolerance > 0 && integration_tolerance <= 1e-6)) {
    return common::Fail(error, "integration_tolerance must be in (0, 1e-6]");
  }
  if (!(sample_step_s > 0)) return common::Fail(error, "sample_step_s must be > 0");
  return true;
}

Eigen::Vector3d FeedbackControl(const Vector6& x, const TargetElements& target,
                                const FeedbackOptions& o, const ScaledUnits& units,
                                double* efficiency) {
  const Eigen::Vector3d g =
      Gauss(x, units.mu()).F.transpose() * LyapunovGradient(x, target, o.weights, units);
  const double n = g.norm();
  if (efficiency != nullptr) *efficiency = n;
  return n > o.delta ? Eigen::Vector3d(-g / n) : Eigen::Vector3d(-g / o.delta);
}

namespace {

using FeedbackState = internal::ElementsMassState;

// The on-off rule's state: the current revolution's threshold and the
// extremes of the efficiency over the revolutions before.
struct OnOffWindows {
  double p = 0.5;
  long window = 0;  // floor((L - L0) / 2 pi)
  double threshold = 0;
  double max_now = 0, min_now = HUGE_VAL;
  double max_prev[2] = {0, 0}, min_prev[2] = {0, 0};  // [i-1], [i-2]
  int completed = 0;

  void Observe(double efficiency, long current_window) {
    if (current_window != window) {
      max_prev[1] = max_prev[0], min_prev[1] = min_prev[0];
      max_prev[0] = max_now, min_prev[0] = min_now;
      max_now = 0, min_now = HUGE_VAL;
      window = current_window;
      ++completed;
      if (completed >= 2) {
        const double hi = 2 * max_prev[0] - max_prev[1], lo = 2 * min_prev[0] - min_prev[1];
        threshold = lo + p * (hi - lo);  // Bombrun (4.70)-(4.71)
      }
    }
    max_now = std::max(max_now, efficiency);
    min_now = std::min(min_now, efficiency);
  }
};

// Watches the feedback's integration step by step: the Lyapunov function's
// largest increase, the on-off windows, the stop rules (target, saturation,
// interrupt, propellant) and the trajectory samples. operator() returns
// false to stop.
class FeedbackObserver {
 public:
  FeedbackObserver(const MinTimeProblem& p, const FeedbackOptions& o, const ScaledUnits& u,
                   OnOffWindows* windows, FeedbackResult* r)
      : p_(p), o_(o), u_(u), windows_(windows), r_(r) {}

  bool operator()(double t, const FeedbackState& s) {
    const Vector6 x = internal::ElementsOf(s);
    const double v = LyapunovValue(x, p_.target, o_.weights, u_);
    if (std::isfinite(last_v_)) {
      r_->max_lyapunov_increase = std::max(r_->max_lyapunov_increase, v - last_v_);
    }
    last_v_ = v;
    double eff = 0;
    const Eigen::Vector3d c = FeedbackControl(x, p_.target, o_, u_, &eff);
    windows_->Observe(eff,
                      static_cast<long>(std::floor((x(5) - p_.initial.l_rad) / (2 * common::kPi))));
    const bool at_target = v <= o_.v_stop;
    const bool done = at_target || (o_.stop_at_saturation && eff <= o_.delta);
    if (done) r_->stop_reason = at_target ? "target" : "saturation";
    if (o_.interrupt != nullptr && o_.interrupt->load()) {
      r_->reached = false;
      r_->stop_reason = "interrupted";
      return false;
    }
    if (s[6] <= 1e-3 * p_.mass_kg) {  // out of propellant: stop, not reached
      r_->reached = false;
      r_->stop_reason = "propellant";
      return false;
    }
    if (t >= next_sample_h_ || done) {
      const bool off = o_.on_off && eff < windows_->threshold;
      r_->trajectory.push_back({t * u_.time_s, u_.FromScaled(x), s[6], v, off ? 0.0 : c.norm(), eff,
                                off ? Eigen::Vector3d::Zero() : c});
      next_sample_h_ = t + o_.sample_step_s / u_.time_s;
    }
    r_->reached = at_target;
    return !done;
  }

 private:
  const MinTimeProblem& p_;
  const FeedbackOptions& o_;
  const ScaledUnits& u_;
  OnOffWindows* windows_;
  FeedbackResult* r_;
  double last_v_ = HUGE_VAL;
  double next_sample_h_ = 0;
};

// The result's final figures from the state y at scaled time t_end, and the
// trajectory's last sample there.
void FinishFeedbackResult(const MinTimeProblem& p, const FeedbackOptions& o, const ScaledUnits& u,
                          const FeedbackState& y, double t_end, FeedbackResult* r) {
  const Vector6 xf = internal::ElementsOf(y);
  r->duration_s = t_end * u.time_s;
  r->final_elements = u.FromScaled(xf);
  r->final_mass_kg = y[6];
  r->propellant_kg = p.mass_kg - y[6];
  r->final_lyapunov = LyapunovValue(xf, p.target, o.weights, u);
  r->revolutions = (xf(5) - p.initial.l_rad) / (2 * common::kPi);
  if (r->trajectory.empty() || r->trajectory.back().t_s != r->duration_s) {
    r->trajectory.push_back({r->duration_s, r->final_elements, y[6], r->final_lyapunov, 0.0, 0.0,
                             Eigen::Vector3d::Zero()});
  }
}

}  // namespace

FeedbackResult RunFeedback(const MinTimeProblem& p, const FeedbackOptions& o) {
  std::string error;
  if (!p.IsValid(&error)) throw std::invalid_argument("feedback problem: " + error);
  if (!o.IsValid(&error)) throw std::invalid_argument("feedback options: " + error);
  ScaledUnits u;
  u.mu_si = p.mu;
  const double thrust = u.Thrust(p.thrust_n);
  const double flow =
      thrust / u.Speed(common::kStandardGravity_m_s2 * p.isp_s);  // kg/h at full thrust
  OnOffWindows windows;
  windows.p = o.on_off_p;
  auto control = [&](const Vector6& x, double* eff) {
    Eigen::Vector3d c = FeedbackControl(x, p.target, o, u, eff);
    if (o.on_off && *eff < windows.threshold) c.setZero();
    return c;
  };
  auto rhs = [&](const FeedbackState& y, FeedbackState& dy, double) {
    const Vector6 x = internal::ElementsOf(y);
    if (!(x(0) > 0) || !(x(1) * x(1) + x(2) * x(2) < 1)) {
      throw std::runtime_error("feedback left the ellipses (P <= 0 or e >= 1)");
    }
    double eff = 0;
    internal::ElementsMassRates(y, control(x, &eff), thrust, flow, p.force_model, u, dy);
  };
  FeedbackState y = internal::ElementsMassStateOf(u.ToScaled(p.initial), p.mass_kg);
  FeedbackResult r;
  FeedbackObserver observe(p, o, u, &windows, &r);
  double t_end = 0;
  FeedbackState last = y;
  double last_t = 0;
  try {
    t_end = internal::Integrate(rhs, y, 0.0, o.max_duration_s / u.time_s, o.integration_tolerance,
                                0.25, [&](double t, const FeedbackState& s) {
                                  last = s, last_t = t;
                                  return observe(t, s);
                                });
    if (r.stop_reason.empty()) r.stop_reason = "max_duration";
  } catch (const std::runtime_error& e) {
    y = last, t_end = last_t;  // the last accepted step
    r.reached = false;
    r.stop_reason = e.what();
  }
  FinishFeedbackResult(p, o, u, y, t_end, &r);
  return r;
}

FeedbackWithEnd FinishWithMinimumTime(const MinTimeProblem& p, const FeedbackResult& feedback,
                                      const ShootingOptions& options) {
  MinTimeProblem end = p;
  end.initial = feedback.final_elements;
  end.mass_kg = feedback.final_mass_kg;
  FeedbackWithEnd r;
  r.feedback = feedback;
  const ShootingGuess guess = InitialGuess(end);
  for (double factor : {1.0, 1.5, 2.0, 3.0, 0.7}) {
    ShootingGuess g = guess;
    g.duration_s *= factor;
    r.end = SolveMinTime(end, g, options);
    if (r.end.converged || r.end.interrupted) break;
  }
  r.total_duration_s = feedback.duration_s + r.end.duration_s;
  r.total_propellant_kg = feedback.propellant_kg + r.end.propellant_kg;
  return r;
}

}  // namespace thrustsched::transfer
