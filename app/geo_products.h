// Flight-dynamics products of a GEO schedule, for the people and tools that
// speak UTC and CCSDS: per-burn facts for schedule.csv (UTC start and end,
// the thruster's RTN direction, the delta-v the burn delivers on the
// nonlinear replay), the replay as a CCSDS OEM (EME2000, UTC, segments split
// at every burn start and end) and the plan as a CCSDS OPM with one maneuver
// block per burn. Formats: data/scenarios/README.md, section 10.
//
//   app::ReplayLeg leg = app::ScenarioReplayLeg(scenario, burns, report.sample_times);
//   std::vector<app::BurnFacts> facts = app::ComputeBurnFacts(scenario, burns, leg);
//   app::WriteTextFile("plan.oem", app::FormatOem(app::BuildReplayOem(scenario, {leg})));
//   app::WriteTextFile("plan.opm", app::FormatOpm(app::BuildManeuverOpm(scenario, {leg})));
//
// The replay here is a fresh propagation with the scenario's GeoSimulator
// from the leg's start state, so the same burns and start give the checker's
// (and the year simulation's) replay to the integrator's tolerance.
#ifndef THRUSTSCHED_APP_GEO_PRODUCTS_H_
#define THRUSTSCHED_APP_GEO_PRODUCTS_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "app/ccsds_oem.h"
#include "app/ccsds_opm.h"
#include "app/scenario.h"
#include "dynamics/orbital_elements.h"
#include "planning/long_horizon.h"
#include "transcription/operations.h"

namespace thrustsched::app {

/// A stretch of replay: the true state at a model time, the burns flown from
/// there until `end_s`, and the times at which the OEM holds a data line
/// (every burn start and end inside the leg is added).
struct ReplayLeg {
  double start_s = 0.0;
  dynamics::Vector6d eci = dynamics::Vector6d::Zero();  // model frame MOE(epoch), m, m/s
  double end_s = 0.0;
  std::vector<transcription::Burn> burns;
  std::vector<double> sample_times;
};

/// The scenario's own leg: from its initial state at the horizon start to the
/// horizon end, with `burns`, data lines at `sample_times` (e.g. the
/// checker's samples; empty: the grid nodes).
ReplayLeg ScenarioReplayLeg(const Scenario& s, const std::vector<transcription::Burn>& burns,
                            const std::vector<double>& sample_times);

/// Per burn: UTC start and end (ISO 8601, millisecond precision, 'Z'), the
/// thruster's unit direction in the satellite's RTN frame, and the delta-v
/// (m/s) the burn delivers on the nonlinear replay: the norm of the thrust
/// acceleration integrated in the inertial frame along the replayed motion,
/// |integral R_RTN->ECI(t) a_RTN dt|. The thrust turns with the RTN frame
/// (omega_E), so this is below F/m x duration by the cosine loss of the
/// in-plane part: 0.03 % for a 20-minute Anzel burn, 1.3 % for 145 minutes.
struct BurnFacts {
  std::string start_utc, end_utc;
  Eigen::Vector3d direction_rtn = Eigen::Vector3d::Zero();
  double delta_v_m_s = 0.0;
};
/// `leg` gives the replay start (the scenario's, or a cycle's true state).
/// @throws std::invalid_argument if the scenario is not GEO.
std::vector<BurnFacts> ComputeBurnFacts(const Scenario& s,
                                        const std::vector<transcription::Burn>& burns,
                                        const ReplayLeg& leg);

/// The replay of consecutive legs as an OEM 2.0 in EME2000 and UTC: one
/// segment per coast or burn arc (boundaries shared by adjacent segments),
/// Hermite interpolation of degree min(7, points - 1). OBJECT_NAME and
/// OBJECT_ID come from the initial OPM if there was one, else the scenario
/// name and "UNKNOWN".
/// @throws ScenarioError if a leap second of the table falls inside the run
///         (the uniform model clock would make the UTC labels after it 1 s off).
OemFile BuildReplayOem(const Scenario& s, const std::vector<ReplayLeg>& legs);

/// The plan as an OPM 2.0: the state at the first leg's start (EME2000, UTC),
/// the spacecraft parameters, and one maneuver block per burn with
/// MAN_REF_FRAME = RTN, MAN_DV = (F/m) x duration x direction (km/s: the
/// thrust is held constant in the satellite's own RTN frame for
/// MAN_DURATION) and MAN_DELTA_MASS = -F/(g0 Isp) x duration.
/// @throws ScenarioError as BuildReplayOem.
Opm BuildManeuverOpm(const Scenario& s, const std::vector<ReplayLeg>& legs);

/// The leg a finished cycle of a year simulation flew: from its true state at
/// the cycle start to the end of its applied part, data lines every `step_s`.
ReplayLeg CycleReplayLeg(const planning::CycleRecord& cycle, double step_s);

/// The CCSDS files a command was asked for (--oem FILE, --opm-maneuvers FILE).
struct FlightDynamicsFiles {
  std::string oem, opm_maneuvers;
  bool any() const { return !oem.empty() || !opm_maneuvers.empty(); }
};
/// Checked before any work: the files need a GEO scenario with on-off
/// thrusters and a run [t0, t1] (model time) without a leap second of the
/// table. @throws ScenarioError naming the option and the value.
void CheckFlightDynamicsFiles(const Scenario& s, const FlightDynamicsFiles& files, double t0,
                              double t1);
/// Writes the requested files for the legs; returns their paths.
/// @throws std::runtime_error naming the path on I/O failure.
std::vector<std::string> WriteFlightDynamicsFiles(const Scenario& s,
                                                  const FlightDynamicsFiles& files,
                                                  const std::vector<ReplayLeg>& legs);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_GEO_PRODUCTS_H_
