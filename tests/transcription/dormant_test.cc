// FindDormantThrusters (transcription/dormant.h) on Hill-Clohessy-Wiltshire
// problems whose blocks are known in closed form: the out-of-plane motion
// (z, +N/-N) is independent of the in-plane one (x, y, +R/-R/+T/-T), so a
// start offset along one of them leaves the other block at rest, inside its
// window, for the whole horizon. And the search with and without the
// reduction against CBC alone on the whole MILP.
#include "transcription/dormant.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/discretisation.h"
#include "milp/cbc_solver.h"
#include "tests/transcription/thesis_cases.h"
#include "transcription/search.h"
#include "transcription/solve.h"

namespace thrustsched::transcription {
namespace {

// Thesis Table 4.1's set-up over one day on a 10-min grid, started `x_m`
// radially and `z_m` out of plane from the origin, the window (+-36.8 km in
// y and z) imposed from half a day on, as in thesis Table 4.2. A radial
// offset makes y drift out of the window; an out-of-plane one beyond 36.8 km
// keeps z oscillating outside it; either needs thrust.
ScheduleProblem HcwDay(double x_m, double z_m) {
  ScheduleProblem p = ThesisTable41(1.0);
  p.grid = dynamics::UniformGrid(0.0, 86400.0, 144);
  p.initial_state[0] = x_m;
  p.initial_state[2] = z_m;
  p.window.enforce_from_s = 43200.0;
  return p;
}

constexpr double kOutsideZ = 40000.0;  // m, beyond the window's 36.8 km

std::vector<bool> Flags(const ScheduleMilp& milp, const std::vector<std::string>& names) {
  std::vector<bool> out(static_cast<size_t>(milp.problem().thrusters.size()), false);
  for (const std::string& n : names)
    out[static_cast<size_t>(milp.problem().thrusters.IndexOf(n))] = true;
  return out;
}

// Every on-off column of thruster i is in a dormant block iff i is dormant.
void ExpectColumnsFollowThrusters(const ScheduleMilp& milp, const DormantThrusters& d) {
  const OperationalEncoding& enc = milp.encoding();
  for (int i = 0; i < enc.num_thrusters; ++i) {
    for (const milp::Variable& v : enc.on[static_cast<size_t>(i)]) {
      ASSERT_EQ(d.column[static_cast<size_t>(v.index())], d.thruster[static_cast<size_t>(i)]) << i;
    }
  }
}

TEST(FindDormantThrusters, TheBlockAtRestIsLeftOffInBothEncodings) {
  for (Encoding e : {Encoding::kThesis, Encoding::kTight}) {
    BuildOptions b;
    b.encoding = e;
    const ScheduleMilp out_of_plane(HcwDay(0.0, kOutsideZ), b);
    const DormantThrusters d = FindDormantThrusters(out_of_plane);
    EXPECT_GE(d.num_blocks, 2);
    EXPECT_EQ(d.thruster, Flags(out_of_plane, {"+R", "+T", "-R", "-T"}));
    EXPECT_EQ(d.Names(out_of_plane), "+R, +T, -R, -T");
    ExpectColumnsFollowThrusters(out_of_plane, d);
    // The all-off point: the in-plane states stay at the origin.
    EXPECT_EQ(d.all_off[out_of_plane.state(50, 0).index()], 0.0);

    const ScheduleMilp in_plane(HcwDay(3000.0, 0.0), b);
    const DormantThrusters n = FindDormantThrusters(in_plane);
    EXPECT_EQ(n.thruster, Flags(in_plane, {"+N", "-N"}));
    ExpectColumnsFollowThrusters(in_plane, n);

    // Both blocks need thrust: nothing is dormant.
    EXPECT_FALSE(FindDormantThrusters(ScheduleMilp(HcwDay(3000.0, kOutsideZ), b)).any());
    // Neither needs thrust (z oscillates inside the window): all dormant.
    const ScheduleMilp at_rest(HcwDay(0.0, 3000.0), b);
    EXPECT_EQ(FindDormantThrusters(at_rest).thruster, std::vector<bool>(6, true));
  }
}

// The window is what makes a block need thrust: the in-plane block at rest
// but outside its window (y offset beyond the half width) is not dormant.
TEST(FindDormantThrusters, ABlockOutsideItsWindowIsNotDormant) {
  ScheduleProblem p = HcwDay(0.0, 0.0);
  p.initial_state[1] = kOutsideZ;  // y beyond the 36.8 km half width, at rest
  const ScheduleMilp milp(p, BuildOptions{});
  EXPECT_EQ(FindDormantThrusters(milp).thruster, Flags(milp, {"+N", "-N"}));
}

// A thruster its history holds on (a burn shorter than the minimum at t0)
// cannot be left off: its block is not dormant, the other block is.
TEST(FindDormantThrusters, AThrusterHeldOnByItsHistoryKeepsItsBlock) {
  ScheduleProblem p = HcwDay(0.0, kOutsideZ);
  p.history = BoundaryHistory::AllOff(p.thrusters.size());
  p.history.on_for_s[static_cast<size_t>(p.thrusters.IndexOf("+T"))] = 60.0;
  const ScheduleMilp milp(p, BuildOptions{});
  EXPECT_FALSE(FindDormantThrusters(milp).any());
}

// A thruster pointing out of plane and along-track moves both blocks and
// joins them: one block, nothing dormant.
TEST(FindDormantThrusters, AThrusterThatMovesBothSubsystemsJoinsThem) {
  ScheduleProblem p = HcwDay(0.0, kOutsideZ);
  const double s = std::sqrt(0.5);
  p.thrusters = dynamics::ThrusterSet(
      {{"+NT", Eigen::Vector3d(0.0, s, s), true}, {"-NT", Eigen::Vector3d(0.0, -s, -s), true}},
      0.265, 4850, 2005);
  const ScheduleMilp milp(p, BuildOptions{});
  const DormantThrusters d = FindDormantThrusters(milp);
  EXPECT_FALSE(d.any());
  EXPECT_EQ(d.num_blocks, 1 + static_cast<int>(milp.encoding().gamma.size()));
}

// The search with the reduction proves the same optimum as without it and as
// CBC alone on the whole MILP (gap 1e-9), fires no dormant thruster, and its
// LP bound is the whole relaxation's.
TEST(FindDormantThrusters, TheSearchWithTheReductionKeepsTheOptimumAndTheBound) {
  auto solver = milp::MakeCbcSolver();
  const ScheduleProblem p = HcwDay(0.0, kOutsideZ);
  SolveScheduleOptions o;
  o.milp.relative_gap = 1e-9;
  o.milp.absolute_gap = 1e-9;
  o.milp.threads = 1;
  o.milp.max_nodes = 200000;
  const ScheduleResult with = SolveSchedule(p, *solver, o);
  o.search.relaxation.drop_dormant_blocks = false;
  const ScheduleResult without = SolveSchedule(p, *solver, o);
  o.search.enabled = false;
  const ScheduleResult cbc = SolveSchedule(p, *solver, o);
  ASSERT_EQ(cbc.solve.status, milp::SolveStatus::kOptimal) << cbc.solve.detail;
  ASSERT_EQ(with.solve.status, milp::SolveStatus::kOptimal) << with.solve.detail;
  EXPECT_NEAR(with.solve.objective, cbc.solve.objective, 1e-9 * cbc.solve.objective);
  EXPECT_NEAR(without.solve.objective, cbc.solve.objective, 1e-9 * cbc.solve.objective);
  EXPECT_NEAR(with.search.lp_bound, without.search.lp_bound, 1e-6 * cbc.solve.objective);
  EXPECT_LE(with.search.lp_bound, cbc.solve.objective + 1e-9);
  EXPECT_NE(with.solve.detail.find("+R, +T, -R, -T left off"), std::string::npos)
      << with.solve.detail;
  EXPECT_EQ(without.solve.detail.find("left off"), std::string::npos) << without.solve.detail;
  for (const Burn& burn : with.schedule.burns) {
    EXPECT_TRUE(burn.thruster == p.thrusters.IndexOf("+N") ||
                burn.thruster == p.thrusters.IndexOf("-N"))
        << burn.thruster;
  }
  EXPECT_TRUE(with.check.operational_ok) << with.check.Summary();
  EXPECT_LE(with.check.max_window_violation_at_nodes, 1e-3) << with.check.Summary();
}

// Nothing needs thrust: every block is dormant, the LP left is empty (or
// only the thesis encoding's gamma columns), and the search proves the
// empty schedule optimal at 0 in both encodings.
TEST(FindDormantThrusters, WithEveryThrusterDormantTheEmptyScheduleIsProvenOptimal) {
  auto solver = milp::MakeCbcSolver();
  for (Encoding e : {Encoding::kThesis, Encoding::kTight}) {
    SolveScheduleOptions o;
    o.build.encoding = e;
    o.milp.threads = 1;
    o.milp.max_nodes = 1000;
    const ScheduleResult r = SolveSchedule(HcwDay(0.0, 3000.0), *solver, o);
    ASSERT_EQ(r.solve.status, milp::SolveStatus::kOptimal) << r.solve.detail;
    EXPECT_EQ(r.solve.objective, 0.0);
    EXPECT_TRUE(r.schedule.burns.empty());
    EXPECT_NE(r.solve.detail.find("+R, +T, +N, -R, -T, -N left off"), std::string::npos)
        << r.solve.detail;
    EXPECT_TRUE(r.check.operational_ok) << r.check.Summary();
    EXPECT_LE(r.check.max_window_violation_at_nodes, 1e-3) << r.check.Summary();
  }
}

}  // namespace
}  // namespace thrustsched::transcription
