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
// Time scales (dynamics.md §5.8): UT1 is taken equal to UTC (|UT1 - UTC| < 0.9 s,
// i.e. < 4e-3 deg of Earth rotation); TT = UTC + (TAI - UTC) + 32.184 s with the
// leap-second table below (TAI - UTC = 37 s since 2017-01-01, also used for all
// later dates: no leap second has been announced since, and the CGPM decided
// in 2022 to stop inserting them by 2035).
#ifndef THRUSTSCHED_DYNAMICS_TIME_H_
#define THRUSTSCHED_DYNAMICS_TIME_H_

#include <cstdint>
#include <string>
#include <string_view>

namespace thrustsched::dynamics {

/// Seconds per day and the Julian date of J2000.0 (2000-01-01 12:00 TT).
inline constexpr double kSecondsPerDay = 86400.0;
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

/// Greenwich mean sidereal time (rad, in [0, 2 pi)) at the UT1 Julian date,
/// IAU 1982 expression (Meeus 12.4):
///   GMST = 280.46061837 deg + 360.98564736629 deg d + 0.000387933 deg T^2 - T^3/38710000 deg,
///   d = JD_UT1 - 2451545.0, T = d / 36525.
/// The angle is measured from the mean equinox of date.
/// @throws std::invalid_argument if jd_ut1 is not finite.
double GmstRad(double jd_ut1);

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_TIME_H_
