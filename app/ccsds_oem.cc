#include "app/ccsds_oem.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

#include "app/ccsds_kvn.h"

namespace thrustsched::app {
namespace {

// Slack (s) on an epoch against its segment's START_TIME and STOP_TIME:
// the precision of written epochs.
constexpr double kEpochSlack_s = 1e-6;

// The keyword lines of one META block, by keyword.
struct MetaBlock {
  std::map<std::string, KvnLine> keys;
  int start_line = 0;
};

const std::vector<std::string>& MetaKeywords() {
  static const std::vector<std::string> k = {
      "OBJECT_NAME",       "OBJECT_ID",   "CENTER_NAME",   "REF_FRAME",
      "REF_FRAME_EPOCH",   "TIME_SYSTEM", "START_TIME",    "USEABLE_START_TIME",
      "USEABLE_STOP_TIME", "STOP_TIME",   "INTERPOLATION", "INTERPOLATION_DEGREE"};
  return k;
}

bool Contains(const std::vector<std::string>& v, const std::string& s) {
  for (const std::string& x : v) {
    if (x == s) return true;
  }
  return false;
}

// Data line "epoch x y z vx vy vz [ax ay az]" (km, km/s) -> SI.
OemPoint ParseDataLine(const std::string& source, const KvnLine& line, dynamics::TimeScale scale) {
  std::istringstream in(line.text);
  std::string epoch;
  in >> epoch;
  std::vector<double> v;
  std::string tok;
  while (in >> tok) {
    char* end = nullptr;
    const double x = std::strtod(tok.c_str(), &end);
    if (end != tok.c_str() + tok.size() || !std::isfinite(x)) {
      KvnFail(source, line, "\"" + tok + "\" is not a finite number");
    }
    v.push_back(x);
  }
  if (v.size() != 6 && v.size() != 9) {
    KvnFail(
        source, line,
        "a data line holds an epoch and 6 numbers (x y z in km, x_dot y_dot z_dot in km/s) or 9 "
        "(with accelerations), got " +
            std::to_string(v.size()));
  }
  OemPoint p;
  try {
    p.epoch = ParseCcsdsEpoch(epoch, scale);
  } catch (const std::invalid_argument& e) {
    KvnFail(source, line, "bad epoch \"" + epoch + "\": " + e.what());
  }
  for (int i = 0; i < 6; ++i) p.rv[i] = v[i] * 1e3;
  return p;
}

// Fills a segment's metadata from a META block (mandatory keywords checked).
OemSegment SegmentFromMeta(const std::string& source, const MetaBlock& m) {
  for (const char* k : {"OBJECT_NAME", "OBJECT_ID", "CENTER_NAME", "REF_FRAME", "TIME_SYSTEM",
                        "START_TIME", "STOP_TIME"}) {
    if (m.keys.count(k) == 0) {
      throw ScenarioError(source + ":" + std::to_string(m.start_line) +
                          ": META block lacks the mandatory keyword " + k);
    }
  }
  OemSegment s;
  s.object_name = m.keys.at("OBJECT_NAME").value;
  s.object_id = m.keys.at("OBJECT_ID").value;
  KvnCheckCenter(source, m.keys.at("CENTER_NAME"));
  s.center_name = "EARTH";
  s.frame = KvnFrame(source, m.keys.at("REF_FRAME"));
  if (m.keys.count("REF_FRAME_EPOCH") > 0) {
    KvnFail(source, m.keys.at("REF_FRAME_EPOCH"),
            "not used with EME2000 or GCRF (their epoch is fixed)");
  }
  s.time_system = KvnTimeSystem(source, m.keys.at("TIME_SYSTEM"));
  s.start_time = KvnEpoch(source, m.keys.at("START_TIME"), s.time_system);
  s.stop_time = KvnEpoch(source, m.keys.at("STOP_TIME"), s.time_system);
  if (s.stop_time.SecondsSince(s.start_time) < 0)
    KvnFail(source, m.keys.at("STOP_TIME"), "before START_TIME");
  s.interpolation = m.keys.count("INTERPOLATION") ? m.keys.at("INTERPOLATION").value : "";
  s.interpolation_degree = -1;
  if (m.keys.count("INTERPOLATION_DEGREE")) {
    const KvnLine& l = m.keys.at("INTERPOLATION_DEGREE");
    const double d = KvnNumber(source, l, "");
    if (d != std::floor(d) || d < 0 || d > 100) KvnFail(source, l, "expected an integer in 0..100");
    s.interpolation_degree = static_cast<int>(d);
  }
  return s;
}

void CheckPoints(const std::string& source, const OemSegment& s, const KvnLine& line) {
  const OemPoint& p = s.points.back();
  if (p.epoch.SecondsSince(s.start_time) < -kEpochSlack_s ||
      s.stop_time.SecondsSince(p.epoch) < -kEpochSlack_s) {
    KvnFail(source, line, "epoch outside the segment's [START_TIME, STOP_TIME]");
  }
  if (s.points.size() > 1 && !(p.epoch.SecondsSince(s.points[s.points.size() - 2].epoch) > 0)) {
    KvnFail(source, line, "epochs must increase within a segment");
  }
}

}  // namespace

std::string FormatOem(const OemFile& f) {
  std::ostringstream os;
  os << KvnHeader("CCSDS_OEM_VERS", f.version, f.comments, f.creation_date, f.originator);
  for (const OemSegment& s : f.segments) {
    if (s.time_system != dynamics::TimeScale::kUtc) {
      throw std::invalid_argument("FormatOem: segments are written in UTC");
    }
    if (s.points.empty()) throw std::invalid_argument("FormatOem: a segment without data lines");
    for (size_t k = 0; k < s.points.size(); ++k) {
      const double t = s.points[k].epoch.SecondsSince(s.start_time);
      if (t < -kEpochSlack_s || s.stop_time.SecondsSince(s.points[k].epoch) < -kEpochSlack_s ||
          (k > 0 && !(s.points[k].epoch.SecondsSince(s.points[k - 1].epoch) > 0))) {
        throw std::invalid_argument(
            "FormatOem: points must increase within [start_time, stop_time]");
      }
    }
    os << "\nMETA_START\n"
       << KvnKeyValue("OBJECT_NAME", s.object_name) << "\n"
       << KvnKeyValue("OBJECT_ID", s.object_id) << "\n"
       << KvnKeyValue("CENTER_NAME", s.center_name) << "\n"
       << KvnKeyValue("REF_FRAME", dynamics::ToString(s.frame)) << "\n"
       << KvnKeyValue("TIME_SYSTEM", "UTC") << "\n"
       << KvnKeyValue("START_TIME", CcsdsEpochText(s.start_time)) << "\n"
       << KvnKeyValue("USEABLE_START_TIME", CcsdsEpochText(s.start_time)) << "\n"
       << KvnKeyValue("USEABLE_STOP_TIME", CcsdsEpochText(s.stop_time)) << "\n"
       << KvnKeyValue("STOP_TIME", CcsdsEpochText(s.stop_time)) << "\n";
    if (!s.interpolation.empty()) os << KvnKeyValue("INTERPOLATION", s.interpolation) << "\n";
    if (s.interpolation_degree >= 0) {
      os << KvnKeyValue("INTERPOLATION_DEGREE", std::to_string(s.interpolation_degree)) << "\n";
    }
    os << "META_STOP\n\n";
    for (const std::string& c : s.comments) os << "COMMENT " << c << "\n";
    for (const OemPoint& p : s.points) {
      os << CcsdsEpochText(p.epoch);
      for (int i = 0; i < 3; ++i) os << " " << KvnFixed(p.rv[i] / 1e3, 6);
      for (int i = 3; i < 6; ++i) os << " " << KvnFixed(p.rv[i] / 1e3, 9);
      os << "\n";
    }
  }
  return os.str();
}

OemFile ParseOem(std::string_view text, const std::string& source) {
  const std::vector<KvnLine> lines = ReadKvn(text);
  OemFile f;
  if (lines.empty() || lines[0].kind != KvnLine::kKeyValue ||
      lines[0].keyword != "CCSDS_OEM_VERS") {
    throw ScenarioError(
        source + ": not a CCSDS OEM in KVN form (the first line must be CCSDS_OEM_VERS = ...)");
  }
  f.version = lines[0].value;
  if (f.version != "1.0" && f.version != "2.0" && f.version != "3.0") {
    KvnFail(source, lines[0], "unsupported version (1.0, 2.0 or 3.0)");
  }
  size_t i = 1;
  bool have_creation = false, have_originator = false;
  for (;
       i < lines.size() && !(lines[i].kind == KvnLine::kMarker && lines[i].keyword == "META_START");
       ++i) {
    const KvnLine& l = lines[i];
    if (l.kind == KvnLine::kComment) {
      f.comments.push_back(l.value);
    } else if (l.kind == KvnLine::kKeyValue && l.keyword == "CREATION_DATE") {
      f.creation_date = KvnEpoch(source, l, dynamics::TimeScale::kUtc);
      have_creation = true;
    } else if (l.kind == KvnLine::kKeyValue && l.keyword == "ORIGINATOR") {
      f.originator = l.value;
      have_originator = true;
    } else if (!(l.kind == KvnLine::kKeyValue &&
                 (l.keyword == "MESSAGE_ID" || l.keyword == "CLASSIFICATION"))) {
      KvnFail(source, l, "unexpected in the OEM header");
    }
  }
  if (!have_creation || !have_originator) {
    throw ScenarioError(source + ": the OEM header lacks " +
                        std::string(have_creation ? "ORIGINATOR" : "CREATION_DATE"));
  }
  while (i < lines.size()) {
    const KvnLine& start = lines[i++];
    if (!(start.kind == KvnLine::kMarker && start.keyword == "META_START")) {
      KvnFail(source, start, "expected META_START");
    }
    MetaBlock m;
    m.start_line = start.number;
    for (; i < lines.size() &&
           !(lines[i].kind == KvnLine::kMarker && lines[i].keyword == "META_STOP");
         ++i) {
      const KvnLine& l = lines[i];
      if (l.kind == KvnLine::kComment) continue;
      if (l.kind != KvnLine::kKeyValue || !Contains(MetaKeywords(), l.keyword)) {
        KvnFail(source, l, "unexpected in a META block");
      }
      if (!m.keys.emplace(l.keyword, l).second) KvnFail(source, l, "repeated in the META block");
    }
    if (i == lines.size()) {
      throw ScenarioError(source + ":" + std::to_string(start.number) +
                          ": META_START without META_STOP");
    }
    ++i;
    OemSegment s = SegmentFromMeta(source, m);
    bool in_covariance = false;
    for (; i < lines.size() &&
           !(lines[i].kind == KvnLine::kMarker && lines[i].keyword == "META_START");
         ++i) {
      const KvnLine& l = lines[i];
      if (l.kind == KvnLine::kMarker && l.keyword == "COVARIANCE_START") in_covariance = true;
      if (l.kind == KvnLine::kMarker && l.keyword == "COVARIANCE_STOP") in_covariance = false;
      if (l.kind == KvnLine::kMarker && l.keyword != "COVARIANCE_START" &&
          l.keyword != "COVARIANCE_STOP") {
        KvnFail(source, l, "unexpected block keyword in an ephemeris data block");
      }
      if (in_covariance || l.kind == KvnLine::kMarker) continue;  // covariance is not used
      if (l.kind == KvnLine::kComment) {
        if (s.points.empty()) s.comments.push_back(l.value);
        continue;
      }
      if (l.kind != KvnLine::kData) KvnFail(source, l, "unexpected in an ephemeris data block");
      s.points.push_back(ParseDataLine(source, l, s.time_system));
      CheckPoints(source, s, l);
    }
    if (s.points.empty()) {
      throw ScenarioError(source + ":" + std::to_string(start.number) +
                          ": segment without data lines");
    }
    s.time_system = dynamics::TimeScale::kUtc;  // epochs are held in UTC from here on
    f.segments.push_back(std::move(s));
  }
  if (f.segments.empty()) throw ScenarioError(source + ": no META_START: the OEM holds no segment");
  return f;
}

}  // namespace thrustsched::app
