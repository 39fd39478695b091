// One long-horizon cycle after its solve: what the accepted schedule records,
// the applied part of the plan, and its nonlinear replay from the true state
// (internal/long_horizon_cycle.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "common/constants.h"
#include "dynamics/propagation.h"
#include "planning/internal/long_horizon_cycle.h"
#include "transcription/operations.h"

namespace thrustsched::planning::internal {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using common::kRadToDeg;
using Clock = std::chrono::steady_clock;

int Steps(double step, double value) { return static_cast<int>(std::llround(value / step)); }

}  // namespace

void RecordAccepted(const ScheduleResult& accepted, CycleRecord* rec) {
  rec->status = accepted.solve.status;
  rec->objective = accepted.solve.objective;
  rec->best_bound = accepted.solve.best_bound;
  rec->gap = accepted.solve.gap;
  rec->nodes = accepted.solve.nodes;
  if (!accepted.solve.incumbents.empty()) {
    rec->first_solution_seconds = accepted.solve.incumbents.front().wall_seconds;
  }
  rec->planned_burns = static_cast<int>(accepted.schedule.burns.size());
  if (accepted.checked) {
    rec->checked = true;
    rec->rules_ok = accepted.check.operational_ok;
    rec->linear_window_violation_deg = accepted.check.max_window_violation_at_nodes * kRadToDeg;
    if (rec->fallback != Fallback::kNone)
      rec->soft_violation_deg = rec->linear_window_violation_deg;
  }
}

void ApplyPlan(const std::vector<Burn>& planned, double applied_end_s,
               const dynamics::ThrusterSet& thrusters, CycleRecord* rec) {
  for (const Burn& b : planned) {
    if (b.start_s < applied_end_s - transcription::kTimeTolerance) {
      Burn a = b;
      a.end_s = std::min(a.end_s, applied_end_s);
      rec->burns.push_back(a);
    }
  }
  Schedule applied;
  applied.burns = rec->burns;
  ComputeTotals(thrusters, &applied);
  rec->consumption_l1_m_s = applied.consumption_l1_m_s;
  rec->delta_v_m_s = applied.delta_v_m_s;
  rec->propellant_kg = applied.propellant_kg;
  rec->on_time_s = applied.on_time_s;
  rec->on_time_s.resize(thrusters.size(), 0.0);
  const double acc = thrusters.acceleration();
  for (const Burn& b : rec->burns) {
    rec->normal_delta_v_m_s +=
        acc * std::abs(thrusters.thruster(b.thruster).direction(2)) * b.duration_s();
  }
}

void ReplayApplied(const ReplaySpec& spec, const ScheduleResult* accepted,
                   const dynamics::Vector6d& eci_start, CycleRecord* rec) {
  const Clock::time_point tr = Clock::now();
  const int applied_steps = Steps(spec.step_s, spec.applied_end_s - spec.start_s);
  const int q = spec.samples_per_step;
  std::vector<double> times;
  times.reserve(static_cast<size_t>(applied_steps) * q + 1);
  for (int j = 0; j < applied_steps; ++j) {
    for (int s = 0; s < q; ++s) {
      times.push_back(spec.start_s + (j + static_cast<double>(s) / q) * spec.step_s);
    }
  }
  times.push_back(spec.applied_end_s);
  std::vector<dynamics::InputPulse> pulses;
  for (const Burn& b : rec->burns) pulses.push_back({b.thruster, b.start_s, b.end_s});
  const std::vector<dynamics::Vector6d> eci = spec.simulator->Propagate(
      eci_start, spec.start_s, spec.thrusters->AccelerationMatrix(), pulses, times);
  const WindowSpec& w = *spec.window;
  bool prev_outside = false;
  rec->sample_times = times;
  rec->sample_outputs.reserve(times.size());
  rec->sample_states.reserve(times.size());
  for (size_t s = 0; s < times.size(); ++s) {
    const Eigen::Vector3d y = spec.simulator->RelativeOutputs(eci[s], times[s]);
    rec->sample_outputs.push_back(y);
    rec->sample_states.push_back(spec.simulator->RelativeFromEci(eci[s], times[s]));
    rec->max_abs_lat_deg = std::max(rec->max_abs_lat_deg, std::abs(y(1)) * kRadToDeg);
    rec->max_abs_lon_deg = std::max(rec->max_abs_lon_deg, std::abs(y(2)) * kRadToDeg);
    bool outside = false;
    if (s > 0) {
      for (size_t o = 0; o < w.outputs.size(); ++o) {
        if (w.outputs[o] != 1 && w.outputs[o] != 2) continue;
        const double excess = (std::abs(y(w.outputs[o])) - w.half_widths[o]) * kRadToDeg;
        outside = outside || excess > 0.0;
        if (excess > rec->max_window_violation_deg) {
          rec->max_window_violation_deg = excess;
          rec->worst_time_s = times[s];
        }
      }
      rec->time_outside_window_s +=
          0.5 * (times[s] - times[s - 1]) * ((prev_outside ? 1 : 0) + (outside ? 1 : 0));
    }
    prev_outside = outside;
    // Synthesis-model error at grid nodes of the applied part.
    if (accepted != nullptr && s % static_cast<size_t>(q) == 0) {
      const size_t node = s / static_cast<size_t>(q);
      if (node < accepted->schedule.outputs.size()) {
        const Eigen::VectorXd& yl = accepted->schedule.outputs[node];
        const double e = std::max(std::abs(yl(1) - y(1)), std::abs(yl(2) - y(2))) * kRadToDeg;
        rec->prediction_error_deg = std::max(rec->prediction_error_deg, e);
      }
    }
  }
  if (accepted == nullptr) rec->prediction_error_deg = kNaN;
  rec->replay_seconds = std::chrono::duration<double>(Clock::now() - tr).count();
  rec->eci_end = eci.back();
  rec->final_state = rec->sample_states.back();
}

}  // namespace thrustsched::planning::internal
