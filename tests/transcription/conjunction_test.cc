// Conjunction data and its verification (Serra 2015 ch. 4) on the small
// avoidance problem of conjunction_test_util.h:
//  - Serra's LVLH frame onto ours, eps' from the global risk (sec. 4.2.1);
//  - the specification's validation names the field and the value;
//  - the covariance repair changes only what is negative, in nondimensional units;
//  - the geometry (secondary's mean and covariance at the check times) equals
//    the closed-form Yamanaka-Ankersen propagation (the MILP uses the
//    discretisation, the reference the closed form);
//  - the verification's Monte Carlo agrees with the computed instantaneous
//    risk (interval risk >= maximum instantaneous risk), and a solved plan
//    has no collision, linear or nonlinear;
//  - with on-off thrusters, SolveConjunction starts from the plan without
//    the conjunction repaired at its least-missed faces, whose cost without
//    the conjunction is a valid lower bound, and ends with a plan that
//    passes the verification (node limits, no wall-clock dependence).
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "milp/cbc_solver.h"
#include "tests/transcription/conjunction_test_util.h"
#include "transcription/collision_probability.h"
#include "transcription/conjunction.h"
#include "transcription/conjunction_check.h"
#include "transcription/conjunction_geometry.h"
#include "transcription/conjunction_solve.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"

