// The scenario field solver.search: true or false (the search on or off),
// or an object with the search's plan, the phases left out and each
// phase's options (transcription/search/search_options.h). Every field is
// documented in data/scenarios/README.md.
//
//   "search": {"disabled_phases": ["exchange"], "nets": {"max_widenings": 4}}
//
//   app::ParseSearch(solver_object, "search", &scenario.search_options);
//
// Errors are ScenarioError naming the field path and the value
// ("solver.search.nets.max_widenings: must be >= 0, got -1", say).
#ifndef THRUSTSCHED_APP_SEARCH_SECTION_H_
#define THRUSTSCHED_APP_SEARCH_SECTION_H_

#include <string_view>

#include "app/json_reader.h"
#include "transcription/search/search_options.h"

namespace thrustsched::app {

/// Reads `solver`'s field `key` (absent: `search` unchanged).
/// @throws ScenarioError.
void ParseSearch(JsonObject& solver, std::string_view key, transcription::SearchOptions* search);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_SEARCH_SECTION_H_
