#include "dynamics/propagation.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "dynamics/internal/adaptive_integrator.h"
#include "dynamics/internal/scaled_model.h"

namespace thrustsched::dynamics {
namespace {

constexpr const char* kWhere = "PropagateLinear";

struct SwitchEvent {
  double t;
  int column;
  int delta;  // +1 on, -1 off
};

}  // namespace

std::vector<Eigen::VectorXd> PropagateLinear(const LinearModel& model,
                                             const Eigen::MatrixXd& input_columns,
                                             const Eigen::VectorXd& x0, double t0,
                                             const std::vector<InputPulse>& pulses,
                                             const std::vector<double>& sample_times,
                                             double tolerance) {
  if (!std::isfinite(t0)) {
    std::ostringstream msg;
    msg << kWhere << ": t0 must be finite, got " << t0;
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(tolerance) || tolerance <= 0.0 || tolerance > 1e-3) {
    std::ostringstream msg;
    msg << kWhere << ": tolerance must be in (0, 1e-3], got " << tolerance;
    throw std::invalid_argument(msg.str());
  }
  internal::ScaledModel sm(model, input_columns, kWhere);
  const int n = sm.n(), m = sm.m();
  if (x0.size() != n) {
    throw std::invalid_argument(std::string(kWhere) + ": x0 has " + std::to_string(x0.size()) +
                                " entries, model '" + std::string(model.name()) + "' has " +
                                std::to_string(n) + " states");
  }
  if (!x0.allFinite()) throw std::invalid_argument(std::string(kWhere) + ": x0 is not finite");
  for (size_t k = 0; k < pulses.size(); ++k) {
    const InputPulse& p = pulses[k];
    std::ostringstream msg;
    if (p.column < 0 || p.column >= m) {
      msg << kWhere << ": pulses[" << k << "].column = " << p.column
          << " is not an input column (0.." << m - 1 << ")";
    } else if (!std::isfinite(p.start_s) || !std::isfinite(p.end_s)) {
      msg << kWhere << ": pulses[" << k << "] has non-finite times [" << p.start_s << ", "
          << p.end_s << ")";
    } else if (p.end_s < p.start_s) {
      msg << kWhere << ": pulses[" << k << "] ends before it starts: end_s = " << p.end_s
          << " < start_s = " << p.start_s;
    }
    if (!msg.str().empty()) throw std::invalid_argument(msg.str());
  }
  for (size_t k = 0; k < sample_times.size(); ++k) {
    const double s = sample_times[k];
    std::ostringstream msg;
    if (!std::isfinite(s)) {
      msg << kWhere << ": sample_times[" << k << "] is not finite (" << s << ")";
    } else if (s < t0) {
      msg << kWhere << ": sample_times[" << k << "] = " << s << " is before t0 = " << t0;
    } else if (k > 0 && s < sample_times[k - 1]) {
      msg << kWhere << ": sample_times must be non-decreasing, but sample_times[" << k
          << "] = " << s << " < sample_times[" << k - 1 << "] = " << sample_times[k - 1];
    }
    if (!msg.str().empty()) throw std::invalid_argument(msg.str());
  }

  std::vector<Eigen::VectorXd> out;
  out.reserve(sample_times.size());
  if (sample_times.empty()) return out;
  const double t_end = sample_times.back();

  // Switch events sorted by time; segment boundaries = t0, switches inside
  // (t0, t_end) and the sample times, so the input is constant per segment.
  std::vector<SwitchEvent> events;
  events.reserve(2 * pulses.size());
  std::vector<double> breaks;
  breaks.reserve(2 * pulses.size() + sample_times.size() + 1);
  breaks.push_back(t0);
  for (const InputPulse& p : pulses) {
    if (p.end_s <= p.start_s) continue;  // empty pulse
    events.push_back({p.start_s, p.column, +1});
    events.push_back({p.end_s, p.column, -1});
    if (p.start_s > t0 && p.start_s < t_end) breaks.push_back(p.start_s);
    if (p.end_s > t0 && p.end_s < t_end) breaks.push_back(p.end_s);
  }
  std::sort(events.begin(), events.end(),
            [](const SwitchEvent& a, const SwitchEvent& b) { return a.t < b.t; });
  breaks.insert(breaks.end(), sample_times.begin(), sample_times.end());
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  const Eigen::VectorXd& sc = sm.scale();
  const double T = sm.time_scale();
  std::vector<double> xi(n);
  Eigen::Map<Eigen::VectorXd>(xi.data(), n) = sm.inv_scale().cwiseProduct(x0);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(m + 1);  // [active count per column; 1]
  w[m] = 1.0;
  internal::AdaptiveIntegrator integ(tolerance, kWhere);

  size_t next_sample = 0, next_event = 0;
  auto emit_samples_at = [&](double t) {
    while (next_sample < sample_times.size() && sample_times[next_sample] == t) {
      out.emplace_back(sc.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(xi.data(), n)));
      ++next_sample;
    }
  };
  emit_samples_at(t0);
  for (size_t b = 0; b + 1 < breaks.size(); ++b) {
    const double ta = breaks[b], tb = breaks[b + 1];
    // Input on [ta, tb): every event at or before ta has happened.
    while (next_event < events.size() && events[next_event].t <= ta) {
      w[events[next_event].column] += events[next_event].delta;
      ++next_event;
    }
    const double s_end = (tb - ta) / T;
    const double s_snap = s_end * (1.0 - 1e-14);
    auto rhs = [&](const std::vector<double>& y, std::vector<double>& dy, double s) {
      const internal::ScaledModel::Frozen& f = sm.At((s >= s_snap) ? tb : ta + s * T);
      Eigen::Map<const Eigen::VectorXd> ym(y.data(), n);
      Eigen::Map<Eigen::VectorXd> dym(dy.data(), n);
      dym.noalias() = f.a * ym;
      dym.noalias() += f.e * w;
    };
    integ.Integrate(rhs, xi, s_end);
    emit_samples_at(tb);
  }
  return out;
}

}  // namespace thrustsched::dynamics

namespace thrustsched::dynamics {

LinearFlow PropagateFlow(const LinearModel& model, double t0,
                         const std::vector<double>& sample_times, double tolerance) {
  const int n = model.num_states();
  const Eigen::MatrixXd none = Eigen::MatrixXd::Zero(model.num_inputs(), 1);
  LinearFlow f;
  f.drift = PropagateLinear(model, none, Eigen::VectorXd::Zero(n), t0, {}, sample_times, tolerance);
  f.phi.assign(sample_times.size(), Eigen::MatrixXd(n, n));
  for (int c = 0; c < n; ++c) {
    const auto xs =
        PropagateLinear(model, none, Eigen::VectorXd::Unit(n, c), t0, {}, sample_times, tolerance);
    for (size_t i = 0; i < sample_times.size(); ++i) f.phi[i].col(c) = xs[i] - f.drift[i];
  }
  return f;
}

}  // namespace thrustsched::dynamics
