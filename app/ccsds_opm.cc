#include "app/ccsds_opm.h"

#include <map>
#include <sstream>

#include "app/ccsds_kvn.h"
#include "common/constants.h"

namespace thrustsched::app {
namespace {

constexpr double kDeg = common::kDegToRad;

// Logical blocks of an OPM, in the order §3.2 prescribes.
enum Block {
  kHeader,
  kMetadata,
  kState,
  kKeplerian,
  kSpacecraft,
  kCovariance,
  kManeuver,
  kUserDefined
};

bool IsCovarianceKeyword(const std::string& k) {
  if (k == "COV_REF_FRAME") return true;
  // CX_X ... CZ_DOT_Z_DOT: 'C', an axis, optional _DOT, '_', an axis, optional _DOT.
  static const char* kAxes[] = {"X", "Y", "Z", "X_DOT", "Y_DOT", "Z_DOT"};
  for (const char* a : kAxes) {
    for (const char* b : kAxes) {
      if (k == std::string("C") + a + "_" + b) return true;
    }
  }
  return false;
}

std::optional<Block> BlockOf(const std::string& k) {
  static const std::map<std::string, Block> kBlocks = {{"CREATION_DATE", kHeader},
                                                       {"ORIGINATOR", kHeader},
                                                       {"MESSAGE_ID", kHeader},
                                                       {"CLASSIFICATION", kHeader},
                                                       {"OBJECT_NAME", kMetadata},
                                                       {"OBJECT_ID", kMetadata},
                                                       {"CENTER_NAME", kMetadata},
                                                       {"REF_FRAME", kMetadata},
                                                       {"REF_FRAME_EPOCH", kMetadata},
                                                       {"TIME_SYSTEM", kMetadata},
                                                       {"EPOCH", kState},
                                                       {"X", kState},
                                                       {"Y", kState},
                                                       {"Z", kState},
                                                       {"X_DOT", kState},
                                                       {"Y_DOT", kState},
                                                       {"Z_DOT", kState},
                                                       {"SEMI_MAJOR_AXIS", kKeplerian},
                                                       {"ECCENTRICITY", kKeplerian},
                                                       {"INCLINATION", kKeplerian},
                                                       {"RA_OF_ASC_NODE", kKeplerian},
                                                       {"ARG_OF_PERICENTER", kKeplerian},
                                                       {"TRUE_ANOMALY", kKeplerian},
                                                       {"MEAN_ANOMALY", kKeplerian},
                                                       {"GM", kKeplerian},
                                                       {"MASS", kSpacecraft},
                                                       {"SOLAR_RAD_AREA", kSpacecraft},
                                                       {"SOLAR_RAD_COEFF", kSpacecraft},
                                                       {"DRAG_AREA", kSpacecraft},
                                                       {"DRAG_COEFF", kSpacecraft},
                                                       {"MAN_EPOCH_IGNITION", kManeuver},
                                                       {"MAN_DURATION", kManeuver},
                                                       {"MAN_DELTA_MASS", kManeuver},
                                                       {"MAN_REF_FRAME", kManeuver},
                                                       {"MAN_DV_1", kManeuver},
                                                       {"MAN_DV_2", kManeuver},
                                                       {"MAN_DV_3", kManeuver}};
  auto it = kBlocks.find(k);
  if (it != kBlocks.end()) return it->second;
  if (IsCovarianceKeyword(k)) return kCovariance;
  if (k.rfind("USER_DEFINED_", 0) == 0) return kUserDefined;
  return std::nullopt;
}

using Keys = std::map<std::string, KvnLine>;

struct ManeuverLines {
  std::vector<std::string> comments;
  Keys keys;
  int first_line = 0;
};

// The OPM's keyword lines sorted into blocks (order and repetitions checked).
struct OpmLines {
  Keys single;  // every block except the maneuvers
  std::vector<std::string> header_comments, state_comments;
  std::vector<ManeuverLines> maneuvers;
};

OpmLines Sort(const std::string& source, const std::vector<KvnLine>& lines) {
  OpmLines out;
  Block current = kHeader;
  std::vector<std::string> pending;  // comments waiting for the next keyword's block
  for (size_t i = 1; i < lines.size(); ++i) {
    const KvnLine& l = lines[i];
    if (l.kind == KvnLine::kComment) {
      pending.push_back(l.value);
      continue;
    }
    if (l.kind != KvnLine::kKeyValue)
      KvnFail(source, l, "an OPM holds only KEYWORD = value lines and comments");
    const std::optional<Block> b = BlockOf(l.keyword);
    if (!b) KvnFail(source, l, "unknown OPM keyword");
    if (*b < current)
      KvnFail(source, l,
              "out of order (the OPM blocks are header, metadata, state vector, Keplerian "
              "elements, spacecraft parameters, covariance, maneuvers, user-defined)");
    current = *b;
    if (*b == kManeuver) {
      if (l.keyword == "MAN_EPOCH_IGNITION")
        out.maneuvers.push_back({std::move(pending), {}, l.number});
      if (out.maneuvers.empty())
        KvnFail(source, l, "a maneuver block starts with MAN_EPOCH_IGNITION");
      ManeuverLines& m = out.maneuvers.back();
      if (l.keyword != "MAN_EPOCH_IGNITION")
        m.comments.insert(m.comments.end(), pending.begin(), pending.end());
      if (!m.keys.emplace(l.keyword, l).second)
        KvnFail(source, l, "repeated in the maneuver block");
    } else {
      auto& sink = *b == kHeader ? out.header_comments : out.state_comments;
      if (*b == kHeader || *b == kState) sink.insert(sink.end(), pending.begin(), pending.end());
      if (!out.single.emplace(l.keyword, l).second) KvnFail(source, l, "repeated");
    }
    pending.clear();
  }
  return out;
}

const KvnLine& Need(const std::string& source, const Keys& keys, const char* keyword,
                    const char* block) {
  auto it = keys.find(keyword);
  if (it == keys.end())
    throw ScenarioError(source + ": the " + block + " lacks the mandatory keyword " + keyword);
  return it->second;
}

OpmKeplerian ReadKeplerian(const std::string& source, const Keys& k) {
  OpmKeplerian out;
  dynamics::KeplerianElements& e = out.elements;
  const char* block = "Keplerian elements block";
  e.a_m = KvnNumber(source, Need(source, k, "SEMI_MAJOR_AXIS", block), "km") * 1e3;
  e.e = KvnNumber(source, Need(source, k, "ECCENTRICITY", block), "");
  e.i_rad = KvnNumber(source, Need(source, k, "INCLINATION", block), "deg") * kDeg;
  e.raan_rad = KvnNumber(source, Need(source, k, "RA_OF_ASC_NODE", block), "deg") * kDeg;
  e.arg_perigee_rad = KvnNumber(source, Need(source, k, "ARG_OF_PERICENTER", block), "deg") * kDeg;
  const bool mean = k.count("MEAN_ANOMALY") > 0;
  if (mean && k.count("TRUE_ANOMALY") > 0) {
    KvnFail(source, k.at("MEAN_ANOMALY"), "give TRUE_ANOMALY or MEAN_ANOMALY, not both");
  }
  if (!mean && k.count("TRUE_ANOMALY") == 0) {
    throw ScenarioError(source +
                        ": the Keplerian elements block lacks TRUE_ANOMALY or MEAN_ANOMALY");
  }
  e.anomaly = mean ? dynamics::AnomalyKind::kMean : dynamics::AnomalyKind::kTrue;
  e.anomaly_rad = KvnNumber(source, k.at(mean ? "MEAN_ANOMALY" : "TRUE_ANOMALY"), "deg") * kDeg;
  const KvnLine& gm = Need(source, k, "GM", block);
  out.gm_m3_s2 = KvnNumber(source, gm, "km**3/s**2") * 1e9;
  if (!(out.gm_m3_s2 > 0)) KvnFail(source, gm, "must be > 0");
  try {
    dynamics::EquinoctialFromKeplerian(e);  // range checks (a > 0, 0 <= e < 1, 0 <= i < 180 deg)
  } catch (const std::invalid_argument& ex) {
    KvnFail(source, k.at("SEMI_MAJOR_AXIS"),
            std::string("invalid Keplerian elements: ") + ex.what());
  }
  return out;
}

OpmManeuver ReadManeuver(const std::string& source, const ManeuverLines& m,
                         dynamics::TimeScale scale) {
  const char* block = "maneuver block";
  for (const char* key : {"MAN_EPOCH_IGNITION", "MAN_DURATION", "MAN_DELTA_MASS", "MAN_REF_FRAME",
                          "MAN_DV_1", "MAN_DV_2", "MAN_DV_3"}) {
    if (m.keys.count(key) == 0) {
      throw ScenarioError(source + ":" + std::to_string(m.first_line) + ": the " + block +
                          " lacks " + key);
    }
  }
  OpmManeuver out;
  out.comments = m.comments;
  out.ignition = KvnEpoch(source, m.keys.at("MAN_EPOCH_IGNITION"), scale);
  out.duration_s = KvnNumber(source, m.keys.at("MAN_DURATION"), "s");
  if (out.duration_s < 0) KvnFail(source, m.keys.at("MAN_DURATION"), "must be >= 0");
  out.delta_mass_kg = KvnNumber(source, m.keys.at("MAN_DELTA_MASS"), "kg");
  if (out.delta_mass_kg > 0)
    KvnFail(source, m.keys.at("MAN_DELTA_MASS"), "must be <= 0 (mass lost)");
  out.ref_frame = m.keys.at("MAN_REF_FRAME").value;
  const char* dv[3] = {"MAN_DV_1", "MAN_DV_2", "MAN_DV_3"};
  for (int i = 0; i < 3; ++i) out.dv_m_s[i] = KvnNumber(source, m.keys.at(dv[i]), "km/s") * 1e3;
  return out;
}

std::string Deg(double rad) { return KvnFixed(rad / kDeg, 10); }

}  // namespace

std::string FormatOpm(const Opm& o) {
  std::ostringstream os;
  os << KvnHeader("CCSDS_OPM_VERS", o.version, o.comments, o.creation_date, o.originator) << "\n"
     << KvnKeyValue("OBJECT_NAME", o.object_name) << "\n"
     << KvnKeyValue("OBJECT_ID", o.object_id) << "\n"
     << KvnKeyValue("CENTER_NAME", "EARTH") << "\n"
     << KvnKeyValue("REF_FRAME", dynamics::ToString(o.frame)) << "\n"
     << KvnKeyValue("TIME_SYSTEM", "UTC") << "\n\n";
  for (const std::string& c : o.state_comments) os << "COMMENT " << c << "\n";
  os << KvnKeyValue("EPOCH", CcsdsEpochText(o.epoch)) << "\n";
  const char* names[6] = {"X", "Y", "Z", "X_DOT", "Y_DOT", "Z_DOT"};
  for (int i = 0; i < 6; ++i) {
    os << KvnKeyValue(names[i], KvnFixed(o.rv[i] / 1e3, i < 3 ? 6 : 9), i < 3 ? "km" : "km/s")
       << "\n";
  }
  if (o.keplerian) {
    const dynamics::KeplerianElements& k = o.keplerian->elements;
    os << "\n"
       << KvnKeyValue("SEMI_MAJOR_AXIS", KvnFixed(k.a_m / 1e3, 6), "km") << "\n"
       << KvnKeyValue("ECCENTRICITY", KvnFixed(k.e, 12)) << "\n"
       << KvnKeyValue("INCLINATION", Deg(k.i_rad), "deg") << "\n"
       << KvnKeyValue("RA_OF_ASC_NODE", Deg(k.raan_rad), "deg") << "\n"
       << KvnKeyValue("ARG_OF_PERICENTER", Deg(k.arg_perigee_rad), "deg") << "\n"
       << KvnKeyValue(k.anomaly == dynamics::AnomalyKind::kMean ? "MEAN_ANOMALY" : "TRUE_ANOMALY",
                      Deg(k.anomaly_rad), "deg")
       << "\n"
       << KvnKeyValue("GM", KvnFixed(o.keplerian->gm_m3_s2 / 1e9, 4), "km**3/s**2") << "\n";
  }
  if (o.spacecraft) {
    const OpmSpacecraft& s = *o.spacecraft;
    os << "\n"
       << KvnKeyValue("MASS", KvnFixed(s.mass_kg, 3), "kg") << "\n"
       << KvnKeyValue("SOLAR_RAD_AREA", KvnFixed(s.solar_rad_area_m2, 4), "m**2") << "\n"
       << KvnKeyValue("SOLAR_RAD_COEFF", KvnFixed(s.solar_rad_coeff, 4)) << "\n"
       << KvnKeyValue("DRAG_AREA", KvnFixed(s.drag_area_m2, 4), "m**2") << "\n"
       << KvnKeyValue("DRAG_COEFF", KvnFixed(s.drag_coeff, 4)) << "\n";
  }
  for (const OpmManeuver& m : o.maneuvers) {
    os << "\n";
    for (const std::string& c : m.comments) os << "COMMENT " << c << "\n";
    os << KvnKeyValue("MAN_EPOCH_IGNITION", CcsdsEpochText(m.ignition)) << "\n"
       << KvnKeyValue("MAN_DURATION", KvnFixed(m.duration_s, 3), "s") << "\n"
       << KvnKeyValue("MAN_DELTA_MASS", KvnFixed(m.delta_mass_kg, 6), "kg") << "\n"
       << KvnKeyValue("MAN_REF_FRAME", m.ref_frame) << "\n";
    for (int i = 0; i < 3; ++i) {
      os << KvnKeyValue("MAN_DV_" + std::to_string(i + 1), KvnFixed(m.dv_m_s[i] / 1e3, 12), "km/s")
         << "\n";
    }
  }
  return os.str();
}

Opm ParseOpm(std::string_view text, const std::string& source) {
  const std::vector<KvnLine> lines = ReadKvn(text);
  if (lines.empty() || lines[0].kind != KvnLine::kKeyValue ||
      lines[0].keyword != "CCSDS_OPM_VERS") {
    throw ScenarioError(
        source + ": not a CCSDS OPM in KVN form (the first line must be CCSDS_OPM_VERS = ...)");
  }
  Opm o;
  o.version = lines[0].value;
  if (o.version != "1.0" && o.version != "2.0" && o.version != "3.0") {
    KvnFail(source, lines[0], "unsupported version (1.0, 2.0 or 3.0)");
  }
  const OpmLines s = Sort(source, lines);
  const Keys& k = s.single;
  o.comments = s.header_comments;
  o.state_comments = s.state_comments;
  o.creation_date =
      KvnEpoch(source, Need(source, k, "CREATION_DATE", "header"), dynamics::TimeScale::kUtc);
  o.originator = Need(source, k, "ORIGINATOR", "header").value;
  o.object_name = Need(source, k, "OBJECT_NAME", "metadata").value;
  o.object_id = Need(source, k, "OBJECT_ID", "metadata").value;
  KvnCheckCenter(source, Need(source, k, "CENTER_NAME", "metadata"));
  o.frame = KvnFrame(source, Need(source, k, "REF_FRAME", "metadata"));
  if (k.count("REF_FRAME_EPOCH"))
    KvnFail(source, k.at("REF_FRAME_EPOCH"), "not used with EME2000 or GCRF");
  const dynamics::TimeScale scale =
      KvnTimeSystem(source, Need(source, k, "TIME_SYSTEM", "metadata"));
  o.epoch = KvnEpoch(source, Need(source, k, "EPOCH", "state vector"), scale);
  const char* names[6] = {"X", "Y", "Z", "X_DOT", "Y_DOT", "Z_DOT"};
  for (int i = 0; i < 6; ++i) {
    o.rv[i] =
        KvnNumber(source, Need(source, k, names[i], "state vector"), i < 3 ? "km" : "km/s") * 1e3;
  }
  if (k.count("SEMI_MAJOR_AXIS") || k.count("ECCENTRICITY") || k.count("GM") ||
      k.count("INCLINATION")) {
    o.keplerian = ReadKeplerian(source, k);
  }
  if (k.count("MASS")) {
    OpmSpacecraft sc;
    sc.mass_kg = KvnNumber(source, k.at("MASS"), "kg");
    if (!(sc.mass_kg > 0)) KvnFail(source, k.at("MASS"), "must be > 0");
    auto opt = [&](const char* key, const char* units) {
      return k.count(key) ? KvnNumber(source, k.at(key), units) : 0.0;
    };
    sc.solar_rad_area_m2 = opt("SOLAR_RAD_AREA", "m**2");
    sc.solar_rad_coeff = opt("SOLAR_RAD_COEFF", "");
    sc.drag_area_m2 = opt("DRAG_AREA", "m**2");
    sc.drag_coeff = opt("DRAG_COEFF", "");
    o.spacecraft = sc;
  }
  for (const ManeuverLines& m : s.maneuvers) o.maneuvers.push_back(ReadManeuver(source, m, scale));
  return o;
}

}  // namespace thrustsched::app
