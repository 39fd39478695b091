// A fleet start the keep-out rejected, repaired member by member near the
// members' own plans. Members planned alone may collide (co-located GEO
// satellites both steered to the cheapest end of the week come within a few
// hundred metres of each other), and the whole fleet MILP is too large for
// the solver's root (two GEO weeks: 84,000 columns, 12,000 keep-out
// binaries). Sequential planning with a restricted MILP per step is small:
// member 0 keeps its plan alone; member k = 1, 2, ... is re-planned with every
// other member fixed, its own on-off binaries free only within `radius`
// intervals of its own burns (any thruster; the others fixed to 0, the
// restricted-MILP idea of the single-spacecraft search,
// transcription/search/restricted_milp.h), and only its keep-out checks
// against the members before it that its plan breaks (with two neighbours
// each) kept, more added while its new plan breaks others (row generation,
// at most 20 rounds per member). The pairs with the members before
// it then hold, and are never revisited, so after the last step every pair
// does. A member whose plan already keeps out of those before it is not
// re-planned. The result is feasible for the whole fleet MILP (checked on
// its rows): an incumbent, never a bound.
//
//   transcription::FleetNeighbourhood n =
//       transcription::RepairMemberByMember(milp, start.x, *solver, solve_options, 12);
//   if (n.found) solve_options.initial_solution = n.x;
#ifndef THRUSTSCHED_TRANSCRIPTION_FLEET_NEIGHBOURHOOD_H_
#define THRUSTSCHED_TRANSCRIPTION_FLEET_NEIGHBOURHOOD_H_

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "milp/solver.h"
#include "transcription/fleet.h"

namespace thrustsched::transcription {

struct FleetNeighbourhood {
  bool found = false;  // x keeps every row of the fleet MILP
  Eigen::VectorXd x;
  double objective = std::numeric_limits<double>::quiet_NaN();
  int radius_intervals = 0;
  int members_replanned = 0;
  int rounds = 0;          // restricted solves, over the members (row generation)
  int free_binaries = 0;   // on-off binaries left free, summed over the steps
  int fixed_binaries = 0;  // of the re-planned members, fixed to 0, summed
  milp::SolveStatus status = milp::SolveStatus::kError;  // of the last restricted solve
  std::string note;                                      // which step failed, if one did
  double seconds = 0.0;
};

/// `plans`: a fleet column vector whose member columns are the members'
/// plans (FleetMilp::StartFromPatterns); `options` for each restricted solve
/// (its time limit is the whole repair's, shared by the steps left; gap,
/// threads, interrupt). @throws std::invalid_argument if plans has the wrong
/// size or radius < 0.
FleetNeighbourhood RepairMemberByMember(const FleetMilp& milp, const Eigen::VectorXd& plans,
                                        const milp::Solver& solver,
                                        const milp::SolveOptions& options, int radius_intervals);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_FLEET_NEIGHBOURHOOD_H_
