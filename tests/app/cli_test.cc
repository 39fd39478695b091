// End-to-end tests of the `thrustsched` binary on small scenarios: help and
// version, solve (summary.json consistent with schedule.csv, published optima),
// export, the check round trip, every exit code, SIGINT, impulsive and GEO
// outputs.
#include <signal.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "app/cli.h"
#include "app/interrupt.h"
#include "tests/app/cli_runner.h"
#include "tests/app/test_messages.h"

namespace thrustsched::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kScenarios = THRUSTSCHED_DATA_DIR "/scenarios/";
const std::string kTestData = THRUSTSCHED_APP_TEST_DATA "/";

TEST(Cli, HelpAndVersion) {
  RunResult r = RunCli({"--help"});
  EXPECT_EQ(r.exit_code, 0) << r.Describe();
  for (const char* cmd : {"solve", "export", "check", "import-solution", "validate"}) {
    EXPECT_HAS(r.out, cmd);
  }
  for (const char* cmd : {"solve", "export", "check", "import-solution", "validate"}) {
    r = RunCli({cmd, "--help"});
    EXPECT_EQ(r.exit_code, 0) << cmd << r.Describe();
    EXPECT_HAS(r.out, "scenario");
  }
  r = RunCli({"solve", "--help"});
  for (const char* opt :
       {"--out", "--time-limit", "--gap", "--threads", "--scheme", "--formulation", "--encoding",
        "--export-mps", "--export-lp", "--quiet"}) {
    EXPECT_HAS(r.out, opt);
  }
  r = RunCli({"--version"});
  EXPECT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(r.out, "thrustsched 0.");
  EXPECT_HAS(r.out, "CBC");
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(RunCli({}).exit_code, 2);
  EXPECT_EQ(RunCli({"frobnicate"}).exit_code, 2);
  EXPECT_EQ(RunCli({"solve"}).exit_code, 2);  // missing scenario
  EXPECT_EQ(RunCli({"solve", kScenarios + "hcw_table41_1d.json", "--bogus"}).exit_code, 2);
  RunResult r = RunCli({"solve", "/nonexistent.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_HAS(r.err, "/nonexistent.json: cannot open");
  const std::string dir = TempDir("usage");
  r = RunCli({"solve", kScenarios + "hcw_table41_1d.json", "--gap", "-1", "--out", dir});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_HAS(r.err, "--gap: must be finite and >= 0, got -1");
  r = RunCli({"solve", kScenarios + "hcw_table41_1d.json", "--scheme", "magic", "--out", dir});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_HAS(r.err, "--scheme");
  // A bad scenario names the field and the value on stderr.
  json j = json::parse(ReadFile(kScenarios + "hcw_table41_1d.json"));
  j["horizon"]["step_s"] = 700;
  WriteFile(dir + "/bad.json", j.dump());
  r = RunCli({"solve", dir + "/bad.json", "--out", dir + "/o"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_HAS(r.err, "scenario.horizon.step_s: 700 s does not divide the horizon duration 86400 s");
  EXPECT_FALSE(fs::exists(dir + "/o/summary.json"));
  fs::remove_all(dir);
}

// report.html: one self-contained page with the scenario, the result, the
// checker's verdict, the plots inlined and the schedule; --no-report skips it.
TEST(Cli, SolveWritesTheReportUnlessNoReport) {
  const std::string dir = TempDir("report");
  RunResult r = RunCli({"solve", kScenarios + "hcw_table41_1d.json", "--out", dir + "/a",
                        "--threads", "1", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(r.out, "gap 0 %");  // not 1e-14-level noise
  EXPECT_HAS(r.out, "report.html)");
  const std::string html = ReadFile(dir + "/a/report.html");
  for (const char* part : {"<!DOCTYPE html>", "<h1>hcw_table41_1d</h1>",
                           "HCW (Hill-Clohessy-Wiltshire)", "each burn at least 5 min", "optimal",
                           "0.016391753", "PASSED", "<td>-T</td>", "@media print"}) {
    EXPECT_HAS(html, part);
  }
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<?xml"), std::string::npos);
  if (HaveProgram("gnuplot")) {
    size_t plots = 0;
    for (size_t at = html.find("<svg "); at != std::string::npos; at = html.find("<svg ", at + 1))
      ++plots;
    EXPECT_EQ(plots, 4u);                          // window, xy, timeline, outputs
    EXPECT_HAS(html, "id=\"p2_gnuplot_canvas\"");  // ids made unique per plot
  }
  EXPECT_HAS(ReadFile(dir + "/a/.thrustsched-run.json"), "report.html");
  r = RunCli({"solve", kScenarios + "hcw_table41_1d.json", "--out", dir + "/b", "--threads", "1",
              "--quiet", "--no-report", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_FALSE(fs::exists(dir + "/b/report.html"));
  EXPECT_EQ(r.out.find("report.html"), std::string::npos);
  fs::remove_all(dir);
}

// Thesis Table 4.1, 1 day: one 5-min tangential slot, 0.0164 m/s published
// (exactly 0.265/4850*300 = 0.016391753 m/s), drift term 1.7752 km at tf.
TEST(Cli, SolveWritesConsistentResults) {
  const std::string dir = TempDir("solve");
  const RunResult r =
      RunCli({"solve", kScenarios + "hcw_table41_1d.json", "--out", dir, "--time-limit", "120",
              "--export-mps", dir + "/model.mps", "--export-lp", dir + "/model.lp"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(r.out, "status        optimal");
  EXPECT_HAS(r.out, "check         PASSED");
  const json s = ReadJson(dir + "/summary.json");
  for (const char* key : {"status",
                          "objective",
                          "best_bound",
                          "gap",
                          "consumption_l1_m_s",
                          "delta_v_m_s",
                          "propellant_kg",
                          "n_burns",
                          "burns",
                          "n_binaries",
                          "n_columns",
                          "n_rows",
                          "n_nonzeros",
                          "build_seconds",
                          "solve_seconds",
                          "check",
                          "name",
                          "scheme",
                          "formulation",
                          "encoding",
                          "solver_version",
                          "time_to_first_s",
                          "effective_rules",
                          "discretise_seconds",
                          "check_seconds",
                          "infeasibility_reasons"}) {
    EXPECT_TRUE(s.contains(key)) << key;
  }
  for (const char* key : {"operational_ok", "max_window_violation", "max_window_violation_nodes",
                          "worst_time_s", "rule_violations", "passed"}) {
    EXPECT_TRUE(s["check"].contains(key)) << key;
  }
  EXPECT_EQ(s["status"], "optimal");
  const double slot = 0.265 / 4850 * 300;
  EXPECT_NEAR(s["consumption_l1_m_s"].get<double>(), slot, 1e-9);
  EXPECT_NEAR(s["consumption_l1_m_s"].get<double>(), 0.0164, 5e-5);  // published, 3 digits
  EXPECT_NEAR(s["objective"].get<double>(), s["consumption_l1_m_s"].get<double>(), 1e-9);
  EXPECT_NEAR(s["delta_v_m_s"].get<double>(), slot, 1e-9);  // ideal thrusters: L1 = Euclidean
  EXPECT_NEAR(s["propellant_kg"].get<double>(), 0.265 / (9.80665 * 2005) * 300, 1e-9);
  EXPECT_NEAR(s["final_drift_term_m"].get<double>(), 1775.2, 0.05);  // 2 km - 224.8 m per slot
  EXPECT_EQ(s["n_binaries"], 288 * 6);
  EXPECT_EQ(s["effective_rules"]["min_off_same_intervals"][0], 4);  // thesis m = 4
  EXPECT_TRUE(s["check"]["passed"].get<bool>());
  EXPECT_TRUE(s["check"]["operational_ok"].get<bool>());
  EXPECT_EQ(s["check"]["max_window_violation_nodes"].get<double>(), 0.0);
  // schedule.csv holds the same burns as the summary, and their on-time gives the consumption.
  const CsvRows csv = ReadCsv(dir + "/schedule.csv");
  EXPECT_EQ(csv.header, "thruster,start_s,end_s,duration_s");
  ASSERT_EQ(csv.rows.size(), s["n_burns"].get<size_t>());
  ASSERT_EQ(s["burns"].size(), csv.rows.size());
  double on_time = 0;
  for (size_t i = 0; i < csv.rows.size(); ++i) {
    EXPECT_EQ(csv.rows[i][0], s["burns"][i]["thruster"]);
    EXPECT_DOUBLE_EQ(std::stod(csv.rows[i][1]), s["burns"][i]["start_s"].get<double>());
    EXPECT_DOUBLE_EQ(std::stod(csv.rows[i][3]), s["burns"][i]["duration_s"].get<double>());
    on_time += std::stod(csv.rows[i][3]);
  }
  EXPECT_NEAR(on_time * 0.265 / 4850, s["consumption_l1_m_s"].get<double>(), 1e-12);
  // trajectory.csv: nodes + 4 inner samples per interval.
  const CsvRows traj = ReadCsv(dir + "/trajectory.csv");
  EXPECT_EQ(traj.rows.size(), 288u * 5 + 1);
  EXPECT_HAS(traj.header, "t_s,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,drift_m");
  // Model files.
  EXPECT_HAS(ReadFile(dir + "/model.mps"), "on_0_0");
  EXPECT_HAS(ReadFile(dir + "/model.lp"), "on_0_0");
  if (HaveProgram("gnuplot")) {
    for (const char* f : {"window.svg", "timeline.svg", "outputs.svg"}) {
      EXPECT_HAS(ReadFile(dir + "/" + f), "<svg");
    }
  }
  for (const char* f : {"window.gp", "timeline.gp", "outputs.gp"})
    EXPECT_TRUE(fs::exists(dir + "/" + f));

  // check round trip: our own schedule passes ...
  RunResult c = RunCli({"check", kScenarios + "hcw_table41_1d.json", dir + "/schedule.csv"});
  EXPECT_EQ(c.exit_code, 0) << c.Describe();
  EXPECT_HAS(c.out, "PASSED");
  // ... a hand-broken one (burn shortened below the 5-min minimum) fails with 5 ...
  const auto& b = csv.rows.at(0);
  const double start = std::stod(b[1]);
  std::ostringstream broken;
  broken << "thruster,start_s,end_s,duration_s\n"
         << b[0] << "," << start << "," << start + 120 << ",120\n";
  WriteFile(dir + "/broken.csv", broken.str());
  c = RunCli(
      {"check", kScenarios + "hcw_table41_1d.json", dir + "/broken.csv", "--out", dir + "/chk"});
  EXPECT_EQ(c.exit_code, 5) << c.Describe();
  EXPECT_HAS(c.out, "min_burn");
  const json cj = ReadJson(dir + "/chk/check.json");
  EXPECT_FALSE(cj["passed"].get<bool>());
  EXPECT_FALSE(cj["operational_ok"].get<bool>());
  // ... an empty schedule is judged on the window alone: the exit code agrees with check.json ...
  WriteFile(dir + "/empty.csv", "thruster,start_s,end_s,duration_s\n");
  c = RunCli(
      {"check", kScenarios + "hcw_table41_1d.json", dir + "/empty.csv", "--out", dir + "/chk0"});
  const json ej = ReadJson(dir + "/chk0/check.json");
  EXPECT_EQ(c.exit_code, ej["passed"].get<bool>() ? 0 : 5);
  // ... and an unreadable one is bad input.
  WriteFile(dir + "/garbage.csv", "thruster,start_s,end_s\n-T,abc,300\n");
  c = RunCli({"check", kScenarios + "hcw_table41_1d.json", dir + "/garbage.csv"});
  EXPECT_EQ(c.exit_code, 2) << c.Describe();
  EXPECT_HAS(c.err, "start_s must be a finite number");
  fs::remove_all(dir);
}

TEST(Cli, ExportWritesModelFiles) {
  const std::string dir = TempDir("export");
  RunResult r =
      RunCli({"export", kScenarios + "serra_double_integrator_onoff.json", dir + "/m.mps"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const std::string mps = ReadFile(dir + "/m.mps");
  EXPECT_HAS(mps, "'MARKER'");
  EXPECT_HAS(mps, "on_1_99");  // thruster -X, last of 100 intervals
  EXPECT_HAS(mps, "ENDATA");
  r = RunCli({"export", kScenarios + "serra_double_integrator_onoff.json", dir + "/m.lp"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(ReadFile(dir + "/m.lp"), "on_0_0");
  r = RunCli({"export", kScenarios + "serra_double_integrator_onoff.json", dir + "/m.txt"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_HAS(r.err, "must end in .mps or .lp");
  r = RunCli(
      {"export", kScenarios + "serra_double_integrator_onoff.json", "/nonexistent/dir/m.mps"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  // The solve flags name their format: a mismatched extension is bad input,
  // caught before any work.
  r = RunCli({"solve", kScenarios + "serra_double_integrator_onoff.json", "--out", dir + "/s",
              "--export-lp", dir + "/wrong.mps"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_HAS(r.err, "--export-lp");
  EXPECT_FALSE(fs::exists(dir + "/wrong.mps"));
  EXPECT_FALSE(fs::exists(dir + "/s/summary.json"));
  r = RunCli({"solve", kScenarios + "serra_double_integrator_onoff.json", "--out", dir + "/s",
              "--export-mps", dir + "/m.lp"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_HAS(r.err, "--export-mps");
  fs::remove_all(dir);
}

// A misspelt command or field is named as such (not reported as missing),
// `help` and -V work, a folder given as the scenario says so, and the MPS
// NAME is the scenario's name.
TEST(Cli, MisspellingsAndSmallThingsAreClear) {
  RunResult r = RunCli({"solv", kScenarios + "hcw_table41_1d.json"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_HAS(r.err, "unknown subcommand 'solv'; did you mean 'solve'?");
  r = RunCli({"help"});
  EXPECT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(r.out, "simulate");
  r = RunCli({"help", "check"});
  EXPECT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(r.out, "schedule");
  r = RunCli({"-V"});
  EXPECT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(r.out, "thrustsched ");

  const std::string dir = TempDir("typos");
  json sc = ReadJson(kScenarios + "hcw_table41_1d.json");
  sc["spacecraft"]["thrust_N"] = sc["spacecraft"]["thrust_n"];
  sc["spacecraft"].erase("thrust_n");
  WriteFile(dir + "/typo.json", sc.dump());
  r = RunCli({"validate", dir + "/typo.json"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_HAS(r.err, "unknown field 'thrust_N'; did you mean 'thrust_n'?");
  EXPECT_EQ(r.err.find("missing"), std::string::npos) << r.err;

  r = RunCli({"solve", kScenarios, "--out", dir + "/o"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_HAS(r.err, "is a folder, not a scenario file");

  r = RunCli({"export", kScenarios + "hcw_table41_1d.json", dir + "/m.mps"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(ReadFile(dir + "/m.mps"), "NAME          hcw_table41_1d");
  fs::remove_all(dir);
}

TEST(Cli, InfeasibleExitsThree) {
  const std::string dir = TempDir("infeasible");
  const RunResult r = RunCli({"solve", kTestData + "hcw_10km_infeasible_1d.json", "--out", dir});
  EXPECT_EQ(r.exit_code, 3) << r.Describe();
  const json s = ReadJson(dir + "/summary.json");
  EXPECT_EQ(s["status"], "infeasible");
  EXPECT_TRUE(s["check"].is_null());
  EXPECT_TRUE(s["objective"].is_null());
  EXPECT_FALSE(fs::exists(dir + "/schedule.csv"));
  fs::remove_all(dir);
}

TEST(Cli, NoSolutionWithinTheTimeLimitExitsFour) {
  const std::string dir = TempDir("timelimit");
  const RunResult r =
      RunCli({"solve", kTestData + "geo_2day_5min.json", "--out", dir, "--time-limit", "0.01"});
  EXPECT_EQ(r.exit_code, 4) << r.Describe();
  const json s = ReadJson(dir + "/summary.json");
  EXPECT_EQ(s["status"], "no_solution");
  EXPECT_EQ(s["n_burns"], 0);
  fs::remove_all(dir);
}

// Ctrl-C stops the solve like a time limit; the best schedule is checked and written.
// The SIGINT is sent by the CLI to itself at its first incumbent (injected
// progress hook, app/run_hooks.h; the CLI runs in a child process), so it
// always lands mid-search whatever the machine's speed, and goes through the
// same watcher as a real Ctrl-C. Without it the solve proves optimality (gap
// 0). CBC alone (--no-search): the search proves this case optimal at its
// first incumbent.
TEST(Cli, SigintKeepsTheBestSchedule) {
  const std::string dir = TempDir("sigint");
  thrustsched::app::RunHooks hooks;
  hooks.on_progress = thrustsched::app::InterruptSelfAtFirstIncumbent;
  const RunResult r = thrustsched::testing::RunInChild(
      [&] {
        return thrustsched::app::RunCli(
            {"thrustsched", "solve", kTestData + "geo_2day_5min.json", "--out", dir, "--gap", "0",
             "--time-limit", "250", "--no-search"},
            hooks);
      },
      280.0);
  ASSERT_TRUE(r.exited) << r.Describe();
  EXPECT_EQ(r.exit_code, 0) << r.Describe();
  const json s = ReadJson(dir + "/summary.json");
  EXPECT_TRUE(s["interrupted"].get<bool>()) << r.Describe();
  EXPECT_HAS(r.err, "interrupt");
  EXPECT_HAS(r.out, "(interrupted)");
  // Stopped before the proof: the incumbent is kept with its open gap.
  EXPECT_EQ(s["status"], "feasible") << r.Describe();
  EXPECT_GT(s["gap"].get<double>(), 0.0);
  EXPECT_GT(s["n_burns"].get<int>(), 0);
  EXPECT_TRUE(fs::exists(dir + "/schedule.csv"));
  ASSERT_TRUE(s["check"].is_object());
  EXPECT_TRUE(s["check"]["operational_ok"].get<bool>());
  fs::remove_all(dir);
}

// Published optima of the Serra rendezvous cases (data/reference/serra_rendezvous.json),
// solved through the CLI; the impulsive ones also go through `check` and a broken copy fails.
struct SerraCase {
  const char* file;
  double optimum;
  double tolerance;
};

TEST(Cli, SerraCasesReachThePublishedOptima) {
  const std::vector<SerraCase> cases = {
      {"serra_double_integrator_impulsive", 2.0, 1e-9},  // exact on any grid with both ends
      {"serra_double_integrator_onoff", 2.4, 1e-9},      // grid optimum, derived closed form
      {"serra_leo_circular", 3.6143, 1e-4},              // end impulses: exact on any grid
      {"serra_geo_circular", 1.0707, 1e-4},
      {"serra_gto_nuf52", 6.2728, 1e-4},
      {"serra_gto_nuf3", 8.7572, 1e-4},
  };
  for (const SerraCase& c : cases) {
    SCOPED_TRACE(c.file);
    const std::string dir = TempDir("serra");
    const std::string scenario = kScenarios + c.file + ".json";
    const RunResult r = RunCli({"solve", scenario, "--out", dir, "--no-plots"});
    ASSERT_EQ(r.exit_code, 0) << r.Describe();
    const json s = ReadJson(dir + "/summary.json");
    EXPECT_EQ(s["status"], "optimal");
    EXPECT_NEAR(s["objective"].get<double>(), c.optimum, c.tolerance * c.optimum);
    EXPECT_TRUE(s["check"]["passed"].get<bool>()) << s["check"].dump();
    if (s["input_mode"] == "impulsive") {
      const CsvRows imp = ReadCsv(dir + "/impulses.csv");
      EXPECT_EQ(imp.header, "thruster,node,time_s,delta_v_m_s");
      EXPECT_EQ(imp.rows.size(), s["n_impulses"].get<size_t>());
      double total = 0;
      std::ostringstream scaled;
      scaled << imp.header << "\n";
      for (const auto& row : imp.rows) {
        total += std::stod(row[3]);
        scaled << row[0] << "," << row[1] << "," << row[2] << "," << 0.9 * std::stod(row[3])
               << "\n";
      }
      EXPECT_NEAR(total, s["objective"].get<double>(), 1e-9);
      RunResult ck = RunCli({"check", scenario, dir + "/impulses.csv"});
      EXPECT_EQ(ck.exit_code, 0) << ck.Describe();
      WriteFile(dir + "/scaled.csv", scaled.str());
      ck = RunCli({"check", scenario, dir + "/scaled.csv"});
      EXPECT_EQ(ck.exit_code, 5) << ck.Describe();  // misses the terminal state
      EXPECT_HAS(ck.out, "terminal constraint violated");
    }
    fs::remove_all(dir);
  }
}

// GEO: the nonlinear replay is reported, and trajectory.csv carries the inertial state.
TEST(Cli, GeoSolveReportsTheNonlinearReplay) {
  const std::string dir = TempDir("geo");
  const RunResult r = RunCli({"solve", kTestData + "geo_day_small.json", "--out", dir});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const json s = ReadJson(dir + "/summary.json");
  ASSERT_TRUE(s["check"].is_object());
  EXPECT_TRUE(s["check"]["nonlinear_checked"].get<bool>());
  EXPECT_TRUE(s["check"]["max_window_violation_nonlinear_deg"].is_number());
  EXPECT_EQ(s["check"]["window_unit"], "deg");
  EXPECT_GT(s["n_burns"].get<int>(), 0);  // the end-of-day set needs thrust
  // Anzel L1 factor: consumption / delta-v = 1.44296 (thesis (1.73) with theta, alpha nominal).
  EXPECT_NEAR(s["consumption_l1_m_s"].get<double>() / s["delta_v_m_s"].get<double>(), 1.44296,
              1e-5);
  const CsvRows traj = ReadCsv(dir + "/trajectory.csv");
  EXPECT_HAS(traj.header,
             "t_s,utc,da_m,ex,ey,ix,iy,dl_rad,dr_m,lat_rad,lon_rad,lin_lat_deg,"
             "lin_dlon_deg,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,r_m,lat_deg,lon_deg,"
             "dlon_deg,dr_nl_m,on_NE,on_SE,on_NW,on_SW");
  ASSERT_EQ(traj.rows.size(), 144u * 5 + 1);
  EXPECT_EQ(traj.rows[0][1], "2034-01-01T00:00:00Z");
  // The station point: radius a_mp, longitude 118 E, on the equator.
  const double x = std::stod(traj.rows[0][13]), y = std::stod(traj.rows[0][14]),
               z = std::stod(traj.rows[0][15]);
  EXPECT_NEAR(std::sqrt(x * x + y * y + z * z), 42165765.0, 1.0);
  EXPECT_NEAR(std::stod(traj.rows[0][21]), 118.0, 1e-6);
  EXPECT_NEAR(std::stod(traj.rows[0][20]), 0.0, 1e-6);
  // Our schedule passes `check` (the nonlinear replay is reported there too).
  const RunResult c = RunCli({"check", kTestData + "geo_day_small.json", dir + "/schedule.csv"});
  EXPECT_EQ(c.exit_code, 0) << c.Describe();
  EXPECT_HAS(c.out, "nonlinear");
  fs::remove_all(dir);
}

TEST(Cli, ValidateParsesAndBuilds) {
  RunResult r = RunCli({"validate", kScenarios + "geo_week_anzel4.json", "--no-build"});
  EXPECT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(r.out, "valid");
  r = RunCli({"validate", kScenarios + "hcw_table41_1d.json"});
  EXPECT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_HAS(r.out, "1728 binaries");
}

}  // namespace
}  // namespace thrustsched::testing
