// The phase "nets": the MILP restricted to the slots the relaxation uses
// and their neighbours, widened while it holds no schedule.
//
//   plan.push_back({MakeNetsPhase(), "a relaxation", HasRelaxation});
//
// Why: a GEO week's MILP has thousands of binaries, but its optimum fires
// in about 1 % of the slots and the relaxation (tight encoding) is nearly
// integral there; the MILP over a net of hundreds of slots is solved in a
// fraction of a second. A net without a schedule is widened (threshold /
// 10, neighbourhood doubled, every thruster near a candidate), and after
// SearchOptions::nets.fired_thrusters_net_after widenings the net of every
// slot of the thrusters the relaxation fires is tried first: a problem that
// needs a few slots of one thruster may have to fire them anywhere.
// Contract: incumbents only (a restriction's verdict says nothing of the
// slots it leaves out); ends at the first net that holds a schedule, at a
// net that frees every slot or exceeds nets.max_widened_slots.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_NETS_PHASE_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_NETS_PHASE_H_

#include <memory>

#include "transcription/search/phase.h"

namespace thrustsched::transcription {

std::shared_ptr<SearchPhase> MakeNetsPhase();

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_NETS_PHASE_H_
