// Operational rules of on-off thrusters, the boundary history that chains
// horizons, and forced-off windows. Pure data: the MILP encodings
// (transcription/encodings.h) and the independent checker
// (transcription/checker.h) both read these definitions, stated here in
// continuous time so that each can be verified against the other.
//
//   transcription::OperationalRules rules;       // thesis: K = 1, 5 / 20 / 5 min
//   rules.max_simultaneous = 1;
//   rules.min_burn_s = 300;
//   rules.min_off_same_s = 1200;
//   rules.min_gap_other_s = 300;
//
// Continuous-time meaning (times in s; a burn of thruster i is [start, end)):
//  (1) at every instant at most `max_simultaneous` thrusters are on;
//  (2) every burn lasts end - start >= min_burn_s, except a burn still on at
//      the horizon end when `allow_burn_across_end` (it continues in the next
//      horizon) and a burn on at t0 counts the time it was on before t0;
//  (3) every burn lasts <= max_burn_s (counting time before t0);
//  (4) two burns of the same thruster: next.start - previous.end >= min_off_same_s
//      (the previous end may lie before t0: BoundaryHistory::off_for_s);
//  (5) a burn of thruster i ending at e and a burn of another thruster l
//      starting at s >= e: s - e >= min_gap_other_s (a start while i is still
//      on is governed by (1) only);
//  (6) no burn overlaps (with positive length) a forced-off window of its thruster;
//  (7) at most `max_burns_per_thruster` burns start inside the horizon per thruster.
// On a grid t_0 < ... < t_N burns start and end at nodes, so these rules are
// exact there: a duration T becomes, at node j, the smallest number of whole
// intervals spanning >= T (thesis (4.9) rounding up on a uniform grid).
#ifndef THRUSTSCHED_TRANSCRIPTION_OPERATIONS_H_
#define THRUSTSCHED_TRANSCRIPTION_OPERATIONS_H_

#include <limits>
#include <string>
#include <vector>

namespace thrustsched::transcription {

/// Comparison tolerance (s) when checking durations against rules on a grid.
inline constexpr double kTimeTolerance = 1e-6;

struct OperationalRules {
  int max_simultaneous = 1;  // K >= 1
  double min_burn_s = 0.0;   // T_l >= 0
  double max_burn_s = std::numeric_limits<double>::infinity();
  double min_off_same_s = 0.0;      // same thruster, >= 0
  double min_gap_other_s = 0.0;     // different thrusters, >= 0
  int max_burns_per_thruster = -1;  // < 0: no limit
  /// A burn on in the last interval may be shorter than min_burn_s (it is
  /// assumed to continue in the next horizon, whose history carries it).
  bool allow_burn_across_end = false;

  bool IsValid(std::string* error) const;
};

/// State of the thrusters at t0, so that a horizon continues the previous one.
/// Vectors are empty (= every thruster off and never fired) or one per thruster.
struct BoundaryHistory {
  /// > 0: the thruster is on at t0 and has been on for this long (s).
  std::vector<double> on_for_s;
  /// For an off thruster: time since it last switched off (s); +inf = never
  /// fired (no constraint). Ignored for a thruster that is on at t0.
  std::vector<double> off_for_s;

  static BoundaryHistory AllOff(int num_thrusters);
  bool IsValid(int num_thrusters, std::string* error) const;
  bool is_on(int thruster) const;
  double on_for(int thruster) const;   // 0 when off or unspecified
  double off_for(int thruster) const;  // +inf when unspecified
};

/// Thruster `thruster` may not fire on [start_s, end_s) (failure, eclipse, blackout).
struct ForcedOff {
  int thruster;
  double start_s;
  double end_s;
};

/// A burn of thruster `thruster` (index into the ThrusterSet) on [start_s, end_s).
struct Burn {
  int thruster;
  double start_s;
  double end_s;
  double duration_s() const { return end_s - start_s; }
};

/// One broken rule, for reports.
struct RuleViolation {
  std::string rule;     // "max_simultaneous", "min_burn", "max_burn", "min_off_same",
                        // "min_gap_other", "forced_off", "max_burns", "horizon", "overlap"
  int thruster;         // -1 if not specific
  double time_s;        // where it happens
  std::string message;  // human-readable, with the numbers
};

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_OPERATIONS_H_
