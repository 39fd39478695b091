#include "dynamics/time.h"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "common/constants.h"

namespace thrustsched::dynamics {
namespace {

using common::kPi;
constexpr int kMinYear = 1972;
constexpr int kMaxYear = 2199;

// Days from 1970-01-01 to the proleptic Gregorian date y-m-d (H. Hinnant's
// days_from_civil algorithm).
std::int64_t DaysFromCivil(std::int64_t y, int m, int d) {
  y -= m <= 2 ? 1 : 0;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t yoe = y - era * 400;
  const std::int64_t doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const std::int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

struct CivilDate {
  std::int64_t year;
  int month;
  int day;
};

CivilDate CivilFromDays(std::int64_t z) {
  z += 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const std::int64_t doe = z - era * 146097;
  const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const std::int64_t mp = (5 * doy + 2) / 153;
  const int d = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  const int m = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  return {yoe + era * 400 + (m <= 2 ? 1 : 0), m, d};
}

constexpr std::int64_t kMjdOfUnixEpoch = 40587;  // 1970-01-01

std::int64_t MjdFromCivil(std::int64_t y, int m, int d) {
  return DaysFromCivil(y, m, d) + kMjdOfUnixEpoch;
}

bool IsLeapYear(std::int64_t y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

int DaysInMonth(std::int64_t y, int m) {
  static constexpr std::array<int, 12> kDays = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && IsLeapYear(y) ? 29 : kDays[m - 1];
}

// TAI - UTC steps (IERS Bulletin C): date from which the value applies.
struct LeapStep {
  int year, month;
  double tai_minus_utc;
};
constexpr std::array<LeapStep, 28> kLeapSteps = {{
    {1972, 1, 10}, {1972, 7, 11}, {1973, 1, 12}, {1974, 1, 13}, {1975, 1, 14}, {1976, 1, 15},
    {1977, 1, 16}, {1978, 1, 17}, {1979, 1, 18}, {1980, 1, 19}, {1981, 7, 20}, {1982, 7, 21},
    {1983, 7, 22}, {1985, 7, 23}, {1988, 1, 24}, {1990, 1, 25}, {1991, 1, 26}, {1992, 7, 27},
    {1993, 7, 28}, {1994, 7, 29}, {1996, 1, 30}, {1997, 7, 31}, {1999, 1, 32}, {2006, 1, 33},
    {2009, 1, 34}, {2012, 7, 35}, {2015, 7, 36}, {2017, 1, 37},
}};

[[noreturn]] void ThrowBadText(std::string_view text, const std::string& why) {
  throw std::invalid_argument("Epoch::Parse: cannot parse '" + std::string(text) +
                              "' as an ISO 8601 UTC time (YYYY-MM-DDThh:mm:ssZ): " + why);
}

// Reads exactly `width` digits at `pos`.
bool ReadDigits(std::string_view s, std::size_t& pos, int width, int* value) {
  if (pos + width > s.size()) return false;
  int v = 0;
  for (int k = 0; k < width; ++k) {
    const char c = s[pos + k];
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    v = 10 * v + (c - '0');
  }
  pos += width;
  *value = v;
  return true;
}

void CheckYear(std::int64_t year, const std::string& where) {
  if (year < kMinYear || year > kMaxYear) {
    throw std::invalid_argument(where + ": year " + std::to_string(year) +
                                " outside the supported range " + std::to_string(kMinYear) + ".." +
                                std::to_string(kMaxYear));
  }
}

// The calendar fields of (mjd, seconds of day) rounded to 1/ticks_per_second s
// (a rounding up to midnight carries into the next day).
struct CalendarLabel {
  CivilDate date;
  long long whole_seconds;  // of the day
  long long ticks;          // fraction of the second, in 1/ticks_per_second
};

CalendarLabel Label(std::int64_t mjd, double seconds, long long ticks_per_second) {
  long long ticks = std::llround(seconds * static_cast<double>(ticks_per_second));
  const long long day = 86400LL * ticks_per_second;
  if (ticks >= day) {
    ticks -= day;
    ++mjd;
  }
  return {CivilFromDays(mjd - kMjdOfUnixEpoch), ticks / ticks_per_second, ticks % ticks_per_second};
}

std::string DateTime(const CalendarLabel& l) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%04lld-%02d-%02dT%02lld:%02lld:%02lld",
                static_cast<long long>(l.date.year), l.date.month, l.date.day,
                l.whole_seconds / 3600, (l.whole_seconds / 60) % 60, l.whole_seconds % 60);
  return buf;
}

}  // namespace

Epoch Epoch::Parse(std::string_view text) {
  std::size_t pos = 0;
  int year = 0, month = 0, day = 0, hour = 0, minute = 0;
  double seconds = 0.0;
  if (!ReadDigits(text, pos, 4, &year)) ThrowBadText(text, "expected a 4-digit year");
  if (pos >= text.size() || text[pos] != '-') ThrowBadText(text, "expected '-' after the year");
  ++pos;
  if (!ReadDigits(text, pos, 2, &month)) ThrowBadText(text, "expected a 2-digit month");
  if (pos >= text.size() || text[pos] != '-') ThrowBadText(text, "expected '-' after the month");
  ++pos;
  if (!ReadDigits(text, pos, 2, &day)) ThrowBadText(text, "expected a 2-digit day");
  if (pos < text.size()) {
    if (text[pos] != 'T' && text[pos] != 't' && text[pos] != ' ') {
      ThrowBadText(text, "expected 'T' after the date");
    }
    ++pos;
    if (!ReadDigits(text, pos, 2, &hour)) ThrowBadText(text, "expected a 2-digit hour");
    if (pos >= text.size() || text[pos] != ':') ThrowBadText(text, "expected ':' after the hour");
    ++pos;
    if (!ReadDigits(text, pos, 2, &minute)) ThrowBadText(text, "expected 2-digit minutes");
    if (pos < text.size() && text[pos] == ':') {
      ++pos;
      int whole = 0;
      if (!ReadDigits(text, pos, 2, &whole)) ThrowBadText(text, "expected 2-digit seconds");
      seconds = whole;
      if (pos < text.size() && (text[pos] == '.' || text[pos] == ',')) {
        ++pos;
        double scale = 0.1;
        int n = 0;
        while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) {
          if (n < 15) seconds += scale * (text[pos] - '0');
          scale *= 0.1;
          ++pos;
          ++n;
        }
        if (n == 0) ThrowBadText(text, "expected digits after the decimal point");
      }
    }
    const std::string_view zone = text.substr(pos);
    if (!(zone.empty() || zone == "Z" || zone == "z" || zone == "+00:00" || zone == "+0000" ||
          zone == "+00")) {
      ThrowBadText(text, "only UTC ('Z' or '+00:00') is accepted, got '" + std::string(zone) + "'");
    }
  }
  if (month < 1 || month > 12)
    ThrowBadText(text, "month " + std::to_string(month) + " not in 1..12");
  if (day < 1 || day > DaysInMonth(year, month)) {
    ThrowBadText(text, "day " + std::to_string(day) + " not in 1.." +
                           std::to_string(DaysInMonth(year, month)));
  }
  if (hour > 23) ThrowBadText(text, "hour " + std::to_string(hour) + " not in 0..23");
  if (minute > 59) ThrowBadText(text, "minute " + std::to_string(minute) + " not in 0..59");
  if (!(seconds < 60.0))
    ThrowBadText(text, "seconds must be < 60 (leap seconds are not representable)");
  CheckYear(year, "Epoch::Parse: '" + std::string(text) + "'");
  return Epoch(MjdFromCivil(year, month, day), 3600.0 * hour + 60.0 * minute + seconds);
}

