#include "transfer/lyapunov_feedback.h"

#include <atomic>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "common/constants.h"
#include "transfer/replay.h"

namespace thrustsched::transfer {
namespace {

constexpr double kHour = 3600.0;

TEST(LyapunovFeedbackTest, GradientMatchesFiniteDifferences) {
  const ScaledUnits u;
  Vector6 x;
  x << 20.0, 0.3, -0.1, 0.05, -0.02, 1.0;
  TargetElements targets[3] = {TargetElements::Circular(42165e3), TargetElements::Circular(42165e3),
                               TargetElements{}};
  targets[1].free[2] = targets[1].free[4] = true;  // ey and hy left free
  targets[2].value = {30000e3, 0.1, 0.05, 0.01, 0.02};
  for (const TargetElements& t : targets) {
    const Vector6 g = LyapunovGradient(x, t, LyapunovWeights{}, u);
    for (int j = 0; j < 6; ++j) {
      const double h = 1e-6;
      Vector6 xp = x, xm = x;
      xp(j) += h, xm(j) -= h;
      const double fd = (LyapunovValue(xp, t, {}, u) - LyapunovValue(xm, t, {}, u)) / (2 * h);
      EXPECT_NEAR(g(j), fd, 1e-7 * (1 + std::abs(fd))) << j;
    }
  }
  // Bombrun (5.1) at a GTO: 4 (a/a_geo - 1)^2 + 3 e^2 + 10 i^2.
  const Equinoctial q =
      EquinoctialFromKeplerian({24505.9e3, 0.725, 5.2 * common::kDegToRad, 0, 0, 0});
  const double a = 24505.9 / 42165.0 - 1, i = 5.2 * common::kDegToRad;
  EXPECT_NEAR(LyapunovValue(u.ToScaled(q), targets[0], {}, u),
              4 * a * a + 3 * 0.725 * 0.725 + 10 * i * i, 1e-12);
}

// A fast case (10 N from Caillau's GTO, five revolutions): V never
// increases (V' = -acc |F^T grad V| <= 0 for the law (4.7)), the target is
// reached (V <= 1e-5: a within 0.16 %, e within 1.8e-3, i within 1e-3 rad),
// and the Cartesian replay of the same feedback law agrees.
TEST(LyapunovFeedbackTest, FastCaseReachesTheTargetWithVDecreasing) {
  const MinTimeProblem p = CaillauGtoProblem(10.0);
  FeedbackOptions o;
  o.stop_at_saturation = false;
  o.v_stop = 1e-5;
  const FeedbackResult r = RunFeedback(p, o);
  ASSERT_TRUE(r.reached) << r.stop_reason;
  EXPECT_EQ(r.stop_reason, "target");
  EXPECT_LE(r.max_lyapunov_increase, 1e-12);
  for (std::size_t k = 1; k < r.trajectory.size(); ++k) {
    EXPECT_LE(r.trajectory[k].lyapunov, r.trajectory[k - 1].lyapunov + 1e-12) << k;
  }
  EXPECT_LE(r.final_lyapunov, 1e-5);
  EXPECT_NEAR(SemiMajorAxis(r.final_elements), 42165e3, 0.0016 * 42165e3);
  EXPECT_LT(Eccentricity(r.final_elements), 1.9e-3);
  EXPECT_LT(Inclination(r.final_elements), 1e-3);
  EXPECT_GT(r.revolutions, 3);
  EXPECT_LT(r.revolutions, 10);
  // Slower than the minimum time at 10 N (87.28 h by continuation from 60 N).
  EXPECT_GT(r.duration_s / kHour, 87.28);
  EXPECT_LT(r.duration_s / kHour, 1.2 * 87.28);
  const ScaledUnits u;
  const ReplayResult c = Replay(p, r.duration_s, [&](double, const dynamics::Vector6d& rv, double) {
    double efficiency = 0;
    return FeedbackControl(u.ToScaled(EquinoctialFromCartesian(rv, p.mu)), p.target, o, u,
                           &efficiency);
  });
  EXPECT_NEAR(c.final_a_m, SemiMajorAxis(r.final_elements), 10.0);
  EXPECT_NEAR(c.final_e, Eccentricity(r.final_elements), 1e-6);
  EXPECT_NEAR(c.final_mass_kg, r.final_mass_kg, 1e-4);
}

// Bombrun's procedure: feedback while |F^T grad V| > delta, then a
// minimum-time end; the whole is feasible, so it cannot beat the minimum
// time (87.28 h at 10 N), and the on-off variant (4.68)-(4.71) spends less
// propellant than the continuous law.
TEST(LyapunovFeedbackTest, FeedbackWithOptimalEndAndOnOffVariant) {
  const MinTimeProblem p = CaillauGtoProblem(10.0);
  FeedbackOptions o;
  const FeedbackWithEnd c = FinishWithMinimumTime(p, RunFeedback(p, o));
  EXPECT_EQ(c.feedback.stop_reason, "saturation");
  ASSERT_TRUE(c.end.converged);
  EXPECT_GE(c.total_duration_s / kHour, 87.28);
  EXPECT_LT(c.total_duration_s / kHour, 1.2 * 87.28);
  EXPECT_NEAR(c.end.final_elements.p_m, 42165e3, 1.0);
  o.on_off = true;
  const FeedbackWithEnd h = FinishWithMinimumTime(p, RunFeedback(p, o));
  ASSERT_TRUE(h.end.converged);
  EXPECT_LT(h.total_propellant_kg, c.total_propellant_kg - 5.0);
  EXPECT_GT(h.total_duration_s, c.total_duration_s);
  EXPECT_LE(h.feedback.max_lyapunov_increase, 1e-12);
  double coasting = 0;
  for (const FeedbackSample& s : h.feedback.trajectory) coasting += s.throttle == 0 ? 1 : 0;
  EXPECT_GT(coasting, 0);
}

// A stop request (Ctrl-C) halts the feedback at the next accepted step with
// what it has propagated so far.
TEST(LyapunovFeedbackTest, InterruptStopsThePropagationWhereItIs) {
  const MinTimeProblem p = CaillauGtoProblem(10.0);
  std::atomic<bool> stop{true};
  FeedbackOptions o;
  o.interrupt = &stop;
  const FeedbackResult r = RunFeedback(p, o);
  EXPECT_EQ(r.stop_reason, "interrupted");
  EXPECT_FALSE(r.reached);
  EXPECT_EQ(r.duration_s, 0.0);
  EXPECT_EQ(r.final_mass_kg, p.mass_kg);
  ASSERT_FALSE(r.trajectory.empty());
  ShootingOptions shooting;
  shooting.interrupt = &stop;
  const FeedbackWithEnd e = FinishWithMinimumTime(p, r, shooting);
  EXPECT_TRUE(e.end.interrupted);
  EXPECT_EQ(e.end.evaluations, 0);
}

TEST(LyapunovFeedbackTest, BadOptionsAreRefusedNamingTheField) {
  FeedbackOptions o;
  o.on_off_p = 2;
  std::string error;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("on_off_p"), std::string::npos);
  EXPECT_THROW(RunFeedback(CaillauGtoProblem(1.0), o), std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::transfer
