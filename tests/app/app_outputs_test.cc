// Output writers and readers of the scenario library: schedule/impulse CSV
// round trips and rejections, other solvers' solution files, the checker
// verdict, trajectory columns, and the gnuplot scripts.
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "app/outputs.h"
#include "app/plots.h"
#include "app/scenario.h"
#include "app/solution_import.h"
#include "tests/app/cli_runner.h"
#include "tests/app/test_messages.h"

namespace thrustsched::app {
namespace {

using testing::ReadFile;
using testing::TempDir;
using testing::WriteFile;

Scenario Hcw() {
  return ParseScenarioText(R"({
    "name": "hcw_out",
    "model": {"type": "hcw", "mean_motion_rad_s": 7.2921159e-5},
    "spacecraft": {"mass_kg": 4850, "isp_s": 2005, "thrust_n": 0.265, "thrusters": {"preset": "ideal6"}},
    "initial_state": {"hcw_position_m": [1000, 0, 0]},
    "horizon": {"duration_s": 3600, "step_s": 300},
    "window": {"half_width_m": 36800},
    "operations": {"min_burn_s": 300, "min_off_same_s": 1200, "min_gap_other_s": 300}
  })");
}

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const ScenarioError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ScenarioError";
  return "";
}

TEST(ScheduleCsv, RoundTrip) {
  const Scenario s = Hcw();
  const std::string dir = TempDir("csv");
  const std::vector<transcription::Burn> burns = {{4, 600, 1200}, {0, 1800, 2100.5}};
  WriteScheduleCsv(dir + "/s.csv", s, burns);
  EXPECT_EQ(ReadFile(dir + "/s.csv"),
            "thruster,start_s,end_s,duration_s\n-T,600,1200,600\n+R,1800,2100.5,300.5\n");
  const auto back = ReadScheduleCsv(dir + "/s.csv", s);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].thruster, 4);
  EXPECT_EQ(back[1].thruster, 0);
  EXPECT_DOUBLE_EQ(back[1].end_s, 2100.5);
  // Hand-written: comments, blank lines, no duration column, spaces.
  WriteFile(dir + "/h.csv", "# by hand\nthruster, start_s, end_s\n\n+N, 0, 300\n");
  const auto h = ReadScheduleCsv(dir + "/h.csv", s);
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0].thruster, 2);
  std::filesystem::remove_all(dir);
}

TEST(ScheduleCsv, RejectsBadFiles) {
  const Scenario s = Hcw();
  const std::string dir = TempDir("csvbad");
  auto err = [&](const std::string& text) {
    WriteFile(dir + "/b.csv", text);
    return ErrorOf([&] { ReadScheduleCsv(dir + "/b.csv", s); });
  };
  EXPECT_HAS(err("thruster,begin,end_s\n"), "header column \"begin\" is unknown");
  EXPECT_HAS(err("thruster,start_s\n"), "header lacks column \"end_s\"");
  EXPECT_HAS(err("thruster,start_s,end_s\nNE,0,300\n"),
             ":2: thruster \"NE\" is not in the scenario");
  EXPECT_HAS(err("thruster,start_s,end_s\n+R,0,abc\n"),
             ":2: end_s must be a finite number, got \"abc\"");
  EXPECT_HAS(err("thruster,start_s,end_s\n+R,0,inf\n"),
             "end_s must be a finite number, got \"inf\"");
  EXPECT_HAS(err("thruster,start_s,end_s\n+R,600,300\n"), "end_s 300 is before start_s 600");
  EXPECT_HAS(err("thruster,start_s,end_s,duration_s\n+R,0,300,200\n"),
             "duration_s 200 disagrees with end_s - start_s = 300");
  EXPECT_HAS(err("thruster,start_s,end_s\n+R,0\n"), "expected 3 fields, got 2");
  EXPECT_HAS(err(""), "empty file");
  EXPECT_HAS(ErrorOf([&] { ReadScheduleCsv(dir + "/missing.csv", s); }), "cannot open");
  std::filesystem::remove_all(dir);
}

