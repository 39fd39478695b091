#include "dynamics/orbital_elements.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "dynamics/geo_model.h"

namespace thrustsched::dynamics {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMu = geo::kEarthMu;

struct Classical {
  double a, e, i, raan, argp, mean_anomaly;
};

// Independent reference: classical elements -> perifocal -> R3(W) R1(i) R3(w).
Vector6d FromClassical(const Classical& c) {
  double ecc = c.mean_anomaly;
  for (int k = 0; k < 50; ++k)
    ecc -= (ecc - c.e * std::sin(ecc) - c.mean_anomaly) / (1.0 - c.e * std::cos(ecc));
  const double n = std::sqrt(kMu / (c.a * c.a * c.a));
  const double root = std::sqrt(1.0 - c.e * c.e);
  const Eigen::Vector3d r_pf(c.a * (std::cos(ecc) - c.e), c.a * root * std::sin(ecc), 0.0);
  const Eigen::Vector3d v_pf = n * c.a / (1.0 - c.e * std::cos(ecc)) *
                               Eigen::Vector3d(-std::sin(ecc), root * std::cos(ecc), 0.0);
  const Eigen::Matrix3d rot = (Eigen::AngleAxisd(c.raan, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(c.i, Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(c.argp, Eigen::Vector3d::UnitZ()))
                                  .toRotationMatrix();
  Vector6d rv;
  rv << rot * r_pf, rot * v_pf;
  return rv;
}

EquinoctialElements ToEquinoctial(const Classical& c) {
  EquinoctialElements el;
  el.a_m = c.a;
  el.ex = c.e * std::cos(c.argp + c.raan);
  el.ey = c.e * std::sin(c.argp + c.raan);
  el.ix = std::tan(c.i / 2) * std::cos(c.raan);
  el.iy = std::tan(c.i / 2) * std::sin(c.raan);
  el.mean_longitude_rad = WrapPi(c.raan + c.argp + c.mean_anomaly);
  return el;
}

const Classical kCases[] = {
    {42165765.0, 4.5e-4, 0.05 * kPi / 180, 1.2, 0.7, 2.9},  // GEO-like
    {42164000.0, 3.6e-3, 1.0 * kPi / 180, -2.0, 2.5, -0.4},
    {26560000.0, 0.02, 55.0 * kPi / 180, 0.3, -1.1, 4.0},  // GNSS-like
    {24500000.0, 0.73, 7.0 * kPi / 180, 3.0, 3.0, 0.2},    // GTO
    {7000000.0, 0.001, 98.0 * kPi / 180, 5.0, 0.1, 1.0},   // polar, i > 90
};

TEST(OrbitalElementsTest, CartesianMatchesClassicalConversion) {
  for (const Classical& c : kCases) {
    const Vector6d ref = FromClassical(c);
    const Vector6d got = CartesianFromEquinoctial(ToEquinoctial(c), kMu);
    // 1e-10 a: 4 mm at GEO; the appendix D forms are off by 40-60 km.
    EXPECT_LT((got.head<3>() - ref.head<3>()).norm(), 1e-10 * c.a) << c.a;
    EXPECT_LT((got.tail<3>() - ref.tail<3>()).norm(), 1e-12 * ref.tail<3>().norm() * 1e3) << c.a;
  }
}

TEST(OrbitalElementsTest, RoundTrips) {
  for (const Classical& c : kCases) {
    const EquinoctialElements el = ToEquinoctial(c);
    const EquinoctialElements back =
        EquinoctialFromCartesian(CartesianFromEquinoctial(el, kMu), kMu);
    EXPECT_NEAR(back.a_m, el.a_m, 1e-8 * el.a_m);
    EXPECT_NEAR(back.ex, el.ex, 1e-12);
    EXPECT_NEAR(back.ey, el.ey, 1e-12);
    EXPECT_NEAR(back.ix, el.ix, 1e-12);
    EXPECT_NEAR(back.iy, el.iy, 1e-12);
    EXPECT_NEAR(WrapPi(back.mean_longitude_rad - el.mean_longitude_rad), 0.0, 1e-11);
  }
  // Exactly circular and equatorial: the set stays regular.
  const EquinoctialElements geo_point{42165765.0, 0.0, 0.0, 0.0, 0.0, 2.0};
  const Vector6d rv = CartesianFromEquinoctial(geo_point, kMu);
  EXPECT_NEAR(rv(0), 42165765.0 * std::cos(2.0), 1e-6);
  EXPECT_NEAR(rv(1), 42165765.0 * std::sin(2.0), 1e-6);
  EXPECT_NEAR(rv(2), 0.0, 1e-9);
  EXPECT_NEAR(rv.tail<3>().norm(), std::sqrt(kMu / 42165765.0), 1e-9);
  const EquinoctialElements back = EquinoctialFromCartesian(rv, kMu);
  EXPECT_NEAR(back.ex, 0.0, 1e-14);
  EXPECT_NEAR(back.ix, 0.0, 1e-14);
  EXPECT_NEAR(back.mean_longitude_rad, 2.0, 1e-13);
}

TEST(OrbitalElementsTest, InclinationVectorSignsFollowTheThesisDefinition) {
  // i = 1 deg, node at 90 deg: ix = 0, iy = +tan(0.5 deg) (appendix D (D.30) has both signs
  // flipped).
  const Classical c{42165765.0, 0.0, kPi / 180, kPi / 2, 0.0, 0.0};
  const EquinoctialElements el = EquinoctialFromCartesian(FromClassical(c), kMu);
  EXPECT_NEAR(el.ix, 0.0, 1e-14);
  EXPECT_NEAR(el.iy, std::tan(kPi / 360), 1e-14);
}

// Gauss matrix against finite differences of the element conversion under a
// small velocity impulse along each RTN axis (the check that exposes the
// misprinted (6,1) entry of Gazzino 2018, eq. (B.51)).
void ExpectGaussMatchesImpulses(const EquinoctialElements& el, double rel_tol) {
  const Eigen::Matrix<double, 6, 3> g = GaussMatrix(el, kMu);
  const Vector6d rv = CartesianFromEquinoctial(el, kMu);
  const Eigen::Matrix3d rtn = RtnBasis(rv);
  const double dv = 1e-3;  // m/s
  for (int j = 0; j < 3; ++j) {
    Vector6d plus = rv, minus = rv;
    plus.tail<3>() += dv * rtn.col(j);
    minus.tail<3>() -= dv * rtn.col(j);
    const EquinoctialElements ep = EquinoctialFromCartesian(plus, kMu);
    const EquinoctialElements em = EquinoctialFromCartesian(minus, kMu);
    const double fd[6] = {(ep.a_m - em.a_m) / (2 * dv),
                          (ep.ex - em.ex) / (2 * dv),
                          (ep.ey - em.ey) / (2 * dv),
                          (ep.ix - em.ix) / (2 * dv),
                          (ep.iy - em.iy) / (2 * dv),
                          WrapPi(ep.mean_longitude_rad - em.mean_longitude_rad) / (2 * dv)};
    for (int i = 0; i < 6; ++i) {
      const double scale = g.row(i).cwiseAbs().maxCoeff();
      EXPECT_NEAR(g(i, j), fd[i], rel_tol * scale + 1e-18) << "entry (" << i << ", " << j << ")";
    }
  }
}

TEST(OrbitalElementsTest, GaussMatrixMatchesImpulseFiniteDifferences) {
  for (const Classical& c : kCases) ExpectGaussMatchesImpulses(ToEquinoctial(c), 2e-6);
  // The entry the thesis prints wrongly: (6,1) at e = 3.6e-3 is about -0.651 s/km.
  const EquinoctialElements el = ToEquinoctial(kCases[1]);
  EXPECT_NEAR(GaussMatrix(el, kMu)(5, 0) * 1e3, -0.651, 0.01);
}

TEST(OrbitalElementsTest, GaussMatrixAtTheStationPointIsTheThesisB) {
  // Gazzino 2018 eq. (B.59) with B12 corrected to 2a (printed a), kappa = 2.5 rad:
  // B = (1/v) [0 2a 0; s 2c 0; -c 2s 0; 0 0 c/2; 0 0 s/2; -2 0 0].
  const double a = geo::kStationRadius, k = 2.5, v = std::sqrt(kMu / a);
  const EquinoctialElements el{a, 0.0, 0.0, 0.0, 0.0, k};
  Eigen::Matrix<double, 6, 3> b;
  b << 0, 2 * a, 0, std::sin(k), 2 * std::cos(k), 0, -std::cos(k), 2 * std::sin(k), 0, 0, 0,
      std::cos(k) / 2, 0, 0, std::sin(k) / 2, -2, 0, 0;
  b /= v;
  EXPECT_LT((GaussMatrix(el, kMu) - b).cwiseAbs().maxCoeff(), 1e-12 * b.cwiseAbs().maxCoeff());
  ExpectGaussMatchesImpulses(el, 1e-6);
}

TEST(OrbitalElementsTest, RtnBasisAndWrap) {
  const Vector6d rv = FromClassical(kCases[2]);
  const Eigen::Matrix3d m = RtnBasis(rv);
  EXPECT_LT((m.transpose() * m - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_NEAR(m.determinant(), 1.0, 1e-14);
  EXPECT_GT(m.col(1).dot(rv.tail<3>()), 0.0);  // T is along the motion
  EXPECT_DOUBLE_EQ(WrapPi(kPi), kPi);
  EXPECT_DOUBLE_EQ(WrapPi(-kPi), kPi);
  EXPECT_NEAR(WrapPi(3 * kPi / 2), -kPi / 2, 1e-15);
  EXPECT_NEAR(WrapPi(-7.0), -7.0 + 2 * kPi, 1e-15);
}

TEST(OrbitalElementsTest, BadInputThrows) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EquinoctialElements el{42165765.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  el.ix = nan;
  EXPECT_THAT([&] { CartesianFromEquinoctial(el, kMu); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("ix must be finite")));
  el = {-1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  EXPECT_THAT([&] { GaussMatrix(el, kMu); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("a_m must be > 0")));
  el = {42165765.0, 0.8, 0.7, 0.0, 0.0, 0.0};
  EXPECT_THAT([&] { CartesianFromEquinoctial(el, kMu); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("eccentricity")));
  el = {42165765.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  EXPECT_THAT([&] { CartesianFromEquinoctial(el, -1.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("mu")));

  Vector6d rv = Vector6d::Zero();
  rv(0) = 42165765.0;
  rv(3) = 100.0;  // radial velocity only: r x v = 0
  EXPECT_THAT([&] { EquinoctialFromCartesian(rv, kMu); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("parallel")));
  EXPECT_THAT([&] { RtnBasis(rv); }, ThrowsMessage<std::invalid_argument>(HasSubstr("parallel")));
  rv << 42165765.0, 0, 0, 0, -3074.6, 0;  // retrograde equatorial
  EXPECT_THAT([&] { EquinoctialFromCartesian(rv, kMu); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("retrograde")));
  rv << 42165765.0, 0, 0, 0, 6000.0, 0;  // hyperbolic
  EXPECT_THAT([&] { EquinoctialFromCartesian(rv, kMu); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("not an ellipse")));
  rv(4) = nan;
  EXPECT_THAT([&] { EquinoctialFromCartesian(rv, kMu); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("finite")));
}

}  // namespace
}  // namespace thrustsched::dynamics
