// Fleet scenario files end to end: the parser's messages name the field, and
// the `thrustsched` binary solves the two shipped double-integrator fleets to
// their derived optima, writes fleet.csv and one schedule per member (which
// `check` on the member's own scenario passes), and exports the fleet MILP.
//
// Derivations (1 m/s^2 on-off thrust, 6 slots of 1 s): a one-slot pulse moves
// a member by (t_N - the pulse's middle) times 1 m/s. Spread (x_b - x_a from
// 2 m to 6 m, equal final velocities): +X and -X of one member 4 slots apart
// (2 m/s in all), or one +X slot each, a at 4-5 s and b at 0-1 s (1 m/s
// each; or -X slots, a at 0-1 s and b at 4-5 s): min-max picks these, 1 + 0.001 x 2. Swap (x_b -
// x_a from 2 m to -2 m): the same 2 m/s, at a relative speed of 1 m/s that crosses the 1-m cube in
// 1 s, so two checks 0.5 s apart see it unless b steps aside with one y slot: 3 m/s (a faster
// crossing costs 2 m/s more per member).
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
const std::string kSpread = kFleetDir + "/di_spread.json";
const std::string kSwap = kFleetDir + "/di_swap.json";

std::string ErrorOf(const json& j) {
  return ScenarioErrorOf([&] { app::ParseFleetScenario(j, kFleetDir); });
}

TEST(FleetScenario, ErrorsNameTheField) {
  const json base = ReadJson(kSwap);
  EXPECT_EQ(ErrorOf(base), "(accepted)");
  EXPECT_EQ(ErrorOf(ReadJson(kSpread)), "(accepted)");  // a member by path
  json j = base;
  j["fleet"]["members"].erase(1);
  EXPECT_HAS(ErrorOf(j), "fleet.members: a fleet needs at least 2 members, got 1");
  j = base;
  j["fleet"]["members"][1]["name"] = "a";
  EXPECT_HAS(ErrorOf(j), "fleet.members[1].name: \"a\" is used twice");
  j = base;
  j["fleet"]["members"][1]["scenario"]["horizon"]["num_intervals"] = 0;
  EXPECT_HAS(ErrorOf(j), "fleet.members[1].scenario: scenario.horizon.num_intervals");
  j = base;
  j["fleet"]["members"][1]["scenario"]["horizon"]["num_intervals"] = 12;
  EXPECT_HAS(ErrorOf(j), "grid");
  j = base;
  j["fleet"]["members"][0]["scenario"] = "no_such_member.json";
  EXPECT_HAS(ErrorOf(j), "fleet.members[0].scenario: ");
  EXPECT_HAS(ErrorOf(j), "no_such_member.json: cannot open");
  j = base;
  j["fleet"]["members"][0]["scenario"]["input_mode"] = "impulsive";
  j["fleet"]["members"][0]["scenario"].erase("operations");
  EXPECT_HAS(ErrorOf(j), "fleet.members[0].scenario: a fleet member needs \"input_mode\"");
  j = base;
  j["fleet"]["couplings"][0]["member"] = "c";
  EXPECT_HAS(ErrorOf(j), "fleet.couplings[0].member: no member named \"c\"");
  j = base;
  j["fleet"]["couplings"][0]["map"][1] = {1, 2};
  EXPECT_HAS(ErrorOf(j), "fleet.couplings[0].map[1]: expected 6 numbers");
  j = base;
  j["fleet"]["couplings"][0]["offset"] = {1};
  EXPECT_HAS(ErrorOf(j), "fleet.couplings[0].offset");
  j = base;
  j["fleet"]["keep_out"]["check_times_s"] = {1, 2};
  EXPECT_HAS(ErrorOf(j), "fleet.keep_out");
  j = base;
  j["fleet"]["keep_out"].erase("check_step_s");
  j["fleet"]["keep_out"]["check_times_s"] = {1, 7};
  EXPECT_HAS(ErrorOf(j), "fleet.keep_out.check_times_s: [1] = 7 s");
  j = base;
  j["fleet"]["keep_out"]["half_size_m"] = -1;
  EXPECT_HAS(ErrorOf(j), "fleet.keep_out.half_size_m");
  j = base;
  j["fleet"]["balance"] = "fair";
  EXPECT_HAS(ErrorOf(j), "fleet.balance");
  j = base;
  j["fleet"]["colision"] = true;
  EXPECT_HAS(ErrorOf(j), "fleet.colision: unknown field");

  const app::FleetScenario f = app::ParseFleetScenario(base, kFleetDir);
  ASSERT_EQ(f.members.size(), 2u);
  EXPECT_EQ(f.problem.members[1].name, "b");
  ASSERT_TRUE(f.problem.keep_out.has_value());
  EXPECT_EQ(f.problem.keep_out->check_times_s.size(), 12u);  // 0.5, 1, ..., 6 s
  EXPECT_DOUBLE_EQ(f.problem.keep_out->check_times_s.back(), 6.0);
}

