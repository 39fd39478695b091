// A first incumbent for the fleet MILP from its members planned alone: each
// member's own schedule MILP, with the fleet's absolute terminal couplings
// as its terminal box, solved by the problem-aware search (SolveSchedule);
// with a slot assignment, every member for every slot, and the assignment of
// least total cost whose plans keep the fleet's rows (the keep-out: all
// permutations up to 8 members in order of cost, the first 24 tried; greedy
// beyond), else the cheapest. The
// patterns become one fleet column vector (FleetMilp::StartFromPatterns), a
// MIP start: the solver keeps it only if it is feasible, i.e. if the members
// planned alone keep out of each other and meet the balance rows. It is a
// heuristic for the incumbent; its bound comes from the members' own proven
// bounds (see FleetStart::bound), never from the incumbent.
//
//   transcription::FleetStart s = transcription::DecoupledStart(milp, *solver, member_options);
//   if (s.built) solve_options.initial_solution = s.x;
//
// Not built (with the reason in `note`) when a coupling or the assignment is
// relative to another member (no member alone knows its target), a coupling
// map is not a selection of state components (a member's terminal set is a
// box), a member has station-keeping terminal sets of its own, or some
// member alone (or every assignment) has no schedule.
#ifndef THRUSTSCHED_TRANSCRIPTION_FLEET_START_H_
#define THRUSTSCHED_TRANSCRIPTION_FLEET_START_H_

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "transcription/fleet.h"
#include "transcription/solve.h"

namespace thrustsched::transcription {
/// Largest row or bound violation (model units) at which a start counts as
/// feasible for the fleet MILP (ScheduleMilp's pattern tolerance).
inline constexpr double kStartFeasibility = ScheduleMilp::kPatternFeasibilityTolerance;
}  // namespace thrustsched::transcription

namespace thrustsched::transcription {

struct FleetStart {
  bool built = false;
  std::string note;  // why not built, or what was done
  Eigen::VectorXd x;
  std::vector<int> slots;                 // per assigned member
  std::vector<double> member_objectives;  // J_k of each member's schedule alone
  double objective = std::numeric_limits<double>::quiet_NaN();  // the fleet objective of x
  /// A lower bound on the fleet MILP's objective: the fleet without its
  /// keep-out and balance rows separates into the members alone, so the
  /// members' proven bounds (the least over the assignments, with the
  /// fleet's balance objective) bound it. NaN when not built.
  double bound = std::numeric_limits<double>::quiet_NaN();
  int member_solves = 0;
  int tries = 0;  // assignments tried until one kept every fleet row (0: none did, or none tried)
  double seconds = 0.0;
};

/// `member_options`: how each member is solved alone (its time limit per
/// solve; the check is skipped).
FleetStart DecoupledStart(const FleetMilp& milp, const milp::Solver& solver,
                          const SolveScheduleOptions& member_options);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_FLEET_START_H_
