#include "transcription/terminal_sets.h"

#include <cmath>
#include <stdexcept>

#include "common/constants.h"
#include "common/error.h"
#include "dynamics/geo_model.h"
#include "dynamics/models.h"

namespace thrustsched::transcription {
namespace {

using common::kPi;

void CheckOptions(const SkSetOptions& o) {
  std::string error;
  if (!o.IsValid(&error)) throw std::invalid_argument("terminal set: " + error);
}

// Rows of xi1, xi2 and xi-(t) + eps (the eps-free part of xi+/-) in zeta.
Eigen::Matrix<double, 1, 6> Xi1(double n) {
  Eigen::Matrix<double, 1, 6> r = Eigen::Matrix<double, 1, 6>::Zero();
  r(3) = 2.0 / n;
  return r;
}
Eigen::Matrix<double, 1, 6> Xi2(double n) {
  Eigen::Matrix<double, 1, 6> r = Eigen::Matrix<double, 1, 6>::Zero();
  r(0) = 6.0;
  r(4) = 4.0 / n;
  return r;
}
Eigen::Matrix<double, 1, 6> XiDrift(double n, double t) {
  Eigen::Matrix<double, 1, 6> r = Eigen::Matrix<double, 1, 6>::Zero();
  r(0) = 6.0 * n * t;
  r(1) = -1.0;
  r(3) = 2.0 / n;
  r(4) = 3.0 * t;
  return r;
}

}  // namespace

bool SkSetOptions::IsValid(std::string* error) const {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(mean_motion)) {
    return common::Fail(error,
                        "mean_motion must be finite and > 0, got " + std::to_string(mean_motion));
  }
  if (!positive(eps_y) || !positive(eps_z)) {
    return common::Fail(error, "window half widths must be finite and > 0, got " +
                                   std::to_string(eps_y) + " and " + std::to_string(eps_z));
  }
  if (facets_out_of_plane < 3 || facets_cone_plus < 3 || facets_cone_minus < 3) {
    return common::Fail(error, "at least 3 facets per polygon are needed");
  }
  if (lookahead_s.empty()) return common::Fail(error, "lookahead_s is empty");
  for (double t : lookahead_s) {
    if (!std::isfinite(t) || t < 0.0)
      return common::Fail(error, "lookahead_s entries must be finite and >= 0");
  }
  return true;
}

HalfSpaces StationKeepingSet(const SkSetOptions& o) {
  CheckOptions(o);
  const double n = o.mean_motion;
  const int kz = o.facets_out_of_plane;
  const int kp = o.facets_cone_plus;
  const int km = o.facets_cone_minus;
  const int times = static_cast<int>(o.lookahead_s.size());
  const int rows = kz + times * (kp + km);
  HalfSpaces h;
  h.a = Eigen::MatrixXd::Zero(rows, 6);
  h.b = Eigen::VectorXd::Zero(rows);
  int r = 0;
  // Disk in (z, zdot/n): cos(phi) z + sin(phi) zdot/n <= eps_z cos(pi/K).
  for (int k = 0; k < kz; ++k, ++r) {
    const double phi = (2 * k + 1) * kPi / kz;
    h.a(r, 2) = std::cos(phi);
    h.a(r, 5) = std::sin(phi) / n;
    h.b(r) = o.eps_z * std::cos(kPi / kz);
    h.names.push_back("sk_disk_" + std::to_string(k));
  }
  for (int ti = 0; ti < times; ++ti) {
    const double t = o.lookahead_s[ti];
    const auto drift = XiDrift(n, t);
    // Positive cone: cos(phi) xi1 + sin(phi) xi2 <= cos(pi/K) xi+,  xi+ = eps + drift.
    for (int k = 0; k < kp; ++k, ++r) {
      const double phi = (2 * k + 1) * kPi / kp;
      const double c = std::cos(kPi / kp);
      h.a.row(r) = std::cos(phi) * Xi1(n) + std::sin(phi) * Xi2(n) - c * drift;
      h.b(r) = c * o.eps_y;
      h.names.push_back("sk_cone_plus_t" + std::to_string(ti) + "_" + std::to_string(k));
    }
    // Negative cone: cos(phi) xi1 + sin(phi) xi2 <= -cos(pi/K) xi-,  xi- = -eps + drift.
    for (int k = 0; k < km; ++k, ++r) {
      const double phi = (2 * k + 1) * kPi / km;
      const double c = std::cos(kPi / km);
      h.a.row(r) = std::cos(phi) * Xi1(n) + std::sin(phi) * Xi2(n) + c * drift;
      h.b(r) = c * o.eps_y;
      h.names.push_back("sk_cone_minus_t" + std::to_string(ti) + "_" + std::to_string(k));
    }
  }
  return h;
}

