// The MILP build of `thrustsched validate` for the scenario harnesses, on
// grids up to kMaxFuzzBuildIntervals: a larger grid is a legitimately large
// model (seconds to build), not a parser defect, and would trip the 1-s
// input budget of scripts/fuzz.sh.
//
//   fuzz::BuildIfSmall(app::ParseScenarioText(text));
#ifndef THRUSTSCHED_TESTS_FUZZ_SCENARIO_BUILD_H_
#define THRUSTSCHED_TESTS_FUZZ_SCENARIO_BUILD_H_

#include "app/scenario.h"
#include "transcription/schedule_milp.h"

namespace thrustsched::fuzz {

inline constexpr int kMaxFuzzBuildIntervals = 200;

inline void BuildIfSmall(const app::Scenario& s) {
  if (s.problem.num_intervals() > kMaxFuzzBuildIntervals) return;
  const transcription::ScheduleMilp milp(s.problem, s.build);
  (void)milp;
}

}  // namespace thrustsched::fuzz

#endif  // THRUSTSCHED_TESTS_FUZZ_SCENARIO_BUILD_H_
