// The phase "whole_milp": the solver on the whole MILP, on its own (not
// from the incumbent, which is kept if the solver finds nothing better).
//
//   plan.push_back({MakeWholeMilpPhase(), "not proven infeasible", ...});
//
// Contract: yields incumbents (verified by Offer) and the solver's bound;
// with no incumbent, the solver's infeasible or error verdict is the
// search's.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_WHOLE_MILP_PHASE_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_WHOLE_MILP_PHASE_H_

#include <memory>

#include "transcription/search/phase.h"

namespace thrustsched::transcription {

std::shared_ptr<SearchPhase> MakeWholeMilpPhase();

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_WHOLE_MILP_PHASE_H_
