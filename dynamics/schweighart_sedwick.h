// Schweighart-Sedwick linearised relative motion with the J2 zonal harmonic,
// about a circular reference orbit (Schweighart & Sedwick, "High-fidelity
// linearized J2 model for satellite formation flight", J. Guidance, Control,
// and Dynamics 25(6), 2002):
//
//   x'' - 2 n c y' - (5 c^2 - 2) n^2 x = a_R
//   y'' + 2 n c x'                     = a_T
//   z'' + q^2 z                        = a_N
//
//   n = sqrt(mu / r_ref^3),  s = 3 J2 R_E^2 / (8 r_ref^2) (1 + 3 cos 2 i_ref),
//   c = sqrt(1 + s),
//   q = n c + 3 n J2 R_E^2 / (2 r_ref^2) cos^2 i_ref   (CrossTrack::kEqualInclination)
//   q = n sqrt(3 c^2 - 2)                                (CrossTrack::kSimple)
//
//   dynamics::SchweighartSedwickModel ss(/*reference_radius_m=*/7028137.0,
//                                        /*inclination_rad=*/98.0 * common::kDegToRad);
//   dynamics::ModelMatrices m = ss.Evaluate(0.0);                 // time-invariant A, B
//   double vy0 = ss.DriftFreeAlongTrackVelocity(/*x0_m=*/200.0);  // -2 n c x0, m/s
//
// Contract: the state, inputs and outputs are those of HcwModel
// (dynamics/models.h): [x, y, z, vx, vy, vz] (m, m/s), x radial (outward), y
// along-track, z orbit normal, velocities in the rotating frame, inputs the
// RTN thrust acceleration (m/s^2), outputs the positions (m). The frame is
// the reference orbit's: it turns about the orbit normal only, not with the
// O(J2) roll of an osculating orbit plane about the radius vector. With J2 = 0
// the matrices are HCW's for the same n. The model is time-invariant, so the
// exact zero-order-hold discretisation (matrix exponential) applies; d = 0.
// The in-plane part is the paper's, as printed.
//
// Cross-track: the paper's full equation z'' + q^2 z = 2 l q cos(q t + phi)
// has l, q, phi from both orbits' inclinations and nodes (differential nodal
// precession). For a deputy of the chief's inclination (formations whose
// cross-track motion comes from a node offset) the precession rates are equal,
// so l = 0 and q = n c - Omega' cos i with Omega' = -3 n J2 R_E^2 / (2 r^2)
// cos i, the mean argument-of-latitude rate of the reference: the tilt of two
// planes precessing together gives z = a cos(u) to first order. This is the
// default (kEqualInclination), time-invariant. kSimple is the paper's first,
// single-satellite form z'' = -(3 c^2 - 2) n^2 z; against the nonlinear J2
// motion (tests/dynamics/schweighart_sedwick_test.cc), 300 m cross-track from
// a node offset, its cross-track error after 15 orbits is 1.08 m at 98 deg
// (HCW 0.11 m, kEqualInclination 0.0002 m) and 0.60 m at 45 deg (HCW 0.93 m,
// kEqualInclination 0.001 m). Neither represents a deputy of another
// inclination (l != 0, a forced, time-varying term): that would need the
// deputy's elements in the model, and was not derived and tested here.
//
// Drift-free in-plane motion: integrating y'' = -2 n c x' gives
// y' = y'_0 - 2 n c (x - x_0), and the x equation becomes
// x'' + (1 - s) n^2 x = 2 n c (y'_0 + 2 n c x_0), so the along-track drift
// (the mean of y') vanishes iff y'_0 = -2 n c x_0 (HCW: -2 n x_0); the radial
// oscillation then has frequency n sqrt(1 - s) about x = 0. This is the
// orbit-averaged condition: the osculating J2 terms at the initial argument of
// latitude u0 shift the truly drift-free y'_0 by O(J2 sin^2 i cos 2u0) x0
// (measured in the test: ~6 m of along-track drift per orbit for x0 = 250 m at
// 98 deg and u0 = 0, ~0 at u0 = 45 deg), which no time-invariant model carries.

#ifndef THRUSTSCHED_DYNAMICS_SCHWEIGHART_SEDWICK_H_
#define THRUSTSCHED_DYNAMICS_SCHWEIGHART_SEDWICK_H_

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "common/constants.h"
#include "dynamics/linear_model.h"

namespace thrustsched::dynamics {

/// J2 of the model's default (EGM2008's C20 as the unnormalised J2); mu and
/// the radius are common::kEarthMu_m3_s2 and common::kEarthRadius_m.
inline constexpr double kSsEarthJ2 = 1.08262668e-3;

/// Which cross-track equation (header comment).
enum class CrossTrack { kEqualInclination, kSimple };

class SchweighartSedwickModel final : public LinearModel {
 public:
  /// reference_radius_m: radius of the circular reference orbit (m);
  /// inclination_rad: its inclination, in [0, pi]; j2 may be 0 (HCW).
  /// @throws std::invalid_argument if reference_radius_m, mu_m3_s2,
  ///         earth_radius_m or length_scale_m is not finite and > 0, the
  ///         inclination is not in [0, pi], j2 is not finite and >= 0, or s
  ///         is not in (-1/3, 1) (the motion would not be oscillatory; only
  ///         far inside the Earth).
  SchweighartSedwickModel(double reference_radius_m, double inclination_rad,
                          double length_scale_m = 1000.0,
                          CrossTrack cross_track = CrossTrack::kEqualInclination,
                          double mu_m3_s2 = common::kEarthMu_m3_s2, double j2 = kSsEarthJ2,
                          double earth_radius_m = common::kEarthRadius_m);

  std::string_view name() const override { return "schweighart_sedwick"; }
  int num_states() const override { return 6; }
  int num_inputs() const override { return 3; }
  int num_outputs() const override { return 3; }
  bool is_time_invariant() const override { return true; }
  ModelMatrices Evaluate(double t) const override;
  OutputMatrices EvaluateOutput(double t) const override;
  std::vector<std::string> state_names() const override;
  std::vector<std::string> output_names() const override;
  Eigen::VectorXd state_scale() const override;
  double time_scale() const override { return 1.0 / n_; }

  double reference_radius() const { return r_ref_; }
  double inclination() const { return inclination_; }
  /// Mean motion n = sqrt(mu / r_ref^3) of the reference orbit, rad/s.
  double mean_motion() const { return n_; }
  /// The paper's s (dimensionless; < 0 for i between 54.7 and 125.3 deg).
  double s() const { return s_; }
  /// c = sqrt(1 + s).
  double c() const { return c_; }
  /// Cross-track angular frequency q (rad/s) of the chosen CrossTrack form.
  double cross_track_frequency() const { return q_; }
  CrossTrack cross_track() const { return cross_track_; }
  /// y'(0) (m/s) that cancels the along-track drift for a radial offset x0_m
  /// (header comment): -2 n c x0. @throws std::invalid_argument if not finite.
  double DriftFreeAlongTrackVelocity(double x0_m) const;

 private:
  double r_ref_, inclination_, length_scale_m_;
  CrossTrack cross_track_;
  double n_, s_, c_, q_;
};

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_SCHWEIGHART_SEDWICK_H_
