#include "dynamics/models.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Eigen/Dense>

#include "common/constants.h"

namespace thrustsched::dynamics {
namespace {

using common::kPi;
constexpr double kTwoPi = 2.0 * kPi;

void RequirePositive(std::string_view where, const char* field, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    std::ostringstream msg;
    msg << where << ": " << field << " must be finite and > 0, got " << value;
    throw std::invalid_argument(msg.str());
  }
}

void RequireFinite(std::string_view where, const char* field, double value) {
  if (!std::isfinite(value)) {
    std::ostringstream msg;
    msg << where << ": " << field << " must be finite, got " << value;
    throw std::invalid_argument(msg.str());
  }
}

// x - sin(x) without cancellation for small |x| (series), exact formula otherwise.
double XMinusSin(double x) {
  if (std::abs(x) >= 1.0) return x - std::sin(x);
  const double x2 = x * x;
  double term = x * x2 / 6.0;  // x^3 / 3!
  double sum = term;
  for (int k = 2; k < 30; ++k) {  // term_k = (-1)^(k+1) x^(2k+1) / (2k+1)!
    term *= -x2 / ((2.0 * k) * (2.0 * k + 1.0));
    sum += term;
    if (std::abs(term) <= 1e-18 * std::abs(sum)) break;
  }
  return sum;
}

// 1 - cos(x) without cancellation.
double OneMinusCos(double x) {
  const double h = std::sin(0.5 * x);
  return 2.0 * h * h;
}

// Cartesian relative-motion names shared by the 3-D models.
std::vector<std::string> CartesianStateNames() {
  return {"x_m", "y_m", "z_m", "vx_m_s", "vy_m_s", "vz_m_s"};
}
std::vector<std::string> CartesianOutputNames() { return {"x_m", "y_m", "z_m"}; }

// [0 I; 0 0] structure pieces common to the 6-state models.
ModelMatrices SecondOrder6(double t, std::string_view where) {
  RequireFinite(where, "t", t);
  ModelMatrices m;
  m.a = Eigen::MatrixXd::Zero(6, 6);
  m.a.topRightCorner<3, 3>().setIdentity();
  m.b = Eigen::MatrixXd::Zero(6, 3);
  m.b.bottomRows<3>().setIdentity();
  m.d = Eigen::VectorXd::Zero(6);
  return m;
}

OutputMatrices PositionOutput6(double t, std::string_view where) {
  RequireFinite(where, "t", t);
  OutputMatrices o;
  o.c = Eigen::MatrixXd::Zero(3, 6);
  o.c.leftCols<3>().setIdentity();
  o.c_dot = Eigen::MatrixXd::Zero(3, 6);
  return o;
}

Eigen::VectorXd OrbitalScale(double length_m, double n) {
  Eigen::VectorXd s(6);
  s << length_m, length_m, length_m, length_m * n, length_m * n, length_m * n;
  return s;
}

}  // namespace

// ---------------------------------------------------------------- double integrators

DoubleIntegrator1d::DoubleIntegrator1d(double time_scale_s, double length_scale_m)
    : time_scale_s_(time_scale_s), length_scale_m_(length_scale_m) {
  RequirePositive("DoubleIntegrator1d", "time_scale_s", time_scale_s);
  RequirePositive("DoubleIntegrator1d", "length_scale_m", length_scale_m);
}

ModelMatrices DoubleIntegrator1d::Evaluate(double t) const {
  RequireFinite("DoubleIntegrator1d::Evaluate", "t", t);
  ModelMatrices m;
  m.a = Eigen::MatrixXd::Zero(2, 2);
  m.a(0, 1) = 1.0;
  m.b = Eigen::MatrixXd::Zero(2, 1);
  m.b(1, 0) = 1.0;
  m.d = Eigen::VectorXd::Zero(2);
  return m;
}

OutputMatrices DoubleIntegrator1d::EvaluateOutput(double t) const {
  RequireFinite("DoubleIntegrator1d::EvaluateOutput", "t", t);
  OutputMatrices o;
  o.c = Eigen::MatrixXd::Zero(1, 2);
  o.c(0, 0) = 1.0;
  o.c_dot = Eigen::MatrixXd::Zero(1, 2);
  return o;
}

std::vector<std::string> DoubleIntegrator1d::state_names() const { return {"x_m", "v_m_s"}; }
std::vector<std::string> DoubleIntegrator1d::output_names() const { return {"x_m"}; }

Eigen::VectorXd DoubleIntegrator1d::state_scale() const {
  return Eigen::Vector2d(length_scale_m_, length_scale_m_ / time_scale_s_);
}

