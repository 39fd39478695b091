// Tests for dynamics/propagation.h against the closed-form HCW composition
// (TransitionMatrix, ZohInputMatrix) and the Yamanaka-Ankersen STM.
#include "dynamics/propagation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dynamics/models.h"
#include "dynamics/thrusters.h"
#include "tests/dynamics/dynamics_test_util.h"

namespace thrustsched::dynamics {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using testing_util::ColumnRelError;
using testing_util::kGeoMeanMotion;

// Closed-form HCW response: the input is constant between consecutive change
// times, so x advances by Phi(dt) x + G(dt) U w on each piece.
Eigen::VectorXd HcwClosedForm(const HcwModel& hcw, const Eigen::MatrixXd& u, Eigen::VectorXd x,
                              double t0, const std::vector<InputPulse>& pulses, double t) {
  std::vector<double> cuts = {t0, t};
  for (const InputPulse& p : pulses) {
    for (double c : {p.start_s, p.end_s}) {
      if (c > t0 && c < t) cuts.push_back(c);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double ta = cuts[k], tb = cuts[k + 1];
    if (tb <= ta) continue;
    Eigen::VectorXd w = Eigen::VectorXd::Zero(u.cols());
    for (const InputPulse& p : pulses) {
      if (p.start_s <= ta && p.end_s >= tb) w[p.column] += 1.0;
    }
    x = hcw.TransitionMatrix(tb - ta) * x + hcw.ZohInputMatrix(tb - ta) * (u * w);
  }
  return x;
}

TEST(PropagateLinearTest, HcwBurnsMatchClosedFormComposition) {
  const HcwModel hcw(kGeoMeanMotion);
  const Eigen::MatrixXd u = ThrusterSet::Ideal6(0.265, 4850.0, 2005.0).AccelerationMatrix();
  Eigen::VectorXd x0(6);
  x0 << 1200.0, -3500.0, 800.0, 0.05, -0.12, 0.02;
  const double t0 = 37.5;
  // Switch times off any regular step; overlapping pulses on one column add up;
  // a pulse starting before t0 is on from t0; a zero-length pulse does nothing.
  const std::vector<InputPulse> pulses = {{1, 123.4, 1000.7},      {1, 600.3, 700.9},
                                          {3, 5000.25, 5317.77},   {5, 0.0, 90.1},
                                          {2, 40000.123, 47000.5}, {0, 7777.0, 7777.0}};
  const std::vector<double> samples = {t0,      t0,      500.0,   1000.7, 3000.0,
                                       25920.0, 47000.5, 86400.0, 2.0e5};
  const std::vector<Eigen::VectorXd> xs = PropagateLinear(hcw, u, x0, t0, pulses, samples);
  ASSERT_EQ(xs.size(), samples.size());
  EXPECT_EQ(xs[0], x0);
  EXPECT_EQ(xs[1], x0);
  for (size_t k = 2; k < samples.size(); ++k) {
    const Eigen::VectorXd ref = HcwClosedForm(hcw, u, x0, t0, pulses, samples[k]);
    EXPECT_LT(ColumnRelError(ref, xs[k], hcw.state_scale()), 1e-9) << "t=" << samples[k];
  }
  // The burns matter: without them the state is different by far more than the tolerance.
  const Eigen::VectorXd free = HcwClosedForm(hcw, u, x0, t0, {}, samples.back());
  EXPECT_GT(ColumnRelError(free, xs.back(), hcw.state_scale()), 1e-3);
}

TEST(PropagateLinearTest, TighterToleranceIsMoreAccurate) {
  const HcwModel hcw(kGeoMeanMotion);
  const Eigen::MatrixXd u = 1e-4 * Eigen::MatrixXd::Identity(3, 3);
  const Eigen::VectorXd x0 = (Eigen::VectorXd(6) << 0, 0, 0, 0, 0, 0).finished();
  const std::vector<InputPulse> pulses = {{1, 0.0, 3000.0}};
  const Eigen::VectorXd ref = HcwClosedForm(hcw, u, x0, 0.0, pulses, 86400.0);
  const double loose = ColumnRelError(
      ref, PropagateLinear(hcw, u, x0, 0.0, pulses, {86400.0}, 1e-6)[0], hcw.state_scale());
  const double tight = ColumnRelError(
      ref, PropagateLinear(hcw, u, x0, 0.0, pulses, {86400.0}, 1e-12)[0], hcw.state_scale());
  EXPECT_LT(tight, 1e-10);
  EXPECT_LT(loose, 1e-4);
  EXPECT_LT(tight, loose);
}

TEST(PropagateLinearTest, EllipticFreeMotionMatchesYamanakaAnkersen) {
  const YamanakaAnkersenModel ya(12.0e6, 0.3, YamanakaAnkersenModel::kEarthMu, 1.0);
  const Eigen::MatrixXd u = Eigen::MatrixXd::Identity(3, 3);
  Eigen::VectorXd x0(6);
  x0 << 500.0, 2000.0, -300.0, 0.3, -0.4, 0.1;
  const double t0 = 1234.5, p = ya.period();
  const std::vector<double> samples = {t0 + 0.1 * p, t0 + 0.55 * p, t0 + 1.2 * p};
  const std::vector<Eigen::VectorXd> xs = PropagateLinear(ya, u, x0, t0, {}, samples);
  for (size_t k = 0; k < samples.size(); ++k) {
    EXPECT_LT(ColumnRelError(ya.TransitionMatrix(samples[k], t0) * x0, xs[k], ya.state_scale()),
              1e-9)
        << k;
  }
}

// HCW with a constant acceleration a0 in the drift d = B a0.
class DriftedHcw final : public LinearModel {
 public:
  DriftedHcw(double n, Eigen::Vector3d a0) : hcw_(n), a0_(a0) {}
  std::string_view name() const override { return "drifted_hcw"; }
  int num_states() const override { return 6; }
  int num_inputs() const override { return 3; }
  int num_outputs() const override { return 3; }
  bool is_time_invariant() const override { return true; }
  ModelMatrices Evaluate(double t) const override {
    ModelMatrices m = hcw_.Evaluate(t);
    m.d = m.b * a0_;
    return m;
  }
  OutputMatrices EvaluateOutput(double t) const override { return hcw_.EvaluateOutput(t); }
  std::vector<std::string> state_names() const override { return hcw_.state_names(); }
  std::vector<std::string> output_names() const override { return hcw_.output_names(); }
  Eigen::VectorXd state_scale() const override { return hcw_.state_scale(); }
  double time_scale() const override { return hcw_.time_scale(); }

 private:
  HcwModel hcw_;
  Eigen::Vector3d a0_;
};

TEST(PropagateLinearTest, DriftActsLikeAnAlwaysOnInput) {
  const Eigen::Vector3d a0(1e-6, -3e-6, 2e-6);
  const DriftedHcw drifted(kGeoMeanMotion, a0);
  const HcwModel hcw(kGeoMeanMotion);
  const Eigen::MatrixXd u = 5e-5 * Eigen::MatrixXd::Identity(3, 3);
  Eigen::MatrixXd u_plus(3, 4);
  u_plus << u, a0;
  const Eigen::VectorXd x0 = Eigen::VectorXd::Constant(6, 0.0);
  const std::vector<InputPulse> pulses = {{2, 100.0, 900.0}};
  const std::vector<InputPulse> pulses_plus = {{2, 100.0, 900.0}, {3, 0.0, 1e6}};
  const double t = 50000.0;
  const Eigen::VectorXd got = PropagateLinear(drifted, u, x0, 0.0, pulses, {t})[0];
  const Eigen::VectorXd ref = HcwClosedForm(hcw, u_plus, x0, 0.0, pulses_plus, t);
  EXPECT_LT(ColumnRelError(ref, got, hcw.state_scale()), 1e-9);
}

TEST(PropagateLinearTest, NoSamplesGivesNoStates) {
  const HcwModel hcw(kGeoMeanMotion);
  EXPECT_TRUE(PropagateLinear(hcw, Eigen::MatrixXd::Identity(3, 3), Eigen::VectorXd::Zero(6), 0.0,
                              {{0, 0.0, 10.0}}, {})
                  .empty());
}

TEST(PropagateLinearTest, RejectsBadInput) {
  const HcwModel hcw(kGeoMeanMotion);
  const Eigen::MatrixXd u = Eigen::MatrixXd::Identity(3, 3);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
  const std::vector<double> s = {10.0};
  EXPECT_THAT([&] { PropagateLinear(hcw, u, x0, NAN, {}, s); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t0 must be finite")));
  EXPECT_THAT(
      [&] { PropagateLinear(hcw, u, x0, 0.0, {}, s, 0.0); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("tolerance must be in (0, 1e-3], got 0")));
  EXPECT_THAT([&] { PropagateLinear(hcw, u, x0, 0.0, {}, s, 0.1); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("tolerance")));
  EXPECT_THAT([&] { PropagateLinear(hcw, Eigen::MatrixXd::Identity(2, 2), x0, 0.0, {}, s); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("input_columns has 2 rows")));
  Eigen::MatrixXd bad_u = u;
  bad_u(0, 0) = INFINITY;
  EXPECT_THAT([&] { PropagateLinear(hcw, bad_u, x0, 0.0, {}, s); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("non-finite")));
  EXPECT_THAT([&] { PropagateLinear(hcw, u, Eigen::VectorXd::Zero(5), 0.0, {}, s); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("x0 has 5 entries")));
  Eigen::VectorXd bad_x0 = x0;
  bad_x0[3] = NAN;
  EXPECT_THAT([&] { PropagateLinear(hcw, u, bad_x0, 0.0, {}, s); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("x0 is not finite")));
  EXPECT_THAT(
      [&] {
        PropagateLinear(hcw, u, x0, 0.0, {{3, 0.0, 1.0}}, s);
      },
      ThrowsMessage<std::invalid_argument>(
          HasSubstr("pulses[0].column = 3 is not an input column (0..2)")));
  EXPECT_THAT(
      [&] {
        PropagateLinear(hcw, u, x0, 0.0, {{0, 0.0, 1.0}, {-1, 0.0, 1.0}}, s);
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("pulses[1].column = -1")));
  EXPECT_THAT(
      [&] {
        PropagateLinear(hcw, u, x0, 0.0, {{0, 5.0, 4.0}}, s);
      },
      ThrowsMessage<std::invalid_argument>(
          HasSubstr("pulses[0] ends before it starts: end_s = 4 < start_s = 5")));
  EXPECT_THAT(
      [&] {
        PropagateLinear(hcw, u, x0, 0.0, {{0, NAN, 4.0}}, s);
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("non-finite times")));
  EXPECT_THAT(
      [&] {
        PropagateLinear(hcw, u, x0, 0.0, {}, {5.0, 4.0});
      },
      ThrowsMessage<std::invalid_argument>(
          HasSubstr("non-decreasing, but sample_times[1] = 4 < sample_times[0] = 5")));
  EXPECT_THAT(
      [&] { PropagateLinear(hcw, u, x0, 10.0, {}, {5.0}); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("sample_times[0] = 5 is before t0 = 10")));
  EXPECT_THAT([&] { PropagateLinear(hcw, u, x0, 0.0, {}, {INFINITY}); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("sample_times[0] is not finite")));
}

TEST(PropagateLinearTest, UnreachableToleranceThrowsRuntimeError) {
  const HcwModel hcw(kGeoMeanMotion);
  EXPECT_THAT(
      [&] {
        PropagateLinear(hcw, Eigen::MatrixXd::Identity(3, 3), Eigen::VectorXd::Ones(6), 0.0, {},
                        {100.0}, 1e-300);
      },
      ThrowsMessage<std::runtime_error>(
          HasSubstr("PropagateLinear: adaptive integration step size underflow")));
}

// A time-varying model returning NaN after t = 50 s.
class NanModel final : public LinearModel {
 public:
  std::string_view name() const override { return "nan_model"; }
  int num_states() const override { return 2; }
  int num_inputs() const override { return 1; }
  int num_outputs() const override { return 1; }
  bool is_time_invariant() const override { return false; }
  ModelMatrices Evaluate(double t) const override {
    ModelMatrices m{Eigen::MatrixXd::Zero(2, 2), Eigen::MatrixXd::Ones(2, 1),
                    Eigen::VectorXd::Zero(2)};
    if (t > 50.0) m.d[0] = std::nan("");
    return m;
  }
  OutputMatrices EvaluateOutput(double) const override { return {}; }
  std::vector<std::string> state_names() const override { return {"a", "b"}; }
  std::vector<std::string> output_names() const override { return {"a"}; }
  Eigen::VectorXd state_scale() const override { return Eigen::Vector2d(1, 1); }
  double time_scale() const override { return 1.0; }
};

TEST(PropagateLinearTest, RejectsNonFiniteModelMatrices) {
  const NanModel model;
  const Eigen::MatrixXd u = Eigen::MatrixXd::Ones(1, 1);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(2);
  EXPECT_EQ(PropagateLinear(model, u, x0, 0.0, {}, {40.0}).size(), 1u);
  EXPECT_THAT([&] { PropagateLinear(model, u, x0, 0.0, {}, {100.0}); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("PropagateLinear: model 'nan_model' returned non-finite A, B or d")));
}

}  // namespace
}  // namespace thrustsched::dynamics
