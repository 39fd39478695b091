#include "transfer/force_model.h"

#include <cmath>
#include <stdexcept>

#include "common/constants.h"
#include "common/error.h"
#include "common/format.h"
#include "transfer/internal/elements_mass.h"
#include "transfer/internal/integrator.h"
#include "transfer/min_time_shooting.h"

namespace thrustsched::transfer {

std::string ToString(ForceModelKind k) {
  switch (k) {
    case ForceModelKind::kTwoBody:
      return "two_body";
    case ForceModelKind::kJ2:
      return "j2";
  }
  return "?";
}

bool ForceModel::IsValid(std::string* error) const {
  if (!(std::isfinite(j2) && j2 >= 0)) {
    return common::Fail(error, "j2 must be >= 0, got " + common::FormatG(j2, 10));
  }
  if (!(std::isfinite(radius_m) && radius_m > 0)) {
    return common::Fail(error, "radius_m must be > 0, got " + common::FormatG(radius_m, 10));
  }
  return true;
}

Eigen::Vector3d PerturbationQsw(const Vector6& x, const ForceModel& f, const ScaledUnits& u) {
  if (f.kind == ForceModelKind::kTwoBody) return Eigen::Vector3d::Zero();
  // Betts 2010 ch. 6, the low-thrust orbit transfer (Delta_r, Delta_theta, Delta_h).
  const double p = x(0), ex = x(1), ey = x(2), hx = x(3), hy = x(4);
  const double cl = std::cos(x(5)), sl = std::sin(x(5));
  const double r = p / (1 + ex * cl + ey * sl);
  const double radius = f.radius_m / u.length_m;
  const double k = u.mu() * f.j2 * radius * radius / (r * r * r * r);
  const double z = hx * sl - hy * cl, zl = hx * cl + hy * sl;
  const double s2 = 1 + hx * hx + hy * hy, s4 = s2 * s2;
  return Eigen::Vector3d(-1.5 * k * (1 - 12 * z * z / s4), -12 * k * z * zl / s4,
                         -6 * k * (1 - hx * hx - hy * hy) * z / s4);
}

Eigen::Matrix<double, 3, 6> PerturbationJacobianQsw(const Vector6& x, const ForceModel& f,
                                                    const ScaledUnits& u) {
  enum { kP = 0, kEx, kEy, kHx, kHy, kL };
  Eigen::Matrix<double, 3, 6> d = Eigen::Matrix<double, 3, 6>::Zero();
  if (f.kind == ForceModelKind::kTwoBody) return d;
  const Eigen::Vector3d g = PerturbationQsw(x, f, u);
  const double p = x(0), ex = x(1), ey = x(2), hx = x(3), hy = x(4);
  const double cl = std::cos(x(5)), sl = std::sin(x(5));
  const double w = 1 + ex * cl + ey * sl, wl = -ex * sl + ey * cl;  // wl = dw/dL
  const double r = p / w, radius = f.radius_m / u.length_m;
  const double k = u.mu() * f.j2 * radius * radius / (r * r * r * r);  // k = mu J2 R^2 w^4 / P^4
  const double z = hx * sl - hy * cl, zl = hx * cl + hy * sl;
  const double s2 = 1 + hx * hx + hy * hy, s4 = s2 * s2, s6 = s4 * s2;
  const double c1 = 1 - hx * hx - hy * hy;
  // k's factor: every component is k times a function of (hx, hy, L).
  d.col(kP) = -4 * g / p;
  d.col(kEx) = 4 * g * cl / w;
  d.col(kEy) = 4 * g * sl / w;
  d.col(kL) = 4 * g * wl / w;
  // The (hx, hy, L) factors: A = Z^2 / s2^2, B = Z Zl / s2^2, C = c1 Z / s2^2,
  // with dZ/dhx = sin L, dZ/dhy = -cos L, dZ/dL = Zl, dZl/dhx = cos L,
  // dZl/dhy = sin L, dZl/dL = -Z.
  auto add = [&](int j, double dz, double dzl, double ds2, double dc1) {
    const double da = 2 * z * dz / s4 - 2 * z * z * ds2 / s6;
    const double db = (dz * zl + z * dzl) / s4 - 2 * z * zl * ds2 / s6;
    const double dc = (dc1 * z + c1 * dz) / s4 - 2 * c1 * z * ds2 / s6;
    d(0, j) += 18 * k * da;  // gamma_Q = -3/2 k (1 - 12 A)
    d(1, j) += -12 * k * db;
    d(2, j) += -6 * k * dc;
  };
  add(kHx, sl, cl, 2 * hx, -2 * hx);
  add(kHy, -cl, sl, 2 * hy, -2 * hy);
  add(kL, zl, -z, 0, 0);
  return d;
}

Vector6 GaussRates(const Vector6& x, const Eigen::Vector3d& control_acceleration_qsw,
                   const ForceModel& f, const ScaledUnits& u) {
  const GaussTerms g = Gauss(x, u.mu());
  if (f.kind == ForceModelKind::kTwoBody) return g.f0 + g.F * control_acceleration_qsw;
  return g.f0 + g.F * (control_acceleration_qsw + PerturbationQsw(x, f, u));
}

std::vector<GaussSample> PropagateGauss(const MinTimeProblem& p, double duration_s,
                                        const ElementsCommand& command, double sample_step_s,
                                        double tolerance) {
  std::string error;
  if (!p.IsValid(&error)) throw std::invalid_argument("Gauss propagation: " + error);
  if (!(duration_s > 0) || !(sample_step_s > 0)) {
    throw std::invalid_argument("Gauss propagation: duration_s and sample_step_s must be > 0");
  }
  ScaledUnits u;
  u.mu_si = p.mu;
  const double thrust = u.Thrust(p.thrust_n);
  const double flow = thrust / u.Speed(common::kStandardGravity_m_s2 * p.isp_s);  // kg/h
  using internal::ElementsMassState;
  auto rhs = [&](const ElementsMassState& y, ElementsMassState& dy, double t) {
    const Eigen::Vector3d c = command(t * u.time_s, u.FromScaled(internal::ElementsOf(y)), y[6]);
    internal::ElementsMassRates(y, c, thrust, flow, p.force_model, u, dy);
  };
  ElementsMassState y = internal::ElementsMassStateOf(u.ToScaled(p.initial), p.mass_kg);
  std::vector<GaussSample> out;
  const double tf = duration_s / u.time_s, step = sample_step_s / u.time_s;
  const int n = static_cast<int>(std::ceil(tf / step - 1e-9));
  out.push_back({0.0, p.initial, p.mass_kg});
  for (int k = 1; k <= n; ++k) {
    const double t0 = (k - 1) * step, t1 = k == n ? tf : k * step;
    internal::Integrate(rhs, y, t0, t1, tolerance, 0.25,
                        [](double, const ElementsMassState&) { return true; });
    out.push_back({t1 * u.time_s, u.FromScaled(internal::ElementsOf(y)), y[6]});
  }
  return out;
}

}  // namespace thrustsched::transfer
