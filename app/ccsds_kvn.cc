#include "app/ccsds_kvn.h"

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "common/constants.h"

namespace thrustsched::app {
namespace {

// An epoch is written to the millisecond when it is this close (ms) to a
// whole one (1 us), to the microsecond otherwise.
constexpr double kWholeMillisecondSlack_ms = 1e-3;

// Unix time of 2000-01-01T00:00:00Z (Epoch supports years from 1972 only).
constexpr long long kUnixSecondsAt2000 = 946684800LL;

std::string Trim(std::string_view s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return std::string(s.substr(a, b - a));
}

bool IsKeyword(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s) {
    if (!(std::isupper(static_cast<unsigned char>(c)) ||
          std::isdigit(static_cast<unsigned char>(c)) || c == '_')) {
      return false;
    }
  }
  return std::isupper(static_cast<unsigned char>(s[0])) != 0;
}

std::string Upper(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

// Splits "value [units]" into the value and the units.
void SplitUnits(const std::string& rest, KvnLine* line) {
  const size_t open = rest.rfind('[');
  if (open != std::string::npos && !rest.empty() && rest.back() == ']') {
    line->units = Trim(std::string_view(rest).substr(open + 1, rest.size() - open - 2));
    line->value = Trim(std::string_view(rest).substr(0, open));
  } else {
    line->value = rest;
  }
}

dynamics::Epoch FromUnixSeconds(long long seconds) {
  return dynamics::Epoch::Parse("2000-01-01T00:00:00Z")
      .PlusSeconds(static_cast<double>(seconds - kUnixSecondsAt2000));
}

}  // namespace

std::vector<KvnLine> ReadKvn(std::string_view text) {
  std::vector<KvnLine> out;
  int number = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    ++number;
    const std::string t = Trim(text.substr(pos, end - pos));
    pos = end + 1;
    if (t.empty()) continue;
    KvnLine l;
    l.number = number;
    l.text = t;
    const size_t eq = t.find('=');
    const std::string first = Trim(t.substr(0, t.find_first_of(" \t=")));
    if (first == "COMMENT") {
      l.kind = KvnLine::kComment;
      l.keyword = "COMMENT";
      l.value = Trim(std::string_view(t).substr(7));
    } else if (eq != std::string::npos && IsKeyword(Trim(std::string_view(t).substr(0, eq)))) {
      l.kind = KvnLine::kKeyValue;
      l.keyword = Trim(std::string_view(t).substr(0, eq));
      SplitUnits(Trim(std::string_view(t).substr(eq + 1)), &l);
    } else if (IsKeyword(t)) {
      l.kind = KvnLine::kMarker;
      l.keyword = t;
    } else {
      l.kind = KvnLine::kData;
    }
    out.push_back(l);
    if (end == text.size()) break;
  }
  return out;
}

void KvnFail(const std::string& source, const KvnLine& line, const std::string& why) {
  const std::string what =
      line.kind == KvnLine::kKeyValue ? line.keyword + " = " + line.value : line.text;
  throw ScenarioError(source + ":" + std::to_string(line.number) + ": " + what + ": " + why);
}

double KvnNumber(const std::string& source, const KvnLine& line, std::string_view units) {
  const std::string& s = line.value;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v))
    KvnFail(source, line, "not a finite number");
  if (!line.units.empty() && Upper(line.units) != Upper(units)) {
    KvnFail(source, line,
            "units [" + line.units + "] where " +
                (units.empty() ? "none" : "[" + std::string(units) + "]") + " are expected");
  }
  return v;
}

dynamics::TimeScale KvnTimeSystem(const std::string& source, const KvnLine& line) {
  for (auto scale : {dynamics::TimeScale::kUtc, dynamics::TimeScale::kTai, dynamics::TimeScale::kTt,
                     dynamics::TimeScale::kGps}) {
    if (line.value == dynamics::ToString(scale)) return scale;
  }
  KvnFail(source, line, "unsupported time system (supported: UTC, TAI, TT, GPS)");
}

dynamics::InertialFrame KvnFrame(const std::string& source, const KvnLine& line) {
  if (auto f = dynamics::ParseInertialFrame(line.value)) return *f;
  KvnFail(
      source, line,
      "unsupported reference frame (supported: EME2000, also spelt J2000, and GCRF; Earth-fixed, "
      "true-of-date and TEME states must be converted first)");
}

