// Serra 2015 ch. 4 Examples 1 and 2 from the shipped scenario files
// (data/scenarios/serra_avoidance_ex{1,2}.json) against the published values
// in data/reference/serra_avoidance.json:
//  - the printed covariance (4.21) is indefinite far beyond its rounding and
//    becomes positive semi-definite to rounding with the sign of cov(x, vx)
//    changed (the scenario's correction); (4.22) is indefinite by rounding only;
//  - the unmanoeuvred maximum instantaneous risk: Example 1 within 5 %;
//    Example 2 is 14 % above the published value, and the published value
//    lies inside the range that the printed resolution of Table 4.4's
//    velocities (+-0.05 mm/s) allows;
//  - the avoidance plans (fixed-face start, one node-limited round, so the
//    test does not depend on wall-clock time) cost within 5 % of Tables 4.2
//    and 4.5, go where Serra's go (out of plane, along-track), and pass the
//    verification (risk below eps', no Monte Carlo collision, linear or
//    two-body). Proven optima and CBC times are the benchmark's job.
#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>

#include "app/scenario.h"
#include "milp/cbc_solver.h"
#include "transcription/conjunction_check.h"
#include "transcription/conjunction_solve.h"

namespace thrustsched::app {
namespace {

nlohmann::json Reference(const std::string& example) {
  std::ifstream in(std::string(THRUSTSCHED_DATA_DIR) + "/reference/serra_avoidance.json");
  const nlohmann::json all = nlohmann::json::parse(in);
  for (const auto& c : all.at("cases")) {
    if (c.at("example") == example) return c;
  }
  throw std::runtime_error("no case " + example);
}

Scenario Load(const std::string& example) {
  return LoadScenario(std::string(THRUSTSCHED_DATA_DIR) + "/scenarios/serra_avoidance_" + example +
                      ".json");
}

Eigen::MatrixXd Printed(const nlohmann::json& c) {
  Eigen::MatrixXd m(6, 6);
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) m(i, j) = c.at("covariance_serra")[i][j];
  }
  return m;
}

// Smallest eigenvalue in units m and m/(s n): positions and velocities alike.
double ScaledMinEigenvalue(const Eigen::MatrixXd& cov, double n) {
  Eigen::VectorXd d = Eigen::VectorXd::Ones(6);
  d.tail(3).setConstant(1.0 / n);
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(d.asDiagonal() * cov * d.asDiagonal())
      .eigenvalues()
      .minCoeff();
}

TEST(SerraAvoidanceTest, PrintedCovarianceDefects) {
  const nlohmann::json ex1 = Reference("ex1"), ex2 = Reference("ex2");
  const double n = ex1.at("mean_motion_rad_s");
  Eigen::MatrixXd c1 = Printed(ex1);
  EXPECT_LT(ScaledMinEigenvalue(c1, n), -1000.0);  // -2418 m^2: not a rounding effect
  const auto& fix = ex1.at("covariance_correction");
  const int i = fix["entry"][0], j = fix["entry"][1];
  c1(i, j) = c1(j, i) = fix["used"].get<double>();
  EXPECT_GT(ScaledMinEigenvalue(c1, n), -0.02);  // rounding of 0.05 m^2 entries
  EXPECT_GT(ScaledMinEigenvalue(Printed(ex2), n), -0.01);
  EXPECT_LT(ScaledMinEigenvalue(Printed(ex2), n), 0.0);
}

double UnmanoeuvredRisk(const Scenario& s) {
  transcription::ConjunctionCheckOptions o;
  o.monte_carlo_samples = 0;
  return transcription::CheckConjunction(s.problem, {}, {}, o).max_risk_unmanoeuvred;
}

TEST(SerraAvoidanceTest, UnmanoeuvredRiskExample1) {
  const double published = Reference("ex1").at("unmanoeuvred_max_risk");  // 9.74e-2, N' = 500
  const Scenario s = Load("ex1");
  ASSERT_EQ(s.problem.conjunction->num_checks, 500);
  EXPECT_NEAR(UnmanoeuvredRisk(s), published, 0.05 * published);
}

