// Independent schedule checker (see checker.h). Written from the
// continuous-time rule statements of operations.h only; it deliberately
// shares no code with the MILP builder (schedule_milp.*, encodings.*).
//
// Conventions of the rule check (all comparisons use kTimeTolerance = tol):
//  - A burn is malformed (rule "malformed") if a time is not finite, its
//    thruster index is unknown or end <= start; it is outside the horizon
//    (rule "horizon") if start < t0 - tol or end > tf + tol. Malformed and
//    outside burns are reported and take no further part in the rule check
//    (the linear re-propagation still fires the in-horizon part of an
//    outside burn, see CheckSchedule).
//  - Burns of one thruster that touch (|next.start - end| <= tol) are one
//    burn and are merged first; burns that overlap by more than tol are
//    reported ("overlap") and merged as their union.
//  - History: a thruster on at t0 for h s whose first merged burn starts at
//    t0 (within tol) is continuing that burn: its true start is t0 - h (used
//    by min_burn and max_burn), it is not a "start" for min_off_same,
//    min_gap_other and max_burns. If no burn starts at t0 the thruster
//    switched off at t0: that is legal, but the finished burn [t0 - h, t0)
//    must satisfy min_burn (it could have been continued), and t0 is its
//    switch-off time for the gap rules. A thruster off at t0 with off_for g
//    switched off at t0 - g. A burn lying wholly before t0 is data: its
//    duration is not judged against max_burn.
//  - The gap rules judge a pair (end e, start s) only when s is a decision
//    of this horizon (s >= t0); s >= e - tol counts as "after" e (a start
//    strictly while the other thruster is on is rule (1)'s business).
//  - Rule (1) splits time at every burn boundary and counts the burns
//    covering each elementary segment longer than tol.
#include "transcription/checker.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/constants.h"
#include "common/error.h"
#include "common/format.h"
#include "dynamics/geo_model.h"
#include "dynamics/geo_simulator.h"
#include "dynamics/models.h"
#include "dynamics/propagation.h"

