#include "dynamics/geo_simulator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

// Odeint copies its (deliberately uninitialised) std::array stage buffers when
// the controlled stepper is built; GCC flags that copy inside the Boost header.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint/algebra/array_algebra.hpp>
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#pragma GCC diagnostic pop

#include <Eigen/Geometry>

#include "common/format.h"
#include "dynamics/internal/geo_force_model.h"

namespace thrustsched::dynamics {

using common::FormatG;

namespace {

namespace odeint = boost::numeric::odeint;
using State = std::array<double, 6>;
using ErrorStepper =
    odeint::runge_kutta_fehlberg78<State, double, State, double, odeint::array_algebra>;
using Checker =
    odeint::default_error_checker<double, odeint::array_algebra, odeint::default_operations>;
using Controlled = odeint::controlled_runge_kutta<ErrorStepper, Checker>;

constexpr double kLength = geo::kStationRadius;                           // m
constexpr double kSpeed = geo::kStationRadius * geo::kEarthRotationRate;  // m/s
constexpr long kMaxStepsPerSegment = 10000000;
// Step cap (s). Without it the controller takes ~1.5 h steps at 1e-12.
constexpr double kMaxStep = 1800.0;
// Shadow boundaries are located as events: after each step the shadow
// function is checked at the end and at kShadowProbes interior points (cubic
// Hermite interpolation of the position), so eclipses longer than
// kMaxStep / (kShadowProbes + 1) = 6 min are never stepped over; the crossing
// is then bisected to kShadowTimeTolerance by re-integrating from the step start.
constexpr int kShadowProbes = 4;
constexpr double kShadowTimeTolerance = 1e-4;  // s

void CheckTime(double t, const char* where) {
  if (!std::isfinite(t))
    throw std::invalid_argument(std::string(where) + ": t must be finite, got " + FormatG(t, 17));
}

// Cowell right-hand side on the scaled state [r / L, v / V].
struct CowellRhs {
  const internal::GeoForceModel* forces;
  Eigen::Vector3d thrust_rtn;  // m/s^2
  bool thrusting;
  // SRP shadow state, frozen during a step (boundaries are events).
  internal::GeoForceModel::Shadow shadow = internal::GeoForceModel::Shadow::kSunlit;

  void operator()(const State& y, State& dy, double t) const {
    const internal::Vec3<double> r = {y[0] * kLength, y[1] * kLength, y[2] * kLength};
    const internal::Vec3<double> v = {y[3] * kSpeed, y[4] * kSpeed, y[5] * kSpeed};
    const double r2 = internal::Dot(r, r);
    const double k = -geo::kEarthMu / (r2 * std::sqrt(r2));
    const internal::Vec3<double> pert =
        forces->Acceleration(r, forces->Theta(t), forces->BodiesAt(t), shadow);
    Eigen::Vector3d acc(k * r[0] + pert[0], k * r[1] + pert[1], k * r[2] + pert[2]);
    if (thrusting) {
      const Eigen::Vector3d rv(r[0], r[1], r[2]), vv(v[0], v[1], v[2]);
      const Eigen::Vector3d ur = rv.normalized();
      const Eigen::Vector3d un = rv.cross(vv).normalized();
      const Eigen::Vector3d ut = un.cross(ur);
      acc += thrust_rtn.x() * ur + thrust_rtn.y() * ut + thrust_rtn.z() * un;
    }
    for (int i = 0; i < 3; ++i) {
      dy[i] = y[3 + i] * (kSpeed / kLength);
      dy[3 + i] = acc(i) / kSpeed;
    }
  }
};

double ShadowAt(const internal::GeoForceModel& forces, const State& y, double t) {
  return internal::ShadowFunction({y[0] * kLength, y[1] * kLength, y[2] * kLength}, forces.SunAt(t),
                                  geo::kEarthRadius);
}

// Cubic Hermite interpolation of the scaled position at fraction s of a step
// of h seconds (derivative of the scaled position = scaled velocity * V / L).
State HermitePosition(const State& y0, const State& y1, double h, double s) {
  const double h00 = (1.0 + 2.0 * s) * (1.0 - s) * (1.0 - s), h10 = s * (1.0 - s) * (1.0 - s);
  const double h01 = s * s * (3.0 - 2.0 * s), h11 = s * s * (s - 1.0);
  const double k = h * kSpeed / kLength;
  State p{};
  for (int i = 0; i < 3; ++i)
    p[i] = h00 * y0[i] + h10 * k * y0[3 + i] + h01 * y1[i] + h11 * k * y1[3 + i];
  return p;
}

struct PulseEvent {
  double time;
  int column;
  int delta;  // +1 on, -1 off
};

}  // namespace

GeoSimulator::GeoSimulator(const GeoModelOptions& options, double tolerance)
    : forces_(std::make_shared<const internal::GeoForceModel>(options)), tolerance_(tolerance) {
  if (!(tolerance >= 1e-14 && tolerance <= 1e-10)) {
    throw std::invalid_argument("GeoSimulator: tolerance must be in [1e-14, 1e-10], got " +
                                FormatG(tolerance, 17));
  }
}

const GeoModelOptions& GeoSimulator::options() const { return forces_->options(); }

double GeoSimulator::EarthRotationAngle(double t) const {
  CheckTime(t, "GeoSimulator::EarthRotationAngle");
  return forces_->Theta(t);
}

Vector6d GeoSimulator::EciFromRelative(const Eigen::VectorXd& x_rel, double t) const {
  CheckTime(t, "GeoSimulator::EciFromRelative");
  if (x_rel.size() != 6) {
    throw std::invalid_argument(
        "GeoSimulator::EciFromRelative: x_rel must have 6 components, got " +
        std::to_string(x_rel.size()));
  }
  if (!x_rel.allFinite())
    throw std::invalid_argument("GeoSimulator::EciFromRelative: x_rel must be finite");
  EquinoctialElements el;
  el.a_m = geo::kStationRadius + x_rel(0);
  el.ex = x_rel(1);
  el.ey = x_rel(2);
  el.ix = x_rel(3);
  el.iy = x_rel(4);
  el.mean_longitude_rad = forces_->station_longitude_rad() + forces_->Theta(t) + x_rel(5);
  try {
    return CartesianFromEquinoctial(el, geo::kEarthMu);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("GeoSimulator::EciFromRelative: ") + e.what());
  }
}

