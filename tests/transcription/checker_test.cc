// Tests of transcription::CheckSchedule (checker.h): the linear
// re-propagation against HCW closed forms (TransitionMatrix / ZohInputMatrix
// compositions), window sampling between nodes, enforce_from_s, terminal
// checks, error handling, and the GEO nonlinear replay.
#include "transcription/checker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/discretisation.h"
#include "dynamics/geo_model.h"
#include "dynamics/geo_simulator.h"
#include "dynamics/models.h"
#include "dynamics/thrusters.h"
#include "transcription/problem.h"

namespace thrustsched::transcription {
namespace {

constexpr double kN = 7.2921159e-5;  // GEO mean motion, rad/s
constexpr double kPi = 3.14159265358979323846;
using Vec6 = Eigen::Matrix<double, 6, 1>;

ScheduleProblem HcwProblem(std::vector<double> grid, Eigen::VectorXd x0) {
  ScheduleProblem p;
  p.model = std::make_shared<dynamics::HcwModel>(kN);
  p.thrusters = dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005);  // +R +T +N -R -T -N
  p.grid = std::move(grid);
  p.initial_state = std::move(x0);
  p.rules.min_burn_s = 300;
  p.rules.min_off_same_s = 1200;
  p.rules.min_gap_other_s = 300;
  return p;
}

const dynamics::HcwModel& Hcw(const ScheduleProblem& p) {
  return static_cast<const dynamics::HcwModel&>(*p.model);
}

// Closed-form HCW state at time t (>= t0) under non-overlapping burns of
// single thrusters, composed from Phi and the ZOH input matrix.
Vec6 ClosedForm(const ScheduleProblem& p, std::vector<Burn> burns, double t) {
  const dynamics::HcwModel& hcw = Hcw(p);
  const Eigen::MatrixXd u = p.thrusters.AccelerationMatrix();
  std::sort(burns.begin(), burns.end(),
            [](const Burn& a, const Burn& b) { return a.start_s < b.start_s; });
  Vec6 x = p.initial_state;
  double now = p.grid.front();
  for (const Burn& b : burns) {
    const double s = std::min(std::max(b.start_s, now), t), e = std::min(b.end_s, t);
    x = hcw.TransitionMatrix(s - now) * x;
    now = s;
    if (e > s) {
      x = hcw.TransitionMatrix(e - s) * x + hcw.ZohInputMatrix(e - s) * u.col(b.thruster);
      now = e;
    }
  }
  return hcw.TransitionMatrix(t - now) * x;
}

// Scaled relative distance |a - b| / |b| in the model's state scale.
double RelErr(const ScheduleProblem& p, const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::VectorXd s = p.model->state_scale();
  return (a - b).cwiseQuotient(s).norm() / b.cwiseQuotient(s).norm();
}

TEST(Checker, HcwRePropagationMatchesClosedForm) {
  const Eigen::VectorXd x0 = (Eigen::VectorXd(6) << 1000, -500, 200, 0.01, 0.1, -0.02).finished();
  ScheduleProblem p = HcwProblem(dynamics::UniformGrid(0, 86400, 288), x0);
  // +T on a grid burn, -R off the grid.
  const std::vector<Burn> burns = {{1, 3600, 3900}, {3, 20000.5, 20400.5}};
  CheckOptions opt;
  opt.samples_per_interval = 3;
  const CheckReport r = CheckSchedule(p, burns, opt);
  EXPECT_TRUE(r.operational_ok) << r.Summary();
  ASSERT_EQ(r.sample_times.size(), 288u * 4 + 1);
  ASSERT_EQ(r.sample_states.size(), r.sample_times.size());
  ASSERT_EQ(r.sample_outputs.size(), r.sample_times.size());
  EXPECT_DOUBLE_EQ(r.sample_times.front(), 0.0);
  EXPECT_DOUBLE_EQ(r.sample_times.back(), 86400.0);
  EXPECT_NEAR(r.sample_times[1], 75.0, 1e-9);  // 300 s / (3 + 1)
  EXPECT_NEAR(r.sample_times[4], 300.0, 1e-9);
  const Vec6 ref = ClosedForm(p, burns, 86400);
  EXPECT_LT(RelErr(p, r.final_state, ref), 1e-8) << r.final_state.transpose() << "\n"
                                                 << ref.transpose();
  // The burn changed the state (the comparison is not with the drift alone).
  EXPECT_GT(RelErr(p, ClosedForm(p, {}, 86400), ref), 1e-3);
  // Interior samples and outputs (positions) during and after a burn.
  for (std::size_t k : {std::size_t{4 * 12 + 2}, std::size_t{4 * 67 + 1}, std::size_t{700}}) {
    const Vec6 xk = ClosedForm(p, burns, r.sample_times[k]);
    EXPECT_LT(RelErr(p, r.sample_states[k], xk), 1e-8) << "sample " << k;
    EXPECT_LT((r.sample_outputs[k] - xk.head<3>()).norm(), 1e-8 * xk.head<3>().norm());
  }
  EXPECT_TRUE(r.terminal_ok);
  EXPECT_EQ(r.max_window_violation, 0.0);  // no window
  EXPECT_TRUE(std::isnan(r.worst_time_s));
}

// z(t) oscillates with period P after a +N burn; with nodes half a period
// apart |z| is small at every node but peaks between them.
struct Oscillation {
  ScheduleProblem p;
  std::vector<Burn> burns;
  double period;
};

Oscillation OutOfPlaneOscillation() {
  const double period = 2 * kPi / kN;
  const std::vector<double> grid = {0, 300, 300 + period / 2, 300 + period};
  Oscillation o{HcwProblem(grid, Eigen::VectorXd::Zero(6)), {{2, 0, 300}}, period};
  o.p.window.outputs = {2};
  o.p.window.half_widths = {100.0};  // m; amplitude ~225 m, |z(nodes)| ~2.5 m
  return o;
}

TEST(Checker, WindowViolationBetweenNodesIsCaught) {
  const Oscillation o = OutOfPlaneOscillation();
  CheckOptions opt;
  opt.samples_per_interval = 4;
  const CheckReport r = CheckSchedule(o.p, o.burns, opt);
  // Reference: closed-form z at every sample after t0.
  double worst = 0.0, worst_t = 0.0, worst_node = 0.0;
  for (std::size_t k = 1; k < r.sample_times.size(); ++k) {
    const double z = ClosedForm(o.p, o.burns, r.sample_times[k])(2);
    const double excess = std::abs(z) - 100.0;
    if (excess > worst) {
      worst = excess;
      worst_t = r.sample_times[k];
    }
    if (k % 5 == 0) worst_node = std::max(worst_node, excess);
  }
  ASSERT_GT(worst, 50.0);      // really violated between nodes
  EXPECT_EQ(worst_node, 0.0);  // ... and not at the nodes
  EXPECT_NEAR(r.max_window_violation, worst, 1e-6 * 225);
  EXPECT_EQ(r.max_window_violation_at_nodes, 0.0);
  EXPECT_NEAR(r.worst_time_s, worst_t, 1e-6);
  EXPECT_EQ(r.worst_output, 2);
  EXPECT_NE(r.Summary().find("violated"), std::string::npos) << r.Summary();
  // Nodes only: nothing is seen.
  opt.samples_per_interval = 0;
  const CheckReport nodes = CheckSchedule(o.p, o.burns, opt);
  EXPECT_EQ(nodes.sample_times.size(), 4u);
  EXPECT_EQ(nodes.max_window_violation, 0.0);
}

TEST(Checker, EnforceFromIsRespected) {
  Oscillation o = OutOfPlaneOscillation();
  CheckOptions opt;
  opt.samples_per_interval = 4;
  // Only the last half period counts.
  o.p.window.enforce_from_s = o.p.grid[2];
  const CheckReport r = CheckSchedule(o.p, o.burns, opt);
  double worst = 0.0;
  for (std::size_t k = 10; k < r.sample_times.size(); ++k) {
    worst = std::max(worst, std::abs(ClosedForm(o.p, o.burns, r.sample_times[k])(2)) - 100.0);
  }
  EXPECT_NEAR(r.max_window_violation, worst, 1e-6 * 225);
  EXPECT_GT(r.worst_time_s, o.p.grid[2]);
  // From the last node on: only the final node (|z| ~ 2.5 m) counts.
  o.p.window.enforce_from_s = o.p.grid.back();
  EXPECT_EQ(CheckSchedule(o.p, o.burns, opt).max_window_violation, 0.0);
}

TEST(Checker, InitialNodeIsNeverConstrained) {
  // Start at z = 150 m outside a 100 m window; a quarter period later z = 0.
  const double quarter = 0.5 * kPi / kN;
  ScheduleProblem p =
      HcwProblem({0, quarter}, (Eigen::VectorXd(6) << 0, 0, 150, 0, 0, 0).finished());
  p.window.outputs = {2};
  p.window.half_widths = {100};
  CheckOptions opt;
  opt.samples_per_interval = 0;
  EXPECT_EQ(CheckSchedule(p, {}, opt).max_window_violation, 0.0);
  // One interior sample at 1/8 period: z = 150 cos(pi/4) = 106.07 m.
  opt.samples_per_interval = 1;
  EXPECT_NEAR(CheckSchedule(p, {}, opt).max_window_violation, 150 * std::cos(kPi / 4) - 100, 1e-6);
}

TEST(Checker, TerminalFixedStateAndBox) {
  const Eigen::VectorXd x0 = (Eigen::VectorXd(6) << 500, 0, 0, 0, 0, 0).finished();
  ScheduleProblem p = HcwProblem(dynamics::UniformGrid(0, 43200, 144), x0);
  const std::vector<Burn> burns = {{4, 6000, 6600}};
  const Vec6 xf = ClosedForm(p, burns, 43200);
  const Eigen::VectorXd scale = p.model->state_scale();
  CheckOptions opt;
  opt.samples_per_interval = 1;

  p.terminal.kind = TerminalKind::kFixedState;
  p.terminal.target = xf;
  CheckReport r = CheckSchedule(p, burns, opt);
  EXPECT_TRUE(r.terminal_ok);
  EXPECT_LT(r.terminal_error, 1e-8);
  p.terminal.target(1) += 2e-6 * scale(1);
  r = CheckSchedule(p, burns, opt);
  EXPECT_FALSE(r.terminal_ok);
  EXPECT_NEAR(r.terminal_error, 2e-6, 1e-8);
  EXPECT_NE(r.Summary().find("terminal: VIOLATED"), std::string::npos) << r.Summary();

  p.terminal.kind = TerminalKind::kStateBox;
  p.terminal.target = xf;
  p.terminal.target(0) += 10.0;  // m
  p.terminal.tolerance = Eigen::VectorXd::Constant(6, 1e-3);
  p.terminal.tolerance(0) = 9.99;
  r = CheckSchedule(p, burns, opt);
  EXPECT_FALSE(r.terminal_ok);
  EXPECT_NEAR(r.terminal_error, 0.01 / scale(0), 1e-8);
  p.terminal.tolerance(0) = 10.01;
  r = CheckSchedule(p, burns, opt);
  EXPECT_TRUE(r.terminal_ok);
  EXPECT_EQ(r.terminal_error, 0.0);
  p.terminal.tolerance(0) = std::numeric_limits<double>::infinity();
  p.terminal.target(0) += 1e6;
  EXPECT_TRUE(CheckSchedule(p, burns, opt).terminal_ok);

  p.terminal.kind = TerminalKind::kFree;
  r = CheckSchedule(p, burns, opt);
  EXPECT_TRUE(r.terminal_ok);
  EXPECT_EQ(r.terminal_error, 0.0);
}

TEST(Checker, RuleViolationsUseThrusterNames) {
  ScheduleProblem p = HcwProblem(dynamics::UniformGrid(0, 7200, 24), Eigen::VectorXd::Zero(6));
  const CheckReport r = CheckSchedule(p, {{1, 600, 840}}, {});
  EXPECT_FALSE(r.operational_ok);
  ASSERT_EQ(r.rule_violations.size(), 1u);
  EXPECT_EQ(r.rule_violations[0].rule, "min_burn");
  EXPECT_NE(r.rule_violations[0].message.find("+T burn at 600 s lasts 240 s < min_burn 300 s"),
            std::string::npos)
      << r.rule_violations[0].message;
  EXPECT_NE(r.Summary().find("[min_burn]"), std::string::npos) << r.Summary();
  EXPECT_NE(CheckSchedule(p, {{1, 600, 900}}, {}).Summary().find("operational rules: ok"),
            std::string::npos);
}

TEST(Checker, DisabledThrusterIsAViolationButStillFires) {
  ScheduleProblem p = HcwProblem(dynamics::UniformGrid(0, 7200, 24), Eigen::VectorXd::Zero(6));
  p.thrusters.Disable({"+T"});
  const std::vector<Burn> burns = {{1, 600, 900}};
  const CheckReport r = CheckSchedule(p, burns, {});
  EXPECT_FALSE(r.operational_ok);
  ASSERT_EQ(r.rule_violations.size(), 1u);
  EXPECT_EQ(r.rule_violations[0].rule, "disabled");
  EXPECT_NE(r.rule_violations[0].message.find("+T"), std::string::npos);
  const Vec6 ref = ClosedForm(p, burns, 7200);
  EXPECT_LT(RelErr(p, r.final_state, ref), 1e-8);
}

TEST(Checker, OutsideAndOverlappingBurnsPropagateTheirUnionInsideTheHorizon) {
  ScheduleProblem p = HcwProblem(dynamics::UniformGrid(0, 7200, 24), Eigen::VectorXd::Zero(6));
  // [-100, 400) is reported and fires on [0, 400); [1000, 1400) and
  // [1200, 1500) overlap and fire once on [1000, 1500); a malformed burn does
  // not fire.
  const CheckReport r =
      CheckSchedule(p, {{0, -100, 400}, {4, 3000, 3400}, {4, 3200, 3500}, {2, 50, 10}}, {});
  std::multiset<std::string> rules;
  for (const RuleViolation& v : r.rule_violations) rules.insert(v.rule);
  EXPECT_EQ(rules, std::multiset<std::string>({"horizon", "malformed", "overlap"}));
  const Vec6 ref = ClosedForm(p, {{0, 0, 400}, {4, 3000, 3500}}, 7200);
  EXPECT_LT(RelErr(p, r.final_state, ref), 1e-8);
}

TEST(Checker, InvalidProblemsAndOptionsThrow) {
  ScheduleProblem p = HcwProblem(dynamics::UniformGrid(0, 7200, 24), Eigen::VectorXd::Zero(6));
  ScheduleProblem bad = p;
  bad.initial_state = Eigen::VectorXd::Zero(5);
  try {
    CheckSchedule(bad, {});
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("initial_state"), std::string::npos) << e.what();
  }
  bad = p;
  bad.model = nullptr;
  EXPECT_THROW(CheckSchedule(bad, {}), std::invalid_argument);
  bad = p;
  bad.input_mode = InputMode::kImpulsive;
  EXPECT_THROW(CheckSchedule(bad, {}), std::invalid_argument);
  CheckOptions opt;
  opt.samples_per_interval = -1;
  EXPECT_THROW(CheckSchedule(p, {}, opt), std::invalid_argument);
  opt = {};
  opt.propagation_tolerance = 0.0;
  EXPECT_THROW(CheckSchedule(p, {}, opt), std::invalid_argument);
  // Nonlinear replay needs a GEO problem.
  opt = {};
  opt.nonlinear = std::make_shared<dynamics::GeoSimulator>(dynamics::GeoModelOptions{});
  EXPECT_THROW(CheckSchedule(p, {}, opt), std::invalid_argument);
}

