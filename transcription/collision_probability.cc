#include "transcription/collision_probability.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Eigenvalues>

#include "common/constants.h"
#include "common/format.h"

namespace thrustsched::transcription {
namespace {

using common::FormatG;
using common::kPi;
constexpr double kSqrt2 = 1.41421356237309504880;

// Gauss-Kronrod 7-15 nodes (positive half) and weights.
constexpr std::array<double, 8> kXk = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
constexpr std::array<double, 8> kWk = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> kWg = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

// One Gauss-Kronrod 7-15 rule on [a, b]: the Kronrod value and |K - G|.
template <typename F>
std::pair<double, double> Rule(const F& f, double a, double b) {
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  const double fc = f(c);
  double k = kWk[7] * fc, g = kWg[3] * fc;
  for (int i = 0; i < 7; ++i) {
    const double x = h * kXk[i];
    const double s = f(c - x) + f(c + x);
    k += kWk[i] * s;
    if (i % 2 == 1) g += kWg[i / 2] * s;
  }
  return {k * h, std::abs(k - g) * h};
}

// Globally adaptive quadrature over [a, b] split at `breaks`: the piece with
// the largest error estimate is bisected until the total error is below
// `rel` times the integral (or 1e-300), with at most kMaxPieces pieces, so
// that the cost stays bounded whatever the integrand.
template <typename F>
double Integrate(const F& f, double a, double b, std::vector<double> breaks, double rel) {
  constexpr int kMaxPieces = 64;
  struct Piece {
    double a, b, value, error;
  };
  breaks.push_back(a);
  breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  std::vector<Piece> pieces;
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    const auto [v, e] = Rule(f, breaks[i], breaks[i + 1]);
    pieces.push_back({breaks[i], breaks[i + 1], v, e});
  }
  while (true) {
    double value = 0.0, error = 0.0;
    size_t worst = 0;
    for (size_t i = 0; i < pieces.size(); ++i) {
      value += pieces[i].value;
      error += pieces[i].error;
      if (pieces[i].error > pieces[worst].error) worst = i;
    }
    if (error <= rel * std::abs(value) || error <= 1e-300 || pieces.size() >= kMaxPieces)
      return value;
    const Piece w = pieces[worst];
    const double mid = 0.5 * (w.a + w.b);
    const auto [v1, e1] = Rule(f, w.a, mid);
    const auto [v2, e2] = Rule(f, mid, w.b);
    pieces[worst] = {w.a, mid, v1, e1};
    pieces.push_back({mid, w.b, v2, e2});
  }
}

// P(|Y| <= h) for Y ~ N(mu, sigma^2), from the tail on the far side so that
// far-tail values keep their relative accuracy.
double CentralInterval(double mu, double sigma, double h) {
  if (h <= 0.0) return 0.0;
  if (sigma <= 0.0) return std::abs(mu) <= h ? 1.0 : 0.0;
  const double hi = (h - mu) / sigma, lo = (-h - mu) / sigma;
  auto upper = [](double z) { return 0.5 * std::erfc(z / kSqrt2); };
  if (lo > 0.0) return upper(lo) - upper(hi);
  if (hi < 0.0) return upper(-hi) - upper(-lo);
  return 1.0 - upper(hi) - upper(-lo);
}

double GaussianDensity(double y, double mu, double sigma) {
  const double z = (y - mu) / sigma;
  return std::exp(-0.5 * z * z) / (std::sqrt(2.0 * kPi) * sigma);
}

// Angles theta = asin(y / half_width) of the points mu + k sigma inside the
// interval (they locate the peak of the Gaussian factor for the quadrature).
std::vector<double> PeakBreaks(double mu, double sigma, double half_width) {
  std::vector<double> out;
  for (double k : {-8.0, -4.0, -2.0, -1.0, 0.0, 1.0, 2.0, 4.0, 8.0}) {
    const double y = (mu + k * sigma) / half_width;
    if (y > -1.0 && y < 1.0) out.push_back(std::asin(y));
  }
  return out;
}

constexpr double kRelTol = 1e-10;

// Integral over the disk y1^2 + y2^2 <= rr^2 of N(y1) N(y2) F3(sqrt(rr^2 - |y|^2)),
// with the substitutions y1 = rr sin t1, y2 = h2 sin t2 (smooth at the rim).
double DiskIntegral(const Eigen::Vector3d& nu, const Eigen::Vector3d& sd, double rr) {
  auto inner = [&](double h2) {
    if (h2 <= 0.0) return 0.0;
    if (sd[1] <= 0.0) {
      const double y2 = nu[1];
      return std::abs(y2) < h2 ? CentralInterval(nu[2], sd[2], std::sqrt(h2 * h2 - y2 * y2)) : 0.0;
    }
    auto f2 = [&](double t2) {
      const double y2 = h2 * std::sin(t2), h3 = h2 * std::cos(t2);
      return GaussianDensity(y2, nu[1], sd[1]) * CentralInterval(nu[2], sd[2], h3) * h2 *
             std::cos(t2);
    };
    return Integrate(f2, -0.5 * kPi, 0.5 * kPi, PeakBreaks(nu[1], sd[1], h2), kRelTol);
  };
  if (sd[0] <= 0.0) {
    return std::abs(nu[0]) < rr ? inner(std::sqrt(rr * rr - nu[0] * nu[0])) : 0.0;
  }
  auto f1 = [&](double t1) {
    const double y1 = rr * std::sin(t1), h2 = rr * std::cos(t1);
    return GaussianDensity(y1, nu[0], sd[0]) * inner(h2) * rr * std::cos(t1);
  };
  return Integrate(f1, -0.5 * kPi, 0.5 * kPi, PeakBreaks(nu[0], sd[0], rr), kRelTol);
}

}  // namespace

