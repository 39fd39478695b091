// Classical (Keplerian) orbital elements, as exchanged in CCSDS Orbit
// Parameter Messages (CCSDS 502.0-B-3 §3.2.4, Table 3-3), and their exact
// conversions to the equinoctial elements of dynamics/orbital_elements.h and
// to position/velocity.
//
//   dynamics::KeplerianElements k;
//   k.a_m = 42165765.0; k.e = 2e-4; k.i_rad = 1e-3; k.raan_rad = 0.3;
//   k.arg_perigee_rad = 1.2; k.anomaly_rad = 2.0; k.anomaly = dynamics::AnomalyKind::kTrue;
//   dynamics::Vector6d rv = dynamics::CartesianFromKeplerian(k, dynamics::geo::kEarthMu);
//   dynamics::KeplerianElements back =
//       dynamics::KeplerianFromCartesian(rv, dynamics::geo::kEarthMu,
//       dynamics::AnomalyKind::kTrue);
//
// Keplerian -> equinoctial (thesis (1.17)): ex + j ey = e exp(j(w + W)),
// ix + j iy = tan(i/2) exp(jW), mean longitude K = W + w + M. This direction
// is regular everywhere except i = 180 deg. The inverse is singular where the
// classical angles are undefined: for i = 0 (tan(i/2) < 1e-10) the node is
// set to W = 0, for e = 0 (e < 1e-10) the perigee to w = 0 (the sums W + w
// and W + w + anomaly stay exact), the usual convention.
#ifndef THRUSTSCHED_DYNAMICS_KEPLERIAN_H_
#define THRUSTSCHED_DYNAMICS_KEPLERIAN_H_

#include "dynamics/orbital_elements.h"

namespace thrustsched::dynamics {

enum class AnomalyKind { kTrue, kMean };

struct KeplerianElements {
  double a_m = 0.0;
  double e = 0.0;
  double i_rad = 0.0;
  double raan_rad = 0.0;         // right ascension of the ascending node W
  double arg_perigee_rad = 0.0;  // argument of pericenter w
  double anomaly_rad = 0.0;      // true or mean anomaly, per `anomaly`
  AnomalyKind anomaly = AnomalyKind::kTrue;
};

/// Mean anomaly (rad, in (-pi, pi]) of true anomaly nu on an ellipse of
/// eccentricity e. @throws std::invalid_argument unless 0 <= e < 1 and nu is finite.
double MeanFromTrueAnomaly(double nu_rad, double e);
/// True anomaly (rad, in (-pi, pi]) of mean anomaly M (Kepler's equation by Newton).
/// @throws as MeanFromTrueAnomaly.
double TrueFromMeanAnomaly(double mean_rad, double e);

/// @throws std::invalid_argument naming the element if a value is not finite,
///         a <= 0, e is not in [0, 1) or i is not in [0, pi).
EquinoctialElements EquinoctialFromKeplerian(const KeplerianElements& k);
/// Inverse of EquinoctialFromKeplerian (angles in [0, 2 pi), anomaly of the
/// requested kind). @throws std::invalid_argument if e >= 1 or a value is not finite.
KeplerianElements KeplerianFromEquinoctial(const EquinoctialElements& el, AnomalyKind anomaly);

/// Position (m) and velocity (m/s). @throws as EquinoctialFromKeplerian, or if mu <= 0.
Vector6d CartesianFromKeplerian(const KeplerianElements& k, double mu);
/// Osculating elements of a state. @throws as EquinoctialFromCartesian.
KeplerianElements KeplerianFromCartesian(const Vector6d& rv, double mu, AnomalyKind anomaly);

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_KEPLERIAN_H_