namespace thrustsched::transcription {
namespace {

TEST(ConjunctionTest, SerraFrameAndThreshold) {
  const Eigen::Matrix3d m = SerraLvlhToLocal();
  EXPECT_NEAR((m * m.transpose() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(m.determinant(), 1.0, 1e-15);  // both frames are right-handed
  // Serra: x along-track, y = -h, z = nadir -> ours: y along-track, z = +h, x = -nadir.
  EXPECT_EQ(m * Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(m * Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(m * Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(-1, 0, 0));
  // Examples 1 and 2: eps = 1e-4 over 1e5 s and 1.8e5 s (printed 1e-9, 5.56e-10).
  EXPECT_DOUBLE_EQ(InstantaneousThreshold(1e-4, 1e5), 1e-9);
  EXPECT_NEAR(InstantaneousThreshold(1e-4, 1.8e5), 5.56e-10, 0.001 * 5.56e-10);
  EXPECT_THROW(InstantaneousThreshold(2.0, 1e5), std::invalid_argument);
}

TEST(ConjunctionTest, ValidationNamesTheField) {
  auto error_of = [](const std::function<void(ConjunctionSpec&)>& edit) {
    ConjunctionSpec c = *testing::SmallAvoidance().conjunction;
    edit(c);
    std::string err;
    EXPECT_FALSE(c.IsValid(&err));
    return err;
  };
  EXPECT_NE(error_of([](ConjunctionSpec& c) { c.radius_m = -1; }).find("conjunction.radius_m"),
            std::string::npos);
  EXPECT_NE(error_of([](ConjunctionSpec& c) { c.covariance(0, 1) = 3.0; }).find("not symmetric"),
            std::string::npos);
  EXPECT_NE(error_of([](ConjunctionSpec& c) {
              c.instantaneous_threshold = 0.7;
            }).find("conjunction.instantaneous_threshold"),
            std::string::npos);
  EXPECT_NE(error_of([](ConjunctionSpec& c) {
              c.covariance(0, 1) = c.covariance(1, 0) = 1e3;
            }).find("covariance_repair"),
            std::string::npos);
  EXPECT_NE(error_of([](ConjunctionSpec& c) {
              c.polytope = KeepOutPolytope::Cube(10.0);  // does not contain the 15 m ball
            }).find("does not contain the ball"),
            std::string::npos);
  ScheduleProblem p = testing::SmallAvoidance();
  p.conjunction->check_end_s = 30000.0;
  std::string err;
  EXPECT_FALSE(p.IsValid(&err));
  EXPECT_NE(err.find("not inside the horizon"), std::string::npos) << err;
}

TEST(ConjunctionTest, RepairInNondimensionalUnits) {
  // Serra (4.22)'s out-of-plane block, indefinite by rounding: var(y) printed 0.
  ConjunctionSpec c = *testing::SmallAvoidance().conjunction;
  c.covariance = Eigen::MatrixXd::Zero(6, 6);
  c.covariance(0, 0) = 15526.4;
  c.covariance(3, 3) = 0.0532e-6;
  c.covariance(2, 5) = c.covariance(5, 2) = 0.0015e-3;
  c.covariance(5, 5) = 0.0005e-6;
  c.repair = CovarianceRepair::kClipEigenvalues;
  const double t = 1.0 / 7.4996e-5;
  double low = 0.0;
  const Eigen::MatrixXd fixed = EffectiveCovariance(c, t, &low);
  EXPECT_LT(low, 0.0);
  // Only var(y) moves noticeably, and by less than the printed resolution (0.1 m^2).
  EXPECT_GT(fixed(2, 2), 4e-3);
  EXPECT_LT(fixed(2, 2), 0.05);
  EXPECT_NEAR(fixed(5, 5), 0.0005e-6, 1e-11);
  EXPECT_NEAR(fixed(0, 0), 15526.4, 1e-9);
  Eigen::VectorXd d = Eigen::VectorXd::Ones(6);
  d.tail(3).setConstant(t);
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(d.asDiagonal() * fixed * d.asDiagonal())
                .eigenvalues()
                .minCoeff(),
            -1e-9);
}

TEST(ConjunctionTest, GeometryMatchesClosedFormPropagation) {
  const ScheduleProblem p = testing::SmallAvoidance(7);
  BuildOptions b;
  const dynamics::DiscreteModel d =
      dynamics::Discretize(*p.model, p.thrusters.AccelerationMatrix(), p.grid, b.discretisation);
  const ConjunctionGeometry g = ComputeConjunctionGeometry(p, d, b.discretisation);
  ASSERT_EQ(g.checks.size(), 7u);
  const auto& ya = static_cast<const dynamics::YamanakaAnkersenModel&>(*p.model);
  const double q = NormalUpperQuantile(1e-6);
  for (const CheckGeometry& k : g.checks) {
    const Eigen::MatrixXd phi = ya.TransitionMatrix(k.t(), 0.0);
    const Eigen::Vector3d mean = (phi * p.conjunction->secondary_state).head<3>();
    const Eigen::Matrix3d cov =
        (phi * p.conjunction->covariance * phi.transpose()).topLeftCorner<3, 3>();
    EXPECT_LT((k.secondary - mean).norm(), 1e-6 * (1.0 + mean.norm())) << k.t();
    EXPECT_LT((k.covariance - cov).norm(), 1e-7 * cov.norm()) << k.t();
    // Margins of the cube faces: Phi^-1(1 - eps') sigma along each axis.
    for (int f = 0; f < 6; ++f) {
      EXPECT_NEAR(k.margins[f], q * std::sqrt(cov(f / 2, f / 2)), 1e-6 * k.margins[f]);
    }
  }
  EXPECT_NEAR(g.checks[3].t(), 10000.0, 1e-9);  // the middle check is the TCA
  EXPECT_LT(g.checks[3].secondary.norm(), 1e-6);
}

TEST(ConjunctionCheckTest, MonteCarloAgreesWithComputedRisk) {
  const ScheduleProblem p = testing::SmallAvoidance(41);
  ConjunctionCheckOptions o;
  o.monte_carlo_samples = 20000;
  o.nonlinear = false;
  const ConjunctionCheckReport r = CheckConjunction(p, {}, {}, o);  // no manoeuvre
  // The mean passes through the primary: a large instantaneous risk.
  EXPECT_GT(r.max_risk_unmanoeuvred, 1e-3);
  EXPECT_NEAR(r.max_risk, r.max_risk_unmanoeuvred, 1e-15);
  EXPECT_FALSE(r.risk_ok);
  // The interval risk (Monte Carlo) is at least the largest instantaneous one.
  const double p_mc = static_cast<double>(r.collisions_unmanoeuvred_linear) / r.samples;
  const double sd = std::sqrt(r.max_risk_unmanoeuvred * (1 - r.max_risk_unmanoeuvred) / r.samples);
  EXPECT_GT(p_mc, r.max_risk_unmanoeuvred - 4 * sd);
  EXPECT_EQ(r.collisions_linear, r.collisions_unmanoeuvred_linear);
  EXPECT_FALSE(r.passed());
}

TEST(ConjunctionCheckTest, SolvedPlanHasNoCollision) {
  const ScheduleMilp milp(testing::SmallAvoidance(41), BuildOptions{});
  const auto solver = milp::MakeCbcSolver();
  SolveScheduleOptions so;
  so.milp.relative_gap = 1e-6;
  so.milp.max_nodes = 20000;  // deterministic stop; the case is small
  const ScheduleResult res = SolveBuilt(milp, *solver, so);
  ASSERT_TRUE(res.has_schedule());
  EXPECT_LT(res.impulsive_check.terminal_error, 1e-6);
  ConjunctionCheckOptions o;
  o.monte_carlo_samples = 5000;
  const ConjunctionCheckReport r = CheckConjunction(milp.problem(), {}, res.schedule.impulses, o);
  EXPECT_TRUE(r.risk_ok) << r.max_risk;
  EXPECT_LE(r.max_risk, 1e-6);
  EXPECT_EQ(r.collisions_linear, 0);
  ASSERT_TRUE(r.nonlinear_checked) << r.nonlinear_note;
  EXPECT_EQ(r.collisions_nonlinear, 0);
  // Linear and two-body Monte Carlo see the same closest approach (km-scale
  // relative motion, so the linearisation error is centimetres).
  EXPECT_NEAR(r.min_distance_linear_m, r.min_distance_nonlinear_m, 0.5);
  EXPECT_GT(r.collisions_unmanoeuvred_linear, 0);
  EXPECT_TRUE(r.passed());
}

// On-off thrusters (5e-5 m/s^2, one 500 s interval = 0.025 m/s) on HCW about
// GEO, the primary at rest at the origin: without the conjunction the
// optimum is no burn at all; the secondary passes 5 m above the origin
// (orbit normal) at t = 10000 s, so the keep-out rows (Serra 2015 Problem
// 10) force a burn, and the face the plan misses least is the same at every
// check (below the secondary).
ScheduleProblem SmallOnOffAvoidance() {
  ScheduleProblem p;
  p.model = std::make_shared<const dynamics::HcwModel>(7.2921159e-5);
  p.thrusters = dynamics::ThrusterSet::Ideal6(0.05, 1000, 300);
  p.grid = dynamics::UniformGrid(0.0, 20000.0, 40);
  p.initial_state = Eigen::VectorXd::Zero(6);
  ConjunctionSpec c;
  c.secondary_state = Eigen::VectorXd::Zero(6);
  c.secondary_state << 0.0, 0.0, 5.0, 0.01, -0.03, 0.0;
  c.state_time_s = 10000.0;
  Eigen::VectorXd sd(6);
  sd << 20, 30, 5, 1e-3, 2e-3, 5e-4;
  c.covariance = sd.cwiseAbs2().asDiagonal();
  c.radius_m = 15.0;
  c.instantaneous_threshold = 1e-6;
  c.num_checks = 5;
  c.check_start_s = 9000.0;
  c.check_end_s = 11000.0;
  c.cost_budget = 0.2;
  p.conjunction = c;
  return p;
}

TEST(ConjunctionSolveTest, OnOffStartRepairsThePlanWithoutTheConjunction) {
  const ScheduleMilp milp(SmallOnOffAvoidance(), BuildOptions{});
  const auto solver = milp::MakeCbcSolver();
  SolveScheduleOptions so;
  so.milp.relative_gap = 1e-6;
  so.milp.max_nodes = 2000;  // deterministic stop; the case is small
  const ConjunctionStart start = FixedFaceStart(milp, *solver, so.milp);
  ASSERT_GT(start.x.size(), 0) << "no repaired start";
  EXPECT_NE(start.label.find("repaired"), std::string::npos) << start.label;
  EXPECT_NEAR(start.lower_bound, 0.0, 1e-9);  // no burn without the conjunction
  EXPECT_GT(start.objective, 0.0);            // the repair must burn
  EXPECT_LT(milp.lp().MaxViolation(start.x), 1e-6);

  // The repair is first looked for over the slots near the plan's burns and
  // the half orbit before the checks (here the plan has no burn: the slots
  // from 9000 - pi/n = -34080 s, i.e. the whole horizon up to 11000 s).
  EXPECT_NE(start.label.find("over 132 slots"), std::string::npos) << start.label;
  // The plan without the conjunction: no burn, and it fails the conjunction.
  EXPECT_NEAR(start.without_objective, 0.0, 1e-9);
  ASSERT_EQ(start.without_x.size(), milp.lp().num_cols());
  const Schedule without = milp.Decode(start.without_x);
  EXPECT_EQ(without.num_burns(), 0);
  ConjunctionCheckOptions quick;
  quick.monte_carlo_samples = 2000;
  EXPECT_FALSE(CheckConjunction(milp.problem(), without.burns, {}, quick).risk_ok);

  const ConjunctionSolve cs = SolveConjunction(milp, *solver, so);
  ASSERT_TRUE(cs.result.has_schedule());
  EXPECT_EQ(cs.without_objective, start.without_objective);
  EXPECT_EQ(cs.start_objective, start.objective);
  EXPECT_EQ(cs.lower_bound, start.lower_bound);
  EXPECT_LE(cs.result.solve.objective, start.objective + 1e-9);
  EXPECT_GE(cs.result.solve.objective, cs.lower_bound - 1e-9);
  EXPECT_GT(cs.result.schedule.num_burns(), 0);
  EXPECT_TRUE(cs.result.checked);
  EXPECT_TRUE(cs.result.check.operational_ok);
  ConjunctionCheckOptions o;
  o.monte_carlo_samples = 2000;
  const ConjunctionCheckReport r =
      CheckConjunction(milp.problem(), cs.result.schedule.burns, {}, o);
  EXPECT_TRUE(r.risk_ok) << r.max_risk;
  EXPECT_EQ(r.collisions_linear, 0);
  EXPECT_GT(r.collisions_unmanoeuvred_linear, 0);  // the manoeuvre matters
  EXPECT_FALSE(r.nonlinear_checked);               // HCW: linear only, and said why
  EXPECT_FALSE(r.nonlinear_note.empty());
}

// A secondary passing 5 km from the primary's plan: every check is clear,
// the plan without the conjunction is feasible with it and costs the lower
// bound, so the solve ends after the start, with no budget round and the
// plan proven optimal (the gap to the bound is 0).
TEST(ConjunctionSolveTest, StartAtTheBoundWithoutTheConjunctionEndsTheSolve) {
  ScheduleProblem p = SmallOnOffAvoidance();
  p.conjunction->secondary_state[2] = 5000.0;
  const ScheduleMilp milp(p, BuildOptions{});
  const auto solver = milp::MakeCbcSolver();
  SolveScheduleOptions so;
  so.milp.relative_gap = 1e-6;
  so.milp.max_nodes = 2000;
  const ConjunctionSolve cs = SolveConjunction(milp, *solver, so);
  ASSERT_TRUE(cs.result.has_schedule());
  EXPECT_TRUE(cs.rounds.empty());
  EXPECT_EQ(cs.result.solve.status, milp::SolveStatus::kOptimal);
  EXPECT_NEAR(cs.result.solve.objective, 0.0, 1e-9);
  EXPECT_NEAR(cs.without_objective, 0.0, 1e-9);
  EXPECT_EQ(cs.result.schedule.num_burns(), 0);
  EXPECT_TRUE(cs.result.checked);
  EXPECT_LT(milp.lp().MaxViolation(cs.result.solve.x), 1e-6);
  ConjunctionCheckOptions o;
  o.monte_carlo_samples = 2000;
  const ConjunctionCheckReport r = CheckConjunction(p, cs.result.schedule.burns, {}, o);
  EXPECT_TRUE(r.passed()) << r.max_risk;
}

}  // namespace
}  // namespace thrustsched::transcription
