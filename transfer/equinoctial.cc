#include "transfer/equinoctial.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include "common/constants.h"
#include "common/format.h"

namespace thrustsched::transfer {
namespace {

void RequireFinite(double value, const char* name) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(std::string(name) + " must be finite, got " +
                                common::FormatG(value, 10));
  }
}

}  // namespace

Equinoctial EquinoctialFromKeplerian(const Keplerian& k) {
  RequireFinite(k.a_m, "a_m");
  RequireFinite(k.e, "e");
  RequireFinite(k.i_rad, "i_rad");
  RequireFinite(k.raan_rad, "raan_rad");
  RequireFinite(k.arg_perigee_rad, "arg_perigee_rad");
  RequireFinite(k.true_anomaly_rad, "true_anomaly_rad");
  if (!(k.a_m > 0))
    throw std::invalid_argument("a_m must be > 0, got " + common::FormatG(k.a_m, 10));
  if (!(k.e >= 0 && k.e < 1)) {
    throw std::invalid_argument("e must be in [0, 1), got " + common::FormatG(k.e, 10));
  }
  if (!(k.i_rad >= 0 && k.i_rad < common::kPi)) {
    throw std::invalid_argument("i_rad must be in [0, pi), got " + common::FormatG(k.i_rad, 10));
  }
  const double lop = k.raan_rad + k.arg_perigee_rad;  // longitude of the pericentre
  const double t = std::tan(k.i_rad / 2);
  Equinoctial q;
  q.p_m = k.a_m * (1 - k.e * k.e);
  q.ex = k.e * std::cos(lop);
  q.ey = k.e * std::sin(lop);
  q.hx = t * std::cos(k.raan_rad);
  q.hy = t * std::sin(k.raan_rad);
  q.l_rad = lop + k.true_anomaly_rad;
  return q;
}

double Eccentricity(const Equinoctial& q) { return std::hypot(q.ex, q.ey); }

double SemiMajorAxis(const Equinoctial& q) {
  const double e2 = q.ex * q.ex + q.ey * q.ey;
  if (!(e2 < 1)) {
    throw std::invalid_argument("not an ellipse: e = " + common::FormatG(std::sqrt(e2), 10));
  }
  return q.p_m / (1 - e2);
}

double Inclination(const Equinoctial& q) { return 2 * std::atan(std::hypot(q.hx, q.hy)); }

dynamics::Vector6d CartesianFromEquinoctial(const Equinoctial& q, double mu) {
  for (double v : {q.p_m, q.ex, q.ey, q.hx, q.hy, q.l_rad, mu}) RequireFinite(v, "element");
  if (!(q.p_m > 0)) throw std::invalid_argument("P must be > 0, got " + common::FormatG(q.p_m, 10));
  if (!(mu > 0)) throw std::invalid_argument("mu must be > 0, got " + common::FormatG(mu, 10));
  if (!(Eccentricity(q) < 1)) {
    throw std::invalid_argument("e must be < 1, got " + common::FormatG(Eccentricity(q), 10));
  }
  // Walker, Ireland & Owens 1985 (modified equinoctial elements).
  const double h = q.hx, k = q.hy, f = q.ex, g = q.ey;
  const double cl = std::cos(q.l_rad), sl = std::sin(q.l_rad);
  const double a2 = h * h - k * k, s2 = 1 + h * h + k * k;
  const double w = 1 + f * cl + g * sl;
  const double r = q.p_m / w;
  const double vs = std::sqrt(mu / q.p_m) / s2;
  dynamics::Vector6d rv;
  rv(0) = r / s2 * (cl + a2 * cl + 2 * h * k * sl);
  rv(1) = r / s2 * (sl - a2 * sl + 2 * h * k * cl);
  rv(2) = 2 * r / s2 * (h * sl - k * cl);
  rv(3) = -vs * (sl + a2 * sl - 2 * h * k * cl + g - 2 * f * h * k + a2 * g);
  rv(4) = -vs * (-cl + a2 * cl + 2 * h * k * sl - f + 2 * g * h * k + a2 * f);
  rv(5) = 2 * vs * (h * cl + k * sl + f * h + g * k);
  return rv;
}

