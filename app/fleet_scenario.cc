#include "app/fleet_scenario.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

namespace thrustsched::app {
namespace {

namespace fs = std::filesystem;
using transcription::FleetProblem;

// A member's scenario, inline or from a path relative to the fleet file.
Scenario ReadMemberScenario(JsonObject& m, const std::string& base_dir) {
  const nlohmann::json& v = m.Raw("scenario");
  const std::string field = m.FieldPath("scenario");
  try {
    if (v.is_string()) {
      const fs::path p(v.get<std::string>());
      return LoadScenario(p.is_absolute() ? p.string() : (fs::path(base_dir) / p).string());
    }
    if (v.is_object()) return ParseScenario(v);
  } catch (const ScenarioError& e) {
    throw ScenarioError(field + ": " + e.what());
  }
  m.Fail("scenario",
         "expected a scenario file path or an inline scenario object, got " + DescribeJson(v));
}

// What a fleet member may be (the file comment), named by its field. GEO
// members are positioned about their station point (radial, east, north), so
// they share it: the first member's station longitude and epoch.
void CheckMember(const Scenario& s, const Scenario* first, JsonObject& m) {
  const auto refuse = [&](const std::string& why) { m.Fail("scenario", why); };
  if (s.impulsive()) refuse("a fleet member needs \"input_mode\": \"on_off\"");
  if (s.geo && first != nullptr && first->geo) {
    const dynamics::GeoModelOptions& a = *first->geo;
    const dynamics::GeoModelOptions& b = *s.geo;
    if (a.station_longitude_deg != b.station_longitude_deg || a.epoch != b.epoch) {
      refuse("GEO members share one station point: model.station_longitude_deg " +
             FormatNumber(b.station_longitude_deg) + " and epoch " + b.epoch +
             " differ from the first member's " + FormatNumber(a.station_longitude_deg) + " and " +
             a.epoch);
    }
  }
  if (s.problem.conjunction) refuse("a fleet member cannot have a conjunction section");
  if (s.min_time) refuse("a fleet member cannot have the \"min_time\" objective");
  if (s.build.formulation != transcription::Formulation::kSparse) {
    refuse(
        "a fleet member needs transcription.formulation \"sparse\" (the couplings are "
        "written on the state columns)");
  }
}

int MemberIndexOf(const FleetScenario& f, JsonObject& o, std::string_view key) {
  const std::string name = o.String(key);
  const int k = f.problem.MemberIndex(name);
  if (k < 0) o.Fail(key, "no member named \"" + name + "\"");
  return k;
}

// "position" (the first three states, metres), "state" (all of them) or a
// matrix with the state size as its row length.
Eigen::MatrixXd ReadMap(JsonObject& o, const FleetScenario& f) {
  const int n = f.members.front().problem.model->num_states();
  const nlohmann::json& v = o.Raw("map");
  if (v.is_string()) {
    const std::string k = o.Choice("map", {"position", "state"});
    if (k == "position" && f.members.front().geo) {
      o.Fail("map",
             "\"position\" is the first three states; a GEO member's position depends on "
             "time: give \"state\" or a matrix of rows of 6 numbers");
    }
    return k == "state" ? Eigen::MatrixXd::Identity(n, n).eval()
                        : Eigen::MatrixXd::Identity(n, n).topRows(3).eval();
  }
  if (!v.is_array() || v.empty()) {
    o.Fail("map", "expected \"position\", \"state\" or a non-empty array of rows of " +
                      std::to_string(n) + " numbers, got " + DescribeJson(v));
  }
  return o.NumberMatrix("map", -1, n);
}

Eigen::VectorXd ReadVector(JsonObject& o, std::string_view key, int size, Bound bound) {
  const std::vector<double> v = o.NumberArray(key, size, bound);
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<int>(v.size()));
}

void ParseCouplings(JsonObject& fleet, FleetScenario* f) {
  for (JsonObject& c : fleet.ObjectArray("couplings")) {
    transcription::TerminalCoupling tc;
    tc.member = MemberIndexOf(*f, c, "member");
    tc.reference = c.Has("reference") ? MemberIndexOf(*f, c, "reference") : -1;
    if (tc.reference == tc.member) c.Fail("reference", "is the member itself");
    tc.map = ReadMap(c, *f);
    tc.offset = ReadVector(c, "offset", static_cast<int>(tc.map.rows()), Bound::kAny);
    if (c.Has("tolerance")) {
      tc.tolerance =
          ReadVector(c, "tolerance", static_cast<int>(tc.map.rows()), Bound::kNonNegative);
    }
    c.Finish();
    f->problem.couplings.push_back(std::move(tc));
  }
}

void ParseBalance(JsonObject& fleet, FleetScenario* f) {
  transcription::FuelBalance& b = f->problem.balance;
  const std::vector<std::string> kinds = {"none", "max_excess_over_mean", "min_max"};
  if (fleet.Raw("balance").is_string()) {
    b.kind = transcription::ParseFuelBalanceKind(fleet.Choice("balance", kinds));
    return;
  }
  JsonObject o = fleet.Object("balance");
  b.kind = transcription::ParseFuelBalanceKind(o.Choice("kind", kinds));
  if (b.kind == transcription::FuelBalanceKind::kMaxExcessOverMean) {
    b.max_excess_fraction =
        o.OptionalNumber("max_excess_fraction", Bound::kNonNegative).value_or(0.1);
  }
  if (b.kind == transcription::FuelBalanceKind::kMinMax) {
    b.sum_weight = o.OptionalNumber("sum_weight", Bound::kNonNegative).value_or(1e-3);
  }
  o.Finish();
}

void ParseKeepOut(JsonObject o, FleetScenario* f) {
  transcription::FleetKeepOut k;
  k.half_size_m = o.Number("half_size_m", Bound::kPositive);
  if (o.Has("instantaneous_threshold")) {
    k.instantaneous_threshold = o.Number("instantaneous_threshold", Bound::kPositive);
    if (!(k.instantaneous_threshold < 0.5)) {
      o.Fail("instantaneous_threshold",
             "must be in (0, 0.5), got " + FormatNumber(k.instantaneous_threshold));
    }
  }
  const std::vector<double>& grid = f->members.front().problem.grid;
  o.ExactlyOneOf({"check_step_s", "check_times_s"}, /*required=*/true);
  if (o.Has("check_times_s")) {
    k.check_times_s = o.NumberArray("check_times_s", -1, Bound::kAny);
    for (size_t q = 0; q < k.check_times_s.size(); ++q) {
      const double t = k.check_times_s[q];
      if (t < grid.front() || t > grid.back() || (q > 0 && t <= k.check_times_s[q - 1])) {
        o.Fail("check_times_s", "[" + std::to_string(q) + "] = " + FormatNumber(t) +
                                    " s: the times must increase inside the horizon [" +
                                    FormatNumber(grid.front()) + ", " + FormatNumber(grid.back()) +
                                    "] s");
      }
    }
  } else {
    const double step = o.Number("check_step_s", Bound::kPositive);
    const double span = grid.back() - grid.front();
    if (span / step > kMaxIntervals) {
      o.Fail("check_step_s", FormatNumber(step) + " s gives more than " +
                                 std::to_string(kMaxIntervals) + " checks");
    }
    for (int q = 1; grid.front() + q * step <= grid.back() + 1e-9 * span; ++q) {
      k.check_times_s.push_back(std::min(grid.back(), grid.front() + q * step));
    }
  }
  o.Finish();
  f->problem.keep_out = std::move(k);
}

void ParseAssignment(JsonObject o, FleetScenario* f) {
  transcription::SlotAssignment a;
  const std::vector<std::string> names = o.StringArray("members");
  for (const std::string& name : names) {
    const int k = f->problem.MemberIndex(name);
    if (k < 0) o.Fail("members", "no member named \"" + name + "\"");
    a.members.push_back(k);
  }
  a.reference = o.Has("reference") ? MemberIndexOf(*f, o, "reference") : -1;
  a.map = ReadMap(o, *f);
  const nlohmann::json& slots = o.Raw("slots");
  if (!slots.is_array() || slots.size() != names.size()) {
    o.Fail("slots", "expected one slot per member (" + std::to_string(names.size()) + "), got " +
                        DescribeJson(slots));
  }
  for (size_t s = 0; s < slots.size(); ++s) {
    const std::string path = o.FieldPath("slots") + "[" + std::to_string(s) + "]";
    if (!slots[s].is_array() || static_cast<int>(slots[s].size()) != a.map.rows()) {
      throw ScenarioError(path + ": expected " + std::to_string(a.map.rows()) +
                          " numbers (the map's rows), got " + DescribeJson(slots[s]));
    }
    Eigen::VectorXd v(a.map.rows());
    for (int r = 0; r < v.size(); ++r)
      v[r] = CheckedNumber(slots[s][r], path + "[" + std::to_string(r) + "]", Bound::kAny);
    a.slots.push_back(v);
  }
  if (o.Has("tolerance"))
    a.tolerance = ReadVector(o, "tolerance", static_cast<int>(a.map.rows()), Bound::kNonNegative);
  o.Finish();
  f->problem.assignment = std::move(a);
}

void ParseFleetSolver(JsonObject o, FleetScenario* f) {
  milp::SolveOptions& so = f->options.milp;
  if (auto t = o.OptionalNumber("time_limit_s", Bound::kPositive)) so.time_limit_s = *t;
  if (auto g = o.OptionalNumber("relative_gap", Bound::kNonNegative)) so.relative_gap = *g;
  so.threads = o.OptionalInteger("threads", 1, 64).value_or(so.threads);
  so.random_seed = o.OptionalInteger("random_seed", 0, 2147483647).value_or(so.random_seed);
  o.Finish();
}

// "initial_covariance" (n x n, SI) or "initial_std" (n standard deviations:
// a diagonal covariance), or neither (the initial state is known exactly).
Eigen::MatrixXd ReadInitialCovariance(JsonObject& m, int n) {
  m.ExactlyOneOf({"initial_covariance", "initial_std"}, /*required=*/false);
  if (m.Has("initial_std")) {
    const Eigen::VectorXd sd = ReadVector(m, "initial_std", n, Bound::kNonNegative);
    return sd.array().square().matrix().asDiagonal();
  }
  if (!m.Has("initial_covariance")) return Eigen::MatrixXd();
  // Symmetry and definiteness: FleetProblem::IsValid, naming the member.
  return m.NumberMatrix("initial_covariance", n, n);
}

void ParseMonteCarlo(JsonObject o, FleetScenario* f) {
  transcription::FleetMonteCarloOptions& mc = f->options.monte_carlo;
  mc.samples = o.OptionalInteger("samples", 0, 10000000).value_or(mc.samples);
  mc.seed = static_cast<std::uint64_t>(
      o.OptionalInteger("seed", 0, 2147483647).value_or(static_cast<int>(mc.seed)));
  mc.steps = o.OptionalInteger("steps", 1, kMaxIntervals).value_or(mc.steps);
  o.Finish();
}

void ParseMembers(JsonObject& fleet, const std::string& base_dir, FleetScenario* f) {
  std::vector<JsonObject> members = fleet.ObjectArray("members");
  if (members.size() < 2) {
    fleet.Fail("members",
               "a fleet needs at least 2 members, got " + std::to_string(members.size()));
  }
  for (JsonObject& m : members) {
    const std::string name = m.String("name");
    if (name.empty() || name.find_first_of(". ,") != std::string::npos) {
      m.Fail("name",
             "must be non-empty without '.', ',' or spaces (it prefixes the member's "
             "columns and file names), got \"" +
                 name + "\"");
    }
    if (f->problem.MemberIndex(name) >= 0) m.Fail("name", "\"" + name + "\" is used twice");
    Scenario s = ReadMemberScenario(m, base_dir);
    CheckMember(s, f->members.empty() ? nullptr : &f->members.front(), m);
    Eigen::MatrixXd covariance = ReadInitialCovariance(m, s.problem.model->num_states());
    m.Finish();
    f->problem.members.push_back({name, s.problem, std::move(covariance)});
    f->members.push_back(std::move(s));
  }
}

}  // namespace

