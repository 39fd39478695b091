// Scenario files (JSON) into a ScheduleProblem and its options. One file on
// purpose, ~700 lines: every section of the format (model, thrusters, rules,
// window, terminal, solver) is read by the same field-checking helpers, in the
// order data/scenarios/README.md documents them, so a field is found in one place.
#include "app/scenario.h"
#include "app/search_section.h"

#include "app/conjunction_section.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "common/constants.h"
#include "common/error.h"
#include "dynamics/discretisation.h"
#include "dynamics/geo_simulator.h"
#include "dynamics/models.h"
#include "dynamics/schweighart_sedwick.h"
#include "dynamics/time.h"
#include "transcription/encodings.h"

namespace thrustsched::app {
namespace {

using common::kPi;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Bounds that keep every model and grid well defined (documented in the README).
constexpr double kMaxAbsTime = 1e10;  // s, |start_s| and |end|
constexpr double kMaxDuration = 1e9;  // s, ~31.7 years
// A step is no longer than the horizon up to this relative rounding.
constexpr double kStepFitsRelativeSlack = 1e-12;
// A step divides the horizon when duration / step is this close to a whole
// number, relative to max(1, duration / step).
constexpr double kWholeStepsRelativeTolerance = 1e-9;

std::string Join(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// Thruster names end up in CSV files and MPS column comments: keep them simple.
bool ValidThrusterName(const std::string& name) {
  if (name.empty() || name.size() > 32) return false;
  for (char c : name) {
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                    c == '+' || c == '-' || c == '_' || c == '.';
    if (!ok) return false;
  }
  return true;
}

// Keys of a state description, per model type (a GEO initial state may also
// be an orbit: initial_orbit.h).
std::vector<std::string> StateForms(ModelType type, bool initial = false) {
  if (type == ModelType::kGeo) {
    std::vector<std::string> forms = {"station_point", "relative_equinoctial", "state"};
    if (initial) forms.insert(forms.end(), OrbitForms().begin(), OrbitForms().end());
    return forms;
  }
  return {"hcw_position_m", "state"};
}

// Reads a state given in one of the forms above from `o` (other keys of `o`
// are left to the caller).
Eigen::VectorXd ReadState(JsonObject& o, ModelType type, int n, bool initial = false) {
  o.ExactlyOneOf(StateForms(type, initial), /*required=*/true);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  if (o.Has("state")) {
    const std::vector<double> v = o.NumberArray("state", n);
    for (int i = 0; i < n; ++i) x[i] = v[i];
    return x;
  }
  if (type == ModelType::kGeo) {
    if (o.Has("station_point")) {
      if (!o.Bool("station_point")) {
        o.Fail("station_point", "must be true (give relative_equinoctial or state otherwise)");
      }
      return x;
    }
    const std::vector<double> v = o.NumberArray("relative_equinoctial", 6);
    for (int i = 0; i < 6; ++i) x[i] = v[i];
    return x;
  }
  const std::vector<double> p = o.NumberArray("hcw_position_m", 3);
  const std::vector<double> v = o.Has("hcw_velocity_m_s") ? o.NumberArray("hcw_velocity_m_s", 3)
                                                          : std::vector<double>{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    x[i] = p[i];
    x[3 + i] = v[i];
  }
  return x;
}

// The initial state; needs the model and the horizon (an orbit is converted
// at the horizon start). OPM paths are relative to the scenario file.
void ParseInitialState(JsonObject init, const ScenarioParseOptions& options, Scenario* s) {
  if (s->model_type != ModelType::kGeo) {
    for (const std::string& form : OrbitForms()) {
      if (init.Has(form)) {
        init.Fail(form, "an orbit needs a \"geo\" model, got \"" +
                            std::string(ToString(s->model_type)) + "\"");
      }
    }
  }
  if (s->model_type == ModelType::kGeo && HasOrbitForm(init)) {
    init.ExactlyOneOf(StateForms(ModelType::kGeo, /*initial=*/true), /*required=*/true);
    std::error_code ec;
    const bool is_file = std::filesystem::is_regular_file(options.source, ec);
    const std::string base_dir =
        is_file ? std::filesystem::path(options.source).parent_path().string() : "";
    const dynamics::GeoSimulator sim(*s->geo);
    s->initial_orbit = ReadInitialOrbit(init, sim, s->start_s, base_dir);
    s->problem.initial_state = s->initial_orbit->relative_state;
  } else {
    s->problem.initial_state =
        ReadState(init, s->model_type, s->problem.model->num_states(), /*initial=*/true);
  }
  init.Finish();
}

// "schweighart_sedwick": the circular reference orbit by its radius or its
// altitude above the model's equatorial radius, and its inclination.
void ParseSchweighartSedwick(JsonObject& m, Scenario* s) {
  s->model_type = ModelType::kSchweighartSedwick;
  m.ExactlyOneOf({"altitude_m", "radius_m"}, /*required=*/true);
  const double radius_m =
      m.Has("radius_m") ? m.Number("radius_m", Bound::kPositive)
                        : common::kEarthRadius_m + m.Number("altitude_m", Bound::kNonNegative);
  const double inclination_deg = m.Number("inclination_deg", Bound::kNonNegative);
  if (inclination_deg > 180.0) {
    m.Fail("inclination_deg", "must be in [0, 180], got " + FormatNumber(inclination_deg));
  }
  const std::string cross = m.Has("cross_track")
                                ? m.Choice("cross_track", {"equal_inclination", "simple"})
                                : "equal_inclination";
  const dynamics::CrossTrack cross_track =
      cross == "simple" ? dynamics::CrossTrack::kSimple : dynamics::CrossTrack::kEqualInclination;
  const double l = m.OptionalNumber("length_scale_m", Bound::kPositive).value_or(1000.0);
  s->problem.model = Wrap(m.path(), [&] {
    return std::make_shared<const dynamics::SchweighartSedwickModel>(
        radius_m, inclination_deg * common::kDegToRad, l, cross_track);
  });
}

void ParseModel(JsonObject m, Scenario* s) {
  const std::string type = m.Choice(
      "type", {"hcw", "geo", "double_integrator", "yamanaka_ankersen", "schweighart_sedwick"});
  if (type == "schweighart_sedwick") {
    ParseSchweighartSedwick(m, s);
  } else if (type == "hcw") {
    s->model_type = ModelType::kHcw;
    const double n = m.Number("mean_motion_rad_s", Bound::kPositive);
    const double l = m.OptionalNumber("length_scale_m", Bound::kPositive).value_or(1000.0);
    s->problem.model =
        Wrap(m.path(), [&] { return std::make_shared<const dynamics::HcwModel>(n, l); });
  } else if (type == "geo") {
    s->model_type = ModelType::kGeo;
    dynamics::GeoModelOptions g;
    g.station_longitude_deg = m.Number("station_longitude_deg");
    if (g.station_longitude_deg < -180.0 || g.station_longitude_deg > 360.0) {
      m.Fail("station_longitude_deg",
             "must be in [-180, 360], got " + FormatNumber(g.station_longitude_deg));
    }
    g.epoch = m.String("epoch");
    Wrap(m.FieldPath("epoch"), [&] { return dynamics::Epoch::Parse(g.epoch); });
    if (m.Has("perturbations")) {
      const std::vector<std::string> all = {"j2", "tesseral", "sun", "moon", "srp"};
      const std::vector<std::string> list = m.StringArray("perturbations");
      g.j2 = g.tesseral = g.sun = g.moon = g.srp = false;
      for (size_t i = 0; i < list.size(); ++i) {
        const std::string& p = list[i];
        if (p == "j2")
          g.j2 = true;
        else if (p == "tesseral")
          g.tesseral = true;
        else if (p == "sun")
          g.sun = true;
        else if (p == "moon")
          g.moon = true;
        else if (p == "srp")
          g.srp = true;
        else
          throw ScenarioError(m.FieldPath("perturbations") + "[" + std::to_string(i) +
                              "]: unknown perturbation \"" + p +
                              "\" (expected one of: " + Join(all) + ")");
      }
    }
    g.area_to_mass_m2_kg =
        m.OptionalNumber("area_to_mass_m2_kg", Bound::kNonNegative).value_or(g.area_to_mass_m2_kg);
    if (g.area_to_mass_m2_kg > 1000.0) {
      m.Fail("area_to_mass_m2_kg",
             "must be in [0, 1000], got " + FormatNumber(g.area_to_mass_m2_kg));
    }
    if (auto cr = m.OptionalNumber("reflectivity_cr", Bound::kNonNegative)) {
      if (*cr > 2.0) m.Fail("reflectivity_cr", "must be in [0, 2], got " + FormatNumber(*cr));
      g.reflectivity_cr = *cr;
    }
    g.gravity_degree = m.OptionalInteger("gravity_degree", 2, 4).value_or(g.gravity_degree);
    std::string err;
    if (!g.IsValid(&err)) throw ScenarioError(m.path() + ": " + err);
    s->geo = g;
    s->problem.model =
        Wrap(m.path(), [&] { return std::make_shared<const dynamics::GeoLinearModel>(g); });
  } else if (type == "double_integrator") {
    s->model_type = ModelType::kDoubleIntegrator;
    const double ts = m.OptionalNumber("time_scale_s", Bound::kPositive).value_or(1.0);
    const double l = m.OptionalNumber("length_scale_m", Bound::kPositive).value_or(1.0);
    s->problem.model =
        Wrap(m.path(), [&] { return std::make_shared<const dynamics::DoubleIntegrator3d>(ts, l); });
  } else {
    s->model_type = ModelType::kYamanakaAnkersen;
    m.ExactlyOneOf({"semi_major_axis_m", "mean_motion_rad_s"}, /*required=*/true);
    const double e = m.Number("eccentricity", Bound::kNonNegative);
    if (e > 0.99) m.Fail("eccentricity", "must be in [0, 0.99], got " + FormatNumber(e));
    const double mu = m.OptionalNumber("mu_m3_s2", Bound::kPositive)
                          .value_or(dynamics::YamanakaAnkersenModel::kEarthMu);
    // Serra 2015 sec. 4.4 gives the mean motion, not the semi-major axis.
    const double a =
        m.Has("semi_major_axis_m")
            ? m.Number("semi_major_axis_m", Bound::kPositive)
            : std::cbrt(mu / std::pow(m.Number("mean_motion_rad_s", Bound::kPositive), 2));
    const double l = m.OptionalNumber("length_scale_m", Bound::kPositive).value_or(1000.0);
    m.ExactlyOneOf({"true_anomaly_at_epoch_rad", "true_anomaly_rad"}, /*required=*/false);
    double nu0 = m.OptionalNumber("true_anomaly_at_epoch_rad").value_or(0.0);
    if (m.Has("true_anomaly_rad")) {
      // The anomaly at another time (e.g. the horizon start): carried to the epoch.
      const double nu = m.Number("true_anomaly_rad");
      const double at = m.OptionalNumber("true_anomaly_time_s").value_or(0.0);
      nu0 = Wrap(m.FieldPath("true_anomaly_rad"), [&] {
        return dynamics::YamanakaAnkersenModel(a, e, mu, nu, l).TrueAnomalyAt(-at);
      });
    } else if (m.Has("true_anomaly_time_s")) {
      m.Fail("true_anomaly_time_s", "is only used with true_anomaly_rad");
    }
    s->problem.model = Wrap(m.path(), [&] {
      return std::make_shared<const dynamics::YamanakaAnkersenModel>(a, e, mu, nu0, l);
    });
  }
  m.Finish();
}

void ParseSpacecraft(JsonObject sc, Scenario* s) {
  const double mass = sc.Number("mass_kg", Bound::kPositive);
  const double isp = sc.Number("isp_s", Bound::kPositive);
  const double thrust = sc.Number("thrust_n", Bound::kPositive);
  JsonObject th = sc.Object("thrusters");
  th.ExactlyOneOf({"preset", "custom"}, /*required=*/true);
  dynamics::ThrusterSet set;
  if (th.Has("preset")) {
    const std::string preset = th.Choice("preset", {"ideal6", "anzel4"});
    double theta = 63.64, alpha = 7.03;
    if (preset == "anzel4") {
      theta = th.OptionalNumber("theta_deg").value_or(theta);
      alpha = th.OptionalNumber("alpha_deg").value_or(alpha);
      if (theta < 0.0 || theta > 90.0) {
        th.Fail("theta_deg", "must be in [0, 90], got " + FormatNumber(theta));
      }
      if (alpha < 0.0 || alpha > 90.0) {
        th.Fail("alpha_deg", "must be in [0, 90], got " + FormatNumber(alpha));
      }
    }
    set = Wrap(th.path(), [&] {
      return dynamics::ThrusterSet::FromPreset(preset, thrust, mass, isp, theta, alpha);
    });
    if (th.Has("use")) {
      const std::vector<std::string> use = th.StringArray("use");
      if (use.empty()) th.Fail("use", "selects no thruster (the thruster set would be empty)");
      set = Wrap(th.FieldPath("use"), [&] { return set.Subset(use); });
    }
  } else {
    std::vector<JsonObject> list = th.ObjectArray("custom");
    if (list.empty()) th.Fail("custom", "is empty (a thruster set needs at least one thruster)");
    std::vector<dynamics::Thruster> thrusters;
    for (JsonObject& t : list) {
      dynamics::Thruster x;
      x.name = t.String("name");
      if (!ValidThrusterName(x.name)) {
        t.Fail("name",
               "\"" + x.name +
                   "\" is not a valid thruster name (1-32 characters among A-Z a-z 0-9 + - _ .)");
      }
      const std::vector<double> d = t.NumberArray("direction_rtn", 3);
      x.direction = Eigen::Vector3d(d[0], d[1], d[2]);
      if (x.direction.norm() == 0.0) t.Fail("direction_rtn", "must not be the zero vector");
      t.Finish();
      thrusters.push_back(x);
    }
    set = Wrap(th.FieldPath("custom"),
               [&] { return dynamics::ThrusterSet(thrusters, thrust, mass, isp); });
  }
  th.Finish();
  if (sc.Has("disabled")) {
    const std::vector<std::string> disabled = sc.StringArray("disabled");
    for (size_t i = 0; i < disabled.size(); ++i) {
      bool found = false;
      for (const std::string& n : set.names()) found = found || n == disabled[i];
      if (!found) {
        throw ScenarioError(sc.FieldPath("disabled") + "[" + std::to_string(i) + "]: \"" +
                            disabled[i] + "\" is not a thruster (thrusters: " + Join(set.names()) +
                            ")");
      }
    }
    if (static_cast<int>(disabled.size()) == set.size()) {
      sc.Fail("disabled", "disables every thruster (" + Join(disabled) +
                              "): the usable thruster set would be empty");
    }
    set.Disable(disabled);
  }
  sc.Finish();
  s->problem.thrusters = set;
}

int ThrusterIndex(const Scenario& s, const std::string& name, const std::string& path) {
  const std::vector<std::string> names = s.problem.thrusters.names();
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  throw ScenarioError(path + ": \"" + name + "\" is not a thruster (thrusters: " + Join(names) +
                      ")");
}

void ParseHorizon(JsonObject h, Scenario* s) {
  const double start = h.OptionalNumber("start_s").value_or(0.0);
  if (std::abs(start) > kMaxAbsTime) {
    h.Fail("start_s", "must be within +-1e10 s, got " + FormatNumber(start));
  }
  const bool ya = s->model_type == ModelType::kYamanakaAnkersen;
  h.ExactlyOneOf(ya ? std::vector<std::string>{"duration_s", "end_true_anomaly_rad"}
                    : std::vector<std::string>{"duration_s"},
                 /*required=*/true);
  double duration = 0.0;
  if (h.Has("duration_s")) {
    duration = h.Number("duration_s", Bound::kPositive);
  } else {
    const double nu_f = h.Number("end_true_anomaly_rad");
    const auto& ya_model = static_cast<const dynamics::YamanakaAnkersenModel&>(*s->problem.model);
    const double t_end =
        Wrap(h.FieldPath("end_true_anomaly_rad"), [&] { return ya_model.TimeAtTrueAnomaly(nu_f); });
    duration = t_end - start;
    if (!(duration > 0.0)) {
      h.Fail("end_true_anomaly_rad", FormatNumber(nu_f) +
                                         " rad is reached at t = " + FormatNumber(t_end) +
                                         " s, not after start_s = " + FormatNumber(start) + " s");
    }
  }
  if (duration > kMaxDuration) {
    h.Fail("duration_s", "must be <= 1e9 s, got " + FormatNumber(duration));
  }
  h.ExactlyOneOf({"step_s", "num_intervals"}, /*required=*/true);
  int n = 0;
  if (h.Has("step_s")) {
    const double step = h.Number("step_s", Bound::kPositive);
    if (step > duration * (1 + kStepFitsRelativeSlack)) {
      h.Fail("step_s", FormatNumber(step) + " s is longer than the horizon (" +
                           FormatNumber(duration) + " s)");
    }
    const double ratio = duration / step;
    if (ratio > kMaxIntervals + 0.5) {
      h.Fail("step_s", FormatNumber(step) + " s gives " + FormatNumber(std::round(ratio)) +
                           " intervals; at most " + std::to_string(kMaxIntervals) + " are allowed");
    }
    const double rounded = std::round(ratio);
    if (std::abs(ratio - rounded) > kWholeStepsRelativeTolerance * std::max(1.0, ratio)) {
      h.Fail("step_s", FormatNumber(step) + " s does not divide the horizon duration " +
                           FormatNumber(duration) + " s (" + FormatNumber(ratio) + " steps)");
    }
    n = static_cast<int>(rounded);
  } else {
    n = h.Integer("num_intervals", 1, kMaxIntervals);
  }
  h.Finish();
  s->start_s = start;
  s->num_intervals = n;
  s->step_s = duration / n;
  s->problem.grid =
      Wrap(h.path(), [&] { return dynamics::UniformGrid(start, start + duration, n); });
}

void ParseWindow(JsonObject w, Scenario* s) {
  transcription::WindowSpec& win = s->problem.window;
  if (s->model_type == ModelType::kGeo) {
    const double deg = w.Number("half_width_deg", Bound::kPositive);
    if (deg > 90.0) w.Fail("half_width_deg", "must be <= 90, got " + FormatNumber(deg));
    win.outputs = {1, 2};  // latitude, longitude (rad)
    win.half_widths = {deg * kPi / 180.0, deg * kPi / 180.0};
    s->window_unit = "deg";
    s->window_unit_per_output_unit = 180.0 / kPi;
    s->window_half_widths = {deg, deg};
  } else {
    const double m = w.Number("half_width_m", Bound::kPositive);
    win.outputs = {1, 2};  // y (along-track), z (normal), m
    win.half_widths = {m, m};
    s->window_unit = "m";
    s->window_unit_per_output_unit = 1.0;
    s->window_half_widths = {m, m};
  }
  win.enforce_from_s = w.OptionalNumber("enforce_from_s").value_or(s->start_s);
  const double end = s->problem.grid.back();
  if (win.enforce_from_s > end) {
    w.Fail("enforce_from_s", FormatNumber(win.enforce_from_s) + " s is after the horizon end " +
                                 FormatNumber(end) + " s");
  }
  win.soft = w.OptionalBool("soft").value_or(false);
  if (auto p = w.OptionalNumber("soft_penalty", Bound::kPositive)) {
    if (!win.soft) w.Fail("soft_penalty", "is only used with \"soft\": true");
    win.soft_penalty = *p;
  }
  win.intersample_points = w.OptionalInteger("intersample_points", 0, 100).value_or(0);
  if (auto mg = w.OptionalNumber("margin", Bound::kNonNegative)) {
    if (*mg >= 1.0) w.Fail("margin", "must be in [0, 1), got " + FormatNumber(*mg));
    win.margin = *mg;
  }
  w.Finish();
}

void ParseOperations(JsonObject o, Scenario* s) {
  transcription::OperationalRules& r = s->problem.rules;
  r.max_simultaneous = o.OptionalInteger("max_simultaneous", 1, 64).value_or(1);
  r.min_burn_s = o.OptionalNumber("min_burn_s", Bound::kNonNegative).value_or(0.0);
  r.min_off_same_s = o.OptionalNumber("min_off_same_s", Bound::kNonNegative).value_or(0.0);
  r.min_gap_other_s = o.OptionalNumber("min_gap_other_s", Bound::kNonNegative).value_or(0.0);
  r.max_burn_s = o.OptionalNumber("max_burn_s", Bound::kPositive).value_or(kInf);
  r.max_burns_per_thruster = o.OptionalInteger("max_burns_per_thruster", 0, 1000000).value_or(-1);
  r.allow_burn_across_end = o.OptionalBool("allow_burn_across_end").value_or(false);
  if (r.max_burn_s < r.min_burn_s) {
    o.Fail("max_burn_s", FormatNumber(r.max_burn_s) + " s is shorter than min_burn_s " +
                             FormatNumber(r.min_burn_s) + " s");
  }
  o.Finish();
  std::string err;
  if (!r.IsValid(&err)) throw ScenarioError(o.path() + ": " + err);
}

// "min_time" (a string or an object's kind): the earliest arrival in the
// terminal section's set; the fuel of the second MILP is objective.fuel.
void ParseMinTimeObjective(JsonObject* o, Scenario* s) {
  transcription::MinTimeSpec spec;
  if (o != nullptr) {
    if (o->Has("fuel")) {
      s->problem.objective.kind =
          transcription::ParseObjectiveKind(o->Choice("fuel", {"l1", "delta_v", "propellant"}));
    }
    spec.hold = o->OptionalBool("hold").value_or(true);
    spec.fuel_budget = o->OptionalNumber("fuel_budget", Bound::kPositive).value_or(kInf);
    spec.minimise_fuel_after = o->OptionalBool("minimise_fuel_after").value_or(true);
  }
  s->min_time = spec;
}

void ParseObjective(JsonObject& top, Scenario* s) {
  if (!top.Has("objective")) return;  // default l1
  const nlohmann::json& v = top.Raw("objective");
  const std::vector<std::string> kinds = {"l1", "delta_v", "propellant", "min_time"};
  if (v.is_string()) {
    const std::string k = top.Choice("objective", kinds);
    if (k == "min_time") {
      ParseMinTimeObjective(nullptr, s);
    } else {
      s->problem.objective.kind = transcription::ParseObjectiveKind(k);
    }
    return;
  }
  if (!v.is_object()) {
    top.Fail("objective",
             "expected \"l1\", \"delta_v\", \"propellant\", \"min_time\" or an object, got " +
                 DescribeJson(v));
  }
  JsonObject o = top.Object("objective");
  const std::string k = o.Choice("kind", kinds);
  if (k == "min_time") {
    ParseMinTimeObjective(&o, s);
  } else {
    s->problem.objective.kind = transcription::ParseObjectiveKind(k);
  }
  s->problem.objective.burn_start_penalty =
      o.OptionalNumber("burn_start_penalty", Bound::kNonNegative).value_or(0.0);
  o.Finish();
}

// The target of "min_time" is the terminal section's set, which is then
// not imposed at t_N (with hold, the arrival rows keep it to the end).
void ResolveMinTimeTarget(JsonObject& top, Scenario* s) {
  if (!s->min_time) return;
  if (s->impulsive()) {
    top.Fail("objective",
             "\"min_time\" needs \"input_mode\": \"on_off\" (impulses have no duration to "
             "minimise)");
  }
  if (s->problem.conjunction) {
    top.Fail("objective", "\"min_time\" cannot be combined with a conjunction section");
  }
  if (s->build.formulation != transcription::Formulation::kSparse) {
    top.Fail("objective",
             "\"min_time\" needs transcription.formulation \"sparse\" (the "
             "arrival rows bound the state columns), got \"" +
                 std::string(transcription::ToString(s->build.formulation)) + "\"");
  }
  transcription::TerminalSpec& t = s->problem.terminal;
  if (t.kind != transcription::TerminalKind::kStateBox &&
      t.kind != transcription::TerminalKind::kFixedState) {
    top.Fail("objective",
             "\"min_time\" needs the target set in a terminal section of type "
             "\"state_box\" or \"fixed_state\"" +
                 std::string(top.Has("terminal") ? ", got another type" : ": there is none"));
  }
  s->min_time->target = t.target;
  s->min_time->tolerance = t.kind == transcription::TerminalKind::kStateBox
                               ? t.tolerance
                               : Eigen::VectorXd::Zero(t.target.size());
  t = transcription::TerminalSpec{};
  std::string err;
  if (!s->min_time->IsValid(s->problem, &err)) throw ScenarioError("scenario.objective: " + err);
}

std::vector<std::string> SchemeNames() {
  std::vector<std::string> out;
  for (dynamics::Scheme sc : dynamics::AllSchemes()) out.emplace_back(dynamics::ToString(sc));
  return out;
}

void ParseDiscretisation(JsonObject d, Scenario* s) {
  dynamics::DiscretizationOptions& o = s->build.discretisation;
  if (d.Has("scheme")) o.scheme = dynamics::ParseScheme(d.Choice("scheme", SchemeNames()));
  o.rk4_substeps = d.OptionalInteger("rk4_substeps", 1, 1000).value_or(1);
  if (auto tol = d.OptionalNumber("reference_tolerance", Bound::kPositive)) {
    if (*tol > 1e-3)
      d.Fail("reference_tolerance", "must be in (0, 1e-3], got " + FormatNumber(*tol));
    o.reference_tolerance = *tol;
  }
  d.Finish();
}

void ParseTranscription(JsonObject t, Scenario* s) {
  if (t.Has("formulation")) {
    s->build.formulation =
        transcription::ParseFormulation(t.Choice("formulation", {"sparse", "condensed"}));
  }
  if (t.Has("encoding")) {
    s->build.encoding = transcription::ParseEncoding(t.Choice("encoding", {"thesis", "tight"}));
  }
  s->build.scale = t.OptionalBool("scale").value_or(true);
  t.Finish();
}

void ParseSolver(JsonObject o, Scenario* s) {
  milp::SolveOptions& so = s->solve;
  if (auto t = o.OptionalNumber("time_limit_s", Bound::kPositive)) so.time_limit_s = *t;
  if (auto g = o.OptionalNumber("relative_gap", Bound::kNonNegative)) so.relative_gap = *g;
  if (auto g = o.OptionalNumber("absolute_gap", Bound::kNonNegative)) so.absolute_gap = *g;
  so.threads = o.OptionalInteger("threads", 1, 64).value_or(so.threads);
  so.random_seed = o.OptionalInteger("random_seed", 0, 2147483647).value_or(so.random_seed);
  so.log_level = o.OptionalInteger("log_level", 0, 3).value_or(so.log_level);
  so.presolve = o.OptionalBool("presolve").value_or(so.presolve);
  if (auto n = o.OptionalInteger("max_nodes", 0, 2147483647)) so.max_nodes = *n;
  if (auto p = o.OptionalNumber("progress_interval_s", Bound::kPositive))
    so.progress_interval_s = *p;
  if (auto d = o.OptionalNumber("diagnosis_time_limit_s", Bound::kNonNegative)) {
    s->diagnosis_time_limit_s = *d;
  }
  ParseSearch(o, "search", &s->search_options);
  s->search = s->search_options.enabled;
  o.Finish();
  std::string err;
  if (!so.IsValid(&err)) throw ScenarioError(o.path() + ": " + err);
}

void ParseHistory(JsonObject h, Scenario* s) {
  const int m = s->problem.thrusters.size();
  transcription::BoundaryHistory hist;
  hist.on_for_s.assign(m, 0.0);
  hist.off_for_s.assign(m, kInf);
  const nlohmann::json& raw = s->raw.at("history");
  for (auto it = raw.begin(); it != raw.end(); ++it) {
    const std::string key = it.key();
    const int i = ThrusterIndex(*s, key, h.FieldPath(key));
    JsonObject e = h.Object(key);
    e.ExactlyOneOf({"on_for_s", "off_for_s"}, /*required=*/true);
    if (auto on = e.OptionalNumber("on_for_s", Bound::kPositive)) hist.on_for_s[i] = *on;
    if (auto off = e.OptionalNumber("off_for_s", Bound::kNonNegative)) hist.off_for_s[i] = *off;
    e.Finish();
  }
  h.Finish();
  std::string err;
  if (!hist.IsValid(m, &err)) throw ScenarioError(h.path() + ": " + err);
  s->problem.history = hist;
}

void ParseForcedOff(JsonObject& top, Scenario* s) {
  for (JsonObject& f : top.ObjectArray("forced_off")) {
    transcription::ForcedOff x;
    x.thruster = ThrusterIndex(*s, f.String("thruster"), f.FieldPath("thruster"));
    x.start_s = f.Number("start_s");
    x.end_s = f.Number("end_s");
    if (!(x.end_s > x.start_s)) {
      f.Fail("end_s", "must be after start_s (" + FormatNumber(x.start_s) + " s), got " +
                          FormatNumber(x.end_s) + " s");
    }
    f.Finish();
    s->problem.forced_off.push_back(x);
  }
}

void ParseTerminal(JsonObject t, Scenario* s) {
  transcription::TerminalSpec& ts = s->problem.terminal;
  const int n = s->problem.model->num_states();
  const std::string type =
      t.Choice("type", {"free", "fixed_state", "state_box", "station_keeping"});
  if (type == "free") {
    ts.kind = transcription::TerminalKind::kFree;
  } else if (type == "fixed_state" || type == "state_box") {
    ts.kind = type == "fixed_state" ? transcription::TerminalKind::kFixedState
                                    : transcription::TerminalKind::kStateBox;
    ts.target = ReadState(t, s->model_type, n);
    if (type == "state_box") {
      const nlohmann::json& tol = t.Raw("tolerance");
      if (!tol.is_array() || static_cast<int>(tol.size()) != n) {
        t.Fail("tolerance", "expected an array of " + std::to_string(n) +
                                " numbers (null = unbounded), got " + DescribeJson(tol));
      }
      ts.tolerance.resize(n);
      for (int i = 0; i < n; ++i) {
        ts.tolerance[i] =
            tol[i].is_null()
                ? kInf
                : CheckedNumber(tol[i], t.FieldPath("tolerance") + "[" + std::to_string(i) + "]",
                                Bound::kNonNegative);
      }
    }
  } else {
    if (s->model_type != ModelType::kHcw && s->model_type != ModelType::kGeo) {
      t.Fail("type", "\"station_keeping\" needs an hcw or geo model, got " +
                         std::string(ToString(s->model_type)));
    }
    if (!s->problem.window.enabled()) {
      t.Fail("type", "\"station_keeping\" needs a window section");
    }
    ts.kind = transcription::TerminalKind::kStationKeepingSets;
    ts.facets_out_of_plane = t.OptionalInteger("facets_out_of_plane", 3, 1000).value_or(16);
    ts.facets_cone_plus = t.OptionalInteger("facets_cone_plus", 3, 1000).value_or(16);
    ts.facets_cone_minus = t.OptionalInteger("facets_cone_minus", 3, 1000).value_or(16);
    if (t.Has("lookahead_s"))
      ts.lookahead_s = t.NumberArray("lookahead_s", -1, Bound::kNonNegative);
    if (auto mg = t.OptionalNumber("margin", Bound::kNonNegative)) {
      if (*mg >= 1.0) t.Fail("margin", "must be in [0, 1), got " + FormatNumber(*mg));
      ts.margin = *mg;
    }
  }
  t.Finish();
}

// A number (every thruster) or an object {thruster name: bound} (unlisted
// thrusters unbounded), e.g. per-axis bounds with the ideal six thrusters.
void ParseMaxImpulse(JsonObject& top, Scenario* s) {
  if (!top.Raw("max_impulse_m_s").is_object()) {
    s->problem.max_impulse_m_s = top.Number("max_impulse_m_s", Bound::kPositive);
    return;
  }
  JsonObject o = top.Object("max_impulse_m_s");
  std::vector<double> bounds(s->problem.thrusters.size(), kInf);
  const nlohmann::json& raw = top.Raw("max_impulse_m_s");
  for (auto it = raw.begin(); it != raw.end(); ++it) {
    const int i = ThrusterIndex(*s, it.key(), o.FieldPath(it.key()));
    bounds[i] = o.Number(it.key(), Bound::kNonNegative);
  }
  o.Finish();
  s->problem.max_impulse_per_thruster_m_s = bounds;
}

void ParseCheck(JsonObject c, Scenario* s) {
  s->check.samples_per_interval = c.OptionalInteger("samples_per_interval", 0, 100).value_or(4);
  if (auto tol = c.OptionalNumber("propagation_tolerance", Bound::kPositive)) {
    if (*tol > 1e-6) {
      c.Fail("propagation_tolerance", "must be in (0, 1e-6], got " + FormatNumber(*tol));
    }
    s->check.propagation_tolerance = *tol;
  }
  if (auto w = c.OptionalNumber("window_tolerance", Bound::kNonNegative)) {
    s->verdict.window_tolerance = *w;
  }
  s->verdict.include_intersample = c.OptionalBool("include_intersample").value_or(false);
  if (s->model_type == ModelType::kGeo) {
    const bool nonlinear = c.OptionalBool("nonlinear").value_or(true);
    if (!nonlinear) {
      s->check.nonlinear.reset();
      s->check.nonlinear_default = false;
    }
    s->verdict.include_nonlinear = c.OptionalBool("include_nonlinear").value_or(false);
    if (s->verdict.include_nonlinear && !nonlinear) {
      c.Fail("include_nonlinear", "needs \"nonlinear\": true");
    }
  }
  c.Finish();
}

}  // namespace

std::string_view ToString(ModelType type) {
  switch (type) {
    case ModelType::kHcw:
      return "hcw";
    case ModelType::kGeo:
      return "geo";
    case ModelType::kDoubleIntegrator:
      return "double_integrator";
    case ModelType::kYamanakaAnkersen:
      return "yamanaka_ankersen";
    case ModelType::kSchweighartSedwick:
      return "schweighart_sedwick";
  }
  return "unknown";
}

std::vector<std::string> ScenarioSections() {
  return {"name",          "description",     "model",      "spacecraft", "initial_state",
          "horizon",       "window",          "operations", "objective",  "discretisation",
          "transcription", "solver",          "history",    "forced_off", "terminal",
          "input_mode",    "max_impulse_m_s", "check",      "conjunction"};
}

bool ScenarioParseOptions::IsValid(std::string* error) const {
  if (source.empty()) return common::Fail(error, "source must not be empty");
  const std::vector<std::string> known = ScenarioSections();
  for (size_t k = 0; k < extra_sections.size(); ++k) {
    const std::string& name = extra_sections[k];
    const std::string where = "extra_sections[" + std::to_string(k) + "]";
    if (name.empty()) return common::Fail(error, where + " must not be empty");
    if (std::find(known.begin(), known.end(), name) != known.end()) {
      return common::Fail(
          error, where + " \"" + name + "\" is a section the scenario parser reads itself");
    }
  }
  return true;
}

bool VerdictOptions::IsValid(std::string* error) const {
  if (!(window_tolerance >= 0.0) || !std::isfinite(window_tolerance)) {
    return common::Fail(
        error, "window_tolerance must be finite and >= 0, got " + FormatNumber(window_tolerance));
  }
  return true;
}

Scenario ParseScenario(const nlohmann::json& json, const ScenarioParseOptions& options) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument("ScenarioParseOptions: " + err);
  Scenario s;
  s.raw = json;
  JsonObject top(s.raw, "scenario");
  for (const std::string& extra : options.extra_sections) top.Accept(extra);

