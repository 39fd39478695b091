#include "transfer/feedback_switch.h"

#include <string>

#include <gtest/gtest.h>

namespace thrustsched::transfer {
namespace {

constexpr double kHour = 3600.0;

// The saturation rule is FinishWithMinimumTime at the feedback's end; the
// earliest-convergent rule, tried every 12 h backwards, switches earlier and
// is not slower (an end from an earlier point is a minimum over transfers
// that include the feedback's arc). Every end reaches the target, and the
// ends found from earlier points are shorter than the feedback from there to
// the saturation point plus the saturation end.
TEST(FeedbackSwitchTest, EarliestConvergentSwitchesEarlierAndIsNotSlower) {
  const MinTimeProblem p = CaillauGtoProblem(10.0);
  const FeedbackResult f = RunFeedback(p, FeedbackOptions{});
  ASSERT_EQ(f.stop_reason, "saturation");
  SwitchOptions s;
  const SwitchedTransfer at_saturation = SwitchToMinimumTime(p, f, s);
  ASSERT_TRUE(at_saturation.transfer.end.converged);
  EXPECT_EQ(at_saturation.switch_s, f.duration_s);
  ASSERT_EQ(at_saturation.attempts.size(), 1u);
  const FeedbackWithEnd direct = FinishWithMinimumTime(p, f);
  EXPECT_DOUBLE_EQ(at_saturation.transfer.total_duration_s, direct.total_duration_s);

  s.rule = SwitchRule::kEarliestConvergent;
  s.interval_s = 12 * kHour;
  const SwitchedTransfer earliest = SwitchToMinimumTime(p, f, s);
  ASSERT_TRUE(earliest.transfer.end.converged);
  ASSERT_GE(earliest.attempts.size(), 2u);
  EXPECT_LT(earliest.switch_s, f.duration_s - 11 * kHour);
  EXPECT_EQ(earliest.transfer.feedback.duration_s, earliest.switch_s);
  EXPECT_EQ(earliest.transfer.feedback.stop_reason, "switch");
  EXPECT_LE(earliest.transfer.total_duration_s,
            at_saturation.transfer.total_duration_s + 1e-3 * kHour);
  for (const SwitchAttempt& a : earliest.attempts) {
    if (a.converged) {
      EXPECT_LE(a.switch_s + a.end_s, at_saturation.transfer.total_duration_s + 1.0);
    }
  }
  // The attempts go backwards 12 h apart (to the sample at or before), and
  // the one kept is the last convergent one.
  for (std::size_t k = 1; k < earliest.attempts.size(); ++k) {
    EXPECT_LT(earliest.attempts[k].switch_s, earliest.attempts[k - 1].switch_s);
    EXPECT_NEAR(earliest.attempts[k].switch_s, f.duration_s - 12 * kHour * k,
                0.5 * kHour);  // samples <= 0.25 h apart
  }
  // Mass and time add up across the switch.
  EXPECT_NEAR(earliest.transfer.end.final_mass_kg + earliest.transfer.total_propellant_kg,
              p.mass_kg, 1e-6);
  EXPECT_NEAR(earliest.transfer.end.final_elements.p_m, 42165e3, 1.0);

  // The shortest-convergent rule tries the same points and keeps the
  // shortest feedback + end among them.
  s.rule = SwitchRule::kShortestConvergent;
  const SwitchedTransfer shortest = SwitchToMinimumTime(p, f, s);
  ASSERT_EQ(shortest.attempts.size(), earliest.attempts.size());
  for (const SwitchAttempt& a : shortest.attempts) {
    if (a.converged) {
      EXPECT_LE(shortest.transfer.total_duration_s, a.switch_s + a.end_s + 1e-6);
    }
  }
  EXPECT_LE(shortest.transfer.total_duration_s, earliest.transfer.total_duration_s);
  EXPECT_NEAR(shortest.transfer.total_duration_s,
              shortest.switch_s + shortest.transfer.end.duration_s, 1e-6);
}

TEST(FeedbackSwitchTest, TruncationKeepsTheSampleAndTheBadIntervalIsRefused) {
  const MinTimeProblem p = CaillauGtoProblem(10.0);
  const FeedbackResult f = RunFeedback(p, FeedbackOptions{});
  const std::size_t k = f.trajectory.size() / 2;
  const FeedbackResult t = TruncateFeedback(f, k, p.initial.l_rad);
  EXPECT_EQ(t.duration_s, f.trajectory[k].t_s);
  EXPECT_EQ(t.final_mass_kg, f.trajectory[k].mass_kg);
  EXPECT_NEAR(t.propellant_kg, p.mass_kg - f.trajectory[k].mass_kg, 1e-9);
  EXPECT_EQ(t.trajectory.size(), k + 1);
  EXPECT_THROW(TruncateFeedback(f, f.trajectory.size(), 0.0), std::invalid_argument);
  SwitchOptions s;
  s.interval_s = 0;
  std::string error;
  EXPECT_FALSE(s.IsValid(&error));
  EXPECT_NE(error.find("interval_s"), std::string::npos);
  EXPECT_THROW(SwitchToMinimumTime(p, f, s), std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::transfer
