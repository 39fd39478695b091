#include <cmath>
#include <stdexcept>
#include <string>

#include "common/constants.h"
#include "dynamics/ephemerides.h"
#include "dynamics/internal/geo_force_model.h"
#include "dynamics/time.h"

namespace thrustsched::dynamics::internal {
namespace {
using common::kPi;

double Factorial(int k) {
  double f = 1.0;
  for (int i = 2; i <= k; ++i) f *= i;
  return f;
}
}  // namespace

double NormalizationFactor(int n, int m) {
  return std::sqrt((m == 0 ? 1.0 : 2.0) * (2.0 * n + 1.0) * Factorial(n - m) / Factorial(n + m));
}

GeoForceModel::GeoForceModel(const GeoModelOptions& options) : options_(options) {
  std::string error;
  if (!options_.IsValid(&error)) throw std::invalid_argument(error);
  station_longitude_rad_ = options_.station_longitude_deg * kPi / 180.0;
  const Epoch epoch = Epoch::Parse(options_.epoch);
  epoch_jd_tt_ = epoch.JulianDateTt();
  theta0_ = GmstRad(epoch.JulianDateUtc());  // UT1 ~ UTC
  if (options_.srp)
    srp_coefficient_ = geo::kSolarPressure * options_.reflectivity_cr * options_.area_to_mass_m2_kg;
  coefficients_.degree = (options_.j2 || options_.tesseral) ? options_.gravity_degree : 0;
  for (const NormalizedCoefficient& k : kEgm2008) {
    if (k.n > coefficients_.degree) continue;
    if (k.m == 0 && !options_.j2) continue;
    if (k.m > 0 && !options_.tesseral) continue;
    const double f = NormalizationFactor(k.n, k.m);
    coefficients_.c[k.n][k.m] = f * k.c;
    coefficients_.s[k.n][k.m] = f * k.s;
  }
}

double GeoForceModel::Theta(double t) const {
  double theta = std::fmod(theta0_ + geo::kEarthRotationRate * t, 2.0 * kPi);
  if (theta < 0.0) theta += 2.0 * kPi;
  return theta;
}

Vec3<double> GeoForceModel::SunAt(double t) const {
  const Eigen::Vector3d s = SunPositionMeanOfEpoch(epoch_jd_tt_ + t / kSecondsPerDay, epoch_jd_tt_);
  return {s.x(), s.y(), s.z()};
}

GeoForceModel::Bodies GeoForceModel::BodiesAt(double t) const {
  Bodies b;
  const double jd = epoch_jd_tt_ + t / kSecondsPerDay;
  if (options_.sun || srp_coefficient_ > 0.0) {
    const Eigen::Vector3d s = SunPositionMeanOfEpoch(jd, epoch_jd_tt_);
    b.sun = {s.x(), s.y(), s.z()};
  }
  if (options_.moon) {
    const Eigen::Vector3d m = MoonPositionMeanOfEpoch(jd, epoch_jd_tt_);
    b.moon = {m.x(), m.y(), m.z()};
  }
  return b;
}

}  // namespace thrustsched::dynamics::internal
