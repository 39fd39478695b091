// Modified equinoctial elements with the true longitude, and the Gauss
// equations of the controlled two-body problem with mass in them (Bombrun
// 2007, eq. (1.29)-(1.34), written with the semi-latus rectum P = c^2/mu as
// in Caillau, Gergaud & Noailles 2003):
//
//   dq/dt = f0(q) + (T/m) sum_i u_i f_i(q),  dm/dt = -T |u| / (g0 Isp),  |u| <= 1,
//
// with the control u = (u_Q, u_S, u_W) in the local frame Q radial, S
// orthoradial, W along the angular momentum.
//
//   transfer::Equinoctial q0 = transfer::EquinoctialFromKeplerian(
//       {24505.9e3, 0.725, 5.2 * common::kDegToRad, 0, 0, 0});     // a, e, i, W, w, nu
//   dynamics::Vector6d rv = transfer::CartesianFromEquinoctial(q0, transfer::kMuEarth);
//   transfer::ScaledUnits u;                                     // Mm and hours inside
//   transfer::Vector6 x = u.ToScaled(q0);
//   transfer::GaussTerms g = transfer::Gauss(x, u.mu());            // f0, F = [f_Q f_S f_W]
//
// Contract: SI at the API (m, s, rad, kg, N); the dynamics work in scaled
// units (ScaledUnits: Mm, h) so that the elements and their costates stay
// near 1. Elements: P semi-latus rectum; ex + j ey = e exp(j(w + W));
// hx + j hy = tan(i/2) exp(jW); L = W + w + nu, true longitude (not wrapped:
// it counts the revolutions). Regular for e = 0 and i = 0, singular at
// i = 180 deg only.
#ifndef THRUSTSCHED_TRANSFER_EQUINOCTIAL_H_
#define THRUSTSCHED_TRANSFER_EQUINOCTIAL_H_

#include <array>

#include <Eigen/Core>

#include "dynamics/orbital_elements.h"

namespace thrustsched::transfer {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix63 = Eigen::Matrix<double, 6, 3>;

/// Earth's gravitational constant of Caillau, Gergaud & Noailles 2003 and of
/// the MAP434 course (398600.47 km^3/s^2), m^3/s^2.
inline constexpr double kMuEarth = 398600.47e9;

struct Equinoctial {
  double p_m = 0.0;  // semi-latus rectum
  double ex = 0.0, ey = 0.0;
  double hx = 0.0, hy = 0.0;
  double l_rad = 0.0;  // true longitude
};

/// Classical elements with the true anomaly.
struct Keplerian {
  double a_m = 0.0;
  double e = 0.0;
  double i_rad = 0.0;
  double raan_rad = 0.0;
  double arg_perigee_rad = 0.0;
  double true_anomaly_rad = 0.0;
};

/// @throws std::invalid_argument naming the element if a value is not finite,
///         a <= 0, e not in [0, 1) or i not in [0, pi).
Equinoctial EquinoctialFromKeplerian(const Keplerian& k);
/// Semi-major axis, eccentricity and inclination of q (the classical angles
/// are not needed by the transfers). @throws std::invalid_argument if e >= 1.
double SemiMajorAxis(const Equinoctial& q);
double Eccentricity(const Equinoctial& q);
double Inclination(const Equinoctial& q);

/// Position (m) and velocity (m/s). @throws std::invalid_argument if a value
/// is not finite, P <= 0, e >= 1 or mu <= 0.
dynamics::Vector6d CartesianFromEquinoctial(const Equinoctial& q, double mu);
/// Osculating elements of a state, L in (-pi, pi]. @throws
/// std::invalid_argument if r x v = 0, the orbit is not an ellipse, is
/// retrograde equatorial or a value is not finite.
Equinoctial EquinoctialFromCartesian(const dynamics::Vector6d& rv, double mu);
/// Columns Q = r/|r|, S = W x Q, W = (r x v)/|r x v| in the inertial frame.
Eigen::Matrix3d QswBasis(const dynamics::Vector6d& rv);

/// Scaled units of the dynamics: lengths in Mm, times in hours (Caillau,
/// Gergaud & Noailles 2003), masses in kg.
struct ScaledUnits {
  double length_m = 1e6;
  double time_s = 3600.0;
  double mu_si = kMuEarth;

  double mu() const { return mu_si * time_s * time_s / (length_m * length_m * length_m); }
  /// Thrust (N) in kg * length / time^2.
  double Thrust(double thrust_n) const { return thrust_n * time_s * time_s / length_m; }
  /// Exhaust velocity g0 Isp (m/s) in length / time.
  double Speed(double speed_m_s) const { return speed_m_s * time_s / length_m; }
  Vector6 ToScaled(const Equinoctial& q) const;
  Equinoctial FromScaled(const Vector6& x) const;
};

/// The vector fields of the Gauss equations at x = (P, ex, ey, hx, hy, L)
/// (any consistent units; mu in them): drift f0 and the control fields as
/// the columns of F (Q, S, W).
struct GaussTerms {
  Vector6 f0;
  Matrix63 F;
};
GaussTerms Gauss(const Vector6& x, double mu);

/// Their derivatives with respect to x, written by hand (tested against
/// finite differences): df0(i, j) = d f0_i / d x_j, dF[j] = dF / d x_j.
struct GaussJacobians {
  Matrix6 df0;
  std::array<Matrix63, 6> dF;
};
GaussJacobians GaussDerivatives(const Vector6& x, double mu);

}  // namespace thrustsched::transfer

#endif  // THRUSTSCHED_TRANSFER_EQUINOCTIAL_H_
