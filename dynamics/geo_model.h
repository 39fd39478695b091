// Linearised GEO station-keeping model (the "synthesis model" of Gazzino
// 2018, eqs. (1.41)-(1.44) and App. B): relative osculating equinoctial
// elements about a station point fixed in the Earth-fixed frame, with Earth
// gravity to degree and order 4, Sun, Moon and solar radiation pressure.
//
//   dynamics::GeoModelOptions opt;              // 118 E, epoch 2034-01-01T00:00:00Z
//   dynamics::GeoLinearModel geo(opt);          // throws on invalid options
//   dynamics::ModelMatrices m = geo.Evaluate(3600.0);   // A (6x6), B (6x3), d (6), SI
//   dynamics::OutputMatrices c = geo.EvaluateOutput(3600.0);   // C, C' (3x6)
//
// State x = [da_m, ex, ey, ix, iy, dl_rad]: osculating elements minus the
// station point x_mp = [a_mp = 42165.765 km, 0, 0, 0, 0, l_mp = station
// longitude], with (thesis (1.17), (1.20)) ex + j ey = e exp(j(w + W)),
// ix + j iy = tan(i/2) exp(jW), l = M_Q - Theta(t) (mean longitude minus the
// Earth rotation angle, wrapped to (-pi, pi] relative to l_mp).
// Input u = thrust acceleration (m/s^2) in the satellite's RTN frame.
// Outputs y = [dr_m, lat_rad, lon_rad]: geocentric radius minus a_mp,
// geocentric latitude, east longitude minus the station longitude.
//
//   x' = A(t) x + B(t) u + d(t),    y = C(t) x,    y' = C'(t) x + C(t) x'
//   A(t) = df_L/dx (x_mp, t)   exact Jacobian (forward-mode dual numbers) of
//          f_L(x, t) = [0,0,0,0,0, n(a) - omega_E] + G(x, t) a_nat^RTN(x, t)
//   B(t) = G(x_mp, t)          Gauss matrix, B12 = 2 a_mp / v_mp (corrected: Gazzino
//                              2018 eq. (B.59) prints a_mp / v_mp; cf. its (B.64a))
//   d(t) = f_L(x_mp, t)        includes the Kepler residual n(a_mp) - omega_E =
//                              -4.14e-9 rad/s (x_mp is not an equilibrium;
//                              corrected: Gazzino 2018 (B.32), (B.60) assume it is)
//   C(t)  (Gazzino 2018, eq. (B.82)), kappa = l_mp + Theta(t):
//     [1, -a cos k, -a sin k, 0, 0, 0; 0, 0, 0, 2 sin k, -2 cos k, 0; 0, 2 sin k, -2 cos k, 0, 0,
//     1]
//   C'(t) = dC/dt with dkappa/dt = omega_E (E = 2H + CA + C' of Gazzino 2018 (B.98) is wrong).
// The physics, frame and time conventions are those of GeoSimulator
// (dynamics/geo_simulator.h), which is the nonlinear reference for this model.
#ifndef THRUSTSCHED_DYNAMICS_GEO_MODEL_H_
#define THRUSTSCHED_DYNAMICS_GEO_MODEL_H_

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "common/constants.h"
#include "dynamics/linear_model.h"

namespace thrustsched::dynamics {

/// Physical constants of the GEO models (SI). Sources: Gazzino 2018 (a_mp, delta);
/// standard values the thesis does not give: EGM2008 (mu_E, R_E), IERS (omega_E),
/// JPL ephemerides (mu_S, mu_M), IAU 2012 (AU), Montenbruck & Gill 2000 sec. 3.4 (P).
namespace geo {
inline constexpr double kEarthMu = common::kEarthMu_m3_s2;      // m^3/s^2 (EGM2008 / IERS)
inline constexpr double kEarthRadius = common::kEarthRadius_m;  // m, geopotential reference radius
inline constexpr double kEarthRotationRate = 7.2921158553e-5;   // rad/s, d(GMST)/dt
inline constexpr double kSunMu = 1.32712440018e20;              // m^3/s^2
inline constexpr double kMoonMu = 4.902800066e12;               // m^3/s^2
inline constexpr double kAstronomicalUnit = 1.495978707e11;     // m
inline constexpr double kSolarPressure = 4.56e-6;               // N/m^2 at 1 AU
inline constexpr double kStationRadius = 42165765.0;            // m, a_mp (thesis (B.31))
inline constexpr double kWindowHalfWidthRad = 0.05 * common::kPi / 180.0;  // delta
}  // namespace geo

struct GeoModelOptions {
  double station_longitude_deg = 118.0;        // east, in [-180, 360]
  std::string epoch = "2034-01-01T00:00:00Z";  // UTC instant of t = 0 (Epoch::Parse format)
  bool j2 = true;                      // zonal harmonics J2..J_degree (named after the dominant J2)
  bool tesseral = true;                // tesseral and sectorial harmonics (n, m >= 1), n <= degree
  bool sun = true, moon = true;        // third-body attraction (with the indirect term)
  bool srp = true;                     // cannonball solar radiation pressure, cylindrical shadow
  int gravity_degree = 4;              // 2..4, order = degree (EGM2008 coefficients)
  double area_to_mass_m2_kg = 0.0227;  // A/m (m^2/kg), >= 0 (thesis sigma, L7281)
  double reflectivity_cr = 1.0;        // C_r in [0, 2]

