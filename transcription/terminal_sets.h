// End-of-horizon station-keeping sets (thesis ch. 5, corrected): linear inner
// approximations of the set of relative states from which free Keplerian
// (HCW) motion stays inside the window.
//
// In HCW coordinates zeta = (x, y, z, xdot, ydot, zdot) (x radial, y
// along-track, z normal; m, m/s), mean motion n, window half-widths eps_y
// (along-track) and eps_z (normal):
//   out of plane  (5.11):  z^2 + (zdot/n)^2 <= eps_z^2                   (a disk)
//   in plane (5.19), (5.30) with xi1 = 2 xdot/n, xi2 = 6 x + 4 ydot/n,
//     xi+(t) = +eps_y + (6 n x + 3 ydot) t - y + 2 xdot/n,
//     xi-(t) = -eps_y + (6 n x + 3 ydot) t - y + 2 xdot/n:
//       sqrt(xi1^2 + xi2^2) <= xi+(t)  and  sqrt(xi1^2 + xi2^2) <= -xi-(t)  (two cones)
//   i.e. the drifting in-plane ellipse (centre drift -(6 n x + 3 ydot) t,
//   along-track semi-axis 2 A_xy = sqrt(xi1^2 + xi2^2)) fits |y| <= eps_y at
//   time t after the junction. The centre is affine in t, so imposing it at
//   t = 0 and t = T keeps the ellipse inside on all of [0, T] (the thesis
//   plugged the absolute date t_j^c into its (5.32)-(5.35)).
// Each round set is replaced by its inscribed regular K-gon (thesis App. K):
//   cos(phi_k) u + sin(phi_k) v <= cos(pi/K) r,   phi_k = (2k + 1) pi / K,
// which is (K.3)/(K.8)/(K.14) divided by 2 sin(pi/K) (tested), with
// k = 0..K-1 (the thesis's k = 1..K-1 in (K.5) drops a facet).
//
// For the GEO model the HCW coordinates come from the outputs and their rates
// through the corrected, diagonal map (thesis App. J is wrong):
//   x = dr, y = rho dlon, z = rho dlat, xdot = dr', ydot = rho dlon', zdot = rho dlat',
// with rho = a_mp (not the altitude r_mp the thesis prints).
//
//   transcription::SkSetOptions o{.mean_motion = 7.2921159e-5, .eps_y = 36.8e3, .eps_z = 36.8e3};
//   transcription::HalfSpaces h = transcription::StationKeepingSet(o);   // h.a * zeta <= h.b
#ifndef THRUSTSCHED_TRANSCRIPTION_TERMINAL_SETS_H_
#define THRUSTSCHED_TRANSCRIPTION_TERMINAL_SETS_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/linear_model.h"

namespace thrustsched::transcription {

/// a * zeta <= b, one row per facet, with names.
struct HalfSpaces {
  Eigen::MatrixXd a;
  Eigen::VectorXd b;
  std::vector<std::string> names;
  int rows() const { return static_cast<int>(b.size()); }
};

struct SkSetOptions {
  double mean_motion = 0.0;  // rad/s
  double eps_y = 0.0;        // along-track half width (m)
  double eps_z = 0.0;        // normal half width (m)
  int facets_out_of_plane = 16;
  int facets_cone_plus = 16;
  int facets_cone_minus = 16;
  std::vector<double> lookahead_s = {0.0};  // times t at which the cones hold

  /// mean_motion, eps_y and eps_z finite and > 0; at least 3 facets per
  /// polygon; lookahead_s not empty, its entries finite and >= 0. On failure
  /// `*error` (if given) says which.
  bool IsValid(std::string* error) const;
};

/// Facets of the inscribed polygons. @throws std::invalid_argument on
/// non-positive n or widths, fewer than 3 facets, negative look-ahead.
HalfSpaces StationKeepingSet(const SkSetOptions& options);

/// Exact (round) membership, for tests: disk and both cones at every look-ahead.
bool InExactStationKeepingSet(const SkSetOptions& options, const Eigen::Matrix<double, 6, 1>& zeta,
                              double tolerance = 0.0);

/// zeta = map * x + offset for a model state x at time t (HCW or GEO model).
struct AffineMap {
  Eigen::MatrixXd map;     // 6 x n
  Eigen::VectorXd offset;  // 6
};
/// Supported models: dynamics::HcwModel and dynamics::YamanakaAnkersenModel
/// (identity: their state is already these coordinates) and
/// dynamics::GeoLinearModel (outputs and rates, input-free rate).
/// @throws std::invalid_argument for other models.
AffineMap HcwCoordinates(const dynamics::LinearModel& model, double t);
/// Mean motion of the HCW frame of the model (rad/s); same model support.
double HcwMeanMotion(const dynamics::LinearModel& model);
/// Along-track and normal half widths (m) of a window on the model outputs:
/// HCW outputs y (1) and z (2) in m; GEO lon (2) and lat (1) in rad times rho.
/// @throws std::invalid_argument if the window does not constrain both.
void HcwWindowWidths(const dynamics::LinearModel& model, const std::vector<int>& outputs,
                     const std::vector<double>& half_widths, double* eps_y, double* eps_z);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_TERMINAL_SETS_H_
