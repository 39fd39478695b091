#include "app/format_units.h"

#include <cmath>
#include <cstdio>

namespace thrustsched::app {
namespace {

std::string ThreeDigits(double v, const char* unit) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.3g %s", v, unit);
  return buf;
}

}  // namespace

std::string FormatSignificant(double v, int digits) {
  if (std::isnan(v)) return "n/a";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[48];
  std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
  return buf;
}

std::string FormatPercent(double fraction) {
  if (std::isnan(fraction)) return "n/a";
  if (std::isinf(fraction)) return fraction > 0 ? "inf %" : "-inf %";
  if (std::abs(fraction) < kZeroGap) return "0 %";
  return ThreeDigits(100.0 * fraction, "%");
}

std::string FormatDuration(double seconds) {
  if (std::isnan(seconds)) return "n/a";
  if (std::isinf(seconds)) return seconds > 0 ? "inf" : "-inf";
  const double a = std::abs(seconds);
  if (a < 120.0) return ThreeDigits(seconds, "s");
  if (a < 7200.0) return ThreeDigits(seconds / 60.0, "min");
  if (a < 10 * 86400.0) return ThreeDigits(seconds / 3600.0, "h");
  return ThreeDigits(seconds / 86400.0, "d");
}

}  // namespace thrustsched::app