double Epoch::JulianDateUtc() const {
  return static_cast<double>(mjd_) + 2400000.5 + seconds_ / kSecondsPerDay;
}

double Epoch::TaiMinusUtc() const {
  double value = kLeapSteps[0].tai_minus_utc;
  for (const LeapStep& step : kLeapSteps) {
    if (mjd_ >= MjdFromCivil(step.year, step.month, 1)) value = step.tai_minus_utc;
  }
  return value;
}

double Epoch::JulianDateTt() const {
  // Add the offset to the seconds before forming the date to keep precision.
  return static_cast<double>(mjd_) + 2400000.5 +
         (seconds_ + TaiMinusUtc() + 32.184) / kSecondsPerDay;
}

std::string Epoch::ToIso8601() const {
  const CalendarLabel l = Label(mjd_, seconds_, 1000000LL);
  std::string out = DateTime(l);
  if (l.ticks != 0) {
    char fbuf[16];
    std::snprintf(fbuf, sizeof(fbuf), ".%06lld", l.ticks);
    std::string f(fbuf);
    while (f.back() == '0') f.pop_back();
    out += f;
  }
  out += 'Z';
  return out;
}

std::string Epoch::FormatUtc(int decimals, bool zulu) const {
  if (decimals < 0 || decimals > 9) {
    throw std::invalid_argument("Epoch::FormatUtc: decimals must be in 0..9, got " +
                                std::to_string(decimals));
  }
  long long ticks_per_second = 1;
  for (int k = 0; k < decimals; ++k) ticks_per_second *= 10;
  const CalendarLabel l = Label(mjd_, seconds_, ticks_per_second);
  std::string out = DateTime(l);
  if (decimals > 0) {
    char fbuf[16];
    std::snprintf(fbuf, sizeof(fbuf), ".%0*lld", decimals, l.ticks);
    out += fbuf;
  }
  if (zulu) out += 'Z';
  return out;
}

