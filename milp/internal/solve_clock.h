// The wall clock and stop sources of one solve, under the CBC backend's name
// (the implementation is common::SolveClock, common/timing.h).
//
//   SolveClock clock(options.time_limit_s, options.interrupt);
//   while (!clock.ShouldStop()) Work();
//   if (clock.stopped_by_interrupt()) ...
#ifndef THRUSTSCHED_MILP_INTERNAL_SOLVE_CLOCK_H_
#define THRUSTSCHED_MILP_INTERNAL_SOLVE_CLOCK_H_

#include "common/timing.h"

namespace thrustsched::milp::internal {

using SolveClock = common::SolveClock;

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_SOLVE_CLOCK_H_
