// CCSDS Orbit Parameter Message (OPM), KVN form (CCSDS 502.0-B-3 §3, §7):
// reader (initial orbits: state vector, optional Keplerian elements) and
// writer (a plan: the state at the plan start and one maneuver block per burn).
//
//   app::Opm opm = app::ParseOpm(text, "orbit.opm");      // SI units, epochs in UTC
//   dynamics::Vector6d rv = opm.rv;                        // m, m/s in opm.frame at opm.epoch
//   app::WriteTextFile("plan.opm", app::FormatOpm(opm));
//
// Units in the file: km, km/s, deg, kg, m**2, s, km**3/s**2 (§3.2.4 Table
// 3-3); given units must be those. Covariance and user-defined parameters are
// read over (not used). Maneuvers (§3.2.4.8): MAN_EPOCH_IGNITION,
// MAN_DURATION, MAN_DELTA_MASS (< 0), MAN_REF_FRAME, MAN_DV_1..3.
#ifndef THRUSTSCHED_APP_CCSDS_OPM_H_
#define THRUSTSCHED_APP_CCSDS_OPM_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "dynamics/frames.h"
#include "dynamics/keplerian.h"
#include "dynamics/time.h"

namespace thrustsched::app {

struct OpmKeplerian {
  dynamics::KeplerianElements elements;  // SI, radians
  double gm_m3_s2 = 0.0;                 // GM (mandatory with Keplerian elements)
};

struct OpmSpacecraft {
  double mass_kg = 0.0;
  double solar_rad_area_m2 = 0.0, solar_rad_coeff = 0.0;
  double drag_area_m2 = 0.0, drag_coeff = 0.0;
};

struct OpmManeuver {
  std::vector<std::string> comments;
  dynamics::Epoch ignition;  // UTC
  double duration_s = 0.0;
  double delta_mass_kg = 0.0;     // < 0
  std::string ref_frame = "RTN";  // as written in the file
  Eigen::Vector3d dv_m_s = Eigen::Vector3d::Zero();
};

struct Opm {
  std::string version = "2.0";
  std::vector<std::string> comments;  // header
  dynamics::Epoch creation_date;
  std::string originator;
  std::string object_name, object_id;
  dynamics::InertialFrame frame = dynamics::InertialFrame::kEme2000;
  std::vector<std::string> state_comments;
  dynamics::Epoch epoch;                               // UTC
  dynamics::Vector6d rv = dynamics::Vector6d::Zero();  // m, m/s
  std::optional<OpmKeplerian> keplerian;
  std::optional<OpmSpacecraft> spacecraft;
  std::vector<OpmManeuver> maneuvers;
};

/// KVN text with TIME_SYSTEM = UTC, state vector (km, km/s, 6 and 9
/// decimals), Keplerian elements and spacecraft parameters if present, then
/// the maneuvers (duration 3 decimals, delta mass 6, DV in km/s 12 decimals).
std::string FormatOpm(const Opm& opm);

/// Parses an OPM (versions 1.0-3.0): mandatory header, metadata and state
/// vector keywords; CENTER_NAME = EARTH; REF_FRAME EME2000/J2000/GCRF; TIME_SYSTEM
/// UTC/TAI/TT/GPS (epochs are converted to UTC); units; maneuver blocks
/// complete with MAN_DELTA_MASS <= 0. @throws ScenarioError naming the file,
/// line, keyword and value.
Opm ParseOpm(std::string_view text, const std::string& source);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_CCSDS_OPM_H_
