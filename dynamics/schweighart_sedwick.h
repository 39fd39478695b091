// Schweighart-Sedwick linearised relative motion with the J2 zonal harmonic,
// about a circular reference orbit (Schweighart & Sedwick, "High-fidelity
// linearized J2 model for satellite formation flight", J. Guidance, Control,
// and Dynamics 25(6), 2002):
//
//   x'' - 2 n c y' - (5 c^2 - 2) n^2 x = a_R
//   y'' + 2 n c x'                     = a_T
//   z'' + (3 c^2 - 2) n^2 z            = a_N
//
//   n = sqrt(mu / r_ref^3),  s = 3 J2 R_E^2 / (8 r_ref^2) (1 + 3 cos 2 i_ref),
//   c = sqrt(1 + s).
//
//   dynamics::SchweighartSedwickModel ss(/*reference_radius_m=*/7028137.0,
//                                        /*inclination_rad=*/98.0 * common::kDegToRad);
//   dynamics::ModelMatrices m = ss.Evaluate(0.0);              // time-invariant A, B
//   double vy0 = ss.DriftFreeAlongTrackVelocity(/*x0_m=*/200.0);  // -2 n c x0, m/s
//
// Contract: the state, inputs and outputs are those of HcwModel
// (dynamics/models.h): [x, y, z, vx, vy, vz] (m, m/s), x radial (outward), y
// along-track, z orbit normal, velocities in the rotating frame, inputs the
// RTN thrust acceleration (m/s^2), outputs the positions (m). With J2 = 0 the
// matrices are HCW's for the same n. The model is time-invariant, so the exact
// zero-order-hold discretisation (matrix exponential) applies; d = 0.
//
// Cross-track: this is the time-invariant form of the paper, valid when the
// deputy's orbit plane is the chief's up to a small tilt that precesses with
// it (equal inclinations). The paper's full cross-track equation
// z'' + q^2 z = 2 l q cos(q t + phi) adds the differential nodal precession of
// two planes with different inclinations (l, q, phi depend on both orbits'
// elements, not only on the reference); it is not implemented: it would need
// the deputy's elements in the model and make the right side time-varying,
// and it could not be derived and validated in the time this unit had.
// The in-plane part is exact as printed in the paper.
//
// Drift-free in-plane motion: integrating y'' = -2 n c x' gives
// y' = y'_0 - 2 n c (x - x_0), and the x equation becomes
// x'' + (1 - s) n^2 x = 2 n c (y'_0 + 2 n c x_0), so the along-track drift
// (the mean of y') vanishes iff y'_0 = -2 n c x_0 (HCW: -2 n x_0); the radial
// oscillation then has frequency n sqrt(1 - s) about x = 0.
#ifndef THRUSTSCHED_DYNAMICS_SCHWEIGHART_SEDWICK_H_
#define THRUSTSCHED_DYNAMICS_SCHWEIGHART_SEDWICK_H_

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "dynamics/linear_model.h"

namespace thrustsched::dynamics {

/// Earth constants of the model's defaults (EGM2008 values, as dynamics::geo).
inline constexpr double kSsEarthMu_m3_s2 = 3.986004418e14;
inline constexpr double kSsEarthRadius_m = 6378137.0;
inline constexpr double kSsEarthJ2 = 1.08262668e-3;

class SchweighartSedwickModel final : public LinearModel {
 public:
  /// reference_radius_m: radius of the circular reference orbit (m);
  /// inclination_rad: its inclination, in [0, pi]; j2 may be 0 (HCW).
  /// @throws std::invalid_argument if reference_radius_m, mu_m3_s2,
  ///         earth_radius_m or length_scale_m is not finite and > 0, the
  ///         inclination is not in [0, pi], j2 is not finite and >= 0, or the
  ///         in-plane motion would not be oscillatory (s >= 1, far below the
  ///         Earth's surface).
  SchweighartSedwickModel(double reference_radius_m, double inclination_rad,
                          double length_scale_m = 1000.0, double mu_m3_s2 = kSsEarthMu_m3_s2,
                          double j2 = kSsEarthJ2, double earth_radius_m = kSsEarthRadius_m);

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
  /// y'(0) (m/s) that cancels the along-track drift for a radial offset x0_m
  /// (header comment): -2 n c x0. @throws std::invalid_argument if not finite.
  double DriftFreeAlongTrackVelocity(double x0_m) const;

 private:
  double r_ref_, inclination_, length_scale_m_;
  double n_, s_, c_;
};

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_SCHWEIGHART_SEDWICK_H_
