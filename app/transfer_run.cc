#include "app/transfer_run.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>
#include <vector>

#include "app/transfer_handover.h"
#include "common/constants.h"
#include "common/format.h"
#include "dynamics/two_body.h"
#include "transfer/second_order.h"
#include "transfer/two_impulse.h"

namespace thrustsched::app {
namespace {

using nlohmann::json;
using transfer::Equinoctial;

// One row of trajectory.csv.
struct Row {
  double t_s;
  Equinoctial q;
  double mass_kg;
  Eigen::Vector3d command_qsw;
};

struct Outcome {
  bool ok = false;
  double duration_s = 0, propellant_kg = 0, final_mass_kg = 0, revolutions = 0;
  Equinoctial final_elements;
  json convergence = json::object();
  json extra = json::object();  // method-specific fields
  std::vector<Row> rows;
  // Cartesian states: the replay's steps ("replay"), the two-impulse coast
  // with the states before the first and after the second impulse
  // ("coast"), or none (made from the rows: "elements").
  std::vector<transfer::ReplayState> orbit;
  std::string orbit_source = "elements";
};

json ElementsJson(const Equinoctial& q) {
  return {{"p_m", q.p_m},
          {"ex", q.ex},
          {"ey", q.ey},
          {"hx", q.hx},
          {"hy", q.hy},
          {"l_rad", q.l_rad},
          {"a_m", transfer::SemiMajorAxis(q)},
          {"e", transfer::Eccentricity(q)},
          {"i_deg", transfer::Inclination(q) * common::kRadToDeg}};
}

// Final minus target for every targeted element (null for a free one).
json ErrorsJson(const Equinoctial& q, const transfer::TargetElements& t) {
  const double v[5] = {q.p_m, q.ex, q.ey, q.hx, q.hy};
  const char* names[5] = {"p_m", "ex", "ey", "hx", "hy"};
  json e = json::object();
  for (int j = 0; j < 5; ++j) e[names[j]] = t.free[j] ? json(nullptr) : json(v[j] - t.value[j]);
  if (!t.free[0] && !t.free[1] && !t.free[2]) {
    const double et = std::hypot(t.value[1], t.value[2]);
    e["a_m"] = transfer::SemiMajorAxis(q) - t.value[0] / (1 - et * et);
    e["e"] = transfer::Eccentricity(q) - et;
  }
  if (!t.free[3] && !t.free[4]) {
    e["i_deg"] = (transfer::Inclination(q) - 2 * std::atan(std::hypot(t.value[3], t.value[4]))) *
                 common::kRadToDeg;
  }
  return e;
}

void AppendShooting(const transfer::MinTimeSolution& s, Outcome* o, double t0_s) {
  for (const transfer::TrajectorySample& x : s.trajectory) {
    o->rows.push_back({t0_s + x.t_s, x.elements, x.mass_kg, x.direction_qsw});
  }
}

json ShootingJson(const transfer::MinTimeSolution& s) {
  return {{"converged", s.converged},
          {"shooting_residual", s.residual_norm},
          {"iterations", s.evaluations},
          {"hybrd_info", s.hybrd_info},
          {"hamiltonian", s.hamiltonian},
          {"hamiltonian_drift", s.hamiltonian_drift},
          {"costate", std::vector<double>(s.costate.data(), s.costate.data() + 6)}};
}

json ReplayJson(const transfer::MinTimeProblem& p, const transfer::ReplayResult& r,
                const Equinoctial& q) {
  return {{"a_m", r.final_a_m},
          {"e", r.final_e},
          {"i_deg", r.final_i_rad * common::kRadToDeg},
          {"mass_kg", r.final_mass_kg},
          {"a_difference_m", r.final_a_m - transfer::SemiMajorAxis(q)},
          {"e_difference", r.final_e - transfer::Eccentricity(q)},
          {"mu_m3_s2", p.mu}};
}

transfer::ShootingOptions WithInterrupt(transfer::ShootingOptions o, const TransferHooks& hooks) {
  o.interrupt = hooks.interrupt;
  return o;
}

// The second-order necessary conditions of a converged extremal
// (transfer/second_order.h), sampled at most 2000 times along it.
json SecondOrderJson(const transfer::MinTimeProblem& p, const transfer::MinTimeSolution& s,
                     const transfer::ShootingOptions& shooting) {
  transfer::SecondOrderOptions o;
  o.shooting = shooting;
  o.samples_per_hour = std::min(20.0, 2000.0 / (s.duration_s / 3600));
  const transfer::SecondOrderCheck c = transfer::CheckSecondOrder(p, s, o);
  return {{"conjugate_point_test", c.verdict},
          {"legendre_holds", c.legendre_holds},
          {"min_switching_norm_ratio", c.min_switching_norm},
          {"no_conjugate_point", c.no_conjugate_point},
          {"conjugate_times_s", c.conjugate_times_s},
          {"resolved_from_s", c.resolved_from_s},
          {"resolved_samples", c.resolved_samples},
          {"resolved_fraction_second_half", c.resolved_fraction_second_half},
          {"min_abs_determinant_second_half", c.min_abs_determinant},
          {"final_determinant", c.final_determinant},
          {"samples", c.t_s.size()}};
}

Outcome RunMinimumTime(const TransferScenario& sc, bool quiet, const TransferHooks& hooks) {
  transfer::MinTimeProblem p = sc.problem;
  if (sc.continuation_from_thrust_n) p.thrust_n = *sc.continuation_from_thrust_n;
  const transfer::ShootingOptions options = WithInterrupt(sc.shooting, hooks);
  const transfer::ShootingGuess guess = sc.guess ? *sc.guess : transfer::InitialGuess(p);
  transfer::MinTimeSolution s = transfer::SolveMinTime(p, guess, options);
  Outcome o;
  int steps = 0;
  // The problem the solution solves: the thrust the continuation reached.
  transfer::MinTimeProblem reached = sc.problem;
  if (sc.continuation_from_thrust_n && s.converged && p.thrust_n != sc.problem.thrust_n) {
    if (!quiet) std::cerr << "shooting at " << p.thrust_n << " N: converged, continuing\n";
    const transfer::ContinuationResult c = transfer::ContinueOnThrust(
        p, s, sc.problem.thrust_n, options, [&](const transfer::ContinuationStep& st) {
          if (hooks.progress) {
            hooks.progress({{"phase", "continuation"},
                            {"thrust_n", st.thrust_n},
                            {"converged", st.converged},
                            {"duration_s", st.duration_s}});
          }
          if (quiet) return;
          std::cerr << "  thrust " << common::FormatG(st.thrust_n, 6)
                    << " N: " << (st.converged ? "converged, t_f = " : "not converged, t_f ~ ")
                    << common::FormatG(st.duration_s / 3600, 8) << " h\n";
        });
    steps = static_cast<int>(c.steps.size());
    s = c.solution;
    s.converged = s.converged && c.thrust_n == sc.problem.thrust_n;
    reached.thrust_n = c.thrust_n;
  } else {
    reached.thrust_n = p.thrust_n;  // no continuation ran: the start's shooting
  }
  o.ok = s.converged;
  o.duration_s = s.duration_s;
  o.propellant_kg = s.propellant_kg;
  o.final_mass_kg = s.final_mass_kg;
  o.final_elements = s.final_elements;
  o.revolutions = s.revolutions;
  o.convergence = ShootingJson(s);
  o.convergence["continuation_steps"] = steps;
  if (sc.continuation_from_thrust_n) {
    // Null when not even the start's shooting converged.
    o.convergence["continuation_thrust_reached_n"] =
        steps > 0 || s.converged ? json(reached.thrust_n) : json(nullptr);
  }
  AppendShooting(s, &o, 0.0);
  if (s.trajectory.size() >= 2) {
    const transfer::ReplayResult r = transfer::ReplaySamples(reached, s.trajectory, s.duration_s);
    o.extra["replay"] = ReplayJson(reached, r, s.final_elements);
    o.orbit = r.states;
    o.orbit_source = "replay";
  }
  o.extra["propellant_check_kg"] =
      reached.thrust_n * s.duration_s / (common::kStandardGravity_m_s2 * reached.isp_s);
  // Of the converged extremal only (an interrupted run keeps its time).
  o.extra["second_order"] = s.converged ? SecondOrderJson(reached, s, sc.shooting) : json(nullptr);
  return o;
}

json SwitchJson(const transfer::SwitchedTransfer& t, const transfer::SwitchOptions& o) {
  json attempts = json::array();
  for (const transfer::SwitchAttempt& a : t.attempts) {
    attempts.push_back({{"switch_s", a.switch_s}, {"converged", a.converged}, {"end_s", a.end_s}});
  }
  json j = {{"rule", transfer::ToString(o.rule)}, {"switch_s", t.switch_s}, {"attempts", attempts}};
  if (o.rule != transfer::SwitchRule::kSaturation) j["interval_s"] = o.interval_s;
  return j;
}

Outcome RunFeedbackMethod(const TransferScenario& sc, bool quiet, const TransferHooks& hooks) {
  const transfer::MinTimeProblem& p = sc.problem;
  transfer::FeedbackOptions feedback_options = sc.feedback;
  feedback_options.interrupt = hooks.interrupt;
  transfer::FeedbackResult f = transfer::RunFeedback(p, feedback_options);
  json feedback_phase = {{"saturation_s", f.duration_s}};
  std::optional<transfer::SwitchedTransfer> end;
  if (sc.optimal_end && !f.reached && f.stop_reason == "saturation") {
    end = transfer::SwitchToMinimumTime(
        p, f, sc.feedback_switch, WithInterrupt(sc.shooting, hooks),
        [&](const transfer::SwitchAttempt& a) {
          if (hooks.progress) {
            hooks.progress({{"phase", "switch"},
                            {"switch_s", a.switch_s},
                            {"converged", a.converged},
                            {"end_s", a.end_s}});
          }
          if (quiet) return;
          std::cerr << "  end from " << common::FormatG(a.switch_s / common::kSecondsPerDay, 7)
                    << " d: "
                    << (a.converged ? "converged, " + common::FormatG(a.end_s / 3600, 6) + " h"
                                    : std::string("not converged"))
                    << "\n";
        });
    f = end->transfer.feedback;
  }
  Outcome o;
  for (const transfer::FeedbackSample& x : f.trajectory) {
    o.rows.push_back({x.t_s, x.elements, x.mass_kg, x.command_qsw});
  }
  feedback_phase.update({{"duration_s", f.duration_s},
                         {"stop_reason", f.stop_reason},
                         {"reached", f.reached},
                         {"final_lyapunov", f.final_lyapunov},
                         {"max_lyapunov_increase", f.max_lyapunov_increase},
                         {"propellant_kg", f.propellant_kg},
                         {"on_off", sc.feedback.on_off}});
  o.extra["feedback"] = feedback_phase;
  o.ok = f.reached, o.duration_s = f.duration_s, o.propellant_kg = f.propellant_kg;
  o.final_mass_kg = f.final_mass_kg, o.final_elements = f.final_elements;
  o.revolutions = f.revolutions;
  if (end) {
    const transfer::FeedbackWithEnd& e = end->transfer;
    o.extra["optimal_end"] = ShootingJson(e.end);
    o.extra["optimal_end"]["duration_s"] = e.end.duration_s;
    o.extra["optimal_end"]["switch"] = SwitchJson(*end, sc.feedback_switch);
    o.convergence = ShootingJson(e.end);
    if (e.end.converged) {
      AppendShooting(e.end, &o, f.duration_s);
      o.ok = true, o.duration_s = e.total_duration_s, o.propellant_kg = e.total_propellant_kg;
      o.final_mass_kg = e.end.final_mass_kg, o.final_elements = e.end.final_elements;
      o.revolutions = (o.final_elements.l_rad - p.initial.l_rad) / (2 * common::kPi);
    }
  }
  return o;
}

Outcome RunTwoImpulse(const TransferScenario& sc) {
  const transfer::MinTimeProblem& p = sc.problem;
  const auto& t = p.target;
  const double e0 = transfer::Eccentricity(p.initial), et = std::hypot(t.value[1], t.value[2]);
  if (e0 > 1e-12 || et > 1e-12 || std::abs(p.initial.hx - t.value[3]) > 1e-12 ||
      std::abs(p.initial.hy - t.value[4]) > 1e-12 || t.free[0]) {
    throw ScenarioError(
        "scenario.transfer.method: two_impulse needs a circular start, a "
        "circular target in the same plane and a fixed target P (e0 = " +
        FormatNumber(e0) + ", target e = " + FormatNumber(et) + ")");
  }
  const transfer::TwoImpulseResult r =
      transfer::MinimiseTwoImpulse({p.mu, p.initial.p_m, t.value[0]});
  const transfer::HohmannTransfer h = transfer::Hohmann(p.initial.p_m, t.value[0], p.mu);
  Outcome o;
  o.ok = true;
  o.duration_s = r.time_of_flight_s;
  const double c = common::kStandardGravity_m_s2 * p.isp_s;
  o.final_mass_kg = p.mass_kg * std::exp(-(r.dv0_m_s + r.dvf_m_s) / c);
  o.propellant_kg = p.mass_kg - o.final_mass_kg;
  o.revolutions = 0.5;
  o.extra["two_impulse"] = {{"dv0_m_s", r.dv0_m_s},
                            {"dvf_m_s", r.dvf_m_s},
                            {"total_dv_m_s", r.dv0_m_s + r.dvf_m_s},
                            {"cost_m2_s2", r.cost_m2_s2},
                            {"hohmann_total_dv_m_s", h.total_m_s},
                            {"hohmann_time_of_flight_s", h.time_of_flight_s}};
  // The coast, sampled from Kepler's equation after the first impulse.
  dynamics::Vector6d rv = transfer::CartesianFromEquinoctial(p.initial, p.mu);
  const Eigen::Matrix3d b = transfer::QswBasis(rv);
  rv.tail<3>() += b * Eigen::Vector3d(r.dv0_radial_m_s, r.dv0_tangential_m_s, 0);
  const dynamics::KeplerOrbit orbit(rv, 0.0, p.mu);
  const double m1 = p.mass_kg * std::exp(-r.dv0_m_s / c);
  const int n = 200;
  o.orbit_source = "coast";
  o.orbit.push_back({0.0, transfer::CartesianFromEquinoctial(p.initial, p.mu), p.mass_kg});
  for (int k = 0; k <= n; ++k) {
    const double ts = r.time_of_flight_s * k / n;
    const dynamics::Vector6d x = orbit.At(ts);
    o.rows.push_back({ts, transfer::EquinoctialFromCartesian(x, p.mu),
                      k == n ? o.final_mass_kg : m1, Eigen::Vector3d::Zero()});
    o.orbit.push_back({ts, x, m1});
  }
  // After the second impulse: the target orbit at the arrival longitude.
  o.final_elements = Equinoctial{t.value[0], 0, 0, t.value[3], t.value[4], o.rows.back().q.l_rad};
  o.rows.back().q = o.final_elements;
  o.orbit.push_back({r.time_of_flight_s, transfer::CartesianFromEquinoctial(o.final_elements, p.mu),
                     o.final_mass_kg});
  return o;
}

std::string TrajectoryCsv(const std::vector<Row>& rows) {
  std::ostringstream s;
  s << "t_s,p_m,ex,ey,hx,hy,l_rad,a_m,e,i_deg,mass_kg,u_q,u_s,u_w\n";
  for (const Row& r : rows) {
    const double v[] = {r.t_s,
                        r.q.p_m,
                        r.q.ex,
                        r.q.ey,
                        r.q.hx,
                        r.q.hy,
                        r.q.l_rad,
                        transfer::SemiMajorAxis(r.q),
                        transfer::Eccentricity(r.q),
                        transfer::Inclination(r.q) * common::kRadToDeg,
                        r.mass_kg,
                        r.command_qsw(0),
                        r.command_qsw(1),
                        r.command_qsw(2)};
    for (std::size_t i = 0; i < sizeof(v) / sizeof(v[0]); ++i) {
      s << (i ? "," : "") << common::FormatG(v[i], 12);
    }
    s << "\n";
  }
  return s.str();
}

json Summary(const TransferScenario& sc, const std::string& scenario_path, const Outcome& o,
             bool interrupted) {
  const transfer::TargetElements& t = sc.problem.target;
  json target = {{"p_m", t.value[0]}, {"ex", t.value[1]}, {"ey", t.value[2]},
                 {"hx", t.value[3]},  {"hy", t.value[4]}, {"free", json::array()}};
  const char* names[5] = {"p", "ex", "ey", "hx", "hy"};
  for (int j = 0; j < 5; ++j) {
    if (t.free[j]) target["free"].push_back(names[j]);
  }
  json j = {{"command", "transfer"},
            {"scenario", scenario_path},
            {"name", sc.name},
            {"method", ToString(sc.method)},
            {"force_model", transfer::ToString(sc.problem.force_model.kind)},
            {"status", o.ok          ? "converged"
                       : interrupted ? "interrupted"
                                     : "not_converged"},
            {"interrupted", interrupted},
            {"duration_s", o.duration_s},
            {"duration_h", o.duration_s / 3600},
            {"duration_d", o.duration_s / common::kSecondsPerDay},
            {"propellant_kg", o.propellant_kg},
            {"final_mass_kg", o.final_mass_kg},
            {"revolutions", o.revolutions},
            {"thrust_n", sc.problem.thrust_n},
            {"isp_s", sc.problem.isp_s},
            {"mass_kg", sc.problem.mass_kg},
            {"initial_elements", ElementsJson(sc.problem.initial)},
            {"final_elements", ElementsJson(o.final_elements)},
            {"target", target},
            {"errors", ErrorsJson(o.final_elements, t)},
            {"convergence", o.convergence}};
  for (auto it = o.extra.begin(); it != o.extra.end(); ++it) j[it.key()] = it.value();
  std::optional<dynamics::Epoch> end;
  if (sc.epoch) {
    end = sc.epoch->PlusSeconds(o.duration_s);
    j["epoch"] = sc.epoch->ToIso8601();
    j["end_epoch"] = end->ToIso8601();
  }
  j["final_state"] = StationKeepingInitialState(o.final_elements, sc.problem.mu, end);
  j["orbit_source"] = o.orbit_source;
  return j;
}

}  // namespace

TransferRun RunTransferScenario(const TransferScenario& sc, const std::string& scenario_path,
                                bool quiet, const TransferHooks& hooks) {
  CheckForceModel(sc);  // again: the method may have been overridden
  Outcome o;
  switch (sc.method) {
    case TransferMethod::kMinimumTime:
      o = RunMinimumTime(sc, quiet, hooks);
      break;
    case TransferMethod::kFeedback:
      o = RunFeedbackMethod(sc, quiet, hooks);
      break;
    case TransferMethod::kTwoImpulse:
      o = RunTwoImpulse(sc);
      break;
  }
  TransferRun run;
  run.converged = o.ok;
  // A stop request that came after the run converged changes nothing.
  run.interrupted = !o.ok && hooks.interrupt != nullptr && hooks.interrupt->load();
  run.summary = Summary(sc, scenario_path, o, run.interrupted);
  run.trajectory_csv = TrajectoryCsv(o.rows);
  run.trajectory_rows = o.rows.size();
  run.orbit = std::move(o.orbit);
  if (run.orbit.empty()) {
    for (const Row& r : o.rows) {
      run.orbit.push_back(
          {r.t_s, transfer::CartesianFromEquinoctial(r.q, sc.problem.mu), r.mass_kg});
    }
  }
  return run;
}

std::string OrbitCsv(const std::vector<transfer::ReplayState>& orbit) {
  std::ostringstream s;
  s << "t_s,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,mass_kg\n";
  for (const transfer::ReplayState& x : orbit) {
    s << common::FormatG(x.t_s, 12);
    for (int i = 0; i < 6; ++i) s << "," << common::FormatG(x.rv(i), 12);
    s << "," << common::FormatG(x.mass_kg, 12) << "\n";
  }
  return s.str();
}

}  // namespace thrustsched::app
