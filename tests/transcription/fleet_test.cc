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
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/geo_model.h"
#include "dynamics/models.h"
#include "milp/cbc_solver.h"
#include "transcription/collision_probability.h"
#include "transcription/fleet_in_turn.h"
#include "transcription/fleet_monte_carlo.h"
#include "transcription/fleet_neighbourhood.h"
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
  std::vector<int> slot;  // 0 off, i > 0 thruster i - 1, per slot
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
    plan.slot = slot;
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
  FleetSolveOptions o = Exact();
  o.decoupled_start = false;  // the fleet MILP itself
  const FleetResult r = SolveFleet(f, *solver, o);
  ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
  EXPECT_GT(sum, 0.0);
  EXPECT_NEAR(r.objective, sum, 1e-6);
  EXPECT_FALSE(r.start.tried);
  // With the decoupled start the members alone are the fleet's optimum.
  const FleetResult d = SolveFleet(f, *solver, Exact());
  ASSERT_EQ(d.status, milp::SolveStatus::kOptimal) << d.detail;
  EXPECT_TRUE(d.start.accepted);
  EXPECT_NEAR(d.objective, sum, 1e-6);
  EXPECT_NEAR(d.start.bound, sum, 1e-6);
  // One block per member and nothing else without couplings.
  const FleetMilp milp(f, BuildOptions{});
  EXPECT_EQ(r.stats.num_columns, milp.member(0).lp().num_cols() + milp.member(1).lp().num_cols());
  EXPECT_EQ(r.stats.num_rows, milp.member(0).lp().num_rows() + milp.member(1).lp().num_rows());
}

// a at rest at the origin (thrusters along x), b 3 m behind it at 1 m/s
// (thrusters along y), 1-m keep-out cube checked at the nodes and midpoints.
struct CrossingPair {
  FleetProblem fleet;
  std::vector<double> checks;
  std::vector<Plan> a, b;  // every plan of each
  CrossingPair() {
    fleet.members = {{"a", Member(State(0, 0, 0, 0), {kX, -kX})},
                     {"b", Member(State(-3, 0, 1, 0), {kY, -kY})}};
    for (int q = 1; q <= 2 * kSlots; ++q) checks.push_back(0.5 * q);
    fleet.keep_out = FleetKeepOut{1.0, checks};
    a = Enumerate(fleet.members[0].problem, checks);
    b = Enumerate(fleet.members[1].problem, checks);
  }
  // a fires thruster 0 (+x) in slot 2, b thruster 1 in slot 2: they collide.
  static std::vector<Eigen::MatrixXi> CollidingPatterns() {
    Eigen::MatrixXi pa = Eigen::MatrixXi::Zero(2, kSlots), pb = Eigen::MatrixXi::Zero(2, kSlots);
    pa(0, 2) = 1;
    pb(1, 2) = 1;
    return {pa, pb};
  }
  // a's plan of this pattern (per slot: 0 off, i > 0 thruster i - 1), or null.
  const Plan* PlanOfA(const std::vector<int>& slot) const {
    for (const Plan& p : a) {
      if (p.slot == slot) return &p;
    }
    return nullptr;
  }
  bool Clear(const Plan& x, const Plan& y) const {
    for (size_t q = 0; q < checks.size(); ++q) {
      if ((x.positions[q] - y.positions[q]).cwiseAbs().maxCoeff() < 1.0 - 1e-9) return false;
    }
    return true;
  }
};

