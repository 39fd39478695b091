// Equinoctial orbital elements (Gazzino 2018, eq. (1.17)) and exact
// conversions to and from ECI position/velocity (Broucke & Cefola 1972 with
// those definitions; corrected: Gazzino 2018 App. D prints the equinoctial
// basis transposed (D.27), both signs of (D.30) wrong and, in (D.38)-(D.45),
// nu_Q ~ M_Q, 40-60 km off), plus the Gauss equations (Gazzino 2018, (B.51)).
//
//   #include "dynamics/geo_model.h"   // for geo::kEarthMu
//   dynamics::EquinoctialElements el{42165765.0, 1e-4, 0.0, 0.0, 2e-4, 1.0};
//   dynamics::Vector6d rv = dynamics::CartesianFromEquinoctial(el, dynamics::geo::kEarthMu);
//   dynamics::EquinoctialElements back = dynamics::EquinoctialFromCartesian(rv,
//   dynamics::geo::kEarthMu); Eigen::Matrix<double, 6, 3> g = dynamics::GaussMatrix(el,
//   dynamics::geo::kEarthMu);
//
// Elements: a (m); ex + j ey = e exp(j(omega + Omega)); ix + j iy =
// tan(i/2) exp(j Omega) (the tan(i/2) variant, not sin); mean longitude
// K = M_Q = Omega + omega + M (rad). Non-singular for e = 0 and i = 0;
// singular only for retrograde equatorial orbits (i = 180 deg).
#ifndef THRUSTSCHED_DYNAMICS_ORBITAL_ELEMENTS_H_
#define THRUSTSCHED_DYNAMICS_ORBITAL_ELEMENTS_H_

#include <Eigen/Core>

namespace thrustsched::dynamics {

/// ECI position (m) and velocity (m/s) stacked.
using Vector6d = Eigen::Matrix<double, 6, 1>;

struct EquinoctialElements {
  double a_m = 0.0;
  double ex = 0.0, ey = 0.0;
  double ix = 0.0, iy = 0.0;
  double mean_longitude_rad = 0.0;  // K = M_Q
};

/// Position and velocity (exact: Kepler's equation in equinoctial form,
/// Gazzino 2018 eq. (D.25), solved by Newton).
/// @throws std::invalid_argument if a value is not finite, a <= 0, e >= 1 or mu <= 0.
Vector6d CartesianFromEquinoctial(const EquinoctialElements& el, double mu);

/// Osculating elements of an ECI state, mean longitude in (-pi, pi]; ix =
/// -h_y/(h + h_z), iy = h_x/(h + h_z) (corrected: Gazzino 2018 (D.30) has both
/// signs wrong).
/// @throws std::invalid_argument if a value is not finite, the orbit is not an
///         ellipse (a <= 0 or e >= 1), r x v = 0 or the orbit is retrograde
///         equatorial (h + h_z <= 1e-12 h).
EquinoctialElements EquinoctialFromCartesian(const Vector6d& rv, double mu);

/// d(elements)/dt = G(el) a_RTN for a perturbing acceleration a_RTN (m/s^2) in
/// the orbit's RTN frame: rows a, ex, ey, ix, iy, K; columns R, T, N (Gazzino
/// 2018, eq. (B.51); corrected: its (6,1) entry is dimensionally wrong, it is
/// -(2r + ab/(a+b) p1)/(n a^2)). The Keplerian mean-motion term n is not
/// included. @throws as CartesianFromEquinoctial.
Eigen::Matrix<double, 6, 3> GaussMatrix(const EquinoctialElements& el, double mu);

/// Columns u_R = r/|r|, u_T = u_N x u_R, u_N = (r x v)/|r x v| in ECI.
/// @throws std::invalid_argument if r x v = 0 or a value is not finite.
Eigen::Matrix3d RtnBasis(const Vector6d& rv);

/// Wraps an angle to (-pi, pi].
double WrapPi(double angle_rad);

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_ORBITAL_ELEMENTS_H_
