// The MILP build of `thrustsched validate` for the scenario harnesses, on
// grids up to kMaxFuzzBuildIntervals and without a "conjunction" section: a
// larger grid is a legitimately large model (seconds to build), and the
// keep-out rows of a conjunction are bounded by LP solves in child
// processes (0.07 s for a 124-interval Serra example in the Release build,
// 3.7 s under ASan and the fuzzer's coverage): solving, not parsing, and
// either would trip the 1-s input budget of scripts/fuzz.sh. Nor beyond
// kMaxFuzzBuildHorizonS of a time-varying model: its discretisation
// integrates the reference along the horizon at a cost proportional to its
// length (a GEO horizon of 212 days in 10 intervals took over 20 s under
// the sanitizers: computing, not parsing).
//
//   fuzz::BuildIfSmall(app::ParseScenarioText(text));
#ifndef THRUSTSCHED_TESTS_FUZZ_SCENARIO_BUILD_H_
#define THRUSTSCHED_TESTS_FUZZ_SCENARIO_BUILD_H_

#include "app/scenario.h"
#include "transcription/schedule_milp.h"

namespace thrustsched::fuzz {

inline constexpr int kMaxFuzzBuildIntervals = 200;
inline constexpr double kMaxFuzzBuildHorizonS = 8 * 86400.0;

inline void BuildIfSmall(const app::Scenario& s) {
  if (s.problem.num_intervals() > kMaxFuzzBuildIntervals || s.problem.conjunction) return;
  if (!s.problem.model->is_time_invariant() && s.problem.horizon_s() > kMaxFuzzBuildHorizonS) {
    return;
  }
  const transcription::ScheduleMilp milp(s.problem, s.build);
  (void)milp;
}

}  // namespace thrustsched::fuzz

#endif  // THRUSTSCHED_TESTS_FUZZ_SCENARIO_BUILD_H_
