// Private helper (not installed): the GEO physics written once as templates on
// the scalar type, so that the same code gives values (double) and exact
// first derivatives (internal::Dual<N>). Public double wrappers live in
// dynamics/orbital_elements.h and dynamics/geo_forces.h; formulas and their
// provenance are documented there.
// SI units throughout (m, s, rad).
#ifndef THRUSTSCHED_DYNAMICS_INTERNAL_GEO_PHYSICS_H_
#define THRUSTSCHED_DYNAMICS_INTERNAL_GEO_PHYSICS_H_

#include <algorithm>
#include <array>
#include <cmath>

#include "dynamics/internal/geo_dual.h"

namespace thrustsched::dynamics::internal {

template <typename T>
using Vec3 = std::array<T, 3>;

template <typename T>
inline T Dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Geometry of an osculating orbit in equinoctial elements (Broucke & Cefola
/// 1972; basis [f g w] = R3(W) R1(i) R3(-W), corrected: Gazzino 2018 (A.11)
/// prints R3(-W) R1(i) R3(W)).
template <typename T>
struct OrbitGeometry {
  T a, ex, ey, ix, iy;
  T ecc_anomaly;     // E_Q
  T n;               // sqrt(mu / a^3)
  T b;               // a sqrt(1 - e^2)
  T r;               // |position|
  T cos_l, sin_l;    // true longitude nu_Q
  Vec3<T> f, g, w;   // equinoctial basis; w = orbit normal
  Vec3<T> pos, vel;  // ECI
  Vec3<T> u_r, u_t;  // RTN radial and along-track unit vectors (u_n = w)
};

/// Solves E + ey cos E - ex sin E = k by Newton from E = k; always at least
/// two iterations so that derivatives of dual numbers converge too.
template <typename T>
T SolveKepler(const T& k, const T& ex, const T& ey) {
  using std::cos;
  using std::sin;
  T e = k;
  for (int it = 0; it < 30; ++it) {
    const T ce = cos(e), se = sin(e);
    const T step = (e + ey * ce - ex * se - k) / (1.0 - ey * se - ex * ce);
    e -= step;
    if (it >= 1 && std::abs(Value(step)) < 1e-15) break;
  }
  return e;
}

/// Elements (a, ex, ey, ix, iy, mean longitude K = M_Q) -> orbit geometry.
template <typename T>
OrbitGeometry<T> Geometry(const T& a, const T& ex, const T& ey, const T& ix, const T& iy,
                          const T& k, double mu) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  OrbitGeometry<T> o;
  o.a = a;
  o.ex = ex;
  o.ey = ey;
  o.ix = ix;
  o.iy = iy;
  o.ecc_anomaly = SolveKepler(k, ex, ey);
  const T ce = cos(o.ecc_anomaly), se = sin(o.ecc_anomaly);
  const T root = sqrt(1.0 - ex * ex - ey * ey);
  const T beta = 1.0 / (1.0 + root);
  o.n = sqrt(mu / (a * a * a));
  o.b = a * root;
  o.r = a * (1.0 - ex * ce - ey * se);
  const T x1 = a * ((1.0 - ey * ey * beta) * ce + ex * ey * beta * se - ex);
  const T y1 = a * ((1.0 - ex * ex * beta) * se + ex * ey * beta * ce - ey);
  const T vfac = o.n * a * a / o.r;
  const T vx1 = vfac * (ex * ey * beta * ce - (1.0 - ey * ey * beta) * se);
  const T vy1 = vfac * ((1.0 - ex * ex * beta) * ce - ex * ey * beta * se);
  const T s = 1.0 + ix * ix + iy * iy;
  o.f = {(1.0 + ix * ix - iy * iy) / s, 2.0 * ix * iy / s, -2.0 * iy / s};
  o.g = {2.0 * ix * iy / s, (1.0 - ix * ix + iy * iy) / s, 2.0 * ix / s};
  o.w = {2.0 * iy / s, -2.0 * ix / s, (1.0 - ix * ix - iy * iy) / s};
  o.cos_l = x1 / o.r;
  o.sin_l = y1 / o.r;
  for (int i = 0; i < 3; ++i) {
    o.pos[i] = x1 * o.f[i] + y1 * o.g[i];
    o.vel[i] = vx1 * o.f[i] + vy1 * o.g[i];
    o.u_r[i] = o.cos_l * o.f[i] + o.sin_l * o.g[i];
    o.u_t[i] = o.cos_l * o.g[i] - o.sin_l * o.f[i];
  }
  return o;
}

/// Gauss matrix G_EOE (6 x 3, rows a, ex, ey, ix, iy, K; columns R, T, N) of
/// Gazzino 2018, eq. (B.51), with the (6,1) entry corrected (printed
/// dimensionally wrong).
template <typename T>
std::array<Vec3<T>, 6> GaussMatrix(const OrbitGeometry<T>& o) {
  const T& a = o.a;
  const T& b = o.b;
  const T& r = o.r;
  const T& n = o.n;
  const T p1 = o.ex * o.cos_l + o.ey * o.sin_l;
  const T p2 = o.ex * o.sin_l - o.ey * o.cos_l;
  const T p5 = 1.0 + o.ix * o.ix + o.iy * o.iy;
  const T p6 = o.ix * o.sin_l - o.iy * o.cos_l;
  const T nab = n * a * b;
  const T q = 1.0 + b * b / (a * r);
  const T zero(0.0);
  std::array<Vec3<T>, 6> g;
  g[0] = {2.0 * a * p2 / (n * b), 2.0 * b / (n * r), zero};
  g[1] = {b * o.sin_l / (n * a * a), r / nab * (o.ex + q * o.cos_l), -o.ey * r * p6 / nab};
  g[2] = {-b * o.cos_l / (n * a * a), r / nab * (o.ey + q * o.sin_l), o.ex * r * p6 / nab};
  g[3] = {zero, zero, r * p5 * o.cos_l / (2.0 * nab)};
  g[4] = {zero, zero, r * p5 * o.sin_l / (2.0 * nab)};
  g[5] = {-(2.0 * r + a * b / (a + b) * p1) / (n * a * a), r * p2 * q / (n * b * (a + b)),
          r * p6 / nab};
  return g;
}

/// Unnormalised geopotential coefficients up to degree/order 4, with the
/// zonal (m = 0) and tesseral/sectorial (m >= 1) parts switchable.
struct GeopotentialCoefficients {
  static constexpr int kMaxDegree = 4;
  int degree = 0;  // 0: no geopotential beyond the central term
  double c[kMaxDegree + 1][kMaxDegree + 1] = {};
  double s[kMaxDegree + 1][kMaxDegree + 1] = {};
};

/// Non-central geopotential acceleration in the Earth-fixed frame
/// (Cunningham recursion, Montenbruck & Gill §3.2.4). r in m.
template <typename T>
Vec3<T> GeopotentialAccelerationEcef(const Vec3<T>& r, const GeopotentialCoefficients& cs,
                                     double mu, double radius) {
  constexpr int kN = GeopotentialCoefficients::kMaxDegree + 2;  // V, W up to degree + 1
  const int nmax = cs.degree;
  Vec3<T> acc = {T(0.0), T(0.0), T(0.0)};
  if (nmax < 2) return acc;
  const T r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  const T rho = radius * radius / r2;
  const T x0 = radius * r[0] / r2, y0 = radius * r[1] / r2, z0 = radius * r[2] / r2;
  T v[kN][kN], w[kN][kN];
  using std::sqrt;
  v[0][0] = radius / sqrt(r2);
  w[0][0] = T(0.0);
  const int top = nmax + 1;
  for (int m = 0; m <= top; ++m) {
    if (m > 0) {
      v[m][m] = (2.0 * m - 1.0) * (x0 * v[m - 1][m - 1] - y0 * w[m - 1][m - 1]);
      w[m][m] = (2.0 * m - 1.0) * (x0 * w[m - 1][m - 1] + y0 * v[m - 1][m - 1]);
    }
    if (m + 1 <= top) {
      v[m + 1][m] = (2.0 * m + 1.0) * z0 * v[m][m];
      w[m + 1][m] = (2.0 * m + 1.0) * z0 * w[m][m];
    }
    for (int n = m + 2; n <= top; ++n) {
      v[n][m] =
          ((2.0 * n - 1.0) * z0 * v[n - 1][m] - (n + m - 1.0) * rho * v[n - 2][m]) / double(n - m);
      w[n][m] =
          ((2.0 * n - 1.0) * z0 * w[n - 1][m] - (n + m - 1.0) * rho * w[n - 2][m]) / double(n - m);
    }
  }
  for (int n = 2; n <= nmax; ++n) {
    for (int m = 0; m <= n; ++m) {
      const double c = cs.c[n][m], s = cs.s[n][m];
      if (c == 0.0 && s == 0.0) continue;
      if (m == 0) {
        acc[0] -= c * v[n + 1][1];
        acc[1] -= c * w[n + 1][1];
        acc[2] -= (n + 1.0) * c * v[n + 1][0];
      } else {
        const double fac = 0.5 * (n - m + 1.0) * (n - m + 2.0);
        acc[0] += 0.5 * (-c * v[n + 1][m + 1] - s * w[n + 1][m + 1]) +
                  fac * (c * v[n + 1][m - 1] + s * w[n + 1][m - 1]);
        acc[1] += 0.5 * (-c * w[n + 1][m + 1] + s * v[n + 1][m + 1]) +
                  fac * (-c * w[n + 1][m - 1] + s * v[n + 1][m - 1]);
        acc[2] += (n - m + 1.0) * (-c * v[n + 1][m] - s * w[n + 1][m]);
      }
    }
  }
  const double k = mu / (radius * radius);
  for (T& x : acc) x *= k;
  return acc;
}

/// Third-body acceleration with the indirect term (Montenbruck & Gill 2000, sec. 3.3.1).
template <typename T>
Vec3<T> ThirdBodyAcceleration(const Vec3<T>& r, const Vec3<double>& body, double mu_body) {
  using std::sqrt;
  const Vec3<T> d = {body[0] - r[0], body[1] - r[1], body[2] - r[2]};
  const T d2 = Dot(d, d);
  const T inv_d3 = 1.0 / (d2 * sqrt(d2));
  const double b2 = body[0] * body[0] + body[1] * body[1] + body[2] * body[2];
  const double inv_b3 = 1.0 / (b2 * std::sqrt(b2));
  Vec3<T> acc;
  for (int i = 0; i < 3; ++i) acc[i] = mu_body * (d[i] * inv_d3 - body[i] * inv_b3);
  return acc;
}

/// Continuous cylindrical-shadow indicator (m): negative exactly when the
/// satellite at r is in the shadow (r.s < 0 and |r - (r.s) s| < R_E, s the
/// Sun direction). Equal to |r_perp| - R_E behind the Earth and |r| - R_E on
/// the day side (continuous across the terminator plane, where both are equal).
inline double ShadowFunction(const Vec3<double>& r, const Vec3<double>& sun, double earth_radius) {
  const double sn = std::sqrt(sun[0] * sun[0] + sun[1] * sun[1] + sun[2] * sun[2]);
  const double proj = (r[0] * sun[0] + r[1] * sun[1] + r[2] * sun[2]) / sn;
  const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  if (proj >= 0.0) return std::sqrt(r2) - earth_radius;
  return std::sqrt(std::max(r2 - proj * proj, 0.0)) - earth_radius;
}

/// Cannonball solar-radiation-pressure acceleration in sunlight (Montenbruck &
/// Gill 2000, sec. 3.4); coefficient = P_sun * C_r * A/m (m/s^2 at 1 AU). The
/// caller applies the shadow (ShadowFunction).
template <typename T>
Vec3<T> SrpAcceleration(const Vec3<T>& r, const Vec3<double>& sun, double coefficient, double au) {
  using std::sqrt;
  const Vec3<T> d = {sun[0] - r[0], sun[1] - r[1], sun[2] - r[2]};
  const T d2 = Dot(d, d);
  const T dn = sqrt(d2);
  const T k = -coefficient * au * au / (d2 * dn);
  Vec3<T> acc;
  for (int i = 0; i < 3; ++i) acc[i] = k * d[i];
  return acc;
}

}  // namespace thrustsched::dynamics::internal

#endif  // THRUSTSCHED_DYNAMICS_INTERNAL_GEO_PHYSICS_H_
