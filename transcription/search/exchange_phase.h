// The phase "exchange" (along an axis): the MILP restricted to every slot of
// the thrusters on one axis (+T and -T, say) and to the incumbent's slots of
// the others, with the cutoff; the exact phase's rounds after each better
// schedule (block coordinate descent over the axes).
//
//   plan.push_back({MakeExchangePhase(), "an incumbent", HasIncumbent});
//
// Why: the nets grow in time around the relaxation's slots; here an axis'
// firings can move anywhere in the horizon while the other axes keep
// theirs. That holds for thrusters in opposite pairs along the orbital
// frame's axes (AxisExchangeApplies: each firing moves its own axis'
// components), not for thrusters that each push along several axes.
// Contract: incumbents only (and the exact phase's bounds after each).
// Axes the incumbent fires at least one slot more than the relaxation,
// most first; each solved again only against a new incumbent.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_EXCHANGE_PHASE_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_EXCHANGE_PHASE_H_

#include <memory>

#include "dynamics/thrusters.h"
#include "transcription/search/phase.h"

namespace thrustsched::transcription {

std::shared_ptr<SearchPhase> MakeExchangePhase();

/// Whether the exchange applies to `thrusters`: they lie on two axes or
/// more (ThrusterAxes) and one axis holds two of them or more (the ideal
/// six's +T and -T), not the thesis' four Anzel thrusters (each alone on
/// its axis). Depends on the thrusters only, not on the MILP's encoding.
bool AxisExchangeApplies(const dynamics::ThrusterSet& thrusters);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_EXCHANGE_PHASE_H_
