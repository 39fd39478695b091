// Co-located GEO satellites end to end (data/scenarios/fleet/geo_colocation_pair_2day.json):
// two e/i-separated satellites of the thesis, each with its four thrusters,
// rules and station-keeping sets, share the +-0.05 deg box for two days.
// References that share none of the fleet's code: each member's own
// scenario solved alone by `thrustsched solve` (the members' plans alone are
// the fleet optimum when they keep out of each other, which they do here),
// and the nonlinear replay of every member (GeoSimulator), whose exact
// separations must agree with the linearised positions the keep-out uses.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "app/fleet_scenario.h"
#include "tests/app/cli_runner.h"
#include "tests/app/test_messages.h"

namespace thrustsched::testing {
namespace {

using nlohmann::json;

const std::string kFleetDir = std::string(THRUSTSCHED_DATA_DIR) + "/scenarios/fleet";
const std::string kPair = kFleetDir + "/geo_colocation_pair_2day.json";
constexpr double kGuard = 3600.0;

std::string ErrorOf(const json& j) {
  return ScenarioErrorOf([&] { app::ParseFleetScenario(j, kFleetDir); });
}

TEST(FleetColocation, GeoMembersShareTheStationPointAndErrorsNameTheField) {
  const json base = ReadJson(kPair);
  EXPECT_EQ(ErrorOf(base), "(accepted)");
  json j = base;
  j["fleet"]["members"][1]["scenario"]["model"]["station_longitude_deg"] = 119.0;
  EXPECT_HAS(ErrorOf(j), "fleet.members[1].scenario: GEO members share one station point");
  EXPECT_HAS(ErrorOf(j), "station_longitude_deg 119 and epoch 2034-01-01T00:00:00Z differ");
  j = base;
  j["fleet"]["members"][1]["scenario"]["model"]["epoch"] = "2034-01-02T00:00:00Z";
  EXPECT_HAS(ErrorOf(j), "fleet.members[1].scenario: GEO members share one station point");
  j = base;
  j["fleet"]["couplings"] = {
      {{"member", "sat2"}, {"reference", "sat1"}, {"map", "position"}, {"offset", {0, 0, 0}}}};
  EXPECT_HAS(ErrorOf(j), "fleet.couplings[0].map: \"position\" is the first three states");
}

// One member's own scenario alone, by the single-spacecraft path.
double AloneObjective(const json& fleet, int member, const std::string& dir) {
  json s = fleet["fleet"]["members"][member]["scenario"];
  s["solver"] = {{"relative_gap", 1e-4}, {"threads", 1}};
  const std::string path = dir + "/alone_" + std::to_string(member) + ".json";
  WriteFile(path, s.dump());
  const RunResult r =
      RunCli({"solve", path, "--out", dir + "/alone_" + std::to_string(member)}, kGuard);
  EXPECT_EQ(r.exit_code, 0) << r.Describe();
  const json summary = ReadJson(dir + "/alone_" + std::to_string(member) + "/summary.json");
  EXPECT_EQ(summary["status"], "optimal");
  return summary["objective"].get<double>();
}

// Untimed (no time limit: the members alone are solved to their proofs), so
// the run is the same on any machine.
TEST(FleetColocation, PairKeepsOutAndIsTheSumOfItsMembersAloneInTheNonlinearReplay) {
  const std::string dir = TempDir("fleet_colocation");
  json j = ReadJson(kPair);
  j["fleet"]["solver"].erase("time_limit_s");
  WriteFile(dir + "/pair.json", j.dump());
  const RunResult r = RunCli({"solve", dir + "/pair.json", "--out", dir + "/pair"}, kGuard);
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const json s = ReadJson(dir + "/pair/summary.json");
  EXPECT_EQ(s["status"], "optimal") << s["solver_detail"];
  EXPECT_TRUE(s["start"]["accepted"].get<bool>()) << s["start"];
  for (int k = 0; k < 2; ++k) {
    const double alone = AloneObjective(j, k, dir);
    const double in_fleet = s["members"][k]["consumption"].get<double>();
    EXPECT_NEAR(in_fleet, alone, 2e-4 * alone) << k;  // both proven within 1e-4
    const json& check = s["members"][k]["check"];
    EXPECT_TRUE(check["passed"].get<bool>()) << check;
    EXPECT_TRUE(check["nonlinear_checked"].get<bool>());
    EXPECT_EQ(check["time_outside_window_nonlinear_s"].get<double>(),
              0.0);  // nobody leaves the box
  }
  EXPECT_TRUE(s["keep_out"]["held_on_samples"].get<bool>());
  EXPECT_TRUE(s["keep_out"]["held_nonlinear"].get<bool>());
  ASSERT_EQ(s["pairs"].size(), 1u);
  const json& p = s["pairs"][0];
  const double linear = p["min_distance_m"].get<double>();
  const double exact = p["nonlinear_min_distance_m"].get<double>();
  EXPECT_GT(exact, 5000.0);
  // The first-order position map: (25 km)^2 / a_mp = 15 m, plus the
  // linearisation of the dynamics over two days.
  EXPECT_NEAR(linear, exact, 100.0);
  EXPECT_NEAR(p["min_box_distance_m"].get<double>(),
              p["nonlinear_min_box_distance_m"].get<double>(), 100.0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace thrustsched::testing
