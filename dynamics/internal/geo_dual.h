// Private helper (not installed): forward-mode dual numbers with N derivative
// directions, used to get the exact Jacobian A(t) = df_L/dx of the GEO
// equinoctial dynamics in one pass (Gazzino 2018 defines it, eq. (B.36), but
// never prints it). Only the operations the GEO physics templates use are
// provided; comparisons look at the value only (the code must not branch on
// derivatives).
//
//   using D = internal::Dual<6>;
//   D x = D::Variable(0.3, 0);            // value 0.3, dx/dx_0 = 1
//   D y = sin(x) * x;                     // y.v, y.d[0] = cos(0.3) 0.3 + sin(0.3)
#ifndef THRUSTSCHED_DYNAMICS_INTERNAL_GEO_DUAL_H_
#define THRUSTSCHED_DYNAMICS_INTERNAL_GEO_DUAL_H_

#include <array>
#include <cmath>

namespace thrustsched::dynamics::internal {

template <int N>
struct Dual {
  double v = 0.0;
  std::array<double, N> d{};

  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT: implicit from constants, like a double
  static Dual Variable(double value, int index) {
    Dual x(value);
    x.d[index] = 1.0;
    return x;
  }

  Dual& operator+=(const Dual& o) {
    v += o.v;
    for (int k = 0; k < N; ++k) d[k] += o.d[k];
    return *this;
  }
  Dual& operator-=(const Dual& o) {
    v -= o.v;
    for (int k = 0; k < N; ++k) d[k] -= o.d[k];
    return *this;
  }
  Dual& operator*=(const Dual& o) {
    for (int k = 0; k < N; ++k) d[k] = d[k] * o.v + v * o.d[k];
    v *= o.v;
    return *this;
  }
  Dual& operator*=(double s) {
    v *= s;
    for (int k = 0; k < N; ++k) d[k] *= s;
    return *this;
  }
  Dual& operator/=(const Dual& o) {
    const double inv = 1.0 / o.v;
    v *= inv;
    for (int k = 0; k < N; ++k) d[k] = (d[k] - v * o.d[k]) * inv;
    return *this;
  }
};

// Chain rule helper: value f, derivative factor df.
template <int N>
inline Dual<N> Apply(const Dual<N>& x, double f, double df) {
  Dual<N> r(f);
  for (int k = 0; k < N; ++k) r.d[k] = df * x.d[k];
  return r;
}

template <int N>
inline Dual<N> operator-(const Dual<N>& a) {
  return Apply(a, -a.v, -1.0);
}
template <int N>
inline Dual<N> operator+(Dual<N> a, const Dual<N>& b) {
  return a += b;
}
template <int N>
inline Dual<N> operator-(Dual<N> a, const Dual<N>& b) {
  return a -= b;
}
template <int N>
inline Dual<N> operator*(Dual<N> a, const Dual<N>& b) {
  return a *= b;
}
template <int N>
inline Dual<N> operator/(Dual<N> a, const Dual<N>& b) {
  return a /= b;
}
template <int N>
inline Dual<N> operator+(Dual<N> a, double b) {
  a.v += b;
  return a;
}
template <int N>
inline Dual<N> operator+(double b, Dual<N> a) {
  a.v += b;
  return a;
}
template <int N>
inline Dual<N> operator-(Dual<N> a, double b) {
  a.v -= b;
  return a;
}
template <int N>
inline Dual<N> operator-(double b, const Dual<N>& a) {
  return Apply(a, b - a.v, -1.0);
}
template <int N>
inline Dual<N> operator*(Dual<N> a, double b) {
  return a *= b;
}
template <int N>
inline Dual<N> operator*(double b, Dual<N> a) {
  return a *= b;
}
template <int N>
inline Dual<N> operator/(Dual<N> a, double b) {
  return a *= (1.0 / b);
}
template <int N>
inline Dual<N> operator/(double b, const Dual<N>& a) {
  const double f = b / a.v;
  return Apply(a, f, -f / a.v);
}

template <int N>
inline bool operator<(const Dual<N>& a, const Dual<N>& b) {
  return a.v < b.v;
}
template <int N>
inline bool operator<(const Dual<N>& a, double b) {
  return a.v < b;
}
template <int N>
inline bool operator>(const Dual<N>& a, double b) {
  return a.v > b;
}

template <int N>
inline Dual<N> sin(const Dual<N>& x) {
  return Apply(x, std::sin(x.v), std::cos(x.v));
}
template <int N>
inline Dual<N> cos(const Dual<N>& x) {
  return Apply(x, std::cos(x.v), -std::sin(x.v));
}
template <int N>
inline Dual<N> sqrt(const Dual<N>& x) {
  const double s = std::sqrt(x.v);
  return Apply(x, s, 0.5 / s);
}
template <int N>
inline Dual<N> atan2(const Dual<N>& y, const Dual<N>& x) {
  const double r2 = x.v * x.v + y.v * y.v;
  Dual<N> r(std::atan2(y.v, x.v));
  for (int k = 0; k < N; ++k) r.d[k] = (x.v * y.d[k] - y.v * x.d[k]) / r2;
  return r;
}

/// Value part of a double or a dual number.
inline double Value(double x) { return x; }
template <int N>
inline double Value(const Dual<N>& x) {
  return x.v;
}

}  // namespace thrustsched::dynamics::internal

#endif  // THRUSTSCHED_DYNAMICS_INTERNAL_GEO_DUAL_H_