TEST(ImpulsesCsv, RoundTripAndRejections) {
  Scenario s = Hcw();
  const std::string dir = TempDir("imp");
  WriteImpulsesCsv(dir + "/i.csv", s, {{2, 3, 900, 0.125}});
  EXPECT_EQ(ReadFile(dir + "/i.csv"), "thruster,node,time_s,delta_v_m_s\n+N,3,900,0.125\n");
  const auto back = ReadImpulsesCsv(dir + "/i.csv", s);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].node, 3);
  EXPECT_DOUBLE_EQ(back[0].time_s, 900);
  EXPECT_DOUBLE_EQ(back[0].delta_v_m_s, 0.125);
  WriteFile(dir + "/b.csv", "thruster,node,time_s,delta_v_m_s\n+N,13,,1\n");
  EXPECT_HAS(ErrorOf([&] { ReadImpulsesCsv(dir + "/b.csv", s); }),
             "node must be an integer in [0, 12], got 13");
  WriteFile(dir + "/b.csv", "thruster,node,time_s,delta_v_m_s\n+N,2,500,1\n");
  EXPECT_HAS(ErrorOf([&] { ReadImpulsesCsv(dir + "/b.csv", s); }),
             "time_s 500 is not the time of node 2 (600)");
  WriteFile(dir + "/b.csv", "thruster,node,delta_v_m_s\n+N,2,-1\n");
  EXPECT_HAS(ErrorOf([&] { ReadImpulsesCsv(dir + "/b.csv", s); }),
             "delta_v_m_s must be >= 0, got -1");
  std::filesystem::remove_all(dir);
}

// Real output of `cbc t.mps sec 10 solve solu file` (CBC 2.10.8) on a 3-column model.
constexpr const char* kCbcSolution =
    "Optimal - objective value 0.75000000\n"
    "      0 on_0_0                                        0                     0.5\n"
    "      1 on_1_0                                        0                       2\n"
    "      2 x_state_with_a_very_long_name_0             1.5                       0\n";
// Same with `printingOptions all`: rows first, then columns, both numbered from 0.
constexpr const char* kCbcSolutionAll =
    "Optimal - objective value 0.75000000\n"
    "      0 c1                                            0                       0\n"
    "      1 c2                                          1.5                     0.5\n"
    "      0 on_0_0                                        0                     0.5\n"
    "      1 on_1_0                                        1                       2\n"
    "**    2 x_state_with_a_very_long_name_0             1.5                       0\n";
// Real output of `glpsol --freemps t.mps -o file` (GLPK 5.0), long name wrapped.
constexpr const char* kGlpsolReport =
    "Problem:    tiny\nRows:       2\nColumns:    3 (2 integer, 2 binary)\nNon-zeros:  4\n"
    "Status:     INTEGER OPTIMAL\nObjective:  obj = 0.75 (MINimum)\n\n"
    "   No.   Row name        Activity     Lower bound   Upper bound\n"
    "------ ------------    ------------- ------------- -------------\n"
    "     1 c1                          0                           1 \n"
    "     2 c2                        1.5           1.5               \n\n"
    "   No. Column name       Activity     Lower bound   Upper bound\n"
    "------ ------------    ------------- ------------- -------------\n"
    "     1 on_0_0       *              0             0             1 \n"
    "     2 on_1_0       *              1             0             1 \n"
    "     3 x_state_with_a_very_long_name_0\n"
    "                                 1.5             0            10 \n\n"
    "Integer feasibility conditions:\n\nKKT.PE: max.abs.err = 0.00e+00 on row 0\n\nEnd of output\n";

