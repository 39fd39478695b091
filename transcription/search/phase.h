// A phase of the search: one technique with a name, what it yields, and a
// Run on the search state. The plan (plan.h) says when each one runs.
//
//   class MyPhase : public SearchPhase {
//    public:
//     std::string name() const override { return "my_phase"; }
//     PhaseYield yields() const override { return PhaseYield::kIncumbents; }
//     void Run(SearchState& state) override { ... state.Offer(x, "my phase"); }
//   };
//
// Contract: a phase changes the incumbent and the bound only through the
// state (Offer, RaiseBound, RaiseBoundTo); a phase that yields incumbents
// only never raises the bound. A phase checks the state's Done()/Stopped()
// between its own sub-solves; the plan's loop checks them between phases.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_PHASE_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_PHASE_H_

#include <string>

#include "transcription/search/search_state.h"

namespace thrustsched::transcription {

enum class PhaseYield { kIncumbents, kBound, kBoth };

class SearchPhase {
 public:
  virtual ~SearchPhase() = default;
  /// The name the step log, SearchOptions::disabled_phases and docs use.
  virtual std::string name() const = 0;
  virtual PhaseYield yields() const = 0;
  virtual void Run(SearchState& state) = 0;
};

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_PHASE_H_