namespace thrustsched::transcription {

using common::FormatG;

namespace {

constexpr double kTol = kTimeTolerance;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Interval {
  double start;
  double end;
};

void Add(std::vector<RuleViolation>* out, const char* rule, int thruster, double time_s,
         std::string message) {
  out->push_back(RuleViolation{rule, thruster, time_s, std::move(message)});
}

/// Sorts and unites intervals that overlap or touch (within tol).
std::vector<Interval> Union(std::vector<Interval> v) {
  std::sort(v.begin(), v.end(), [](const Interval& a, const Interval& b) {
    return std::tie(a.start, a.end) < std::tie(b.start, b.end);
  });
  std::vector<Interval> out;
  for (const Interval& b : v) {
    if (!out.empty() && b.start <= out.back().end + kTol) {
      out.back().end = std::max(out.back().end, b.end);
    } else {
      out.push_back(b);
    }
  }
  return out;
}

void ValidateRuleInputs(const OperationalRules& rules, const BoundaryHistory& history,
                        const std::vector<ForcedOff>& forced_off, int num_thrusters, double t0,
                        double tf) {
  const std::string where = "CheckOperationalRules: ";
  if (num_thrusters < 0) {
    throw std::invalid_argument(where + "num_thrusters must be >= 0, got " +
                                std::to_string(num_thrusters));
  }
  if (!std::isfinite(t0) || !std::isfinite(tf) || !(tf > t0)) {
    throw std::invalid_argument(where + "horizon [t0, tf] must be finite with tf > t0, got [" +
                                FormatG(t0, 10) + ", " + FormatG(tf, 10) + "]");
  }
  std::string err;
  if (!rules.IsValid(&err)) throw std::invalid_argument(where + "rules: " + err);
  if (!history.IsValid(num_thrusters, &err)) {
    throw std::invalid_argument(where + "history: " + err);
  }
  for (std::size_t k = 0; k < forced_off.size(); ++k) {
    const ForcedOff& w = forced_off[k];
    const std::string name = "forced_off[" + std::to_string(k) + "]";
    if (w.thruster < 0 || w.thruster >= num_thrusters) {
      throw std::invalid_argument(where + name + ".thruster must be in [0, " +
                                  std::to_string(num_thrusters) + "), got " +
                                  std::to_string(w.thruster));
    }
    if (std::isnan(w.start_s) || std::isnan(w.end_s) || w.end_s < w.start_s) {
      throw std::invalid_argument(where + name + " must have start_s <= end_s (not NaN), got [" +
                                  FormatG(w.start_s, 10) + ", " + FormatG(w.end_s, 10) + ")");
    }
  }
}

/// The rule check proper; `names` label thrusters in messages.
std::vector<RuleViolation> CheckRules(const OperationalRules& rules, const BoundaryHistory& history,
                                      const std::vector<ForcedOff>& forced_off, int num_thrusters,
                                      double t0, double tf, const std::vector<Burn>& burns,
                                      const std::vector<std::string>& names) {
  ValidateRuleInputs(rules, history, forced_off, num_thrusters, t0, tf);
  std::vector<RuleViolation> out;
  auto name = [&](int i) { return names[static_cast<std::size_t>(i)]; };
  auto span = [](double a, double b) { return "[" + FormatG(a, 10) + ", " + FormatG(b, 10) + ")"; };

  // 1. Well-formedness and horizon; keep the good burns per thruster.
  std::vector<std::vector<Interval>> raw(static_cast<std::size_t>(num_thrusters));
  for (std::size_t k = 0; k < burns.size(); ++k) {
    const Burn& b = burns[k];
    const std::string id = "burn #" + std::to_string(k);
    if (!std::isfinite(b.start_s) || !std::isfinite(b.end_s)) {
      Add(&out, "malformed", -1, std::isfinite(b.start_s) ? b.start_s : t0,
          id + " has a non-finite time " + span(b.start_s, b.end_s));
    } else if (b.thruster < 0 || b.thruster >= num_thrusters) {
      Add(&out, "malformed", -1, b.start_s,
          id + " names unknown thruster " + std::to_string(b.thruster) + " (have " +
              std::to_string(num_thrusters) + ")");
    } else if (b.end_s <= b.start_s) {
      Add(&out, "malformed", b.thruster, b.start_s,
          id + " of " + name(b.thruster) + " has end <= start: " + span(b.start_s, b.end_s));
    } else if (b.start_s < t0 - kTol || b.end_s > tf + kTol) {
      Add(&out, "horizon", b.thruster, b.start_s,
          name(b.thruster) + " burn " + span(b.start_s, b.end_s) + " is outside the horizon [" +
              FormatG(t0, 10) + ", " + FormatG(tf, 10) + "]");
    } else {
      // Snap to the horizon (moves a time by at most tol).
      raw[static_cast<std::size_t>(b.thruster)].push_back(
          {std::max(b.start_s, t0), std::min(b.end_s, tf)});
    }
  }

  // 2. Merge touching burns, report overlapping ones.
  std::vector<std::vector<Interval>> merged(raw.size());
  for (int i = 0; i < num_thrusters; ++i) {
    std::vector<Interval>& v = raw[static_cast<std::size_t>(i)];
    std::sort(v.begin(), v.end(), [](const Interval& a, const Interval& b) {
      return std::tie(a.start, a.end) < std::tie(b.start, b.end);
    });
    std::vector<Interval>& m = merged[static_cast<std::size_t>(i)];
    for (const Interval& b : v) {
      if (!m.empty() && b.start < m.back().end - kTol) {
        Add(&out, "overlap", i, b.start,
            name(i) + " burns " + span(m.back().start, m.back().end) + " and " +
                span(b.start, b.end) + " overlap");
      }
      if (!m.empty() && b.start <= m.back().end + kTol) {
        m.back().end = std::max(m.back().end, b.end);
      } else {
        m.push_back(b);
      }
    }
  }

  // 3. Per-thruster rules: history, (2), (3), (4), (6), (7). Also collect the
  //    switch-off times and the decided starts for rule (5).
  std::vector<std::vector<double>> ends(merged.size());    // incl. before t0
  std::vector<std::vector<double>> starts(merged.size());  // decided in this horizon
  for (int i = 0; i < num_thrusters; ++i) {
    const std::vector<Interval>& m = merged[static_cast<std::size_t>(i)];
    const bool on = history.is_on(i);
    const double h = history.on_for(i);
    const bool continuation = on && !m.empty() && m.front().start <= t0 + kTol;
    double prev_end = -kInf;  // last switch-off before the next burn; -inf = none
    if (on && !continuation) {
      if (h < rules.min_burn_s - kTol) {
        Add(&out, "min_burn", i, t0,
            name(i) + " on for " + FormatG(h, 10) + " s before t0 = " + FormatG(t0, 10) +
                " (history) and off from t0: burn lasts " + FormatG(h, 10) + " s < min_burn " +
                FormatG(rules.min_burn_s, 10) + " s");
      }
      prev_end = t0;
    } else if (!on) {
      prev_end = t0 - history.off_for(i);  // -inf when never fired
    }
    if (prev_end > -kInf) ends[static_cast<std::size_t>(i)].push_back(prev_end);

    int counted = 0;
    for (std::size_t k = 0; k < m.size(); ++k) {
      const Interval& b = m[k];
      const bool is_cont = continuation && k == 0;
      const double true_start = is_cont ? t0 - h : b.start;
      const double duration = b.end - true_start;
      const std::string what =
          name(i) + " burn at " + FormatG(b.start, 10) + " s" +
          (is_cont ? " (on since " + FormatG(true_start, 10) + " s per history)" : std::string());
      const bool across_end = rules.allow_burn_across_end && b.end >= tf - kTol;
      if (duration < rules.min_burn_s - kTol && !across_end) {
        Add(&out, "min_burn", i, b.start,
            what + " lasts " + FormatG(duration, 10) + " s < min_burn " +
                FormatG(rules.min_burn_s, 10) + " s");
      }
      if (duration > rules.max_burn_s + kTol) {
        Add(&out, "max_burn", i, b.start,
            what + " lasts " + FormatG(duration, 10) + " s > max_burn " +
                FormatG(rules.max_burn_s, 10) + " s");
      }
      if (!is_cont) {
        if (prev_end > -kInf && b.start - prev_end < rules.min_off_same_s - kTol) {
          Add(&out, "min_off_same", i, b.start,
              what + " starts " + FormatG(b.start - prev_end, 10) + " s after its switch-off at " +
                  FormatG(prev_end, 10) + " s < min_off_same " + FormatG(rules.min_off_same_s, 10) +
                  " s");
        }
        starts[static_cast<std::size_t>(i)].push_back(b.start);
        ++counted;
        if (rules.max_burns_per_thruster >= 0 && counted == rules.max_burns_per_thruster + 1) {
          int total = 0;
          for (std::size_t q = 0; q < m.size(); ++q) total += (continuation && q == 0) ? 0 : 1;
          Add(&out, "max_burns", i, b.start,
              name(i) + " starts " + std::to_string(total) +
                  " burns in the horizon > max_burns_per_thruster " +
                  std::to_string(rules.max_burns_per_thruster) + " (first excess at " +
                  FormatG(b.start, 10) + " s)");
        }
      }
      prev_end = b.end;
      ends[static_cast<std::size_t>(i)].push_back(b.end);
      for (const ForcedOff& w : forced_off) {
        if (w.thruster != i) continue;
        const double overlap = std::min(b.end, w.end_s) - std::max(b.start, w.start_s);
        if (overlap > kTol) {
          Add(&out, "forced_off", i, std::max(b.start, w.start_s),
              what + " " + span(b.start, b.end) + " overlaps forced-off window " +
                  span(w.start_s, w.end_s) + " by " + FormatG(overlap, 10) + " s");
        }
      }
    }
  }

  // 4. Rule (5): a decided start s of thruster l after a switch-off e of
  //    another thruster i.
  for (int l = 0; l < num_thrusters; ++l) {
    for (double s : starts[static_cast<std::size_t>(l)]) {
      for (int i = 0; i < num_thrusters; ++i) {
        if (i == l) continue;
        for (double e : ends[static_cast<std::size_t>(i)]) {
          if (s >= e - kTol && s - e < rules.min_gap_other_s - kTol) {
            Add(&out, "min_gap_other", l, s,
                name(l) + " burn starts at " + FormatG(s, 10) + " s, " + FormatG(s - e, 10) +
                    " s after " + name(i) + " switched off at " + FormatG(e, 10) +
                    " s < min_gap_other " + FormatG(rules.min_gap_other_s, 10) + " s");
          }
        }
      }
    }
  }

  // 5. Rule (1): count burns on each elementary segment between boundaries.
  std::vector<double> cuts;
  for (const auto& m : merged) {
    for (const Interval& b : m) {
      cuts.push_back(b.start);
      cuts.push_back(b.end);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  double run_start = 0.0, run_end = -kInf;
  int run_max = 0;
  auto flush = [&]() {
    if (run_max > 0) {
      Add(&out, "max_simultaneous", -1, run_start,
          std::to_string(run_max) + " thrusters on at once on " + span(run_start, run_end) +
              " > max_simultaneous " + std::to_string(rules.max_simultaneous));
    }
    run_max = 0;
  };
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = cuts[k], b = cuts[k + 1];
    if (b - a <= kTol) continue;
    const double mid = 0.5 * (a + b);
    int count = 0;
    for (const auto& m : merged) {
      for (const Interval& x : m) count += (x.start < mid && mid < x.end) ? 1 : 0;
    }
    if (count > rules.max_simultaneous) {
      if (run_max > 0 && a > run_end + kTol) flush();
      if (run_max == 0) run_start = a;
      run_end = b;
      run_max = std::max(run_max, count);
    } else {
      flush();
    }
  }
  flush();

  std::sort(out.begin(), out.end(), [](const RuleViolation& a, const RuleViolation& b) {
    return std::tie(a.time_s, a.thruster, a.rule, a.message) <
           std::tie(b.time_s, b.thruster, b.rule, b.message);
  });
  return out;
}

std::vector<double> SampleTimes(const std::vector<double>& grid, int per_interval,
                                std::vector<bool>* is_node) {
  std::vector<double> t;
  is_node->clear();
  for (std::size_t j = 0; j + 1 < grid.size(); ++j) {
    t.push_back(grid[j]);
    is_node->push_back(true);
    const double h = grid[j + 1] - grid[j];
    for (int k = 1; k <= per_interval; ++k) {
      t.push_back(grid[j] + h * k / (per_interval + 1));
      is_node->push_back(false);
    }
  }
  t.push_back(grid.back());
  is_node->push_back(true);
  return t;
}

using common::kRadToDeg;

// End-of-horizon station-keeping sets, judged on the exact (round) sets that
// the MILP's inscribed polygons approximate from inside (terminal_sets.h), in
// HCW coordinates zeta = (x, y, z, xdot, ydot, zdot) computed here from the
// model's own outputs: HCW outputs are (x, y, z); GEO outputs are (dr, lat,
// lon) and x = dr, y = rho lon, z = rho lat with rho the station radius.
// Returns max(0, worst excess / half width) over the disk
//   sqrt(z^2 + (zdot/n)^2) <= eps_z
// and, at every look-ahead time t, the two cones
//   |(2 xdot/n, 6 x + 4 ydot/n)| <= eps_y -+ ((6 n x + 3 ydot) t - y + 2 xdot/n)
// (the drifting free-motion ellipse fits the window at t), with eps the
// window half widths shrunk by the window and terminal margins.
double StationKeepingExcess(const ScheduleProblem& problem, const Eigen::VectorXd& xf) {
  const dynamics::LinearModel& model = *problem.model;
  const double tf = problem.grid.back();
  const dynamics::OutputMatrices out = model.EvaluateOutput(tf);
  const dynamics::ModelMatrices mm = model.Evaluate(tf);
  const Eigen::VectorXd y = out.c * xf;
  const Eigen::VectorXd ydot = out.c_dot * xf + out.c * (mm.a * xf + mm.d);  // thrust off
  Eigen::Matrix<double, 6, 1> zeta;
  double n = 0.0, rho = 1.0;
  int along = 1, normal = 2;  // window outputs of the along-track and normal positions
  if (const auto* hcw = dynamic_cast<const dynamics::HcwModel*>(&model)) {
    n = hcw->mean_motion();
    zeta << y(0), y(1), y(2), ydot(0), ydot(1), ydot(2);
  } else if (const auto* geo = dynamic_cast<const dynamics::GeoLinearModel*>(&model)) {
    rho = geo->station_radius_m();
    n = geo->mean_motion();
    zeta << y(0), rho * y(2), rho * y(1), ydot(0), rho * ydot(2), rho * ydot(1);
    along = 2;
    normal = 1;
  } else {
    throw std::invalid_argument(
        "CheckSchedule: station-keeping sets need an HCW or GEO model, got " +
        std::string(model.name()));
  }
  double eps_y = 0.0, eps_z = 0.0;
  const WindowSpec& w = problem.window;
  for (std::size_t k = 0; k < w.outputs.size(); ++k) {
    if (w.outputs[k] == along) eps_y = rho * w.half_widths[k];
    if (w.outputs[k] == normal) eps_z = rho * w.half_widths[k];
  }
  const double shrink = (1.0 - w.margin) * (1.0 - problem.terminal.margin);
  eps_y *= shrink;
  eps_z *= shrink;
  double excess = std::hypot(zeta(2), zeta(5) / n) / eps_z - 1.0;
  const double amp = std::hypot(2.0 * zeta(3) / n, 6.0 * zeta(0) + 4.0 * zeta(4) / n);
  std::vector<double> lookahead = problem.terminal.lookahead_s;
  if (lookahead.empty()) lookahead = {0.0, problem.horizon_s()};
  for (double t : lookahead) {
    const double drift = (6.0 * n * zeta(0) + 3.0 * zeta(4)) * t - zeta(1) + 2.0 * zeta(3) / n;
    excess = std::max(excess, (amp - (eps_y + drift)) / eps_y);
    excess = std::max(excess, (amp - (eps_y - drift)) / eps_y);
  }
  return std::max(0.0, excess);
}

/// Nonlinear replay of a GEO schedule (fills the nonlinear_* fields of r,
/// whose sample_times are already set). Window outputs 1 (lat) and 2 (lon)
/// are angles and are judged in degrees; a window on output 0 (radius, m)
/// has no degree counterpart and is not judged here (the linear check
/// covers it).
void ReplayNonlinear(const ScheduleProblem& problem, const dynamics::GeoSimulator& sim,
                     const std::vector<dynamics::InputPulse>& pulses, CheckReport* r) {
  const auto* geo = dynamic_cast<const dynamics::GeoLinearModel*>(problem.model.get());
  if (geo == nullptr) {
    throw std::invalid_argument(
        "CheckSchedule: options.nonlinear needs a problem on dynamics::GeoLinearModel, got "
        "model '" +
        std::string(problem.model->name()) + "'");
  }
  if (geo->options().station_longitude_deg != sim.options().station_longitude_deg ||
      geo->options().epoch != sim.options().epoch) {
    throw std::invalid_argument(
        "CheckSchedule: options.nonlinear simulates station " +
        FormatG(sim.options().station_longitude_deg, 10) + " deg at epoch " + sim.options().epoch +
        ", the problem's model station " + FormatG(geo->options().station_longitude_deg, 10) +
        " deg at epoch " + geo->options().epoch);
  }
  const double t0 = problem.grid.front();
  const dynamics::Vector6d eci0 = sim.EciFromRelative(problem.initial_state, t0);
  r->nonlinear_eci =
      sim.Propagate(eci0, t0, problem.thrusters.AccelerationMatrix(), pulses, r->sample_times);
  const WindowSpec& w = problem.window;
  r->max_window_violation_nonlinear_deg = 0.0;
  r->max_abs_lat_deg = 0.0;
  r->max_abs_lon_deg = 0.0;
  r->time_outside_window_nonlinear_s = 0.0;
  bool prev_outside = false;
  for (std::size_t k = 0; k < r->sample_times.size(); ++k) {
    const double t = r->sample_times[k];
    const Eigen::Vector3d y = sim.RelativeOutputs(r->nonlinear_eci[k], t);
    r->nonlinear_outputs.push_back(y);
    r->max_abs_lat_deg = std::max(r->max_abs_lat_deg, std::abs(y(1)) * kRadToDeg);
    r->max_abs_lon_deg = std::max(r->max_abs_lon_deg, std::abs(y(2)) * kRadToDeg);
    bool outside = false;
    if (k > 0 && t >= w.enforce_from_s - kTol) {
      for (std::size_t q = 0; q < w.outputs.size(); ++q) {
        if (w.outputs[q] != 1 && w.outputs[q] != 2) continue;
        const double excess_deg = (std::abs(y(w.outputs[q])) - w.half_widths[q]) * kRadToDeg;
        outside = outside || excess_deg > 0.0;
        if (excess_deg > r->max_window_violation_nonlinear_deg) {
          r->max_window_violation_nonlinear_deg = excess_deg;
          r->worst_time_nonlinear_s = t;
        }
      }
    }
    // Trapezoid rule on the outside indicator: a spacing counts fully when
    // both ends are outside, half when one is.
    if (k > 0) {
      r->time_outside_window_nonlinear_s +=
          0.5 * (t - r->sample_times[k - 1]) * ((prev_outside ? 1 : 0) + (outside ? 1 : 0));
    }
    prev_outside = outside;
  }
  r->nonlinear_checked = true;
}

// The path constraints on their own propagation to their times (the samples
// need not contain them).
void CheckStateConstraints(const ScheduleProblem& problem,
                           const std::vector<dynamics::InputPulse>& pulses, double tolerance,
                           CheckReport* r) {
  const std::vector<StateConstraint>& cs = problem.state_constraints;
  if (cs.empty()) return;
  std::vector<int> order(cs.size());
  for (size_t k = 0; k < cs.size(); ++k) order[k] = static_cast<int>(k);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cs[a].t_s < cs[b].t_s; });
  std::vector<double> times;
  for (int k : order)
    times.push_back(std::clamp(cs[k].t_s, problem.grid.front(), problem.grid.back()));
  const std::vector<Eigen::VectorXd> states = dynamics::PropagateLinear(
      *problem.model, problem.thrusters.AccelerationMatrix(), problem.initial_state,
      problem.grid.front(), pulses, times, tolerance);
  for (size_t q = 0; q < order.size(); ++q) {
    const StateConstraint& c = cs[order[q]];
    const double v = c.a.dot(states[q]);
    const double excess = std::max(c.lower - v, v - c.upper);
    if (excess > r->max_state_constraint_violation) {
      r->max_state_constraint_violation = excess;
      r->worst_state_constraint = order[q];
    }
  }
}

}  // namespace