DoubleIntegrator3d::DoubleIntegrator3d(double time_scale_s, double length_scale_m)
    : time_scale_s_(time_scale_s), length_scale_m_(length_scale_m) {
  RequirePositive("DoubleIntegrator3d", "time_scale_s", time_scale_s);
  RequirePositive("DoubleIntegrator3d", "length_scale_m", length_scale_m);
}

ModelMatrices DoubleIntegrator3d::Evaluate(double t) const {
  return SecondOrder6(t, "DoubleIntegrator3d::Evaluate");
}

OutputMatrices DoubleIntegrator3d::EvaluateOutput(double t) const {
  return PositionOutput6(t, "DoubleIntegrator3d::EvaluateOutput");
}

std::vector<std::string> DoubleIntegrator3d::state_names() const { return CartesianStateNames(); }
std::vector<std::string> DoubleIntegrator3d::output_names() const { return CartesianOutputNames(); }

Eigen::VectorXd DoubleIntegrator3d::state_scale() const {
  return OrbitalScale(length_scale_m_, 1.0 / time_scale_s_);
}

// ---------------------------------------------------------------- HCW

HcwModel::HcwModel(double mean_motion_rad_s, double length_scale_m)
    : n_(mean_motion_rad_s), length_scale_m_(length_scale_m) {
  RequirePositive("HcwModel", "mean_motion_rad_s", mean_motion_rad_s);
  RequirePositive("HcwModel", "length_scale_m", length_scale_m);
}

ModelMatrices HcwModel::Evaluate(double t) const {
  ModelMatrices m = SecondOrder6(t, "HcwModel::Evaluate");
  m.a(3, 0) = 3.0 * n_ * n_;
  m.a(3, 4) = 2.0 * n_;
  m.a(4, 3) = -2.0 * n_;
  m.a(5, 2) = -n_ * n_;
  return m;
}

OutputMatrices HcwModel::EvaluateOutput(double t) const {
  return PositionOutput6(t, "HcwModel::EvaluateOutput");
}

std::vector<std::string> HcwModel::state_names() const { return CartesianStateNames(); }
std::vector<std::string> HcwModel::output_names() const { return CartesianOutputNames(); }
Eigen::VectorXd HcwModel::state_scale() const { return OrbitalScale(length_scale_m_, n_); }

Eigen::Matrix<double, 6, 6> HcwModel::TransitionMatrix(double tau) const {
  RequireFinite("HcwModel::TransitionMatrix", "tau", tau);
  const double n = n_, x = n * tau;
  const double s = std::sin(x), c = std::cos(x);
  const double omc = OneMinusCos(x);  // 1 - c
  const double xms = XMinusSin(x);    // x - s
  Eigen::Matrix<double, 6, 6> p = Eigen::Matrix<double, 6, 6>::Zero();
  // Columns: x, y, z, vx, vy, vz.
  p(0, 0) = 1.0 + 3.0 * omc;  // 4 - 3c
  p(0, 3) = s / n;
  p(0, 4) = 2.0 * omc / n;
  p(1, 0) = -6.0 * xms;  // 6 (s - n tau)
  p(1, 1) = 1.0;
  p(1, 3) = -2.0 * omc / n;       // 2 (c - 1) / n
  p(1, 4) = (x - 4.0 * xms) / n;  // (4 s - 3 n tau) / n
  p(2, 2) = c;
  p(2, 5) = s / n;
  p(3, 0) = 3.0 * n * s;
  p(3, 3) = c;
  p(3, 4) = 2.0 * s;
  p(4, 0) = -6.0 * n * omc;  // 6 n (c - 1); corrected: Gazzino 2018 (I.4) prints 6 (c - 1)
  p(4, 3) = -2.0 * s;
  p(4, 4) = 1.0 - 4.0 * omc;  // 4 c - 3
  p(5, 2) = -n * s;
  p(5, 5) = c;
  return p;
}

