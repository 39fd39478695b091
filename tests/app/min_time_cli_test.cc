// "objective": "min_time" end to end: the parser's messages name the field,
// and the `thrustsched` binary solves the two shipped double-integrator
// cases to their closed forms (rest to rest over d = 1 m with |u| = U = 4
// m/s^2: T* = 2 sqrt(d / U) = 1 s with the fuel U T* = 4 m/s forced; with an
// L1 budget of 2 m/s, bang-coast-bang: T* = 1.25 s), a fly-by to the first
// grid node past sqrt(2 d / U), and exports the arrival MILP.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "app/scenario.h"
#include "tests/app/cli_runner.h"
#include "tests/app/test_messages.h"

namespace thrustsched::testing {
namespace {

using nlohmann::json;

const std::string kScenarios = std::string(THRUSTSCHED_DATA_DIR) + "/scenarios";
const std::string kBase = kScenarios + "/min_time_double_integrator.json";
const std::string kBudget = kScenarios + "/min_time_double_integrator_budget.json";

std::string ErrorOf(const json& j) {
  return ScenarioErrorOf([&] { app::ParseScenario(j); });
}

TEST(MinTimeObjective, ErrorsNameTheField) {
  const json base = ReadJson(kBase);
  EXPECT_EQ(ErrorOf(base), "(accepted)");
  json j = base;
  j.erase("terminal");
  EXPECT_HAS(ErrorOf(j), "scenario.objective: \"min_time\" needs the target set");
  j = base;
  j["terminal"] = {{"type", "free"}};
  EXPECT_HAS(ErrorOf(j), "got another type");
  j = base;
  j["objective"] = {{"kind", "min_time"}, {"fuel_budget", -1}};
  EXPECT_HAS(ErrorOf(j), "scenario.objective.fuel_budget");
  j = base;
  j["objective"] = {{"kind", "min_time"}, {"fuel", "time"}};
  EXPECT_HAS(ErrorOf(j), "scenario.objective.fuel");
  j = base;
  j["objective"] = {{"kind", "min_time"}, {"hold", "yes"}};
  EXPECT_HAS(ErrorOf(j), "scenario.objective.hold");
  j = base;
  j["objective"] = {{"kind", "min_time"}, {"holds", true}};
  EXPECT_HAS(ErrorOf(j), "scenario.objective.holds: unknown field");
  j = base;
  j["transcription"] = {{"formulation", "condensed"}};
  EXPECT_HAS(ErrorOf(j), "needs transcription.formulation \"sparse\"");
  j = base;
  j["input_mode"] = "impulsive";
  j.erase("operations");
  EXPECT_HAS(ErrorOf(j), "needs \"input_mode\": \"on_off\"");
  j = base;
  j["terminal"] = {{"type", "state_box"},
                   {"hcw_position_m", {1, 0, 0}},
                   {"hcw_velocity_m_s", {0, 0, 0}},
                   {"tolerance", {nullptr, nullptr, nullptr, nullptr, nullptr, nullptr}}};
  EXPECT_HAS(ErrorOf(j), "infinite for every component");

  // The target is the terminal set, which is then not imposed at t_N.
  const app::Scenario s = app::ParseScenario(base);
  ASSERT_TRUE(s.min_time.has_value());
  EXPECT_EQ(s.problem.terminal.kind, transcription::TerminalKind::kFree);
  EXPECT_DOUBLE_EQ(s.min_time->target[0], 1.0);
  EXPECT_EQ(s.min_time->tolerance.size(), 6);
  EXPECT_DOUBLE_EQ(s.min_time->tolerance.maxCoeff(), 0.0);
  EXPECT_TRUE(s.min_time->hold);
  EXPECT_EQ(s.problem.objective.kind, transcription::ObjectiveKind::kL1);
}

json SolveSummary(const std::string& scenario, const std::string& dir, RunResult* run) {
  *run = RunCli({"solve", scenario, "--out", dir, "--no-plots", "--no-report"});
  return run->exit_code == 0 ? ReadJson(dir + "/summary.json") : json();
}

TEST(MinTimeCli, RestToRestIsTwoSqrtOfDOverU) {
  const std::string dir = TempDir("min_time");
  RunResult r;
  const json summary = SolveSummary(kBase, dir + "/solve", &r);
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(r.out, "arrival       t = 1 s (node 20), proven earliest");
  EXPECT_EQ(summary["status"], "optimal");
  const json& m = summary["min_time"];
  EXPECT_NEAR(m["arrival_time_s"].get<double>(), 2.0 * std::sqrt(1.0 / 4.0), 1e-9);
  EXPECT_EQ(m["arrival_node"], 20);
  EXPECT_NEAR(m["arrival_bound_s"].get<double>(), 1.0, 1e-9);
  EXPECT_EQ(m["time_status"], "optimal");
  EXPECT_EQ(m["fuel_status"], "optimal");
  EXPECT_TRUE(m["verified"].get<bool>());
  EXPECT_LE(m["arrival_error"].get<double>(), 1e-6);
  EXPECT_NEAR(m["fuel"].get<double>(), 4.0, 1e-6);  // U T*: forced at the minimum time
  EXPECT_NEAR(summary["objective"].get<double>(), 4.0, 1e-6);
  EXPECT_EQ(summary["n_burns"], 2);  // +X for 0.5 s, then -X for 0.5 s
  EXPECT_TRUE(summary["check"]["operational_ok"].get<bool>());
  std::filesystem::remove_all(dir);
}

TEST(MinTimeCli, AFuelBudgetGivesBangCoastBang) {
  const std::string dir = TempDir("min_time_budget");
  RunResult r = RunCli({"solve", kBudget, "--out", dir + "/solve", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const json summary = ReadJson(dir + "/solve/summary.json");
  EXPECT_HAS(ReadFile(dir + "/solve/report.html"),
             "arrival (minimum time)</th><td>1.25 s after the start, proven earliest; verified");
  const json& m = summary["min_time"];
  EXPECT_NEAR(m["arrival_time_s"].get<double>(), 1.25, 1e-9);
  EXPECT_EQ(m["time_status"], "optimal");
  EXPECT_TRUE(m["verified"].get<bool>());
  EXPECT_NEAR(m["fuel"].get<double>(), 2.0, 1e-6);
  EXPECT_NEAR(m["fuel_budget"].get<double>(), 2.0, 0.0);
  std::filesystem::remove_all(dir);
}

// Reaching x = 1 m within 1 cm at any speed: full thrust needs sqrt(2 d / U)
// = 0.707 s, so the first node is 0.75 s (node 14 at 0.70 s reaches at most
// U t^2 / 2 = 0.98 m).
TEST(MinTimeCli, AFlyByArrivesAtTheFirstNodePastTheFullThrustTime) {
  const std::string dir = TempDir("min_time_flyby");
  json j = ReadJson(kBase);
  j["objective"] = {{"kind", "min_time"}, {"hold", false}};
  j["terminal"] = {{"type", "state_box"},
                   {"hcw_position_m", {1, 0, 0}},
                   {"hcw_velocity_m_s", {0, 0, 0}},
                   {"tolerance", {0.01, 1e-6, 1e-6, nullptr, 1e-6, 1e-6}}};
  WriteFile(dir + "/flyby.json", j.dump());
  RunResult r;
  const json summary = SolveSummary(dir + "/flyby.json", dir + "/solve", &r);
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const json& m = summary["min_time"];
  EXPECT_NEAR(m["arrival_time_s"].get<double>(), 0.75, 1e-9);
  EXPECT_EQ(m["time_status"], "optimal");
  EXPECT_FALSE(m["hold"].get<bool>());
  EXPECT_TRUE(m["verified"].get<bool>());
  EXPECT_TRUE(m["tolerance"][3].is_null());
  std::filesystem::remove_all(dir);
}

TEST(MinTimeCli, ExportWritesTheArrivalMilpAndBadInputExitsTwo) {
  const std::string dir = TempDir("min_time_export");
  RunResult e = RunCli({"export", kBase, dir + "/arrival.mps"});
  ASSERT_EQ(e.exit_code, 0) << e.Describe();
  EXPECT_HAS(e.out, "objective: arrival time");
  const std::string mps = ReadFile(dir + "/arrival.mps");
  EXPECT_HAS(mps, "arrive_at_20");
  EXPECT_HAS(mps, "arrive_once");

  json j = ReadJson(kBase);
  j.erase("terminal");
  WriteFile(dir + "/bad.json", j.dump());
  RunResult bad = RunCli({"solve", dir + "/bad.json", "--out", dir + "/bad"});
  EXPECT_EQ(bad.exit_code, 2) << bad.Describe();
  EXPECT_HAS(bad.err, "scenario.objective");
  WriteFile(dir + "/x.sol", "Optimal - objective value 1\n");
  RunResult imp = RunCli(
      {"import-solution", kBase, dir + "/x.sol", "--format", "cbc", "--out", dir + "/s.csv"});
  EXPECT_EQ(imp.exit_code, 2) << imp.Describe();
  EXPECT_HAS(imp.err, "import-solution reads solutions of the schedule MILP");
  RunResult cond = RunCli({"solve", kBase, "--out", dir + "/cond", "--formulation", "condensed"});
  EXPECT_EQ(cond.exit_code, 2) << cond.Describe();
  EXPECT_HAS(cond.err, "--formulation");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace thrustsched::testing