Eigen::VectorXd GeoSimulator::RelativeFromEci(const Vector6d& eci, double t) const {
  CheckTime(t, "GeoSimulator::RelativeFromEci");
  EquinoctialElements el;
  try {
    el = EquinoctialFromCartesian(eci, geo::kEarthMu);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("GeoSimulator::RelativeFromEci: ") + e.what());
  }
  Eigen::VectorXd x(6);
  x << el.a_m - geo::kStationRadius, el.ex, el.ey, el.ix, el.iy,
      WrapPi(el.mean_longitude_rad - forces_->Theta(t) - forces_->station_longitude_rad());
  return x;
}

GeoPoint GeoSimulator::Geographic(const Vector6d& eci, double t) const {
  CheckTime(t, "GeoSimulator::Geographic");
  if (!eci.allFinite())
    throw std::invalid_argument("GeoSimulator::Geographic: eci state must be finite");
  const double r = eci.head<3>().norm();
  if (!(r > 0.0)) throw std::invalid_argument("GeoSimulator::Geographic: position is zero");
  GeoPoint p;
  p.r_m = r;
  p.lat_rad = std::asin(std::clamp(eci(2) / r, -1.0, 1.0));
  p.lon_rad = WrapPi(std::atan2(eci(1), eci(0)) - forces_->Theta(t));
  return p;
}

Eigen::Vector3d GeoSimulator::RelativeOutputs(const Vector6d& eci, double t) const {
  const GeoPoint p = Geographic(eci, t);
  return Eigen::Vector3d(p.r_m - geo::kStationRadius, p.lat_rad,
                         WrapPi(p.lon_rad - forces_->station_longitude_rad()));
}

Eigen::Vector3d GeoSimulator::PerturbingAcceleration(const Eigen::Vector3d& r_eci, double t) const {
  CheckTime(t, "GeoSimulator::PerturbingAcceleration");
  if (!r_eci.allFinite())
    throw std::invalid_argument("GeoSimulator::PerturbingAcceleration: r must be finite");
  const internal::Vec3<double> r = {r_eci.x(), r_eci.y(), r_eci.z()};
  const internal::Vec3<double> a =
      forces_->Acceleration(r, forces_->Theta(t), forces_->BodiesAt(t));
  return Eigen::Vector3d(a[0], a[1], a[2]);
}