// ---------------------------------------------------------------- GEO

ScheduleProblem GeoProblem(const dynamics::GeoModelOptions& options, double horizon_s,
                           int intervals) {
  ScheduleProblem p;
  p.model = std::make_shared<dynamics::GeoLinearModel>(options);
  p.thrusters = dynamics::ThrusterSet::Anzel4(0.265, 4850, 2005);
  p.grid = dynamics::UniformGrid(0, horizon_s, intervals);
  p.initial_state = Eigen::VectorXd::Zero(6);
  p.window.outputs = {1, 2};
  p.window.half_widths = {dynamics::geo::kWindowHalfWidthRad, dynamics::geo::kWindowHalfWidthRad};
  return p;
}

// Without an explicit simulator, a GEO problem is still judged by the
// nonlinear model (one made from the problem's own GeoModelOptions), with the
// same verdict as the explicit one; it can be switched off.
TEST(CheckerGeo, NonlinearReplayIsTheDefaultForGeo) {
  const dynamics::GeoModelOptions options;
  const ScheduleProblem p = GeoProblem(options, 86400, 24);
  const std::vector<Burn> burns = {{0, 3600, 4500}, {3, 30000, 30600}};
  CheckOptions opt;
  opt.samples_per_interval = 1;
  const CheckReport by_default = CheckSchedule(p, burns, opt);
  ASSERT_TRUE(by_default.nonlinear_checked);
  opt.nonlinear = std::make_shared<dynamics::GeoSimulator>(options);
  const CheckReport explicit_sim = CheckSchedule(p, burns, opt);
  EXPECT_EQ(by_default.max_abs_lat_deg, explicit_sim.max_abs_lat_deg);
  EXPECT_EQ(by_default.max_abs_lon_deg, explicit_sim.max_abs_lon_deg);
  opt.nonlinear.reset();
  opt.nonlinear_default = false;
  EXPECT_FALSE(CheckSchedule(p, burns, opt).nonlinear_checked);
}

