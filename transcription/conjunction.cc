#include "transcription/conjunction.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "common/error.h"
#include "common/format.h"
#include "transcription/collision_probability.h"

namespace thrustsched::transcription {

using common::Fail;

namespace {

using common::FormatG;

}  // namespace

std::string_view ToString(CovarianceRepair repair) {
  return repair == CovarianceRepair::kNone ? "none" : "clip_eigenvalues";
}

CovarianceRepair ParseCovarianceRepair(std::string_view name) {
  if (name == "none") return CovarianceRepair::kNone;
  if (name == "clip_eigenvalues") return CovarianceRepair::kClipEigenvalues;
  throw std::invalid_argument("covariance repair: unknown name \"" + std::string(name) +
                              "\" (expected none or clip_eigenvalues)");
}

KeepOutPolytope KeepOutPolytope::Cube(double radius_m) {
  KeepOutPolytope p;
  p.faces = Eigen::MatrixXd::Zero(6, 3);
  p.offsets = Eigen::VectorXd::Constant(6, radius_m);
  for (int i = 0; i < 3; ++i) {
    p.faces(2 * i, i) = 1.0;
    p.faces(2 * i + 1, i) = -1.0;
  }
  return p;
}

bool KeepOutPolytope::ContainsBall(double radius_m) const {
  for (int j = 0; j < size(); ++j) {
    const double norm = faces.row(j).norm();
    if (!(norm > 0.0) || offsets[j] < radius_m * norm * (1.0 - 1e-12)) return false;
  }
  return size() > 0;
}

KeepOutPolytope ConjunctionSpec::EffectivePolytope() const {
  return polytope.size() == 0 ? KeepOutPolytope::Cube(radius_m) : polytope;
}

std::vector<double> ConjunctionSpec::CheckTimes(double horizon_start_s,
                                                double horizon_end_s) const {
  const double a = std::isnan(check_start_s) ? horizon_start_s : check_start_s;
  const double b = std::isnan(check_end_s) ? horizon_end_s : check_end_s;
  std::vector<double> t(num_checks);
  for (int k = 0; k < num_checks; ++k) t[k] = a + (b - a) * (k + 1) / (num_checks + 1);
  return t;
}

bool ConjunctionSpec::IsValid(std::string* error) const {
  if (secondary_state.size() != 6 || !secondary_state.allFinite()) {
    return Fail(error, "conjunction.secondary_state must be 6 finite numbers (m, m/s)");
  }
  if (!std::isfinite(state_time_s)) return Fail(error, "conjunction.state_time_s must be finite");
  if (covariance.rows() != 6 || covariance.cols() != 6 || !covariance.allFinite()) {
    return Fail(error, "conjunction.covariance must be a finite 6 x 6 matrix");
  }
  const double big = covariance.cwiseAbs().maxCoeff();
  const double asym = (covariance - covariance.transpose()).cwiseAbs().maxCoeff();
  if (asym > 1e-12 * big) {
    return Fail(error, "conjunction.covariance is not symmetric (largest |S_ij - S_ji| = " +
                           FormatG(asym, 10) + ")");
  }
  for (int i = 0; i < 6; ++i) {
    if (covariance(i, i) < 0.0) {
      return Fail(error, "conjunction.covariance has a negative variance " +
                             FormatG(covariance(i, i), 10) + " on the diagonal (entry " +
                             std::to_string(i) + ")");
    }
  }
  if (repair == CovarianceRepair::kNone) {
    const Eigen::VectorXd ev =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(covariance).eigenvalues();
    const double low = ev.minCoeff();
    if (low < -1e-12 * ev.maxCoeff()) {
      return Fail(error,
                  "conjunction.covariance is not positive semi-definite (smallest eigenvalue " +
                      FormatG(low, 10) +
                      "); give covariance_repair \"clip_eigenvalues\" to repair it");
    }
  }
  if (!(radius_m > 0.0) || !std::isfinite(radius_m)) {
    return Fail(error, "conjunction.radius_m must be finite and > 0, got " + FormatG(radius_m, 10));
  }
  if (!(instantaneous_threshold > 0.0 && instantaneous_threshold < 0.5)) {
    return Fail(error, "conjunction.instantaneous_threshold must be in (0, 0.5), got " +
                           FormatG(instantaneous_threshold, 10));
  }
  if (num_checks < 1) {
    return Fail(error, "conjunction.num_checks must be >= 1, got " + std::to_string(num_checks));
  }
  if (std::isinf(check_start_s) || std::isinf(check_end_s)) {
    return Fail(error, "conjunction check window bounds must be finite");
  }
  if (!std::isnan(check_start_s) && !std::isnan(check_end_s) && !(check_end_s > check_start_s)) {
    return Fail(error, "conjunction.check_end_s (" + FormatG(check_end_s, 10) +
                           ") must be after check_start_s (" + FormatG(check_start_s, 10) + ")");
  }
  if (polytope.size() > 0) {
    if (polytope.faces.rows() != polytope.size() || polytope.faces.cols() != 3 ||
        !polytope.faces.allFinite() || !polytope.offsets.allFinite()) {
      return Fail(error,
                  "conjunction.polytope needs m x 3 finite face normals and m finite offsets");
    }
    if (!polytope.ContainsBall(radius_m)) {
      return Fail(error, "conjunction.polytope does not contain the ball of radius " +
                             FormatG(radius_m, 10) + " m (every face needs b_j >= R |a_j|)");
    }
  }
  if (std::isnan(cost_budget) || cost_budget <= 0.0) {
    return Fail(error, "conjunction.cost_budget must be > 0, got " + FormatG(cost_budget, 10));
  }
  return true;
}

Eigen::MatrixXd EffectiveCovariance(const ConjunctionSpec& spec, double time_scale_s,
                                    double* min_eigenvalue) {
  if (!(time_scale_s > 0.0) || !std::isfinite(time_scale_s)) {
    throw std::invalid_argument("EffectiveCovariance: time scale must be finite and > 0, got " +
                                FormatG(time_scale_s, 10));
  }
  Eigen::VectorXd d = Eigen::VectorXd::Ones(spec.covariance.rows());
  d.tail(d.size() / 2).setConstant(time_scale_s);
  const Eigen::MatrixXd scaled =
      d.asDiagonal() * (0.5 * (spec.covariance + spec.covariance.transpose())) * d.asDiagonal();
  double low = 0.0;
  const Eigen::MatrixXd clipped = ClipToPositiveSemidefinite(scaled, &low);
  if (min_eigenvalue != nullptr) *min_eigenvalue = low;
  const Eigen::VectorXd inv = d.cwiseInverse();
  const Eigen::MatrixXd& use = spec.repair == CovarianceRepair::kClipEigenvalues ? clipped : scaled;
  return inv.asDiagonal() * use * inv.asDiagonal();
}

Eigen::Matrix3d SerraLvlhToLocal() {
  // Local x (radial out) = -z_S, y (along-track) = x_S, z (normal, +h) = -y_S.
  Eigen::Matrix3d m;
  m << 0, 0, -1, 1, 0, 0, 0, -1, 0;
  return m;
}

double InstantaneousThreshold(double risk, double encounter_s, double t0_s) {
  if (!(risk > 0.0 && risk < 1.0)) {
    throw std::invalid_argument("risk threshold must be in (0, 1), got " + FormatG(risk, 10));
  }
  if (!(encounter_s > 0.0) || !std::isfinite(encounter_s) || !(t0_s > 0.0) ||
      !std::isfinite(t0_s)) {
    throw std::invalid_argument("encounter duration and T0 must be finite and > 0");
  }
  return t0_s * risk / encounter_s;
}

}  // namespace thrustsched::transcription