bool InExactStationKeepingSet(const SkSetOptions& o, const Eigen::Matrix<double, 6, 1>& zeta,
                              double tolerance) {
  CheckOptions(o);
  const double n = o.mean_motion;
  const double z = zeta(2), zd = zeta(5) / n;
  if (std::sqrt(z * z + zd * zd) > o.eps_z + tolerance) return false;
  const double xi1 = Xi1(n) * zeta, xi2 = Xi2(n) * zeta;
  const double amp = std::hypot(xi1, xi2);
  for (double t : o.lookahead_s) {
    const double drift = XiDrift(n, t) * zeta;
    if (amp > o.eps_y + drift + tolerance) return false;  // xi+
    if (amp > o.eps_y - drift + tolerance) return false;  // -xi-
  }
  return true;
}

AffineMap HcwCoordinates(const dynamics::LinearModel& model, double t) {
  AffineMap m;
  if (dynamic_cast<const dynamics::HcwModel*>(&model) != nullptr ||
      dynamic_cast<const dynamics::YamanakaAnkersenModel*>(&model) != nullptr) {
    m.map = Eigen::MatrixXd::Identity(6, 6);
    m.offset = Eigen::VectorXd::Zero(6);
    return m;
  }
  if (const auto* geo = dynamic_cast<const dynamics::GeoLinearModel*>(&model)) {
    const double rho = geo->station_radius_m();
    const dynamics::OutputMatrices out = geo->EvaluateOutput(t);
    const dynamics::ModelMatrices mm = geo->Evaluate(t);
    // Outputs [dr, dlat, dlon]; rates (C' + C A) x + C d (thrust enters the
    // element rates but not the position, so C B ~ 0 and is left out).
    const Eigen::MatrixXd rate = out.c_dot + out.c * mm.a;
    const Eigen::VectorXd rate0 = out.c * mm.d;
    const int n = geo->num_states();
    m.map = Eigen::MatrixXd::Zero(6, n);
    m.offset = Eigen::VectorXd::Zero(6);
    m.map.row(0) = out.c.row(0);
    m.map.row(1) = rho * out.c.row(2);
    m.map.row(2) = rho * out.c.row(1);
    m.map.row(3) = rate.row(0);
    m.map.row(4) = rho * rate.row(2);
    m.map.row(5) = rho * rate.row(1);
    m.offset << 0.0, 0.0, 0.0, rate0(0), rho * rate0(2), rho * rate0(1);
    return m;
  }
  throw std::invalid_argument(
      "local HCW coordinates need an HCW, Yamanaka-Ankersen or GEO model, got " +
      std::string(model.name()));
}

double HcwMeanMotion(const dynamics::LinearModel& model) {
  if (const auto* hcw = dynamic_cast<const dynamics::HcwModel*>(&model)) return hcw->mean_motion();
  if (const auto* geo = dynamic_cast<const dynamics::GeoLinearModel*>(&model)) {
    return geo->mean_motion();
  }
  throw std::invalid_argument("terminal station-keeping sets need an HCW or GEO model, got " +
                              std::string(model.name()));
}

void HcwWindowWidths(const dynamics::LinearModel& model, const std::vector<int>& outputs,
                     const std::vector<double>& half_widths, double* eps_y, double* eps_z) {
  double scale = 1.0;
  int y_out = 1, z_out = 2;
  if (const auto* geo = dynamic_cast<const dynamics::GeoLinearModel*>(&model)) {
    scale = geo->station_radius_m();
    y_out = 2;  // longitude
    z_out = 1;  // latitude
  } else if (dynamic_cast<const dynamics::HcwModel*>(&model) == nullptr) {
    throw std::invalid_argument("terminal station-keeping sets need an HCW or GEO model, got " +
                                std::string(model.name()));
  }
  *eps_y = *eps_z = -1.0;
  for (size_t k = 0; k < outputs.size(); ++k) {
    if (outputs[k] == y_out) *eps_y = scale * half_widths[k];
    if (outputs[k] == z_out) *eps_z = scale * half_widths[k];
  }
  if (*eps_y <= 0.0 || *eps_z <= 0.0) {
    throw std::invalid_argument(
        "terminal station-keeping sets need a window on both the along-track and the normal "
        "output (HCW: y and z; GEO: longitude and latitude)");
  }
}

}  // namespace thrustsched::transcription
