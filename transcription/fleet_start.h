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
// or assignment map is not a selection of state components or applies to a
// member whose terminal set is not a box (its own station-keeping sets; a
// member with them and no coupling is solved alone as it is), or some member
// alone (or every assignment) has no schedule.
#ifndef THRUSTSCHED_TRANSCRIPTION_FLEET_START_H_
#define THRUSTSCHED_TRANSCRIPTION_FLEET_START_H_

#include <string>
#include <vector>

#include "transcription/fleet.h"
#include "transcription/solve.h"

namespace thrustsched::transcription {

/// `member_options`: how each member is solved alone (its time limit per
/// solve; the check is skipped). The result's `tried` is true; `accepted`
/// says whether x keeps every row of the fleet MILP.
FleetStart DecoupledStart(const FleetMilp& milp, const milp::Solver& solver,
                          const SolveScheduleOptions& member_options);

/// Each member's problem as the start solves it alone: its own, with the
/// fleet's absolute terminal couplings and, for an assigned member, its slot
/// `slots[i]` narrowing its terminal box. Empty, with `*why`, when the fleet
/// cannot be decoupled (the cases above).
std::vector<ScheduleProblem> MemberProblemsAlone(const FleetProblem& fleet,
                                                 const std::vector<int>& slots, std::string* why);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_FLEET_START_H_
