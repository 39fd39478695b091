// Natural-force models of the GEO simulator (internal helpers + the public
// GeoSimulator::PerturbingAcceleration), each against an independent formula.
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include "dynamics/geo_model.h"
#include "dynamics/geo_simulator.h"
#include "dynamics/internal/geo_dual.h"
#include "dynamics/internal/geo_force_model.h"
#include "dynamics/internal/geo_physics.h"

namespace thrustsched::dynamics {
namespace {

using internal::Vec3;
constexpr double kPi = 3.14159265358979323846;

// Fully normalised associated Legendre functions P_nm(u) for n <= 4 written out
// (no Condon-Shortley phase), times N_nm computed from factorials.
double LegendreUnnormalised(int n, int m, double u) {
  const double c = std::sqrt(1.0 - u * u);
  switch (n * 10 + m) {
    case 20:
      return 0.5 * (3 * u * u - 1);
    case 21:
      return 3 * u * c;
    case 22:
      return 3 * c * c;
    case 30:
      return 0.5 * (5 * u * u * u - 3 * u);
    case 31:
      return 1.5 * (5 * u * u - 1) * c;
    case 32:
      return 15 * u * c * c;
    case 33:
      return 15 * c * c * c;
    case 40:
      return (35 * std::pow(u, 4) - 30 * u * u + 3) / 8;
    case 41:
      return 2.5 * (7 * u * u * u - 3 * u) * c;
    case 42:
      return 7.5 * (7 * u * u - 1) * c * c;
    case 43:
      return 105 * u * c * c * c;
    case 44:
      return 105 * std::pow(c, 4);
  }
  return 0.0;
}

double Factorial(int k) { return k <= 1 ? 1.0 : k * Factorial(k - 1); }

// Non-central potential (m^2/s^2) summed directly from the EGM2008 table.
double DirectPotential(const Eigen::Vector3d& r, int degree, bool zonal, bool tesseral) {
  const double rn = r.norm(), u = r.z() / rn, lon = std::atan2(r.y(), r.x());
  double sum = 0.0;
  for (const auto& k : internal::kEgm2008) {
    if (k.n > degree || (k.m == 0 && !zonal) || (k.m > 0 && !tesseral)) continue;
    const double norm = std::sqrt((k.m == 0 ? 1.0 : 2.0) * (2 * k.n + 1) * Factorial(k.n - k.m) /
                                  Factorial(k.n + k.m));
    sum += std::pow(geo::kEarthRadius / rn, k.n) * norm * LegendreUnnormalised(k.n, k.m, u) *
           (k.c * std::cos(k.m * lon) + k.s * std::sin(k.m * lon));
  }
  return geo::kEarthMu / rn * sum;
}

internal::GeopotentialCoefficients Coefficients(int degree, bool zonal, bool tesseral) {
  GeoModelOptions o;
  o.gravity_degree = degree;
  o.j2 = zonal;
  o.tesseral = tesseral;
  return internal::GeoForceModel(o).coefficients();
}

TEST(GeoForcesTest, CunninghamRecursionIsTheGradientOfTheDirectPotential) {
  const Eigen::Vector3d points[] = {{42165765.0 * std::cos(2.06), 42165765.0 * std::sin(2.06), 0.0},
                                    {-3.0e7, 1.2e7, 2.5e7},
                                    {5.0e6, -4.0e6, -3.0e6}};
  for (int degree = 2; degree <= 4; ++degree) {
    for (const auto& [zonal, tesseral] :
         {std::pair{true, true}, std::pair{true, false}, std::pair{false, true}}) {
      const internal::GeopotentialCoefficients cs = Coefficients(degree, zonal, tesseral);
      for (const Eigen::Vector3d& r : points) {
        const Vec3<double> rv = {r.x(), r.y(), r.z()};
        const Vec3<double> a =
            internal::GeopotentialAccelerationEcef(rv, cs, geo::kEarthMu, geo::kEarthRadius);
        const double h = 10.0;
        Eigen::Vector3d grad;
        for (int i = 0; i < 3; ++i) {
          Eigen::Vector3d p = r, m = r;
          p(i) += h;
          m(i) -= h;
          grad(i) = (DirectPotential(p, degree, zonal, tesseral) -
                     DirectPotential(m, degree, zonal, tesseral)) /
                    (2 * h);
        }
        const Eigen::Vector3d got(a[0], a[1], a[2]);
        EXPECT_LT((got - grad).norm(), 1e-7 * grad.norm())
            << degree << zonal << tesseral << r.transpose();
      }
    }
  }
}

TEST(GeoForcesTest, J2ClosedFormAndDerivedCoefficients) {
  // Derived here from EGM2008: J2 = -sqrt(5) C20 = 1.0826262e-3, C22 = 1.574615e-6,
  // S22 = -9.038728e-7.
  const internal::GeopotentialCoefficients cs = Coefficients(4, true, true);
  EXPECT_NEAR(-cs.c[2][0], 1.0826262e-3, 1e-10);
  EXPECT_NEAR(cs.c[2][2], 1.574615e-6, 1e-12);
  EXPECT_NEAR(cs.s[2][2], -9.038728e-7, 1e-12);
  const double j2 = -cs.c[2][0];
  const internal::GeopotentialCoefficients only_j2 = Coefficients(2, true, false);
  const Eigen::Vector3d r(1.1e7, -2.0e6, 6.0e6);
  const double rn = r.norm(), z2 = r.z() * r.z() / (rn * rn);
  const double k =
      -1.5 * j2 * geo::kEarthMu * geo::kEarthRadius * geo::kEarthRadius / std::pow(rn, 5);
  const Eigen::Vector3d ref(k * r.x() * (1 - 5 * z2), k * r.y() * (1 - 5 * z2),
                            k * r.z() * (3 - 5 * z2));
  const Vec3<double> a = internal::GeopotentialAccelerationEcef<double>(
      {r.x(), r.y(), r.z()}, only_j2, geo::kEarthMu, geo::kEarthRadius);
  EXPECT_LT((Eigen::Vector3d(a[0], a[1], a[2]) - ref).norm(), 1e-12 * ref.norm());
}

TEST(GeoForcesTest, ThirdBodyAndRadiationPressure) {
  // Satellite on the Earth-body line: a = mu (1/(d - r)^2 - 1/d^2) toward the body.
  const double d = 3.84e8, r = 4.2e7;
  const Vec3<double> acc =
      internal::ThirdBodyAcceleration<double>({r, 0, 0}, {d, 0, 0}, geo::kMoonMu);
  EXPECT_NEAR(acc[0], geo::kMoonMu * (1 / ((d - r) * (d - r)) - 1 / (d * d)),
              1e-12 * std::abs(acc[0]));
  EXPECT_EQ(acc[1], 0.0);
  // Perpendicular: a = mu (d_vec - r_vec)/|.|^3 - mu d_vec/d^3, radial part -mu r/|.|^3.
  const Vec3<double> acc2 =
      internal::ThirdBodyAcceleration<double>({0, r, 0}, {d, 0, 0}, geo::kMoonMu);
  const double q = std::pow(d * d + r * r, 1.5);
  EXPECT_NEAR(acc2[1], -geo::kMoonMu * r / q, 1e-12 * std::abs(acc2[1]));

  // SRP: P Cr A/m at 1 AU, pointing away from the Sun; zero in the cylindrical shadow.
  const double au = geo::kAstronomicalUnit, coef = geo::kSolarPressure * 1.0 * 0.0227;
  const Vec3<double> sun = {au, 0, 0};
  const Vec3<double> day = {0, 4.2e7, 0};
  const Vec3<double> srp = internal::SrpAcceleration<double>(day, sun, coef, au);
  const double dist2 = au * au + 4.2e7 * 4.2e7;
  EXPECT_NEAR(srp[0], -coef * au * au / dist2 * au / std::sqrt(dist2), 1e-20);
  EXPECT_NEAR(std::hypot(srp[0], srp[1]), 1.0351e-7, 1e-11);
  EXPECT_GT(internal::ShadowFunction(day, sun, geo::kEarthRadius), 0.0);
  EXPECT_LT(internal::ShadowFunction({-4.2e7, 6.0e6, 0}, sun, geo::kEarthRadius),
            0.0);  // behind, |perp| < R_E
  EXPECT_GT(internal::ShadowFunction({-4.2e7, 6.5e6, 0}, sun, geo::kEarthRadius),
            0.0);  // behind, |perp| > R_E
  // Continuous across the terminator plane.
  EXPECT_NEAR(internal::ShadowFunction({-1e-3, 4.2e7, 0}, sun, geo::kEarthRadius),
              internal::ShadowFunction({1e-3, 4.2e7, 0}, sun, geo::kEarthRadius), 1e-3);
}

TEST(GeoForcesTest, DualNumbersGiveExactDerivatives) {
  using D = internal::Dual<2>;
  const D x = D::Variable(0.7, 0), y = D::Variable(-1.3, 1);
  const D f = sin(x) * y / sqrt(x * x + y * y) + atan2(y, x) - 2.0 / x + cos(y);
  const auto fv = [](double a, double b) {
    return std::sin(a) * b / std::sqrt(a * a + b * b) + std::atan2(b, a) - 2.0 / a + std::cos(b);
  };
  const double h = 1e-6;
  EXPECT_NEAR(f.v, fv(0.7, -1.3), 1e-15);
  EXPECT_NEAR(f.d[0], (fv(0.7 + h, -1.3) - fv(0.7 - h, -1.3)) / (2 * h), 1e-8);
  EXPECT_NEAR(f.d[1], (fv(0.7, -1.3 + h) - fv(0.7, -1.3 - h)) / (2 * h), 1e-8);
}

TEST(GeoForcesTest, SimulatorSumsTheEnabledForces) {
  GeoModelOptions all;
  const GeoSimulator sim(all);
  const double t = 12345.0;
  const Eigen::Vector3d r = sim.EciFromRelative(Eigen::VectorXd::Zero(6), t).head<3>();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const char* only : {"geopotential", "sun", "moon", "srp"}) {
    GeoModelOptions o;
    o.j2 = o.tesseral = std::string(only) == "geopotential";
    o.sun = std::string(only) == "sun";
    o.moon = std::string(only) == "moon";
    o.srp = std::string(only) == "srp";
    sum += GeoSimulator(o).PerturbingAcceleration(r, t);
  }
  EXPECT_LT((sim.PerturbingAcceleration(r, t) - sum).norm(), 1e-15);
  // Orders of magnitude at GEO: total ~1e-5 m/s^2 (dominated by the Moon/Sun tides and J2).
  EXPECT_GT(sim.PerturbingAcceleration(r, t).norm(), 1e-6);
  EXPECT_LT(sim.PerturbingAcceleration(r, t).norm(), 3e-5);
  GeoModelOptions none;
  none.j2 = none.tesseral = none.sun = none.moon = none.srp = false;
  EXPECT_EQ(GeoSimulator(none).PerturbingAcceleration(r, t).norm(), 0.0);
}

}  // namespace
}  // namespace thrustsched::dynamics
