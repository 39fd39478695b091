// Wall-clock durations for reports and time limits, on the monotonic clock
// (a system-clock change must not stretch or cut a time limit).
//
//   const auto t0 = common::Clock::now();
//   ...
//   report.seconds = common::Since(t0);
#ifndef THRUSTSCHED_COMMON_TIMING_H_
#define THRUSTSCHED_COMMON_TIMING_H_

#include <chrono>

namespace thrustsched::common {

using Clock = std::chrono::steady_clock;

/// Seconds elapsed since `t0`.
inline double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace thrustsched::common

#endif  // THRUSTSCHED_COMMON_TIMING_H_
