#include "app/transfer_scenario.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "app/initial_orbit.h"
#include "common/constants.h"
#include "dynamics/frames.h"

namespace thrustsched::app {
namespace {

using transfer::Equinoctial;

constexpr const char* kElementNames[5] = {"p", "ex", "ey", "hx", "hy"};

// The transfer's own forms: equinoctial elements, or Keplerian ones in m and deg.
Equinoctial ReadOwnForm(JsonObject& o) {
  Equinoctial q;
  if (o.Has("equinoctial")) {
    JsonObject e = o.Object("equinoctial");
    q.p_m = e.Number("p_m", Bound::kPositive);
    q.ex = e.Number("ex");
    q.ey = e.Number("ey");
    q.hx = e.Number("hx");
    q.hy = e.Number("hy");
    q.l_rad = e.Number("l_deg") * common::kDegToRad;
    const double ecc = std::hypot(q.ex, q.ey);
    if (!(ecc < 1)) {
      e.Fail("ex", "the initial orbit is not an ellipse (hyperbolic or parabolic start): e = " +
                       FormatNumber(ecc));
    }
    e.Finish();
    return q;
  }
  JsonObject k = o.Object("keplerian");
  transfer::Keplerian kep;
  kep.a_m = k.Number("a_m");
  kep.e = k.Number("e", Bound::kNonNegative);
  if (!(kep.e < 1)) {
    k.Fail("e", "the initial orbit is not an ellipse (hyperbolic or parabolic start), got " +
                    FormatNumber(kep.e));
  }
  if (!(kep.a_m > 0)) k.Fail("a_m", "must be > 0, got " + FormatNumber(kep.a_m));
  const double i_deg = k.Number("i_deg", Bound::kNonNegative);
  if (!(i_deg < 180)) k.Fail("i_deg", "must be in [0, 180), got " + FormatNumber(i_deg));
  kep.i_rad = i_deg * common::kDegToRad;
  kep.raan_rad = k.Number("raan_deg") * common::kDegToRad;
  kep.arg_perigee_rad = k.Number("arg_perigee_deg") * common::kDegToRad;
  kep.true_anomaly_rad = k.Number("true_anomaly_deg") * common::kDegToRad;
  k.Finish();
  return transfer::EquinoctialFromKeplerian(kep);
}

// The station-keeping scenarios' orbit forms (app/initial_orbit.h: an OPM,
// an ECI state, Keplerian elements in km with their frame and epoch), taken
// to EME2000 (the transfer's inertial frame) and to equinoctial elements with
// the transfer's mu. Their epoch, when they state one, is the transfer's start.
Equinoctial ReadOrbitForm(JsonObject& o, const std::string& base_dir, double mu,
                          std::optional<dynamics::Epoch>* epoch) {
  const std::string form = o.Has("opm") ? "opm" : o.Has("eci_state") ? "eci_state" : "keplerian";
  const bool dated = form == "opm" || o.Raw(form).contains("epoch");
  const InitialOrbit orbit = ReadOrbitAsGiven(
      o, epoch->value_or(dynamics::Epoch::Parse("2000-01-01T12:00:00Z")), base_dir);
  const std::string path = o.FieldPath(form);
  if (dated) {
    if (*epoch && std::abs(orbit.given.epoch.SecondsSince(**epoch)) > 1e-3) {
      throw ScenarioError(path + ": the state's epoch " + orbit.given.epoch.ToIso8601() +
                          " is not the transfer's epoch " + (*epoch)->ToIso8601() +
                          " (scenario.transfer.epoch; give one of them, or the same)");
    }
    *epoch = orbit.given.epoch;
  }
  dynamics::Vector6d rv = orbit.given.rv;
  if (orbit.given.frame == dynamics::InertialFrame::kGcrf) {
    const Eigen::Matrix3d b = dynamics::FrameBiasIers2003();  // r_EME2000 = B r_GCRF
    rv.head<3>() = b * rv.head<3>();
    rv.tail<3>() = b * rv.tail<3>();
  }
  const double r = rv.head<3>().norm(), v2 = rv.tail<3>().squaredNorm();
  if (!(2 * mu / r - v2 > 0)) {
    throw ScenarioError(path + ": the initial orbit is not an ellipse (hyperbolic or parabolic " +
                        "start): v^2 = " + FormatNumber(v2) +
                        " m^2/s^2 >= 2 mu / r = " + FormatNumber(2 * mu / r));
  }
  return transfer::EquinoctialFromCartesian(rv, mu);
}

bool IsSharedForm(JsonObject& o) {
  if (o.Has("opm") || o.Has("eci_state")) return true;
  return o.Has("keplerian") && o.Raw("keplerian").is_object() &&
         o.Raw("keplerian").contains("semi_major_axis_km");
}

Equinoctial ReadInitial(JsonObject o, const std::string& base_dir, double mu,
                        std::optional<dynamics::Epoch>* epoch) {
  o.ExactlyOneOf({"equinoctial", "keplerian", "eci_state", "opm"}, true);
  const Equinoctial q = IsSharedForm(o) ? ReadOrbitForm(o, base_dir, mu, epoch) : ReadOwnForm(o);
  o.Finish();
  const double rp = q.p_m / (1 + std::hypot(q.ex, q.ey));
  if (rp < kEarthRadiusM) {
    throw ScenarioError(o.path() + ": perigee radius " + FormatNumber(rp / 1e3) +
                        " km is below the Earth's equatorial radius (6378.137 km)");
  }
  return q;
}

transfer::TargetElements ReadTarget(JsonObject o) {
  transfer::TargetElements t;
  std::vector<std::string> free =
      o.Has("free") ? o.StringArray("free") : std::vector<std::string>{};
  for (const std::string& f : free) {
    bool known = false;
    for (int j = 0; j < 5; ++j) {
      if (f == kElementNames[j]) t.free[j] = known = true;
    }
    if (!known) {
      o.Fail("free", "unknown element '" + f + "' (accepted: p, ex, ey, hx, hy)");
    }
  }
  for (int j = 1; j < 5; ++j) {
    const std::optional<double> v = o.OptionalNumber(kElementNames[j]);
    if (!v && !t.free[j]) o.Fail(kElementNames[j], "required unless listed in \"free\"");
    t.value[j] = v.value_or(0.0);
  }
  const double e = std::hypot(t.value[1], t.value[2]);
  if (!(e < 1)) o.Fail("ex", "the target is not an ellipse: e = " + FormatNumber(e));
  o.ExactlyOneOf({"p_m", "a_m"}, !t.free[0]);
  if (o.Has("a_m")) {
    const double a = o.Number("a_m", Bound::kPositive);
    if (a * (1 + e) > kEarthSphereOfInfluenceM) {
      o.Fail("a_m", "the target's apogee " + FormatNumber(a * (1 + e) / 1e3) +
                        " km is above escape (beyond the Earth's sphere of influence, " +
                        FormatNumber(kEarthSphereOfInfluenceM / 1e3) + " km), got " +
                        FormatNumber(a));
    }
    t.value[0] = a * (1 - e * e);
  } else if (o.Has("p_m")) {
    t.value[0] = o.Number("p_m", Bound::kPositive);
    if (t.value[0] / (1 - e) > kEarthSphereOfInfluenceM) {
      o.Fail("p_m",
             "the target's apogee is above escape (beyond the Earth's sphere of "
             "influence), got " +
                 FormatNumber(t.value[0]));
    }
  }
  o.Finish();
  return t;
}

void ReadShooting(JsonObject o, TransferScenario* s) {
  s->continuation_from_thrust_n = o.OptionalNumber("continuation_from_thrust_n", Bound::kPositive);
  if (o.Has("costate_guess")) {
    JsonObject g = o.Object("costate_guess");
    transfer::ShootingGuess guess;
    guess.duration_s = g.Number("duration_s", Bound::kPositive);
    const std::vector<double> p = g.NumberArray("costate", 6);
    for (int i = 0; i < 6; ++i) guess.costate(i) = p[i];
    if (!(guess.costate.norm() > 0)) g.Fail("costate", "must not be zero");
    g.Finish();
    s->guess = guess;
  }
  if (auto v = o.OptionalNumber("integration_tolerance", Bound::kPositive)) {
    s->shooting.integration_tolerance = *v;
  }
  if (auto v = o.OptionalInteger("max_evaluations", 10, 100000)) s->shooting.max_evaluations = *v;
  o.Finish();
  std::string error;
  if (!s->shooting.IsValid(&error)) throw ScenarioError(o.path() + ": " + error);
}

void ReadFeedback(JsonObject o, TransferScenario* s) {
  transfer::FeedbackOptions& f = s->feedback;
  if (o.Has("weights")) {
    JsonObject w = o.Object("weights");
    f.weights.a = w.Number("a", Bound::kNonNegative);
    f.weights.e = w.Number("e", Bound::kNonNegative);
    f.weights.i = w.Number("i", Bound::kNonNegative);
    w.Finish();
  }
  f.delta = o.OptionalNumber("delta", Bound::kPositive).value_or(f.delta);
  f.v_stop = o.OptionalNumber("v_stop", Bound::kPositive).value_or(f.v_stop);
  f.max_duration_s =
      o.OptionalNumber("max_duration_s", Bound::kPositive).value_or(f.max_duration_s);
  f.on_off = o.OptionalBool("on_off").value_or(false);
  f.on_off_p = o.OptionalNumber("on_off_p", Bound::kNonNegative).value_or(f.on_off_p);
  f.stop_at_saturation = o.OptionalBool("stop_at_saturation").value_or(true);
  s->optimal_end = o.OptionalBool("optimal_end").value_or(true);
  if (o.Has("switch")) {
    const std::string rule =
        o.Choice("switch", {"saturation", "earliest_convergent", "shortest_convergent"});
    for (transfer::SwitchRule r :
         {transfer::SwitchRule::kSaturation, transfer::SwitchRule::kEarliestConvergent,
          transfer::SwitchRule::kShortestConvergent}) {
      if (rule == transfer::ToString(r)) s->feedback_switch.rule = r;
    }
  }
  s->feedback_switch.interval_s = o.OptionalNumber("switch_interval_s", Bound::kPositive)
                                      .value_or(s->feedback_switch.interval_s);
  o.Finish();
  std::string error;
  if (!f.IsValid(&error)) throw ScenarioError(o.path() + ": " + error);
}

}  // namespace

std::string ToString(TransferMethod m) {
  switch (m) {
    case TransferMethod::kMinimumTime:
      return "minimum_time";
    case TransferMethod::kFeedback:
      return "feedback";
    case TransferMethod::kTwoImpulse:
      return "two_impulse";
  }
  return "?";
}

TransferMethod ParseTransferMethod(const std::string& name, const std::string& path) {
  for (TransferMethod m :
       {TransferMethod::kMinimumTime, TransferMethod::kFeedback, TransferMethod::kTwoImpulse}) {
    if (name == ToString(m)) return m;
  }
  throw ScenarioError(path + ": unknown method \"" + name +
                      "\" (accepted: minimum_time, feedback, two_impulse)");
}

TransferScenario ParseTransferScenario(const nlohmann::json& root, const std::string& path) {
  TransferScenario s;
  s.path = path;
  JsonObject top(root, "scenario");
  s.name = top.OptionalString("name").value_or("");
  s.description = top.OptionalString("description").value_or("");
  JsonObject t = top.Object("transfer");
  top.Finish();
  // A misspelt key is named (with its closest accepted name) before any
  // required field it hides is reported missing.
  for (const char* key : {"mu_m3_s2", "initial", "target", "thrust_n", "isp_s", "mass_kg", "method",
                          "epoch", "shooting", "feedback", "force_model"}) {
    t.Has(key);
  }
  t.Finish();
  transfer::MinTimeProblem& p = s.problem;
  p.mu = t.OptionalNumber("mu_m3_s2", Bound::kPositive).value_or(transfer::kMuEarth);
  if (const std::optional<std::string> epoch = t.OptionalString("epoch")) {
    s.epoch = Wrap(t.FieldPath("epoch"), [&] { return dynamics::Epoch::Parse(*epoch); });
  }
  const std::string base_dir =
      path.empty() ? std::string() : std::filesystem::path(path).parent_path().string();
  p.initial = ReadInitial(t.Object("initial"), base_dir, p.mu, &s.epoch);
  p.target = ReadTarget(t.Object("target"));
  p.thrust_n = t.Number("thrust_n", Bound::kPositive);
  p.isp_s = t.Number("isp_s", Bound::kPositive);
  p.mass_kg = t.Number("mass_kg", Bound::kPositive);
  s.method = ParseTransferMethod(t.String("method"), t.FieldPath("method"));
  if (t.Has("force_model")) {
    const std::string model = t.Choice("force_model", {"two_body", "j2"});
    p.force_model.kind =
        model == "j2" ? transfer::ForceModelKind::kJ2 : transfer::ForceModelKind::kTwoBody;
  }
  if (t.Has("shooting")) ReadShooting(t.Object("shooting"), &s);
  if (t.Has("feedback")) ReadFeedback(t.Object("feedback"), &s);
  t.Finish();
  std::string error;
  if (!p.IsValid(&error)) throw ScenarioError(t.path() + ": " + error);
  CheckForceModel(s);
  return s;
}

void CheckForceModel(const TransferScenario& s) {
  if (s.problem.force_model.kind == transfer::ForceModelKind::kTwoBody) return;
  if (s.method == TransferMethod::kTwoImpulse) {
    throw ScenarioError(
        "scenario.transfer.force_model: two_impulse (the Hohmann closed form) supports "
        "force_model two_body only, got \"" +
        transfer::ToString(s.problem.force_model.kind) + "\"");
  }
}

TransferScenario LoadTransferScenario(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ScenarioError(path + ": is a folder, not a transfer scenario file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot open the scenario file");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw ScenarioError(path + ": cannot read the scenario file");
  return ParseTransferScenario(ParseJsonText(ss.str(), path), path);
}

}  // namespace thrustsched::app