  s.name = top.String("name");
  if (s.name.empty()) top.Fail("name", "must not be empty");
  top.OptionalString("description");

  ParseModel(top.Object("model"), &s);
  ParseSpacecraft(top.Object("spacecraft"), &s);
  ParseHorizon(top.Object("horizon"), &s);
  ParseInitialState(top.Object("initial_state"), options, &s);

  // Input mode first: it decides which other sections make sense.
  if (top.Has("input_mode")) {
    if (top.Choice("input_mode", {"on_off", "impulsive"}) == "impulsive") {
      s.problem.input_mode = transcription::InputMode::kImpulsive;
    }
  }
  if (s.impulsive()) {
    if (top.Has("max_impulse_m_s")) ParseMaxImpulse(top, &s);
    for (const char* key : {"operations", "history", "forced_off"}) {
      if (top.Has(key)) top.Fail(key, "is not used with \"input_mode\": \"impulsive\"");
    }
  } else {
    if (top.Has("operations")) ParseOperations(top.Object("operations"), &s);
    if (top.Has("history")) ParseHistory(top.Object("history"), &s);
    if (top.Has("forced_off")) ParseForcedOff(top, &s);
  }

  if (top.Has("window")) ParseWindow(top.Object("window"), &s);
  ParseObjective(top, &s);
  if (top.Has("discretisation")) ParseDiscretisation(top.Object("discretisation"), &s);
  if (top.Has("transcription")) ParseTranscription(top.Object("transcription"), &s);
  if (top.Has("solver")) ParseSolver(top.Object("solver"), &s);
  if (top.Has("terminal")) ParseTerminal(top.Object("terminal"), &s);
  if (top.Has("conjunction")) ParseConjunction(top.Object("conjunction"), &s);
  ResolveMinTimeTarget(top, &s);

