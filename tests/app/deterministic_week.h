// A scenario file loaded for a test that must not depend on the wall clock:
// one thread, no time limit, a node limit per MILP, and its solve with the
// scenario's own build and check settings.
//
//   const Scenario s = DeterministicWeek(path, 2000);
//   const transcription::ScheduleResult r = SolveWeek(s);
#ifndef THRUSTSCHED_TESTS_APP_DETERMINISTIC_WEEK_H_
#define THRUSTSCHED_TESTS_APP_DETERMINISTIC_WEEK_H_

#include <limits>
#include <string>

#include "app/scenario.h"
#include "milp/cbc_solver.h"
#include "transcription/solve.h"

namespace thrustsched::app {

inline Scenario DeterministicWeek(const std::string& path, long long max_nodes) {
  Scenario s = LoadScenario(path);
  s.solve.threads = 1;
  s.solve.time_limit_s = std::numeric_limits<double>::infinity();
  s.solve.relative_gap = 1e-4;
  s.solve.max_nodes = max_nodes;
  return s;
}

inline transcription::ScheduleResult SolveWeek(const Scenario& s) {
  auto solver = milp::MakeCbcSolver();
  transcription::SolveScheduleOptions o;
  o.build = s.build;
  o.milp = s.solve;
  o.check = s.check;
  return transcription::SolveSchedule(s.problem, *solver, o);
}

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_TESTS_APP_DETERMINISTIC_WEEK_H_
