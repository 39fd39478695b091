// The phase "relaxation": the LP relaxation by interior point without
// crossover (RelaxationOptions::lp_method: the project's own,
// milp/interior_point.h, then CLP's barrier if it ends without an optimum;
// or CLP's barrier alone), and a bound from its row duals valid whatever
// their accuracy (milp/lp_bound.h), rounded up to the objective step.
//
//   plan.push_back({MakeRelaxationPhase(), "always", Always});
//
// Contract: yields the bound and the relaxation's point; without it (an
// error or a limit) the state has no relaxation, and an infeasible
// relaxation marks the problem infeasible. The blocks of dormant thrusters
// (transcription/dormant.h) are left out of the LP, never of the bound's
// check: their duals are zero and SafeDualBound checks the whole MILP.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_RELAXATION_PHASE_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_RELAXATION_PHASE_H_

#include <memory>

#include "transcription/search/phase.h"

namespace thrustsched::transcription {

std::shared_ptr<SearchPhase> MakeRelaxationPhase();

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_RELAXATION_PHASE_H_
