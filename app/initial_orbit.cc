#include "app/initial_orbit.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/ccsds_opm.h"
#include "common/constants.h"
#include "dynamics/geo_model.h"
#include "dynamics/keplerian.h"

namespace thrustsched::app {
namespace {

constexpr double kDeg = common::kDegToRad;
// Orbits further than this from the station point are not GEO station
// keeping: the linearised model of the thesis would be meaningless there.
constexpr double kMaxRelativeA = 0.05;  // |a - a_mp| / a_mp
constexpr double kMaxEccentricity = 0.05;
constexpr double kMaxInclinationDeg = 15.0;

std::string ReadText(const std::string& path, const std::string& field) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(field + ": cannot open the OPM file " + path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

InitialOrbit FromOpm(JsonObject o, const std::string& base_dir) {
  InitialOrbit out;
  out.form = "opm";
  const std::string file = o.String("file");
  const std::filesystem::path p(file);
  out.file =
      p.is_absolute() || base_dir.empty() ? file : (std::filesystem::path(base_dir) / p).string();
  const std::string use =
      o.Has("use") ? o.Choice("use", {"state_vector", "keplerian"}) : "state_vector";
  o.Finish();
  const Opm opm = ParseOpm(ReadText(out.file, o.FieldPath("file")), out.file);
  if (!opm.maneuvers.empty()) {
    throw ScenarioError(
        o.FieldPath("file") + ": " + out.file + " holds " + std::to_string(opm.maneuvers.size()) +
        " maneuver block(s): an initial state must not (thrustsched plans the burns itself; remove "
        "them or give the state after them)");
  }
  out.object_name = opm.object_name;
  out.object_id = opm.object_id;
  out.given = {opm.epoch, opm.frame, opm.rv};
  if (use == "keplerian") {
    if (!opm.keplerian) {
      throw ScenarioError(o.FieldPath("use") + ": \"keplerian\" but " + out.file +
                          " has no Keplerian elements");
    }
    out.given.rv =
        dynamics::CartesianFromKeplerian(opm.keplerian->elements, opm.keplerian->gm_m3_s2);
  }
  return out;
}

// The fields the inline forms share: their frame and epoch.
InitialOrbit Inline(JsonObject& o, const char* form, const dynamics::Epoch& start) {
  InitialOrbit out;
  out.form = form;
  out.given.frame = *dynamics::ParseInertialFrame(o.Choice("frame", {"EME2000", "GCRF"}));
  const std::optional<std::string> text = o.OptionalString("epoch");
  out.given.epoch =
      text ? Wrap(o.FieldPath("epoch"), [&] { return dynamics::Epoch::Parse(*text); }) : start;
  return out;
}

InitialOrbit FromEciState(JsonObject o, const dynamics::Epoch& start) {
  InitialOrbit out = Inline(o, "eci_state", start);
  const std::vector<double> r = o.NumberArray("position_km", 3);
  const std::vector<double> v = o.NumberArray("velocity_km_s", 3);
  o.Finish();
  out.given.rv << r[0], r[1], r[2], v[0], v[1], v[2];
  out.given.rv *= 1e3;
  return out;
}

InitialOrbit FromKeplerian(JsonObject o, const dynamics::Epoch& start) {
  InitialOrbit out = Inline(o, "keplerian", start);
  dynamics::KeplerianElements k;
  k.a_m = o.Number("semi_major_axis_km", Bound::kPositive) * 1e3;
  k.e = o.Number("eccentricity", Bound::kNonNegative);
  if (k.e >= 1.0) o.Fail("eccentricity", "must be in [0, 1), got " + FormatNumber(k.e));
  const double i_deg = o.Number("inclination_deg", Bound::kNonNegative);
  if (i_deg >= 180.0) o.Fail("inclination_deg", "must be in [0, 180), got " + FormatNumber(i_deg));
  k.i_rad = i_deg * kDeg;
  k.raan_rad = o.Number("ra_of_asc_node_deg") * kDeg;
  k.arg_perigee_rad = o.Number("arg_of_pericenter_deg") * kDeg;
  o.ExactlyOneOf({"true_anomaly_deg", "mean_anomaly_deg"}, /*required=*/true);
  k.anomaly =
      o.Has("mean_anomaly_deg") ? dynamics::AnomalyKind::kMean : dynamics::AnomalyKind::kTrue;
  k.anomaly_rad = o.Number(k.anomaly == dynamics::AnomalyKind::kMean ? "mean_anomaly_deg"
                                                                     : "true_anomaly_deg") *
                  kDeg;
  const double gm =
      o.OptionalNumber("gm_km3_s2", Bound::kPositive).value_or(dynamics::geo::kEarthMu / 1e9) * 1e9;
  o.Finish();
  out.given.rv = Wrap(o.path(), [&] { return dynamics::CartesianFromKeplerian(k, gm); });
  return out;
}

void CheckNearStation(const std::string& path, const Eigen::VectorXd& x) {
  const double a_mp = dynamics::geo::kStationRadius;
  const double e = std::hypot(x(1), x(2));
  const double i_deg = 2.0 * std::atan(std::hypot(x(3), x(4))) / kDeg;
  if (std::abs(x(0)) > kMaxRelativeA * a_mp || e > kMaxEccentricity || i_deg > kMaxInclinationDeg) {
    std::ostringstream os;
    os << path
       << ": not a near-geostationary orbit at the horizon start (a = " << (a_mp + x(0)) / 1e3
       << " km, e = " << e << ", i = " << i_deg << " deg; the GEO model needs |a - " << a_mp / 1e3
       << " km| <= " << kMaxRelativeA * a_mp / 1e3 << " km, e <= " << kMaxEccentricity
       << ", i <= " << kMaxInclinationDeg << " deg)";
    throw ScenarioError(os.str());
  }
}

}  // namespace

const std::vector<std::string>& OrbitForms() {
  static const std::vector<std::string> kForms = {"opm", "eci_state", "keplerian"};
  return kForms;
}

bool HasOrbitForm(JsonObject& init) {
  bool any = false;
  for (const std::string& f : OrbitForms()) any = init.Has(f) || any;
  return any;
}

InitialOrbit ReadOrbitAsGiven(JsonObject& init, const dynamics::Epoch& default_epoch,
                              const std::string& base_dir) {
  if (init.Has("opm")) return FromOpm(init.Object("opm"), base_dir);
  if (init.Has("eci_state")) return FromEciState(init.Object("eci_state"), default_epoch);
  return FromKeplerian(init.Object("keplerian"), default_epoch);
}

InitialOrbit ReadInitialOrbit(JsonObject& init, const dynamics::GeoSimulator& sim, double t_start,
                              const std::string& base_dir) {
  const dynamics::Epoch start = dynamics::Epoch::Parse(sim.options().epoch).PlusSeconds(t_start);
  InitialOrbit out = ReadOrbitAsGiven(init, start, base_dir);
  const std::string path = init.FieldPath(out.form);
  if (out.given.epoch.SecondsSince(start) > 0) {
    throw ScenarioError(path + ": the state's epoch " + out.given.epoch.ToIso8601() +
                        " is after the horizon start " + start.ToIso8601() +
                        " (states are propagated forward to the start, never backward)");
  }
  // Checked at the state's own epoch first, so that no far-off orbit is propagated.
  const dynamics::Epoch model_epoch = dynamics::Epoch::Parse(sim.options().epoch);
  CheckNearStation(path, Wrap(path, [&] {
                     return sim.RelativeFromEci(
                         dynamics::ToModelFrame(out.given.rv, out.given.frame, model_epoch),
                         out.given.epoch.SecondsSince(model_epoch));
                   }));
  out.relative_state =
      Wrap(path, [&] { return dynamics::RelativeStateFromOrbit(sim, out.given, t_start); });
  return out;
}

}  // namespace thrustsched::app