  // Checker: GEO schedules are also replayed through the nonlinear model by default.
  if (s.model_type == ModelType::kGeo) {
    s.check.nonlinear = std::make_shared<const dynamics::GeoSimulator>(*s.geo);
  }
  if (!s.window_half_widths.empty()) {
    s.verdict.window_tolerance = kDefaultWindowToleranceFraction *
                                 std::min(s.window_half_widths[0], s.window_half_widths[1]);
  }
  if (top.Has("check")) ParseCheck(top.Object("check"), &s);
  top.Finish();

  if (!s.verdict.IsValid(&err)) throw ScenarioError("scenario.check." + err);
  if (!s.problem.IsValid(&err)) throw ScenarioError("scenario: " + err);
  return s;
}

Scenario ParseScenarioText(std::string_view text, const ScenarioParseOptions& options) {
  return ParseScenario(ParseJsonText(text, options.source), options);
}

Scenario LoadScenario(const std::string& path, const ScenarioParseOptions& options) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ScenarioError(path + ": is a folder, not a scenario file (give a .json file, e.g. " +
                        (std::filesystem::path(path) / "geo_week_anzel4.json").string() + ")");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot open the scenario file");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw ScenarioError(path + ": cannot read the scenario file");
  ScenarioParseOptions o = options;
  o.source = path;
  Scenario s = ParseScenarioText(ss.str(), o);
  s.path = path;
  return s;
}

