// The hand-over of a transfer to station keeping: summary.json's
// "final_state" read back by the real GEO scenario parser (app/scenario.h)
// inside a short GEO scenario gives the transfer's end state (the shipped
// 60 N minimum-time transfer, Caillau, Gergaud & Noailles 2003) and its
// epoch (the transfer's start + its duration); and the OEM of the replay.
#include <algorithm>
#include <cmath>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Dense>

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
  // Dense enough for the HERMITE 7 it announces: each line left out and
  // interpolated from its four neighbours (positions and velocities, so
  // over twice the file's spacing) is within 1 m (0.10 m at 60 N).
  double worst_m = 0;
  for (std::size_t i = 2; i + 2 < seg.points.size(); ++i) {
    Eigen::Matrix<double, 8, 8> a;
    Eigen::Matrix<double, 8, 3> b;
    int row = 0;
    for (std::size_t j : {i - 2, i - 1, i + 1, i + 2}) {
      const double x = seg.points[j].epoch.SecondsSince(seg.points[i].epoch) / 1000.0;  // ks
      for (int k = 0; k < 8; ++k) {
        a(row, k) = std::pow(x, k);
        a(row + 1, k) = k == 0 ? 0.0 : k * std::pow(x, k - 1);
      }
      b.row(row) = seg.points[j].rv.head<3>().transpose();
      b.row(row + 1) = 1000.0 * seg.points[j].rv.tail<3>().transpose();
      row += 2;
    }
    const Eigen::Matrix<double, 8, 3> c = a.fullPivLu().solve(b);
    worst_m = std::max(worst_m, (c.row(0).transpose() - seg.points[i].rv.head<3>()).norm());
  }
  EXPECT_LT(worst_m, 1.0);
  // The replay's end orbit is GEO to the summary's figures.
  const transfer::Equinoctial end =
      transfer::EquinoctialFromCartesian(seg.points.back().rv, sc.problem.mu);
  EXPECT_NEAR(transfer::SemiMajorAxis(end), run.summary["replay"]["a_m"].get<double>(), 1e-2);
}

// Two impulses: the OEM starts a segment at each impulse (the states before
// and after it share the epoch), and the velocity jumps there by the
// impulses' delta-v (MAP434: 3907.1 m/s in all).
TEST(TransferHandover, TwoImpulseOemHasASegmentPerArcSplitAtTheImpulses) {
  nlohmann::json j = nlohmann::json::parse(ReadFile(kData + "transfer/map434_hohmann.json"));
  j["transfer"]["epoch"] = kStart;
  const TransferScenario sc = ParseTransferScenario(j, "map434.json");
  const TransferRun run = RunTransferScenario(sc, "map434.json", /*quiet=*/true);
  const OemFile back =
      ParseOem(FormatOem(TransferOem(run.orbit, *sc.epoch, sc.name, "test")), "x.oem");
  ASSERT_EQ(back.segments.size(), 3u);
  EXPECT_EQ(back.segments[0].points.size(), 1u);
  EXPECT_EQ(back.segments[2].points.size(), 1u);
  EXPECT_EQ(back.segments[0].stop_time, back.segments[1].start_time);
  EXPECT_EQ(back.segments[1].stop_time, back.segments[2].start_time);
  const auto dv = [&](int a, int b) {
    return (back.segments[b].points.front().rv.tail<3>() -
            back.segments[a].points.back().rv.tail<3>())
        .norm();
  };
  const nlohmann::json& t = run.summary.at("two_impulse");
  EXPECT_NEAR(dv(0, 1), t.at("dv0_m_s").get<double>(), 1e-5);  // the file's 1 um/s
  EXPECT_NEAR(dv(1, 2), t.at("dvf_m_s").get<double>(), 1e-3);
  EXPECT_NEAR(dv(0, 1) + dv(1, 2), 3907.1, 0.05);
}

}  // namespace
}  // namespace thrustsched::app
