// GEO initial states given as real orbits, in a scenario's "initial_state"
// section (fields in data/scenarios/README.md): an OPM file, an inline ECI
// state vector, or classical Keplerian elements, each with its frame and
// epoch. They are converted to the GEO model's relative equinoctial state at
// the horizon start (dynamics/geo_orbit_state.h).
//
//   "initial_state": {"opm": {"file": "geo_week_from_opm.opm"}}
//   "initial_state": {"eci_state": {"frame": "EME2000", "epoch": "2034-01-01T00:00:00Z",
//                                   "position_km": [...], "velocity_km_s": [...]}}
//   "initial_state": {"keplerian": {"frame": "GCRF", "semi_major_axis_km": 42165.8, ...}}
//
//   dynamics::GeoSimulator sim(*scenario.geo);
//   if (app::HasOrbitForm(init)) orbit = app::ReadInitialOrbit(init, sim, start_s, scenario_dir);
#ifndef THRUSTSCHED_APP_INITIAL_ORBIT_H_
#define THRUSTSCHED_APP_INITIAL_ORBIT_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "app/json_reader.h"
#include "dynamics/geo_orbit_state.h"
#include "dynamics/geo_simulator.h"

namespace thrustsched::app {

/// An initial orbit as given, and what it became.
struct InitialOrbit {
  std::string form;                    // "opm", "eci_state" or "keplerian"
  std::string file;                    // the OPM file as resolved ("" otherwise)
  std::string object_name, object_id;  // from the OPM ("" otherwise)
  dynamics::OrbitState given;          // the state as given (its frame and epoch)
  Eigen::VectorXd relative_state;      // the model state at the horizon start
};

/// The keys of the orbit forms: "opm", "eci_state", "keplerian".
const std::vector<std::string>& OrbitForms();
/// True if `init` holds one of the orbit forms (marks the key as read).
bool HasOrbitForm(JsonObject& init);

/// Reads the orbit form of `init` (exactly one; the caller checks that no
/// other state form is present) as given: `form`, the OPM's file and object,
/// and `given` (frame, epoch, Cartesian state in m and m/s); relative_state
/// stays empty. Inline forms without an "epoch" take `default_epoch`. OPM
/// paths are relative to `base_dir`. Shared by the GEO scenarios and the
/// orbit transfers (app/transfer_scenario.h).
/// @throws ScenarioError naming the field (or the OPM file, line, keyword and
///         value) for bad values, unsupported frames, time systems and
///         centres, or an OPM with maneuvers.
InitialOrbit ReadOrbitAsGiven(JsonObject& init, const dynamics::Epoch& default_epoch,
                              const std::string& base_dir);

/// Reads the orbit form of `init` (exactly one; the caller checks that no
/// other state form is present) and converts it with `sim` to the relative
/// state at model time `t_start`. OPM paths are relative to `base_dir`.
/// @throws ScenarioError naming the field (or the OPM file, line, keyword and
///         value) for unsupported frames, time systems and centres, an epoch
///         after the horizon start, an OPM with maneuvers, or an orbit that is
///         not near-geostationary.
InitialOrbit ReadInitialOrbit(JsonObject& init, const dynamics::GeoSimulator& sim, double t_start,
                              const std::string& base_dir);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_INITIAL_ORBIT_H_
