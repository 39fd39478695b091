#include "dynamics/frames.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/constants.h"

namespace thrustsched::dynamics {
namespace {

constexpr double kArcsec = common::kPi / (180.0 * 3600.0);

// Passive (frame) rotations: the coordinates of a fixed vector in axes turned
// by `a` about x, y or z.
Eigen::Matrix3d R1(double a) {
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a);
  return m;
}
Eigen::Matrix3d R2(double a) {
  Eigen::Matrix3d m;
  m << std::cos(a), 0, -std::sin(a), 0, 1, 0, std::sin(a), 0, std::cos(a);
  return m;
}
Eigen::Matrix3d R3(double a) {
  Eigen::Matrix3d m;
  m << std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a), 0, 0, 0, 1;
  return m;
}

Vector6d Rotate(const Eigen::Matrix3d& r, const Vector6d& rv) {
  Vector6d out;
  out << r * rv.head<3>(), r * rv.tail<3>();
  return out;
}

}  // namespace

std::string_view ToString(InertialFrame frame) {
  return frame == InertialFrame::kGcrf ? "GCRF" : "EME2000";
}

std::optional<InertialFrame> ParseInertialFrame(std::string_view name) {
  if (name == "EME2000" || name == "J2000") return InertialFrame::kEme2000;
  if (name == "GCRF") return InertialFrame::kGcrf;
  return std::nullopt;
}

Eigen::Matrix3d PrecessionIau1976(double jd_tt) {
  if (!std::isfinite(jd_tt)) {
    throw std::invalid_argument("PrecessionIau1976: jd_tt must be finite, got " +
                                std::to_string(jd_tt));
  }
  // Lieske (1977) angles from J2000.0 to the date, T in Julian centuries of TT.
  const double t = (jd_tt - kJulianDateJ2000) / 36525.0;
  const double zeta = (2306.2181 + (0.30188 + 0.017998 * t) * t) * t * kArcsec;
  const double z = (2306.2181 + (1.09468 + 0.018203 * t) * t) * t * kArcsec;
  const double theta = (2004.3109 + (-0.42665 - 0.041833 * t) * t) * t * kArcsec;
  return R3(-z) * R2(theta) * R3(-zeta);
}

Eigen::Matrix3d FrameBiasIers2003() {
  // IAU 2000 bias in longitude and obliquity and the ICRS RA offset; the
  // offsets of the pole are xi0 = d_psi sin(eps0) = -16.617 mas and
  // eta0 = d_eps = -6.8192 mas, eps0 = 84381.448".
  const double d_psi = -0.041775 * kArcsec, d_eps = -0.0068192 * kArcsec,
               d_alpha0 = -0.0146 * kArcsec;
  const double eps0 = 84381.448 * kArcsec;
  return R1(-d_eps) * R2(d_psi * std::sin(eps0)) * R3(d_alpha0);
}

Eigen::Matrix3d ModelFrameRotation(InertialFrame frame, const Epoch& model_epoch) {
  const Eigen::Matrix3d p = PrecessionIau1976(model_epoch.JulianDateTt());
  return frame == InertialFrame::kGcrf ? Eigen::Matrix3d(p * FrameBiasIers2003()) : p;
}

Vector6d ToModelFrame(const Vector6d& rv, InertialFrame frame, const Epoch& model_epoch) {
  return Rotate(ModelFrameRotation(frame, model_epoch), rv);
}

Vector6d FromModelFrame(const Vector6d& rv_model, InertialFrame frame, const Epoch& model_epoch) {
  return Rotate(ModelFrameRotation(frame, model_epoch).transpose(), rv_model);
}

}  // namespace thrustsched::dynamics
