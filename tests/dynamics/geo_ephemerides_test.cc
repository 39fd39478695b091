#include "dynamics/ephemerides.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "dynamics/time.h"

namespace thrustsched::dynamics {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kArcsec = kDeg / 3600.0;
constexpr double kJd2034 = 2463963.5;  // 2034-01-01 00:00 TT (date of the check values below)

double RaDeg(const Eigen::Vector3d& v) {
  double ra = std::atan2(v.y(), v.x()) / kDeg;
  return ra < 0.0 ? ra + 360.0 : ra;
}
double DecDeg(const Eigen::Vector3d& v) { return std::asin(v.z() / v.norm()) / kDeg; }

// IAU 1976 (Lieske) precession matrix J2000 -> mean of date, written here
// independently of the library (which only shifts the ecliptic longitude).
Eigen::Matrix3d PrecessionJ2000ToDate(double jd_tt) {
  const double t = (jd_tt - 2451545.0) / 36525.0;
  const double zeta = (2306.2181 * t + 0.30188 * t * t + 0.017998 * t * t * t) * kArcsec;
  const double z = (2306.2181 * t + 1.09468 * t * t + 0.018203 * t * t * t) * kArcsec;
  const double theta = (2004.3109 * t - 0.42665 * t * t - 0.041833 * t * t * t) * kArcsec;
  // Passive rotations: r_date = R3(-z) R2(theta) R3(-zeta) r_J2000.
  const auto r3 = [](double a) {
    Eigen::Matrix3d m;
    m << std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a), 0, 0, 0, 1;
    return m;
  };
  const auto r2 = [](double a) {
    Eigen::Matrix3d m;
    m << std::cos(a), 0, -std::sin(a), 0, 1, 0, std::sin(a), 0, std::cos(a);
    return m;
  };
  return r3(-z) * r2(theta) * r3(-zeta);
}

TEST(EphemeridesTest, J2000SeriesMatchesTheExtractorCheckValues) {
  // The series of Montenbruck & Gill 2000 (sec. 3.3.2) evaluated independently
  // (derived here, not published values): Sun RA 280.93, Dec -23.06, r 1.47102e8 km;
  // Moon RA 48.00, Dec +14.34, r 367957 km at 2034-01-01 00:00 TT (to 0.01 deg).
  const Eigen::Vector3d sun = SunPositionJ2000(kJd2034);
  EXPECT_NEAR(RaDeg(sun), 280.93, 0.006);
  EXPECT_NEAR(DecDeg(sun), -23.06, 0.006);
  EXPECT_NEAR(sun.norm() / 1e3, 1.47102e8, 1e3);
  const Eigen::Vector3d moon = MoonPositionJ2000(kJd2034);
  EXPECT_NEAR(RaDeg(moon), 48.00, 0.006);
  EXPECT_NEAR(DecDeg(moon), 14.34, 0.006);
  EXPECT_NEAR(moon.norm() / 1e3, 367957.0, 1.0);
}

TEST(EphemeridesTest, OfDateSeriesAgreesWithErfaAfterPrecessionToJ2000) {
  // ERFA (evaluated independently, not a published value) gives the Sun at
  // RA 281.05 deg (J2000) on 2034-01-01;
  // the of-date series (with the perihelion drift) should be within ~0.01 deg.
  const Eigen::Matrix3d p = PrecessionJ2000ToDate(kJd2034);
  const Eigen::Vector3d sun = p.transpose() * SunPositionMeanOfEpoch(kJd2034, kJd2034);
  std::printf("[ geo ] of-date Sun precessed to J2000: RA %.4f deg\n", RaDeg(sun));
  EXPECT_NEAR(RaDeg(sun), 281.05, 0.015);
  // The J2000 series is 0.11 deg behind because it freezes the perihelion.
  EXPECT_NEAR(RaDeg(sun) - RaDeg(SunPositionJ2000(kJd2034)), 0.11, 0.02);
  // The Moon series differ only by the precession rate in L0: after
  // precession both must give the same direction.
  const Eigen::Vector3d moon = p.transpose() * MoonPositionMeanOfEpoch(kJd2034, kJd2034);
  const Eigen::Vector3d moon_j2000 = MoonPositionJ2000(kJd2034);
  EXPECT_LT(std::acos(moon.normalized().dot(moon_j2000.normalized())) / kDeg, 0.01);
  EXPECT_NEAR(moon.norm(), moon_j2000.norm(), 1.0);
}

