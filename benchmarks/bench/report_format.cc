#include "benchmarks/bench/report_format.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "benchmarks/bench/report.h"
#include "common/format.h"

namespace thrustsched::bench {

using common::FormatG;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

std::string G(double v, int sig) {
  if (!std::isfinite(v)) return "-";
  return FormatG(v, sig);
}

std::string Sec(double v) {
  if (std::isnan(v)) return "-";
  if (std::isinf(v)) return "not reached";
  char buf[64];
  if (v < 0.01)
    std::snprintf(buf, sizeof(buf), "%.4f", v);
  else if (v < 1)
    std::snprintf(buf, sizeof(buf), "%.3g", v);
  else if (v < 10)
    std::snprintf(buf, sizeof(buf), "%.2f", v);
  else
    std::snprintf(buf, sizeof(buf), "%.1f", v);
  return buf;
}

std::string Fixed1(double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.1f", v);
  return buf;
}

std::string Pct(double v) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.2f %%", 100.0 * v);
  return buf;
}

std::string Sci(double v) {
  if (std::isnan(v)) return "-";
  if (v == 0.0) return "0";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.2e", v);
  return buf;
}

std::string MdTable::Str() const {
  std::ostringstream os;
  auto line = [&os](const std::vector<std::string>& cells) {
    os << "|";
    for (const std::string& c : cells) {
      std::string e;  // a '|' inside a cell would end it
      for (char ch : c) e += ch == '|' ? std::string("\\|") : std::string(1, ch);
      os << " " << (e.empty() ? "-" : e) << " |";
    }
    os << "\n";
  };
  line(header_);
  os << "|";
  for (size_t i = 0; i < header_.size(); ++i) os << "---|";
  os << "\n";
  for (const auto& r : rows_) line(r);
  return os.str();
}

// Median treating NaN as "not reached" (+inf) when `missing_is_inf`.
double MedianOf(std::vector<double> v, bool missing_is_inf) {
  if (missing_is_inf) {
    for (double& x : v) {
      if (std::isnan(x)) x = kInf;
    }
  }
  return Median(v);
}

std::string Verdict(double value, double limit) {
  if (std::isnan(value)) return "not measured";
  if (std::isinf(value)) return "**missed**: not reached within the time limit";
  if (value < limit) return "met (" + G(100.0 * value / limit, 3) + " % of the limit)";
  return "**missed** by " + Sec(value - limit) + " s (" + G(value / limit, 3) + "x the limit)";
}

}  // namespace thrustsched::bench
