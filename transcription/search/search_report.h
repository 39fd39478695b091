// What a search did, for reports (SolveResult::detail says it in words).
//
//   SearchReport report;
//   SearchSchedule(milp, solver, options, SearchOptions{}, {}, &report);
//   for (const std::string& line : report.steps) std::puts(line.c_str());  // "nets: ..."
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_SEARCH_REPORT_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_SEARCH_REPORT_H_

#include <string>
#include <vector>

namespace thrustsched::transcription {

struct SearchReport {
  double lp_seconds = 0.0;
  double lp_bound = 0.0;           // from the duals, before rounding to the step
  int candidate_slots = 0;         // free slots of the last net of the phase "nets"
  int exact_slots = -1;            // free slots after reduced-cost fixing (-1: not run)
  bool whole_milp = false;         // the phase "whole_milp" ran
  std::vector<std::string> steps;  // one line per step, in order, each "<phase>: ..."
};

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_SEARCH_REPORT_H_
