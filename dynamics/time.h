// Calendar epochs and Earth-rotation angle for the GEO models.
//
// An Epoch is a UTC instant (calendar label). The dynamics run on a uniform
// time scale: model time t is SI seconds elapsed since the epoch, so
// TT(t) = TT(epoch) + t and no leap second is ever inserted inside a run.
//
//   auto e = dynamics::Epoch::Parse("2034-01-01T00:00:00Z");
//   double jd_utc = e.JulianDateUtc();          // 2463963.5
//   double jd_tt = e.JulianDateTt();            // + (37 + 32.184) s
//   double gmst = dynamics::GmstRad(jd_utc);    // 100.7225 deg (UT1 ~ UTC)
//   std::string s = e.PlusSeconds(3600).ToIso8601();   // "2034-01-01T01:00:00Z"
//
// Time scales: UT1 is taken equal to UTC (|UT1 - UTC| < 0.9 s, i.e. < 4e-3 deg
// of Earth rotation); TT = UTC + (TAI - UTC) + 32.184 s with the leap-second
// table of IERS Bulletin C (TAI - UTC = 37 s since 2017-01-01). The table is
// known to be complete up to kLeapSecondsKnownUntil (Bulletin C 70, July 2025:
// no leap second at the end of December 2025); later dates use the last value,
// 37 s (the CGPM decided in 2022, resolution 4, to stop inserting leap seconds
// by 2035). The whole chain (UTC labels, TT/TDB for the ephemerides, Earth
// rotation) and what an unannounced leap second would change are documented
// once, in data/scenarios/README.md, section 10.1.
//
//   std::string s = e.FormatUtc(3, true);                       // "2034-01-01T00:00:00.000Z"
//   Epoch utc = UtcFromScale(Epoch::Parse("2034-01-01T00:01:09.184"), TimeScale::kTt);
//                                                               // 2034-01-01T00:00:00Z
#ifndef THRUSTSCHED_DYNAMICS_TIME_H_
#define THRUSTSCHED_DYNAMICS_TIME_H_

#include <cstdint>
#include <string>
#include <string_view>

#include "common/constants.h"

namespace thrustsched::dynamics {

/// Seconds per day (shared by every module) and the Julian date of J2000.0
/// (2000-01-01 12:00 TT).
using common::kSecondsPerDay;
inline constexpr double kJulianDateJ2000 = 2451545.0;

/// A UTC instant, stored as a Modified Julian Day number and the seconds of
/// that UTC day (0 <= seconds < 86400). Years 1972..2199 are supported (the
/// range of the leap-second table plus its extrapolation).
class Epoch {
 public:
  /// 2000-01-01T12:00:00Z.
  Epoch() = default;

  /// Parses ISO 8601 "YYYY-MM-DDThh:mm:ss[.fff]Z". Also accepted: a space
  /// instead of 'T', no seconds ("hh:mm"), a missing 'Z', "+00:00" instead of
  /// 'Z', or a date alone ("2034-01-01" = midnight UTC). Only UTC is accepted.
  /// @throws std::invalid_argument naming the text if it does not match, a
  ///         field is out of range (month 1..12, day 1..days in month, hour
  ///         0..23, minute 0..59, second 0 <= s < 60) or the year is outside
  ///         1972..2199.
  static Epoch Parse(std::string_view iso8601);

  /// Julian date on the UTC clock (days; UT1 is taken equal to UTC).
  double JulianDateUtc() const;
  /// Julian date in Terrestrial Time, JD_UTC + (TAI-UTC + 32.184 s)/86400.
  double JulianDateTt() const;
  /// TAI - UTC in seconds at this instant (10 s in 1972 ... 37 s from 2017).
  double TaiMinusUtc() const;
  /// "YYYY-MM-DDThh:mm:ssZ", with up to 6 decimals of seconds when the
  /// instant is not a whole second (trailing zeros removed).
  std::string ToIso8601() const;
  /// "YYYY-MM-DDThh:mm:ss" with exactly `decimals` (0..9) decimals of seconds,
  /// rounded to the nearest (carries into the minute, hour and day), then 'Z'
  /// if `zulu`. @throws std::invalid_argument if decimals is outside 0..9.
  std::string FormatUtc(int decimals, bool zulu) const;
  /// The UTC label `s` seconds later (s may be negative). Leap seconds that
  /// would fall inside the interval are ignored (the UTC clock is treated as
  /// uniform). @throws std::invalid_argument if s is not finite or the result
  /// leaves the supported years.
  Epoch PlusSeconds(double s) const;
  /// UTC-clock seconds from `other` to this epoch (leap seconds ignored, as in
  /// PlusSeconds, so e.PlusSeconds(s).SecondsSince(e) == s up to rounding).
  double SecondsSince(const Epoch& other) const;

  std::int64_t modified_julian_day() const { return mjd_; }
  double seconds_of_day() const { return seconds_; }

  bool operator==(const Epoch& o) const { return mjd_ == o.mjd_ && seconds_ == o.seconds_; }
  bool operator!=(const Epoch& o) const { return !(*this == o); }

 private:
  Epoch(std::int64_t mjd, double seconds) : mjd_(mjd), seconds_(seconds) {}

  std::int64_t mjd_ = 51544;  // 2000-01-01
  double seconds_ = 43200.0;
};

/// Last instant up to which the leap-second table is known to be complete
/// (IERS Bulletin C 70 announced no leap second at the end of December 2025;
/// the next possible one is at the end of June 2026). Update it, and the
/// table in time.cc, with each new Bulletin C.
inline constexpr const char* kLeapSecondsKnownUntil = "2026-06-30T23:59:59Z";

/// True if the table's value of TAI - UTC changes between `from` and the
/// instant `seconds` later, i.e. a leap second of the table falls inside: UTC
/// labels computed with PlusSeconds are then off by the leap seconds after it.
bool CrossesLeapSecond(const Epoch& from, double seconds);

/// Time scales a calendar label can be given in (the TIME_SYSTEM values of
/// CCSDS 502.0-B-3 §3.2.3 that this library converts exactly).
enum class TimeScale { kUtc, kTai, kTt, kGps };
/// "UTC", "TAI", "TT", "GPS".
const char* ToString(TimeScale scale);
/// The UTC instant whose calendar label in `scale` is `label` (parsed as if
/// it were UTC): TAI = UTC + (TAI - UTC), TT = TAI + 32.184 s, GPS = TAI - 19 s.
/// @throws std::invalid_argument if the result leaves the supported years.
Epoch UtcFromScale(const Epoch& label, TimeScale scale);

/// Greenwich mean sidereal time (rad, in [0, 2 pi)) at the UT1 Julian date,
/// IAU 1982 expression (Meeus 12.4):
///   GMST = 280.46061837 deg + 360.98564736629 deg d + 0.000387933 deg T^2 - T^3/38710000 deg,
///   d = JD_UT1 - 2451545.0, T = d / 36525.
/// The angle is measured from the mean equinox of date.
/// @throws std::invalid_argument if jd_ut1 is not finite.
double GmstRad(double jd_ut1);

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_TIME_H_
