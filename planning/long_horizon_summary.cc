// The totals and distributions of a long-horizon run (LongHorizonSummary,
// planning/long_horizon.h).
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/constants.h"
#include "planning/long_horizon.h"

namespace thrustsched::planning {

Distribution Distribute(std::vector<double> values) {
  values.erase(
      std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
      values.end());
  Distribution d;
  d.count = static_cast<int>(values.size());
  if (values.empty()) return d;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  d.median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  const size_t rank = static_cast<size_t>(std::ceil(0.9 * static_cast<double>(n)));
  d.p90 = values[std::max<size_t>(rank, 1) - 1];
  d.max = values.back();
  double s = 0.0;
  for (double v : values) s += v;
  d.mean = s / static_cast<double>(n);
  return d;
}

LongHorizonSummary Summarize(const std::vector<CycleRecord>& cycles,
                             const dynamics::ThrusterSet& thrusters) {
  LongHorizonSummary s;
  const int m = thrusters.size();
  s.on_time_s.assign(m, 0.0);
  s.thrust_days.assign(m, 0.0);
  std::vector<double> solve, gap, wall, cpu;
  for (const CycleRecord& c : cycles) {
    ++s.cycles;
    s.simulated_s += c.applied_end_s - c.start_s;
    s.consumption_l1_m_s += c.consumption_l1_m_s;
    s.delta_v_m_s += c.delta_v_m_s;
    s.propellant_kg += c.propellant_kg;
    s.normal_delta_v_m_s += c.normal_delta_v_m_s;
    s.burns += static_cast<int>(c.burns.size());
    for (int i = 0; i < m && i < static_cast<int>(c.on_time_s.size()); ++i) {
      s.on_time_s[i] += c.on_time_s[i];
    }
    s.time_outside_window_s += c.time_outside_window_s;
    s.max_abs_lat_deg = std::max(s.max_abs_lat_deg, c.max_abs_lat_deg);
    s.max_abs_lon_deg = std::max(s.max_abs_lon_deg, c.max_abs_lon_deg);
    if (c.max_window_violation_deg > s.max_window_violation_deg) {
      s.max_window_violation_deg = c.max_window_violation_deg;
      s.worst_time_s = c.worst_time_s;
    }
    switch (c.fallback) {
      case Fallback::kNone:
        break;
      case Fallback::kSoftWindow:
        ++s.fallback_soft_window;
        break;
      case Fallback::kSoftWindowFreeTerminal:
        ++s.fallback_free_terminal;
        break;
      case Fallback::kZeroThrust:
        ++s.fallback_zero_thrust;
        break;
    }
    if (!c.controllable) ++s.uncontrollable_cycles;
    if (c.status == milp::SolveStatus::kFeasible) ++s.time_limited_cycles;
    s.rules_ok = s.rules_ok && c.rules_ok;
    solve.push_back(c.solve_seconds);
    gap.push_back(c.gap);
    wall.push_back(c.wall_seconds);
    cpu.push_back(c.cpu_seconds);
    s.wall_seconds_total += c.wall_seconds;
    s.cpu_seconds_total += c.cpu_seconds;
  }
  for (int i = 0; i < m; ++i) {
    s.thrust_days[i] = s.on_time_s[i] / common::kSecondsPerDay;
    const ThrusterFaces f = FacesOf(thrusters.thruster(i));
    if (f.north) s.north_days += s.thrust_days[i];
    if (f.south) s.south_days += s.thrust_days[i];
    if (f.east) s.east_days += s.thrust_days[i];
    if (f.west) s.west_days += s.thrust_days[i];
  }
  s.solve_seconds = Distribute(solve);
  s.gap = Distribute(gap);
  s.wall_seconds = Distribute(wall);
  s.cpu_seconds = Distribute(cpu);
  return s;
}

}  // namespace thrustsched::planning