struct FleetRun {
  RunResult run;
  json summary;
};

FleetRun SolveFleetFile(const std::string& file, const std::string& dir) {
  FleetRun r;
  r.run = RunCli({"solve", file, "--out", dir});
  if (r.run.exit_code == 0) r.summary = ReadJson(dir + "/summary.json");
  return r;
}

std::string Edited(const std::string& file, const std::string& dir,
                   const std::function<void(json*)>& edit) {
  json j = ReadJson(file);
  // Member paths stay relative to the shipped folder.
  for (json& m : j["fleet"]["members"]) {
    if (m["scenario"].is_string())
      m["scenario"] = kFleetDir + "/" + m["scenario"].get<std::string>();
  }
  edit(&j);
  const std::string path = dir + "/edited.json";
  WriteFile(path, j.dump());
  return path;
}

TEST(FleetCli, SpreadIsBalancedAtOneMeterPerSecondEach) {
  const std::string dir = TempDir("fleet_spread");
  const FleetRun r = SolveFleetFile(kSpread, dir + "/solve");
  ASSERT_EQ(r.run.exit_code, 0) << r.run.Describe();
  const json& s = r.summary;
  EXPECT_EQ(s["status"], "optimal");
  EXPECT_NEAR(s["objective"].get<double>(), 1.0 + 0.001 * 2.0, 1e-9);
  ASSERT_EQ(s["members"].size(), 2u);
  for (const json& m : s["members"]) {
    EXPECT_NEAR(m["consumption"].get<double>(), 1.0, 1e-9) << m["name"];
    EXPECT_EQ(m["n_burns"], 1);
    EXPECT_TRUE(m["check"]["passed"].get<bool>());
  }
  // Two mirror optima: +X of a at 4-5 s and of b at 0-1 s, or -X of a at
  // 0-1 s and of b at 4-5 s; either way the same thruster, 4 s apart.
  const json& burn_a = s["members"][0]["burns"][0];
  const json& burn_b = s["members"][1]["burns"][0];
  EXPECT_EQ(burn_a["thruster"], burn_b["thruster"]);
  const double sign = burn_a["thruster"] == "+X" ? 1.0 : -1.0;
  EXPECT_DOUBLE_EQ(sign * (burn_a["start_s"].get<double>() - burn_b["start_s"].get<double>()), 4.0);
  ASSERT_EQ(s["coupling_residuals"].size(), 1u);
  EXPECT_LE(s["coupling_residuals"][0].get<double>(), 1e-9);
  EXPECT_HAS(ReadFile(dir + "/solve/fleet.csv"),
             "member_a,member_b,min_distance_m,min_box_distance_m,time_s,planned_min_distance_m,"
             "planned_min_box_distance_m,keep_out_half_size_m\na,b,2,2,0,");
  // The member's schedule passes the member's own scenario in `check`.
  RunResult c = RunCli({"check", kFleetDir + "/di_member_b.json", dir + "/solve/schedule_b.csv"});
  EXPECT_EQ(c.exit_code, 0) << c.Describe();

  // Without the balance, 2 m/s in all (however split).
  const std::string plain = Edited(kSpread, dir, [](json* j) { (*j)["fleet"].erase("balance"); });
  const FleetRun p = SolveFleetFile(plain, dir + "/plain");
  ASSERT_EQ(p.run.exit_code, 0) << p.run.Describe();
  EXPECT_NEAR(p.summary["objective"].get<double>(), 2.0, 1e-9);
  std::filesystem::remove_all(dir);
}

