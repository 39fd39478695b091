// The phase "improvement" (local improvement): the MILP restricted to the
// next, wider nets around the relaxation's and the incumbent's slots, each
// asked for a schedule better than the incumbent by a step (a cutoff row).
//
//   plan.push_back({MakeImprovementPhase(1), "an incumbent", HasIncumbent});  // one net
//   plan.push_back({MakeImprovementPhase(), "an incumbent", HasIncumbent});   // the rest
//
// Contract: incumbents only. It walks the widening levels after the one
// whose net held the nets' incumbent (SearchState::ladder, shared by every
// instance), at most nets.improvement_rounds of them, nets of at most
// nets.max_improvement_slots slots; an instance solves at most `max_nets`.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_IMPROVEMENT_PHASE_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_IMPROVEMENT_PHASE_H_

#include <memory>

#include "transcription/search/phase.h"

namespace thrustsched::transcription {

/// `max_nets` < 0: every level left.
std::shared_ptr<SearchPhase> MakeImprovementPhase(int max_nets = -1);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_IMPROVEMENT_PHASE_H_
