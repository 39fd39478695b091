// What a transfer hands on: the end state as a station-keeping scenario's
// "initial_state" (the Keplerian form of app/initial_orbit.h, EME2000) and
// the trajectory as a CCSDS OEM (app/ccsds_oem.h).
//
//   nlohmann::json init = app::StationKeepingInitialState(final_q, p.mu, end_epoch);
//   geo_scenario["initial_state"] = init;   // read back by app::ParseScenario
//   app::OemFile oem = app::TransferOem(run.orbit, start_epoch, scenario.name);
//
// The transfer's inertial frame is taken as EME2000 (the transfer model has
// no Earth orientation of its own), and the elements carry the transfer's
// own mu (gm_km3_s2), so the parser rebuilds exactly the Cartesian end state.
// The classical angles are singular on a circular or equatorial orbit; they
// are read off the equinoctial elements (atan2 of the vectors, 0 when a
// vector is exactly zero), so that the sums W + w + nu and the state stay
// exact however small e and i are.
#ifndef THRUSTSCHED_APP_TRANSFER_HANDOVER_H_
#define THRUSTSCHED_APP_TRANSFER_HANDOVER_H_

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/ccsds_oem.h"
#include "dynamics/time.h"
#include "transfer/equinoctial.h"
#include "transfer/replay.h"

namespace thrustsched::app {

/// {"keplerian": {"frame": "EME2000", "epoch" (only with an epoch),
/// "semi_major_axis_km", "eccentricity", "inclination_deg",
/// "ra_of_asc_node_deg", "arg_of_pericenter_deg", "true_anomaly_deg",
/// "gm_km3_s2"}}. @throws std::invalid_argument if q is not an ellipse.
nlohmann::json StationKeepingInitialState(const transfer::Equinoctial& q, double mu_m3_s2,
                                          const std::optional<dynamics::Epoch>& epoch);

/// The states of `orbit` (times in s since `start`) for the object `name`:
/// one OEM segment (EME2000, UTC, HERMITE of degree min(7, points - 1)),
/// and a new one at each repeated time (an impulse: the states before and
/// after it), adjacent segments sharing that epoch. States less than a
/// millisecond apart are written once. @throws std::invalid_argument if
/// `orbit` is empty.
OemFile TransferOem(const std::vector<transfer::ReplayState>& orbit, const dynamics::Epoch& start,
                    const std::string& name, const std::string& comment);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_TRANSFER_HANDOVER_H_