TEST(SolutionImport, CbcAndGlpsolFiles) {
  const std::string dir = TempDir("sol");
  const std::vector<std::string> cols = {"on_0_0", "on_1_0", "x_state_with_a_very_long_name_0",
                                         "never_listed"};
  WriteFile(dir + "/cbc.sol", kCbcSolution);
  ImportedSolution c = ReadSolutionFile(dir + "/cbc.sol", SolutionFormat::kCbc);
  EXPECT_TRUE(c.has_solution);
  EXPECT_EQ(c.status, "Optimal");
  EXPECT_DOUBLE_EQ(c.objective, 0.75);
  Eigen::VectorXd x = ToColumnVector(c, cols);
  EXPECT_EQ(x, (Eigen::VectorXd(4) << 0, 0, 1.5, 0).finished());

  WriteFile(dir + "/cbc_all.sol", kCbcSolutionAll);
  c = ReadSolutionFile(dir + "/cbc_all.sol", SolutionFormat::kCbc);
  EXPECT_EQ(c.values.count("c1"), 0u);  // rows dropped
  EXPECT_EQ(ToColumnVector(c, cols), (Eigen::VectorXd(4) << 0, 1, 1.5, 0).finished());

  WriteFile(dir + "/glp.txt", kGlpsolReport);
  const ImportedSolution g = ReadSolutionFile(dir + "/glp.txt", SolutionFormat::kGlpsol);
  EXPECT_TRUE(g.has_solution);
  EXPECT_EQ(g.status, "INTEGER OPTIMAL");
  EXPECT_DOUBLE_EQ(g.objective, 0.75);
  EXPECT_EQ(ToColumnVector(g, cols), (Eigen::VectorXd(4) << 0, 1, 1.5, 0).finished());

  // LP report (`glpsol -o` on a model without integers) has a status column.
  WriteFile(dir + "/lp.txt",
            "Status:     OPTIMAL\nObjective:  OBJ = 3.614231267 (MINimum)\n\n"
            "   No. Column name  St   Activity     Lower bound   Upper bound    Marginal\n"
            "------ ------------ -- ------------- ------------- ------------- -------------\n"
            "     1 on_0_0       NS             0             0             =         < eps\n"
            "     2 on_1_0       B        3.43775\n"
            "     3 x_state_with_a_very_long_name_0\n"
            "                    NL           1.5             0                       0.5 \n\n");
  const ImportedSolution lp = ReadSolutionFile(dir + "/lp.txt", SolutionFormat::kGlpsol);
  EXPECT_TRUE(lp.has_solution);
  EXPECT_EQ(ToColumnVector(lp, cols), (Eigen::VectorXd(4) << 0, 3.43775, 1.5, 0).finished());

  // GLPK raw files (glpsol -w): columns by index, full precision.
  WriteFile(dir + "/mip.raw",
            "c Problem: tiny\nc\ns mip 2 4 o 0.75\ni 1 0\ni 2 1.5\n"
            "j 1 0\nj 2 1\nj 3 1.5000000000000002\nj 4 0\ne o f\n");
  const ImportedSolution raw = ReadSolutionFile(dir + "/mip.raw", SolutionFormat::kGlpkRaw);
  EXPECT_TRUE(raw.has_solution);
  EXPECT_DOUBLE_EQ(raw.objective, 0.75);
  EXPECT_EQ(ToColumnVector(raw, cols),
            (Eigen::VectorXd(4) << 0, 1, 1.5000000000000002, 0).finished());
  EXPECT_HAS(ErrorOf([&] {
               ToColumnVector(raw, {"a", "b"});
             }),
             "solution has 4 columns, the scenario's model has 2");
  WriteFile(dir + "/lp.raw", "s bas 1 2 f f 3.5\ni 1 b 3.5 0\nj 1 b 3.25 0\nj 2 l 0 1\n");
  const ImportedSolution lpraw = ReadSolutionFile(dir + "/lp.raw", SolutionFormat::kGlpkRaw);
  EXPECT_TRUE(lpraw.has_solution);
  EXPECT_EQ(lpraw.values_by_index, (std::vector<double>{3.25, 0}));
  WriteFile(dir + "/nofeas.raw", "s mip 1 2 n 0\nj 1 0\nj 2 0\n");
  EXPECT_FALSE(ReadSolutionFile(dir + "/nofeas.raw", SolutionFormat::kGlpkRaw).has_solution);
  EXPECT_EQ(ParseSolutionFormat("glpsol-raw"), SolutionFormat::kGlpkRaw);

  WriteFile(dir + "/inf.sol", "Infeasible - objective value 0.00000000\n");
  EXPECT_FALSE(ReadSolutionFile(dir + "/inf.sol", SolutionFormat::kCbc).has_solution);
  WriteFile(dir + "/none.txt", "Status:     INTEGER UNDEFINED\nObjective:  obj = 0 (MINimum)\n");
  EXPECT_FALSE(ReadSolutionFile(dir + "/none.txt", SolutionFormat::kGlpsol).has_solution);

  // Wrong model: a column we do not have.
  EXPECT_HAS(ErrorOf([&] { ToColumnVector(g, {"on_0_0"}); }),
             "\"on_1_0\", which the scenario's model does not have");
  WriteFile(dir + "/junk.sol", "Optimal - objective value 1\nnot a solution line\n");
  EXPECT_HAS(ErrorOf([&] { ReadSolutionFile(dir + "/junk.sol", SolutionFormat::kCbc); }),
             "junk.sol:2");
  WriteFile(dir + "/junk.txt", "hello\n");
  EXPECT_HAS(ErrorOf([&] { ReadSolutionFile(dir + "/junk.txt", SolutionFormat::kGlpsol); }),
             "no \"Status:\" line");
  EXPECT_HAS(ErrorOf([&] { ParseSolutionFormat("gurobi"); }),
             "--format: unknown solution format \"gurobi\"");
  std::filesystem::remove_all(dir);
}

