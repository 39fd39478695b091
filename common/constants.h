// Physical and mathematical constants used by several modules, spelled once.
//
//   const double days = t_s / common::kSecondsPerDay;
//   const double lon_rad = lon_deg * common::kDegToRad;
#ifndef THRUSTSCHED_COMMON_CONSTANTS_H_
#define THRUSTSCHED_COMMON_CONSTANTS_H_

namespace thrustsched::common {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegToRad = kPi / 180.0;
inline constexpr double kRadToDeg = 180.0 / kPi;
/// A day of the time scales used here (UTC days with a leap second are the
/// time module's business, dynamics/time.h).
inline constexpr double kSecondsPerDay = 86400.0;
/// Standard gravity g0 of the specific impulse (mass flow = thrust / (g0 Isp)).
inline constexpr double kStandardGravity_m_s2 = 9.80665;
/// Earth's gravitational parameter and equatorial (geopotential reference)
/// radius, EGM2008 / IERS values.
inline constexpr double kEarthMu_m3_s2 = 3.986004418e14;
inline constexpr double kEarthRadius_m = 6378137.0;

}  // namespace thrustsched::common

#endif  // THRUSTSCHED_COMMON_CONSTANTS_H_