  /// False (and a message naming the field and value in *error, if non-null)
  /// when a field is out of range or the epoch does not parse.
  bool IsValid(std::string* error) const;

  /// Sets one field from text, by its name above (e.g. "gravity_degree", "4";
  /// booleans "true"/"false"/"1"/"0"). Does not validate ranges (IsValid does).
  /// @throws std::invalid_argument naming an unknown field or a value that does
  ///         not parse as the field's type.
  void Set(std::string_view field, std::string_view value);
  /// The names accepted by Set.
  static std::vector<std::string> FieldNames();
};

namespace internal {
class GeoForceModel;
}

/// Relative equinoctial state x = [da_m, ex, ey, ix, iy, dl_rad] (osculating elements minus the
/// station point x_mp = [a_mp = 42165.765 km, 0,0,0,0, l_mp = station longitude]); inputs RTN
/// acceleration (m/s^2); outputs [dr_m, lat_rad, lon_rad] relative to the station point.
/// Const methods are thread-safe (no caches).
class GeoLinearModel final : public LinearModel {
 public:
  /// @throws std::invalid_argument with the IsValid message if options are invalid.
  explicit GeoLinearModel(const GeoModelOptions& options);

  std::string_view name() const override { return "geo"; }
  int num_states() const override { return 6; }
  int num_inputs() const override { return 3; }
  int num_outputs() const override { return 3; }
  bool is_time_invariant() const override { return false; }

  /// A, B, d at t (s since the epoch), ~2 us (one ephemeris evaluation plus one
  /// dual-number pass). @throws std::invalid_argument if t is not finite.
  ModelMatrices Evaluate(double t) const override;
  /// C and C' at t. @throws std::invalid_argument if t is not finite.
  OutputMatrices EvaluateOutput(double t) const override;
  /// Rows radial, east, north (m) about the station point, from C(t):
  /// [dr; a_mp lon; a_mp lat]. Two satellites of one station point are
  /// P(t) (x - y) apart to first order in their offsets from it (second-order
  /// error ~ |offset|^2 / a_mp: 30 m at 36.8 km, the edge of a 0.05 deg box).
  /// @throws std::invalid_argument if t is not finite.
  Eigen::MatrixXd LocalPositionMap(double t) const override;

  /// {"da_m", "ex", "ey", "ix", "iy", "dl_rad"}.
  std::vector<std::string> state_names() const override;
  /// {"dr_m", "lat_rad", "lon_rad"}.
  std::vector<std::string> output_names() const override;
  /// [delta a_mp, delta, delta, delta, delta, delta], delta = 0.05 deg in rad.
  Eigen::VectorXd state_scale() const override;
  /// 1 / omega_E (s).
  double time_scale() const override;

  /// Earth rotation rate used (rad/s): omega_E = 7.2921158553e-5.
  double mean_motion() const;
  /// a_mp = 42165765 m.
  double station_radius_m() const;
  /// Station longitude l_mp (rad, east).
  double station_longitude_rad() const;
  const GeoModelOptions& options() const;
  /// Theta(t) = GMST(epoch) + omega_E t, wrapped to [0, 2 pi) (rad).
  double EarthRotationAngle(double t) const;

  /// The nonlinear natural rate f_L(x, t) of the relative state (osculating
  /// variation of parameters, no thrust); A = df_L/dx and d = f_L at x = 0.
  /// @throws std::invalid_argument if x is not a finite 6-vector or t is not finite.
  Eigen::VectorXd NaturalRate(const Eigen::VectorXd& x, double t) const;
  /// The nonlinear input matrix G(x, t) (6 x 3, Gauss equations) at state x;
  /// B(t) = G(0, t). @throws as NaturalRate.
  Eigen::MatrixXd InputMatrix(const Eigen::VectorXd& x, double t) const;

 private:
  std::shared_ptr<const internal::GeoForceModel> forces_;
};

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_GEO_MODEL_H_
