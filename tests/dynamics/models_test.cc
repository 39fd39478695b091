// Tests for dynamics/models.h: closed forms against independent references
// (Taylor series in long double, Gauss-Legendre quadrature, the ODE itself,
// adaptive numerical integration, Kepler's equation residual).
#include "dynamics/models.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dynamics/discretisation.h"
#include "tests/dynamics/dynamics_test_util.h"

namespace thrustsched::dynamics {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using testing_util::kGeoMeanMotion;
using testing_util::PhiRelError;

constexpr double kPi = 3.14159265358979323846;

using MatLd = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

// exp(A x) and int_0^x exp(A s) ds B by Taylor series in long double.
void TaylorExp(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double x, Eigen::MatrixXd* phi,
               Eigen::MatrixXd* zoh) {
  const MatLd al = a.cast<long double>();
  const long n = a.rows();
  MatLd term = MatLd::Identity(n, n);  // (A x)^k / k!
  MatLd sum_phi = term;
  MatLd sum_int = term * static_cast<long double>(x);  // A^k x^(k+1) / (k+1)!
  for (int k = 1; k < 80; ++k) {
    term = (al * term) * (static_cast<long double>(x) / k);
    sum_phi += term;
    sum_int += term * (static_cast<long double>(x) / (k + 1));
  }
  *phi = sum_phi.cast<double>();
  *zoh = (sum_int * b.cast<long double>()).cast<double>();
}

// Gauss-Legendre nodes/weights on [-1, 1] by Newton on P_q (long double).
void GaussLegendre(int q, std::vector<long double>* x, std::vector<long double>* w) {
  x->resize(q);
  w->resize(q);
  for (int i = 0; i < q; ++i) {
    long double z = std::cos(kPi * (i + 0.75L) / (q + 0.5L));
    long double dp = 0;
    for (int it = 0; it < 100; ++it) {
      long double p0 = 1, p1 = z;
      for (int k = 2; k <= q; ++k) {
        const long double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = q * (z * p1 - p0) / (z * z - 1);
      const long double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-19L) break;
    }
    (*x)[i] = z;
    (*w)[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

// ------------------------------------------------------------------ double integrators

TEST(DoubleIntegratorTest, Matrices) {
  const DoubleIntegrator1d di(10.0, 2.0);
  const ModelMatrices m = di.Evaluate(3.0);
  EXPECT_TRUE(m.a.isApprox((Eigen::Matrix2d() << 0, 1, 0, 0).finished(), 0.0));
  EXPECT_EQ(m.b, (Eigen::MatrixXd(2, 1) << 0, 1).finished());
  EXPECT_EQ(m.d, Eigen::VectorXd::Zero(2));
  EXPECT_EQ(di.EvaluateOutput(0.0).c, (Eigen::MatrixXd(1, 2) << 1, 0).finished());
  EXPECT_EQ(di.state_scale(), Eigen::Vector2d(2.0, 0.2));
  EXPECT_DOUBLE_EQ(di.time_scale(), 10.0);
  EXPECT_EQ(di.state_names(), (std::vector<std::string>{"x_m", "v_m_s"}));
  EXPECT_TRUE(di.is_time_invariant());

  const DoubleIntegrator3d d3(5.0, 100.0);
  const ModelMatrices m3 = d3.Evaluate(0.0);
  Eigen::MatrixXd a3 = Eigen::MatrixXd::Zero(6, 6);
  a3.topRightCorner(3, 3).setIdentity();
  EXPECT_EQ(m3.a, a3);
  EXPECT_EQ(m3.b.bottomRows(3), Eigen::MatrixXd::Identity(3, 3));
  EXPECT_EQ(m3.b.topRows(3), Eigen::MatrixXd::Zero(3, 3));
  EXPECT_EQ(d3.EvaluateOutput(1.0).c.leftCols(3), Eigen::MatrixXd::Identity(3, 3));
  EXPECT_DOUBLE_EQ(d3.state_scale()[3], 20.0);
  EXPECT_EQ(d3.num_outputs(), 3);
  EXPECT_EQ(d3.output_names().size(), 3u);
}

TEST(DoubleIntegratorTest, RejectsBadInput) {
  EXPECT_THAT([] { DoubleIntegrator1d(0.0); }, ThrowsMessage<std::invalid_argument>(HasSubstr(
                                                   "time_scale_s must be finite and > 0, got 0")));
  EXPECT_THAT([] { DoubleIntegrator1d(1.0, -2.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("length_scale_m")));
  EXPECT_THAT([] { DoubleIntegrator3d(NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("time_scale_s")));
  EXPECT_THAT([] { DoubleIntegrator3d(1.0, 0.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("length_scale_m")));
  EXPECT_THAT([] { DoubleIntegrator1d().Evaluate(NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
  EXPECT_THAT([] { DoubleIntegrator1d().EvaluateOutput(INFINITY); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
  EXPECT_THAT([] { DoubleIntegrator3d().Evaluate(-INFINITY); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
  EXPECT_THAT([] { DoubleIntegrator3d().EvaluateOutput(NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
}

// ------------------------------------------------------------------ HCW

TEST(HcwModelTest, MatricesFollowThesisI3) {
  const double n = kGeoMeanMotion;
  const HcwModel hcw(n, 500.0);
  const ModelMatrices m = hcw.Evaluate(123.0);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6, 6);
  a.topRightCorner(3, 3).setIdentity();
  a(3, 0) = 3 * n * n;
  a(3, 4) = 2 * n;
  a(4, 3) = -2 * n;
  a(5, 2) = -n * n;
  EXPECT_EQ(m.a, a);
  EXPECT_EQ(m.b.bottomRows(3), Eigen::MatrixXd::Identity(3, 3));
  EXPECT_DOUBLE_EQ(hcw.time_scale(), 1.0 / n);
  EXPECT_DOUBLE_EQ(hcw.state_scale()[0], 500.0);
  EXPECT_DOUBLE_EQ(hcw.state_scale()[4], 500.0 * n);
  EXPECT_EQ(hcw.state_names()[4], "vy_m_s");
}

TEST(HcwModelTest, TransitionMatrixEntry51HasTheMeanMotion) {
  // (I.4) prints 6 (c - 1); the correct entry is 6 n (c - 1).
  const double n = kGeoMeanMotion, tau = 5000.0;
  const HcwModel hcw(n);
  const double expected = 6.0 * n * (std::cos(n * tau) - 1.0);
  EXPECT_NEAR(hcw.TransitionMatrix(tau)(4, 0), expected, 1e-12 * std::abs(expected));
}

TEST(HcwModelTest, TransitionMatrixMatchesTaylorSeries) {
  const double n = kGeoMeanMotion;
  const HcwModel hcw(n);
  const Eigen::VectorXd sc = hcw.state_scale();
  const Eigen::MatrixXd a_hat =
      sc.cwiseInverse().asDiagonal() * hcw.Evaluate(0).a * sc.asDiagonal() / n;
  const Eigen::MatrixXd b_hat = sc.cwiseInverse().asDiagonal() * hcw.Evaluate(0).b / n;
  // x = n tau from 1e-7 (cancellation-prone) to 2 (series still exact in long double).
  for (double x : {1e-7, 1e-4, 4.4e-3, 0.0219, 0.5, 2.0, -0.3}) {
    Eigen::MatrixXd phi_s, zoh_s;
    TaylorExp(a_hat, b_hat, x, &phi_s, &zoh_s);
    const Eigen::MatrixXd phi = hcw.TransitionMatrix(x / n);
    const Eigen::MatrixXd zoh = hcw.ZohInputMatrix(x / n);
    const Eigen::MatrixXd phi_hat = sc.cwiseInverse().asDiagonal() * phi * sc.asDiagonal();
    const Eigen::MatrixXd zoh_hat = sc.cwiseInverse().asDiagonal() * zoh;
    // Entrywise relative error: each entry is accurate, even tiny ones.
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        EXPECT_NEAR(phi_hat(i, j), phi_s(i, j), 2e-15 * std::abs(phi_s(i, j)) + 1e-300)
            << "x=" << x << " Phi(" << i << "," << j << ")";
      }
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(zoh_hat(i, j), zoh_s(i, j), 4e-15 * std::abs(zoh_s(i, j)) + 1e-300)
            << "x=" << x << " G(" << i << "," << j << ")";
      }
    }
  }
}

TEST(HcwModelTest, TransitionMatrixSolvesTheOdeAndComposes) {
  const double n = kGeoMeanMotion;
  const HcwModel hcw(n);
  const Eigen::VectorXd sc = hcw.state_scale();
  const Eigen::MatrixXd a = hcw.Evaluate(0).a;
  EXPECT_EQ(hcw.TransitionMatrix(0.0), (Eigen::Matrix<double, 6, 6>::Identity()));
  for (double tau : {600.0, 43200.0, 86400.0, 3.0e5}) {
    // dPhi/dtau = A Phi, by a 4th-order central difference.
    const double h = 1.0;
    const Eigen::MatrixXd dphi =
        (-hcw.TransitionMatrix(tau + 2 * h) + 8 * hcw.TransitionMatrix(tau + h) -
         8 * hcw.TransitionMatrix(tau - h) + hcw.TransitionMatrix(tau - 2 * h)) /
        (12 * h);
    EXPECT_LT(PhiRelError(a * hcw.TransitionMatrix(tau), dphi, sc), 1e-9) << tau;
    // Semigroup and inverse.
    EXPECT_LT(PhiRelError(hcw.TransitionMatrix(tau),
                          hcw.TransitionMatrix(0.3 * tau) * hcw.TransitionMatrix(0.7 * tau), sc),
              1e-14);
    EXPECT_LT(PhiRelError(Eigen::MatrixXd::Identity(6, 6),
                          hcw.TransitionMatrix(-tau) * hcw.TransitionMatrix(tau), sc),
              1e-12);
  }
}

TEST(HcwModelTest, ZohInputMatrixMatchesQuadrature) {
  const double n = kGeoMeanMotion;
  const HcwModel hcw(n);
  const Eigen::VectorXd sc = hcw.state_scale();
  const Eigen::MatrixXd b = hcw.Evaluate(0).b;
  std::vector<long double> gx, gw;
  GaussLegendre(12, &gx, &gw);
  for (double tau : {60.0, 300.0, 3600.0, 86400.0, 2.5e5}) {
    // int_0^tau Phi(tau - s) B ds, composite 12-point Gauss-Legendre, 16 panels.
    const int panels = 16;
    const long double hp = static_cast<long double>(tau) / panels;
    MatLd sum = MatLd::Zero(6, 3);
    for (int p = 0; p < panels; ++p) {
      for (size_t q = 0; q < gx.size(); ++q) {
        const long double s = hp * (p + 0.5L * (gx[q] + 1));
        const Eigen::MatrixXd integrand = hcw.TransitionMatrix(tau - static_cast<double>(s)) * b;
        sum += (0.5L * hp * gw[q]) * integrand.cast<long double>();
      }
    }
    const Eigen::MatrixXd quad = sum.cast<double>();
    const Eigen::VectorXd col_scale = Eigen::VectorXd::Constant(3, n);  // a ~ L n^2
    EXPECT_LT(testing_util::ScaledRelError(quad, hcw.ZohInputMatrix(tau), sc, col_scale), 1e-14)
        << "tau=" << tau;
  }
}

TEST(HcwModelTest, RejectsBadInput) {
  EXPECT_THAT([] { HcwModel(0.0); }, ThrowsMessage<std::invalid_argument>(HasSubstr(
                                         "mean_motion_rad_s must be finite and > 0, got 0")));
  EXPECT_THAT([] { HcwModel(-1e-4); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("mean_motion_rad_s")));
  EXPECT_THAT([] { HcwModel(1e-4, NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("length_scale_m")));
  const HcwModel hcw(1e-4);
  EXPECT_THAT([&] { hcw.TransitionMatrix(NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("tau must be finite")));
  EXPECT_THAT([&] { hcw.ZohInputMatrix(INFINITY); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("tau must be finite")));
  EXPECT_THAT([&] { hcw.Evaluate(NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
  EXPECT_THAT([&] { hcw.EvaluateOutput(NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
}

// ------------------------------------------------------------------ Kepler / YA

TEST(KeplerTest, SolvesKeplersEquation) {
  for (double e : {0.0, 0.1, 0.5, 0.7, 0.9, 0.99}) {
    for (int k = -40; k <= 40; ++k) {
      const double m = 0.1571 * k + 1e-3;
      const double ecc = YamanakaAnkersenModel::SolveKepler(m, e);
      EXPECT_NEAR(ecc - e * std::sin(ecc), m, 4e-15 * std::max(1.0, std::abs(m)))
          << "e=" << e << " M=" << m;
    }
  }
  // Exact points: M = 0 and M = pi.
  EXPECT_NEAR(YamanakaAnkersenModel::SolveKepler(0.0, 0.9), 0.0, 1e-15);
  EXPECT_NEAR(YamanakaAnkersenModel::SolveKepler(kPi, 0.9), kPi, 1e-15);
  EXPECT_THAT([] { YamanakaAnkersenModel::SolveKepler(NAN, 0.1); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("mean_anomaly_rad")));
  EXPECT_THAT(
      [] { YamanakaAnkersenModel::SolveKepler(1.0, 1.0); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("eccentricity must be in [0, 1), got 1")));
}

TEST(YamanakaAnkersenTest, TimeAndTrueAnomalyAreInverse) {
  const double a = 12.0e6;
  for (double e : {0.0, 0.1, 0.7, 0.9}) {
    const YamanakaAnkersenModel ya(a, e, YamanakaAnkersenModel::kEarthMu, 2.0);
    const double p = ya.period();
    EXPECT_NEAR(ya.TrueAnomalyAt(0.0), 2.0, 1e-13);
    EXPECT_NEAR(ya.TrueAnomalyAt(p), 2.0 + 2 * kPi, 1e-12);
    EXPECT_NEAR(ya.TrueAnomalyAt(-2 * p), 2.0 - 4 * kPi, 1e-12);
    for (double f : {-1.3, -0.2, 0.05, 0.4999, 0.5, 0.77, 1.0, 2.6}) {
      const double t = f * p;
      EXPECT_NEAR(ya.TimeAtTrueAnomaly(ya.TrueAnomalyAt(t)), t, 1e-10 * p) << e << " " << f;
    }
    // d nu / dt = sqrt(mu / p^3) (1 + e cos nu)^2: Kepler path vs the rate used in A(t).
    const double sl = a * (1 - e * e);
    for (double t : {0.0, 0.3 * p, 0.61 * p}) {
      const double h = 2e-5 * p;
      const double rate = (-ya.TrueAnomalyAt(t + 2 * h) + 8 * ya.TrueAnomalyAt(t + h) -
                           8 * ya.TrueAnomalyAt(t - h) + ya.TrueAnomalyAt(t - 2 * h)) /
                          (12 * h);
      const double nu = ya.TrueAnomalyAt(t);
      const double expected =
          std::sqrt(ya.mu() / (sl * sl * sl)) * std::pow(1 + e * std::cos(nu), 2);
      EXPECT_NEAR(rate, expected, 1e-7 * expected) << "e=" << e << " t=" << t;
      // A(t) carries 2 nu' in (3, 4).
      EXPECT_NEAR(ya.Evaluate(t).a(3, 4), 2 * expected, 1e-12 * expected);
    }
  }
}

TEST(YamanakaAnkersenTest, CircularCaseIsHcw) {
  const double a = 42164.0e3;
  const YamanakaAnkersenModel ya(a, 0.0);
  const HcwModel hcw(ya.mean_motion());
  EXPECT_TRUE(ya.Evaluate(1234.0).a.isApprox(hcw.Evaluate(0).a, 1e-14));
  for (double t : {300.0, 86400.0, 2.0e5}) {
    EXPECT_LT(PhiRelError(hcw.TransitionMatrix(t - 1000.0), ya.TransitionMatrix(t, 1000.0),
                          hcw.state_scale()),
              1e-12)
        << t;
  }
}

// YA closed form against adaptive integration of the linearised elliptic
// equations (A(t) of the model), over more than one orbit.
TEST(YamanakaAnkersenTest, MatchesNumericalIntegration) {
  const double a = 12.0e6;
  DiscretizationOptions opt;
  opt.scheme = Scheme::kReference;
  opt.reference_tolerance = 1e-13;
  const Eigen::MatrixXd u = Eigen::MatrixXd::Identity(3, 3);
  for (double e : {0.0, 0.1, 0.7}) {
    for (double nu0 : {0.0, 2.0}) {
      const YamanakaAnkersenModel ya(a, e, YamanakaAnkersenModel::kEarthMu, nu0);
      const double p = ya.period();
      const double t0 = 0.137 * p;
      double worst = 0.0;
      for (double f : {0.25, 0.5, 0.8, 1.0, 1.3}) {
        const double t1 = t0 + f * p;
        const DiscreteModel dm = Discretize(ya, u, {t0, t1}, opt);
        const double err = PhiRelError(dm.phi[0], ya.TransitionMatrix(t1, t0), ya.state_scale());
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-9) << "e=" << e << " nu0=" << nu0 << " t-t0=" << f << " periods";
        // The true-anomaly form gives the same matrix.
        EXPECT_LT(PhiRelError(ya.TransitionMatrixFromTrueAnomaly(ya.TrueAnomalyAt(t1),
                                                                 ya.TrueAnomalyAt(t0)),
                              ya.TransitionMatrix(t1, t0), ya.state_scale()),
                  1e-10);
      }
      char key[64], value[32];
      std::snprintf(key, sizeof(key), "ya_max_rel_err_e%.1f_nu0_%.0f", e, nu0);
      std::snprintf(value, sizeof(value), "%.2e", worst);
      RecordProperty(key, value);
    }
  }
}

TEST(YamanakaAnkersenTest, RejectsBadInput) {
  EXPECT_THAT([] { YamanakaAnkersenModel(-1.0, 0.1); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("semi_major_axis_m")));
  EXPECT_THAT(
      [] { YamanakaAnkersenModel(7e6, 1.0); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("eccentricity must be in [0, 0.99], got 1")));
  EXPECT_THAT([] { YamanakaAnkersenModel(7e6, -0.1); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("eccentricity")));
  EXPECT_THAT([] { YamanakaAnkersenModel(7e6, NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("eccentricity")));
  EXPECT_THAT([] { YamanakaAnkersenModel(7e6, 0.1, 0.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("mu_m3_s2")));
  EXPECT_THAT([] { YamanakaAnkersenModel(7e6, 0.1, 3.9e14, INFINITY); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("true_anomaly_at_epoch_rad")));
  EXPECT_THAT([] { YamanakaAnkersenModel(7e6, 0.1, 3.9e14, 0.0, -5.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("length_scale_m")));
  const YamanakaAnkersenModel ya(7e6, 0.1);
  EXPECT_THAT([&] { ya.Evaluate(NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
  EXPECT_THAT([&] { ya.EvaluateOutput(NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
  EXPECT_THAT([&] { ya.TransitionMatrix(1.0, NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t0 must be finite")));
  EXPECT_THAT([&] { ya.TransitionMatrixFromTrueAnomaly(INFINITY, 0.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("nu_rad must be finite")));
  EXPECT_THAT([&] { ya.TrueAnomalyAt(NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
  EXPECT_THAT([&] { ya.TimeAtTrueAnomaly(NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("nu_rad must be finite")));
}

}  // namespace
}  // namespace thrustsched::dynamics