TEST(CheckerGeo, NonlinearReplayAgreesWithLinearModel) {
  const dynamics::GeoModelOptions options;
  ScheduleProblem p = GeoProblem(options, 86400, 24);
  const std::vector<Burn> burns = {{0, 3600, 4500}, {3, 30000, 30600}};
  CheckOptions opt;
  opt.samples_per_interval = 1;
  opt.nonlinear = std::make_shared<dynamics::GeoSimulator>(options);
  const CheckReport r = CheckSchedule(p, burns, opt);
  ASSERT_TRUE(r.nonlinear_checked);
  ASSERT_EQ(r.nonlinear_outputs.size(), r.sample_times.size());
  ASSERT_EQ(r.nonlinear_eci.size(), r.sample_times.size());
  double lat = 0, lon = 0, diff = 0, swing = 0;
  for (std::size_t k = 0; k < r.sample_times.size(); ++k) {
    const Eigen::Vector3d& y = r.nonlinear_outputs[k];
    lat = std::max(lat, std::abs(y(1)) * 180 / kPi);
    lon = std::max(lon, std::abs(y(2)) * 180 / kPi);
    diff = std::max(diff, (y.tail<2>() - r.sample_outputs[k].tail<2>()).cwiseAbs().maxCoeff());
    swing = std::max(swing, r.sample_outputs[k].tail<2>().cwiseAbs().maxCoeff());
  }
  EXPECT_DOUBLE_EQ(r.max_abs_lat_deg, lat);
  EXPECT_DOUBLE_EQ(r.max_abs_lon_deg, lon);
  // Linearisation error over one day is a small fraction of the motion.
  EXPECT_GT(swing, 1e-6);
  EXPECT_LT(diff, 2e-3 * swing) << "diff " << diff << " rad, swing " << swing;
  // The burns matter far more than that (so the replay really fired them).
  CheckOptions linear_only = opt;
  linear_only.nonlinear = nullptr;
  const CheckReport drift = CheckSchedule(p, {}, linear_only);
  double burn_effect = 0;
  for (std::size_t k = 0; k < r.sample_times.size(); ++k) {
    burn_effect = std::max(
        burn_effect,
        (drift.sample_outputs[k].tail<2>() - r.sample_outputs[k].tail<2>()).cwiseAbs().maxCoeff());
  }
  EXPECT_GT(burn_effect, 50 * diff) << burn_effect;
  std::printf(
      "GEO 1 day: max |lin - nonlin| = %.3g rad, max |y| = %.3g rad, burn effect %.3g rad\n", diff,
      swing, burn_effect);
  // Inside the 0.05 deg window: no violation, nothing outside.
  EXPECT_EQ(r.max_window_violation_nonlinear_deg, 0.0);
  EXPECT_EQ(r.time_outside_window_nonlinear_s, 0.0);
  EXPECT_NE(r.Summary().find("nonlinear replay"), std::string::npos);
}

