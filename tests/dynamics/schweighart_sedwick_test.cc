// Tests for dynamics/schweighart_sedwick.h against independent references:
// the nonlinear two-body + J2 motion of a chief and a deputy (integrated here
// with Boost.Odeint, the J2 acceleration written out by hand), HCW's matrices,
// the closed-form drift of the linear model, and the adaptive integration of
// the continuous model (dynamics/propagation.h) for the exact ZOH map.
// `ctest --test-dir build -R SchweighartSedwickTest -V` prints the SS and HCW errors.
#include "dynamics/schweighart_sedwick.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

// The controlled stepper copies an error stepper whose buffers GCC flags
// inside the Boost header (as in dynamics/geo_simulator.cc).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "common/constants.h"
#include "dynamics/discretisation.h"
#include "dynamics/models.h"
#include "dynamics/propagation.h"

namespace thrustsched::dynamics {
namespace {

using common::kDegToRad;
using common::kPi;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat3 = Eigen::Matrix3d;

constexpr double kMu = common::kEarthMu_m3_s2, kRe = common::kEarthRadius_m, kJ2 = kSsEarthJ2;
constexpr double kLeoRadius_m = kRe + 650e3;

// ---------------------------------------------------------------- nonlinear reference

// Two-body + J2 acceleration in an Earth-centred inertial frame whose z axis is
// the Earth's pole (m/s^2).
Eigen::Vector3d GravityJ2(const Eigen::Vector3d& r) {
  const double r2 = r.squaredNorm(), rn = std::sqrt(r2);
  const double zz = r.z() * r.z() / r2;
  const double k = -1.5 * kJ2 * kMu * kRe * kRe / (r2 * r2 * rn);
  Eigen::Vector3d a = -kMu / (r2 * rn) * r;
  a.x() += k * r.x() * (1.0 - 5.0 * zz);
  a.y() += k * r.y() * (1.0 - 5.0 * zz);
  a.z() += k * r.z() * (3.0 - 5.0 * zz);
  return a;
}

// Chief and deputy inertial states [r_c, v_c, r_d, v_d] (m, m/s).
using Pair = std::array<double, 12>;

void PairDerivative(const Pair& y, Pair& dy, double /*t*/) {
  for (int sat = 0; sat < 2; ++sat) {
    const int o = 6 * sat;
    const Eigen::Vector3d a = GravityJ2(Eigen::Vector3d(y[o], y[o + 1], y[o + 2]));
    for (int k = 0; k < 3; ++k) {
      dy[o + k] = y[o + 3 + k];
      dy[o + 3 + k] = a[k];
    }
  }
}

namespace odeint = boost::numeric::odeint;
using Stepper = odeint::runge_kutta_fehlberg78<Pair, double, Pair, double, odeint::array_algebra>;
using Checker =
    odeint::default_error_checker<double, odeint::array_algebra, odeint::default_operations>;
using Controlled = odeint::controlled_runge_kutta<Stepper, Checker>;

// Columns: radial, along-track, orbit normal of the chief (r, v), in inertial axes.
Mat3 LvlhAxes(const Eigen::Vector3d& r, const Eigen::Vector3d& v) {
  const Eigen::Vector3d ex = r.normalized(), ez = r.cross(v).normalized();
  Mat3 axes;
  axes << ex, ez.cross(ex), ez;
  return axes;
}

// Rotation rate (LVLH components) that relative velocities are taken in:
// h / r^2 about the orbit normal. The chief's osculating LVLH frame also rolls
// about the radius vector at r a_N / h (a_N: the J2 acceleration normal to the
// plane, an O(J2) oscillation at the orbital frequency), but the model's frame
// follows a reference orbit whose plane does not roll, so the velocity is
// taken without that term (positions are exact either way). Counting the roll
// biases y'(0) by -r a_N z / h: measured at u0 = 45 deg with 300 m
// cross-track, the SS error after 15 orbits grows from 0.59 to 16.2 m (98 deg)
// and 4.2 to 52.6 m (45 deg), HCW's stays ~15-40 m.
Eigen::Vector3d FrameRate(const Eigen::Vector3d& r, const Eigen::Vector3d& v) {
  return Eigen::Vector3d(0.0, 0.0, r.cross(v).norm() / r.squaredNorm());
}

// Deputy relative state in the chief's LVLH axes, velocity relative to FrameRate.
Vec6 RelativeLvlh(const Pair& y) {
  const Eigen::Vector3d rc(y[0], y[1], y[2]), vc(y[3], y[4], y[5]);
  const Eigen::Vector3d rd(y[6], y[7], y[8]), vd(y[9], y[10], y[11]);
  const Mat3 axes = LvlhAxes(rc, vc);
  const Eigen::Vector3d rho = axes.transpose() * (rd - rc);
  Vec6 x;
  x << rho, axes.transpose() * (vd - vc) - FrameRate(rc, vc).cross(rho);
  return x;
}

// The chief alone over one orbit from (r, v): the first-harmonic (cos u) part
// of its radius (m), u the angle from the start position, by least squares on
// [1, cos u, sin u, cos 2u, sin 2u] (J2 adds the 2u terms to a circular orbit).
double FirstHarmonicOfRadius(const Eigen::Vector3d& r, const Eigen::Vector3d& v, double period_s) {
  Pair y = {r.x(), r.y(), r.z(), v.x(), v.y(), v.z(), r.x(), r.y(), r.z(), v.x(), v.y(), v.z()};
  const Eigen::Vector3d node = r.normalized(), perp = r.cross(v).cross(r).normalized();
  constexpr int kSamples = 64;
  Eigen::MatrixXd basis(kSamples, 5);
  Eigen::VectorXd radius(kSamples);
  std::vector<double> times;
  for (int k = 0; k < kSamples; ++k) times.push_back(period_s * k / kSamples);
  Controlled stepper(Checker(1e-12, 1e-12));
  double t = 0.0;
  for (int k = 0; k < kSamples; ++k) {
    if (times[k] > t) odeint::integrate_adaptive(stepper, PairDerivative, y, t, times[k], 10.0);
    t = times[k];
    const Eigen::Vector3d rk(y[0], y[1], y[2]);
    const double u = std::atan2(rk.dot(perp), rk.dot(node));
    basis.row(k) << 1.0, std::cos(u), std::sin(u), std::cos(2 * u), std::sin(2 * u);
    radius[k] = rk.norm();
  }
  return basis.colPivHouseholderQr().solve(radius)[1];
}

// Chief at argument of latitude u0 (RAAN 0), radial velocity 0, at
// r_ref + X cos 2u0 with X = J2 R^2 sin^2 i / (4 r) (the 2u radius oscillation
// of a circular orbit under J2, Schweighart & Sedwick 2002's bounded response
// of a satellite to the reference's J2 forcing, so the mean radius is about
// r_ref), its speed tuned by the secant method until the radius has no first
// harmonic: a mean-circular chief from the nonlinear dynamics alone. (A chief
// started at n c r, the circular speed of the averaged gravity, is eccentric
// at O(J2), and the relative drift then depends on that eccentricity, which
// no circular-reference model represents: 2.5x larger errors for both.)
void MeanCircularChief(const SchweighartSedwickModel& m, double u0_rad, Eigen::Vector3d* r,
                       Eigen::Vector3d* v) {
  const double r_ref = m.reference_radius(), i = m.inclination(), n = m.mean_motion();
  const double amplitude_m = kJ2 * kRe * kRe / r_ref * std::sin(i) * std::sin(i) / 4.0;
  const Eigen::Vector3d node(1.0, 0.0, 0.0), perp(0.0, std::cos(i), std::sin(i));
  *r = (r_ref + amplitude_m * std::cos(2.0 * u0_rad)) *
       (std::cos(u0_rad) * node + std::sin(u0_rad) * perp);
  const Eigen::Vector3d along = -std::sin(u0_rad) * node + std::cos(u0_rad) * perp;
  const double period_s = 2.0 * kPi / n;
  double s0 = n * m.c() * r->norm(), s1 = s0 + 0.1;
  double f0 = FirstHarmonicOfRadius(*r, s0 * along, period_s);
  for (int it = 0; it < 8; ++it) {
    const double f1 = FirstHarmonicOfRadius(*r, s1 * along, period_s);
    if (std::abs(f1) < 1e-4 || f1 == f0) break;
    const double s2 = s1 - f1 * (s1 - s0) / (f1 - f0);
    s0 = s1;
    f0 = f1;
    s1 = s2;
  }
  *v = s1 * along;
}

// A bounded-like formation about the mean-circular chief at argument of
// latitude u0: in plane, a radial_m (2 radial_m along-track) ellipse with the
// drift-free y'(0); out of plane, the deputy's orbit turned about the Earth's
// pole by the node offset that gives a cross_track_m amplitude (equal
// inclinations: no differential nodal precession, which the time-invariant
// model leaves out).
struct Formation {
  double inclination_deg = 98.0;
  double u0_deg = 45.0;
  double radial_m = 250.0;
  double cross_track_m = 300.0;
};

Pair FormationPair(const SchweighartSedwickModel& m, const Formation& f) {
  Eigen::Vector3d rc, vc;
  MeanCircularChief(m, f.u0_deg * kDegToRad, &rc, &vc);
  Vec6 x0;
  x0 << f.radial_m, 0.0, 0.0, 0.0, m.DriftFreeAlongTrackVelocity(f.radial_m), 0.0;
  const Mat3 axes = LvlhAxes(rc, vc);
  const Eigen::Vector3d rho = x0.head<3>();
  const double node_offset_rad = f.cross_track_m / (rc.norm() * std::sin(m.inclination()));
  const Mat3 turn = Eigen::AngleAxisd(node_offset_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d rd = turn * (rc + axes * rho);
  const Eigen::Vector3d vd = turn * (vc + axes * (x0.tail<3>() + FrameRate(rc, vc).cross(rho)));
  return {rc.x(), rc.y(), rc.z(), vc.x(), vc.y(), vc.z(),
          rd.x(), rd.y(), rd.z(), vd.x(), vd.y(), vd.z()};
}

// Relative LVLH states of the nonlinear pair at the sample times (s).
std::vector<Vec6> NonlinearRelative(Pair y, const std::vector<double>& times) {
  Controlled stepper(Checker(1e-13, 1e-13));
  std::vector<Vec6> out;
  double t = 0.0;
  for (double t_next : times) {
    if (t_next > t) odeint::integrate_adaptive(stepper, PairDerivative, y, t, t_next, 10.0);
    t = t_next;
    out.push_back(RelativeLvlh(y));
  }
  return out;
}

std::vector<Vec6> LinearRelative(const LinearModel& model, const Vec6& x0,
                                 const std::vector<double>& times) {
  const std::vector<Eigen::VectorXd> xs =
      PropagateLinear(model, Eigen::MatrixXd::Identity(3, 3), x0, 0.0, {}, times);
  std::vector<Vec6> out(xs.begin(), xs.end());
  return out;
}

// Position errors (m) of SS (both cross-track forms) and HCW against the
// nonlinear pair after each orbit count, all started from the pair's relative
// state; in-plane and cross-track parts separately.
struct ModelErrors {
  std::vector<double> ss_m, ss_simple_m, hcw_m;        // |r_model - r_truth|
  std::vector<double> ss_z_m, ss_simple_z_m, hcw_z_m;  // |z_model - z_truth|
  double separation_m = 0.0;                           // largest |r_truth| at the samples
};

ModelErrors MeasureErrors(const Formation& f, const std::vector<int>& orbits) {
  const double i_rad = f.inclination_deg * kDegToRad;
  const SchweighartSedwickModel ss(kLeoRadius_m, i_rad);
  const SchweighartSedwickModel simple(kLeoRadius_m, i_rad, 1000.0, CrossTrack::kSimple);
  const HcwModel hcw(ss.mean_motion());
  const Pair pair = FormationPair(ss, f);
  const Vec6 x0 = RelativeLvlh(pair);
  std::vector<double> times;
  for (int k : orbits) times.push_back(k * 2.0 * kPi / ss.mean_motion());
  const std::vector<Vec6> truth = NonlinearRelative(pair, times);
  const std::vector<Vec6> x_ss = LinearRelative(ss, x0, times);
  const std::vector<Vec6> x_simple = LinearRelative(simple, x0, times);
  const std::vector<Vec6> x_hcw = LinearRelative(hcw, x0, times);
  ModelErrors e;
  for (size_t k = 0; k < times.size(); ++k) {
    e.ss_m.push_back((x_ss[k] - truth[k]).head<3>().norm());
    e.ss_simple_m.push_back((x_simple[k] - truth[k]).head<3>().norm());
    e.hcw_m.push_back((x_hcw[k] - truth[k]).head<3>().norm());
    e.ss_z_m.push_back(std::abs(x_ss[k][2] - truth[k][2]));
    e.ss_simple_z_m.push_back(std::abs(x_simple[k][2] - truth[k][2]));
    e.hcw_z_m.push_back(std::abs(x_hcw[k][2] - truth[k][2]));
    e.separation_m = std::max(e.separation_m, truth[k].head<3>().norm());
    std::printf(
        "i = %4.1f deg, u0 = %4.1f deg, x %3.0f m, z %3.0f m, %2d orbits: |dr| SS %7.3f m, "
        "SS simple %7.3f m, HCW %7.3f m; |dz| SS %6.3f m, simple %6.3f m, HCW %6.3f m\n",
        f.inclination_deg, f.u0_deg, f.radial_m, f.cross_track_m, orbits[k], e.ss_m[k],
        e.ss_simple_m[k], e.hcw_m[k], e.ss_z_m[k], e.ss_simple_z_m[k], e.hcw_z_m[k]);
  }
  return e;
}

// ---------------------------------------------------------------- closed forms

TEST(SchweighartSedwickTest, WithoutJ2IsHcw) {
  const SchweighartSedwickModel ss(kLeoRadius_m, 98.0 * kDegToRad, 1000.0,
                                   CrossTrack::kEqualInclination, kMu, /*j2=*/0.0);
  const HcwModel hcw(std::sqrt(kMu / std::pow(kLeoRadius_m, 3)));
  EXPECT_EQ(ss.s(), 0.0);
  EXPECT_NEAR(ss.mean_motion(), hcw.mean_motion(), 1e-18);
  EXPECT_LT((ss.Evaluate(0.0).a - hcw.Evaluate(0.0).a).cwiseAbs().maxCoeff(), 1e-20);
  EXPECT_EQ(ss.Evaluate(0.0).b, hcw.Evaluate(0.0).b);
  EXPECT_EQ(ss.state_scale(), hcw.state_scale());
}

TEST(SchweighartSedwickTest, SFollowsTheInclination) {
  // s = 3 J2 (R/r)^2 / 8 (1 + 3 cos 2i): 650 km, 98 deg: 3.3431e-4 * (1 + 3 cos 196 deg).
  const double k = 3.0 * kJ2 * std::pow(kRe / kLeoRadius_m, 2) / 8.0;
  const SchweighartSedwickModel sso(kLeoRadius_m, 98.0 * kDegToRad);
  EXPECT_NEAR(sso.s(), -6.2987e-4, 1e-8);
  EXPECT_NEAR(sso.s(), k * (1.0 + 3.0 * std::cos(196.0 * kDegToRad)), 1e-15);
  EXPECT_NEAR(sso.c(), std::sqrt(1.0 + sso.s()), 1e-15);
  // Equatorial: 4 k; at the inclination where cos 2i = -1/3 (54.7 deg): 0.
  EXPECT_NEAR(SchweighartSedwickModel(kLeoRadius_m, 0.0).s(), 4.0 * k, 1e-15);
  const double critical = 0.5 * std::acos(-1.0 / 3.0);
  EXPECT_NEAR(SchweighartSedwickModel(kLeoRadius_m, critical).s(), 0.0, 1e-15);
  const ModelMatrices m = sso.Evaluate(0.0);
  const double n = sso.mean_motion(), c2 = 1.0 + sso.s();
  EXPECT_DOUBLE_EQ(m.a(3, 0), (5.0 * c2 - 2.0) * n * n);
  EXPECT_DOUBLE_EQ(m.a(3, 4), 2.0 * n * sso.c());
  EXPECT_DOUBLE_EQ(m.a(4, 3), -2.0 * n * sso.c());
  // Cross-track: n c - Omega' cos i (equal inclinations), or n^2 (3 c^2 - 2).
  const double nodal_rate =
      -1.5 * n * kJ2 * std::pow(kRe / kLeoRadius_m, 2) * std::cos(sso.inclination());
  EXPECT_DOUBLE_EQ(-m.a(5, 2), std::pow(n * sso.c() - nodal_rate * std::cos(sso.inclination()), 2));
  const SchweighartSedwickModel simple(kLeoRadius_m, sso.inclination(), 1000.0,
                                       CrossTrack::kSimple);
  EXPECT_DOUBLE_EQ(simple.Evaluate(0.0).a(5, 2), -(3.0 * c2 - 2.0) * n * n);
  EXPECT_EQ(simple.Evaluate(0.0).a.topRows<5>(), m.a.topRows<5>());
}

// y(t) of the linear model from x(0) = x0, y(0) = x'(0) = 0, y'(0) = vy0
// (header derivation): x = xm + (x0 - xm) cos wt, y = vm t - 2 n c (x0 - xm)
// sin(wt) / w, with w = n sqrt(1 - s), xm = 2 n c (vy0 + 2 n c x0) / w^2 and
// the mean along-track rate vm = vy0 - 2 n c (xm - x0).
double AlongTrackClosedForm(const SchweighartSedwickModel& m, double x0, double vy0, double t) {
  const double n = m.mean_motion(), c = m.c(), w = n * std::sqrt(1.0 - m.s());
  const double xm = 2.0 * n * c * (vy0 + 2.0 * n * c * x0) / (w * w);
  const double vm = vy0 - 2.0 * n * c * (xm - x0);
  return vm * t - 2.0 * n * c * (x0 - xm) * std::sin(w * t) / w;
}

TEST(SchweighartSedwickTest, DriftFreeConditionCancelsTheDrift) {
  const SchweighartSedwickModel ss(kLeoRadius_m, 98.0 * kDegToRad);
  const double x0 = 250.0, orbit_s = 2.0 * kPi / ss.mean_motion();
  const std::vector<double> times = {0.37 * orbit_s, 5.0 * orbit_s, 15.0 * orbit_s};
  for (double vy0 : {ss.DriftFreeAlongTrackVelocity(x0), -2.0 * ss.mean_motion() * x0}) {
    Vec6 s0;
    s0 << x0, 0.0, 0.0, 0.0, vy0, 0.0;
    const std::vector<Vec6> xs = LinearRelative(ss, s0, times);
    for (size_t k = 0; k < times.size(); ++k) {
      EXPECT_NEAR(xs[k][1], AlongTrackClosedForm(ss, x0, vy0, times[k]), 1e-6);
    }
  }
  // With -2 n c x0 y stays in its +-2 c x0 / sqrt(1 - s) oscillation; with
  // HCW's -2 n x0 it drifts -3 n s x0 t (+44.5 m after 15 orbits at 98 deg).
  const double drift_free =
      AlongTrackClosedForm(ss, x0, ss.DriftFreeAlongTrackVelocity(x0), 15.0 * orbit_s);
  EXPECT_LT(std::abs(drift_free), 2.0 * x0 * ss.c() / std::sqrt(1.0 - ss.s()));
  Vec6 hcw0;
  hcw0 << x0, 0.0, 0.0, 0.0, -2.0 * ss.mean_motion() * x0, 0.0;
  const double y15 = LinearRelative(ss, hcw0, {15.0 * orbit_s})[0][1];
  EXPECT_NEAR(y15 - drift_free, -3.0 * ss.s() * x0 * 30.0 * kPi, 0.01 * std::abs(y15 - drift_free));
}

TEST(SchweighartSedwickTest, ExactZohMatchesIntegration) {
  const SchweighartSedwickModel ss(kLeoRadius_m, 45.0 * kDegToRad);
  Eigen::MatrixXd u(3, 2);  // two thrusters, 1e-4 m/s^2 along -T and +R/+N
  u << 0.0, 7e-5, -1e-4, 0.0, 0.0, 7e-5;
  const double step = 120.0;
  const DiscreteModel dm = Discretize(ss, u, UniformGrid(0.0, 2.0 * step, 2), {});
  Vec6 x0;
  x0 << 250.0, -400.0, 100.0, 0.1, -0.5, 0.05;
  const Eigen::Vector2d on(1.0, 0.0), off(0.0, 1.0);
  const Eigen::VectorXd x1 = dm.phi[0] * x0 + dm.gamma[0] * on + dm.drift[0];
  const Eigen::VectorXd x2 = dm.phi[1] * x1 + dm.gamma[1] * off + dm.drift[1];
  const std::vector<Eigen::VectorXd> ref = PropagateLinear(
      ss, u, x0, 0.0, {{0, 0.0, step}, {1, step, 2.0 * step}}, {step, 2 * step}, 1e-13);
  const Eigen::VectorXd scale = ss.state_scale();
  EXPECT_LT((x1 - ref[0]).cwiseQuotient(scale).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((x2 - ref[1]).cwiseQuotient(scale).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_GT((x2 - x0).head<3>().norm(), 10.0);  // the input moved the state
}

TEST(SchweighartSedwickTest, RejectsBadParameters) {
  EXPECT_THAT([] { SchweighartSedwickModel(-1.0, 0.5); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("reference_radius_m")));
  EXPECT_THAT(
      [] { SchweighartSedwickModel(7e6, 3.5); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("inclination_rad must be in [0, pi]")));
  EXPECT_THAT([] { SchweighartSedwickModel(7e6, 0.5, 1000.0, CrossTrack::kSimple, kMu, -1e-3); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("j2")));
  EXPECT_THAT([] { SchweighartSedwickModel(7e6, 0.5).Evaluate(NAN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("t must be finite")));
}

// ---------------------------------------------------------------- nonlinear J2
// Figures printed by `ctest -R SchweighartSedwickTest -V` (position error norms
// after 1 / 5 / 15 orbits, 650 km; chief mean-circular at u0).

// 250 m radial ellipse, u0 = 45 deg (where the osculating shift of the
// drift-free y'(0) vanishes, see OsculatingPhaseLimitation). Measured:
//   98 deg: SS 0.086 / 0.430 / 1.290 m, HCW 2.066 / 10.330 / 30.993 m (24x)
//   45 deg: SS 0.084 / 0.423 / 1.268 m, HCW 0.966 /  4.828 / 14.483 m (11x)
TEST(SchweighartSedwickTest, InPlaneAgainstNonlinearJ2) {
  for (double inclination_deg : {98.0, 45.0}) {
    SCOPED_TRACE(inclination_deg);
    const ModelErrors e = MeasureErrors({inclination_deg, 45.0, 250.0, 0.0}, {1, 5, 15});
    EXPECT_LT(8.0 * e.ss_m[2], e.hcw_m[2]);
    EXPECT_LT(e.ss_m[2], 2.0);  // 0.4 % of the 560 m separation
    EXPECT_LT(e.ss_m[0], e.ss_m[1]);
    EXPECT_LT(e.ss_m[1], e.ss_m[2]);
  }
}

// 300 m cross-track from a node offset, no in-plane motion, u0 = 0. The
// cross-track error |dz| after 15 orbits: 98 deg: SS 0.0002 m, simple form
// 1.078 m, HCW 0.112 m; 45 deg: SS 0.001 m, simple 0.597 m, HCW 0.932 m. The
// total (1.88 m at 98 deg, 5.44 m at 45 deg) is an along-track drift from the
// J2 coupling of the node offset that no model here has (the same for all).
TEST(SchweighartSedwickTest, CrossTrackAgainstNonlinearJ2) {
  for (double inclination_deg : {98.0, 45.0}) {
    SCOPED_TRACE(inclination_deg);
    const ModelErrors e = MeasureErrors({inclination_deg, 0.0, 0.0, 300.0}, {1, 5, 15});
    EXPECT_LT(e.ss_z_m[2], 0.01);
    EXPECT_LT(50.0 * e.ss_z_m[2], e.hcw_z_m[2]);
    EXPECT_LT(50.0 * e.ss_z_m[2], e.ss_simple_z_m[2]);
    EXPECT_LE(e.ss_m[2], 1.001 * e.hcw_m[2]);
  }
}

// Both: 250 m radial ellipse and 300 m cross-track (250-580 m apart), u0 = 45.
//   98 deg: SS 0.039 / 0.196 / 0.589 m, HCW 1.979 / 9.893 / 29.672 m (50x)
//   45 deg: SS 0.277 / 1.387 / 4.160 m, HCW 1.736 / 8.720 / 26.435 m (6.4x)
TEST(SchweighartSedwickTest, FormationAgainstNonlinearJ2) {
  for (double inclination_deg : {98.0, 45.0}) {
    SCOPED_TRACE(inclination_deg);
    const ModelErrors e = MeasureErrors({inclination_deg, 45.0, 250.0, 300.0}, {1, 5, 15});
    EXPECT_LT(5.0 * e.ss_m[2], e.hcw_m[2]);
    EXPECT_LT(e.ss_m[2], 0.01 * e.separation_m);
  }
}

// The limitation in the header: at u0 = 0 or 90 deg the osculating J2 terms
// move the truly drift-free y'(0) by O(J2 sin^2 i) x0, an along-track drift
// that neither time-invariant model has. Measured after 15 orbits:
//   98 deg: u0 = 0: SS 91.3 m, HCW 61.6 m; u0 = 90: SS 93.9 m, HCW 123.6 m
//   45 deg: u0 = 0: SS 46.0 m, HCW 61.7 m; u0 = 90: SS 48.6 m, HCW 32.8 m
// (SS's error is nearly the same at u0 = 0 and 90: the shift is ~cos 2u0.)
TEST(SchweighartSedwickTest, OsculatingPhaseLimitation) {
  for (double inclination_deg : {98.0, 45.0}) {
    SCOPED_TRACE(inclination_deg);
    const ModelErrors at_node = MeasureErrors({inclination_deg, 0.0, 250.0, 0.0}, {1, 5, 15});
    const ModelErrors at_90 = MeasureErrors({inclination_deg, 90.0, 250.0, 0.0}, {1, 5, 15});
    const double expected_m = inclination_deg > 90.0 ? 91.3 : 46.0;
    EXPECT_NEAR(at_node.ss_m[2], expected_m, 0.5);
    EXPECT_NEAR(at_90.ss_m[2], at_node.ss_m[2], 0.06 * at_node.ss_m[2]);
  }
}

}  // namespace
}  // namespace thrustsched::dynamics
