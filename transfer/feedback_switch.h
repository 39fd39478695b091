// When the Lyapunov feedback hands over to its minimum-time end (Bombrun
// 2007 sec. 5.1.1, Table 5.2: "feedback + optimal end").
//
// Two rules, both named in the scenario (feedback.switch):
//
//  - kSaturation, the thesis's statement: the feedback (4.7) runs while
//    |F^T grad V| > delta, then the minimum-time transfer joins the target
//    from where it stopped (FinishWithMinimumTime). Where that is depends on
//    the units of delta, which the thesis does not state.
//  - kEarliestConvergent: the earliest point of the feedback from which the
//    minimum-time shooting (started from its own first guess, as
//    FinishWithMinimumTime does) converges. Tried backwards from the
//    saturation point every interval_s of feedback time, stopping at the
//    first point where it fails (or at the start): the earliest point of the
//    last stretch where the end can be computed. A minimum-time end from an
//    earlier point cannot take longer than the feedback from there plus the
//    later end, so among the tried points the earliest is the fastest when
//    the shooting finds the optimum. It need not: the minimum-time problem
//    has extremals that differ by revolutions, and the shooting from two
//    points can land on different ones.
//  - kShortestConvergent: the same points tried, the one whose feedback +
//    end is the shortest kept.
//
//   transfer::FeedbackResult f = transfer::RunFeedback(p, o);   // to saturation
//   transfer::SwitchOptions s;
//   s.rule = transfer::SwitchRule::kEarliestConvergent;           // s.interval_s = 1 day
//   transfer::SwitchedTransfer r = transfer::SwitchToMinimumTime(p, f, s);
//   // r.transfer.feedback ends at r.switch_s, r.transfer.end joins the target
//
// Contract: `feedback` is RunFeedback's result (its trajectory samples are
// the candidate switch points: the point tried is the last sample at or
// before each time). The result's feedback is truncated at the switch.
#ifndef THRUSTSCHED_TRANSFER_FEEDBACK_SWITCH_H_
#define THRUSTSCHED_TRANSFER_FEEDBACK_SWITCH_H_

#include <functional>
#include <string>
#include <vector>

#include "transfer/lyapunov_feedback.h"

namespace thrustsched::transfer {

enum class SwitchRule { kSaturation, kEarliestConvergent, kShortestConvergent };

/// "saturation", "earliest_convergent", "shortest_convergent".
std::string ToString(SwitchRule r);

struct SwitchOptions {
  SwitchRule rule = SwitchRule::kSaturation;
  double interval_s = 86400.0;  // the *Convergent rules: feedback time between two tries
  int max_attempts = 400;       // the *Convergent rules: tries before the saturation point
  bool IsValid(std::string* error) const;
};

struct SwitchAttempt {
  double switch_s = 0.0;  // feedback time of the point tried
  bool converged = false;
  double end_s = 0.0;  // the minimum-time end from there (when converged)
};

struct SwitchedTransfer {
  FeedbackWithEnd transfer;  // feedback truncated at the switch + its end
  double switch_s = 0.0;     // = transfer.feedback.duration_s
  /// The points tried, latest first (the saturation point is the first).
  std::vector<SwitchAttempt> attempts;
};

/// The feedback `feedback` of p ended by the rule of `s`. @throws
/// std::invalid_argument if s is invalid.
SwitchedTransfer SwitchToMinimumTime(
    const MinTimeProblem& p, const FeedbackResult& feedback, const SwitchOptions& s,
    const ShootingOptions& shooting = {},
    const std::function<void(const SwitchAttempt&)>& progress = {});

/// The feedback `f` cut at its trajectory sample k (the switch point there).
FeedbackResult TruncateFeedback(const FeedbackResult& f, std::size_t k, double initial_l_rad);

}  // namespace thrustsched::transfer

#endif  // THRUSTSCHED_TRANSFER_FEEDBACK_SWITCH_H_
