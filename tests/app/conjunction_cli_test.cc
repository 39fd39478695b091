// The "conjunction" section end to end: the parser's messages name the field
// and the value, and the `thrustsched` binary validates, exports (MPS with
// the keep-out rows), solves (summary.json with the keep-out rows, the budget
// rounds and a passing verification) and checks (a plan without manoeuvre
// fails the conjunction: exit 5) the small test case tests/app/data/conjunction_small.json.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "app/scenario.h"
#include "tests/app/cli_runner.h"
#include "tests/app/test_messages.h"

namespace thrustsched::testing {
namespace {

using nlohmann::json;

const std::string kSmall = THRUSTSCHED_APP_TEST_DATA "/conjunction_small.json";

std::string ErrorOf(const json& j) {
  return ScenarioErrorOf([&] { app::ParseScenario(j); });
}

TEST(ConjunctionSection, ErrorsNameTheField) {
  const json base = ReadJson(kSmall);
  EXPECT_EQ(ErrorOf(base), "(accepted)");
  json j = base;
  j["conjunction"]["frame"] = "eci";
  EXPECT_HAS(ErrorOf(j), "scenario.conjunction.frame");
  j = base;
  j["conjunction"]["covariance"][2] = json::array({1, 2, 3});
  EXPECT_HAS(ErrorOf(j), "scenario.conjunction.covariance[2]: expected 6 numbers");
  j = base;
  j["conjunction"]["risk_threshold"] = 1e-4;
  EXPECT_HAS(ErrorOf(j), "instantaneous_threshold");
  j = base;
  j["conjunction"].erase("checks");
  EXPECT_HAS(ErrorOf(j), "scenario.conjunction.checks");
  j = base;
  j["conjunction"]["checks"]["end_s"] = 30000;
  EXPECT_HAS(ErrorOf(j), "not inside the horizon");
  j = base;
  j["conjunction"]["covariance"][0][1] = 300;
  j["conjunction"]["covariance"][1][0] = 300;
  j["conjunction"]["covariance"][0][0] = 1;
  EXPECT_HAS(ErrorOf(j), "not positive semi-definite");
  j["conjunction"]["covariance_repair"] = "clip_eigenvalues";
  EXPECT_EQ(ErrorOf(j), "(accepted)");
  j = base;
  j["conjunction"]["polytope"] = {{"faces", {{1, 0, 0}}}, {"offsets_m", {14}}};
  EXPECT_HAS(ErrorOf(j), "does not contain the ball");
  j = base;
  j["conjunction"]["secondary"]["speed"] = 1;
  EXPECT_HAS(ErrorOf(j), "scenario.conjunction.secondary.speed: unknown field");
}

TEST(ConjunctionSection, SerraFrameAndGlobalRisk) {
  json j = ReadJson(kSmall);
  j["conjunction"]["frame"] = "serra_lvlh";
  j["conjunction"]["secondary"]["position_m"] = {1, 2, 3};
  j["conjunction"].erase("instantaneous_threshold");
  j["conjunction"]["risk_threshold"] = 1e-4;
  const app::Scenario s = app::ParseScenario(j);
  const auto& c = *s.problem.conjunction;
  EXPECT_EQ(c.secondary_state.head<3>(),
            Eigen::Vector3d(-3, 1, -2));                       // x = -z_S, y = x_S, z = -y_S
  EXPECT_DOUBLE_EQ(c.covariance(0, 0), 25.0);                  // var(z_S) -> var(x)
  EXPECT_DOUBLE_EQ(c.instantaneous_threshold, 1e-4 / 2000.0);  // over the 2000 s window
}

TEST(ConjunctionCli, ValidateExportSolveCheck) {
  const std::string dir = TempDir("conjunction");
  RunResult v = RunCli({"validate", kSmall});
  ASSERT_EQ(v.exit_code, 0) << v.Describe();
  EXPECT_HAS(v.out, "keep-out      3 checks");

  RunResult e = RunCli({"export", kSmall, dir + "/model.mps"});
  ASSERT_EQ(e.exit_code, 0) << e.Describe();
  const std::string mps = ReadFile(dir + "/model.mps");
  EXPECT_HAS(mps, "keep_out_budget");
  EXPECT_HAS(mps, "keep_out_w_");

  RunResult r = RunCli({"solve", kSmall, "--out", dir + "/solve", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(r.out, "conjunction   PASSED");
  const json summary = ReadJson(dir + "/solve/summary.json");
  EXPECT_EQ(summary["status"], "optimal");
  const json& c = summary["conjunction"];
  EXPECT_GT(c["keep_out"]["num_binaries"].get<int>(), 0);
  EXPECT_GE(c["solve"]["rounds"].size(), 1u);
  EXPECT_TRUE(c["verification"]["passed"].get<bool>());
  EXPECT_EQ(c["verification"]["collisions_linear"], 0);
  EXPECT_EQ(c["verification"]["collisions_nonlinear"], 0);
  EXPECT_GT(c["verification"]["collisions_unmanoeuvred_linear"].get<int>(), 0);
  EXPECT_LE(c["verification"]["max_risk"].get<double>(), 1e-6);
  // Impulsive mode: no plan without the conjunction is solved.
  EXPECT_TRUE(c["solve"]["without_conjunction_objective"].is_null());
  EXPECT_TRUE(c["solve"]["extra_cost"].is_null());

  RunResult ok = RunCli({"check", kSmall, dir + "/solve/impulses.csv"});
  EXPECT_EQ(ok.exit_code, 0) << ok.Describe();
  // No manoeuvre: terminal fine (the primary stays on its orbit), conjunction fails.
  WriteFile(dir + "/none.csv", "thruster,node,time_s,delta_v_m_s\n");
  RunResult none = RunCli({"check", kSmall, dir + "/none.csv", "--out", dir + "/none"});
  EXPECT_EQ(none.exit_code, 5) << none.Describe();
  EXPECT_HAS(none.out, "conjunction   FAILED");
  EXPECT_FALSE(
      ReadJson(dir + "/none/check.json")["conjunction"]["verification"]["passed"].get<bool>());
  std::filesystem::remove_all(dir);
}

// On-off mode: the primary at rest needs no burn without the conjunction;
// with it, the cheapest plan is one slot (0.05 N / 1000 kg x 500 s = 0.025
// m/s: a plan that moves the primary burns at least one whole slot), and the
// summary reports the plan without the conjunction and the extra cost.
TEST(ConjunctionCli, OnOffReportsTheExtraCostOverThePlanWithoutTheConjunction) {
  const std::string dir = TempDir("conjunction_onoff");
  const std::string scenario = THRUSTSCHED_APP_TEST_DATA "/conjunction_onoff_small.json";
  RunResult r = RunCli({"solve", scenario, "--out", dir + "/solve", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(r.out, "without       0 (the plan without the conjunction, bound 0)");
  EXPECT_HAS(r.out, "conjunction   PASSED");
  const json summary = ReadJson(dir + "/solve/summary.json");
  EXPECT_EQ(summary["status"], "optimal");
  EXPECT_NEAR(summary["objective"].get<double>(), 0.025, 1e-9);
  const json& solve = summary["conjunction"]["solve"];
  EXPECT_NEAR(solve["without_conjunction_objective"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(solve["lower_bound"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(solve["extra_cost"].get<double>(), 0.025, 1e-9);
  EXPECT_NE(solve["start_label"].get<std::string>().find("over 132 slots"), std::string::npos);
  EXPECT_TRUE(summary["conjunction"]["verification"]["passed"].get<bool>());

  // The plan without the conjunction (no burn) fails it: exit 5.
  WriteFile(dir + "/none.csv", "thruster,start_s,end_s\n");
  RunResult none = RunCli({"check", scenario, dir + "/none.csv", "--out", dir + "/none"});
  EXPECT_EQ(none.exit_code, 5) << none.Describe();
  EXPECT_HAS(none.out, "conjunction   FAILED");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace thrustsched::testing