TEST(SerraAvoidanceTest, UnmanoeuvredRiskExample2WithinPrintedResolution) {
  const double published = Reference("ex2").at("unmanoeuvred_max_risk");  // 3.46e-2, N' = 600
  Scenario s = Load("ex2");
  const double risk = UnmanoeuvredRisk(s);
  EXPECT_NEAR(risk, 0.0396, 0.0005);  // measured: +14 % (documented in data/scenarios/README.md)
  // The velocities of Table 4.4 have 3 digits (0.1 mm/s): their half units
  // in the two in-plane components bracket the published value.
  double low = 1.0, high = 0.0;
  s.problem.conjunction->num_checks = 120;  // a coarser grid: the peak is 2000 s wide
  const Eigen::VectorXd state = s.problem.conjunction->secondary_state;
  for (double dx : {-5e-5, 5e-5}) {
    for (double dz : {-5e-5, 5e-5}) {
      s.problem.conjunction->secondary_state = state;
      s.problem.conjunction->secondary_state[4] += dx;  // along-track (Serra x)
      s.problem.conjunction->secondary_state[3] += dz;  // radial (Serra -z)
      const double r = UnmanoeuvredRisk(s);
      low = std::min(low, r);
      high = std::max(high, r);
    }
  }
  EXPECT_LT(low, published);
  EXPECT_GT(high, published);
}

struct Plan {
  transcription::ConjunctionSolve solve;
  transcription::ConjunctionCheckReport check;
};

Plan SolveExample(const std::string& example) {
  const Scenario s = Load(example);
  const transcription::ScheduleMilp milp(s.problem, s.build);
  const auto solver = milp::MakeCbcSolver();
  transcription::SolveScheduleOptions o{};
  o.build = s.build;
  o.milp = s.solve;
  o.milp.time_limit_s = std::numeric_limits<double>::infinity();
  o.milp.max_nodes = 50;  // deterministic: the start, then a short search
  o.milp.threads = 1;
  transcription::ConjunctionSolveOptions co = s.conjunction_solve;
  co.max_rounds = 1;
  Plan p;
  p.solve = transcription::SolveConjunction(milp, *solver, o, co);
  transcription::ConjunctionCheckOptions v;
  v.monte_carlo_samples = 1000;
  p.check = transcription::CheckConjunction(s.problem, {}, p.solve.result.schedule.impulses, v);
  return p;
}

void ExpectVerified(const Plan& p) {
  ASSERT_TRUE(p.solve.result.has_schedule());
  EXPECT_TRUE(p.solve.result.checked);
  EXPECT_LT(p.solve.result.impulsive_check.terminal_error, 1e-6);
  EXPECT_TRUE(p.check.risk_ok) << p.check.max_risk;
  EXPECT_EQ(p.check.collisions_linear, 0);
  EXPECT_TRUE(p.check.nonlinear_checked) << p.check.nonlinear_note;
  EXPECT_EQ(p.check.collisions_nonlinear, 0);
  EXPECT_GT(p.check.collisions_unmanoeuvred_linear, 0);  // the manoeuvre matters
}

// Sum of |impulse| per axis of the local frame (R, T, N).
Eigen::Vector3d PerAxis(const transcription::Schedule& s, const dynamics::ThrusterSet& thrusters) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (const auto& im : s.impulses)
    out += im.delta_v_m_s * thrusters.thruster(im.thruster).direction.cwiseAbs();
  return out;
}

TEST(SerraAvoidanceTest, Example1PlanWithinFivePercentOutOfPlane) {
  const double published = Reference("ex1").at("risk_selection").at("cost_mm_s");  // 4.651
  const Plan p = SolveExample("ex1");
  ExpectVerified(p);
  const double cost = 1e3 * p.solve.result.schedule.consumption_l1_m_s;
  EXPECT_NEAR(cost, published, 0.05 * published);
  const Eigen::Vector3d axes = PerAxis(p.solve.result.schedule, Load("ex1").problem.thrusters);
  EXPECT_GT(axes[2], 0.95 * axes.sum());  // Table 4.3: all impulses out of plane
}

TEST(SerraAvoidanceTest, Example2PlanWithinFivePercentAlongTrack) {
  const double published = Reference("ex2").at("risk_selection").at("cost_mm_s");  // 1.0668
  const Plan p = SolveExample("ex2");
  ExpectVerified(p);
  const double cost = 1e3 * p.solve.result.schedule.consumption_l1_m_s;
  EXPECT_NEAR(cost, published, 0.05 * published);
  const Eigen::Vector3d axes = PerAxis(p.solve.result.schedule, Load("ex2").problem.thrusters);
  EXPECT_GT(axes[1], 0.95 * axes.sum());  // Table 4.6: all impulses along Serra's x (our T)
}

}  // namespace
}  // namespace thrustsched::app