void KvnCheckCenter(const std::string& source, const KvnLine& line) {
  if (line.value != "EARTH")
    KvnFail(source, line, "unsupported centre (the GEO models are geocentric: EARTH)");
}

dynamics::Epoch ParseCcsdsEpoch(std::string_view text, dynamics::TimeScale scale) {
  std::string s(text);
  if (!s.empty() && (s.back() == 'Z' || s.back() == 'z')) s.pop_back();
  // Day-of-year form YYYY-DDDThh:mm:ss: rewritten as January 1 plus days.
  const bool doy = s.size() >= 9 && s[4] == '-' && std::isdigit(static_cast<unsigned char>(s[5])) &&
                   std::isdigit(static_cast<unsigned char>(s[6])) &&
                   std::isdigit(static_cast<unsigned char>(s[7])) && (s[8] == 'T' || s[8] == 't');
  const size_t colon = s.find(':');
  if (colon != std::string::npos && s.size() >= colon + 6 && s.compare(colon + 4, 2, "60") == 0) {
    throw std::invalid_argument("a leap second (ss = 60) cannot be represented");
  }
  if (!doy) return dynamics::UtcFromScale(dynamics::Epoch::Parse(s), scale);
  const int day = std::atoi(s.substr(5, 3).c_str());
  const int year = std::atoi(s.substr(0, 4).c_str());
  const int days_in_year = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0 ? 366 : 365;
  if (day < 1 || day > days_in_year) {
    throw std::invalid_argument("day of year " + std::to_string(day) + " not in 1.." +
                                std::to_string(days_in_year));
  }
  const dynamics::Epoch jan1 = dynamics::Epoch::Parse(s.substr(0, 4) + "-01-01T" + s.substr(9));
  return dynamics::UtcFromScale(jan1.PlusSeconds((day - 1) * common::kSecondsPerDay), scale);
}

dynamics::Epoch KvnEpoch(const std::string& source, const KvnLine& line,
                         dynamics::TimeScale scale) {
  try {
    return ParseCcsdsEpoch(line.value, scale);
  } catch (const std::invalid_argument& e) {
    KvnFail(source, line,
            std::string(
                "not a CCSDS epoch (YYYY-MM-DDThh:mm:ss[.d][Z] or YYYY-DDDThh:mm:ss[.d][Z]): ") +
                e.what());
  }
}

std::string CcsdsEpochText(const dynamics::Epoch& epoch) {
  const double ms = epoch.seconds_of_day() * 1e3;
  const bool whole_ms = std::abs(ms - std::round(ms)) < kWholeMillisecondSlack_ms;
  return epoch.FormatUtc(whole_ms ? 3 : 6, false);
}

std::string KvnKeyValue(std::string_view keyword, std::string_view value, std::string_view units) {
  std::string out(keyword);
  if (out.size() < 20) out.resize(20, ' ');
  out += " = ";
  out += value;
  if (!units.empty()) out += " [" + std::string(units) + "]";
  return out;
}

std::string KvnHeader(std::string_view version_keyword, std::string_view version,
                      const std::vector<std::string>& comments,
                      const dynamics::Epoch& creation_date, std::string_view originator) {
  std::string out = KvnKeyValue(version_keyword, version) + "\n";
  for (const std::string& c : comments) out += "COMMENT " + c + "\n";
  out += KvnKeyValue("CREATION_DATE", CcsdsEpochText(creation_date)) + "\n";
  out += KvnKeyValue("ORIGINATOR", originator) + "\n";
  return out;
}

std::string KvnFixed(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, value);
  return buf;
}

dynamics::Epoch CreationDate() {
  if (const char* sde = std::getenv("SOURCE_DATE_EPOCH")) {
    char* end = nullptr;
    const long long v = std::strtoll(sde, &end, 10);
    if (*sde == '\0' || *end != '\0') {
      throw ScenarioError(
          std::string(
              "SOURCE_DATE_EPOCH: expected whole seconds since 1970-01-01T00:00:00Z, got \"") +
          sde + "\"");
    }
    return Wrap("SOURCE_DATE_EPOCH", [&] { return FromUnixSeconds(v); });
  }
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return FromUnixSeconds(std::chrono::duration_cast<std::chrono::seconds>(now).count());
}

}  // namespace thrustsched::app
