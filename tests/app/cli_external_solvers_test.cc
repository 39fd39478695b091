// The documented external-solver route: `thrustsched export` an MPS file,
// solve it with the `cbc` and `glpsol` programs, map their solutions back with
// `thrustsched import-solution`, compare the objective with our own solve
// (within the scenario's gap), and run `thrustsched check` on the schedules.
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "tests/app/cli_runner.h"

namespace thrustsched::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kScenarios = THRUSTSCHED_DATA_DIR "/scenarios/";

// "objective     0.01639175258 recomputed on our model" -> 0.01639175258.
double RecomputedObjective(const std::string& out) {
  std::smatch m;
  const std::regex re("objective +([-+0-9.eE]+) recomputed");
  if (!std::regex_search(out, m, re)) return std::nan("");
  return std::stod(m[1]);
}

// "solution ...: status "...", objective X" -> X (the solver's own figure).
double ReportedObjective(const std::string& out) {
  std::smatch m;
  const std::regex re("\", objective ([-+0-9.eE]+)");
  if (!std::regex_search(out, m, re)) return std::nan("");
  return std::stod(m[1]);
}

void RoundTrip(const std::string& name, const std::string& solver) {
  const std::string scenario = kScenarios + name + ".json";
  const std::string dir = TempDir("ext_" + solver);
  // Our own solve (to optimality within the scenario's gap).
  RunResult r = RunCli({"solve", scenario, "--out", dir + "/ours", "--quiet", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const json ours = ReadJson(dir + "/ours/summary.json");
  ASSERT_EQ(ours["status"], "optimal");
  const double objective = ours["objective"].get<double>();
  const double gap = ours["relative_gap"].get<double>();

  // "<program>-lp": the CPLEX LP export instead of MPS (its ranged rows carry
  // "~row" slack columns that import-solution must skip).
  const bool lp_format = solver.size() > 3 && solver.compare(solver.size() - 3, 3, "-lp") == 0;
  const std::string model = dir + (lp_format ? "/model.lp" : "/model.mps");
  r = RunCli({"export", scenario, model});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  std::string solution;
  std::string format = solver;
  if (solver == "cbc-lp") {
    solution = dir + "/cbc.sol";
    format = "cbc";
    r = RunProgram("cbc", {model, "sec", "120", "solve", "solu", solution}, 200);
  } else if (solver == "glpsol-lp") {
    solution = dir + "/glpsol.txt";
    format = "glpsol";
    r = RunProgram("glpsol", {"--lp", model, "--tmlim", "120", "-o", solution}, 200);
  } else if (solver == "cbc") {
    solution = dir + "/cbc.sol";
    r = RunProgram("cbc", {dir + "/model.mps", "sec", "120", "solve", "solu", solution}, 200);
  } else if (solver == "glpsol") {
    solution = dir + "/glpsol.txt";
    r = RunProgram("glpsol", {"--freemps", dir + "/model.mps", "--tmlim", "120", "-o", solution},
                   200);
  } else {  // glpsol-raw: full-precision values by column index
    solution = dir + "/glpsol.raw";
    r = RunProgram("glpsol", {"--freemps", dir + "/model.mps", "--tmlim", "120", "-w", solution},
                   200);
  }
  ASSERT_TRUE(r.exited && r.exit_code == 0) << r.Describe();

  r = RunCli(
      {"import-solution", scenario, solution, "--format", format, "--out", dir + "/schedule.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const double recomputed = RecomputedObjective(r.out);
  const double reported = ReportedObjective(r.out);
  // Both programs prove optimality here, so all three values agree within the gap
  // (plus the printing precision of the solution files).
  const double tol = gap * std::abs(objective) + 1e-6 * std::max(1.0, std::abs(objective));
  EXPECT_NEAR(recomputed, objective, tol) << r.out;
  EXPECT_NEAR(reported, objective, tol) << r.out;

  r = RunCli({"check", scenario, dir + "/schedule.csv", "--out", dir + "/check", "--no-plots"});
  if (ours["input_mode"] == "impulsive") {
    // import-solution wrote the impulses to the --out file.
    EXPECT_EQ(r.exit_code, 0) << r.Describe();
  } else {
    EXPECT_EQ(r.exit_code, 0) << r.Describe();
    const json c = ReadJson(dir + "/check/check.json");
    EXPECT_TRUE(c["passed"].get<bool>());
    EXPECT_NEAR(c["consumption_l1_m_s"].get<double>(), ours["consumption_l1_m_s"].get<double>(),
                tol);
  }
  fs::remove_all(dir);
}

class ExternalSolvers : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(ExternalSolvers, ExportSolveImportCheck) {
  const auto& [scenario, solver] = GetParam();
  const std::string program = solver.rfind("cbc", 0) == 0 ? "cbc" : "glpsol";
  if (!HaveProgram(program)) GTEST_SKIP() << program << " not installed";
  RoundTrip(scenario, solver);
}

std::string CaseName(const ::testing::TestParamInfo<std::tuple<std::string, std::string>>& info) {
  std::string s = std::get<0>(info.param) + "_" + std::get<1>(info.param);
  for (char& ch : s) {
    if (ch == '-') ch = '_';
  }
  return s;
}

// On-off MILPs: the binaries decide the schedule, so glpsol's 6-digit report suffices.
INSTANTIATE_TEST_SUITE_P(OnOff, ExternalSolvers,
                         ::testing::Combine(::testing::Values("hcw_table41_1d"),  // 1728 binaries
                                            ::testing::Values("cbc", "glpsol", "glpsol-raw")),
                         CaseName);
// The same model through the CPLEX LP file.
INSTANTIATE_TEST_SUITE_P(OnOffLpFile, ExternalSolvers,
                         ::testing::Combine(::testing::Values("hcw_table41_1d"),
                                            ::testing::Values("cbc-lp", "glpsol-lp")),
                         CaseName);
// 200 binaries; glpsol needs ~15 s on it, so one glpsol format only.
INSTANTIATE_TEST_SUITE_P(DoubleIntegrator, ExternalSolvers,
                         ::testing::Combine(::testing::Values("serra_double_integrator_onoff"),
                                            ::testing::Values("cbc", "glpsol")),
                         CaseName);
// Impulsive LP: impulse magnitudes need full precision (glpsol -o prints 6 digits).
INSTANTIATE_TEST_SUITE_P(Impulsive, ExternalSolvers,
                         ::testing::Combine(::testing::Values("serra_leo_circular"),
                                            ::testing::Values("cbc", "glpsol-raw")),
                         CaseName);

// An infeasible model: both programs say so and import-solution exits 3.
TEST(ExternalSolversInfeasible, ImportReportsInfeasible) {
  if (!HaveProgram("cbc")) GTEST_SKIP() << "cbc not installed";
  const std::string scenario = THRUSTSCHED_APP_TEST_DATA "/hcw_10km_infeasible_1d.json";
  const std::string dir = TempDir("ext_inf");
  ASSERT_EQ(RunCli({"export", scenario, dir + "/m.mps"}).exit_code, 0);
  const RunResult c =
      RunProgram("cbc", {dir + "/m.mps", "sec", "60", "solve", "solu", dir + "/s.sol"}, 120);
  ASSERT_TRUE(c.exited) << c.Describe();
  const RunResult r = RunCli(
      {"import-solution", scenario, dir + "/s.sol", "--format", "cbc", "--out", dir + "/x.csv"});
  EXPECT_EQ(r.exit_code, 3) << r.Describe();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace thrustsched::testing
