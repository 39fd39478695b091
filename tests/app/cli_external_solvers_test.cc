// The documented external-solver route: `thrustsched export` an MPS (or LP)
// file, solve it with the `cbc` and `glpsol` programs, map their solutions
// back with `thrustsched import-solution`, compare the objective with our own
// solve, and run `thrustsched check` on the schedules.
//
// DocumentedRoute runs the command block of data/scenarios/README.md section 7
// itself, line for line (SCENARIO.json and the bare file names replaced by the
// scenario and a temporary folder), on the thesis Table 4.1 cases: what the
// README tells a user to type is what is tested. Time limits are the
// documented ones (60 s); the assertions need only that a program finds a
// schedule in them (glpsol's first on the 3-day export came within its
// first 5 s progress line under load), never how good it is when the program
// stops at the limit: such a schedule must pass `check` and cost no less
// than our proven optimum; a program that reports optimality must match it.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

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

// The CPLEX LP file through cbc (the README mentions it in a comment; the
// documented routes below run MPS with both programs and LP with glpsol).
INSTANTIATE_TEST_SUITE_P(OnOffLpFile, ExternalSolvers,
                         ::testing::Combine(::testing::Values("hcw_table41_1d"),
                                            ::testing::Values("cbc-lp")),
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

// ---- the command block of data/scenarios/README.md section 7, as written

// One paragraph of the block: the commands of one route, each split into words.
using Command = std::vector<std::string>;
using Route = std::vector<Command>;

// The block's paragraphs, each preceded by the block's first command (the
// MPS export the later paragraphs solve); comments ("# ...") dropped.
std::vector<Route> DocumentedRoutes() {
  std::ifstream in(THRUSTSCHED_DATA_DIR "/scenarios/README.md");
  std::string line;
  while (std::getline(in, line) && line.rfind("## 7.", 0) != 0) {
  }
  while (std::getline(in, line) && line.rfind("```", 0) != 0) {
  }
  std::vector<Route> routes(1);
  while (std::getline(in, line) && line.rfind("```", 0) != 0) {
    const size_t hash = line.find(" #");
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    Command c;
    for (std::string w; words >> w;) c.push_back(w);
    if (c.empty()) {
      if (!routes.back().empty()) routes.emplace_back();
    } else {
      routes.back().push_back(c);
    }
  }
  if (routes.back().empty()) routes.pop_back();
  if (routes.empty() || routes[0].empty()) return {};
  const Command export_mps = routes[0][0];
  for (size_t r = 1; r < routes.size(); ++r) routes[r].insert(routes[r].begin(), export_mps);
  return routes;
}

// The route names of the parameterised cases, in the block's order.
const std::vector<std::string> kRouteNames = {"cbc", "glpsol", "glpsol_raw", "lp_file"};

double Capture(const std::string& text, const std::string& pattern) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(pattern))) return std::nan("");
  return std::stod(m[1]);
}

class DocumentedRoute : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST(DocumentedRouteBlock, HasTheFourRoutesEachEndingInCheck) {
  const std::vector<Route> routes = DocumentedRoutes();
  ASSERT_EQ(routes.size(), kRouteNames.size());
  for (const Route& r : routes) {
    ASSERT_GE(r.size(), 4u);
    EXPECT_EQ(r.front()[1], "export");
    EXPECT_EQ(r.back()[0] + " " + r.back()[1], "thrustsched check");
  }
}

TEST_P(DocumentedRoute, GivesAScheduleThatImportAndCheckAccept) {
  const auto& [name, route_index] = GetParam();
  const std::vector<Route> routes = DocumentedRoutes();
  ASSERT_EQ(routes.size(), kRouteNames.size()) << "data/scenarios/README.md section 7 changed";
  const Route& route = routes[route_index];
  for (const Command& c : route) {
    if (c[0] != "thrustsched" && !HaveProgram(c[0])) GTEST_SKIP() << c[0] << " not installed";
  }
  const std::string scenario = kScenarios + name + ".json";
  const std::string dir = TempDir("doc_" + kRouteNames[route_index]);
  RunResult r = RunCli({"solve", scenario, "--out", dir + "/ours", "--quiet", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const json ours = ReadJson(dir + "/ours/summary.json");
  ASSERT_EQ(ours["status"], "optimal");
  const double optimum = ours["objective"].get<double>();
  const double tol = ours["relative_gap"].get<double>() * optimum + 1e-6 * std::max(1.0, optimum);

  const std::regex file_name("[A-Za-z_][A-Za-z0-9_]*\\.(mps|lp|sol|txt|raw|csv)");
  double imported = std::nan("");
  int checks = 0;
  for (const Command& c : route) {
    std::vector<std::string> args;
    for (size_t k = 1; k < c.size(); ++k) {
      if (c[k] == "SCENARIO.json") {
        args.push_back(scenario);
      } else if (std::regex_match(c[k], file_name)) {
        args.push_back(dir + "/" + c[k]);
      } else {
        args.push_back(c[k]);
      }
    }
    std::string line;
    for (const std::string& w : c) line += w + " ";
    SCOPED_TRACE(line);
    if (c[0] != "thrustsched") {  // the other solver, within its documented time limit
      r = RunProgram(c[0], args, 300);
      ASSERT_TRUE(r.exited && r.exit_code == 0) << r.Describe();
      continue;
    }
    r = RunCli(args);
    ASSERT_EQ(r.exit_code, 0) << r.Describe();
    if (args[0] == "import-solution") {
      imported = RecomputedObjective(r.out);
      const double reported = ReportedObjective(r.out);
      // The program's own figure, printed to 8-10 digits, is ours recomputed.
      EXPECT_NEAR(reported, imported, 1e-7 * std::max(1.0, std::abs(imported))) << r.out;
      EXPECT_GE(imported, optimum - tol) << r.out;  // never better than the proven optimum
      std::smatch status;
      ASSERT_TRUE(std::regex_search(r.out, status, std::regex("status \"([^\"]*)\""))) << r.out;
      const std::string st = status[1];
      if (st == "INTEGER OPTIMAL" || st.rfind("Optimal", 0) == 0) {
        EXPECT_NEAR(imported, optimum, tol) << r.out;
      }
    } else if (args[0] == "check") {
      ++checks;
      EXPECT_NE(r.out.find("check         PASSED"), std::string::npos) << r.out;
      EXPECT_NEAR(Capture(r.out, "consumption ([-+0-9.eE]+) m/s \\(L1\\)"), imported,
                  1e-6 * std::max(1.0, imported))
          << r.out;
    }
  }
  EXPECT_EQ(checks, 1);
  fs::remove_all(dir);
}

std::string RouteCaseName(const ::testing::TestParamInfo<std::tuple<std::string, int>>& info) {
  return std::get<0>(info.param) + "_" + kRouteNames[std::get<1>(info.param)];
}

// Thesis Table 4.1, 1 to 3 days (1728 to 5184 binaries); every route.
INSTANTIATE_TEST_SUITE_P(Table41, DocumentedRoute,
                         ::testing::Combine(::testing::Values("hcw_table41_1d", "hcw_table41_2d",
                                                              "hcw_table41_3d"),
                                            ::testing::Range(0, 4)),
                         RouteCaseName);

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
