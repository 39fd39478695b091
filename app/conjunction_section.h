// The "conjunction" section of a scenario file: a secondary object to keep
// out of (chance-constrained keep-out rows, transcription/keep_out.h) and the
// settings of the plan's verification (transcription/conjunction_check.h).
// Every field is documented in data/scenarios/README.md.
//
//   app::JsonObject top(json, "scenario");
//   app::ParseConjunction(top.Object("conjunction"), &scenario);   // after model, spacecraft,
//   horizon
//   // scenario.problem.conjunction and scenario.conjunction_check are set
//
// Errors are ScenarioError naming the field path and the value.
#ifndef THRUSTSCHED_APP_CONJUNCTION_SECTION_H_
#define THRUSTSCHED_APP_CONJUNCTION_SECTION_H_

#include "app/json_reader.h"
#include "app/scenario.h"

namespace thrustsched::app {

/// Reads the section into scenario->problem.conjunction and
/// scenario->conjunction_check. @throws ScenarioError.
void ParseConjunction(JsonObject section, Scenario* scenario);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_CONJUNCTION_SECTION_H_