Eigen::Matrix<double, 6, 3> HcwModel::ZohInputMatrix(double tau) const {
  RequireFinite("HcwModel::ZohInputMatrix", "tau", tau);
  // Integral over [0, tau] of columns 4..6 of Phi(s) (B = [0; I]); with
  // x = n tau: int s = (1 - c)/n, int c = s/n, int (x - s) = x^2/(2n) - (1-c)/n.
  const double n = n_, x = n * tau, n2 = n * n;
  const double s = std::sin(x);
  const double omc = OneMinusCos(x);
  const double xms = XMinusSin(x);
  Eigen::Matrix<double, 6, 3> g = Eigen::Matrix<double, 6, 3>::Zero();
  // a_R (acts like vx).
  g(0, 0) = omc / n2;
  g(1, 0) = -2.0 * xms / n2;
  g(3, 0) = s / n;
  g(4, 0) = -2.0 * omc / n;
  // a_T (acts like vy).
  g(0, 1) = 2.0 * xms / n2;
  g(1, 1) = (4.0 * omc - 1.5 * x * x) / n2;
  g(3, 1) = 2.0 * omc / n;
  g(4, 1) = (x - 4.0 * xms) / n;  // 4 s / n - 3 tau
  // a_N (acts like vz).
  g(2, 2) = omc / n2;
  g(5, 2) = s / n;
  return g;
}

// ---------------------------------------------------------------- Yamanaka-Ankersen

YamanakaAnkersenModel::YamanakaAnkersenModel(double semi_major_axis_m, double eccentricity,
                                             double mu_m3_s2, double true_anomaly_at_epoch_rad,
                                             double length_scale_m)
    : a_(semi_major_axis_m),
      e_(eccentricity),
      mu_(mu_m3_s2),
      nu_epoch_(true_anomaly_at_epoch_rad),
      length_scale_m_(length_scale_m) {
  constexpr std::string_view kWhere = "YamanakaAnkersenModel";
  RequirePositive(kWhere, "semi_major_axis_m", semi_major_axis_m);
  RequirePositive(kWhere, "mu_m3_s2", mu_m3_s2);
  RequirePositive(kWhere, "length_scale_m", length_scale_m);
  RequireFinite(kWhere, "true_anomaly_at_epoch_rad", true_anomaly_at_epoch_rad);
  if (!std::isfinite(eccentricity) || eccentricity < 0.0 || eccentricity > 0.99) {
    std::ostringstream msg;
    msg << kWhere << ": eccentricity must be in [0, 0.99], got " << eccentricity;
    throw std::invalid_argument(msg.str());
  }
  n_ = std::sqrt(mu_ / (a_ * a_ * a_));
  p_ = a_ * (1.0 - e_ * e_);
  // Unwrapped mean anomaly of the epoch true anomaly.
  const double k = std::round(nu_epoch_ / kTwoPi);
  const double nu_w = nu_epoch_ - kTwoPi * k;
  const double ecc_anomaly = 2.0 * std::atan2(std::sqrt(1.0 - e_) * std::sin(0.5 * nu_w),
                                              std::sqrt(1.0 + e_) * std::cos(0.5 * nu_w));
  mean_anomaly_epoch_ = ecc_anomaly - e_ * std::sin(ecc_anomaly) + kTwoPi * k;
}

double YamanakaAnkersenModel::period() const { return kTwoPi / n_; }

double YamanakaAnkersenModel::SolveKepler(double mean_anomaly_rad, double eccentricity) {
  RequireFinite("YamanakaAnkersenModel::SolveKepler", "mean_anomaly_rad", mean_anomaly_rad);
  if (!std::isfinite(eccentricity) || eccentricity < 0.0 || eccentricity >= 1.0) {
    std::ostringstream msg;
    msg << "YamanakaAnkersenModel::SolveKepler: eccentricity must be in [0, 1), got "
        << eccentricity;
    throw std::invalid_argument(msg.str());
  }
  const double e = eccentricity;
  // Work on M in [-pi, pi]; f(E) = E - e sin E - M is increasing (f' >= 1 - e)
  // and its root lies in [M - e, M + e]: Newton, falling back to bisection
  // whenever the Newton step leaves the bracket.
  const double k = std::round(mean_anomaly_rad / kTwoPi);
  const double m = mean_anomaly_rad - kTwoPi * k;
  if (e == 0.0) return mean_anomaly_rad;
  double lo = m - e, hi = m + e;
  double ecc = (e < 0.8) ? m + e * std::sin(m) : (m >= 0.0 ? kPi : -kPi);
  ecc = std::min(std::max(ecc, lo), hi);
  for (int iter = 0; iter < 100; ++iter) {
    const double f = ecc - e * std::sin(ecc) - m;
    if (f == 0.0) break;
    if (f > 0.0) {
      hi = ecc;
    } else {
      lo = ecc;
    }
    const double step = f / (1.0 - e * std::cos(ecc));
    double next = ecc - step;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - ecc) <= 4e-16 * std::max(1.0, std::abs(ecc))) {
      ecc = next;
      break;
    }
    ecc = next;
  }
  return ecc + kTwoPi * k;
}

