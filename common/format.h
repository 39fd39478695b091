// Number formatting shared by every module: one rule, the precision chosen at
// each call site. `FormatG(v, digits)` is printf's "%.*g" (the same text as an
// ostream's default floating format with precision `digits`), so a message,
// model file or CSV column keeps exactly the digits it always had.
//
//   throw std::invalid_argument("step_s must be > 0, got " + common::FormatG(step, 10));
//   out << common::FormatG(x, 17);  // round-trips every double
#ifndef THRUSTSCHED_COMMON_FORMAT_H_
#define THRUSTSCHED_COMMON_FORMAT_H_

#include <cstdio>
#include <string>

namespace thrustsched::common {

/// `v` with `digits` significant digits, "%g" style: no trailing zeros,
/// exponent notation for very large or small magnitudes, "inf"/"nan" as the C
/// library writes them. 17 digits round-trip any double.
inline std::string FormatG(double v, int digits) {
  char buf[64];
  const int n = std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
  return std::string(buf, n > 0 ? static_cast<size_t>(n) : 0);
}

}  // namespace thrustsched::common

#endif  // THRUSTSCHED_COMMON_FORMAT_H_