TEST(Verdict, JudgesRulesWindowAndTerminal) {
  Scenario s = Hcw();  // tolerance 36.8 m
  transcription::CheckReport r;
  r.max_window_violation_at_nodes = 30.0;
  r.max_window_violation = 500.0;  // between nodes: reported, not judged by default
  EXPECT_TRUE(Judge(s, r).passed);
  s.verdict.include_intersample = true;
  CheckVerdict v = Judge(s, r);
  EXPECT_FALSE(v.passed);
  ASSERT_EQ(v.findings.size(), 1u);
  EXPECT_HAS(v.findings[0], "between nodes by 500 m");
  s.verdict.include_intersample = false;
  r.max_window_violation_at_nodes = 40.0;
  v = Judge(s, r);
  EXPECT_FALSE(v.passed);
  EXPECT_HAS(v.findings[0], "window violated at grid nodes by 40 m (tolerance 36.8 m)");
  r.max_window_violation_at_nodes = 0;
  r.terminal_ok = false;
  r.terminal_error = 0.5;
  EXPECT_HAS(Judge(s, r).findings.at(0), "terminal constraint violated (scaled error 0.5)");
  r.terminal_ok = true;
  r.operational_ok = false;
  r.rule_violations.push_back(
      {"min_burn", 1, 600, "+T burn at 600 s lasts 100 s < min_burn 300 s"});
  v = Judge(s, r);
  EXPECT_FALSE(v.passed);
  EXPECT_HAS(v.findings.at(0), "rule min_burn at t = 600 s: +T burn");

  transcription::ImpulsiveCheck ic;
  ic.terminal_error = 2e-6;
  EXPECT_FALSE(JudgeImpulsive(s, ic).passed);
  ic.terminal_error = 1e-7;
  EXPECT_TRUE(JudgeImpulsive(s, ic).passed);
}

TEST(Outputs, StatusNamesAndDriftTerm) {
  EXPECT_EQ(StatusName(milp::SolveStatus::kOptimal), "optimal");
  EXPECT_EQ(StatusName(milp::SolveStatus::kFeasible), "feasible");
  EXPECT_EQ(StatusName(milp::SolveStatus::kInfeasible), "infeasible");
  EXPECT_EQ(StatusName(milp::SolveStatus::kUnbounded), "unbounded");
  EXPECT_EQ(StatusName(milp::SolveStatus::kNoSolutionFound), "no_solution");
  EXPECT_EQ(StatusName(milp::SolveStatus::kError), "error");
  const Scenario s = Hcw();
  // Thesis Table 4.1: X0 = [1 km, 0, ...] has drift term 2x + vy/n = 2 km.
  EXPECT_DOUBLE_EQ(HcwDriftTerm(s, (Eigen::VectorXd(6) << 1000, 0, 0, 0, 0, 0).finished()), 2000);
  EXPECT_NEAR(HcwDriftTerm(s, (Eigen::VectorXd(6) << 0, 0, 0, 0, 7.2921159e-2, 0).finished()), 1000,
              1e-9);
  EXPECT_EQ(
      TrajectoryColumns(s, false),
      (std::vector<std::string>{"t_s", "x_m", "y_m", "z_m", "vx_m_s", "vy_m_s", "vz_m_s", "drift_m",
                                "on_+R", "on_+T", "on_+N", "on_-R", "on_-T", "on_-N"}));
}

