#include "benchmarks/bench/report_index.h"

#include <algorithm>
#include <cmath>

#include "benchmarks/bench/report_format.h"

namespace thrustsched::bench::report_internal {

int ExpectedOrder(const std::string& scheme) {
  if (scheme == "frozen_start" || scheme == "euler") return 1;
  if (scheme == "frozen_mid" || scheme == "trapezoid") return 2;
  if (scheme == "hermite_simpson" || scheme == "rk4") return 4;
  return 0;
}

std::string MedSpread(const Group& g, const std::string& col, bool missing_is_inf) {
  std::vector<double> v = g.Values(col);
  const double med = MedianOf(v, missing_is_inf);
  if (v.size() <= 1) return Sec(med);
  double lo = kInf, hi = -kInf;
  int n = 0;
  for (double x : v) {
    if (std::isnan(x)) x = missing_is_inf ? kInf : x;
    if (std::isnan(x)) continue;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    ++n;
  }
  return Sec(med) + " (" + Sec(lo) + "-" + Sec(hi) + ", n=" + std::to_string(n) + ")";
}

std::string StatusCell(const Group& g) {
  std::map<std::string, int> count;
  for (const Row* r : g.rows) ++count[r->Get("status")];
  std::string s;
  for (const auto& [k, n] : count) {
    s += (s.empty() ? "" : ", ") + (k.empty() ? std::string("-") : k) +
         (g.rows.size() > 1 ? " x" + std::to_string(n) : "");
  }
  return s;
}

std::string CheckerCell(const Group& g) {
  const Row& r = g.first();
  if (!r.Has("operational_ok")) return "-";
  std::string s = r.Get("operational_ok") == "1" ? "rules ok" : "**rules violated**";
  const double v = r.Num("max_window_violation");
  const double vn = r.Num("max_window_violation_nodes");
  const std::string unit = r.Get("window_unit");
  s += ", window " + G(vn, 3) + " " + unit + " at nodes / " + G(v, 3) + " " + unit + " overall";
  if (r.Has("max_window_violation_nonlinear_deg")) {
    s += ", nonlinear " + G(r.Num("max_window_violation_nonlinear_deg"), 3) + " deg";
  }
  if (r.Has("terminal_ok") && r.Get("terminal_ok") == "0") {
    s += ", **terminal violated** (" + G(r.Num("terminal_error"), 3) + " x scale)";
  }
  return s;
}

double HorizonDays(const Group& g) { return g.Num("horizon_s") / kDay; }

}  // namespace thrustsched::bench::report_internal
