// ConjunctionSpec: a secondary object to keep out of, as chance constraints
// on the primary's mean trajectory (Serra 2015, ch. 4, Problem 10).
//
//   transcription::ConjunctionSpec c;
//   c.secondary_state << -3.99, -2295.60, -388.17, ...;  // local frame, m and m/s
//   c.state_time_s = -50000;                             // at which the state holds
//   c.covariance = sigma;                                // 6 x 6 relative state, SI
//   c.radius_m = 15;                                     // combined radius
//   c.instantaneous_threshold = 1e-9;                    // epsilon'
//   c.num_checks = 500;                                  // check grid in ]start, end[
//   c.cost_budget = 0.01;                                // objective units: bounds big-M
//   problem.conjunction = c;                             // ScheduleMilp adds the rows
//
// Frame: the model's local Cartesian frame of transcription/terminal_sets.h
// (HcwCoordinates): x radial outward, y along-track, z orbit normal (m, m/s,
// velocities relative to the rotating frame). Serra's LVLH frame (z to the
// Earth, y against the angular momentum, x = y cross z) maps onto it with
// SerraLvlhToLocal().
//
// The chance constraint P(|r_p - r_s| <= R) <= eps' at each check time t_k is
// replaced (Serra 2015 (4.10)-(4.19)) by "outside at least one face of a
// polytope covering the ball, with margin": a_j^T mu_R(t_k) >= b_j + c_jk,
// c_jk = sqrt(a_j^T Sigma_R(t_k) a_j) Phi^-1(1 - eps'), where mu_R is the mean
// relative position (primary minus secondary) and Sigma_R its covariance
// (independent of the control). eps' = T0 eps / (t_hi - t_lo) with T0 = 1 s
// (Serra 2015 sec. 4.2.1) is InstantaneousThreshold().
#ifndef THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_H_
#define THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_H_

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace thrustsched::transcription {

/// What to do with a covariance that is not positive semi-definite (the
/// printed covariances of Serra 2015 (4.21)-(4.23) are not, by rounding).
enum class CovarianceRepair {
  kNone,             // reject it (a negative eigenvalue makes sqrt(a^T Sigma a) imaginary)
  kClipEigenvalues,  // set its negative eigenvalues to zero (EffectiveCovariance)
};
std::string_view ToString(CovarianceRepair repair);
/// "none" | "clip_eigenvalues". @throws std::invalid_argument listing them.
CovarianceRepair ParseCovarianceRepair(std::string_view name);

/// Polytope {r : a_j^T r <= b_j, j = 1..m} containing the keep-out ball.
struct KeepOutPolytope {
  Eigen::MatrixXd faces;    // m x 3, outward normals a_j (any length)
  Eigen::VectorXd offsets;  // m, b_j (m)
  int size() const { return static_cast<int>(offsets.size()); }
  /// The axis-aligned cube with faces tangent to the ball (Serra 2015
  /// sec. 4.4): a = +-e_i, b = radius.
  static KeepOutPolytope Cube(double radius_m);
  /// True if the ball of `radius_m` about the origin lies inside (every
  /// face at distance b_j / |a_j| >= radius).
  bool ContainsBall(double radius_m) const;
};

struct ConjunctionSpec {
  /// Mean state of the secondary object (local frame, m, m/s) at state_time_s.
  Eigen::VectorXd secondary_state;
  /// Seconds since the model epoch; must lie in the horizon (the state is
  /// propagated forward and backward with the problem's model).
  double state_time_s = 0.0;
  /// Covariance (6 x 6, local frame, SI) of the relative state primary minus
  /// secondary at state_time_s: the sum of both objects' covariances.
  Eigen::MatrixXd covariance;
  CovarianceRepair repair = CovarianceRepair::kNone;
  double radius_m = 0.0;                 // combined radius R
  double instantaneous_threshold = 0.0;  // eps' in (0, 0.5)
  /// Check grid: num_checks uniform times strictly inside [check_start_s,
  /// check_end_s] (t_k = start + k (end - start) / (num_checks + 1)); NaN =
  /// the horizon's start / end.
  int num_checks = 0;
  double check_start_s = std::numeric_limits<double>::quiet_NaN();
  double check_end_s = std::numeric_limits<double>::quiet_NaN();
  /// Empty: the cube of radius_m.
  KeepOutPolytope polytope;
  /// Upper bound on the objective (the model's own units), added as one row;
  /// it bounds the reachable positions from which every big-M is derived.
  /// Infinite: only allowed if every thrust column has a finite upper bound
  /// (on-off binaries, or a finite impulse bound). An optimum strictly below
  /// the budget is an optimum of the problem without it.
  double cost_budget = std::numeric_limits<double>::infinity();

  /// The cube if `polytope` is empty, else `polytope`.
  KeepOutPolytope EffectivePolytope() const;
  /// Check times in the window [start, end] (the horizon where NaN).
  std::vector<double> CheckTimes(double horizon_start_s, double horizon_end_s) const;
  /// Sizes, finiteness, ranges, symmetry of the covariance and, unless
  /// repaired, its positive semi-definiteness; the polytope must contain the
  /// ball. Fills *error naming the field and the value.
  bool IsValid(std::string* error) const;
};

/// The covariance the keep-out rows and the verification use: the symmetric
/// part of spec.covariance, and with kClipEigenvalues its negative
/// eigenvalues set to zero in nondimensional units, velocities multiplied by
/// `time_scale_s` (the model's 1/n), so that position and velocity entries
/// weigh alike. Clipping in SI units would not: m^2/s^2 entries are ~1e-6 of
/// the m^2 ones, and the repair of Serra 2015 (4.22) would then multiply an
/// out-of-plane velocity deviation by 40 instead of changing var(y) by
/// 0.004 m^2, below its printed resolution. `min_eigenvalue`, if non-null,
/// receives the smallest eigenvalue before clipping, in those units (m^2).
/// @throws std::invalid_argument if time_scale_s is not finite and > 0.
Eigen::MatrixXd EffectiveCovariance(const ConjunctionSpec& spec, double time_scale_s,
                                    double* min_eigenvalue = nullptr);

/// Serra's LVLH axes (x along-track, y = -angular momentum, z = nadir) to the
/// local frame (x radial outward, y along-track, z normal): local = M serra.
Eigen::Matrix3d SerraLvlhToLocal();
/// eps' = t0_s * risk / encounter_s (Serra 2015 sec. 4.2.1, T0 = 1 s).
/// @throws std::invalid_argument unless risk in (0, 1) and the durations are > 0.
double InstantaneousThreshold(double risk, double encounter_s, double t0_s = 1.0);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_H_