TEST(Outputs, TrajectoryCsvFollowsTheCheckerSamples) {
  const Scenario s = Hcw();
  const std::vector<transcription::Burn> burns = {{1, 300, 600}};
  const transcription::CheckReport r = transcription::CheckSchedule(s.problem, burns, s.check);
  const std::string dir = TempDir("traj");
  WriteTrajectoryCsv(dir + "/t.csv", s, r, burns);
  const std::string text = ReadFile(dir + "/t.csv");
  // 12 intervals x (4 inner samples + node) + final node, plus the header.
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 12 * 5 + 1 + 1);
  // The row at t = 360 s has +T on, the row at 600 s has it off again.
  EXPECT_NE(text.find("\n360,"), std::string::npos);
  const size_t row360 = text.find("\n360,");
  const std::string line360 = text.substr(row360 + 1, text.find('\n', row360 + 1) - row360 - 1);
  EXPECT_EQ(line360.substr(line360.size() - 12), ",0,1,0,0,0,0");
  const size_t row600 = text.find("\n600,");
  const std::string line600 = text.substr(row600 + 1, text.find('\n', row600 + 1) - row600 - 1);
  EXPECT_EQ(line600.substr(line600.size() - 12), ",0,0,0,0,0,0");
  std::filesystem::remove_all(dir);
}

// A GEO report replayed through the nonlinear model by a caller whose
// scenario has its simulator switched off: the trajectory has the linear
// columns only (it used to dereference the missing simulator and crash).
TEST(Outputs, TrajectoryCsvOfANonlinearReportWithoutTheScenarioSimulator) {
  Scenario s = LoadScenario(std::string(THRUSTSCHED_DATA_DIR) + "/scenarios/geo_2day_anzel4.json");
  ASSERT_TRUE(s.check.nonlinear != nullptr);
  const transcription::CheckReport r = transcription::CheckSchedule(s.problem, {}, s.check);
  ASSERT_TRUE(r.nonlinear_checked);
  s.check.nonlinear.reset();
  const std::string text = TrajectoryCsvText(s, r, {});
  const std::string header = text.substr(0, text.find('\n'));
  EXPECT_NE(header.find("lin_lat_deg"), std::string::npos) << header;
  EXPECT_EQ(header.find(",lat_deg"), std::string::npos) << header;
  EXPECT_EQ(static_cast<size_t>(std::count(text.begin(), text.end(), '\n')),
            r.sample_times.size() + 1);
}

TEST(Plots, ScriptsAlwaysWrittenGnuplotOptional) {
  const Scenario s = Hcw();
  const std::string dir = TempDir("plots");
  const std::vector<transcription::Burn> burns = {{1, 300, 600}};
  const transcription::CheckReport r = transcription::CheckSchedule(s.problem, burns, s.check);
  WriteTrajectoryCsv(dir + "/trajectory.csv", s, r, burns);
  WriteScheduleCsv(dir + "/schedule.csv", s, burns);
  PlotOptions missing;
  missing.gnuplot = "gnuplot-that-does-not-exist";
  PlotResult p = WritePlots(dir, s, false, missing);
  EXPECT_FALSE(p.gnuplot_found);
  EXPECT_FALSE(p.ok);
  EXPECT_HAS(p.message, "plots skipped");
  EXPECT_EQ(p.scripts,
            (std::vector<std::string>{"window.gp", "timeline.gp", "outputs.gp", "xy.gp"}));
  for (const auto& f : p.scripts) EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
  EXPECT_HAS(ReadFile(dir + "/window.gp"), "set terminal svg");
  EXPECT_HAS(ReadFile(dir + "/timeline.gp"), "names = \"+R +T +N -R -T -N\"");
  if (!GnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed";
  p = WritePlots(dir, s, false);
  EXPECT_TRUE(p.ok) << p.message << ReadFile(dir + "/gnuplot.log");
  for (const char* f : {"window.svg", "timeline.svg", "outputs.svg"}) {
    const std::string svg = ReadFile(dir + "/" + f);
    EXPECT_HAS(svg, "<svg");
    EXPECT_HAS(svg, "</svg>");
  }
  std::filesystem::remove_all(dir);
}

TEST(Outputs, WritersThrowOnUnwritablePaths) {
  const Scenario s = Hcw();
  EXPECT_THROW(WriteTextFile("/nonexistent/dir/x.txt", "x"), std::runtime_error);
  EXPECT_THROW(WriteJsonFile("/nonexistent/dir/x.json", nlohmann::json::object()),
               std::runtime_error);
  EXPECT_THROW(WriteScheduleCsv("/nonexistent/dir/s.csv", s, {}), std::runtime_error);
  PlotOptions o;
  o.run_gnuplot = false;
  EXPECT_THROW(WritePlots("/nonexistent/dir", s, false, o), std::runtime_error);
}

}  // namespace
}  // namespace thrustsched::app