Epoch Epoch::PlusSeconds(double s) const {
  if (!std::isfinite(s)) {
    throw std::invalid_argument("Epoch::PlusSeconds: seconds must be finite, got " +
                                std::to_string(s));
  }
  const double total = seconds_ + s;
  const double days = std::floor(total / kSecondsPerDay);
  if (std::abs(days) > 1e6) {
    throw std::invalid_argument("Epoch::PlusSeconds: offset " + std::to_string(s) +
                                " s leaves the supported years");
  }
  std::int64_t mjd = mjd_ + static_cast<std::int64_t>(days);
  double sec = total - days * kSecondsPerDay;
  if (sec >= kSecondsPerDay) {  // rounding at the day boundary
    sec -= kSecondsPerDay;
    ++mjd;
  }
  if (sec < 0.0) sec = 0.0;
  CheckYear(CivilFromDays(mjd - kMjdOfUnixEpoch).year, "Epoch::PlusSeconds");
  return Epoch(mjd, sec);
}

double Epoch::SecondsSince(const Epoch& other) const {
  return static_cast<double>(mjd_ - other.mjd_) * kSecondsPerDay + (seconds_ - other.seconds_);
}

bool CrossesLeapSecond(const Epoch& from, double seconds) {
  return from.PlusSeconds(seconds).TaiMinusUtc() != from.TaiMinusUtc();
}

const char* ToString(TimeScale scale) {
  switch (scale) {
    case TimeScale::kUtc:
      return "UTC";
    case TimeScale::kTai:
      return "TAI";
    case TimeScale::kTt:
      return "TT";
    case TimeScale::kGps:
      return "GPS";
  }
  return "?";
}

Epoch UtcFromScale(const Epoch& label, TimeScale scale) {
  // Offset of the scale from TAI (s): label_TAI = label - offset.
  double tai_minus_label = 0.0;
  switch (scale) {
    case TimeScale::kUtc:
      return label;
    case TimeScale::kTai:
      tai_minus_label = 0.0;
      break;
    case TimeScale::kTt:
      tai_minus_label = -32.184;
      break;
    case TimeScale::kGps:
      tai_minus_label = 19.0;  // GPS time = TAI - 19 s (fixed since 1980-01-06)
      break;
  }
  const Epoch tai = label.PlusSeconds(tai_minus_label);
  // UTC = TAI - (TAI - UTC); TAI - UTC is looked up at the UTC instant, so
  // take it at the first guess and correct once (exact except inside the
  // leap second itself, which UTC labels here cannot represent).
  const Epoch guess = tai.PlusSeconds(-tai.TaiMinusUtc());
  return tai.PlusSeconds(-guess.TaiMinusUtc());
}

double GmstRad(double jd_ut1) {
  if (!std::isfinite(jd_ut1)) {
    throw std::invalid_argument("GmstRad: jd_ut1 must be finite, got " + std::to_string(jd_ut1));
  }
  const double d = jd_ut1 - kJulianDateJ2000;
  const double t = d / 36525.0;
  // 360.98564736629 d = 360 d + 0.98564736629 d: drop the whole turns first.
  const double frac_day = d - std::floor(d);
  double deg = 280.46061837 + 360.0 * frac_day + 0.98564736629 * d + 0.000387933 * t * t -
               t * t * t / 38710000.0;
  deg = std::fmod(deg, 360.0);
  if (deg < 0.0) deg += 360.0;
  return deg * kPi / 180.0;
}

}  // namespace thrustsched::dynamics
