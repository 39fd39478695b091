#include "transfer/equinoctial.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "common/constants.h"
#include "dynamics/keplerian.h"

namespace thrustsched::transfer {
namespace {

constexpr double kDeg = common::kDegToRad;

Keplerian SomeOrbit() { return Keplerian{24505.9e3, 0.725, 5.2 * kDeg, 0.7, 2.1, 1.3}; }

// The position and velocity agree with the project's classical-element
// conversion (dynamics/keplerian.h, written independently).
TEST(EquinoctialTest, CartesianMatchesTheKeplerianConversionOfDynamics) {
  for (const Keplerian& k : {SomeOrbit(), Keplerian{42165e3, 0.0, 0.0, 0.0, 0.0, 2.0},
                             Keplerian{7000e3, 0.1, 98 * kDeg, 4.0, 5.0, -2.5}}) {
    dynamics::KeplerianElements d;
    d.a_m = k.a_m, d.e = k.e, d.i_rad = k.i_rad, d.raan_rad = k.raan_rad;
    d.arg_perigee_rad = k.arg_perigee_rad, d.anomaly_rad = k.true_anomaly_rad;
    d.anomaly = dynamics::AnomalyKind::kTrue;
    const dynamics::Vector6d ref = dynamics::CartesianFromKeplerian(d, kMuEarth);
    const dynamics::Vector6d rv = CartesianFromEquinoctial(EquinoctialFromKeplerian(k), kMuEarth);
    EXPECT_LT((rv.head<3>() - ref.head<3>()).norm(), 1e-6);  // m
    EXPECT_LT((rv.tail<3>() - ref.tail<3>()).norm(), 1e-9);  // m/s
  }
}

TEST(EquinoctialTest, CartesianRoundTripAndClassicalElements) {
  const Equinoctial q = EquinoctialFromKeplerian(SomeOrbit());
  const Equinoctial back =
      EquinoctialFromCartesian(CartesianFromEquinoctial(q, kMuEarth), kMuEarth);
  EXPECT_NEAR(back.p_m, q.p_m, 1e-6);
  EXPECT_NEAR(back.ex, q.ex, 1e-13);
  EXPECT_NEAR(back.ey, q.ey, 1e-13);
  EXPECT_NEAR(back.hx, q.hx, 1e-13);
  EXPECT_NEAR(back.hy, q.hy, 1e-13);
  EXPECT_NEAR(std::remainder(back.l_rad - q.l_rad, 2 * common::kPi), 0.0, 1e-13);
  EXPECT_NEAR(SemiMajorAxis(q), 24505.9e3, 1e-6);
  EXPECT_NEAR(Eccentricity(q), 0.725, 1e-15);
  EXPECT_NEAR(Inclination(q), 5.2 * kDeg, 1e-15);
  EXPECT_THROW(EquinoctialFromKeplerian(Keplerian{7e6, 1.2, 0, 0, 0, 0}), std::invalid_argument);
}

// The Gauss equations against the time derivative of the osculating
// elements of a Cartesian state pushed by a small acceleration.
TEST(EquinoctialTest, GaussEquationsMatchCartesianFiniteDifferences) {
  const Equinoctial q = EquinoctialFromKeplerian(SomeOrbit());
  const dynamics::Vector6d rv = CartesianFromEquinoctial(q, kMuEarth);
  const Eigen::Matrix3d qsw = QswBasis(rv);
  const Eigen::Vector3d acc_qsw(2e-4, -3e-4, 5e-4);  // m/s^2
  auto deriv = [&](const dynamics::Vector6d& s) {
    dynamics::Vector6d d;
    d.head<3>() = s.tail<3>();
    d.tail<3>() = -kMuEarth * s.head<3>() / std::pow(s.head<3>().norm(), 3) + qsw * acc_qsw;
    return d;
  };
  const double h = 1e-2;  // s, central difference of the elements along the exact derivative
  const Equinoctial qp = EquinoctialFromCartesian(rv + h * deriv(rv), kMuEarth);
  const Equinoctial qm = EquinoctialFromCartesian(rv - h * deriv(rv), kMuEarth);
  ScaledUnits u;
  u.length_m = 1.0, u.time_s = 1.0;  // SI: mu in m^3/s^2
  const GaussTerms g = Gauss(u.ToScaled(q), kMuEarth);
  const Vector6 rate = g.f0 + g.F * acc_qsw;
  const Vector6 fd = (u.ToScaled(qp) - u.ToScaled(qm)) / (2 * h);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(rate(i), fd(i), 1e-6 * std::abs(rate(i)) + 1e-12) << i;
}

TEST(EquinoctialTest, HandWrittenDerivativesMatchFiniteDifferences) {
  ScaledUnits u;
  Vector6 x;
  x << 11.625, 0.3, -0.2, 6.12e-2, 0.03, 2.4;
  const GaussJacobians d = GaussDerivatives(x, u.mu());
  for (int j = 0; j < 6; ++j) {
    const double h = 1e-6;
    Vector6 xp = x, xm = x;
    xp(j) += h, xm(j) -= h;
    const GaussTerms p = Gauss(xp, u.mu()), m = Gauss(xm, u.mu());
    const Vector6 df0 = (p.f0 - m.f0) / (2 * h);
    const Matrix63 dF = (p.F - m.F) / (2 * h);
    EXPECT_LT((df0 - d.df0.col(j)).norm(), 1e-8 * (1 + df0.norm())) << "f0, x_" << j;
    EXPECT_LT((dF - d.dF[j]).norm(), 1e-8 * (1 + dF.norm())) << "F, x_" << j;
  }
}

TEST(EquinoctialTest, ScaledUnitsAreCaillausMegametresAndHours) {
  ScaledUnits u;
  EXPECT_NEAR(u.mu(), 5165.8620912, 1e-6);                                           // Mm^3/h^2
  EXPECT_NEAR(u.Thrust(60.0), 60 * 12.96, 1e-12);                                    // kg Mm / h^2
  EXPECT_NEAR(1 / u.Speed(common::kStandardGravity_m_s2 * 1994.75), 1.42e-2, 1e-6);  // beta, h/Mm
}

}  // namespace
}  // namespace thrustsched::transfer
