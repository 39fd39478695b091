// A GEO week drawn at random (tests/app/data/random_week_almost_no_thrust.json,
// from scripts/random_weeks.py on a development seed) that needs a tenth of
// a slot of thrust by its LP:
//  - the project's interior point reaches the LP's optimum, the value CLP's
//    barrier with crossover gives (it used to stall at a relative residual
//    of 1e-6 and hand the LP to CLP);
//  - with burns of at least 3 slots and the slots carrying the whole
//    objective, every schedule that fires costs at least 3 cheapest slots
//    (a closed form: 3 x 300 s x F/m x the thruster's L1 factor); the search
//    proves that optimum at its first 3-slot schedule, which the checker and
//    the nonlinear replay pass.
// A week whose LP relaxation the interior point cannot solve (it is
// infeasible) has a safe bound above the dearest schedule the rules allow
// (weak duality, whatever the duals): the search says infeasible, with the
// reason, at once instead of searching to its time limit.
// Node limits only: nothing depends on the wall clock.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "app/scenario.h"
#include "milp/cbc_solver.h"
#include "milp/interior_point.h"
#include "tests/app/deterministic_week.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"

namespace thrustsched::app {
namespace {

Scenario Week() {
  return DeterministicWeek(
      std::string(THRUSTSCHED_SOURCE_DIR) + "/tests/app/data/random_week_almost_no_thrust.json",
      2000);
}

TEST(RandomWeek, InteriorPointReachesTheLpOptimumOfClpsBarrier) {
  const Scenario s = Week();
  const transcription::ScheduleMilp milp(s.problem, s.build);
  const milp::InteriorPointResult own = milp::SolveLpByInteriorPoint(milp.lp(), {});
  ASSERT_EQ(own.status, milp::SolveStatus::kOptimal) << own.detail;
  milp::SolveOptions barrier;
  barrier.lp_algorithm = milp::LpAlgorithm::kBarrier;
  const milp::LpRelaxationResult clp = milp::MakeCbcSolver()->SolveLpRelaxation(milp.lp(), barrier);
  ASSERT_EQ(clp.status, milp::SolveStatus::kOptimal) << clp.detail;
  EXPECT_GT(clp.objective, 0.0);
  EXPECT_NEAR(own.objective, clp.objective, 1e-6 * clp.objective);
  // A tenth of the cheapest slot.
  EXPECT_LT(own.objective, 0.2 * milp.least_firing_objective() / 3);
}

TEST(RandomWeek, TheShortestBurnBoundsEveryScheduleAndTheSearchProvesIt) {
  const Scenario s = Week();
  const dynamics::ThrusterSet& t = s.problem.thrusters;
  double cheapest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < t.size(); ++i) {
    if (t.names()[static_cast<size_t>(i)] != "SE") cheapest = std::min(cheapest, t.L1Factor(i));
  }
  const double three_slots = 3 * 300.0 * cheapest;
  const transcription::ScheduleResult r = SolveWeek(s);
  ASSERT_EQ(r.solve.status, milp::SolveStatus::kOptimal) << r.solve.detail;
  EXPECT_NEAR(r.solve.objective, three_slots, 1e-9 * three_slots);
  EXPECT_NEAR(r.solve.best_bound, three_slots, 1e-9 * three_slots);
  EXPECT_EQ(r.schedule.num_burns(), 1);
  EXPECT_TRUE(r.check.operational_ok) << r.check.Summary();
  EXPECT_LE(r.check.max_window_violation_at_nodes, 1e-9) << r.check.Summary();
  ASSERT_TRUE(r.check.nonlinear_checked);
  EXPECT_LE(r.check.max_window_violation_nonlinear_deg, 1e-9) << r.check.Summary();
}

TEST(RandomWeek, ABoundAboveTheDearestScheduleProvesTheWeekInfeasible) {
  const Scenario s = DeterministicWeek(
      std::string(THRUSTSCHED_SOURCE_DIR) + "/tests/app/data/random_week_infeasible.json", 2000);
  const transcription::ScheduleMilp milp(s.problem, s.build);
  // One thruster (max_simultaneous 1) in each of the 1008 10-min intervals.
  double dearest_slot = 0.0;
  for (int i = 0; i < s.problem.thrusters.size(); ++i)
    dearest_slot = std::max(dearest_slot, 600.0 * s.problem.thrusters.L1Factor(i));
  EXPECT_NEAR(milp.dearest_schedule_objective(), 1008 * dearest_slot, 1e-9 * dearest_slot);
  const transcription::ScheduleResult r = SolveWeek(s);
  EXPECT_EQ(r.solve.status, milp::SolveStatus::kInfeasible) << r.solve.detail;
  EXPECT_NE(r.solve.detail.find("above the dearest schedule the rules allow"), std::string::npos)
      << r.solve.detail;
}

}  // namespace
}  // namespace thrustsched::app
