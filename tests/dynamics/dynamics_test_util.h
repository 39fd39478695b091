// Shared helpers for the dynamics core tests (models, discretisation, propagation).
#ifndef THRUSTSCHED_TESTS_DYNAMICS_DYNAMICS_TEST_UTIL_H_
#define THRUSTSCHED_TESTS_DYNAMICS_DYNAMICS_TEST_UTIL_H_

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

namespace thrustsched::dynamics::testing_util {

/// GEO mean motion used throughout (rad/s).
constexpr double kGeoMeanMotion = 7.2921159e-5;

/// Normwise relative error max|got - ref| / max|ref|, both first made
/// nondimensional: rows divided by row_scale, columns multiplied by col_scale
/// (pass ones for a side that has no scaling).
inline double ScaledRelError(const Eigen::MatrixXd& ref, const Eigen::MatrixXd& got,
                             const Eigen::VectorXd& row_scale, const Eigen::VectorXd& col_scale) {
  const Eigen::MatrixXd r = row_scale.cwiseInverse().asDiagonal() * ref * col_scale.asDiagonal();
  const Eigen::MatrixXd g = row_scale.cwiseInverse().asDiagonal() * got * col_scale.asDiagonal();
  const double denom = r.cwiseAbs().maxCoeff();
  return (r - g).cwiseAbs().maxCoeff() / (denom > 0.0 ? denom : 1.0);
}

/// Phi-type matrix (n x n) in nondimensional form S^-1 Phi S.
inline double PhiRelError(const Eigen::MatrixXd& ref, const Eigen::MatrixXd& got,
                          const Eigen::VectorXd& state_scale) {
  return ScaledRelError(ref, got, state_scale, state_scale);
}

/// Gamma-type matrix (n x m) or vector in nondimensional form S^-1 Gamma.
inline double ColumnRelError(const Eigen::MatrixXd& ref, const Eigen::MatrixXd& got,
                             const Eigen::VectorXd& state_scale) {
  return ScaledRelError(ref, got, state_scale, Eigen::VectorXd::Ones(ref.cols()));
}

}  // namespace thrustsched::dynamics::testing_util

#endif  // THRUSTSCHED_TESTS_DYNAMICS_DYNAMICS_TEST_UTIL_H_
