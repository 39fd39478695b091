// Number formatting of the cells of report.md, shared by its sections
// (report.cc, report_conjunction.cc): "-" for a missing value.
//
//   md << "| " << bench::fmt::G(ratio) << " | " << bench::fmt::Sec(seconds) << " |\n";
//   // "1.013", "38.2"; G(NaN) and Sec(NaN) give "-", Sec(inf) "not reached"
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_FORMAT_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_FORMAT_H_

#include <cmath>
#include <cstdio>
#include <string>

namespace thrustsched::bench::fmt {

/// `sig` significant digits.
inline std::string G(double v, int sig = 4) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*g", sig, v);
  return buf;
}

/// Seconds with a precision that follows the magnitude.
inline std::string Sec(double v) {
  if (std::isnan(v)) return "-";
  if (std::isinf(v)) return "not reached";
  char buf[64];
  if (v < 0.01) std::snprintf(buf, sizeof(buf), "%.4f", v);
  else if (v < 1) std::snprintf(buf, sizeof(buf), "%.3g", v);
  else if (v < 10) std::snprintf(buf, sizeof(buf), "%.2f", v);
  else std::snprintf(buf, sizeof(buf), "%.1f", v);
  return buf;
}

/// A fraction as a percentage, two decimals.
inline std::string Pct(double v) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.2f %%", 100.0 * v);
  return buf;
}

/// Scientific notation, three digits; "0" for zero.
inline std::string Sci(double v) {
  if (std::isnan(v)) return "-";
  if (v == 0.0) return "0";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.2e", v);
  return buf;
}

}  // namespace thrustsched::bench::fmt

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_FORMAT_H_
