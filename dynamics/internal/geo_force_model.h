// Private helper (not installed): the natural-force model shared by
// GeoLinearModel and GeoSimulator, so both see exactly the same physics.
// Frame, time scale and constants are documented in dynamics/geo_simulator.h.
#ifndef THRUSTSCHED_DYNAMICS_INTERNAL_GEO_FORCE_MODEL_H_
#define THRUSTSCHED_DYNAMICS_INTERNAL_GEO_FORCE_MODEL_H_

#include <cmath>

#include "dynamics/geo_model.h"
#include "dynamics/internal/geo_physics.h"

namespace thrustsched::dynamics::internal {

/// EGM2008 fully normalised coefficients to degree and order 4 (Pavlis et al. 2012).
struct NormalizedCoefficient {
  int n, m;
  double c, s;
};
inline constexpr NormalizedCoefficient kEgm2008[] = {
    {2, 0, -4.841651437908150e-4, 0.0},
    {2, 1, -2.066155090741760e-10, 1.384413891379790e-9},
    {2, 2, 2.439383573283130e-6, -1.400273703859340e-6},
    {3, 0, 9.571612070934730e-7, 0.0},
    {3, 1, 2.030462010478640e-6, 2.482004158568720e-7},
    {3, 2, 9.047878948095281e-7, -6.190054751776180e-7},
    {3, 3, 7.213217571215680e-7, 1.414349261929410e-6},
    {4, 0, 5.399658666389910e-7, 0.0},
    {4, 1, -5.361573893888670e-7, -4.735673465180860e-7},
    {4, 2, 3.505016239626490e-7, 6.624800262758290e-7},
    {4, 3, 9.908567666723210e-7, -2.009567235674520e-7},
    {4, 4, -1.885196330230330e-7, 3.088038821491940e-7},
};

/// N_nm = sqrt((2 - delta_0m)(2n + 1)(n - m)!/(n + m)!): unnormalised = N_nm * normalised.
double NormalizationFactor(int n, int m);

class GeoForceModel {
 public:
  /// @throws std::invalid_argument with the IsValid message.
  explicit GeoForceModel(const GeoModelOptions& options);

  struct Bodies {
    Vec3<double> sun{};   // m, ECI (zero when neither sun nor srp is enabled)
    Vec3<double> moon{};  // m, ECI (zero when moon is disabled)
  };

  const GeoModelOptions& options() const { return options_; }
  double station_longitude_rad() const { return station_longitude_rad_; }
  double epoch_jd_tt() const { return epoch_jd_tt_; }
  double theta0_rad() const { return theta0_; }
  /// Theta(t) in [0, 2 pi).
  double Theta(double t) const;
  /// Sun and Moon at t (s since the epoch), mean equator and equinox of the epoch.
  Bodies BodiesAt(double t) const;
  /// Sun only (for the shadow function), same frame.
  Vec3<double> SunAt(double t) const;

  /// How SRP decides shadow: from the position (kCompute), or forced by an
  /// integrator that handles the shadow boundary as an event.
  enum class Shadow { kCompute, kSunlit, kShadow };

  /// Sum of the enabled natural accelerations (excluding the central term)
  /// at ECI position r, with Earth rotation angle theta and bodies of the same t.
  template <typename T>
  Vec3<T> Acceleration(const Vec3<T>& r, double theta, const Bodies& bodies,
                       Shadow shadow = Shadow::kCompute) const {
    Vec3<T> acc = {T(0.0), T(0.0), T(0.0)};
    if (coefficients_.degree >= 2) {
      const double c = std::cos(theta), s = std::sin(theta);
      const Vec3<T> r_ef = {c * r[0] + s * r[1], c * r[1] - s * r[0], r[2]};
      const Vec3<T> a_ef =
          GeopotentialAccelerationEcef(r_ef, coefficients_, geo::kEarthMu, geo::kEarthRadius);
      acc[0] += c * a_ef[0] - s * a_ef[1];
      acc[1] += s * a_ef[0] + c * a_ef[1];
      acc[2] += a_ef[2];
    }
    if (options_.sun) Add(acc, ThirdBodyAcceleration(r, bodies.sun, geo::kSunMu));
    if (options_.moon) Add(acc, ThirdBodyAcceleration(r, bodies.moon, geo::kMoonMu));
    if (srp_coefficient_ > 0.0) {
      const bool sunlit = shadow == Shadow::kCompute
                              ? ShadowFunction({Value(r[0]), Value(r[1]), Value(r[2])}, bodies.sun,
                                               geo::kEarthRadius) >= 0.0
                              : shadow == Shadow::kSunlit;
      if (sunlit)
        Add(acc, SrpAcceleration(r, bodies.sun, srp_coefficient_, geo::kAstronomicalUnit));
    }
    return acc;
  }

  const GeopotentialCoefficients& coefficients() const { return coefficients_; }
  bool has_srp() const { return srp_coefficient_ > 0.0; }

 private:
  template <typename T>
  static void Add(Vec3<T>& acc, const Vec3<T>& more) {
    for (int i = 0; i < 3; ++i) acc[i] += more[i];
  }

  GeoModelOptions options_;
  double station_longitude_rad_ = 0.0;
  double epoch_jd_tt_ = 0.0;
  double theta0_ = 0.0;
  double srp_coefficient_ = 0.0;  // P_sun C_r A/m, m/s^2 at 1 AU
  GeopotentialCoefficients coefficients_;
};

}  // namespace thrustsched::dynamics::internal

#endif  // THRUSTSCHED_DYNAMICS_INTERNAL_GEO_FORCE_MODEL_H_
