// A fleet start the keep-out rejected, re-planned member by member, each by
// the problem-aware search against the fixed plans of those before it.
//
// With a member's predecessors fixed, their positions at the keep-out checks
// are known numbers, so the member's keep-out is a single-spacecraft problem
// with a moving obstacle. The checks its plan alone breaks come in runs (one
// encounter each); choosing one face of the cube per run (radial, east or
// north, on one side: the face whose least slack over the run is the
// largest) turns each broken check into one linear path constraint on the
// member's own state (ScheduleProblem::state_constraints), and the member
// stays a plain schedule MILP with a few hundred extra rows: the search
// (transcription/search.h) solves it about as fast as a week alone, where
// the whole fleet MILP and even a restricted one stall CBC. The new plan is
// re-checked against every predecessor and the checks it breaks (with two
// neighbours each, on the face of their run) are added: row generation, at
// most 20 searches. Where the faces cannot all be kept (the search proves
// it), every run takes its next best face, up to the third. Member 0 keeps
// its plan; a member that already keeps out of those before it is not
// re-planned.
//
// Choosing the faces restricts the problem, so the result is an incumbent,
// never a bound: it is accepted only if it keeps every row of the fleet
// MILP, and its objective is compared with the decoupled bound (the members
// alone), which holds whatever the faces.
//
//   transcription::FleetInTurn t = transcription::PlanMembersInTurn(
//       milp, start.x, start.slots, *solver, member_options);
//   if (t.found) solve_options.initial_solution = t.x;
#ifndef THRUSTSCHED_TRANSCRIPTION_FLEET_IN_TURN_H_
#define THRUSTSCHED_TRANSCRIPTION_FLEET_IN_TURN_H_

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "milp/solver.h"
#include "transcription/fleet.h"
#include "transcription/solve.h"

namespace thrustsched::transcription {

struct FleetInTurn {
  bool found = false;  // x keeps every row of the fleet MILP
  Eigen::VectorXd x;
  double objective = std::numeric_limits<double>::quiet_NaN();
  int members_replanned = 0;
  int searches = 0;     // member searches, over the members and rounds
  int constraints = 0;  // path constraints in each member's last search, summed
  std::string note;     // which step failed, if one did
  double seconds = 0.0;
};

/// `plans`: a fleet column vector whose member blocks hold the members'
/// plans (FleetStart::x), `slots` its assignment (FleetStart::slots).
/// `member_options`: each member search's options; its time limit is the
/// whole re-plan's, shared by the searches left; its `announce`, if set, is
/// told as each member's re-plan begins. The fleet needs a keep-out.
/// @throws std::invalid_argument if plans has the wrong size or the fleet has
///         no keep-out.
FleetInTurn PlanMembersInTurn(const FleetMilp& milp, const Eigen::VectorXd& plans,
                              const std::vector<int>& slots, const milp::Solver& solver,
                              const SolveScheduleOptions& member_options);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_FLEET_IN_TURN_H_