// b drifts along x through a, which sits still: alone, neither fires and
// they meet at t = 3 s. With a 1 m keep-out cube a may step aside along x,
// b along y; the enumeration over both members' patterns gives the price.
TEST(Fleet, KeepOutAvoidsTheCollisionOfTheUncoupledPlans) {
  CrossingPair pair;
  FleetProblem& f = pair.fleet;
  const auto& a = pair.a;
  const auto& b = pair.b;
  auto clear = [&](const Plan& x, const Plan& y) { return pair.Clear(x, y); };
  ASSERT_EQ(a[0].cost, 0.0);  // the all-off plans collide
  ASSERT_FALSE(clear(a[0], b[0]));
  const double expected = PairMinimum(a, b, clear, Sum);
  ASSERT_TRUE(std::isfinite(expected));
  ASSERT_GT(expected, 0.0);

  const FleetResult r = SolveFleet(f, *milp::MakeCbcSolver(), Exact());
  ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
  EXPECT_NEAR(r.objective, expected, 1e-6);
  // Alone, nobody fires and they collide: the start is built, the fleet's
  // keep-out rows refuse it, b re-planned against a's plan gives the first
  // incumbent, and the solver's tree finds the optimum.
  EXPECT_TRUE(r.start.built);
  EXPECT_TRUE(r.start.in_turn_tried);
  EXPECT_TRUE(r.start.in_turn_found);
  EXPECT_TRUE(r.start.accepted);
  EXPECT_EQ(r.start.in_turn_members_replanned, 1);
  EXPECT_GE(r.start.objective, expected - 1e-9);
  EXPECT_NEAR(r.start.bound, 0.0, 1e-9);
  // Without the re-plan in turn (and with no burn to repair near), the tree alone.
  FleetSolveOptions tree = Exact();
  tree.in_turn = false;
  const FleetResult t = SolveFleet(f, *milp::MakeCbcSolver(), tree);
  ASSERT_EQ(t.status, milp::SolveStatus::kOptimal) << t.detail;
  EXPECT_NEAR(t.objective, expected, 1e-6);
  EXPECT_FALSE(t.start.accepted);
  EXPECT_FALSE(t.start.in_turn_tried);
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

// Member by member near given burns is the enumeration over b's plans that
// fire only near its own burn and keep out of a's fixed plan: a fires slot 2
// (and keeps it), b's burn in slot 2 leaves it slots 1-3 within one slot; with
// the radius the whole horizon, b's best plan clear of a's.
TEST(Fleet, RepairMemberByMemberIsTheEnumerationOverTheSlotsNearTheGivenBurns) {
  CrossingPair pair;
  FleetProblem& f = pair.fleet;
  const auto& b = pair.b;
  auto clear = [&](const Plan& x, const Plan& y) { return pair.Clear(x, y); };
  auto within = [](const Plan& p, int first, int last) {
    for (int j = 0; j < kSlots; ++j) {
      if (p.slot[j] > 0 && (j < first || j > last)) return false;
    }
    return true;
  };
  const Plan* fixed = pair.PlanOfA({0, 0, 1, 0, 0, 0});  // thruster 0 (+x) in slot 2 only
  ASSERT_NE(fixed, nullptr);
  double near = kInf, anywhere = kInf;
  for (const Plan& p : b) {
    if (!clear(*fixed, p)) continue;
    anywhere = std::min(anywhere, fixed->cost + p.cost);
    if (within(p, 1, 3)) near = std::min(near, fixed->cost + p.cost);
  }
  ASSERT_TRUE(std::isfinite(near));
  ASSERT_GE(near, anywhere);

  const FleetMilp milp(f, BuildOptions{});
  const std::vector<Eigen::MatrixXi> patterns = CrossingPair::CollidingPatterns();
  const Eigen::VectorXd plans = milp.StartFromPatterns(patterns, {});
  ASSERT_GT(milp.lp().MaxViolation(plans), kStartFeasibility);  // the given plans collide
  const auto cbc = milp::MakeCbcSolver();
  const FleetNeighbourhood n = RepairMemberByMember(milp, plans, *cbc, Exact().milp, 1);
  ASSERT_TRUE(n.found) << n.note;
  EXPECT_NEAR(n.objective, near, 1e-6);
  EXPECT_EQ(n.members_replanned, 1);
  EXPECT_GE(n.rounds, 1);  // summed over the rounds of row generation:
  EXPECT_EQ(n.free_binaries, n.rounds * 2 * 3);
  EXPECT_EQ(n.fixed_binaries, n.rounds * 2 * kSlots - n.free_binaries);
  EXPECT_LE(milp.lp().MaxViolation(n.x), kStartFeasibility);

  const FleetNeighbourhood all = RepairMemberByMember(milp, plans, *cbc, Exact().milp, kSlots);
  ASSERT_TRUE(all.found) << all.note;
  EXPECT_NEAR(all.objective, anywhere, 1e-6);
  EXPECT_EQ(all.fixed_binaries, 0);
  // Plans that already keep out are not touched.
  const FleetNeighbourhood same = RepairMemberByMember(milp, all.x, *cbc, Exact().milp, 1);
  ASSERT_TRUE(same.found);
  EXPECT_EQ(same.members_replanned, 0);
  EXPECT_NEAR(same.objective, anywhere, 1e-9);
  EXPECT_THROW(RepairMemberByMember(milp, plans, *cbc, Exact().milp, -1), std::invalid_argument);
  EXPECT_THROW(RepairMemberByMember(milp, plans.head(3), *cbc, Exact().milp, 1),
               std::invalid_argument);
}

// In turn: a keeps its plan (thruster 0, +x, in slot 2), b is re-planned by
// the search against it with one face per encounter: b's best plan clear of
// a's fixed plan over every slot (the enumeration), here reached.
TEST(Fleet, PlanMembersInTurnIsTheBestPlanClearOfTheFixedOne) {
  CrossingPair pair;
  const Plan* fixed = pair.PlanOfA({0, 0, 1, 0, 0, 0});
  ASSERT_NE(fixed, nullptr);
  double anywhere = kInf;
  for (const Plan& p : pair.b) {
    if (pair.Clear(*fixed, p)) anywhere = std::min(anywhere, fixed->cost + p.cost);
  }
  ASSERT_TRUE(std::isfinite(anywhere));
  const FleetMilp milp(pair.fleet, BuildOptions{});
  const std::vector<Eigen::MatrixXi> patterns = CrossingPair::CollidingPatterns();
  const Eigen::VectorXd plans = milp.StartFromPatterns(patterns, {});
  ASSERT_GT(milp.lp().MaxViolation(plans), kStartFeasibility);  // the given plans collide
  const auto cbc = milp::MakeCbcSolver();
  SolveScheduleOptions member;
  member.milp.relative_gap = 0.0;
  const FleetInTurn t = PlanMembersInTurn(milp, plans, {}, *cbc, member);
  ASSERT_TRUE(t.found) << t.note;
  EXPECT_NEAR(t.objective, anywhere, 1e-6);
  EXPECT_EQ(t.members_replanned, 1);
  EXPECT_GE(t.searches, 1);
  EXPECT_GT(t.constraints, 0);
  EXPECT_LE(milp.lp().MaxViolation(t.x), kStartFeasibility);
  EXPECT_EQ(milp.member(0).encoding().OnPattern(milp.MemberColumns(t.x, 0)), patterns[0]);
  // Plans that already keep out are not touched.
  const FleetInTurn same = PlanMembersInTurn(milp, t.x, {}, *cbc, member);
  ASSERT_TRUE(same.found);
  EXPECT_EQ(same.members_replanned, 0);
  EXPECT_EQ(same.searches, 0);
  EXPECT_NEAR(same.objective, anywhere, 1e-9);
  EXPECT_THROW(PlanMembersInTurn(milp, plans.head(3), {}, *cbc, member), std::invalid_argument);
  FleetProblem no_keep_out = pair.fleet;
  no_keep_out.keep_out.reset();
  const FleetMilp free(no_keep_out, BuildOptions{});
  EXPECT_THROW(PlanMembersInTurn(free, free.StartFromPatterns(patterns, {}), {}, *cbc, member),
               std::invalid_argument);
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

// Both members uncertain, sigma_r per axis in position and sigma_v in
// velocity: the relative position's variance per axis at time t is
// 2 (sigma_r^2 + t^2 sigma_v^2) (double integrator, independent members), so
// each face's margin is z sqrt of that (Serra 2015 (4.19)). The fleet MILP
// against the enumeration with the cube grown by that margin at each check.
TEST(Fleet, ChanceConstrainedKeepOutMatchesTheEnumerationWithItsClosedFormMargin) {
  constexpr double kSigmaR = 0.2, kSigmaV = 0.1, kEps = 1e-3;
  FleetProblem f;
  Eigen::VectorXd sd(6);
  sd << kSigmaR, kSigmaR, kSigmaR, kSigmaV, kSigmaV, kSigmaV;
  const Eigen::MatrixXd sigma = sd.array().square().matrix().asDiagonal();
  f.members = {{"a", Member(State(0, 0, 0, 0), {kX, -kX}), sigma},
               {"b", Member(State(-3, 0, 1, 0), {kY, -kY}), sigma}};
  std::vector<double> checks;
  for (int q = 1; q <= 2 * kSlots; ++q) checks.push_back(0.5 * q);
  f.keep_out = FleetKeepOut{1.0, checks, kEps};
  const double z = NormalQuantile(1.0 - kEps);
  auto margin = [&](double t) {
    return z * std::sqrt(2.0 * (kSigmaR * kSigmaR + t * t * kSigmaV * kSigmaV));
  };
  const auto a = Enumerate(f.members[0].problem, checks);
  const auto b = Enumerate(f.members[1].problem, checks);
  auto clear = [&](double grow) {
    return [&, grow](const Plan& x, const Plan& y) {
      for (size_t q = 0; q < checks.size(); ++q) {
        const double rhs = 1.0 + grow * margin(checks[q]);
        if ((x.positions[q] - y.positions[q]).cwiseAbs().maxCoeff() < rhs - 1e-9) return false;
      }
      return true;
    };
  };
  const double deterministic = PairMinimum(a, b, clear(0.0), Sum);
  const double expected = PairMinimum(a, b, clear(1.0), Sum);
  ASSERT_TRUE(std::isfinite(expected));
  ASSERT_GT(expected, deterministic);  // the margin costs something here

  FleetSolveOptions o = Exact();
  o.monte_carlo.samples = 2000;
  o.monte_carlo.steps = 60;
  const FleetResult r = SolveFleet(f, *milp::MakeCbcSolver(), o);
  ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
  EXPECT_NEAR(r.objective, expected, 1e-6);
  EXPECT_NEAR(r.stats.keep_out_quantile, z, 1e-12);
  EXPECT_NEAR(r.stats.keep_out_margin_max_m, margin(checks.back()), 1e-9);
  ASSERT_TRUE(r.monte_carlo.has_value());
  EXPECT_EQ(r.monte_carlo->samples, 2000);
  EXPECT_EQ(r.monte_carlo->pairs.size(), 1u);

  f.keep_out->instantaneous_threshold = 0.0;  // the same fleet without the margin
  o.monte_carlo.samples = 0;
  const FleetResult plain = SolveFleet(f, *milp::MakeCbcSolver(), o);
  ASSERT_EQ(plain.status, milp::SolveStatus::kOptimal) << plain.detail;
  EXPECT_NEAR(plain.objective, deterministic, 1e-6);
  EXPECT_EQ(plain.stats.keep_out_margin_max_m, 0.0);
  EXPECT_FALSE(plain.monte_carlo.has_value());
}

// Nobody fires and nothing moves: the relative position is N(mu, 2 sigma^2 I)
// at every time, so the fraction of colliding samples is P(|r| < R), which
// BallProbability integrates independently; the Monte Carlo must agree within
// its binomial error.
TEST(Fleet, MonteCarloCollisionFractionMatchesTheBallProbability) {
  constexpr double kSigma = 0.6, kRadius = 1.0;
  constexpr int kSamples = 40000;
  FleetProblem f;
  Eigen::VectorXd variance = Eigen::VectorXd::Zero(6);
  variance.head<3>().setConstant(kSigma * kSigma);  // the velocities known exactly
  const Eigen::MatrixXd sigma = variance.asDiagonal();
  f.members = {{"a", Member(State(0, 0, 0, 0), {kX}), sigma},
               {"b", Member(State(1.2, 0.3, 0, 0), {kY}), sigma}};
  f.keep_out = FleetKeepOut{kRadius, {kSlots * kStep}};
  FleetMonteCarloOptions o;
  o.samples = kSamples;
  o.steps = 4;
  const FleetMonteCarloReport mc = CheckFleetMonteCarlo(f, {Schedule{}, Schedule{}}, o);
  const double p = BallProbability(Eigen::Vector3d(-1.2, -0.3, 0),
                                   2.0 * kSigma * kSigma * Eigen::Matrix3d::Identity(), kRadius);
  ASSERT_GT(p, 0.05);
  const double fraction = static_cast<double>(mc.collisions) / kSamples;
  EXPECT_NEAR(fraction, p, 4.0 * std::sqrt(p * (1.0 - p) / kSamples)) << p;
  EXPECT_EQ(mc.pairs.at(0).collisions, mc.collisions);
  EXPECT_LT(mc.min_distance_m, kRadius);

  // The same seed, the same samples; another seed, other samples.
  EXPECT_EQ(CheckFleetMonteCarlo(f, {Schedule{}, Schedule{}}, o).collisions, mc.collisions);
  o.seed = 2;
  EXPECT_NE(CheckFleetMonteCarlo(f, {Schedule{}, Schedule{}}, o).min_distance_m, mc.min_distance_m);

  f.members[0].initial_covariance.resize(0, 0);
  f.members[1].initial_covariance.resize(0, 0);
  EXPECT_THROW(CheckFleetMonteCarlo(f, {Schedule{}, Schedule{}}, o), std::invalid_argument);
}

// Two members each to an absolute target, whose own optima pass 2 m apart
// in y: the start from the members alone keeps the keep-out, so the
// decoupled bound proves it without the fleet's tree; its value is the
// enumerated optimum with the keep-out. With the targets swapped in an
// assignment the start chooses the cheaper assignment, enumerated too.
TEST(Fleet, DecoupledStartProvesTheFleetWhenTheMembersAloneKeepOut) {
  FleetProblem f;
  f.members = {{"a", Member(State(0, 0, 0, 0), {kX, -kX})},
               {"b", Member(State(0, 2, 0, 0), {kX, -kX})}};
  auto target = [](int member, double x) {
    TerminalCoupling c;
    c.member = member;
    c.map = Eigen::MatrixXd::Zero(2, 6);
    c.map(0, 0) = 1.0;
    c.map(1, 3) = 1.0;
    c.offset = Eigen::Vector2d(x, 0.0);
    return c;
  };
  f.couplings = {target(0, 4.0), target(1, -4.0)};
  std::vector<double> checks;
  for (int q = 1; q <= 2 * kSlots; ++q) checks.push_back(0.5 * q);
  f.keep_out = FleetKeepOut{1.0, checks};
  const auto a = Enumerate(f.members[0].problem, checks);
  const auto b = Enumerate(f.members[1].problem, checks);
  auto at = [](const Plan& p, double x) {
    return std::abs(p.final_state[0] - x) < 1e-6 && std::abs(p.final_state[3]) < 1e-6;
  };
  auto clear = [&](const Plan& x, const Plan& y) {
    for (size_t q = 0; q < checks.size(); ++q) {
      if ((x.positions[q] - y.positions[q]).cwiseAbs().maxCoeff() < 1.0 - 1e-9) return false;
    }
    return true;
  };
  const double expected = PairMinimum(
      a, b, [&](const Plan& x, const Plan& y) { return at(x, 4.0) && at(y, -4.0) && clear(x, y); },
      Sum);
  ASSERT_TRUE(std::isfinite(expected));
  const auto solver = milp::MakeCbcSolver();
  const FleetResult r = SolveFleet(f, *solver, Exact());
  ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
  EXPECT_TRUE(r.start.accepted) << r.start.note;
  EXPECT_NE(r.detail.find("decoupled bound"), std::string::npos) << r.detail;
  EXPECT_NEAR(r.objective, expected, 1e-6);
  EXPECT_EQ(r.start.member_solves, 2);

  // The same targets as slots: member a to 4 m costs what b to -4 m does,
  // a to -4 m and b to 4 m the same; the enumerated optimum over both.
  FleetProblem g = f;
  g.couplings.clear();
  SlotAssignment s;
  s.members = {0, 1};
  s.map = f.couplings[0].map;
  s.slots = {Eigen::Vector2d(4.0, 0.0), Eigen::Vector2d(-3.0, 0.0)};
  g.assignment = s;
  double best = kInf;
  for (const auto& [xa, xb] : {std::pair{4.0, -3.0}, std::pair{-3.0, 4.0}}) {
    best = std::min(best, PairMinimum(
                              a, b,
                              [&, xa = xa, xb = xb](const Plan& x, const Plan& y) {
                                return at(x, xa) && at(y, xb) && clear(x, y);
                              },
                              Sum));
  }
  const FleetResult ra = SolveFleet(g, *solver, Exact());
  ASSERT_EQ(ra.status, milp::SolveStatus::kOptimal) << ra.detail;
  EXPECT_NEAR(ra.objective, best, 1e-6);
  EXPECT_EQ(ra.start.member_solves, 4);
  EXPECT_TRUE(ra.start.built) << ra.start.note;
}

TEST(Fleet, BadInputNamesTheField) {
  std::string error;
  FleetProblem f = TwoMembers();
  // GEO members at two station points: their local frames are not one.
  for (int k = 0; k < 2; ++k) {
    dynamics::GeoModelOptions geo;
    geo.station_longitude_deg = k == 0 ? 118.0 : 118.5;
    f.members[k].problem.model = std::make_shared<dynamics::GeoLinearModel>(geo);
  }
  f.couplings.clear();
  EXPECT_FALSE(f.IsValid(&error));
  EXPECT_NE(error.find("members[1].problem.model: its local position frame differs"),
            std::string::npos)
      << error;
  f.members[1].problem.model = f.members[0].problem.model;
  EXPECT_TRUE(f.IsValid(&error)) << error;

  f = TwoMembers();
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
  f.members[1].initial_covariance = Eigen::MatrixXd::Identity(5, 5);
  EXPECT_FALSE(f.IsValid(&error));
  EXPECT_NE(error.find("members[1].initial_covariance: 5 x 5, expected 6 x 6"), std::string::npos)
      << error;
  f.members[1].initial_covariance = -Eigen::MatrixXd::Identity(6, 6);
  EXPECT_FALSE(f.IsValid(&error));
  EXPECT_NE(error.find("members[1].initial_covariance: not positive semi-definite"),
            std::string::npos)
      << error;

  f = TwoMembers();
  f.keep_out = FleetKeepOut{1.0, {3.0}, 0.5};
  EXPECT_FALSE(f.IsValid(&error));
  EXPECT_NE(error.find("keep_out.instantaneous_threshold: 0.5"), std::string::npos) << error;

  f = TwoMembers();
  EXPECT_TRUE(f.IsValid(&error)) << error;
  EXPECT_EQ(f.MemberIndex("b"), 1);
  EXPECT_EQ(f.MemberIndex("c"), -1);
}

}  // namespace
}  // namespace thrustsched::transcription