double YamanakaAnkersenModel::TrueAnomalyAt(double t) const {
  RequireFinite("YamanakaAnkersenModel::TrueAnomalyAt", "t", t);
  const double mean = mean_anomaly_epoch_ + n_ * t;
  const double k = std::round(mean / kTwoPi);
  const double ecc = SolveKepler(mean - kTwoPi * k, e_);
  const double nu_w = 2.0 * std::atan2(std::sqrt(1.0 + e_) * std::sin(0.5 * ecc),
                                       std::sqrt(1.0 - e_) * std::cos(0.5 * ecc));
  return nu_w + kTwoPi * k;
}

double YamanakaAnkersenModel::TimeAtTrueAnomaly(double nu_rad) const {
  RequireFinite("YamanakaAnkersenModel::TimeAtTrueAnomaly", "nu_rad", nu_rad);
  const double k = std::round(nu_rad / kTwoPi);
  const double nu_w = nu_rad - kTwoPi * k;
  const double ecc = 2.0 * std::atan2(std::sqrt(1.0 - e_) * std::sin(0.5 * nu_w),
                                      std::sqrt(1.0 + e_) * std::cos(0.5 * nu_w));
  const double mean = ecc - e_ * std::sin(ecc) + kTwoPi * k;
  return (mean - mean_anomaly_epoch_) / n_;
}

ModelMatrices YamanakaAnkersenModel::Evaluate(double t) const {
  ModelMatrices m = SecondOrder6(t, "YamanakaAnkersenModel::Evaluate");
  const double nu = TrueAnomalyAt(t);
  const double rho = 1.0 + e_ * std::cos(nu);
  const double r = p_ / rho;
  const double k = mu_ / (r * r * r);
  const double w = std::sqrt(mu_ / (p_ * p_ * p_)) * rho * rho;  // nu'
  const double r_dot = std::sqrt(mu_ / p_) * e_ * std::sin(nu);
  const double w_dot = -2.0 * w * r_dot / r;  // nu''
  m.a(3, 0) = w * w + 2.0 * k;
  m.a(3, 1) = w_dot;
  m.a(3, 4) = 2.0 * w;
  m.a(4, 0) = -w_dot;
  m.a(4, 1) = w * w - k;
  m.a(4, 3) = -2.0 * w;
  m.a(5, 2) = -k;
  return m;
}

OutputMatrices YamanakaAnkersenModel::EvaluateOutput(double t) const {
  return PositionOutput6(t, "YamanakaAnkersenModel::EvaluateOutput");
}

std::vector<std::string> YamanakaAnkersenModel::state_names() const {
  return CartesianStateNames();
}
std::vector<std::string> YamanakaAnkersenModel::output_names() const {
  return CartesianOutputNames();
}
Eigen::VectorXd YamanakaAnkersenModel::state_scale() const {
  return OrbitalScale(length_scale_m_, n_);
}

Eigen::Matrix<double, 6, 6> YamanakaAnkersenModel::TransitionMatrix(double t, double t0) const {
  RequireFinite("YamanakaAnkersenModel::TransitionMatrix", "t", t);
  RequireFinite("YamanakaAnkersenModel::TransitionMatrix", "t0", t0);
  return TransitionMatrixImpl(TrueAnomalyAt(t), TrueAnomalyAt(t0), t - t0);
}

Eigen::Matrix<double, 6, 6> YamanakaAnkersenModel::TransitionMatrixFromTrueAnomaly(
    double nu_rad, double nu0_rad) const {
  RequireFinite("YamanakaAnkersenModel::TransitionMatrixFromTrueAnomaly", "nu_rad", nu_rad);
  RequireFinite("YamanakaAnkersenModel::TransitionMatrixFromTrueAnomaly", "nu0_rad", nu0_rad);
  return TransitionMatrixImpl(nu_rad, nu0_rad,
                              TimeAtTrueAnomaly(nu_rad) - TimeAtTrueAnomaly(nu0_rad));
}

