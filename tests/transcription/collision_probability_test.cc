// Instantaneous collision probability and its helpers, against independent
// references: the closed forms of the isotropic Gaussian in a ball (centred:
// chi distribution with 3 degrees of freedom; offset: derived below), the 2-D
// Rayleigh law for a degenerate covariance, Serra 2015 Tables 2.6-2.8
// (data/reference/serra_avoidance.json, 3 printed digits), and the standard
// normal quantile at textbook points.
#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>

#include "transcription/collision_probability.h"

namespace thrustsched::transcription {
namespace {

constexpr double kPi = 3.14159265358979323846;

// P(|r| <= R), r ~ N(d e1, s^2 I): integrating the offset Gaussian over
// spheres of radius rho gives (1/2)[erf((R-d)/(s sqrt2)) + erf((R+d)/(s sqrt2))]
// - s/(d sqrt(2 pi)) [exp(-(R-d)^2/(2 s^2)) - exp(-(R+d)^2/(2 s^2))].
double IsotropicOffset(double s, double radius, double d) {
  if (d == 0.0) {
    const double a = radius / s;
    return std::erf(a / std::sqrt(2.0)) - std::sqrt(2.0 / kPi) * a * std::exp(-0.5 * a * a);
  }
  const double r2 = std::sqrt(2.0) * s;
  // erfc for d > R: erf(R-d) + erf(R+d) would cancel to 1e-16 in the far tail.
  const double shell = d > radius
                           ? 0.5 * (std::erfc((d - radius) / r2) - std::erfc((d + radius) / r2))
                           : 0.5 * (std::erf((radius - d) / r2) + std::erf((radius + d) / r2));
  return shell - s / (d * std::sqrt(2.0 * kPi)) *
                     (std::exp(-(radius - d) * (radius - d) / (2 * s * s)) -
                      std::exp(-(radius + d) * (radius + d) / (2 * s * s)));
}

Eigen::Matrix3d Diag(double a, double b, double c) {
  return Eigen::Vector3d(a * a, b * b, c * c).asDiagonal();
}

TEST(BallProbabilityTest, IsotropicClosedForms) {
  for (double radius : {0.1, 1.0, 3.0, 15.0}) {
    for (double d : {0.0, 0.5, 2.0, 7.0}) {
      const double ref = IsotropicOffset(2.0, radius, d);
      // Any direction of the offset, any rotation of the (isotropic) covariance.
      const Eigen::Vector3d mu = d * Eigen::Vector3d(1, -2, 2).normalized();
      EXPECT_NEAR(BallProbability(mu, Diag(2, 2, 2), radius), ref, 1e-9 * ref + 1e-15)
          << "R " << radius << " d " << d;
    }
  }
}

// Far tail: a relative accuracy that a sampled estimate could never give.
TEST(BallProbabilityTest, FarTailKeepsRelativeAccuracy) {
  const double ref = IsotropicOffset(1.0, 1.0, 10.0);  // ~1.01e-20 (Serra Table 2.7)
  EXPECT_NEAR(BallProbability(Eigen::Vector3d(0, 10, 0), Diag(1, 1, 1), 1.0), ref, 1e-6 * ref);
  const double far = IsotropicOffset(1.0, 1.0, 13.0);  // ~1e-34
  ASSERT_GT(far, 0.0);
  EXPECT_NEAR(BallProbability(Eigen::Vector3d(0, 0, -13), Diag(1, 1, 1), 1.0), far, 1e-6 * far);
}

// A zero variance: the Gaussian lives in the plane, and for a centred mean
// the probability is the 2-D Rayleigh law 1 - exp(-R^2 / (2 s^2)).
TEST(BallProbabilityTest, DegenerateCovarianceIsPlanar) {
  for (double radius : {0.5, 2.0, 5.0}) {
    const double ref = 1.0 - std::exp(-radius * radius / 8.0);
    EXPECT_NEAR(BallProbability(Eigen::Vector3d::Zero(), Diag(2, 2, 0), radius), ref, 1e-9);
  }
  // Mean outside the ball along the degenerate axis: impossible.
  EXPECT_EQ(BallProbability(Eigen::Vector3d(0, 0, 3), Diag(2, 2, 0), 2.0), 0.0);
}

TEST(BallProbabilityTest, SerraTables26To28) {
  std::ifstream in(std::string(THRUSTSCHED_DATA_DIR) + "/reference/serra_avoidance.json");
  ASSERT_TRUE(in);
  const nlohmann::json ref = nlohmann::json::parse(in).at("ball_probability");
  int rows = 0;
  for (const char* table : {"table_2_6", "table_2_7", "table_2_8"}) {
    for (const auto& r : ref.at(table)) {
      const Eigen::Matrix3d cov = Diag(r[0], r[1], r[2]);
      const Eigen::Vector3d mu(r[4], r[5], r[6]);
      const double p = BallProbability(mu, cov, r[3]);
      const double published = r[7];
      // Three printed digits: half a unit of the third is <= 0.5 % of the value.
      EXPECT_NEAR(p, published, 0.005 * published + 1e-15) << table << " " << r.dump();
      ++rows;
    }
  }
  EXPECT_EQ(rows, 26);
}

TEST(BallProbabilityTest, RejectsBadInput) {
  EXPECT_THROW(BallProbability(Eigen::Vector3d::Zero(), Diag(1, 1, 1), 0.0), std::invalid_argument);
  Eigen::Matrix3d asym = Diag(1, 1, 1);
  asym(0, 1) = 0.5;
  EXPECT_THROW(BallProbability(Eigen::Vector3d::Zero(), asym, 1.0), std::invalid_argument);
  EXPECT_THROW(BallProbability(Eigen::Vector3d::Zero(), -Diag(1, 1, 1), 1.0),
               std::invalid_argument);
  EXPECT_THROW(BallProbability(Eigen::Vector3d(NAN, 0, 0), Diag(1, 1, 1), 1.0),
               std::invalid_argument);
}

TEST(NormalQuantileTest, TextbookValuesAndRoundTrip) {
  EXPECT_NEAR(NormalQuantile(0.975), 1.959963984540054, 1e-13);
  EXPECT_NEAR(NormalQuantile(0.5), 0.0, 1e-15);
  EXPECT_NEAR(NormalQuantile(0.001), -3.090232306167814, 1e-12);
  // eps' of Serra 2015 Example 1: keep every digit of 1e-9.
  const double k = NormalUpperQuantile(1e-9);
  EXPECT_NEAR(0.5 * std::erfc(k / std::sqrt(2.0)), 1e-9, 1e-22);
  EXPECT_NEAR(k, 5.997807015007686, 1e-10);
  for (double p : {1e-300, 1e-30, 1e-9, 0.01, 0.3}) {
    EXPECT_NEAR(NormalCdf(NormalQuantile(p)), p, 1e-13 * p) << p;
    EXPECT_NEAR(NormalUpperQuantile(p), -NormalQuantile(p), 1e-12 * std::abs(NormalQuantile(p)));
  }
  EXPECT_THROW(NormalQuantile(0.0), std::invalid_argument);
  EXPECT_THROW(NormalUpperQuantile(1.0), std::invalid_argument);
}

TEST(CovarianceRepairTest, ClipsOnlyNegativeEigenvalues) {
  Eigen::Matrix2d m;
  m << 0.0, 1.5e-6, 1.5e-6, 5e-10;  // Serra (4.22)'s out-of-plane block: indefinite
  double low = 0.0;
  const Eigen::MatrixXd c = ClipToPositiveSemidefinite(m, &low);
  EXPECT_LT(low, 0.0);
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(c).eigenvalues().minCoeff(), -1e-20);
  // A positive semi-definite matrix is returned unchanged.
  Eigen::Matrix3d spd;
  spd << 4, 1, 0, 1, 3, 1, 0, 1, 2;
  EXPECT_LT((ClipToPositiveSemidefinite(spd) - spd).norm(), 1e-12);
  const Eigen::MatrixXd l = CovarianceFactor(spd);
  EXPECT_LT((l * l.transpose() - spd).norm(), 1e-12);
  EXPECT_THROW(CovarianceFactor(-spd), std::invalid_argument);
}

TEST(GaussianSamplerTest, MomentsAndDeterminism) {
  GaussianSampler a(7), b(7);
  double sum = 0.0, sum2 = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double z = a.Next();
    ASSERT_EQ(z, b.Next());
    sum += z;
    sum2 += z * z;
  }
  EXPECT_NEAR(sum / n, 0.0, 4.0 / std::sqrt(n));
  EXPECT_NEAR(sum2 / n, 1.0, 4.0 * std::sqrt(2.0 / n));
}

}  // namespace
}  // namespace thrustsched::transcription
