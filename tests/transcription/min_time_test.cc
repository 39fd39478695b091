// Minimum time to a target with on-off thrusters (transcription/min_time.h)
// against closed forms, exact when the grid step divides the continuous
// optimum's switching times (the zero-order hold of an LTI model is exact):
//  - the controlled harmonic oscillator x'' = -x + u, |u| <= eps, from
//    (2 k eps, 0) to rest at the origin: T* = k pi, one switch every pi
//    (Bombrun 2007, eqs. 2.29-2.36); here the HCW out-of-plane axis at
//    n = 1 rad/s with thrusters +N and -N;
//  - the double integrator with |u| <= U from rest at distance 1 to rest:
//    T* = 2 / sqrt(U), the switch half-way;
//  - the raft (Bombrun 2007, eq. 1.41): q' = 1 + u, |u| <= 1/2, a raft
//    drifting at speed 1 from distance 1: in relative coordinates r' = -u,
//    T* = 2 at full thrust.
// On a grid that does not hold the switching times, no schedule arrives
// before T* (the continuous optimum bounds the discrete one).
#include "transcription/min_time.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>

#include "common/constants.h"
#include "dynamics/models.h"
#include "milp/cbc_solver.h"

namespace thrustsched::transcription {
namespace {

using common::kPi;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Two thrusters along +axis and -axis (RTN), acceleration `accel` (m/s^2).
dynamics::ThrusterSet PlusMinus(int axis, double accel) {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  d[axis] = 1.0;
  return dynamics::ThrusterSet({{"plus", d}, {"minus", -d}}, /*thrust_n=*/accel, /*mass_kg=*/1.0,
                               /*isp_s=*/1000.0);
}

// r' = -u_R: the boat's distance to the raft (m), the raft drifting with the
// current, the boat at 1 + u (m/s); the input is a velocity (m/s).
class RaftModel final : public dynamics::LinearModel {
 public:
  std::string_view name() const override { return "raft"; }
  int num_states() const override { return 1; }
  int num_inputs() const override { return 3; }
  int num_outputs() const override { return 1; }
  bool is_time_invariant() const override { return true; }
  dynamics::ModelMatrices Evaluate(double) const override {
    dynamics::ModelMatrices m;
    m.a = Eigen::MatrixXd::Zero(1, 1);
    m.b = Eigen::MatrixXd::Zero(1, 3);
    m.b(0, 0) = -1.0;
    m.d = Eigen::VectorXd::Zero(1);
    return m;
  }
  dynamics::OutputMatrices EvaluateOutput(double) const override {
    return {Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Zero(1, 1)};
  }
  std::vector<std::string> state_names() const override { return {"r_m"}; }
  std::vector<std::string> output_names() const override { return {"r_m"}; }
  Eigen::VectorXd state_scale() const override { return Eigen::VectorXd::Ones(1); }
  double time_scale() const override { return 1.0; }
};

ScheduleProblem Problem(std::shared_ptr<const dynamics::LinearModel> model,
                        dynamics::ThrusterSet thrusters, double horizon_s, int intervals,
                        Eigen::VectorXd x0) {
  ScheduleProblem p;
  p.model = std::move(model);
  p.thrusters = std::move(thrusters);
  p.grid = dynamics::UniformGrid(0.0, horizon_s, intervals);
  p.initial_state = std::move(x0);
  return p;
}

MinTimeSpec ToRest(int n, double tolerance) {
  MinTimeSpec spec;
  spec.target = Eigen::VectorXd::Zero(n);
  spec.tolerance = Eigen::VectorXd::Constant(n, tolerance);
  return spec;
}

MinTimeResult Solve(const ScheduleProblem& p, const MinTimeSpec& spec) {
  SolveScheduleOptions o;
  o.milp.relative_gap = 0.0;
  o.milp.absolute_gap = 1e-9;
  return SolveMinTime(p, spec, *milp::MakeCbcSolver(), o);
}

void ExpectProvenAndVerified(const MinTimeResult& r) {
  ASSERT_TRUE(r.has_schedule());
  EXPECT_EQ(r.time_status, milp::SolveStatus::kOptimal);
  EXPECT_DOUBLE_EQ(r.arrival_bound_s, r.arrival_time_s);
  EXPECT_TRUE(r.verified()) << r.check.Summary() << " arrival error " << r.arrival_error;
}

// k = 5, eps = 0.1 from (1, 0): 5 pi, five arcs of pi alternating -N, +N.
TEST(MinTime, HarmonicOscillatorArrivesAtKPi) {
  const double eps = 0.1;
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
  x0[2] = 2 * 5 * eps;  // z = 1 m
  const ScheduleProblem p = Problem(std::make_shared<dynamics::HcwModel>(1.0, 1.0),
                                    PlusMinus(2, eps), 6 * kPi, 60, x0);  // pi / 10 steps
  const MinTimeResult r = Solve(p, ToRest(6, 1e-6));
  ExpectProvenAndVerified(r);
  EXPECT_NEAR(r.arrival_time_s, 5 * kPi, 1e-9);
  EXPECT_EQ(r.arrival_node, 50);
  // Bang-bang with a switch every pi: five burns of pi, alternating.
  ASSERT_EQ(r.schedule.num_burns(), 5) << r.check.Summary();
  for (int k = 0; k < 5; ++k) {
    const Burn& b = r.schedule.burns[k];
    EXPECT_NEAR(b.start_s, k * kPi, 1e-9) << k;
    EXPECT_NEAR(b.end_s, (k + 1) * kPi, 1e-9) << k;
    // +eps first: half turns about (eps, 0), (-eps, 0), ... of radii 0.9, 0.7, ..., 0.1.
    EXPECT_EQ(b.thruster, k % 2 == 0 ? 0 : 1) << k;
  }
}

// Other k: T* = k pi for k = 1..3 (eps = 0.1, from 2 k eps).
TEST(MinTime, HarmonicOscillatorScalesWithTheDistance) {
  for (int k = 1; k <= 3; ++k) {
    Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
    x0[2] = 2 * k * 0.1;
    const ScheduleProblem p = Problem(std::make_shared<dynamics::HcwModel>(1.0, 1.0),
                                      PlusMinus(2, 0.1), (k + 1) * kPi, 8 * (k + 1), x0);
    const MinTimeResult r = Solve(p, ToRest(6, 1e-6));
    ExpectProvenAndVerified(r);
    EXPECT_NEAR(r.arrival_time_s, k * kPi, 1e-9) << k;
  }
}

TEST(MinTime, DoubleIntegratorArrivesAtTwoOverSqrtU) {
  for (const double u : {1.0, 0.25}) {
    Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
    x0[0] = 1.0;
    const double t_star = 2.0 / std::sqrt(u);
    const ScheduleProblem p = Problem(std::make_shared<dynamics::DoubleIntegrator3d>(),
                                      PlusMinus(0, u), 1.5 * t_star, 30, x0);  // t*/20 steps
    const MinTimeResult r = Solve(p, ToRest(6, 1e-7));
    ExpectProvenAndVerified(r);
    EXPECT_NEAR(r.arrival_time_s, t_star, 1e-9) << u;
    ASSERT_EQ(r.schedule.num_burns(), 2) << u;  // full thrust back, then forward
    EXPECT_NEAR(r.schedule.burns[0].end_s, t_star / 2, 1e-9) << u;
    // The fuel of the earliest arrival: on all the time.
    EXPECT_NEAR(r.schedule.delta_v_m_s, u * t_star, 1e-9) << u;
  }
}

TEST(MinTime, RaftIsCaughtAtTimeTwo) {
  Eigen::VectorXd x0(1);
  x0 << 1.0;
  const ScheduleProblem p = Problem(std::make_shared<RaftModel>(), PlusMinus(0, 0.5), 3.0, 30, x0);
  MinTimeSpec spec;
  spec.target = Eigen::VectorXd::Zero(1);
  spec.tolerance = Eigen::VectorXd::Constant(1, 1e-9);
  spec.hold = false;  // the raft is reached, not held (holding needs u = 0 after)
  const MinTimeResult r = Solve(p, spec);
  ExpectProvenAndVerified(r);
  EXPECT_NEAR(r.arrival_time_s, 2.0, 1e-9);
  ASSERT_EQ(r.schedule.num_burns(), 1);
  EXPECT_EQ(r.schedule.burns[0].thruster, 0);
}

// The earliest node at which some pattern of u in {-U, 0, U} per interval
// of dt puts a 1-D double integrator from (x0, 0) in |x|, |v| <= box:
// exhaustive enumeration (depth-first, exact kinematics).
int EarliestReachByEnumeration(double x0, double u_max, double dt, double box, int max_nodes) {
  for (int depth = 1; depth <= max_nodes; ++depth) {
    // Every pattern of `depth` intervals, as a base-3 counter.
    long long count = 1;
    for (int k = 0; k < depth; ++k) count *= 3;
    for (long long code = 0; code < count; ++code) {
      double x = x0, v = 0.0;
      long long c = code;
      for (int k = 0; k < depth; ++k, c /= 3) {
        const double u = (c % 3 - 1) * u_max;
        x += v * dt + 0.5 * u * dt * dt;
        v += u * dt;
      }
      if (std::abs(x) <= box && std::abs(v) <= box) return depth;
    }
  }
  return -1;
}

// A grid that misses the switching time: the earliest node equals that of
// the exhaustive enumeration, and is never before the continuous optimum
// (bang-bang to the box: 2 sqrt(0.95 + 0.05^2 / 2) - 0.05 = 1.9006 s).
TEST(MinTime, AGridMissingTheSwitchMatchesEnumerationAndNeverBeatsT) {
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
  x0[0] = 1.0;
  const ScheduleProblem p = Problem(std::make_shared<dynamics::DoubleIntegrator3d>(),
                                    PlusMinus(0, 1.0), 4.2, 14, x0);  // 0.3 s steps
  MinTimeSpec spec = ToRest(6, 0.05);
  spec.hold = false;
  const MinTimeResult r = Solve(p, spec);
  ExpectProvenAndVerified(r);
  const int earliest = EarliestReachByEnumeration(1.0, 1.0, 0.3, 0.05, 14);
  ASSERT_GT(earliest, 0);
  EXPECT_EQ(r.arrival_node, earliest);
  EXPECT_GE(r.arrival_time_s, 2 * std::sqrt(0.95 + 0.05 * 0.05 / 2) - 0.05);
}

// Hold versus reach: the oscillator passes through z = 0 (with speed) at
// pi / 2 on its free motion; reaching only the position box is then
// immediate without thrust, holding it needs the full stop.
TEST(MinTime, ReachingAPositionIsEarlierThanHoldingIt) {
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
  x0[2] = 1.0;
  const ScheduleProblem p = Problem(std::make_shared<dynamics::HcwModel>(1.0, 1.0),
                                    PlusMinus(2, 0.1), 6 * kPi, 60, x0);  // pi / 10 steps
  MinTimeSpec spec;
  spec.target = Eigen::VectorXd::Zero(6);
  spec.tolerance = Eigen::VectorXd::Constant(6, kInf);
  spec.tolerance[2] = 1e-6;  // the position only
  spec.hold = false;
  const MinTimeResult reach = Solve(p, spec);
  ExpectProvenAndVerified(reach);
  // Free motion z = cos t reaches 0 at pi / 2; thrust towards it cannot make
  // it earlier than the first node of pi / 10 steps where z can be 0: the
  // free motion's is pi / 2 and thrust helps, so the arrival is at most that.
  EXPECT_LE(reach.arrival_time_s, kPi / 2 + 1e-9);
  EXPECT_GT(reach.arrival_time_s, 0.0);
  spec.hold = true;
  spec.tolerance[5] = 1e-6;  // holding z = 0 needs vz = 0 too
  const MinTimeResult hold = Solve(p, spec);
  ExpectProvenAndVerified(hold);
  EXPECT_NEAR(hold.arrival_time_s, 5 * kPi, 1e-9);  // the k = 5 case above
}

// Out of reach by t_N: infeasible, with a reason when no node can reach it.
TEST(MinTime, TargetOutOfReachIsInfeasibleWithAReason) {
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
  x0[0] = 1.0;
  const ScheduleProblem p = Problem(std::make_shared<dynamics::DoubleIntegrator3d>(),
                                    PlusMinus(0, 0.01), 2.0, 20, x0);  // moves 2 cm at most
  const MinTimeResult r = Solve(p, ToRest(6, 1e-6));
  EXPECT_FALSE(r.has_schedule());
  EXPECT_EQ(r.time_status, milp::SolveStatus::kInfeasible);
  EXPECT_EQ(r.candidate_nodes, 0);
  ASSERT_FALSE(r.infeasibility_reasons.empty());
  EXPECT_NE(r.infeasibility_reasons.back().find("out of reach"), std::string::npos);
}

// A fuel budget below what the earliest arrival needs delays it: the double
// integrator with U = 1 needs 2 m/s to stop at 2 s; with coasting (budget
// 1 m/s: accelerate 0.5 s, coast, brake 0.5 s) it takes 0.5 + 1.5 + 0.5 =
// 2.5 s (coast distance 1 - 2 x 0.125 = 0.75 m at 0.5 m/s).
TEST(MinTime, AFuelBudgetDelaysTheArrival) {
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
  x0[0] = 1.0;
  ScheduleProblem p =
      Problem(std::make_shared<dynamics::DoubleIntegrator3d>(), PlusMinus(0, 1.0), 4.0, 40, x0);
  p.objective.kind = ObjectiveKind::kDeltaV;
  MinTimeSpec spec = ToRest(6, 1e-7);
  spec.fuel_budget = 1.0 + 1e-9;
  const MinTimeResult r = Solve(p, spec);
  ExpectProvenAndVerified(r);
  EXPECT_NEAR(r.arrival_time_s, 2.5, 1e-9);
  EXPECT_LE(r.schedule.delta_v_m_s, 1.0 + 1e-6);
}

TEST(MinTime, BadSpecNamesTheField) {
  const ScheduleProblem p = Problem(std::make_shared<dynamics::DoubleIntegrator3d>(),
                                    PlusMinus(0, 1.0), 4.0, 40, Eigen::VectorXd::Zero(6));
  std::string err;
  MinTimeSpec spec = ToRest(5, 1e-6);
  EXPECT_FALSE(spec.IsValid(p, &err));
  EXPECT_NE(err.find("min_time.target has 5 components"), std::string::npos) << err;
  spec = ToRest(6, 1e-6);
  spec.tolerance[3] = -1;
  EXPECT_FALSE(spec.IsValid(p, &err));
  EXPECT_NE(err.find("min_time.tolerance[3] must be >= 0, got -1"), std::string::npos) << err;
  spec.tolerance.setConstant(kInf);
  EXPECT_FALSE(spec.IsValid(p, &err));
  EXPECT_NE(err.find("no target"), std::string::npos) << err;
  spec = ToRest(6, 1e-6);
  spec.fuel_budget = 0;
  EXPECT_FALSE(spec.IsValid(p, &err));
  EXPECT_NE(err.find("min_time.fuel_budget"), std::string::npos) << err;
  EXPECT_THROW(SolveMinTime(p, spec, *milp::MakeCbcSolver()), std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::transcription