std::vector<Vector6d> GeoSimulator::Propagate(const Vector6d& eci0, double t0,
                                              const Eigen::MatrixXd& accel_rtn,
                                              const std::vector<InputPulse>& pulses,
                                              const std::vector<double>& sample_times) const {
  // ---- validation ----
  if (!eci0.allFinite())
    throw std::invalid_argument("GeoSimulator::Propagate: eci0 must be finite");
  CheckTime(t0, "GeoSimulator::Propagate (t0)");
  if (accel_rtn.rows() != 3) {
    throw std::invalid_argument(
        "GeoSimulator::Propagate: accel_rtn must have 3 rows (R, T, N), got " +
        std::to_string(accel_rtn.rows()));
  }
  if (!accel_rtn.allFinite())
    throw std::invalid_argument("GeoSimulator::Propagate: accel_rtn must be finite");
  for (std::size_t k = 0; k < pulses.size(); ++k) {
    const InputPulse& p = pulses[k];
    const std::string id = "GeoSimulator::Propagate: pulse " + std::to_string(k);
    if (p.column < 0 || p.column >= accel_rtn.cols()) {
      throw std::invalid_argument(id + ": column " + std::to_string(p.column) + " outside [0, " +
                                  std::to_string(accel_rtn.cols()) + ")");
    }
    if (!std::isfinite(p.start_s) || !std::isfinite(p.end_s)) {
      throw std::invalid_argument(id + ": start_s and end_s must be finite, got " +
                                  FormatG(p.start_s, 17) + ", " + FormatG(p.end_s, 17));
    }
    if (p.end_s < p.start_s) {
      throw std::invalid_argument(id + ": end_s " + FormatG(p.end_s, 17) + " < start_s " +
                                  FormatG(p.start_s, 17));
    }
  }
  for (std::size_t k = 0; k < sample_times.size(); ++k) {
    const double s = sample_times[k];
    if (!std::isfinite(s)) {
      throw std::invalid_argument("GeoSimulator::Propagate: sample_times[" + std::to_string(k) +
                                  "] must be finite, got " + FormatG(s, 17));
    }
    if (s < t0) {
      throw std::invalid_argument("GeoSimulator::Propagate: sample_times[" + std::to_string(k) +
                                  "] = " + FormatG(s, 17) + " is before t0 = " + FormatG(t0, 17));
    }
    if (k > 0 && s < sample_times[k - 1]) {
      throw std::invalid_argument(
          "GeoSimulator::Propagate: sample_times must be non-decreasing (index " +
          std::to_string(k) + ")");
    }
  }
  std::vector<Vector6d> out;
  if (sample_times.empty()) return out;
  out.reserve(sample_times.size());
  const double t_end = sample_times.back();

  // ---- switch events and stop times ----
  std::vector<PulseEvent> events;
  for (const InputPulse& p : pulses) {
    const double start = std::max(p.start_s, t0);
    if (!(p.end_s > start) || start >= t_end) continue;
    events.push_back({start, p.column, +1});
    if (p.end_s < t_end) events.push_back({p.end_s, p.column, -1});
  }
  std::sort(events.begin(), events.end(),
            [](const PulseEvent& a, const PulseEvent& b) { return a.time < b.time; });
  std::vector<double> stops;
  stops.reserve(events.size() + sample_times.size() + 1);
  stops.push_back(t0);
  for (const PulseEvent& e : events) stops.push_back(e.time);
  stops.insert(stops.end(), sample_times.begin(), sample_times.end());
  std::sort(stops.begin(), stops.end());
  stops.erase(std::unique(stops.begin(), stops.end()), stops.end());

  // ---- integration ----
  State y;
  for (int i = 0; i < 3; ++i) {
    y[i] = eci0(i) / kLength;
    y[3 + i] = eci0(3 + i) / kSpeed;
  }
  Controlled stepper(Checker(tolerance_, tolerance_));
  CowellRhs rhs{forces_.get(), Eigen::Vector3d::Zero(), false};
  std::vector<int> active(static_cast<std::size_t>(accel_rtn.cols()), 0);
  std::size_t next_event = 0, next_sample = 0;
  double dt = 60.0;  // s, first trial step; then the controller's suggestion carries over
  const auto record = [&](double t) {
    while (next_sample < sample_times.size() && sample_times[next_sample] == t) {
      Vector6d s;
      for (int i = 0; i < 3; ++i) {
        s(i) = y[i] * kLength;
        s(3 + i) = y[3 + i] * kSpeed;
      }
      out.push_back(s);
      ++next_sample;
    }
  };
  for (std::size_t k = 0; k < stops.size(); ++k) {
    const double t_a = stops[k];
    while (next_event < events.size() && events[next_event].time <= t_a) {
      active[static_cast<std::size_t>(events[next_event].column)] += events[next_event].delta;
      ++next_event;
    }
    record(t_a);
    if (k + 1 >= stops.size()) break;
    const double t_b = stops[k + 1];
    rhs.thrust_rtn.setZero();
    rhs.thrusting = false;
    for (std::size_t c = 0; c < active.size(); ++c) {
      if (active[c] > 0) {
        rhs.thrust_rtn +=
            static_cast<double>(active[c]) * accel_rtn.col(static_cast<Eigen::Index>(c));
        rhs.thrusting = true;
      }
    }
    using Shadow = internal::GeoForceModel::Shadow;
    const bool srp = forces_->has_srp();
    double t = t_a;
    long steps = 0;
    while (t < t_b) {
      if (++steps > kMaxStepsPerSegment || !(dt > 1e-6)) {
        throw std::runtime_error("GeoSimulator::Propagate: step-size control failed near t = " +
                                 FormatG(t, 17));
      }
      if (srp) {  // resynchronise the frozen shadow state (guards against a missed grazing
                  // crossing)
        const bool sunlit_now = ShadowAt(*forces_, y, t) >= 0.0;
        if (sunlit_now != (rhs.shadow == Shadow::kSunlit))
          rhs.shadow = sunlit_now ? Shadow::kSunlit : Shadow::kShadow;
      }
      dt = std::min(dt, kMaxStep);
      const bool last = dt >= t_b - t;
      double h = last ? t_b - t : dt;
      const State y0 = y;
      const double t_start = t;
      if (stepper.try_step(rhs, y, t, h) != odeint::success) {
        dt = h;  // smaller trial step; y and t are unchanged
        t = t_start;
        continue;
      }
      const double t_stop = last ? t_b : t;  // land exactly on the stop time
      dt = last ? std::max(dt, h) : h;
      t = t_stop;
      if (srp) {
        // Shadow event: probe the interior and the end of the step.
        const bool sunlit = rhs.shadow == Shadow::kSunlit;
        const double step = t_stop - t_start;
        double s_lo = 0.0, s_hi = -1.0;
        for (int p = 1; p <= kShadowProbes + 1 && s_hi < 0.0; ++p) {
          const double s = static_cast<double>(p) / (kShadowProbes + 1);
          const State yp = p == kShadowProbes + 1 ? y : HermitePosition(y0, y, step, s);
          if ((ShadowAt(*forces_, yp, t_start + s * step) >= 0.0) != sunlit) {
            s_hi = s;
          } else {
            s_lo = s;
          }
        }
        if (s_hi > 0.0) {
          double lo = s_lo * step, hi = s_hi * step;
          State y_hi = y;
          bool have_hi = s_hi == 1.0;
          if (!have_hi) stepper.stepper().do_step(rhs, y0, t_start, y_hi, hi);
          while (hi - lo > kShadowTimeTolerance) {
            const double mid = 0.5 * (lo + hi);
            State ym;
            stepper.stepper().do_step(rhs, y0, t_start, ym, mid);
            if ((ShadowAt(*forces_, ym, t_start + mid) >= 0.0) != sunlit) {
              hi = mid;
              y_hi = ym;
            } else {
              lo = mid;
            }
          }
          // If the interpolated probe misled us (no crossing up to hi), keep
          // the whole step; otherwise restart just past the boundary.
          if ((ShadowAt(*forces_, y_hi, t_start + hi) >= 0.0) != sunlit) {
            if (t_start + hi < t_stop) {
              y = y_hi;
              t = t_start + hi;
            }
            rhs.shadow = sunlit ? Shadow::kShadow : Shadow::kSunlit;
          }
        }
      }
      const double r2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
      if (!(r2 * kLength * kLength > geo::kEarthRadius * geo::kEarthRadius)) {
        throw std::runtime_error("GeoSimulator::Propagate: the orbit intersects the Earth at t = " +
                                 FormatG(t, 17));
      }
    }
  }
  return out;
}

}  // namespace thrustsched::dynamics
