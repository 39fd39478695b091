// The hand-over of a transfer to station keeping: summary.json's
// "final_state" read back by the real GEO scenario parser (app/scenario.h)
// inside a short GEO scenario gives the transfer's end state (the shipped
// 60 N minimum-time transfer, Caillau, Gergaud & Noailles 2003) and its
// epoch (the transfer's start + its duration); and the OEM of the replay.
#include <cmath>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "app/ccsds_oem.h"
#include "app/scenario.h"
#include "app/transfer_handover.h"
#include "app/transfer_run.h"
#include "app/transfer_scenario.h"
#include "dynamics/geo_model.h"
#include "tests/app/cli_runner.h"

namespace thrustsched::app {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using thrustsched::testing::ReadFile;

const std::string kData = THRUSTSCHED_DATA_DIR "/scenarios/";
constexpr const char* kStart = "2034-01-01T00:00:00Z";

nlohmann::json Caillau60N() {
  return nlohmann::json::parse(ReadFile(kData + "transfer/gto_geo_caillau_60n.json"));
}

// A GEO scenario of one hour (the shipped OPM week's model and thrusters)
// starting at `epoch` from `initial_state`.
Scenario GeoScenarioFrom(const nlohmann::json& initial_state, const std::string& epoch) {
  nlohmann::json j = nlohmann::json::parse(ReadFile(kData + "geo_week_from_opm.json"));
  j["model"]["epoch"] = epoch;
  j["initial_state"] = initial_state;
  j["horizon"] = {{"duration_s", 3600}, {"step_s", 300}};
  return ParseScenario(j);
}

transfer::Equinoctial FinalElements(const nlohmann::json& summary) {
  const nlohmann::json& f = summary.at("final_elements");
  return {f.at("p_m").get<double>(), f.at("ex").get<double>(), f.at("ey").get<double>(),
          f.at("hx").get<double>(),  f.at("hy").get<double>(), f.at("l_rad").get<double>()};
}

TEST(TransferHandover, FinalStateRoundTripsThroughTheStationKeepingParser) {
  nlohmann::json j = Caillau60N();
  j["transfer"]["epoch"] = kStart;
  const TransferScenario sc = ParseTransferScenario(j, "60n.json");
  ASSERT_TRUE(sc.epoch.has_value());
  const TransferRun run = RunTransferScenario(sc, "60n.json", /*quiet=*/true);
  ASSERT_TRUE(run.converged);
  const nlohmann::json& s = run.summary;
  EXPECT_NEAR(s.at("duration_h").get<double>(), 14.8004, 14.8004e-3);
  const dynamics::Epoch end = dynamics::Epoch::Parse(kStart).PlusSeconds(s.at("duration_s"));
  EXPECT_EQ(s.at("epoch"), kStart);
  EXPECT_EQ(s.at("end_epoch"), end.ToIso8601());
  const nlohmann::json& init = s.at("final_state");
  ASSERT_TRUE(init.contains("keplerian")) << init.dump();
  EXPECT_EQ(init["keplerian"]["epoch"], end.ToIso8601());
  EXPECT_EQ(init["keplerian"]["frame"], "EME2000");

  const Scenario geo = GeoScenarioFrom(init, end.ToIso8601());
  ASSERT_TRUE(geo.initial_orbit.has_value());
  EXPECT_EQ(geo.initial_orbit->form, "keplerian");
  EXPECT_EQ(geo.initial_orbit->given.frame, dynamics::InertialFrame::kEme2000);
  EXPECT_LT(std::abs(geo.initial_orbit->given.epoch.SecondsSince(end)), 1e-3);
  // The parser's Cartesian state is the transfer's end state: same position
  // to 10 um and velocity to 1e-8 m/s (rounding only), and the same elements.
  const transfer::Equinoctial q = FinalElements(s);
  const dynamics::Vector6d want = transfer::CartesianFromEquinoctial(q, sc.problem.mu);
  const dynamics::Vector6d& got = geo.initial_orbit->given.rv;
  EXPECT_LT((got.head<3>() - want.head<3>()).norm(), 1e-5);
  EXPECT_LT((got.tail<3>() - want.tail<3>()).norm(), 1e-8);
  const transfer::Equinoctial back = transfer::EquinoctialFromCartesian(got, sc.problem.mu);
  EXPECT_NEAR(transfer::SemiMajorAxis(back), s["final_elements"]["a_m"].get<double>(), 1e-3);
  EXPECT_NEAR(transfer::Eccentricity(back), s["final_elements"]["e"].get<double>(), 1e-10);
  EXPECT_NEAR(transfer::Inclination(back) * 180 / M_PI, s["final_elements"]["i_deg"].get<double>(),
              1e-9);
  EXPECT_NEAR(std::remainder(back.l_rad - q.l_rad, 2 * M_PI), 0.0, 1e-10);
  // And GEO station keeping can start from it: the model state is 42165 km
  // against the station radius, circular and equatorial (to the precession
  // of the 2034 equator from EME2000's, 0.16 deg over 34 years).
  const Eigen::VectorXd& x = geo.problem.initial_state;
  EXPECT_NEAR(x(0), 42165e3 - dynamics::geo::kStationRadius, 50.0);
  EXPECT_LT(std::hypot(x(1), x(2)), 1e-5);
  EXPECT_LT(2 * std::atan(std::hypot(x(3), x(4))) * 180 / M_PI, 0.2);
}

TEST(TransferHandover, WithoutEpochTheStateStartsTheGeoHorizon) {
  const TransferScenario sc = ParseTransferScenario(Caillau60N(), "60n.json");
  EXPECT_FALSE(sc.epoch.has_value());
  const transfer::Equinoctial q{42165e3, 1e-4, -2e-4, 1e-3, 2e-3, 2.5};
  const nlohmann::json init = StationKeepingInitialState(q, sc.problem.mu, std::nullopt);
  EXPECT_FALSE(init["keplerian"].contains("epoch"));
  const Scenario geo = GeoScenarioFrom(init, kStart);
  ASSERT_TRUE(geo.initial_orbit.has_value());
  EXPECT_EQ(geo.initial_orbit->given.epoch, dynamics::Epoch::Parse(kStart));
  const dynamics::Vector6d want = transfer::CartesianFromEquinoctial(q, sc.problem.mu);
  EXPECT_LT((geo.initial_orbit->given.rv.head<3>() - want.head<3>()).norm(), 1e-5);
  EXPECT_LT((geo.initial_orbit->given.rv.tail<3>() - want.tail<3>()).norm(), 1e-8);
}

TEST(TransferHandover, BadEpochIsRefusedNamingTheField) {
  nlohmann::json j = Caillau60N();
  j["transfer"]["epoch"] = "2034-13-01T00:00:00Z";
  EXPECT_THAT([&] { ParseTransferScenario(j, "x.json"); },
              ThrowsMessage<ScenarioError>(HasSubstr("scenario.transfer.epoch")));
  j["transfer"]["epoch"] = 2034;
  EXPECT_THAT([&] { ParseTransferScenario(j, "x.json"); },
              ThrowsMessage<ScenarioError>(HasSubstr("scenario.transfer.epoch")));
}

// The OEM of the replay: one segment from the start epoch to the arrival,
// read back by our parser, its last line the replay's end state.
TEST(TransferHandover, OemOfTheReplayReadsBack) {
  nlohmann::json j = Caillau60N();
  j["transfer"]["epoch"] = kStart;
  const TransferScenario sc = ParseTransferScenario(j, "60n.json");
  const TransferRun run = RunTransferScenario(sc, "60n.json", /*quiet=*/true);
  ASSERT_GT(run.orbit.size(), 50u);
  EXPECT_EQ(run.summary.at("orbit_source"), "replay");
  const std::string text = FormatOem(TransferOem(run.orbit, *sc.epoch, sc.name, "test"));
  const OemFile back = ParseOem(text, "x.oem");
  ASSERT_EQ(back.segments.size(), 1u);
  const OemSegment& seg = back.segments[0];
  EXPECT_EQ(seg.frame, dynamics::InertialFrame::kEme2000);
  EXPECT_EQ(seg.start_time, dynamics::Epoch::Parse(kStart));
  EXPECT_LT(
      std::abs(seg.stop_time.SecondsSince(*sc.epoch) - run.summary.at("duration_s").get<double>()),
      1e-3);
  EXPECT_LT((seg.points.back().rv.head<3>() - run.orbit.back().rv.head<3>()).norm(), 1e-3);
  // The replay's end orbit is GEO to the summary's figures.
  const transfer::Equinoctial end =
      transfer::EquinoctialFromCartesian(seg.points.back().rv, sc.problem.mu);
  EXPECT_NEAR(transfer::SemiMajorAxis(end), run.summary["replay"]["a_m"].get<double>(), 1e-2);
}

}  // namespace
}  // namespace thrustsched::app
