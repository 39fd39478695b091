#include "transfer/two_impulse.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "common/constants.h"
#include "common/error.h"
#include "common/format.h"

namespace thrustsched::transfer {
namespace {

// Golden-section search for the minimum of f on [lo, hi] (assumed unimodal).
double GoldenSection(const std::function<double(double)>& f, double lo, double hi,
                     double tolerance) {
  const double r = (std::sqrt(5.0) - 1) / 2;
  double a = lo, b = hi;
  double x1 = b - r * (b - a), x2 = a + r * (b - a);
  double f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < 400 && b - a > tolerance; ++it) {
    if (f1 <= f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - r * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + r * (b - a), f2 = f(x2);
    }
  }
  return f1 <= f2 ? x1 : x2;
}

// Eccentric anomaly of true anomaly nu, in (-pi, pi].
double EccentricAnomaly(double nu, double e) {
  return std::atan2(std::sqrt(1 - e * e) * std::sin(nu), e + std::cos(nu));
}

}  // namespace

HohmannTransfer Hohmann(double r1_m, double r2_m, double mu) {
  for (double v : {r1_m, r2_m, mu}) {
    if (!(std::isfinite(v) && v > 0)) {
      throw std::invalid_argument("Hohmann: radii and mu must be finite and > 0, got " +
                                  common::FormatG(v, 10));
    }
  }
  const double a = (r1_m + r2_m) / 2;
  HohmannTransfer h;
  h.dv1_m_s = std::abs(std::sqrt(mu * (2 / r1_m - 1 / a)) - std::sqrt(mu / r1_m));
  h.dv2_m_s = std::abs(std::sqrt(mu / r2_m) - std::sqrt(mu * (2 / r2_m - 1 / a)));
  h.total_m_s = h.dv1_m_s + h.dv2_m_s;
  h.time_of_flight_s = common::kPi * std::sqrt(a * a * a / mu);
  return h;
}

bool TwoImpulseProblem::IsValid(std::string* error) const {
  if (!(std::isfinite(mu) && mu > 0)) {
    return common::Fail(error, "mu must be > 0, got " + common::FormatG(mu, 10));
  }
  if (!(std::isfinite(r0_m) && r0_m > 0)) {
    return common::Fail(error, "r0_m must be > 0, got " + common::FormatG(r0_m, 10));
  }
  if (!(std::isfinite(target_m) && target_m > r0_m)) {
    return common::Fail(error, "target_m must be > r0_m = " + common::FormatG(r0_m, 10) + ", got " +
                                   common::FormatG(target_m, 10));
  }
  return true;
}

bool EvaluateTwoImpulse(const TwoImpulseProblem& p, double vr, double vt, TwoImpulseResult* out) {
  if (!(vt > 0)) return false;
  const double h = p.r0_m * vt;
  const double sl = h * h / p.mu;                         // semi-latus rectum
  const double ec = sl / p.r0_m - 1, es = vr * h / p.mu;  // e cos(nu0), e sin(nu0)
  const double e = std::hypot(ec, es);
  if (!(e < 1) || !(e > 0)) return false;
  const double cf = (sl / p.target_m - 1) / e;  // cos(nu_f)
  if (cf < -1 || cf > 1) return false;          // apogee below the target
  // First crossing of the target radius: nu_f in [0, pi], where r grows.
  const double nu0 = std::atan2(es, ec), nuf = std::acos(cf);
  const double a = sl / (1 - e * e);
  const double n = std::sqrt(p.mu / (a * a * a));
  const double e0 = EccentricAnomaly(nu0, e), ef = EccentricAnomaly(nuf, e);
  TwoImpulseResult r;
  r.dv0_radial_m_s = vr;
  r.dv0_tangential_m_s = vt - std::sqrt(p.mu / p.r0_m);
  r.dvf_radial_m_s = -p.mu / h * e * std::sin(nuf);  // cancels the arrival radial velocity
  r.dvf_tangential_m_s = std::sqrt(p.mu / p.target_m) - h / p.target_m;
  r.dv0_m_s = std::hypot(r.dv0_radial_m_s, r.dv0_tangential_m_s);
  r.dvf_m_s = std::hypot(r.dvf_radial_m_s, r.dvf_tangential_m_s);
  r.cost_m2_s2 = (r.dv0_m_s * r.dv0_m_s + r.dvf_m_s * r.dvf_m_s) / 2;
  r.time_of_flight_s = ((ef - e * std::sin(ef)) - (e0 - e * std::sin(e0))) / n;
  r.transfer_a_m = a;
  r.transfer_e = e;
  *out = r;
  return true;
}

TwoImpulseResult MinimiseTwoImpulse(const TwoImpulseProblem& p) {
  std::string error;
  if (!p.IsValid(&error)) throw std::invalid_argument("two-impulse problem: " + error);
  const double v_escape = std::sqrt(2 * p.mu / p.r0_m);
  const double tol = 1e-15 * v_escape;
  TwoImpulseResult scratch;
  auto reaches = [&](double vr, double vt) { return EvaluateTwoImpulse(p, vr, vt, &scratch); };
  auto top = [&](double vr) {  // largest tangential speed of an ellipse
    return std::sqrt(std::max(0.0, v_escape * v_escape - vr * vr)) * (1 - 1e-12);
  };
  // Smallest tangential speed whose ellipse reaches the target (the apogee
  // grows with it), by bisection; NaN if none below the escape speed does.
  auto min_tangential = [&](double vr) {
    double lo = 0, hi = top(vr);
    if (!reaches(vr, hi)) return std::nan("");
    // To the last bit: J's slope is infinite at the boundary (the arrival's
    // radial speed grows as the square root of the apogee's excess), so is
    // the time of flight's.
    for (double mid = (lo + hi) / 2; mid > lo && mid < hi; mid = (lo + hi) / 2) {
      (reaches(vr, mid) ? hi : lo) = mid;
    }
    return hi;
  };
  auto cost = [&](double vr, double vt) {
    return EvaluateTwoImpulse(p, vr, vt, &scratch) ? scratch.cost_m2_s2 : HUGE_VAL;
  };
  auto best_tangential = [&](double vr) {
    const double lo = min_tangential(vr);
    if (std::isnan(lo)) return lo;
    return GoldenSection([&](double vt) { return cost(vr, vt); }, lo, top(vr), tol);
  };
  auto profile = [&](double vr) {
    const double vt = best_tangential(vr);
    return std::isnan(vt) ? HUGE_VAL : cost(vr, vt);
  };
  const double vr = GoldenSection(profile, -v_escape / 2, v_escape / 2, tol);
  TwoImpulseResult best;
  const double vt = best_tangential(vr);
  if (std::isnan(vt) || !EvaluateTwoImpulse(p, vr, vt, &best)) {
    throw std::runtime_error("two-impulse minimisation found no transfer");
  }
  return best;
}

}  // namespace thrustsched::transfer