double BallProbability(const Eigen::Vector3d& mean, const Eigen::Matrix3d& covariance,
                       double radius) {
  if (!mean.allFinite() || !covariance.allFinite() || !std::isfinite(radius)) {
    throw std::invalid_argument("BallProbability: mean, covariance and radius must be finite");
  }
  if (radius <= 0.0)
    throw std::invalid_argument("BallProbability: radius must be > 0, got " + FormatG(radius, 10));
  const double big = covariance.cwiseAbs().maxCoeff();
  if ((covariance - covariance.transpose()).cwiseAbs().maxCoeff() > 1e-9 * std::max(big, 1e-300)) {
    throw std::invalid_argument("BallProbability: the covariance is not symmetric");
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 *
                                                           (covariance + covariance.transpose()));
  const Eigen::Vector3d lambda = eig.eigenvalues();  // ascending
  if (lambda[0] < -1e-9 * std::max(lambda[2], 1e-300)) {
    throw std::invalid_argument("BallProbability: the covariance has a negative eigenvalue " +
                                FormatG(lambda[0], 10));
  }
  // Largest variance outermost, smallest innermost (handled by erfc): the
  // narrowest Gaussian factor is never a quadrature variable.
  Eigen::Vector3d sd, nu;
  for (int i = 0; i < 3; ++i) {
    const int k = 2 - i;
    // A standard deviation below 1e-7 R is a degenerate direction: the
    // Gaussian factor acts as a point mass (relative error ~1e-7).
    const double var = lambda[k] <= 1e-14 * radius * radius ? 0.0 : lambda[k];
    sd[i] = std::sqrt(var);
    nu[i] = eig.eigenvectors().col(k).dot(mean);
  }
  return std::clamp(DiskIntegral(nu, sd, radius), 0.0, 1.0);
}

double NormalCdf(double z) { return 0.5 * std::erfc(-z / kSqrt2); }

namespace {

// Acklam's approximation of the lower-half quantile (p <= 0.5), refined by
// one Halley step on NormalCdf, which is accurate there.
double LowerQuantile(double p) {
  static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                             1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                             6.680131188771972e+01, -1.328068155288572e+01};
  static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                             -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                             3.754408661907416e+00};
  double x;
  if (p < 0.02425) {
    const double q = std::sqrt(-2.0 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  } else {
    const double q = p - 0.5, r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  }
  const double e = NormalCdf(x) - p;
  const double u = e * std::sqrt(2.0 * kPi) * std::exp(0.5 * x * x);
  return x - u / (1.0 + 0.5 * x * u);
}

}  // namespace

double NormalQuantile(double p) {
  if (!(p > 0.0 && p < 1.0))
    throw std::invalid_argument("NormalQuantile: p must be in (0, 1), got " + FormatG(p, 10));
  return p <= 0.5 ? LowerQuantile(p) : -LowerQuantile(1.0 - p);
}

double NormalUpperQuantile(double q) {
  if (!(q > 0.0 && q < 1.0)) {
    throw std::invalid_argument("NormalUpperQuantile: q must be in (0, 1), got " + FormatG(q, 10));
  }
  return q <= 0.5 ? -LowerQuantile(q) : LowerQuantile(1.0 - q);
}

Eigen::MatrixXd ClipToPositiveSemidefinite(const Eigen::MatrixXd& covariance,
                                           double* min_eigenvalue) {
  if (covariance.rows() != covariance.cols() || !covariance.allFinite()) {
    throw std::invalid_argument("ClipToPositiveSemidefinite: expected a finite square matrix");
  }
  const Eigen::MatrixXd sym = 0.5 * (covariance + covariance.transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(sym);
  if (min_eigenvalue != nullptr) *min_eigenvalue = eig.eigenvalues().minCoeff();
  const Eigen::VectorXd clipped = eig.eigenvalues().cwiseMax(0.0);
  const Eigen::MatrixXd out =
      eig.eigenvectors() * clipped.asDiagonal() * eig.eigenvectors().transpose();
  return 0.5 * (out + out.transpose());
}

Eigen::MatrixXd CovarianceFactor(const Eigen::MatrixXd& covariance) {
  if (covariance.rows() != covariance.cols() || !covariance.allFinite()) {
    throw std::invalid_argument("CovarianceFactor: expected a finite square matrix");
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 *
                                                           (covariance + covariance.transpose()));
  const Eigen::VectorXd lambda = eig.eigenvalues();
  if (lambda.size() > 0 && lambda.minCoeff() < -1e-12 * std::max(lambda.maxCoeff(), 1e-300)) {
    throw std::invalid_argument("CovarianceFactor: the matrix has a negative eigenvalue " +
                                FormatG(lambda.minCoeff(), 10));
  }
  return eig.eigenvectors() * lambda.cwiseMax(0.0).cwiseSqrt().asDiagonal();
}

double GaussianSampler::Uniform() {
  const double u = static_cast<double>(engine_() >> 11) * (1.0 / 9007199254740992.0);  // [0, 1)
  return 2.0 * u - 1.0;
}

double GaussianSampler::Next() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  double u, v, s;
  do {
    u = Uniform();
    v = Uniform();
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double f = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = v * f;
  has_spare_ = true;
  return u * f;
}

double SegmentDistanceToOrigin(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d v = b - a;
  const double vv = v.squaredNorm();
  const double s = vv > 0.0 ? std::clamp(-a.dot(v) / vv, 0.0, 1.0) : 0.0;
  return (a + s * v).norm();
}

}  // namespace thrustsched::transcription
