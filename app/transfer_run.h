// One orbit transfer from a parsed transfer scenario, as data: summary.json's
// content, trajectory.csv's text and the Cartesian states of orbit.csv.
// `thrustsched transfer` (app/transfer_command.h) writes them into its run
// folder; the Python package (`ts.transfer`) returns them.
//
//   app::TransferScenario sc =
//   app::LoadTransferScenario("data/scenarios/transfer/gto_geo_caillau_60n.json"); app::TransferRun
//   run = app::RunTransferScenario(sc, sc.path, /*quiet=*/true); run.summary["duration_h"];
//   // 14.8004 run.summary["final_state"];     // a station-keeping scenario's "initial_state"
//
// orbit holds the independent Cartesian replay's steps for minimum_time
// ("replay"); for two_impulse the Kepler coast with the states before the
// first impulse and after the second at repeated times ("coast"); for
// feedback (no replay) the trajectory's elements converted to position and
// velocity ("elements"); summary.json's "orbit_source" says which.
#ifndef THRUSTSCHED_APP_TRANSFER_RUN_H_
#define THRUSTSCHED_APP_TRANSFER_RUN_H_

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/transfer_scenario.h"
#include "transfer/replay.h"

namespace thrustsched::app {

struct TransferRun {
  bool converged = false;    // shooting converged / target reached
  bool interrupted = false;  // stopped by TransferHooks::interrupt before it converged
  nlohmann::json summary;    // summary.json
  std::string trajectory_csv;
  std::size_t trajectory_rows = 0;
  std::vector<transfer::ReplayState> orbit;  // orbit.csv
};

/// What a caller hands to a run besides the scenario: a stop request
/// (Ctrl-C) and a progress callback, both optional.
struct TransferHooks {
  /// Polled by the shooting (every evaluation, every continuation step) and
  /// by the feedback (every step). Once set, the run stops within one
  /// evaluation and returns its best result so far: the last converged
  /// continuation step (summary "convergence.continuation_thrust_reached_n"),
  /// the feedback up to where it stopped; summary "status" "interrupted".
  const std::atomic<bool>* interrupt = nullptr;
  /// Called from the running thread with {"phase": "continuation", "thrust_n",
  /// "converged", "duration_s"} after every continuation step and
  /// {"phase": "switch", "switch_s", "converged", "end_s"} after every try of
  /// the feedback's optimal end.
  std::function<void(const nlohmann::json& event)> progress;
};

/// Runs sc.method; progress lines on stderr unless quiet. @throws
/// ScenarioError for a method the scenario does not allow (two_impulse on
/// non-circular orbits).
TransferRun RunTransferScenario(const TransferScenario& sc, const std::string& scenario_path,
                                bool quiet, const TransferHooks& hooks = {});

/// orbit.csv: t_s,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,mass_kg.
std::string OrbitCsv(const std::vector<transfer::ReplayState>& orbit);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_TRANSFER_RUN_H_
