#include "dynamics/schweighart_sedwick.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "common/constants.h"

namespace thrustsched::dynamics {
namespace {

constexpr std::string_view kWhere = "SchweighartSedwickModel";

[[noreturn]] void Throw(std::string_view where, const char* field, const char* rule, double value) {
  std::ostringstream msg;
  msg << where << ": " << field << " must be " << rule << ", got " << value;
  throw std::invalid_argument(msg.str());
}

void RequirePositive(const char* field, double value) {
  if (!std::isfinite(value) || value <= 0.0) Throw(kWhere, field, "finite and > 0", value);
}

}  // namespace

SchweighartSedwickModel::SchweighartSedwickModel(double reference_radius_m, double inclination_rad,
                                                 double length_scale_m, CrossTrack cross_track,
                                                 double mu_m3_s2, double j2, double earth_radius_m)
    : r_ref_(reference_radius_m),
      inclination_(inclination_rad),
      length_scale_m_(length_scale_m),
      cross_track_(cross_track) {
  RequirePositive("reference_radius_m", reference_radius_m);
  RequirePositive("length_scale_m", length_scale_m);
  RequirePositive("mu_m3_s2", mu_m3_s2);
  RequirePositive("earth_radius_m", earth_radius_m);
  if (!std::isfinite(inclination_rad) || inclination_rad < 0.0 || inclination_rad > common::kPi) {
    Throw(kWhere, "inclination_rad", "in [0, pi]", inclination_rad);
  }
  if (!std::isfinite(j2) || j2 < 0.0) Throw(kWhere, "j2", "finite and >= 0", j2);
  n_ = std::sqrt(mu_m3_s2 / (r_ref_ * r_ref_ * r_ref_));
  const double re_over_r = earth_radius_m / r_ref_;
  s_ = 3.0 * j2 * re_over_r * re_over_r / 8.0 * (1.0 + 3.0 * std::cos(2.0 * inclination_rad));
  // n^2 (1 - s) is the squared radial frequency and n^2 (1 + 3 s) the simple
  // form's cross-track one: |s| that large would need r_ref far inside the
  // Earth (or a J2 hundreds of times the Earth's), where the model means nothing.
  if (!(s_ > -1.0 / 3.0 && s_ < 1.0)) {
    Throw(kWhere, "s (from reference_radius_m and j2)", "in (-1/3, 1)", s_);
  }
  c_ = std::sqrt(1.0 + s_);
  if (cross_track_ == CrossTrack::kSimple) {
    q_ = n_ * std::sqrt(3.0 * c_ * c_ - 2.0);  // 3 c^2 - 2 = 1 + 3 s > 0 (checked)
  } else {
    // n c - Omega' cos i, Omega' = -3 n J2 (R_E / r)^2 cos i / 2 (nodal rate).
    const double cos_i = std::cos(inclination_rad);
    q_ = n_ * c_ + 1.5 * n_ * j2 * re_over_r * re_over_r * cos_i * cos_i;
  }
}

ModelMatrices SchweighartSedwickModel::Evaluate(double t) const {
  if (!std::isfinite(t)) Throw("SchweighartSedwickModel::Evaluate", "t", "finite", t);
  ModelMatrices m;
  m.a = Eigen::MatrixXd::Zero(6, 6);
  m.a.topRightCorner<3, 3>().setIdentity();
  const double n2 = n_ * n_, c2 = c_ * c_;  // n2, c2 used on the in-plane rows
  m.a(3, 0) = (5.0 * c2 - 2.0) * n2;        // HCW: 3 n^2
  m.a(3, 4) = 2.0 * n_ * c_;                // HCW: 2 n
  m.a(4, 3) = -2.0 * n_ * c_;
  m.a(5, 2) = -q_ * q_;  // HCW: -n^2
  m.b = Eigen::MatrixXd::Zero(6, 3);
  m.b.bottomRows<3>().setIdentity();
  m.d = Eigen::VectorXd::Zero(6);
  return m;
}

OutputMatrices SchweighartSedwickModel::EvaluateOutput(double t) const {
  if (!std::isfinite(t)) Throw("SchweighartSedwickModel::EvaluateOutput", "t", "finite", t);
  OutputMatrices o;
  o.c = Eigen::MatrixXd::Zero(3, 6);
  o.c.leftCols<3>().setIdentity();
  o.c_dot = Eigen::MatrixXd::Zero(3, 6);
  return o;
}

std::vector<std::string> SchweighartSedwickModel::state_names() const {
  return {"x_m", "y_m", "z_m", "vx_m_s", "vy_m_s", "vz_m_s"};
}

std::vector<std::string> SchweighartSedwickModel::output_names() const {
  return {"x_m", "y_m", "z_m"};
}

Eigen::VectorXd SchweighartSedwickModel::state_scale() const {
  const double l = length_scale_m_, v = length_scale_m_ * n_;
  Eigen::VectorXd scale(6);
  scale << l, l, l, v, v, v;
  return scale;
}

double SchweighartSedwickModel::DriftFreeAlongTrackVelocity(double x0_m) const {
  if (!std::isfinite(x0_m)) {
    Throw("SchweighartSedwickModel::DriftFreeAlongTrackVelocity", "x0_m", "finite", x0_m);
  }
  return -2.0 * n_ * c_ * x0_m;
}

}  // namespace thrustsched::dynamics