TEST(EphemeridesTest, MeanOfEpochFrameIsFixedInTime) {
  // One year after the frame epoch, "of date" and "of epoch" differ by one
  // year of general precession (50.29"/yr about the ecliptic pole).
  const double jd = kJd2034 + 365.25;
  const Eigen::Vector3d of_date = SunPositionMeanOfEpoch(jd, jd);
  const Eigen::Vector3d of_epoch = SunPositionMeanOfEpoch(jd, kJd2034);
  const double angle =
      std::acos(std::clamp(of_date.normalized().dot(of_epoch.normalized()), -1.0, 1.0));
  EXPECT_NEAR(angle / kArcsec, 50.29, 0.5);
  // And it agrees with the precession matrix between the two dates to < 2".
  const Eigen::Matrix3d p_epoch_to_date =
      PrecessionJ2000ToDate(jd) * PrecessionJ2000ToDate(kJd2034).transpose();
  const Eigen::Vector3d mapped = p_epoch_to_date * of_epoch;
  EXPECT_LT(
      std::acos(std::clamp(mapped.normalized().dot(of_date.normalized()), -1.0, 1.0)) / kArcsec,
      2.0);
}

TEST(EphemeridesTest, AnnualAndMonthlyMotion) {
  // The Sun goes round once a year (equinox to equinox 365.2422 d), the Moon
  // once per tropical month (27.3216 d): check the mean angular rates.
  const Eigen::Vector3d s0 = SunPositionMeanOfEpoch(kJd2034, kJd2034);
  const Eigen::Vector3d s1 = SunPositionMeanOfEpoch(kJd2034 + 365.2422, kJd2034 + 365.2422);
  EXPECT_LT(std::acos(std::clamp(s0.normalized().dot(s1.normalized()), -1.0, 1.0)) / kDeg, 0.01);
  const Eigen::Vector3d m0 = MoonPositionMeanOfEpoch(kJd2034, kJd2034);
  const Eigen::Vector3d m1 =
      MoonPositionMeanOfEpoch(kJd2034 + 27.3216 * 12, kJd2034 + 27.3216 * 12);
  EXPECT_LT(std::acos(std::clamp(m0.normalized().dot(m1.normalized()), -1.0, 1.0)) / kDeg, 8.0);
  // Sun distance between perihelion (~Jan 3) and aphelion (~Jul 4).
  EXPECT_NEAR(SunPositionMeanOfEpoch(kJd2034 + 2, kJd2034).norm(), 1.471e11, 0.002e11);
  EXPECT_NEAR(SunPositionMeanOfEpoch(kJd2034 + 184, kJd2034).norm(), 1.521e11, 0.002e11);
  EXPECT_NEAR(MeanObliquityRad(2451545.0) / kDeg, 23.43929111, 1e-12);
}

TEST(EphemeridesTest, NonFiniteDatesThrow) {
  using ::testing::HasSubstr;
  using ::testing::ThrowsMessage;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT([&] { SunPositionJ2000(nan); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("jd_tt must be finite")));
  EXPECT_THAT([&] { MoonPositionJ2000(nan); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("jd_tt")));
  EXPECT_THAT([&] { SunPositionMeanOfEpoch(kJd2034, nan); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("jd_frame_tt must be finite")));
  EXPECT_THAT([&] { MoonPositionMeanOfEpoch(nan, kJd2034); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("jd_tt must be finite")));
  EXPECT_THAT([&] { MeanObliquityRad(std::numeric_limits<double>::infinity()); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("jd_tt")));
}

}  // namespace
}  // namespace thrustsched::dynamics
