#include "dynamics/keplerian.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "common/constants.h"
#include "common/format.h"

namespace thrustsched::dynamics {

using common::FormatG;

namespace {

using common::kPi;
constexpr double kTwoPi = 2.0 * kPi;
// Below this tan(i/2) or e the node or the perigee is taken as undefined
// (round-off of a state converted from exactly equatorial or circular
// elements is ~1e-16; 1e-10 rad is 4 mm along a GEO orbit).
constexpr double kSingular = 1e-10;

void CheckEccentricity(double e, double angle, const char* where) {
  if (!std::isfinite(angle))
    throw std::invalid_argument(std::string(where) + ": anomaly must be finite");
  if (!(e >= 0.0 && e < 1.0)) {
    throw std::invalid_argument(std::string(where) + ": eccentricity must be in [0, 1), got " +
                                FormatG(e, 17));
  }
}

double Wrap2Pi(double angle) {
  double w = std::fmod(angle, kTwoPi);
  if (w < 0.0) w += kTwoPi;
  return w >= kTwoPi ? 0.0 : w;
}

}  // namespace

double MeanFromTrueAnomaly(double nu, double e) {
  CheckEccentricity(e, nu, "MeanFromTrueAnomaly");
  // Eccentric anomaly from tan(E/2) = sqrt((1-e)/(1+e)) tan(nu/2), in atan2
  // form so that E stays in the same half-turn as nu.
  const double ecc = 2.0 * std::atan2(std::sqrt(1.0 - e) * std::sin(nu / 2.0),
                                      std::sqrt(1.0 + e) * std::cos(nu / 2.0));
  return WrapPi(ecc - e * std::sin(ecc));
}

double TrueFromMeanAnomaly(double mean, double e) {
  CheckEccentricity(e, mean, "TrueFromMeanAnomaly");
  const double m = WrapPi(mean);
  // Newton from E = M, or from E = +-pi for very eccentric orbits (where E = M
  // can start the iteration on the wrong side of the root).
  double ecc = e < 0.8 ? m : (m >= 0.0 ? kPi : -kPi);
  for (int k = 0; k < 50; ++k) {
    const double step = (ecc - e * std::sin(ecc) - m) / (1.0 - e * std::cos(ecc));
    ecc -= step;
    if (std::abs(step) < 1e-15) break;
  }
  return WrapPi(2.0 * std::atan2(std::sqrt(1.0 + e) * std::sin(ecc / 2.0),
                                 std::sqrt(1.0 - e) * std::cos(ecc / 2.0)));
}

EquinoctialElements EquinoctialFromKeplerian(const KeplerianElements& k) {
  const double vals[6] = {k.a_m, k.e, k.i_rad, k.raan_rad, k.arg_perigee_rad, k.anomaly_rad};
  const char* names[6] = {"a_m", "e", "i_rad", "raan_rad", "arg_perigee_rad", "anomaly_rad"};
  for (int i = 0; i < 6; ++i) {
    if (!std::isfinite(vals[i])) {
      throw std::invalid_argument(std::string("EquinoctialFromKeplerian: ") + names[i] +
                                  " must be finite, got " + FormatG(vals[i], 17));
    }
  }
  if (!(k.a_m > 0.0)) {
    throw std::invalid_argument("EquinoctialFromKeplerian: a_m must be > 0, got " +
                                FormatG(k.a_m, 17));
  }
  if (!(k.e >= 0.0 && k.e < 1.0)) {
    throw std::invalid_argument("EquinoctialFromKeplerian: e must be in [0, 1), got " +
                                FormatG(k.e, 17));
  }
  if (!(k.i_rad >= 0.0 && k.i_rad < kPi)) {
    throw std::invalid_argument("EquinoctialFromKeplerian: i_rad must be in [0, pi), got " +
                                FormatG(k.i_rad, 17));
  }
  const double mean =
      k.anomaly == AnomalyKind::kMean ? k.anomaly_rad : MeanFromTrueAnomaly(k.anomaly_rad, k.e);
  const double lon_perigee = k.raan_rad + k.arg_perigee_rad;
  const double t = std::tan(k.i_rad / 2.0);
  EquinoctialElements el;
  el.a_m = k.a_m;
  el.ex = k.e * std::cos(lon_perigee);
  el.ey = k.e * std::sin(lon_perigee);
  el.ix = t * std::cos(k.raan_rad);
  el.iy = t * std::sin(k.raan_rad);
  el.mean_longitude_rad = WrapPi(lon_perigee + mean);
  return el;
}

KeplerianElements KeplerianFromEquinoctial(const EquinoctialElements& el, AnomalyKind anomaly) {
  const double vals[6] = {el.a_m, el.ex, el.ey, el.ix, el.iy, el.mean_longitude_rad};
  for (double v : vals) {
    if (!std::isfinite(v))
      throw std::invalid_argument("KeplerianFromEquinoctial: elements must be finite");
  }
  KeplerianElements k;
  k.a_m = el.a_m;
  k.e = std::hypot(el.ex, el.ey);
  if (!(k.e < 1.0))
    throw std::invalid_argument("KeplerianFromEquinoctial: e must be < 1, got " + FormatG(k.e, 17));
  const double t = std::hypot(el.ix, el.iy);
  k.i_rad = 2.0 * std::atan(t);
  k.raan_rad = t > kSingular ? Wrap2Pi(std::atan2(el.iy, el.ix)) : 0.0;
  const double lon_perigee = k.e > kSingular ? std::atan2(el.ey, el.ex) : k.raan_rad;
  k.arg_perigee_rad = Wrap2Pi(lon_perigee - k.raan_rad);
  const double mean = el.mean_longitude_rad - lon_perigee;
  k.anomaly = anomaly;
  k.anomaly_rad = Wrap2Pi(anomaly == AnomalyKind::kMean ? mean : TrueFromMeanAnomaly(mean, k.e));
  return k;
}

Vector6d CartesianFromKeplerian(const KeplerianElements& k, double mu) {
  return CartesianFromEquinoctial(EquinoctialFromKeplerian(k), mu);
}

KeplerianElements KeplerianFromCartesian(const Vector6d& rv, double mu, AnomalyKind anomaly) {
  return KeplerianFromEquinoctial(EquinoctialFromCartesian(rv, mu), anomaly);
}

}  // namespace thrustsched::dynamics
