#include "transfer/replay.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "common/constants.h"
#include "common/format.h"
#include "dynamics/keplerian.h"
#include "transfer/internal/integrator.h"

namespace thrustsched::transfer {
namespace {

// The J2 acceleration from the gradient of the zonal potential
// U = -mu J2 R^2 / (2 r^3) (3 z^2 / r^2 - 1) (e.g. Vallado 2013 ch. 8), in
// the inertial frame whose z axis is the pole; any consistent units.
Eigen::Vector3d J2AccelerationCartesian(const Eigen::Vector3d& r, double mu, double j2,
                                        double radius) {
  const double rn = r.norm(), r2 = rn * rn;
  const double k = -1.5 * j2 * mu * radius * radius / (r2 * r2 * rn);
  const double z2 = 5 * r.z() * r.z() / r2;
  return k * Eigen::Vector3d(r.x() * (1 - z2), r.y() * (1 - z2), r.z() * (3 - z2));
}

}  // namespace

ReplayResult Replay(const MinTimeProblem& p, double duration_s, const QswCommand& command,
                    double tolerance) {
  std::string error;
  if (!p.IsValid(&error)) throw std::invalid_argument("replay: " + error);
  if (!(duration_s > 0)) {
    throw std::invalid_argument("replay: duration_s must be > 0, got " +
                                common::FormatG(duration_s, 10));
  }
  // Scaled Cartesian state: position in Mm, velocity in Mm/h, mass in kg.
  constexpr double kLength = 1e6, kTime = 3600.0, kSpeed = kLength / kTime;
  const double mu = p.mu * kTime * kTime / (kLength * kLength * kLength);
  const double thrust = p.thrust_n * kTime * kTime / kLength;  // kg Mm / h^2
  const double flow = p.thrust_n / (common::kStandardGravity_m_s2 * p.isp_s) * kTime;  // kg / h
  const bool j2 = p.force_model.kind == ForceModelKind::kJ2;
  const double j2_radius = p.force_model.radius_m / kLength;
  auto si_state = [&](const std::array<double, 7>& y) {
    dynamics::Vector6d rv;
    for (int i = 0; i < 3; ++i) rv(i) = y[i] * kLength, rv(3 + i) = y[3 + i] * kSpeed;
    return rv;
  };
  auto rhs = [&](const std::array<double, 7>& y, std::array<double, 7>& dy, double t) {
    const Eigen::Vector3d r(y[0], y[1], y[2]);
    const double rn = r.norm();
    const dynamics::Vector6d rv = si_state(y);
    const Eigen::Vector3d c = command(t * kTime, rv, y[6]);
    Eigen::Vector3d acc = -mu * r / (rn * rn * rn) + thrust / y[6] * (QswBasis(rv) * c);
    if (j2) acc += J2AccelerationCartesian(r, mu, p.force_model.j2, j2_radius);
    for (int i = 0; i < 3; ++i) dy[i] = y[3 + i], dy[3 + i] = acc(i);
    dy[6] = -flow * c.norm();
  };
  const dynamics::Vector6d rv0 = CartesianFromEquinoctial(p.initial, p.mu);
  std::array<double, 7> y{};
  for (int i = 0; i < 3; ++i) y[i] = rv0(i) / kLength, y[3 + i] = rv0(3 + i) / kSpeed;
  y[6] = p.mass_kg;
  ReplayResult r;
  internal::Integrate(rhs, y, 0.0, duration_s / kTime, tolerance, 0.25,
                      [&](double t, const std::array<double, 7>& x) {
                        r.states.push_back({t * kTime, si_state(x), x[6]});
                        return true;
                      });
  r.final_rv = si_state(y);
  r.final_mass_kg = y[6];
  const dynamics::KeplerianElements k =
      dynamics::KeplerianFromCartesian(r.final_rv, p.mu, dynamics::AnomalyKind::kTrue);
  r.final_a_m = k.a_m, r.final_e = k.e, r.final_i_rad = k.i_rad;
  return r;
}

QswCommand SampledCommand(const std::vector<TrajectorySample>& samples) {
  if (samples.size() < 2) throw std::invalid_argument("sampled command: needs 2 samples or more");
  auto data = std::make_shared<std::vector<TrajectorySample>>(samples);
  return [data](double t, const dynamics::Vector6d&, double) -> Eigen::Vector3d {
    const std::vector<TrajectorySample>& s = *data;
    const auto it = std::upper_bound(s.begin(), s.end(), t,
                                     [](double v, const TrajectorySample& x) { return v < x.t_s; });
    const std::size_t n = s.size();
    const std::size_t i1 = std::min<std::size_t>(
        n - 1, std::max<std::size_t>(1, static_cast<std::size_t>(it - s.begin())));
    const std::size_t i0 = i1 - 1;
    const double h = s[i1].t_s - s[i0].t_s, x = (t - s[i0].t_s) / h;
    // Catmull-Rom tangents (one-sided at the ends), in units of the interval.
    auto slope = [&](std::size_t i) -> Eigen::Vector3d {
      const std::size_t a = i == 0 ? 0 : i - 1, b = std::min(n - 1, i + 1);
      return (s[b].direction_qsw - s[a].direction_qsw) / (s[b].t_s - s[a].t_s) * h;
    };
    const double x2 = x * x, x3 = x2 * x;
    const Eigen::Vector3d v = (2 * x3 - 3 * x2 + 1) * s[i0].direction_qsw +
                              (x3 - 2 * x2 + x) * slope(i0) +
                              (-2 * x3 + 3 * x2) * s[i1].direction_qsw + (x3 - x2) * slope(i1);
    return v.normalized();
  };
}

ReplayResult ReplaySamples(const MinTimeProblem& p, const std::vector<TrajectorySample>& samples,
                           double duration_s, double tolerance) {
  return Replay(p, duration_s, SampledCommand(samples), tolerance);
}

}  // namespace thrustsched::transfer