Equinoctial EquinoctialFromCartesian(const dynamics::Vector6d& rv, double mu) {
  for (int i = 0; i < 6; ++i) RequireFinite(rv(i), "state");
  const Eigen::Vector3d r = rv.head<3>(), v = rv.tail<3>();
  const Eigen::Vector3d hv = r.cross(v);
  const double hn = hv.norm();
  if (!(hn > 0)) throw std::invalid_argument("r x v = 0: no orbit plane");
  const Eigen::Vector3d hu = hv / hn;
  if (!(1 + hu.z() > 1e-12)) throw std::invalid_argument("retrograde equatorial orbit");
  Equinoctial q;
  q.p_m = hn * hn / mu;
  q.hx = -hu.y() / (1 + hu.z());
  q.hy = hu.x() / (1 + hu.z());
  const double h = q.hx, k = q.hy, s2 = 1 + h * h + k * k;
  const Eigen::Vector3d fu = Eigen::Vector3d(1 - k * k + h * h, 2 * h * k, -2 * k) / s2;
  const Eigen::Vector3d gu = Eigen::Vector3d(2 * h * k, 1 + k * k - h * h, 2 * h) / s2;
  const Eigen::Vector3d ev = v.cross(hv) / mu - r.normalized();
  q.ex = ev.dot(fu);
  q.ey = ev.dot(gu);
  if (!(Eccentricity(q) < 1)) {
    throw std::invalid_argument("not an ellipse: e = " + common::FormatG(Eccentricity(q), 10));
  }
  q.l_rad = std::atan2(r.dot(gu), r.dot(fu));
  return q;
}

Eigen::Matrix3d QswBasis(const dynamics::Vector6d& rv) {
  const Eigen::Vector3d r = rv.head<3>(), v = rv.tail<3>();
  Eigen::Matrix3d b;
  b.col(0) = r.normalized();
  b.col(2) = r.cross(v).normalized();
  b.col(1) = b.col(2).cross(b.col(0));
  return b;
}

Vector6 ScaledUnits::ToScaled(const Equinoctial& q) const {
  Vector6 x;
  x << q.p_m / length_m, q.ex, q.ey, q.hx, q.hy, q.l_rad;
  return x;
}

Equinoctial ScaledUnits::FromScaled(const Vector6& x) const {
  return Equinoctial{x(0) * length_m, x(1), x(2), x(3), x(4), x(5)};
}

GaussTerms Gauss(const Vector6& x, double mu) {
  const double p = x(0), ex = x(1), ey = x(2), hx = x(3), hy = x(4);
  const double cl = std::cos(x(5)), sl = std::sin(x(5));
  const double s = std::sqrt(p / mu);
  const double w = 1 + ex * cl + ey * sl;
  const double z = hx * sl - hy * cl;
  const double c = (1 + hx * hx + hy * hy) / 2;
  GaussTerms t;
  t.f0.setZero();
  t.f0(5) = w * w / (p * s);
  t.F.setZero();
  t.F(1, 0) = s * sl;
  t.F(2, 0) = -s * cl;
  t.F(0, 1) = 2 * p * s / w;
  t.F(1, 1) = s * (cl + (ex + cl) / w);
  t.F(2, 1) = s * (sl + (ey + sl) / w);
  const double g = s / w;
  t.F(1, 2) = -g * z * ey;
  t.F(2, 2) = g * z * ex;
  t.F(3, 2) = g * c * cl;
  t.F(4, 2) = g * c * sl;
  t.F(5, 2) = g * z;
  return t;
}

