#include "dynamics/orbital_elements.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include "common/constants.h"
#include "common/format.h"
#include "dynamics/internal/geo_physics.h"

namespace thrustsched::dynamics {

using common::FormatG;

namespace {

using common::kPi;

void CheckElements(const EquinoctialElements& el, double mu, const char* where) {
  const double vals[6] = {el.a_m, el.ex, el.ey, el.ix, el.iy, el.mean_longitude_rad};
  const char* names[6] = {"a_m", "ex", "ey", "ix", "iy", "mean_longitude_rad"};
  for (int i = 0; i < 6; ++i) {
    if (!std::isfinite(vals[i])) {
      throw std::invalid_argument(std::string(where) + ": " + names[i] + " must be finite, got " +
                                  FormatG(vals[i], 17));
    }
  }
  if (!(el.a_m > 0.0)) {
    throw std::invalid_argument(std::string(where) + ": a_m must be > 0, got " +
                                FormatG(el.a_m, 17));
  }
  const double e = std::hypot(el.ex, el.ey);
  if (!(e < 1.0)) {
    throw std::invalid_argument(std::string(where) + ": eccentricity |(ex, ey)| must be < 1, got " +
                                FormatG(e, 17));
  }
  if (!(mu > 0.0) || !std::isfinite(mu)) {
    throw std::invalid_argument(std::string(where) + ": mu must be finite and > 0, got " +
                                FormatG(mu, 17));
  }
}

internal::OrbitGeometry<double> GeometryOf(const EquinoctialElements& el, double mu) {
  return internal::Geometry<double>(el.a_m, el.ex, el.ey, el.ix, el.iy, el.mean_longitude_rad, mu);
}

}  // namespace

double WrapPi(double angle) {
  double w = std::remainder(angle, 2.0 * kPi);  // [-pi, pi]
  if (w <= -kPi) w += 2.0 * kPi;
  return w;
}

Vector6d CartesianFromEquinoctial(const EquinoctialElements& el, double mu) {
  CheckElements(el, mu, "CartesianFromEquinoctial");
  const internal::OrbitGeometry<double> o = GeometryOf(el, mu);
  Vector6d rv;
  rv << o.pos[0], o.pos[1], o.pos[2], o.vel[0], o.vel[1], o.vel[2];
  return rv;
}

EquinoctialElements EquinoctialFromCartesian(const Vector6d& rv, double mu) {
  if (!rv.allFinite()) {
    throw std::invalid_argument("EquinoctialFromCartesian: state must be finite");
  }
  if (!(mu > 0.0) || !std::isfinite(mu)) {
    throw std::invalid_argument("EquinoctialFromCartesian: mu must be finite and > 0, got " +
                                FormatG(mu, 17));
  }
  const Eigen::Vector3d r = rv.head<3>(), v = rv.tail<3>();
  const Eigen::Vector3d h = r.cross(v);
  const double hn = h.norm();
  const double rn = r.norm();
  if (!(hn > 0.0) || !(rn > 0.0)) {
    throw std::invalid_argument(
        "EquinoctialFromCartesian: position and velocity are parallel (r x v = 0)");
  }
  if (!(hn + h.z() > 1e-12 * hn)) {
    throw std::invalid_argument(
        "EquinoctialFromCartesian: retrograde equatorial orbit (i = 180 deg) is singular");
  }
  EquinoctialElements el;
  const double inv_a = 2.0 / rn - v.squaredNorm() / mu;
  if (!(inv_a > 0.0)) {
    throw std::invalid_argument(
        "EquinoctialFromCartesian: orbit is not an ellipse (1/a = " + FormatG(inv_a, 17) + ")");
  }
  el.a_m = 1.0 / inv_a;
  el.ix = -h.y() / (hn + h.z());
  el.iy = h.x() / (hn + h.z());
  const double ix = el.ix, iy = el.iy, s = 1.0 + ix * ix + iy * iy;
  const Eigen::Vector3d f(1.0 + ix * ix - iy * iy, 2.0 * ix * iy, -2.0 * iy);
  const Eigen::Vector3d g(2.0 * ix * iy, 1.0 - ix * ix + iy * iy, 2.0 * ix);
  const Eigen::Vector3d fh = f / s, gh = g / s;
  const Eigen::Vector3d e = v.cross(h) / mu - r / rn;
  el.ex = e.dot(fh);
  el.ey = e.dot(gh);
  const double e2 = el.ex * el.ex + el.ey * el.ey;
  if (!(e2 < 1.0)) {
    throw std::invalid_argument("EquinoctialFromCartesian: eccentricity >= 1 (" +
                                FormatG(std::sqrt(e2), 17) + ")");
  }
  const double root = std::sqrt(1.0 - e2);
  const double beta = 1.0 / (1.0 + root);
  const double x1 = r.dot(fh), y1 = r.dot(gh);
  const double ce =
      el.ex + ((1.0 - el.ex * el.ex * beta) * x1 - el.ex * el.ey * beta * y1) / (el.a_m * root);
  const double se =
      el.ey + ((1.0 - el.ey * el.ey * beta) * y1 - el.ex * el.ey * beta * x1) / (el.a_m * root);
  const double ecc_anomaly = std::atan2(se, ce);
  el.mean_longitude_rad =
      WrapPi(ecc_anomaly + el.ey * std::cos(ecc_anomaly) - el.ex * std::sin(ecc_anomaly));
  return el;
}

Eigen::Matrix<double, 6, 3> GaussMatrix(const EquinoctialElements& el, double mu) {
  CheckElements(el, mu, "GaussMatrix");
  const auto g = internal::GaussMatrix(GeometryOf(el, mu));
  Eigen::Matrix<double, 6, 3> m;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 3; ++j) m(i, j) = g[i][j];
  }
  return m;
}

Eigen::Matrix3d RtnBasis(const Vector6d& rv) {
  if (!rv.allFinite()) throw std::invalid_argument("RtnBasis: state must be finite");
  const Eigen::Vector3d r = rv.head<3>(), v = rv.tail<3>();
  const Eigen::Vector3d h = r.cross(v);
  if (!(h.norm() > 0.0))
    throw std::invalid_argument("RtnBasis: position and velocity are parallel (r x v = 0)");
  Eigen::Matrix3d m;
  m.col(0) = r.normalized();
  m.col(2) = h.normalized();
  m.col(1) = m.col(2).cross(m.col(0));
  return m;
}

}  // namespace thrustsched::dynamics
