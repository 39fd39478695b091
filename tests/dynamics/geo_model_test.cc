#include "dynamics/geo_model.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dynamics/time.h"

namespace thrustsched::dynamics {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kDay = 86400.0;
const double kNan = std::numeric_limits<double>::quiet_NaN();

double Kappa(const GeoLinearModel& m, double t) {
  const double theta0 = GmstRad(Epoch::Parse(m.options().epoch).JulianDateUtc());
  return m.options().station_longitude_deg * kDeg + theta0 + geo::kEarthRotationRate * t;
}

double KeplerResidual() {
  return std::sqrt(geo::kEarthMu / std::pow(geo::kStationRadius, 3)) - geo::kEarthRotationRate;
}

TEST(GeoModelOptionsTest, DefaultsAreValid) {
  std::string error;
  EXPECT_TRUE(GeoModelOptions{}.IsValid(&error)) << error;
  EXPECT_TRUE(GeoModelOptions{}.IsValid(nullptr));
}

TEST(GeoModelOptionsTest, InvalidFieldsAreNamed) {
  struct Case {
    void (*mutate)(GeoModelOptions&);
    const char* field;
  };
  const Case cases[] = {
      {[](GeoModelOptions& o) { o.gravity_degree = 5; }, "gravity_degree must be in 2..4, got 5"},
      {[](GeoModelOptions& o) { o.gravity_degree = 1; }, "gravity_degree must be in 2..4, got 1"},
      {[](GeoModelOptions& o) { o.area_to_mass_m2_kg = -0.1; },
       "area_to_mass_m2_kg must be finite and >= 0, got -0.1"},
      {[](GeoModelOptions& o) { o.area_to_mass_m2_kg = kNan; }, "area_to_mass_m2_kg"},
      {[](GeoModelOptions& o) { o.reflectivity_cr = 2.5; },
       "reflectivity_cr must be finite and in [0, 2], got 2.5"},
      {[](GeoModelOptions& o) { o.station_longitude_deg = kNan; }, "station_longitude_deg"},
      {[](GeoModelOptions& o) { o.station_longitude_deg = 400.0; }, "station_longitude_deg"},
      {[](GeoModelOptions& o) { o.epoch = "2034-13-01"; }, "epoch '2034-13-01' is invalid"},
      {[](GeoModelOptions& o) { o.epoch = "yesterday"; }, "epoch 'yesterday'"},
  };
  for (const Case& c : cases) {
    GeoModelOptions o;
    c.mutate(o);
    std::string error;
    EXPECT_FALSE(o.IsValid(&error));
    EXPECT_THAT(error, HasSubstr(c.field));
    EXPECT_THAT([&] { GeoLinearModel m(o); },
                ThrowsMessage<std::invalid_argument>(HasSubstr(c.field)));
  }
}

TEST(GeoModelOptionsTest, SetByName) {
  GeoModelOptions o;
  o.Set("gravity_degree", "3");
  o.Set("moon", "false");
  o.Set("area_to_mass_m2_kg", "0.015");
  o.Set("epoch", "2030-06-01T00:00:00Z");
  o.Set("station_longitude_deg", "-30.5");
  EXPECT_EQ(o.gravity_degree, 3);
  EXPECT_FALSE(o.moon);
  EXPECT_DOUBLE_EQ(o.area_to_mass_m2_kg, 0.015);
  EXPECT_EQ(o.epoch, "2030-06-01T00:00:00Z");
  EXPECT_DOUBLE_EQ(o.station_longitude_deg, -30.5);
  EXPECT_TRUE(o.IsValid(nullptr));
  EXPECT_EQ(GeoModelOptions::FieldNames().size(), 10u);
  for (const std::string& f : GeoModelOptions::FieldNames())
    EXPECT_NO_THROW(GeoModelOptions{}.Set(f, "1")) << f;
  EXPECT_THAT([&] { o.Set("drag", "true"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("unknown field 'drag'")));
  EXPECT_THAT([&] { o.Set("gravity_degree", "four"); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("'gravity_degree' expects an integer, got 'four'")));
  EXPECT_THAT([&] { o.Set("sun", "maybe"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("'sun' expects a boolean")));
  EXPECT_THAT(
      [&] { o.Set("reflectivity_cr", "1.2x"); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("'reflectivity_cr' expects a number")));
}

TEST(GeoLinearModelTest, Metadata) {
  const GeoLinearModel m{GeoModelOptions{}};
  EXPECT_EQ(m.name(), "geo");
  EXPECT_EQ(m.num_states(), 6);
  EXPECT_EQ(m.num_inputs(), 3);
  EXPECT_EQ(m.num_outputs(), 3);
  EXPECT_FALSE(m.is_time_invariant());
  EXPECT_EQ(m.state_names(), (std::vector<std::string>{"da_m", "ex", "ey", "ix", "iy", "dl_rad"}));
  EXPECT_EQ(m.output_names(), (std::vector<std::string>{"dr_m", "lat_rad", "lon_rad"}));
  const double delta = 0.05 * kDeg;
  EXPECT_NEAR(m.state_scale()(0), delta * 42165765.0, 1e-6);  // 36.8 km (Gazzino 2018, sec. 4.3.3)
  EXPECT_NEAR(m.state_scale()(0), 36796.6, 0.1);
  for (int i = 1; i < 6; ++i) EXPECT_DOUBLE_EQ(m.state_scale()(i), delta);
  EXPECT_DOUBLE_EQ(m.time_scale(), 1.0 / 7.2921158553e-5);
  EXPECT_DOUBLE_EQ(m.mean_motion(), 7.2921158553e-5);
  EXPECT_DOUBLE_EQ(m.station_radius_m(), 42165765.0);
  EXPECT_NEAR(m.EarthRotationAngle(0.0) / kDeg, 100.7225, 5e-5);
}

TEST(GeoLinearModelTest, InputMatrixIsTheCorrectedThesisB) {
  // Gazzino 2018 eq. (B.59), corrected: the printed B12 = a_mp / v_mp is 2 a_mp / v_mp.
  const GeoLinearModel m{GeoModelOptions{}};
  const double a = geo::kStationRadius, v = std::sqrt(geo::kEarthMu / a);
  for (double t : {0.0, 3000.0, 40000.0, 6.0 * kDay}) {
    const double k = Kappa(m, t), s = std::sin(k), c = std::cos(k);
    Eigen::MatrixXd b(6, 3);
    b << 0, 2 * a, 0, s, 2 * c, 0, -c, 2 * s, 0, 0, 0, c / 2, 0, 0, s / 2, -2, 0, 0;
    b /= v;
    const Eigen::MatrixXd got = m.Evaluate(t).b;
    EXPECT_LT((got - b).cwiseAbs().maxCoeff(), 1e-9 * b.cwiseAbs().maxCoeff()) << t;
    EXPECT_LT((m.InputMatrix(Eigen::VectorXd::Zero(6), t) - b).cwiseAbs().maxCoeff(),
              1e-9 * b.cwiseAbs().maxCoeff());
  }
}

TEST(GeoLinearModelTest, J2OnlyMatchesTheClosedForm) {
  // Closed-form J2 part of A(t) and d(t) at x_mp (derived here; the thesis prints
  // no A(t)), plus the Kepler part A(6,1) = -3 n / (2 a) (Gazzino 2018, (B.64f))
  // and the Kepler residual in d6.
  GeoModelOptions o;
  o.tesseral = o.sun = o.moon = o.srp = false;
  o.gravity_degree = 2;
  const GeoLinearModel m(o);
  const double a = geo::kStationRadius, n = std::sqrt(geo::kEarthMu / (a * a * a));
  const double j2 = 1.0826261738522227e-3;  // -sqrt(5) C20 (EGM2008)
  const double k = j2 * std::pow(geo::kEarthRadius / a, 2) * n;
  EXPECT_NEAR(k, 1.80624e-9, 1e-13);
  for (double t : {0.0, 7000.0, 30000.0, 2.5 * kDay}) {
    const double kp = Kappa(m, t), s = std::sin(kp), c = std::cos(kp);
    Eigen::MatrixXd ref(6, 6);
    ref << 0, -3 * a * s, 3 * a * c, 0, 0, 0,                                      //
        21 * s / (4 * a), -4.5 * std::sin(2 * kp), 3 - 9 * s * s, 0, 0, -1.5 * c,  //
        -21 * c / (4 * a), 6 - 9 * s * s, 4.5 * std::sin(2 * kp), 0, 0, -1.5 * s,  //
        0, 0, 0, -1.5 * std::sin(2 * kp), 3 * c * c, 0,                            //
        0, 0, 0, -3 * s * s, 1.5 * std::sin(2 * kp), 0,                            //
        -21 / (2 * a), 39.0 / 4 * c, 39.0 / 4 * s, 0, 0, 0;
    ref *= k;
    ref(5, 0) += -1.5 * n / a;
    Eigen::VectorXd dref(6);
    dref << 0, -1.5 * s, 1.5 * c, 0, 0, 3;
    dref *= k;
    dref(5) += KeplerResidual();
    const ModelMatrices mm = m.Evaluate(t);
    // Compare nondimensionally: S^-1 A S and S^-1 d (S = state_scale).
    const Eigen::MatrixXd s_mat = m.state_scale().asDiagonal();
    const Eigen::MatrixXd s_inv = m.state_scale().cwiseInverse().asDiagonal();
    const Eigen::MatrixXd a_ref = s_inv * ref * s_mat;
    EXPECT_LT((s_inv * mm.a * s_mat - a_ref).cwiseAbs().maxCoeff(),
              1e-7 * a_ref.cwiseAbs().maxCoeff())
        << t;
    EXPECT_LT((s_inv * (mm.d - dref)).cwiseAbs().maxCoeff(),
              1e-7 * (s_inv * dref).cwiseAbs().maxCoeff())
        << t;
  }
}

TEST(GeoLinearModelTest, JacobianMatchesFiniteDifferencesOfTheNonlinearRate) {
  const GeoLinearModel m{GeoModelOptions{}};
  const double steps[6] = {1.0, 1e-8, 1e-8, 1e-8, 1e-8, 1e-8};
  for (double t : {0.0, 11111.0, 3.3 * kDay}) {
    const ModelMatrices mm = m.Evaluate(t);
    const Eigen::VectorXd f0 = m.NaturalRate(Eigen::VectorXd::Zero(6), t);
    EXPECT_LT((f0 - mm.d).cwiseAbs().maxCoeff(), 1e-15 * (1.0 + mm.d.cwiseAbs().maxCoeff()));
    Eigen::MatrixXd fd(6, 6);
    for (int j = 0; j < 6; ++j) {
      Eigen::VectorXd xp = Eigen::VectorXd::Zero(6), xm = xp;
      xp(j) = steps[j];
      xm(j) = -steps[j];
      fd.col(j) = (m.NaturalRate(xp, t) - m.NaturalRate(xm, t)) / (2 * steps[j]);
    }
    // Nondimensional comparison S^-1 A S, row by row (rows differ by orders of magnitude).
    const Eigen::MatrixXd s_mat = m.state_scale().asDiagonal();
    const Eigen::MatrixXd s_inv = m.state_scale().cwiseInverse().asDiagonal();
    const Eigen::MatrixXd got = s_inv * mm.a * s_mat, ref = s_inv * fd * s_mat;
    for (int i = 0; i < 6; ++i) {
      EXPECT_LT((got.row(i) - ref.row(i)).cwiseAbs().maxCoeff(),
                1e-5 * ref.row(i).cwiseAbs().maxCoeff())
          << "row " << i << " t=" << t << "\n"
          << got << "\n"
          << ref;
    }
  }
}

TEST(GeoLinearModelTest, DriftMatchesTheExtractorReferenceNumbers) {
  // Derived here (an independent computation, not published), geopotential 4x4
  // only, 118 E: D1 = 1.7950e-6 km/s, D6 = 1.2821e-9 rad/s, both constant (the
  // station point is Earth-fixed).
  GeoModelOptions geo_only;
  geo_only.sun = geo_only.moon = geo_only.srp = false;
  const GeoLinearModel m(geo_only);
  for (double t : {0.0, 20000.0, 50000.0}) {
    const Eigen::VectorXd d = m.Evaluate(t).d;
    EXPECT_NEAR(d(0), 1.7950e-3, 0.0001e-3);
    EXPECT_NEAR(d(5), 1.2821e-9, 0.0001e-9);
  }
  // Derived here (not published): over 2034 the luni-solar terms bring the mean
  // dl/dt to about -1.4e-5 rad/day (explains a_mp = 42165.765 km of Gazzino 2018
  // (B.31), not Kepler-synchronous), and the mean
  // inclination-vector drift is (-1.4e-5, 1.045e-3) deg/day (thesis (ix, iy) units).
  const GeoLinearModel full{GeoModelOptions{}};
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(6);
  int n = 0;
  for (double t = 0.0; t < 365.25 * kDay; t += 1800.0, ++n) mean += full.Evaluate(t).d;
  mean /= n;
  EXPECT_NEAR(mean(5) * kDay, -1.4e-5, 0.2e-5);
  EXPECT_NEAR(mean(4) * kDay / kDeg, 1.045e-3, 0.01e-3);
  EXPECT_NEAR(mean(3) * kDay / kDeg, -1.4e-5, 0.3e-5);
}

TEST(GeoLinearModelTest, OutputMatricesAndTheirRate) {
  const GeoLinearModel m{GeoModelOptions{}};
  const double t = 5432.0, h = 1.0;
  const OutputMatrices o = m.EvaluateOutput(t);
  const double k = Kappa(m, t), a = geo::kStationRadius;
  Eigen::MatrixXd c(3, 6);
  c << 1, -a * std::cos(k), -a * std::sin(k), 0, 0, 0,  //
      0, 0, 0, 2 * std::sin(k), -2 * std::cos(k), 0,    //
      0, 2 * std::sin(k), -2 * std::cos(k), 0, 0, 1;
  EXPECT_LT((o.c - c).cwiseAbs().maxCoeff(), 1e-9 * a);
  const Eigen::MatrixXd fd = (m.EvaluateOutput(t + h).c - m.EvaluateOutput(t - h).c) / (2 * h);
  EXPECT_LT((o.c_dot - fd).cwiseAbs().maxCoeff(), 1e-7 * o.c_dot.cwiseAbs().maxCoeff());
}

TEST(GeoLinearModelTest, ConstMethodsAreThreadSafe) {
  const GeoLinearModel m{GeoModelOptions{}};
  std::vector<ModelMatrices> serial(8), parallel(8);
  for (int i = 0; i < 8; ++i) serial[i] = m.Evaluate(1000.0 * i);
  std::vector<std::thread> threads;
  for (int i = 0; i < 8; ++i)
    threads.emplace_back([&, i] { parallel[i] = m.Evaluate(1000.0 * i); });
  for (std::thread& th : threads) th.join();
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(serial[i].a, parallel[i].a);
    EXPECT_EQ(serial[i].d, parallel[i].d);
  }
}

TEST(GeoLinearModelTest, BadArgumentsThrow) {
  const GeoLinearModel m{GeoModelOptions{}};
  EXPECT_THAT([&] { m.Evaluate(kNan); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
  EXPECT_THAT([&] { m.EvaluateOutput(std::numeric_limits<double>::infinity()); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
  EXPECT_THAT([&] { m.EarthRotationAngle(kNan); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
  EXPECT_THAT([&] { m.NaturalRate(Eigen::VectorXd::Zero(5), 0.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("6 components, got 5")));
  Eigen::VectorXd x = Eigen::VectorXd::Zero(6);
  x(2) = kNan;
  EXPECT_THAT([&] { m.NaturalRate(x, 0.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("finite")));
  x(2) = 1.5;
  EXPECT_THAT([&] { m.InputMatrix(x, 0.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("eccentricity")));
  x(2) = 0.0;
  x(0) = -5e7;
  EXPECT_THAT([&] { m.NaturalRate(x, 0.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("da_m")));
  EXPECT_THAT([&] { m.NaturalRate(Eigen::VectorXd::Zero(6), kNan); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
}

}  // namespace
}  // namespace thrustsched::dynamics