void ApplyOverrides(const ScenarioOverrides& ov, Scenario* s) {
  if (ov.no_diagnose) s->diagnosis_time_limit_s = 0.0;
  if (ov.no_search) s->search = false;
  if (ov.time_limit_s) {
    if (!(*ov.time_limit_s > 0.0) || std::isnan(*ov.time_limit_s)) {
      throw ScenarioError("--time-limit: must be > 0, got " + FormatNumber(*ov.time_limit_s));
    }
    s->solve.time_limit_s = *ov.time_limit_s;
  }
  if (ov.relative_gap) {
    if (!(*ov.relative_gap >= 0.0) || !std::isfinite(*ov.relative_gap)) {
      throw ScenarioError("--gap: must be finite and >= 0, got " + FormatNumber(*ov.relative_gap));
    }
    s->solve.relative_gap = *ov.relative_gap;
  }
  if (ov.threads) {
    if (*ov.threads < 1 || *ov.threads > 64) {
      throw ScenarioError("--threads: must be in [1, 64], got " + std::to_string(*ov.threads));
    }
    s->solve.threads = *ov.threads;
  }
  if (ov.scheme) {
    s->build.discretisation.scheme =
        Wrap("--scheme", [&] { return dynamics::ParseScheme(*ov.scheme); });
  }
  if (ov.formulation) {
    s->build.formulation =
        Wrap("--formulation", [&] { return transcription::ParseFormulation(*ov.formulation); });
    if (s->min_time && s->build.formulation != transcription::Formulation::kSparse) {
      throw ScenarioError(
          "--formulation: \"min_time\" needs \"sparse\" (the arrival rows "
          "bound the state columns), got \"" +
          *ov.formulation + "\"");
    }
  }
  if (ov.encoding) {
    s->build.encoding =
        Wrap("--encoding", [&] { return transcription::ParseEncoding(*ov.encoding); });
  }
}

}  // namespace thrustsched::app
