// Gaussian collision-risk arithmetic for the keep-out constraints and their
// verification (Serra 2015, ch. 2.3 and ch. 4): the instantaneous collision
// probability of a Gaussian relative position with a ball, the normal
// quantile that turns a chance constraint into a deterministic margin, the
// repair of a covariance that is not positive semi-definite, and a portable
// Gaussian sampler.
//
//   Eigen::Vector3d mu(5.0, 0.0, 0.0);                  // mean relative position, m
//   Eigen::Matrix3d sigma = Eigen::Matrix3d::Identity() * 100.0;   // m^2
//   double p = transcription::BallProbability(mu, sigma, 15.0);   // P(|r| <= 15 m)
//   double k = transcription::NormalQuantile(1.0 - 1e-9);          // 5.9978...
//   transcription::GaussianSampler g(/*seed=*/1);
//   double z = g.Next();                                           // N(0, 1)
//
// Pure functions, thread-safe; no dependency on the MILP or the dynamics.
#ifndef THRUSTSCHED_TRANSCRIPTION_COLLISION_PROBABILITY_H_
#define THRUSTSCHED_TRANSCRIPTION_COLLISION_PROBABILITY_H_

#include <cstdint>
#include <random>

#include <Eigen/Core>

namespace thrustsched::transcription {

/// P(|r| <= radius) for r ~ N(mean, covariance) in R^3: the instantaneous
/// collision probability of Serra 2015 (4.7). Computed, not sampled: in the
/// eigen-axes of the covariance the innermost integral is an error-function
/// difference and the two outer ones are adaptive Gauss-Kronrod quadratures
/// (relative accuracy ~1e-9, also in the far tail: 1e-30 is resolved).
/// Zero eigenvalues (after clipping tiny negative ones) are handled as
/// degenerate directions.
/// @throws std::invalid_argument if an input is not finite, radius <= 0, the
///         covariance is not symmetric (1e-9 relative) or has an eigenvalue
///         below -1e-9 of its largest.
double BallProbability(const Eigen::Vector3d& mean, const Eigen::Matrix3d& covariance,
                       double radius);

/// P(Z <= z) for Z ~ N(0, 1), with the upper tail computed by erfc (no
/// cancellation far in either tail).
double NormalCdf(double z);
/// Inverse of NormalCdf: Acklam's rational approximation refined by one
/// Halley step (relative accuracy ~1e-15 in (1e-300, 1 - 1e-16)).
/// @throws std::invalid_argument unless 0 < p < 1.
double NormalQuantile(double p);
/// Same for the upper tail: NormalQuantile(1 - q) without forming 1 - q, so
/// q = 1e-9 keeps all its digits. @throws std::invalid_argument unless 0 < q < 1.
double NormalUpperQuantile(double q);

/// Symmetric part of `covariance` with its negative eigenvalues set to zero
/// (the nearest positive semi-definite matrix in the Frobenius norm).
/// `min_eigenvalue`, if non-null, receives the smallest eigenvalue before
/// clipping. @throws std::invalid_argument if not square or not finite.
Eigen::MatrixXd ClipToPositiveSemidefinite(const Eigen::MatrixXd& covariance,
                                           double* min_eigenvalue = nullptr);

/// A square-root factor L (L L^T = covariance) of a positive semi-definite
/// matrix, from its eigen-decomposition (works when the matrix is singular).
/// @throws std::invalid_argument if an eigenvalue is below -1e-12 of the largest.
Eigen::MatrixXd CovarianceFactor(const Eigen::MatrixXd& covariance);

/// Distance from the origin to the segment [a, b] (the closest approach of a
/// relative position moving linearly from a to b).
double SegmentDistanceToOrigin(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

/// Standard normal numbers from a 64-bit Mersenne twister by the Marsaglia
/// polar method: the same sequence on every platform and standard library
/// (std::normal_distribution is implementation-defined).
class GaussianSampler {
 public:
  explicit GaussianSampler(std::uint64_t seed) : engine_(seed) {}
  double Next();

 private:
  double Uniform();  // in (-1, 1)
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_COLLISION_PROBABILITY_H_
