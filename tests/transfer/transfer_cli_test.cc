// `thrustsched transfer` end to end through the binary: the shipped 60 N
// scenario (Caillau, Gergaud & Noailles 2003: 14.8004 h), MAP434's Hohmann
// optimum, and bad input (exit 2, the field and the value named).
#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "app/ccsds_oem.h"
#include "app/plots.h"
#include "app/transfer_scenario.h"
#include "tests/app/cli_runner.h"

namespace thrustsched::testing {
namespace {

const std::string kScenarios = std::string(THRUSTSCHED_DATA_DIR) + "/scenarios/transfer/";

TEST(TransferCli, Caillau60NewtonScenarioWritesTheSummaryAndTrajectory) {
  const std::string out = TempDir("transfer_60n");
  const RunResult r = RunCli(
      {"transfer", kScenarios + "gto_geo_caillau_60n.json", "--out", out, "--quiet", "--force"});
  ASSERT_TRUE(r.exited) << r.Describe();
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const nlohmann::json s = ReadJson(out + "/summary.json");
  EXPECT_EQ(s["status"], "converged");
  EXPECT_EQ(s["method"], "minimum_time");
  EXPECT_NEAR(s["duration_h"].get<double>(), 14.8004, 14.8004e-3);
  EXPECT_NEAR(s["propellant_kg"].get<double>(),
              60.0 * s["duration_s"].get<double>() / (9.80665 * 1994.75), 1e-6);
  EXPECT_LT(std::abs(s["errors"]["a_m"].get<double>()), 1.0);
  EXPECT_LT(std::abs(s["errors"]["e"].get<double>()), 1e-8);
  EXPECT_LT(std::abs(s["errors"]["i_deg"].get<double>()), 1e-6);
  EXPECT_LT(s["convergence"]["shooting_residual"].get<double>(), 1e-8);
  EXPECT_GT(s["convergence"]["iterations"].get<int>(), 0);
  EXPECT_EQ(s["convergence"]["continuation_steps"].get<int>(), 0);
  EXPECT_LT(s["convergence"]["hamiltonian_drift"].get<double>(), 1e-9);
  EXPECT_LT(std::abs(s["replay"]["a_difference_m"].get<double>()), 200.0);
  EXPECT_NEAR(s["revolutions"].get<double>(), 1.05, 0.05);
  EXPECT_EQ(s["interrupted"], false);
  EXPECT_EQ(s["force_model"], "two_body");
  // The second-order necessary conditions (transfer/second_order.h).
  EXPECT_EQ(s["second_order"]["conjugate_point_test"], "no_conjugate_point");
  EXPECT_EQ(s["second_order"]["legendre_holds"], true);
  EXPECT_GT(s["second_order"]["min_abs_determinant_second_half"].get<double>(), 0.05);
  const CsvRows rows = ReadCsv(out + "/trajectory.csv");
  EXPECT_EQ(rows.header, "t_s,p_m,ex,ey,hx,hy,l_rad,a_m,e,i_deg,mass_kg,u_q,u_s,u_w");
  ASSERT_GT(rows.rows.size(), 100u);
  EXPECT_EQ(rows.rows.front().size(), 14u);
}

// --method feedback on the same scenario: Bombrun's feedback stops where
// |F^T grad V| <= delta (16.4 h, far from GEO at 60 N), the minimum-time end
// joins GEO; the whole cannot beat the minimum time.
TEST(TransferCli, FeedbackMethodWithItsOptimalEnd) {
  const std::string out = TempDir("transfer_fb60");
  const RunResult r = RunCli({"transfer", kScenarios + "gto_geo_caillau_60n.json", "--method",
                              "feedback", "--out", out, "--quiet", "--force"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const nlohmann::json s = ReadJson(out + "/summary.json");
  EXPECT_EQ(s["method"], "feedback");
  EXPECT_EQ(s["feedback"]["stop_reason"], "saturation");
  EXPECT_LE(s["feedback"]["max_lyapunov_increase"].get<double>(), 1e-12);
  EXPECT_TRUE(s["optimal_end"]["converged"].get<bool>());
  EXPECT_GT(s["duration_h"].get<double>(), 14.800364);
  EXPECT_LT(std::abs(s["errors"]["a_m"].get<double>()), 1.0);
  EXPECT_NEAR(
      s["duration_s"].get<double>(),
      s["feedback"]["duration_s"].get<double>() + s["optimal_end"]["duration_s"].get<double>(),
      1e-6);
}

// The run folder of a transfer: the plots (gnuplot scripts always, SVGs when
// gnuplot runs), report.html, orbit.csv and the OEM asked for inside the
// folder, all named in the manifest; --no-plots and --no-report leave them out.
TEST(TransferCli, PlotsReportAndOemAreWrittenAndNamedInTheManifest) {
  const std::string dir = TempDir("transfer_files");
  nlohmann::json j = nlohmann::json::parse(ReadFile(kScenarios + "gto_geo_caillau_60n.json"));
  j["transfer"]["epoch"] = "2034-01-01T00:00:00Z";
  WriteFile(dir + "/60n.json", j.dump(2));
  const std::string out = dir + "/out";
  RunResult r = RunCli(
      {"transfer", dir + "/60n.json", "--out", out, "--quiet", "--oem", out + "/transfer.oem"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const nlohmann::json manifest = ReadJson(out + "/.thrustsched-run.json");
  std::set<std::string> files(manifest["files"].begin(), manifest["files"].end());
  for (const char* f : {"summary.json", "trajectory.csv", "orbit.csv", "elements.gp", "orbit.gp",
                        "report.html", "transfer.oem"}) {
    EXPECT_EQ(files.count(f), 1u) << f << " not in " << manifest.dump();
  }
  const std::string report = ReadFile(out + "/report.html");
  EXPECT_NE(report.find("Hand-over to station keeping"), std::string::npos);
  EXPECT_NE(report.find("14.80036"), std::string::npos);  // the duration, h
  if (app::GnuplotAvailable()) {
    EXPECT_EQ(files.count("elements.svg"), 1u);
    EXPECT_EQ(files.count("orbit.svg"), 1u);
    EXPECT_NE(report.find("<svg"), std::string::npos);
  }
  const CsvRows orbit = ReadCsv(out + "/orbit.csv");
  EXPECT_EQ(orbit.header, "t_s,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,mass_kg");
  EXPECT_GT(orbit.rows.size(), 50u);
  const app::OemFile oem = app::ParseOem(ReadFile(out + "/transfer.oem"), "transfer.oem");
  ASSERT_EQ(oem.segments.size(), 1u);
  EXPECT_EQ(oem.segments[0].frame, dynamics::InertialFrame::kEme2000);
  EXPECT_EQ(oem.segments[0].start_time.ToIso8601(), "2034-01-01T00:00:00Z");
  EXPECT_EQ(oem.segments[0].points.size(), orbit.rows.size());

  r = RunCli({"transfer", dir + "/60n.json", "--out", out, "--quiet", "--force", "--no-plots",
              "--no-report"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_TRUE(std::filesystem::exists(out + "/elements.gp"));
  EXPECT_FALSE(std::filesystem::exists(out + "/elements.svg"));
  EXPECT_FALSE(std::filesystem::exists(out + "/report.html"));
  EXPECT_FALSE(std::filesystem::exists(out + "/transfer.oem"));  // the earlier run's, removed

  // An OEM needs the epoch.
  r = RunCli({"transfer", kScenarios + "gto_geo_caillau_60n.json", "--out", dir + "/o2", "--quiet",
              "--oem", dir + "/x.oem"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_NE(r.err.find("scenario.transfer.epoch"), std::string::npos) << r.err;
  // Nor is a folder that does not exist (refused before the transfer runs).
  r = RunCli({"transfer", dir + "/60n.json", "--out", dir + "/o3", "--quiet", "--oem",
              dir + "/missing/x.oem"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_NE(r.err.find("--oem"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/o3/summary.json"));
}

TEST(TransferCli, Map434TwoImpulseIsHohmann) {
  const std::string out = TempDir("transfer_map434");
  const RunResult r =
      RunCli({"transfer", kScenarios + "map434_hohmann.json", "--out", out, "--force"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const nlohmann::json s = ReadJson(out + "/summary.json");
  EXPECT_NEAR(s["two_impulse"]["total_dv_m_s"].get<double>(), 3907.1, 0.05);
  EXPECT_NEAR(s["duration_h"].get<double>(), 5.2692, 5e-5);
  const double unit = 42165e3 / 3600.0;
  EXPECT_NEAR(s["two_impulse"]["cost_m2_s2"].get<double>() / (unit * unit), 0.0295189, 5e-7);
  // No replay: the orbit is Kepler's coast, and still drawn.
  EXPECT_EQ(s["orbit_source"], "coast");
  if (app::GnuplotAvailable()) {
    EXPECT_GT(std::filesystem::file_size(out + "/orbit.svg"), 1000u)
        << ReadFile(out + "/gnuplot.log");
    EXPECT_GT(std::filesystem::file_size(out + "/elements.svg"), 1000u);
  }
}

TEST(TransferCli, BadInputExitsTwoNamingTheFieldAndValue) {
  const std::string dir = TempDir("transfer_bad");
  const std::string good = ReadFile(kScenarios + "gto_geo_caillau_60n.json");
  struct Case {
    std::string from, to, field, value;
  };
  const Case cases[] = {
      {"\"thrust_n\": 60", "\"thrust_n\": -60", "scenario.transfer.thrust_n", "-60"},
      {"\"ex\": 0.75", "\"ex\": 1.25", "scenario.transfer.initial.equinoctial.ex", "1.25"},
      {"\"target\": {\"p_m\": 42165e3", "\"target\": {\"p_m\": 2e9", "scenario.transfer.target.p_m",
       "2000000000"},
      {"\"method\": \"minimum_time\"", "\"method\": \"fastest\"", "scenario.transfer.method",
       "fastest"},
      {"\"isp_s\": 1994.75", "\"isp_sec\": 1994.75", "scenario.transfer.isp_sec", "isp_s"},
      // The station-keeping orbit forms (app/initial_orbit.h) are accepted, with their checks.
      {"{\"equinoctial\": {\"p_m\": 11625e3, \"ex\": 0.75, \"ey\": 0, \"hx\": 6.12e-2, \"hy\": 0, "
       "\"l_deg\": 180}}",
       "{\"eci_state\": {\"frame\": \"ITRF\", \"position_km\": [6645, 0, 0], "
       "\"velocity_km_s\": [0, 10.2, 0.5]}}",
       "scenario.transfer.initial.eci_state.frame", "ITRF"},
  };
  for (const Case& c : cases) {
    std::string text = good;
    const std::size_t at = text.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    text.replace(at, c.from.size(), c.to);
    const std::string path = dir + "/bad.json";
    WriteFile(path, text);
    const RunResult r = RunCli({"transfer", path, "--out", dir + "/out", "--quiet"});
    ASSERT_TRUE(r.exited) << r.Describe();
    EXPECT_EQ(r.exit_code, 2) << c.to << "\n" << r.Describe();
    EXPECT_NE(r.err.find(c.field), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.value), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out/summary.json"));
  }
  // A hyperbolic Keplerian start and a perigee inside the Earth (Bombrun
  // 2007's printed a0 = 2.458e7 m with e0 = 0.75 for case 2: 6145 km).
  const nlohmann::json base =
      nlohmann::json::parse(ReadFile(kScenarios + "gto_geo_bombrun_case1.json"));
  for (const auto& [e, a, what] :
       {std::tuple<double, double, std::string>{1.3, 24505.9e3, "hyperbolic"},
        {0.75, 2.458e7, "below the Earth"}}) {
    nlohmann::json j = base;
    j["transfer"]["initial"]["keplerian"]["e"] = e;
    j["transfer"]["initial"]["keplerian"]["a_m"] = a;
    try {
      app::ParseTransferScenario(j, "x.json");
      ADD_FAILURE() << what;
    } catch (const app::ScenarioError& err) {
      EXPECT_NE(std::string(err.what()).find("scenario.transfer.initial"), std::string::npos)
          << err.what();
      EXPECT_NE(std::string(err.what()).find(what), std::string::npos) << err.what();
    }
  }
  const RunResult r = RunCli(
      {"transfer", kScenarios + "map434_hohmann.json", "--method", "warp", "--out", dir + "/out2"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_NE(r.err.find("--method"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace thrustsched::testing