std::vector<RuleViolation> CheckOperationalRules(const OperationalRules& rules,
                                                 const BoundaryHistory& history,
                                                 const std::vector<ForcedOff>& forced_off,
                                                 int num_thrusters, double t0, double tf,
                                                 const std::vector<Burn>& burns) {
  std::vector<std::string> names;
  for (int i = 0; i < std::max(num_thrusters, 0); ++i)
    names.push_back("thruster " + std::to_string(i));
  return CheckRules(rules, history, forced_off, num_thrusters, t0, tf, burns, names);
}

bool CheckOptions::IsValid(std::string* error) const {
  if (samples_per_interval < 0) {
    return common::Fail(
        error, "samples_per_interval must be >= 0, got " + std::to_string(samples_per_interval));
  }
  if (!(propagation_tolerance > 0.0) || !std::isfinite(propagation_tolerance)) {
    return common::Fail(error, "propagation_tolerance must be finite and > 0, got " +
                                   FormatG(propagation_tolerance, 10));
  }
  return true;
}

double TerminalError(const TerminalSpec& term, const Eigen::VectorXd& final_state,
                     const Eigen::VectorXd& scale) {
  if (term.kind != TerminalKind::kFixedState && term.kind != TerminalKind::kStateBox) return 0.0;
  double worst = 0.0;
  for (int c = 0; c < final_state.size(); ++c) {
    double dev = std::abs(final_state(c) - term.target(c));
    if (term.kind == TerminalKind::kStateBox) {
      const double tol = term.tolerance(c);
      dev = std::isinf(tol) ? 0.0 : std::max(0.0, dev - tol);
    }
    worst = std::max(worst, dev / scale(c));
  }
  return worst;
}

