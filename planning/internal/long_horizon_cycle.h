// Steps of one long-horizon cycle (LongHorizonSimulation::RunCycle) that do
// not need the simulation object: what the accepted schedule records, the
// applied part of the plan, and the nonlinear replay. Internal.
//
//   internal::RecordAccepted(accepted, &rec);
//   internal::ApplyPlan(accepted.schedule.burns, applied_end_s, thrusters, &rec);
//   internal::ReplayApplied({...}, &accepted, eci_start, &rec);
#ifndef THRUSTSCHED_PLANNING_INTERNAL_LONG_HORIZON_CYCLE_H_
#define THRUSTSCHED_PLANNING_INTERNAL_LONG_HORIZON_CYCLE_H_

#include <vector>

#include "dynamics/geo_simulator.h"
#include "planning/long_horizon.h"
#include "transcription/problem.h"
#include "transcription/solve.h"

namespace thrustsched::planning::internal {

using transcription::Schedule;
using transcription::WindowSpec;

/// Status, objective, bound, gap and the checker's linear verdict of the
/// accepted schedule into *rec.
void RecordAccepted(const ScheduleResult& accepted, CycleRecord* rec);

/// The applied part of `planned` (burns that start before applied_end_s, cut
/// there) into rec->burns, with its consumption, delta-v, propellant,
/// on-times and normal delta-v.
void ApplyPlan(const std::vector<Burn>& planned, double applied_end_s,
               const dynamics::ThrusterSet& thrusters, CycleRecord* rec);

struct ReplaySpec {
  const dynamics::GeoSimulator* simulator = nullptr;
  const dynamics::ThrusterSet* thrusters = nullptr;
  const WindowSpec* window = nullptr;
  double start_s = 0.0;
  double applied_end_s = 0.0;
  double step_s = 0.0;
  int samples_per_step = 1;
};

/// Propagates rec->burns from `eci_start` through the nonlinear model and
/// records the samples, max |lat| and |lon|, the window violation and time
/// outside it (degrees, the checker's definitions), the synthesis-model error
/// at the nodes (against `accepted`, NaN when null) and the end state.
/// @throws std::runtime_error if the propagation fails.
void ReplayApplied(const ReplaySpec& spec, const ScheduleResult* accepted,
                   const dynamics::Vector6d& eci_start, CycleRecord* rec);

}  // namespace thrustsched::planning::internal

#endif  // THRUSTSCHED_PLANNING_INTERNAL_LONG_HORIZON_CYCLE_H_