Eigen::Matrix<double, 6, 6> YamanakaAnkersenModel::TransitionMatrixImpl(double nu, double nu0,
                                                                        double dt) const {
  // Yamanaka & Ankersen (2002) in the LVLH frame of Serra 2015, sec. 4.1.1 (x_S
  // along-track, y_S = -normal, z_S = nadir), with the transformation
  // q~ = rho q, q~' = -e sin(nu) q + q_dot / (k2 rho) per axis, then mapped to
  // this model's (radial, along-track, normal) frame.
  const double e = e_;
  const double k2 = std::sqrt(mu_ / (p_ * p_ * p_));  // = n (1 - e^2)^(-3/2)
  const double big_j = k2 * dt;

  // Fundamental matrix at nu, in-plane state (x~, z~, x~', z~').
  const double sn = std::sin(nu), cn = std::cos(nu);
  const double rho = 1.0 + e * cn;
  const double s = rho * sn, c = rho * cn;
  const double sp = cn + e * std::cos(2.0 * nu);
  const double cp = -(sn + e * std::sin(2.0 * nu));
  Eigen::Matrix4d phi;
  phi << 1.0, -c * (1.0 + 1.0 / rho), s * (1.0 + 1.0 / rho), 3.0 * rho * rho * big_j,  //
      0.0, s, c, 2.0 - 3.0 * e * s * big_j,                                            //
      0.0, 2.0 * s, 2.0 * c - e, 3.0 * (1.0 - 2.0 * e * s * big_j),                    //
      0.0, sp, cp, -3.0 * e * (sp * big_j + s / (rho * rho));

  // Inverse fundamental matrix at nu0 (J = 0).
  const double sn0 = std::sin(nu0), cn0 = std::cos(nu0);
  const double rho0 = 1.0 + e * cn0;
  const double s0 = rho0 * sn0, c0 = rho0 * cn0;
  Eigen::Matrix4d phi0_inv;
  phi0_inv << 1.0 - e * e, 3.0 * e * s0 * (1.0 / rho0 + 1.0 / (rho0 * rho0)),
      -e * s0 * (1.0 + 1.0 / rho0), 2.0 - e * c0,  //
      0.0, -3.0 * s0 * (1.0 / rho0 + e * e / (rho0 * rho0)), s0 * (1.0 + 1.0 / rho0),
      c0 - 2.0 * e,                                                   //
      0.0, -3.0 * (c0 / rho0 + e), c0 * (1.0 + 1.0 / rho0) + e, -s0,  //
      0.0, 3.0 * rho0 + e * e - 1.0, -rho0 * rho0, e * s0;
  phi0_inv /= (1.0 - e * e);

  // Physical <-> transformed variables, in-plane order (x, z, x_dot, z_dot).
  Eigen::Matrix4d to_tilde0 = Eigen::Matrix4d::Zero();
  to_tilde0(0, 0) = rho0;
  to_tilde0(1, 1) = rho0;
  to_tilde0(2, 0) = -e * sn0;
  to_tilde0(2, 2) = 1.0 / (k2 * rho0);
  to_tilde0(3, 1) = -e * sn0;
  to_tilde0(3, 3) = 1.0 / (k2 * rho0);
  Eigen::Matrix4d from_tilde = Eigen::Matrix4d::Zero();
  from_tilde(0, 0) = 1.0 / rho;
  from_tilde(1, 1) = 1.0 / rho;
  from_tilde(2, 0) = k2 * e * sn;
  from_tilde(2, 2) = k2 * rho;
  from_tilde(3, 1) = k2 * e * sn;
  from_tilde(3, 3) = k2 * rho;
  const Eigen::Matrix4d in_plane = from_tilde * phi * phi0_inv * to_tilde0;

  // Out-of-plane: y~'' = -y~, a rotation by nu - nu0.
  const double dnu = nu - nu0;
  Eigen::Matrix2d rot;
  rot << std::cos(dnu), std::sin(dnu), -std::sin(dnu), std::cos(dnu);
  Eigen::Matrix2d to_tilde0_y, from_tilde_y;
  to_tilde0_y << rho0, 0.0, -e * sn0, 1.0 / (k2 * rho0);
  from_tilde_y << 1.0 / rho, 0.0, k2 * e * sn, k2 * rho;
  const Eigen::Matrix2d out_of_plane = from_tilde_y * rot * to_tilde0_y;

  // Serra in-plane (x_S, z_S, xd_S, zd_S) = (y, -x, vy, -vx) of this frame;
  // out-of-plane (y_S, yd_S) = (-z, -vz) (the signs cancel).
  constexpr int kIdx[4] = {1, 0, 4, 3};
  constexpr double kSign[4] = {1.0, -1.0, 1.0, -1.0};
  Eigen::Matrix<double, 6, 6> out = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) out(kIdx[i], kIdx[j]) = kSign[i] * kSign[j] * in_plane(i, j);
  }
  out(2, 2) = out_of_plane(0, 0);
  out(2, 5) = out_of_plane(0, 1);
  out(5, 2) = out_of_plane(1, 0);
  out(5, 5) = out_of_plane(1, 1);
  return out;
}

}  // namespace thrustsched::dynamics