bool IsFleetDocument(const nlohmann::json& document) {
  return document.is_object() && document.contains("fleet");
}

bool IsFleetFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  try {
    return IsFleetDocument(ParseJsonText(ss.str(), path));
  } catch (const ScenarioError&) {
    return false;
  }
}

FleetScenario ParseFleetScenario(const nlohmann::json& document, const std::string& base_dir) {
  FleetScenario f;
  f.raw = document;
  JsonObject top(f.raw, "fleet scenario");
  f.name = top.String("name");
  if (f.name.empty()) top.Fail("name", "must not be empty");
  top.OptionalString("description");
  JsonObject fleet(f.raw.at("fleet"), "fleet");
  top.Accept("fleet");
  top.Finish();

  ParseMembers(fleet, base_dir, &f);
  f.options.build = f.members.front().build;
  f.options.checker = f.members.front().check;
  if (fleet.Has("couplings")) ParseCouplings(fleet, &f);
  if (fleet.Has("balance")) ParseBalance(fleet, &f);
  if (fleet.Has("keep_out")) ParseKeepOut(fleet.Object("keep_out"), &f);
  if (fleet.Has("assignment")) ParseAssignment(fleet.Object("assignment"), &f);
  if (fleet.Has("solver")) ParseFleetSolver(fleet.Object("solver"), &f);
  if (fleet.Has("monte_carlo")) {
    if (!f.problem.keep_out || !f.problem.HasInitialCovariance()) {
      fleet.Fail("monte_carlo",
                 "needs a keep_out and a member with initial_covariance or initial_std (it samples "
                 "the initial states)");
    }
    ParseMonteCarlo(fleet.Object("monte_carlo"), &f);
  }
  fleet.Finish();
  std::string err;
  if (!f.problem.IsValid(&err)) throw ScenarioError("fleet: " + err);
  if (!f.options.milp.IsValid(&err)) throw ScenarioError("fleet.solver: " + err);
  return f;
}

FleetScenario LoadFleetScenario(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot open the fleet scenario file");
  std::ostringstream ss;
  ss << in.rdbuf();
  FleetScenario f =
      ParseFleetScenario(ParseJsonText(ss.str(), path), fs::path(path).parent_path().string());
  f.path = path;
  return f;
}

void ApplyFleetOverrides(const ScenarioOverrides& ov, FleetScenario* f) {
  if (ov.scheme || ov.formulation || ov.encoding || ov.no_search || ov.no_diagnose) {
    throw ScenarioError(
        "--scheme, --formulation, --encoding, --no-search and --no-diagnose do not apply to a "
        "fleet (set them in the member scenarios; the fleet is solved as one MILP)");
  }
  Scenario probe;  // the checks and messages of ApplyOverrides
  probe.solve = f->options.milp;
  ApplyOverrides(ov, &probe);
  f->options.milp = probe.solve;
}

}  // namespace thrustsched::app
