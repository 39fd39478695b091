// Transfer scenario files: a JSON file whose "transfer" section describes an
// orbit transfer for `thrustsched transfer` (fields in
// data/scenarios/transfer/README.md).
//
//   {"name": "...", "description": "...",
//    "transfer": {
//      "initial": {"keplerian": {"a_m": 24505.9e3, "e": 0.725, "i_deg": 5.2,
//                                "raan_deg": 0, "arg_perigee_deg": 0, "true_anomaly_deg": 0}},
//      "target":  {"a_m": 42165e3, "ex": 0, "ey": 0, "hx": 0, "hy": 0, "free": []},
//      "thrust_n": 0.35, "isp_s": 2000, "mass_kg": 2000,
//      "method": "feedback",
//      "force_model": "two_body",          // optional: "two_body" (default) or "j2"
//      "epoch": "2034-01-01T00:00:00Z"}}   // optional, UTC: dates the hand-over state
//
//   app::TransferScenario s = app::LoadTransferScenario("data/scenarios/transfer/x.json");
//   transfer::MinTimeSolution r = transfer::SolveMinTime(s.problem, ...);
//
// "initial" is {"equinoctial": {"p_m", "ex", "ey", "hx", "hy", "l_deg"}},
// {"keplerian": {"a_m", ...}} or one of the station-keeping scenarios' orbit
// forms read by their parser (app/initial_orbit.h: "eci_state", "keplerian"
// with "semi_major_axis_km", "opm", relative to the scenario file's folder),
// whose stated epoch becomes the transfer's "epoch"; "target" gives "p_m" or "a_m" and the
// equinoctial ex, ey, hx, hy (hx + j hy = tan(i/2) exp(j RAAN)), "free" lists the ones left free
// (the final longitude is always free). Strict: unknown keys, negative thrust, a hyperbolic start,
// a perigee below the Earth's surface or a target beyond the Earth's sphere of influence throw
// ScenarioError naming the field and the value (exit 2).
#ifndef THRUSTSCHED_APP_TRANSFER_SCENARIO_H_
#define THRUSTSCHED_APP_TRANSFER_SCENARIO_H_

#include <optional>
#include <string>

#include "app/json_reader.h"
#include "dynamics/time.h"
#include "transfer/feedback_switch.h"
#include "transfer/lyapunov_feedback.h"
#include "transfer/min_time_shooting.h"

namespace thrustsched::app {

enum class TransferMethod { kMinimumTime, kFeedback, kTwoImpulse };

/// "minimum_time", "feedback", "two_impulse".
std::string ToString(TransferMethod m);
/// @throws ScenarioError listing the choices.
TransferMethod ParseTransferMethod(const std::string& name, const std::string& path);

struct TransferScenario {
  std::string path;  // the file ("" when parsed from text)
  std::string name, description;
  TransferMethod method = TransferMethod::kMinimumTime;
  transfer::MinTimeProblem problem;
  /// The transfer's start (UTC), "epoch": dates the end state handed over to
  /// station keeping and the OEM; none: times are relative to the start.
  std::optional<dynamics::Epoch> epoch;
  // minimum_time
  /// Continue on the thrust from this one (a converged shooting there from
  /// the first guess) down to problem.thrust_n; none: shoot directly.
  std::optional<double> continuation_from_thrust_n;
  std::optional<transfer::ShootingGuess> guess;  // "costate_guess"; none: InitialGuess
  transfer::ShootingOptions shooting;
  // feedback
  transfer::FeedbackOptions feedback;
  bool optimal_end = true;  // Bombrun's minimum-time end after the feedback
  /// Where the feedback hands over to that end ("switch", "switch_interval_s").
  transfer::SwitchOptions feedback_switch;
};

/// Earth's equatorial radius and sphere-of-influence radius used by the checks, m.
inline constexpr double kEarthRadiusM = 6378137.0;
inline constexpr double kEarthSphereOfInfluenceM = 9.25e8;

TransferScenario ParseTransferScenario(const nlohmann::json& root, const std::string& path);
/// "force_model": "j2" is for minimum_time and feedback (two_impulse is the
/// two-body Hohmann closed form); @throws ScenarioError naming the field
/// otherwise. Called by the parser and, after a method override, by
/// RunTransferScenario.
void CheckForceModel(const TransferScenario& s);
/// @throws ScenarioError on unreadable files and on every error above.
TransferScenario LoadTransferScenario(const std::string& path);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_TRANSFER_SCENARIO_H_
