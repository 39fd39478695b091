// Scenarios with `"objective": "min_time"`: the minimum-time solve's result
// as the schedule result every output writer takes, its "min_time" object of
// summary.json and its human line; shared by `solve` and the Python package.
//
//   transcription::MinTimeResult mt = app::SolveScenarioMinTime(s, *solver, options);
//   transcription::ScheduleResult r = app::MinTimeScheduleResult(mt, *s.min_time);
//   app::PrintMinTime(std::cout, mt);                      // "arrival ..." line
//   summary["min_time"] = app::MinTimeJson(mt, *s.min_time);
//
// The schedule result's status is the weaker of the two MILPs' claims: the
// first MILP's (arrival time) unless it proved the earliest arrival, then the
// fuel MILP's (optimal only if it proved the least fuel at that arrival;
// feasible if a limit stopped it or it did not run, optimal when the
// scenario asked for no fuel MILP). Its objective is the fuel
// (MinTimeResult::fuel) and its bound and gap the fuel MILP's; `checked` is
// false (the caller checks with its own fallback and timing).
#ifndef THRUSTSCHED_APP_MIN_TIME_REPORT_H_
#define THRUSTSCHED_APP_MIN_TIME_REPORT_H_

#include <ostream>

#include <nlohmann/json.hpp>

#include "app/scenario.h"
#include "milp/solver.h"
#include "transcription/min_time.h"
#include "transcription/solve.h"

namespace thrustsched::app {

/// SolveMinTime on the scenario's problem and target (requires
/// scenario.min_time), with the scenario's checker settings but no
/// nonlinear replay: the arrival and its error come from the linear
/// re-propagation, and the caller checks the schedule with the full checker
/// (CheckWithLinearFallback), so the replay is not run twice.
transcription::MinTimeResult SolveScenarioMinTime(const Scenario& scenario,
                                                  const milp::Solver& solver,
                                                  transcription::SolveScheduleOptions options);

transcription::ScheduleResult MinTimeScheduleResult(const transcription::MinTimeResult& result,
                                                    const transcription::MinTimeSpec& spec);

/// summary.json's "min_time" (fields in data/scenarios/README.md, section 5).
nlohmann::json MinTimeJson(const transcription::MinTimeResult& result,
                           const transcription::MinTimeSpec& spec);

/// "arrival       t = ... s (node j), proven earliest | bound ... s; ..." on one line.
void PrintMinTime(std::ostream& os, const transcription::MinTimeResult& result);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_MIN_TIME_REPORT_H_
