#include "dynamics/ephemerides.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/constants.h"
#include "dynamics/time.h"

namespace thrustsched::dynamics {
namespace {

using common::kPi;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kArcsecPerTurn = 1296000.0;
constexpr double kArcsecPerRad = 206264.806;
constexpr double kDeg = kPi / 180.0;
// IAU 1976 general precession in longitude, arcsec per Julian century.
constexpr double kPrecessionArcsecPerCentury = 5029.0966;

double Frac(double x) { return x - std::floor(x); }

void CheckJd(double jd, const char* where, const char* name) {
  if (!std::isfinite(jd)) {
    throw std::invalid_argument(std::string(where) + ": " + name + " must be finite, got " +
                                std::to_string(jd));
  }
}
double Centuries(double jd_tt) { return (jd_tt - kJulianDateJ2000) / 36525.0; }

struct Ecliptic {
  double lon, lat, r_km;
};

// Rotation ecliptic -> equator, active R1(+eps) (Montenbruck & Gill 2000,
// sec. 3.3.2, write it with the passive Rx(-eps)).
Eigen::Vector3d ToEquatorial(const Ecliptic& e, double eps) {
  const Eigen::Vector3d ecl(e.r_km * std::cos(e.lon) * std::cos(e.lat),
                            e.r_km * std::sin(e.lon) * std::cos(e.lat), e.r_km * std::sin(e.lat));
  const double ce = std::cos(eps), se = std::sin(eps);
  return 1000.0 *
         Eigen::Vector3d(ecl.x(), ce * ecl.y() - se * ecl.z(), se * ecl.y() + ce * ecl.z());
}

Ecliptic SunEcliptic(double t, bool of_date) {
  Ecliptic e{};
  if (of_date) {
    const double m = kTwoPi * Frac(0.993133 + 99.997361 * t);
    e.lon = kTwoPi *
            Frac(0.7859453 + m / kTwoPi +
                 (6893.0 * std::sin(m) + 72.0 * std::sin(2.0 * m) + 6191.2 * t) / kArcsecPerTurn);
    e.r_km = 149.619e6 - 2.499e6 * std::cos(m) - 0.021e6 * std::cos(2.0 * m);
  } else {
    const double m = kTwoPi * Frac(0.9931267 + 99.9973583 * t);
    e.lon = kTwoPi * Frac(0.7859444 + m / kTwoPi +
                          (6892.0 * std::sin(m) + 72.0 * std::sin(2.0 * m)) / kArcsecPerTurn);
    e.r_km = 149.619e6 - 2.499e6 * std::cos(m) - 0.021e6 * std::cos(2.0 * m);
  }
  e.lat = 0.0;
  return e;
}

Ecliptic MoonEcliptic(double t, bool of_date) {
  const double l0 = Frac(0.606433 + (of_date ? 1336.855225 : 1336.851344) * t);
  const double l = kTwoPi * Frac(0.374897 + 1325.552410 * t);
  const double lp = kTwoPi * Frac(0.993133 + 99.997361 * t);
  const double d = kTwoPi * Frac(0.827361 + 1236.853086 * t);
  const double f = kTwoPi * Frac(0.259086 + 1342.227825 * t);
  const double dl =
      22640.0 * std::sin(l) + 769.0 * std::sin(2.0 * l) - 4586.0 * std::sin(l - 2.0 * d) +
      2370.0 * std::sin(2.0 * d) - 668.0 * std::sin(lp) - 412.0 * std::sin(2.0 * f) -
      212.0 * std::sin(2.0 * l - 2.0 * d) - 206.0 * std::sin(l + lp - 2.0 * d) +
      192.0 * std::sin(l + 2.0 * d) - 165.0 * std::sin(lp - 2.0 * d) + 148.0 * std::sin(l - lp) -
      125.0 * std::sin(d) - 110.0 * std::sin(l + lp) - 55.0 * std::sin(2.0 * f - 2.0 * d);
  Ecliptic e{};
  e.lon = kTwoPi * Frac(l0 + dl / kArcsecPerTurn);
  const double s = f + (dl + 412.0 * std::sin(2.0 * f) + 541.0 * std::sin(lp)) / kArcsecPerRad;
  const double h = f - 2.0 * d;
  const double n = -526.0 * std::sin(h) + 44.0 * std::sin(l + h) - 31.0 * std::sin(-l + h) -
                   23.0 * std::sin(lp + h) + 11.0 * std::sin(-lp + h) -
                   25.0 * std::sin(-2.0 * l + f) + 21.0 * std::sin(-l + f);
  e.lat = (18520.0 * std::sin(s) + n) / kArcsecPerRad;
  e.r_km = 385000.0 - 20905.0 * std::cos(l) - 3699.0 * std::cos(2.0 * d - l) -
           2956.0 * std::cos(2.0 * d) - 570.0 * std::cos(2.0 * l) +
           246.0 * std::cos(2.0 * l - 2.0 * d) - 205.0 * std::cos(lp - 2.0 * d) -
           171.0 * std::cos(l + 2.0 * d) - 152.0 * std::cos(l + lp - 2.0 * d);
  return e;
}

// Refers of-date ecliptic coordinates at T to the equinox of T_frame.
Ecliptic RemovePrecession(Ecliptic e, double t, double t_frame) {
  e.lon -= kPrecessionArcsecPerCentury * (t - t_frame) / kArcsecPerRad;
  return e;
}

}  // namespace

double MeanObliquityRad(double jd_tt) {
  CheckJd(jd_tt, "MeanObliquityRad", "jd_tt");
  return (23.43929111 - 0.0130042 * Centuries(jd_tt)) * kDeg;
}

Eigen::Vector3d SunPositionJ2000(double jd_tt) {
  CheckJd(jd_tt, "SunPositionJ2000", "jd_tt");
  return ToEquatorial(SunEcliptic(Centuries(jd_tt), false), 23.43929111 * kDeg);
}

Eigen::Vector3d MoonPositionJ2000(double jd_tt) {
  CheckJd(jd_tt, "MoonPositionJ2000", "jd_tt");
  return ToEquatorial(MoonEcliptic(Centuries(jd_tt), false), 23.43929111 * kDeg);
}

Eigen::Vector3d SunPositionMeanOfEpoch(double jd_tt, double jd_frame_tt) {
  CheckJd(jd_tt, "SunPositionMeanOfEpoch", "jd_tt");
  CheckJd(jd_frame_tt, "SunPositionMeanOfEpoch", "jd_frame_tt");
  const double t = Centuries(jd_tt), t0 = Centuries(jd_frame_tt);
  return ToEquatorial(RemovePrecession(SunEcliptic(t, true), t, t0), MeanObliquityRad(jd_frame_tt));
}

Eigen::Vector3d MoonPositionMeanOfEpoch(double jd_tt, double jd_frame_tt) {
  CheckJd(jd_tt, "MoonPositionMeanOfEpoch", "jd_tt");
  CheckJd(jd_frame_tt, "MoonPositionMeanOfEpoch", "jd_frame_tt");
  const double t = Centuries(jd_tt), t0 = Centuries(jd_frame_tt);
  return ToEquatorial(RemovePrecession(MoonEcliptic(t, true), t, t0),
                      MeanObliquityRad(jd_frame_tt));
}

}  // namespace thrustsched::dynamics
