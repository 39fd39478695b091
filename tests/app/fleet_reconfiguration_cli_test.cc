// The shipped HCW formation deployment (data/scenarios/fleet/
// hcw_reconfiguration.json) end to end, against references that do not go
// through the fleet: every deputy for every slot solved as a single scenario
// (the slot as its terminal `state_box`, read by the scenario parser), the
// least of the 3! sums enumerated here. That is the fleet without its
// keep-out: the fleet's decoupled bound must be exactly it, its plan within
// the gap asked of it, its keep-out held on the checker's samples, and its
// Monte Carlo of the uncertain initial states must see no pair within the
// cube's half size. (The cheapest assignment's deputies alone collide once
// the margins for the uncertainty are added, so the fleet's plan costs more
// than the relaxation.) The same 9 single scenarios by plain CBC (no search) are the slow
// case. And the new fields' errors name the field.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/fleet_scenario.h"
#include "tests/app/cli_runner.h"
#include "tests/app/test_messages.h"

namespace thrustsched::testing {
namespace {

using nlohmann::json;

const std::string kFleetDir = std::string(THRUSTSCHED_DATA_DIR) + "/scenarios/fleet";
const std::string kFile = kFleetDir + "/hcw_reconfiguration.json";
constexpr double kGuard = 3600.0;

std::string ErrorOf(const json& j) {
  return ScenarioErrorOf([&] { app::ParseFleetScenario(j, kFleetDir); });
}

TEST(FleetReconfiguration, UncertaintyFieldsAreReadAndErrorsNameTheField) {
  const json base = ReadJson(kFile);
  EXPECT_EQ(ErrorOf(base), "(accepted)");
  const app::FleetScenario f = app::ParseFleetScenario(base, kFleetDir);
  ASSERT_TRUE(f.problem.keep_out.has_value());
  EXPECT_DOUBLE_EQ(f.problem.keep_out->instantaneous_threshold, 1e-4);
  EXPECT_NEAR(f.problem.members[0].initial_covariance(0, 0), 0.25, 1e-15);  // 0.5 m squared
  EXPECT_NEAR(f.problem.members[2].initial_covariance(5, 5), 2.5e-7, 1e-20);
  EXPECT_EQ(f.options.monte_carlo.samples, 100000);
  ASSERT_TRUE(f.problem.assignment.has_value());
  EXPECT_DOUBLE_EQ(f.problem.assignment->tolerance[3], 0.02);

  json j = base;
  j["fleet"]["members"][1]["initial_std"] = {1, 2};
  EXPECT_HAS(ErrorOf(j), "fleet.members[1].initial_std: expected 6 numbers");
  j = base;
  j["fleet"]["members"][1]["initial_covariance"] = json::array();
  EXPECT_HAS(ErrorOf(j), "fleet.members[1]: ");
  EXPECT_HAS(ErrorOf(j), "initial_covariance");
  j = base;
  j["fleet"]["members"][0].erase("initial_std");
  j["fleet"]["members"][0]["initial_covariance"] = json::array();
  for (int r = 0; r < 6; ++r)
    j["fleet"]["members"][0]["initial_covariance"].push_back({0, 0, 0, 0, 0, 0});
  j["fleet"]["members"][0]["initial_covariance"][0][0] = -1.0;
  EXPECT_HAS(ErrorOf(j), "fleet: members[0].initial_covariance: not positive semi-definite");
  j["fleet"]["members"][0]["initial_covariance"][0][0] = 1.0;
  j["fleet"]["members"][0]["initial_covariance"][0][1] = 0.5;
  EXPECT_HAS(ErrorOf(j), "fleet: members[0].initial_covariance: not symmetric");
  j = base;
  j["fleet"]["keep_out"]["instantaneous_threshold"] = 0.7;
  EXPECT_HAS(ErrorOf(j), "fleet.keep_out.instantaneous_threshold: must be in (0, 0.5), got 0.7");
  j = base;
  j["fleet"]["assignment"]["tolerance"][2] = -1;
  EXPECT_HAS(ErrorOf(j), "fleet.assignment.tolerance[2]");
  j = base;
  for (json& m : j["fleet"]["members"]) m.erase("initial_std");
  EXPECT_HAS(ErrorOf(j),
             "fleet.monte_carlo: needs a keep_out and a member with initial_covariance");
  j = base;
  j["fleet"]["monte_carlo"]["samples"] = -3;
  EXPECT_HAS(ErrorOf(j), "fleet.monte_carlo.samples");
}

// One deputy alone for one slot: the member scenario with the slot as its
// terminal state box, solved by `thrustsched solve`.
double AloneObjective(const json& fleet, int member, int slot, const std::string& dir,
                      bool no_search) {
  json s = fleet["fleet"]["members"][member]["scenario"];
  const json& a = fleet["fleet"]["assignment"];
  const json& target = a["slots"][slot];
  s["terminal"] = {{"type", "state_box"},
                   {"hcw_position_m", {target[0], target[1], target[2]}},
                   {"hcw_velocity_m_s", {target[3], target[4], target[5]}},
                   {"tolerance", a["tolerance"]}};
  s["solver"] = {{"relative_gap", 0}, {"threads", 1}};
  const std::string tag = std::to_string(member) + "_" + std::to_string(slot);
  const std::string path = dir + "/alone_" + tag + ".json";
  WriteFile(path, s.dump());
  std::vector<std::string> args = {"solve", path, "--out", dir + "/alone_" + tag};
  if (no_search) args.push_back("--no-search");
  const RunResult r = RunCli(args, kGuard);
  EXPECT_EQ(r.exit_code, 0) << r.Describe();
  const json summary = ReadJson(dir + "/alone_" + tag + "/summary.json");
  EXPECT_EQ(summary["status"], "optimal") << tag;
  return summary["objective"].get<double>();
}

// The least over the 3! assignments of the sum of the deputies alone.
double LeastAssignment(const json& fleet, const std::string& dir, bool no_search) {
  double cost[3][3];
  for (int i = 0; i < 3; ++i)
    for (int s = 0; s < 3; ++s) cost[i][s] = AloneObjective(fleet, i, s, dir, no_search);
  std::vector<int> perm = {0, 1, 2};
  double best = INFINITY;
  do {
    best = std::min(best, cost[0][perm[0]] + cost[1][perm[1]] + cost[2][perm[2]]);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

// The fleet, untimed: the members alone are solved to their proofs (no time
// share), and the 10 % gap stops the fleet at the first plan the decoupled
// bound accepts, so the run is the same on any machine.
void ExpectTheFleetWithin(double relaxation, double gap, const std::string& dir) {
  json j = ReadJson(kFile);
  j["fleet"]["solver"]["relative_gap"] = gap;
  j["fleet"]["solver"].erase("time_limit_s");
  WriteFile(dir + "/fleet.json", j.dump());
  const RunResult r = RunCli({"solve", dir + "/fleet.json", "--out", dir + "/fleet"}, kGuard);
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const json s = ReadJson(dir + "/fleet/summary.json");
  EXPECT_EQ(s["status"], "optimal") << s["solver_detail"];
  // The decoupled bound is the enumerated relaxation (no keep-out) exactly.
  EXPECT_NEAR(s["start"]["bound"].get<double>(), relaxation, 1e-9);
  EXPECT_NEAR(s["best_bound"].get<double>(), relaxation, 1e-9);
  const double objective = s["objective"].get<double>();
  EXPECT_GE(objective, relaxation - 1e-9);
  EXPECT_LE(objective, relaxation / (1.0 - gap) + 1e-9);
  EXPECT_TRUE(s["start"]["accepted"].get<bool>()) << s["start"];
  EXPECT_TRUE(s["keep_out"]["held_on_samples"].get<bool>());
  EXPECT_GT(s["keep_out"]["margin_max_m"].get<double>(), 0.0);
  EXPECT_EQ(s["monte_carlo"]["samples"], 100000);
  EXPECT_EQ(s["monte_carlo"]["collisions"], 0);
  EXPECT_GE(s["monte_carlo"]["min_distance_m"].get<double>(), 10.0);
  std::vector<int> slots;
  for (const json& m : s["members"]) {
    EXPECT_TRUE(m["check"]["passed"].get<bool>()) << m["name"];
    slots.push_back(m["slot"].get<int>());
  }
  std::sort(slots.begin(), slots.end());
  EXPECT_EQ(slots, (std::vector<int>{0, 1, 2}));
  for (double v : s["coupling_residuals"]) EXPECT_LE(v, 1e-9);
}

TEST(FleetReconfiguration, DeploymentIsTheLeastAssignmentOfTheDeputiesAlone) {
  const std::string dir = TempDir("fleet_hcw");
  const double expected = LeastAssignment(ReadJson(kFile), dir, /*no_search=*/false);
  ASSERT_TRUE(std::isfinite(expected));
  ExpectTheFleetWithin(expected, 0.1, dir);
  std::filesystem::remove_all(dir);
}

// The same references by plain CBC (about a minute each on 2 cores).
TEST(FleetReconfiguration, SlowDeputiesAloneByPlainCbcAgree) {
  const std::string dir = TempDir("fleet_hcw_cbc");
  // One output folder per run: the two sets of solves in their own.
  std::filesystem::create_directories(dir + "/cbc");
  std::filesystem::create_directories(dir + "/search");
  const double by_cbc = LeastAssignment(ReadJson(kFile), dir + "/cbc", /*no_search=*/true);
  const double by_search = LeastAssignment(ReadJson(kFile), dir + "/search", /*no_search=*/false);
  EXPECT_NEAR(by_cbc, by_search, 1e-9);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace thrustsched::testing