TEST(CheckerGeo, NarrowWindowIsLeftAndTimedOutside) {
  const dynamics::GeoModelOptions options;
  ScheduleProblem p = GeoProblem(options, 43200, 12);
  // Half-width 1e-9 rad: every sample after t0 is outside (the station point
  // drifts), t0 itself is not judged. Trapezoid estimate = horizon - spacing / 2.
  p.window.half_widths = {1e-9, 1e-9};
  CheckOptions opt;
  opt.samples_per_interval = 1;
  opt.nonlinear = std::make_shared<dynamics::GeoSimulator>(options);
  const CheckReport r = CheckSchedule(p, {}, opt);
  ASSERT_TRUE(r.nonlinear_checked);
  EXPECT_NEAR(r.time_outside_window_nonlinear_s, 43200 - 1800 / 2.0, 1e-6);
  // Worst violation, in degrees, from the replay's own outputs.
  double worst = 0, worst_t = 0;
  for (std::size_t k = 1; k < r.sample_times.size(); ++k) {
    for (int q : {1, 2}) {
      const double e = (std::abs(r.nonlinear_outputs[k](q)) - 1e-9) * 180 / kPi;
      if (e > worst) {
        worst = e;
        worst_t = r.sample_times[k];
      }
    }
  }
  EXPECT_DOUBLE_EQ(r.max_window_violation_nonlinear_deg, worst);
  EXPECT_DOUBLE_EQ(r.worst_time_nonlinear_s, worst_t);
  // ... and close to the linear check's (rad -> deg).
  EXPECT_NEAR(r.max_window_violation_nonlinear_deg, r.max_window_violation * 180 / kPi,
              0.05 * r.max_window_violation * 180 / kPi);
}

TEST(CheckerGeo, MismatchedSimulatorThrows) {
  dynamics::GeoModelOptions options;
  ScheduleProblem p = GeoProblem(options, 7200, 2);
  options.station_longitude_deg = 119.0;
  CheckOptions opt;
  opt.nonlinear = std::make_shared<dynamics::GeoSimulator>(options);
  EXPECT_THROW(CheckSchedule(p, {}, opt), std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::transcription