GaussJacobians GaussDerivatives(const Vector6& x, double mu) {
  enum { kP = 0, kEx, kEy, kHx, kHy, kL };
  const double p = x(0), ex = x(1), ey = x(2), hx = x(3), hy = x(4);
  const double cl = std::cos(x(5)), sl = std::sin(x(5));
  const double s = std::sqrt(p / mu);
  const double w = 1 + ex * cl + ey * sl;
  const double wl = -ex * sl + ey * cl;  // dw/dL
  const double z = hx * sl - hy * cl;
  const double zl = hx * cl + hy * sl;  // dZ/dL
  const double c = (1 + hx * hx + hy * hy) / 2;
  const double w2 = w * w;
  GaussJacobians d;
  d.df0.setZero();
  const double f6 = w2 / (p * s);
  d.df0(5, kP) = -1.5 * f6 / p;
  d.df0(5, kEx) = 2 * w * cl / (p * s);
  d.df0(5, kEy) = 2 * w * sl / (p * s);
  d.df0(5, kL) = 2 * w * wl / (p * s);
  for (Matrix63& m : d.dF) m.setZero();
  // Every entry of F is s times a function of (ex, ey, hx, hy, L): d/dP = F / (2P).
  const GaussTerms t = Gauss(x, mu);
  d.dF[kP] = t.F / (2 * p);
  // Q column.
  d.dF[kL](1, 0) = s * cl;
  d.dF[kL](2, 0) = s * sl;
  // S column.
  d.dF[kP](0, 1) = 3 * s / w;  // 2 P s / w grows as P^(3/2)
  d.dF[kEx](0, 1) = -2 * p * s * cl / w2;
  d.dF[kEy](0, 1) = -2 * p * s * sl / w2;
  d.dF[kL](0, 1) = -2 * p * s * wl / w2;
  d.dF[kEx](1, 1) = s * (1 / w - (ex + cl) * cl / w2);
  d.dF[kEy](1, 1) = -s * (ex + cl) * sl / w2;
  d.dF[kL](1, 1) = s * (-sl - sl / w - (ex + cl) * wl / w2);
  d.dF[kEx](2, 1) = -s * (ey + sl) * cl / w2;
  d.dF[kEy](2, 1) = s * (1 / w - (ey + sl) * sl / w2);
  d.dF[kL](2, 1) = s * (cl + cl / w - (ey + sl) * wl / w2);
  // W column: g = s / w times functions of (ex, ey, hx, hy, L).
  const double g = s / w;
  const double g_ex = -s * cl / w2, g_ey = -s * sl / w2, g_l = -s * wl / w2;
  d.dF[kEx](1, 2) = -g_ex * z * ey;
  d.dF[kEy](1, 2) = -(g_ey * z * ey + g * z);
  d.dF[kHx](1, 2) = -g * sl * ey;
  d.dF[kHy](1, 2) = g * cl * ey;
  d.dF[kL](1, 2) = -(g_l * z + g * zl) * ey;
  d.dF[kEx](2, 2) = g_ex * z * ex + g * z;
  d.dF[kEy](2, 2) = g_ey * z * ex;
  d.dF[kHx](2, 2) = g * sl * ex;
  d.dF[kHy](2, 2) = -g * cl * ex;
  d.dF[kL](2, 2) = (g_l * z + g * zl) * ex;
  d.dF[kEx](3, 2) = g_ex * c * cl;
  d.dF[kEy](3, 2) = g_ey * c * cl;
  d.dF[kHx](3, 2) = g * hx * cl;
  d.dF[kHy](3, 2) = g * hy * cl;
  d.dF[kL](3, 2) = g_l * c * cl - g * c * sl;
  d.dF[kEx](4, 2) = g_ex * c * sl;
  d.dF[kEy](4, 2) = g_ey * c * sl;
  d.dF[kHx](4, 2) = g * hx * sl;
  d.dF[kHy](4, 2) = g * hy * sl;
  d.dF[kL](4, 2) = g_l * c * sl + g * c * cl;
  d.dF[kEx](5, 2) = g_ex * z;
  d.dF[kEy](5, 2) = g_ey * z;
  d.dF[kHx](5, 2) = g * sl;
  d.dF[kHy](5, 2) = -g * cl;
  d.dF[kL](5, 2) = g_l * z + g * zl;
  return d;
}

}  // namespace thrustsched::transfer