TEST(FleetCli, SwapStepsAsideForOneMoreSlot) {
  const std::string dir = TempDir("fleet_swap");
  const FleetRun r = SolveFleetFile(kSwap, dir + "/solve");
  ASSERT_EQ(r.run.exit_code, 0) << r.run.Describe();
  const json& s = r.summary;
  EXPECT_EQ(s["status"], "optimal");
  EXPECT_NEAR(s["objective"].get<double>(), 3.0, 1e-9);
  EXPECT_EQ(s["keep_out"]["checks"], 12);
  EXPECT_GT(s["keep_out"]["binaries"].get<int>(), 0);
  ASSERT_EQ(s["pairs"].size(), 1u);
  EXPECT_GE(s["pairs"][0]["planned_min_box_distance_m"].get<double>(), 0.5 - 1e-9);
  for (const json& m : s["members"]) EXPECT_TRUE(m["check"]["passed"].get<bool>());
  EXPECT_TRUE(s["keep_out"]["held_on_samples"].get<bool>());
  EXPECT_HAS(r.run.out, "keep-out      HELD");

  // Checked once a second, the swap of 2 m/s fits between the checks (at
  // 1 m/s relative speed the 1-m cube is crossed in 1 s, centred between
  // two whole seconds): the MILP keeps the plan without a step aside and the
  // re-check on the checker's fine samples reports the pair inside the cube.
  const std::string coarse = Edited(kSwap, dir, [](json* j) {
    (*j)["fleet"]["keep_out"].erase("check_step_s");
    (*j)["fleet"]["keep_out"]["check_times_s"] = {1, 2, 3, 4, 5, 6};
  });
  const FleetRun c = SolveFleetFile(coarse, dir + "/coarse");
  ASSERT_EQ(c.run.exit_code, 0) << c.run.Describe();
  EXPECT_NEAR(c.summary["objective"].get<double>(), 2.0, 1e-9);
  EXPECT_FALSE(c.summary["keep_out"]["held_on_samples"].get<bool>());
  EXPECT_LT(c.summary["keep_out"]["min_box_distance_on_samples_m"].get<double>(), 0.5);
  EXPECT_HAS(c.run.out, "keep-out      BROKEN");

  // Without the keep-out the swap costs 2 m/s and the members meet.
  const std::string free = Edited(kSwap, dir, [](json* j) { (*j)["fleet"].erase("keep_out"); });
  const FleetRun f = SolveFleetFile(free, dir + "/free");
  ASSERT_EQ(f.run.exit_code, 0) << f.run.Describe();
  EXPECT_NEAR(f.summary["objective"].get<double>(), 2.0, 1e-9);
  EXPECT_LT(f.summary["pairs"][0]["min_box_distance_m"].get<double>(), 0.5);
  std::filesystem::remove_all(dir);
}

TEST(FleetCli, ExportWritesTheFleetMilpAndBadInputExitsTwo) {
  const std::string dir = TempDir("fleet_export");
  RunResult v = RunCli({"validate", kSwap});
  EXPECT_EQ(v.exit_code, 0) << v.Describe();
  EXPECT_HAS(v.out, "fleet         di_swap: valid, 2 members");
  RunResult e = RunCli({"export", kSwap, dir + "/fleet.mps"});
  ASSERT_EQ(e.exit_code, 0) << e.Describe();
  const std::string mps = ReadFile(dir + "/fleet.mps");
  EXPECT_HAS(mps, " a.");
  EXPECT_HAS(mps, " b.");

  const std::string bad =
      Edited(kSwap, dir, [](json* j) { (*j)["fleet"]["keep_out"]["half_size_m"] = 0; });
  RunResult b = RunCli({"solve", bad, "--out", dir + "/bad"});
  EXPECT_EQ(b.exit_code, 2) << b.Describe();
  EXPECT_HAS(b.err, "fleet.keep_out.half_size_m");
  RunResult o = RunCli({"solve", kSwap, "--out", dir + "/o", "--no-search"});
  EXPECT_EQ(o.exit_code, 2) << o.Describe();
  EXPECT_HAS(o.err, "do not apply to a fleet");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace thrustsched::testing
