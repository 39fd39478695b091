// CCSDS Orbit Ephemeris Message (OEM), KVN form (CCSDS 502.0-B-3 §5, §7):
// writer and reader. thrustsched writes version 2.0 files (no covariance,
// no accelerations); the reader takes versions 1.0 to 3.0, skips covariance
// blocks and the optional acceleration columns.
//
//   app::OemFile f;
//   f.originator = "THRUSTSCHED";  f.creation_date = app::CreationDate();
//   app::OemSegment seg;  seg.object_name = "GEO-118E"; ...;  seg.points = {{epoch, rv_m}};
//   f.segments.push_back(seg);
//   app::WriteTextFile("plan.oem", app::FormatOem(f));
//   app::OemFile back = app::ParseOem(text, "plan.oem");   // positions back in m, m/s
//
// Data lines are "epoch x y z x_dot y_dot z_dot" in km and km/s (§5.2.4);
// positions are written with 6 decimals (1 mm), velocities with 9 (1 um/s).
#ifndef THRUSTSCHED_APP_CCSDS_OEM_H_
#define THRUSTSCHED_APP_CCSDS_OEM_H_

#include <string>
#include <string_view>
#include <vector>

#include "dynamics/frames.h"
#include "dynamics/orbital_elements.h"
#include "dynamics/time.h"

namespace thrustsched::app {

struct OemPoint {
  dynamics::Epoch epoch;  // UTC
  dynamics::Vector6d rv;  // m, m/s in the segment's frame
};

/// One META block and its data lines (§5.2.3, §5.2.4).
struct OemSegment {
  std::vector<std::string> comments;  // written after META_STOP
  std::string object_name, object_id;
  std::string center_name = "EARTH";
  dynamics::InertialFrame frame = dynamics::InertialFrame::kEme2000;
  dynamics::TimeScale time_system = dynamics::TimeScale::kUtc;  // the reader converts epochs to UTC
  dynamics::Epoch start_time, stop_time;
  std::string interpolation = "HERMITE";  // empty: keyword omitted
  int interpolation_degree = 5;           // < 0: keyword omitted
  std::vector<OemPoint> points;
};

struct OemFile {
  std::string version = "2.0";
  std::vector<std::string> comments;  // header comments
  dynamics::Epoch creation_date;
  std::string originator;
  std::vector<OemSegment> segments;
};

/// The KVN text. Epochs are written in UTC (TIME_SYSTEM = UTC is required).
/// @throws std::invalid_argument if a segment is not in UTC, has no point, or
///         its points are not sorted within [start_time, stop_time].
std::string FormatOem(const OemFile& file);

/// Parses an OEM in KVN form. Checks the header (CCSDS_OEM_VERS 1.0-3.0,
/// CREATION_DATE, ORIGINATOR), each META block's mandatory keywords,
/// CENTER_NAME = EARTH, REF_FRAME EME2000/J2000/GCRF, TIME_SYSTEM
/// UTC/TAI/TT/GPS, data lines of 7 (or 10) numbers with epochs increasing
/// inside [START_TIME, STOP_TIME]. @throws ScenarioError naming the file, the
/// line, the keyword and the value.
OemFile ParseOem(std::string_view text, const std::string& source);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_CCSDS_OEM_H_