CheckReport CheckSchedule(const ScheduleProblem& problem, const std::vector<Burn>& burns,
                          const CheckOptions& options) {
  std::string err;
  if (!problem.IsValid(&err)) {
    throw std::invalid_argument("CheckSchedule: invalid problem: " + err);
  }
  if (problem.input_mode == InputMode::kImpulsive) {
    throw std::invalid_argument("CheckSchedule: impulsive problems are checked by ImpulsiveCheck");
  }
  if (!options.IsValid(&err)) throw std::invalid_argument("CheckSchedule: options." + err);
  const dynamics::LinearModel& model = *problem.model;
  const dynamics::ThrusterSet& thrusters = problem.thrusters;
  const int m = thrusters.size();
  const double t0 = problem.grid.front(), tf = problem.grid.back();

  CheckReport r;
  r.rule_violations = CheckRules(problem.rules, problem.history, problem.forced_off, m, t0, tf,
                                 burns, thrusters.names());
  for (const Burn& b : burns) {
    if (b.thruster >= 0 && b.thruster < m && !thrusters.thruster(b.thruster).enabled) {
      r.rule_violations.push_back(
          RuleViolation{"disabled", b.thruster, b.start_s,
                        thrusters.thruster(b.thruster).name + " is disabled but fires on [" +
                            FormatG(b.start_s, 10) + ", " + FormatG(b.end_s, 10) + ")"});
    }
  }
  std::stable_sort(
      r.rule_violations.begin(), r.rule_violations.end(),
      [](const RuleViolation& a, const RuleViolation& b) { return a.time_s < b.time_s; });
  r.operational_ok = r.rule_violations.empty();

  // Pulses: the union, per thruster, of the well-formed burns clipped to the
  // horizon (overlapping burns of one thruster fire it once, not twice).
  std::vector<dynamics::InputPulse> pulses;
  for (int i = 0; i < m; ++i) {
    std::vector<Interval> v;
    for (const Burn& b : burns) {
      if (b.thruster != i || !std::isfinite(b.start_s) || !std::isfinite(b.end_s)) continue;
      const double s = std::max(b.start_s, t0), e = std::min(b.end_s, tf);
      if (e > s) v.push_back({s, e});
    }
    for (const Interval& x : Union(std::move(v))) pulses.push_back({i, x.start, x.end});
  }

  std::vector<bool> is_node;
  r.sample_times = SampleTimes(problem.grid, options.samples_per_interval, &is_node);
  r.sample_states =
      dynamics::PropagateLinear(model, thrusters.AccelerationMatrix(), problem.initial_state, t0,
                                pulses, r.sample_times, options.propagation_tolerance);
  r.sample_outputs.reserve(r.sample_times.size());
  for (std::size_t k = 0; k < r.sample_times.size(); ++k) {
    r.sample_outputs.push_back(model.EvaluateOutput(r.sample_times[k]).c * r.sample_states[k]);
  }
  r.final_state = r.sample_states.back();

  // Window: every sample after t0 (index 0 is the initial node, data) with
  // t >= enforce_from_s (within tol).
  const WindowSpec& w = problem.window;
  for (std::size_t k = 1; k < r.sample_times.size(); ++k) {
    const double t = r.sample_times[k];
    if (t < w.enforce_from_s - kTol) continue;
    for (std::size_t q = 0; q < w.outputs.size(); ++q) {
      const double excess = std::abs(r.sample_outputs[k](w.outputs[q])) - w.half_widths[q];
      if (excess > r.max_window_violation) {
        r.max_window_violation = excess;
        r.worst_time_s = t;
        r.worst_output = w.outputs[q];
      }
      if (is_node[k]) {
        r.max_window_violation_at_nodes = std::max(r.max_window_violation_at_nodes, excess);
      }
    }
  }

  CheckStateConstraints(problem, pulses, options.propagation_tolerance, &r);

  // Terminal constraint, in units of the model's state scale.
  const TerminalSpec& term = problem.terminal;
  if (term.kind == TerminalKind::kFixedState || term.kind == TerminalKind::kStateBox) {
    r.terminal_error = TerminalError(term, r.final_state, model.state_scale());
    r.terminal_ok = r.terminal_error <= kTerminalTolerance;
  }

  if (term.kind == TerminalKind::kStationKeepingSets) {
    r.terminal_error = StationKeepingExcess(problem, r.final_state);
    r.terminal_ok = r.terminal_error <= kStationKeepingSetTolerance;
  }

  if (options.nonlinear) {
    ReplayNonlinear(problem, *options.nonlinear, pulses, &r);
  } else if (options.nonlinear_default) {
    if (const auto* geo = dynamic_cast<const dynamics::GeoLinearModel*>(problem.model.get())) {
      const dynamics::GeoSimulator simulator(geo->options());
      ReplayNonlinear(problem, simulator, pulses, &r);
    }
  }
  return r;
}

