// Two-impulse coplanar transfer between circular orbits: the Hohmann closed
// form, and the minimum of the MAP434 criterion (Ecole polytechnique course
// MAP434, session 8, 2019) J = (|dV0|^2 + |dVf|^2) / 2 over every transfer
// conic: one impulse at the start point, a coast to the first crossing of the
// target radius at a free time, one impulse onto the circular target orbit.
//
//   transfer::HohmannTransfer h = transfer::Hohmann(6569.48071e3, 42159.48517e3,
//                                                   dynamics::geo::kEarthMu);
//   // h.total_m_s = 3935.224, h.time_of_flight_s = 5.256713 h (Vallado 2013, Example 6-1)
//   transfer::TwoImpulseResult r = transfer::MinimiseTwoImpulse(
//       {transfer::kMuEarth, 0.1575 * 42165e3, 42165e3});   // MAP434's low circular orbit to GEO
//
// Contract: SI (m, m/s, s). The minimiser searches the post-burn velocity
// (radial, tangential) over every ellipse through the start point that
// reaches the target radius (apogee >= target radius): a golden-section
// search on the tangential component (bounded below by the apogee condition,
// found by bisection) nested in one on the radial component. It assumes J
// unimodal along each of them (the tests check the optimum against a grid).
#ifndef THRUSTSCHED_TRANSFER_TWO_IMPULSE_H_
#define THRUSTSCHED_TRANSFER_TWO_IMPULSE_H_

#include <string>

namespace thrustsched::transfer {

struct HohmannTransfer {
  double dv1_m_s = 0.0;
  double dv2_m_s = 0.0;
  double total_m_s = 0.0;
  double time_of_flight_s = 0.0;
};

/// Hohmann transfer from the circle of radius r1 to the circle of radius r2
/// (either larger). @throws std::invalid_argument unless r1, r2, mu > 0 and finite.
HohmannTransfer Hohmann(double r1_m, double r2_m, double mu);

struct TwoImpulseProblem {
  double mu = 0.0;        // m^3/s^2
  double r0_m = 0.0;      // circular start orbit
  double target_m = 0.0;  // circular target orbit, > r0_m
  bool IsValid(std::string* error) const;
};

struct TwoImpulseResult {
  double dv0_radial_m_s = 0.0, dv0_tangential_m_s = 0.0;  // first impulse, local frame
  double dvf_radial_m_s = 0.0, dvf_tangential_m_s = 0.0;  // second impulse, local frame
  double dv0_m_s = 0.0, dvf_m_s = 0.0;                    // their norms
  double cost_m2_s2 = 0.0;                                // (dv0^2 + dvf^2) / 2
  double time_of_flight_s = 0.0;
  double transfer_a_m = 0.0, transfer_e = 0.0;  // the coast ellipse
};

/// Evaluates a transfer: the post-burn velocity (radial, tangential, m/s) at
/// the start point. Returns false (and leaves *out alone) if the coast
/// ellipse never reaches the target radius or is not an ellipse.
bool EvaluateTwoImpulse(const TwoImpulseProblem& p, double v_radial_m_s, double v_tangential_m_s,
                        TwoImpulseResult* out);

/// The minimum of J. @throws std::invalid_argument if !p.IsValid.
TwoImpulseResult MinimiseTwoImpulse(const TwoImpulseProblem& p);

}  // namespace thrustsched::transfer

#endif  // THRUSTSCHED_TRANSFER_TWO_IMPULSE_H_
