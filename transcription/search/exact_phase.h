// The phase "exact": reduced-cost fixing with the bound's duals (Nemhauser
// & Wolsey 1988, sec. II.5.2) leaves free only the slots that can be on in
// a schedule better than the incumbent by a step; the MILP restricted to
// them, with the cutoff, is exact for any improvement.
//
//   plan.push_back({MakeExactPhase(), "an incumbent", HasIncumbent});
//   ExactRounds(state);   // the same, from another phase (after a better schedule)
//
// Contract: yields incumbents and bounds. Its solve proves the incumbent
// optimal (infeasible with the cutoff) or finds a better one, and then the
// bound is min(the old incumbent, that solve's bound): every better
// schedule lies in the restriction. Up to three rounds while one improves
// without a proof; none when more than exact.max_slots slots stay free.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_EXACT_PHASE_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_EXACT_PHASE_H_

#include <memory>

#include "transcription/search/phase.h"

namespace thrustsched::transcription {

std::shared_ptr<SearchPhase> MakeExactPhase();

/// The phase's work, for phases that follow a better schedule with it.
void ExactRounds(SearchState& state);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_EXACT_PHASE_H_