std::string CheckReport::Summary() const {
  std::ostringstream os;
  if (operational_ok) {
    os << "operational rules: ok\n";
  } else {
    os << "operational rules: " << rule_violations.size() << " violation(s)\n";
    for (const RuleViolation& v : rule_violations) {
      os << "  [" << v.rule << "] t = " << FormatG(v.time_s, 10) << " s: " << v.message << "\n";
    }
  }
  if (max_window_violation > 0.0) {
    os << "window (linear re-propagation): violated by " << FormatG(max_window_violation, 10)
       << " (output " << worst_output << " at t = " << FormatG(worst_time_s, 10)
       << " s); at nodes only: " << FormatG(max_window_violation_at_nodes, 10) << "\n";
  } else {
    os << "window (linear re-propagation): ok at " << sample_times.size() << " samples\n";
  }
  if (worst_state_constraint >= 0) {
    os << "state constraints (linear re-propagation): constraint " << worst_state_constraint
       << " violated by " << FormatG(max_state_constraint_violation, 10) << "\n";
  }
  os << "terminal: " << (terminal_ok ? "ok" : "VIOLATED") << " (scaled error "
     << FormatG(terminal_error, 10) << ")\n";
  if (nonlinear_checked) {
    os << "window (nonlinear replay): violation " << FormatG(max_window_violation_nonlinear_deg, 10)
       << " deg at t = " << FormatG(worst_time_nonlinear_s, 10) << " s; max |lat| "
       << FormatG(max_abs_lat_deg, 10) << " deg, max |lon| " << FormatG(max_abs_lon_deg, 10)
       << " deg; about " << FormatG(time_outside_window_nonlinear_s, 10) << " s outside\n";
  }
  return os.str();
}

}  // namespace thrustsched::transcription
