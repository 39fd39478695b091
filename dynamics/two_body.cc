#include "dynamics/two_body.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

namespace thrustsched::dynamics {
namespace {

void RequireFinite(const char* where, double t) {
  if (!std::isfinite(t)) throw std::invalid_argument(std::string(where) + ": t must be finite");
}

// Reference radius, angular rate, and perifocal position/velocity at t.
struct ReferencePoint {
  Eigen::Vector3d r, v;
  double nu_dot;
};

ReferencePoint Reference(const YamanakaAnkersenModel& model, double t) {
  RequireFinite("ReferenceEci", t);
  const double e = model.eccentricity(), mu = model.mu();
  const double p = model.semi_major_axis() * (1.0 - e * e);
  const double nu = model.TrueAnomalyAt(t);
  const double radius = p / (1.0 + e * std::cos(nu));
  const double vs = std::sqrt(mu / p);
  ReferencePoint out;
  out.r = radius * Eigen::Vector3d(std::cos(nu), std::sin(nu), 0.0);
  out.v = vs * Eigen::Vector3d(-std::sin(nu), e + std::cos(nu), 0.0);
  out.nu_dot = std::sqrt(mu * p) / (radius * radius);
  return out;
}

Eigen::Matrix3d Basis(const Eigen::Vector3d& r) {
  const Eigen::Vector3d ur = r.normalized();
  const Eigen::Vector3d un(0.0, 0.0, 1.0);  // perifocal z = angular momentum
  Eigen::Matrix3d c;
  c.col(0) = ur;
  c.col(1) = un.cross(ur);
  c.col(2) = un;
  return c;
}

}  // namespace

KeplerOrbit::KeplerOrbit(const Vector6d& eci, double t0, double mu)
    : elements_(EquinoctialFromCartesian(eci, mu)), t0_(t0), mu_(mu) {
  RequireFinite("KeplerOrbit", t0);
  n_ = std::sqrt(mu_ / (elements_.a_m * elements_.a_m * elements_.a_m));
}

Vector6d KeplerOrbit::At(double t) const {
  RequireFinite("KeplerOrbit::At", t);
  EquinoctialElements el = elements_;
  el.mean_longitude_rad = WrapPi(el.mean_longitude_rad + n_ * (t - t0_));
  return CartesianFromEquinoctial(el, mu_);
}

Vector6d ReferenceEci(const YamanakaAnkersenModel& model, double t) {
  const ReferencePoint ref = Reference(model, t);
  Vector6d out;
  out << ref.r, ref.v;
  return out;
}

Eigen::Matrix3d RelativeFrameBasis(const YamanakaAnkersenModel& model, double t) {
  return Basis(Reference(model, t).r);
}

Vector6d EciFromRelative(const YamanakaAnkersenModel& model, const Eigen::VectorXd& x, double t) {
  if (x.size() != 6 || !x.allFinite()) {
    throw std::invalid_argument("EciFromRelative: the relative state must be a finite 6-vector");
  }
  const ReferencePoint ref = Reference(model, t);
  const Eigen::Matrix3d c = Basis(ref.r);
  const Eigen::Vector3d rho = x.head<3>(), rho_dot = x.tail<3>();
  const Eigen::Vector3d omega(0.0, 0.0, ref.nu_dot);  // frame rate, in frame axes
  Vector6d out;
  out << ref.r + c * rho, ref.v + c * (rho_dot + omega.cross(rho));
  return out;
}

Eigen::VectorXd RelativeFromEci(const YamanakaAnkersenModel& model, const Vector6d& eci, double t) {
  if (!eci.allFinite()) throw std::invalid_argument("RelativeFromEci: the state must be finite");
  const ReferencePoint ref = Reference(model, t);
  const Eigen::Matrix3d c = Basis(ref.r);
  const Eigen::Vector3d rho = c.transpose() * (eci.head<3>() - ref.r);
  const Eigen::Vector3d omega(0.0, 0.0, ref.nu_dot);
  Eigen::VectorXd out(6);
  out << rho, c.transpose() * (eci.tail<3>() - ref.v) - omega.cross(rho);
  return out;
}

}  // namespace thrustsched::dynamics
