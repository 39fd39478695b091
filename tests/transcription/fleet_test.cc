// The fleet MILP (transcription/fleet.h) against references that share none
// of its code: tiny fleets of 3-D double integrators (one or two thrusters
// on one axis each, 6 one-second slots) whose optimum is found by
// enumerating every member's on-off patterns, propagated here in closed form
// (constant acceleration over each slot), not by dynamics::Discretize; the
// sum of the members solved alone by SolveSchedule; and, for the slot
// assignment, the minimum over every permutation of a MILP with the slots
// written as plain terminal couplings.
#include "transcription/fleet.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/models.h"
#include "milp/cbc_solver.h"
#include "transcription/solve.h"

namespace thrustsched::transcription {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kSlots = 6;
constexpr double kStep = 1.0;   // s
constexpr double kAccel = 1.0;  // m/s^2 (1 N on 1 kg); L1 cost 1 m/s per slot

ScheduleProblem Member(const Eigen::VectorXd& x0, const std::vector<Eigen::Vector3d>& dirs) {
  ScheduleProblem p;
  p.model = std::make_shared<dynamics::DoubleIntegrator3d>();
  std::vector<dynamics::Thruster> t;
  for (size_t i = 0; i < dirs.size(); ++i) t.push_back({"t" + std::to_string(i), dirs[i]});
  p.thrusters = dynamics::ThrusterSet(t, kAccel, 1.0, 300.0);
  p.grid = dynamics::UniformGrid(0.0, kSlots * kStep, kSlots);
  p.initial_state = x0;
  return p;
}

Eigen::VectorXd State(double x, double y, double vx, double vy) {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(6);
  s << x, y, 0, vx, vy, 0;
  return s;
}

// One enumerated plan: its cost, final state and positions at the check times.
struct Plan {
  double cost = 0.0;
  Eigen::VectorXd final_state;
  std::vector<Eigen::Vector3d> positions;
};

// Every pattern (each slot off or one thruster on), propagated in closed form.
std::vector<Plan> Enumerate(const ScheduleProblem& p, const std::vector<double>& checks) {
  const int m = p.thrusters.size();
  std::vector<Plan> out;
  std::vector<int> slot(kSlots, 0);  // 0 off, i > 0 thruster i - 1
  while (true) {
    Plan plan;
    std::vector<Eigen::Vector3d> r(kSlots + 1), v(kSlots + 1), u(kSlots, Eigen::Vector3d::Zero());
    r[0] = p.initial_state.head<3>();
    v[0] = p.initial_state.tail<3>();
    for (int j = 0; j < kSlots; ++j) {
      if (slot[j] > 0) {
        u[j] = kAccel * p.thrusters.thruster(slot[j] - 1).direction;
        plan.cost += kAccel * kStep;
      }
      r[j + 1] = r[j] + v[j] * kStep + 0.5 * u[j] * kStep * kStep;
      v[j + 1] = v[j] + u[j] * kStep;
    }
    for (double t : checks) {
      const int j = std::min(static_cast<int>(std::floor(t / kStep + 1e-9)), kSlots - 1);
      const double tau = t - j * kStep;
      plan.positions.push_back(r[j] + v[j] * tau + 0.5 * u[j] * tau * tau);
    }
    plan.final_state.resize(6);
    plan.final_state << r[kSlots], v[kSlots];
    out.push_back(plan);
    int j = 0;
    while (j < kSlots && ++slot[j] > m) slot[j++] = 0;
    if (j == kSlots) break;
  }
  return out;
}

// Minimum over every pair of plans that passes `ok` of `cost`.
double PairMinimum(const std::vector<Plan>& a, const std::vector<Plan>& b,
                   const std::function<bool(const Plan&, const Plan&)>& ok,
                   const std::function<double(const Plan&, const Plan&)>& cost) {
  double best = kInf;
  for (const Plan& pa : a) {
    for (const Plan& pb : b) {
      const double c = cost(pa, pb);
      if (c < best && ok(pa, pb)) best = c;
    }
  }
  return best;
}

double Sum(const Plan& a, const Plan& b) { return a.cost + b.cost; }

FleetSolveOptions Exact() {
  FleetSolveOptions o;
  o.milp.relative_gap = 0.0;
  o.milp.absolute_gap = 1e-7;
  return o;
}

const Eigen::Vector3d kX(1, 0, 0), kY(0, 1, 0);

// x_B - x_A = 4 and equal velocities at t_N: the formation geometry.
TerminalCoupling RelativeX(double dx) {
  TerminalCoupling c;
  c.member = 1;
  c.reference = 0;
  c.map = Eigen::MatrixXd::Zero(2, 6);
  c.map(0, 0) = 1.0;
  c.map(1, 3) = 1.0;
  c.offset = Eigen::Vector2d(dx, 0.0);
  return c;
}

bool Coupled(const Plan& a, const Plan& b, double dx) {
  return std::abs(b.final_state[0] - a.final_state[0] - dx) < 1e-6 &&
         std::abs(b.final_state[3] - a.final_state[3]) < 1e-6;
}

FleetProblem TwoMembers() {
  FleetProblem f;
  f.members = {{"a", Member(State(0, 0, 0, 0), {kX, -kX})},
               {"b", Member(State(10, 0, 0, 0), {kX, -kX})}};
  f.couplings = {RelativeX(4.0)};
  return f;
}

TEST(Fleet, TerminalCouplingMatchesEnumeration) {
  const FleetProblem f = TwoMembers();
  const auto a = Enumerate(f.members[0].problem, {}), b = Enumerate(f.members[1].problem, {});
  const double expected = PairMinimum(
      a, b, [](const Plan& x, const Plan& y) { return Coupled(x, y, 4.0); }, Sum);
  ASSERT_TRUE(std::isfinite(expected));
  const FleetResult r = SolveFleet(f, *milp::MakeCbcSolver(), Exact());
  ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
  EXPECT_NEAR(r.objective, expected, 1e-6);
  EXPECT_NEAR(r.consumption[0] + r.consumption[1], expected, 1e-6);
  ASSERT_EQ(r.coupling_residuals.size(), 1u);
  EXPECT_LT(r.coupling_residuals[0], 1e-6);  // from the checker's re-propagation
  ASSERT_EQ(r.checks.size(), 2u);
  EXPECT_TRUE(r.checks[0].operational_ok && r.checks[1].operational_ok);
}

// Member b fires along +y only: it cannot help the x coupling, so equal
// consumptions make it spend as much as a does (the bound binds: 8 against 4).
TEST(Fleet, MaxExcessOverMeanMatchesEnumeration) {
  FleetProblem f = TwoMembers();
  f.members[1] = {"b", Member(State(10, 0, 0, 0), {kY})};
  f.balance.kind = FuelBalanceKind::kMaxExcessOverMean;
  f.balance.max_excess_fraction = 0.0;  // equal consumptions
  const auto a = Enumerate(f.members[0].problem, {}), b = Enumerate(f.members[1].problem, {});
  const double unbalanced = PairMinimum(
      a, b, [](const Plan& x, const Plan& y) { return Coupled(x, y, 4.0); }, Sum);
  const double expected = PairMinimum(
      a, b,
      [](const Plan& x, const Plan& y) {
        return Coupled(x, y, 4.0) && std::abs(x.cost - y.cost) < 1e-9;
      },
      Sum);
  ASSERT_TRUE(std::isfinite(expected));
  const FleetResult r = SolveFleet(f, *milp::MakeCbcSolver(), Exact());
  ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
  EXPECT_NEAR(r.objective, expected, 1e-6);
  EXPECT_NEAR(r.consumption[0], r.consumption[1], 1e-6);
  EXPECT_GT(expected, unbalanced + 1e-9);  // the balance binds here
}

TEST(Fleet, MinMaxMatchesEnumeration) {
  FleetProblem f = TwoMembers();
  f.balance.kind = FuelBalanceKind::kMinMax;
  f.balance.sum_weight = 0.01;
  const auto a = Enumerate(f.members[0].problem, {}), b = Enumerate(f.members[1].problem, {});
  const double expected = PairMinimum(
      a, b, [](const Plan& x, const Plan& y) { return Coupled(x, y, 4.0); },
      [](const Plan& x, const Plan& y) {
        return std::max(x.cost, y.cost) + 0.01 * (x.cost + y.cost);
      });
  ASSERT_TRUE(std::isfinite(expected));
  const FleetResult r = SolveFleet(f, *milp::MakeCbcSolver(), Exact());
  ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
  EXPECT_NEAR(r.objective, expected, 1e-6);
  const double max_j = std::max(r.consumption[0], r.consumption[1]);
  EXPECT_NEAR(max_j + 0.01 * (r.consumption[0] + r.consumption[1]), expected, 1e-6);
}

TEST(Fleet, DecoupledFleetIsTheSumOfItsMembersAlone) {
  FleetProblem f;
  ScheduleProblem a = Member(State(0, 0, 0, 0), {kX, -kX, kY});
  a.terminal.kind = TerminalKind::kStateBox;  // x = 3 m at rest, y free
  a.terminal.target = State(3, 0, 0, 0);
  a.terminal.tolerance = Eigen::VectorXd::Zero(6);
  a.terminal.tolerance[1] = kInf;
  a.terminal.tolerance[4] = kInf;
  ScheduleProblem b = Member(State(5, 0, 0, 0), {kX, -kX});
  b.terminal.kind = TerminalKind::kFixedState;
  b.terminal.target = State(2, 0, 0, 0);
  f.members = {{"a", a}, {"b", b}};
  const auto solver = milp::MakeCbcSolver();
  SolveScheduleOptions alone;
  alone.milp.relative_gap = 0.0;
  double sum = 0.0;
  for (const FleetMember& m : f.members) {
    const ScheduleResult r = SolveSchedule(m.problem, *solver, alone);
    ASSERT_TRUE(r.has_schedule());
    sum += r.schedule.consumption_l1_m_s;
  }
  const FleetResult r = SolveFleet(f, *solver, Exact());
  ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
  EXPECT_GT(sum, 0.0);
  EXPECT_NEAR(r.objective, sum, 1e-6);
  // One block per member and nothing else without couplings.
  const FleetMilp milp(f, BuildOptions{});
  EXPECT_EQ(r.stats.num_columns, milp.member(0).lp().num_cols() + milp.member(1).lp().num_cols());
  EXPECT_EQ(r.stats.num_rows, milp.member(0).lp().num_rows() + milp.member(1).lp().num_rows());
}

// b drifts along x through a, which sits still: alone, neither fires and
// they meet at t = 3 s. With a 1 m keep-out cube a may step aside along x,
// b along y; the enumeration over both members' patterns gives the price.
TEST(Fleet, KeepOutAvoidsTheCollisionOfTheUncoupledPlans) {
  FleetProblem f;
  f.members = {{"a", Member(State(0, 0, 0, 0), {kX, -kX})},
               {"b", Member(State(-3, 0, 1, 0), {kY, -kY})}};
  std::vector<double> checks;
  for (int q = 1; q <= 2 * kSlots; ++q) checks.push_back(0.5 * q);  // nodes and midpoints
  f.keep_out = FleetKeepOut{1.0, checks};
  const auto a = Enumerate(f.members[0].problem, checks);
  const auto b = Enumerate(f.members[1].problem, checks);
  auto clear = [&](const Plan& x, const Plan& y) {
    for (size_t q = 0; q < checks.size(); ++q) {
      if ((x.positions[q] - y.positions[q]).cwiseAbs().maxCoeff() < 1.0 - 1e-9) return false;
    }
    return true;
  };
  ASSERT_EQ(a[0].cost, 0.0);  // the all-off plans collide
  ASSERT_FALSE(clear(a[0], b[0]));
  const double expected = PairMinimum(a, b, clear, Sum);
  ASSERT_TRUE(std::isfinite(expected));
  ASSERT_GT(expected, 0.0);

  const FleetResult r = SolveFleet(f, *milp::MakeCbcSolver(), Exact());
  ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
  EXPECT_NEAR(r.objective, expected, 1e-6);
  ASSERT_EQ(r.planned_pairs.size(), 1u);
  EXPECT_GE(r.planned_pairs[0].min_box_distance_m, 1.0 - 1e-6);
  EXPECT_GT(r.stats.keep_out_binaries, 0);
  EXPECT_GT(r.stats.big_m_max_m, 0.0);
  EXPECT_TRUE(std::isfinite(r.stats.big_m_max_m));
  ASSERT_EQ(r.checked_pairs.size(), 1u);
  EXPECT_TRUE(std::isfinite(r.checked_pairs[0].min_distance_m));

  f.keep_out.reset();
  const FleetResult free = SolveFleet(f, *milp::MakeCbcSolver(), Exact());
  ASSERT_EQ(free.status, milp::SolveStatus::kOptimal);
  EXPECT_NEAR(free.objective, 0.0, 1e-9);
  EXPECT_LT(free.planned_pairs[0].min_distance_m, 1e-6);  // they meet
}

// Three deputies take three slots relative to a chief: the assignment MILP
// against the minimum over the 3! assignments of a MILP each, whose slots are
// plain terminal couplings (another row path).
TEST(Fleet, AssignmentMatchesEveryPermutationSolved) {
  FleetProblem f;
  f.members = {{"chief", Member(State(10, 0, 0, 0), {kX, -kX})},
               {"d0", Member(State(0, 0, 0, 0), {kX, -kX})},
               {"d1", Member(State(2, 0, 0, 0), {kX, -kX})},
               {"d2", Member(State(4, 0, 0, 0), {kX, -kX})}};
  SlotAssignment s;
  s.members = {1, 2, 3};
  s.reference = 0;
  s.map = Eigen::MatrixXd::Zero(2, 6);
  s.map(0, 0) = 1.0;
  s.map(1, 3) = 1.0;
  s.slots = {Eigen::Vector2d(-5, 0), Eigen::Vector2d(-9, 0), Eigen::Vector2d(-7, 0)};
  const auto solver = milp::MakeCbcSolver();
  std::vector<int> perm = {0, 1, 2};
  double best = kInf;
  std::vector<int> best_perm;
  do {
    FleetProblem g = f;
    for (int i = 0; i < 3; ++i) {
      TerminalCoupling c;
      c.member = s.members[i];
      c.reference = 0;
      c.map = s.map;
      c.offset = s.slots[perm[i]];
      g.couplings.push_back(c);
    }
    const FleetResult r = SolveFleet(g, *solver, Exact());
    if (r.status == milp::SolveStatus::kOptimal && r.objective < best - 1e-9) {
      best = r.objective;
      best_perm = perm;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  ASSERT_TRUE(std::isfinite(best));

  f.assignment = s;
  const FleetResult r = SolveFleet(f, *solver, Exact());
  ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
  EXPECT_NEAR(r.objective, best, 1e-6);
  EXPECT_EQ(r.stats.assignment_binaries, 9);
  ASSERT_EQ(r.slots.size(), 3u);
  std::vector<int> sorted = r.slots;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::vector<int>{0, 1, 2}));
  ASSERT_EQ(r.coupling_residuals.size(), 1u);
  EXPECT_LT(r.coupling_residuals[0], 1e-6);
}

TEST(Fleet, BadInputNamesTheField) {
  std::string error;
  FleetProblem f = TwoMembers();
  f.couplings[0].reference = 5;
  EXPECT_FALSE(f.IsValid(&error));
  EXPECT_NE(error.find("couplings[0].reference: no member 5"), std::string::npos) << error;

  f = TwoMembers();
  f.couplings[0].offset = Eigen::Vector3d(1, 2, 3);
  EXPECT_FALSE(f.IsValid(&error));
  EXPECT_NE(error.find("couplings[0].offset: 3 entries, expected 2"), std::string::npos) << error;

  f = TwoMembers();
  f.members[1].problem.grid = dynamics::UniformGrid(0.0, 12.0, kSlots);
  EXPECT_FALSE(f.IsValid(&error));
  EXPECT_NE(error.find("members[1].grid[1]"), std::string::npos) << error;

  f = TwoMembers();
  f.members[1].name = "a";
  EXPECT_FALSE(f.IsValid(&error));
  EXPECT_NE(error.find("members[1].name: 'a' repeated"), std::string::npos) << error;

  f = TwoMembers();
  f.keep_out = FleetKeepOut{1.0, {7.0}};
  EXPECT_FALSE(f.IsValid(&error));
  EXPECT_NE(error.find("keep_out.check_times_s[0]"), std::string::npos) << error;
  EXPECT_THROW(FleetMilp(f, BuildOptions{}), std::invalid_argument);

  f = TwoMembers();
  EXPECT_TRUE(f.IsValid(&error)) << error;
  EXPECT_EQ(f.MemberIndex("b"), 1);
  EXPECT_EQ(f.MemberIndex("c"), -1);
}

}  // namespace
}  // namespace thrustsched::transcription
