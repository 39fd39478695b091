// `thrustsched simulate` end to end on data/scenarios/year/year_test_4cycles.json
// (4 daily cycles at a 5-min step, ~10 s of CPU), plus the section parser and
// the checkpoint format. The resumed-equals-uninterrupted property is checked
// on the files the command writes (cycles.csv without the timing columns,
// year.json figures, checkpoint state bit for bit).
#include "app/simulate.h"

#include <signal.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/cli.h"
#include "app/interrupt.h"
#include "app/outputs.h"
#include "tests/app/cli_runner.h"
#include "transcription/checker.h"

namespace thrustsched::app {
namespace {

namespace fs = std::filesystem;
using thrustsched::testing::ReadFile;
using thrustsched::testing::ReadJson;
using thrustsched::testing::RunCli;
using thrustsched::testing::TempDir;

const std::string kScenario =
    std::string(THRUSTSCHED_DATA_DIR) + "/scenarios/year/year_test_4cycles.json";

std::vector<std::vector<std::string>> ReadCsvRows(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cur;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') {
        quoted = !quoted;
      } else if (c == ',' && !quoted) {
        cells.push_back(cur);
        cur.clear();
      } else {
        cur += c;
      }
    }
    cells.push_back(cur);
    rows.push_back(cells);
  }
  return rows;
}

int Column(const std::vector<std::string>& header, const std::string& name) {
  for (size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return static_cast<int>(i);
  }
  ADD_FAILURE() << "no column " << name;
  return 0;
}

// A minimal valid scenario text with a given long_horizon section (and extras).
std::string ScenarioText(const std::string& long_horizon, const std::string& extra = "") {
  return R"({
  "name": "t",
  "model": {"type": "geo", "station_longitude_deg": 118, "epoch": "2034-01-01T00:00:00Z"},
  "spacecraft": {"mass_kg": 4850, "isp_s": 2005, "thrust_n": 0.265,
                 "thrusters": {"preset": "anzel4"}},
  "initial_state": {"station_point": true},
  "horizon": {"duration_s": 86400, "step_s": 600},
  "window": {"half_width_deg": 0.05},
  "operations": {"min_burn_s": 300, "min_off_same_s": 1200, "min_gap_other_s": 300},)" +
         extra + R"(
  "long_horizon": )" +
         long_horizon + "\n}";
}

std::string ParseError(const std::string& long_horizon, const std::string& extra = "") {
  try {
    ParseSimulationText(ScenarioText(long_horizon, extra), "x.json");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(SimulateSection, DefaultsAndFields) {
  const SimulationSetup s = ParseSimulationText(
      ScenarioText(R"({"duration_s": 259200, "failures": [{"thrusters": ["NE"], "from_s": 3600,
                       "opposite_also_off": true}]})"),
      "x.json");
  const planning::LongHorizonOptions& o = s.options;
  EXPECT_DOUBLE_EQ(o.duration_s, 259200);
  EXPECT_DOUBLE_EQ(o.cycle_s, 86400);  // the horizon section's duration
  EXPECT_DOUBLE_EQ(o.step_s, 600);
  EXPECT_EQ(o.mode, planning::HorizonMode::kFixed);
  EXPECT_EQ(o.terminal.kind, transcription::TerminalKind::kStationKeepingSets);
  EXPECT_EQ(o.terminal.facets_cone_minus, 16);
  EXPECT_DOUBLE_EQ(o.solve.milp.time_limit_s, 30.0);
  EXPECT_DOUBLE_EQ(o.solve.milp.relative_gap, 0.02);
  EXPECT_EQ(o.solve.milp.lp_algorithm, milp::LpAlgorithm::kBarrier);
  EXPECT_FALSE(o.solve.check.nonlinear);
  EXPECT_EQ(o.num_cycles(), 3);
  // NE failed from 1 h, and its opposite SW with it.
  ASSERT_EQ(o.outages.size(), 2u);
  EXPECT_EQ(o.outages[0].thruster, 0);
  EXPECT_EQ(o.outages[1].thruster, 3);
  EXPECT_DOUBLE_EQ(o.outages[1].from_s, 3600);
  EXPECT_TRUE(std::isinf(o.outages[1].until_s));
  ASSERT_EQ(s.failures.size(), 1u);
  EXPECT_EQ(s.failures[0].switched_off, (std::vector<std::string>{"NE", "SW"}));

  const SimulationSetup r = ParseSimulationText(
      ScenarioText(R"({"duration_s": 259200, "mode": "receding", "control_s": 43200,
                       "cycle_time_limit_s": 5, "cycle_relative_gap": 0.5,
                       "cycle_lp_algorithm": "primal", "timeline_cycle": 2})"),
      "x.json");
  EXPECT_EQ(r.options.mode, planning::HorizonMode::kReceding);
  EXPECT_EQ(r.options.terminal.kind, transcription::TerminalKind::kFree);  // thesis 5.4
  EXPECT_EQ(r.options.num_cycles(), 6);
  EXPECT_DOUBLE_EQ(r.options.solve.milp.time_limit_s, 5);
  EXPECT_EQ(r.options.solve.milp.lp_algorithm, milp::LpAlgorithm::kPrimal);
  EXPECT_EQ(r.timeline_cycle, 1);
  EXPECT_FALSE(s.options.retry_without_preprocessing);  // default: off
  const SimulationSetup retry = ParseSimulationText(
      ScenarioText(R"({"duration_s": 259200, "cycle_retry_without_preprocessing": true})"),
      "x.json");
  EXPECT_TRUE(retry.options.retry_without_preprocessing);
  // Different inputs, different fingerprints (a checkpoint cannot be resumed
  // with another scenario).
  EXPECT_NE(s.fingerprint, r.fingerprint);
}

TEST(SimulateSection, ErrorsNameTheField) {
  EXPECT_NE(ParseError(R"({"cycle_s": 86400})").find("scenario.long_horizon.duration_s"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400, "mode": "sliding"})").find("long_horizon.mode"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400, "mode": "receding"})").find("control_s"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400, "control_s": 600})").find("control_s"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400, "cycle_s": 1000})").find("step_s"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400, "terminal": {"facets": 2}})")
                .find("long_horizon.terminal.facets"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400, "terminal": {"type": "free", "facets": 8}})")
                .find("facets"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400, "failures": [{"thrusters": ["XX"], "from_s": 0}]})")
                .find("long_horizon.failures[0].thrusters[0]"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400, "failures": [{"thrusters": [], "from_s": 0}]})")
                .find("thrusters"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400, "failures": [{"thrusters": ["NE"], "from_s": 10,
                           "until_s": 5}]})")
                .find("until_s"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400, "cycle_limit": 3})").find("unknown field"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400, "cycle_retry_without_preprocessing": 1})")
                .find("long_horizon.cycle_retry_without_preprocessing"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400})", R"(
  "terminal": {"type": "free"},)")
                .find("scenario.terminal"),
            std::string::npos);
  EXPECT_NE(ParseError(R"({"duration_s": 86400})", R"(
  "history": {"NE": {"on_for_s": 600}},)")
                .find("on_for_s"),
            std::string::npos);
  // Not a GEO scenario.
  const std::string hcw = R"({"name": "h", "model": {"type": "hcw", "mean_motion_rad_s": 7.29e-5},
    "spacecraft": {"mass_kg": 1, "isp_s": 1, "thrust_n": 1, "thrusters": {"preset": "ideal6"}},
    "initial_state": {"hcw_position_m": [0, 0, 0]}, "horizon": {"duration_s": 600, "step_s": 60},
    "long_horizon": {"duration_s": 600}})";
  try {
    ParseSimulationText(hcw, "h.json");
    ADD_FAILURE() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("scenario.model.type"), std::string::npos) << e.what();
  }
  // solve/validate still reject the section.
  EXPECT_THROW(ParseScenarioText(ScenarioText(R"({"duration_s": 86400})")), ScenarioError);
}

TEST(SimulateCheckpoint, RecordRoundTripIsExact) {
  planning::CycleRecord r;
  r.index = 4;
  r.start_s = 345600.0;
  r.applied_end_s = 432000.0;
  r.prediction_end_s = 432000.0;
  r.fallback = planning::Fallback::kSoftWindow;
  r.status = milp::SolveStatus::kFeasible;
  r.attempts.push_back({planning::Fallback::kNone, milp::SolveStatus::kInfeasible, 1.5, "x"});
  r.attempts.push_back({planning::Fallback::kSoftWindow, milp::SolveStatus::kFeasible, 2.5, "y"});
  r.objective = 0.1 + 0.2;  // not representable in few digits
  r.gap = std::nan("");
  r.burns = {{1, 600.0, 1200.0}, {3, 3000.0, 3300.0}};
  r.on_time_s = {0, 600, 0, 300};
  r.consumption_l1_m_s = 1.0 / 3.0;
  r.note = "uncontrollable: \"x\", y";
  r.eci_start << 4.2e7 / 3.0, -1.0 / 7.0, 1e-300, 3074.659 / 9.0, 2.0 / 3.0, -0.0;
  r.eci_end = r.eci_start * std::sqrt(2.0);
  r.initial_state = Eigen::VectorXd::LinSpaced(6, 0.1, 0.7);
  r.final_state = r.initial_state / 3.0;
  const nlohmann::json j = nlohmann::json::parse(CycleRecordJson(r).dump());
  const planning::CycleRecord b = CycleRecordFromJson(j, "c");
  EXPECT_EQ(b.index, 4);
  EXPECT_EQ(b.fallback, planning::Fallback::kSoftWindow);
  EXPECT_EQ(b.status, milp::SolveStatus::kFeasible);
  ASSERT_EQ(b.attempts.size(), 2u);
  EXPECT_EQ(b.attempts[0].status, milp::SolveStatus::kInfeasible);
  EXPECT_EQ(b.objective, r.objective);
  EXPECT_TRUE(std::isnan(b.gap));
  EXPECT_EQ(b.consumption_l1_m_s, r.consumption_l1_m_s);
  EXPECT_EQ(b.eci_start, r.eci_start);  // bit for bit
  EXPECT_EQ(b.eci_end, r.eci_end);
  EXPECT_EQ(b.final_state, r.final_state);
  ASSERT_EQ(b.burns.size(), 2u);
  EXPECT_EQ(b.burns[1].thruster, 3);
  EXPECT_EQ(b.note, r.note);
  EXPECT_EQ(CyclesCsvRow(b, "2034-01-01T00:00:00Z"), CyclesCsvRow(r, "2034-01-01T00:00:00Z"));
  // Malformed input names the field.
  nlohmann::json bad = j;
  bad["eci_end"] = {1, 2, 3};
  try {
    CycleRecordFromJson(bad, "checkpoint.cycles[0]");
    ADD_FAILURE() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("checkpoint.cycles[0].eci_end"), std::string::npos);
  }
  bad = j;
  bad["status"] = "great";
  EXPECT_THROW(CycleRecordFromJson(bad, "c"), ScenarioError);
  bad = j;
  bad["burns"] = {{"NE", 1, 2}};
  EXPECT_THROW(CycleRecordFromJson(bad, "c"), ScenarioError);
}

// Cells of cycles.csv that do not depend on timing.
std::vector<std::vector<std::string>> DeterministicCells(const std::string& path) {
  auto rows = ReadCsvRows(path);
  if (rows.empty()) return rows;
  const std::vector<std::string> header = rows[0];
  std::vector<int> timing;
  for (const char* c : {"solve_s", "first_solution_s", "wall_s", "cpu_s"}) {
    timing.push_back(Column(header, c));
  }
  for (auto& row : rows) {
    for (int c : timing) {
      if (c < static_cast<int>(row.size())) row[c] = "*";
    }
  }
  return rows;
}

// The files of a resumed run equal those of the uninterrupted one: cycles.csv
// without its timing columns, the year's figures, the final true state and
// the last burn bit for bit, the trajectory and every cycle's schedule.
void ExpectTheSameYear(const std::string& full, const std::string& resumed) {
  EXPECT_EQ(DeterministicCells(resumed + "/cycles.csv"), DeterministicCells(full + "/cycles.csv"));
  const nlohmann::json ya = ReadJson(full + "/year.json");
  const nlohmann::json yb = ReadJson(resumed + "/year.json");
  for (const char* k : {"consumption_l1_m_s", "delta_v_m_s", "propellant_kg", "normal_delta_v_m_s",
                        "thrust_days", "time_outside_window_s", "max_abs_lat_deg",
                        "max_abs_lon_deg", "burns", "cycles", "complete"}) {
    EXPECT_EQ(ya[k], yb[k]) << k << " of " << resumed;
  }
  const nlohmann::json ca = ReadJson(full + "/checkpoint.json");
  const nlohmann::json cb = ReadJson(resumed + "/checkpoint.json");
  EXPECT_EQ(ca["eci"], cb["eci"]) << resumed;  // the final true state, bit for bit
  EXPECT_EQ(ca["last_burn_end_s"], cb["last_burn_end_s"]) << resumed;
  EXPECT_EQ(ReadFile(full + "/trajectory.csv"), ReadFile(resumed + "/trajectory.csv")) << resumed;
  for (int k = 1; k <= 4; ++k) {
    const std::string f = "/cycles/cycle_00" + std::to_string(k) + ".csv";
    EXPECT_EQ(ReadFile(full + f), ReadFile(resumed + f)) << resumed << f;
  }
}

TEST(SimulateCli, FourCyclesResumeEqualsUninterrupted) {
  // Uninterrupted run.
  const std::string full = TempDir("sim_full");
  const auto r = RunCli({"simulate", kScenario, "--out", full, "--no-plots"}, 300);
  ASSERT_TRUE(r.exited) << r.Describe();
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_NE(r.err.find("cycle 4/4"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ETA"), std::string::npos) << r.err;
  for (const char* f :
       {"cycles.csv", "year.json", "trajectory.csv", "checkpoint.json", "cycles/cycle_001.csv",
        "cycles/cycle_004.csv", "cycles/cycle_004_trajectory.csv", "consumption.gp", "vectors.gp",
        "latlon.gp", "timeline.gp"}) {
    EXPECT_TRUE(fs::exists(full + "/" + f)) << f;
  }
  const nlohmann::json year = ReadJson(full + "/year.json");
  EXPECT_TRUE(year["complete"].get<bool>());
  EXPECT_EQ(year["cycles"], 4);
  EXPECT_DOUBLE_EQ(year["simulated_days"].get<double>(), 4.0);
  for (const char* k :
       {"consumption_l1_m_s", "delta_v_m_s", "propellant_kg", "normal_delta_v_m_s",
        "time_outside_window_s", "wall_seconds", "max_abs_lat_deg", "max_abs_lon_deg"}) {
    EXPECT_TRUE(year[k].is_number()) << k;
  }
  // Physics of the totals: L1 = 1.44296 x delta-v for the Anzel thrusters;
  // propellant = delta-v m / (g0 Isp); normal = cos(theta) x delta-v.
  const double dv = year["delta_v_m_s"].get<double>();
  EXPECT_GT(dv, 0.1);  // the inclined start needs thrust
  EXPECT_NEAR(year["consumption_l1_m_s"].get<double>(), 1.44296 * dv, 1e-4 * dv);
  EXPECT_NEAR(year["propellant_kg"].get<double>(), 4850.0 * dv / (9.80665 * 2005.0), 1e-6);
  EXPECT_NEAR(year["normal_delta_v_m_s"].get<double>(),
              std::cos(63.64 * 3.14159265358979323846 / 180.0) * dv, 1e-9 + 1e-12 * dv);
  // Thrust days: per thruster sums to the total; N + S = E + W = total (Anzel).
  const nlohmann::json& td = year["thrust_days"];
  double sum = 0;
  for (const auto& [name, days] : td["per_thruster"].items()) sum += days.get<double>();
  EXPECT_NEAR(sum, td["total"].get<double>(), 1e-12);
  EXPECT_NEAR(td["north"].get<double>() + td["south"].get<double>(), sum, 1e-12);
  EXPECT_NEAR(td["east"].get<double>() + td["west"].get<double>(), sum, 1e-12);
  // The summary on stdout prints the same total (5 significant digits).
  {
    const size_t at = r.out.find("thrust days   total ");
    ASSERT_NE(at, std::string::npos) << r.out;
    const double printed = std::stod(r.out.substr(at + 20, 24));
    EXPECT_NEAR(printed, sum, 1e-4 * sum + 1e-12) << r.out.substr(at, 80);
  }
  EXPECT_NEAR(sum * 86400.0 * 0.265 / 4850.0, dv, 1e-9);
  EXPECT_TRUE(year["box_held"].get<bool>());
  EXPECT_EQ(year["fallbacks"]["total"], 0);
  EXPECT_TRUE(year["rules_ok"].get<bool>());

  // cycles.csv: one row per cycle with the contract columns.
  const auto rows = ReadCsvRows(full + "/cycles.csv");
  ASSERT_EQ(rows.size(), 5u);
  for (const char* c : {"start_utc", "status", "objective", "gap", "solve_s", "consumption_l1_m_s",
                        "burns", "max_abs_lat_deg", "max_abs_lon_deg", "fallback"}) {
    Column(rows[0], c);
  }
  EXPECT_EQ(rows[1][Column(rows[0], "start_utc")], "2034-01-01T00:00:00Z");
  EXPECT_EQ(rows[4][Column(rows[0], "start_utc")], "2034-01-04T00:00:00Z");
  // The per-cycle schedules together satisfy the operational rules across
  // the cycle boundaries (the independent checker).
  const Scenario sc = LoadSimulation(kScenario).scenario;
  std::vector<transcription::Burn> all;
  int burns = 0;
  for (int k = 1; k <= 4; ++k) {
    const auto b = ReadScheduleCsv(full + "/cycles/cycle_00" + std::to_string(k) + ".csv", sc);
    EXPECT_EQ(static_cast<int>(b.size()), std::stoi(rows[k][Column(rows[0], "burns")]));
    burns += static_cast<int>(b.size());
    all.insert(all.end(), b.begin(), b.end());
  }
  EXPECT_EQ(year["burns"], burns);
  const auto v = transcription::CheckOperationalRules(
      sc.problem.rules, transcription::BoundaryHistory::AllOff(4), {}, 4, 0.0, 4 * 86400.0, all);
  for (const auto& x : v) ADD_FAILURE() << x.message;
  // trajectory.csv: every 30 min over 4 days, inside the box.
  const auto traj = ReadCsvRows(full + "/trajectory.csv");
  EXPECT_EQ(traj.size(), 1u + 4 * 48 + 1);
  for (size_t i = 1; i < traj.size(); ++i) {
    EXPECT_LE(std::abs(std::stod(traj[i][2])), 0.05) << i;
    EXPECT_LE(std::abs(std::stod(traj[i][3])), 0.05) << i;
  }

  // Interrupted after 2 cycles, then resumed.
  const std::string split = TempDir("sim_split");
  const auto r2 =
      RunCli({"simulate", kScenario, "--out", split, "--no-plots", "--cycles", "2"}, 300);
  ASSERT_EQ(r2.exit_code, 0) << r2.Describe();
  const nlohmann::json partial = ReadJson(split + "/year.json");
  EXPECT_FALSE(partial["complete"].get<bool>());
  EXPECT_EQ(partial["cycles"], 2);
  EXPECT_EQ(ReadCsvRows(split + "/cycles.csv").size(), 3u);
  // A stale row (as if the program died after appending it but before the
  // checkpoint) disappears on resume.
  {
    std::ofstream app(split + "/cycles.csv", std::ios::app);
    app << "3,stale,row\n";
  }
  const auto r3 = RunCli({"simulate", kScenario, "--out", split, "--no-plots", "--resume"}, 300);
  ASSERT_EQ(r3.exit_code, 0) << r3.Describe();
  EXPECT_NE(r3.err.find("resuming"), std::string::npos) << r3.err;
  ExpectTheSameYear(full, split);

  // Ctrl-C inside cycle 3's solve (at its first incumbent), then resumed:
  // the cycle is solved again from its start and the year is the same.
  const std::string cut = TempDir("sim_cut");
  RunHooks hooks;
  int cycle_running = 0;
  hooks.in_cycle = [&](int cycle) { cycle_running = cycle; };
  hooks.on_progress = [&](const milp::SolveProgress& p) {
    if (cycle_running == 3) InterruptSelfAtFirstIncumbent(p);
  };
  const auto r5 = thrustsched::testing::RunInChild([&] {
    return thrustsched::app::RunCli(
        {"thrustsched", "simulate", kScenario, "--out", cut, "--no-plots"}, hooks);
  });
  ASSERT_TRUE(r5.exited) << r5.Describe();
  ASSERT_EQ(r5.exit_code, 4) << r5.Describe();
  EXPECT_EQ(ReadJson(cut + "/checkpoint.json")["next_cycle"], 2);
  EXPECT_EQ(ReadCsvRows(cut + "/cycles.csv").size(), 3u);
  const auto r6 = RunCli({"simulate", kScenario, "--out", cut, "--no-plots", "--resume"}, 300);
  ASSERT_EQ(r6.exit_code, 0) << r6.Describe();
  ExpectTheSameYear(full, cut);

  // A checkpoint of another scenario is refused (exit 2), naming it.
  const std::string other = TempDir("sim_other");
  std::string text = ReadFile(kScenario);
  const size_t pos = text.find("\"cycle_relative_gap\"");
  ASSERT_NE(pos, std::string::npos);
  text.insert(pos, "\"soft_penalty\": 500, ");
  thrustsched::testing::WriteFile(other + "/changed.json", text);
  fs::copy_file(split + "/checkpoint.json", other + "/checkpoint.json");
  const auto r4 = RunCli(
      {"simulate", other + "/changed.json", "--out", other, "--resume", "--cycles", "1"}, 120);
  EXPECT_EQ(r4.exit_code, 2) << r4.Describe();
  EXPECT_NE(r4.err.find("checkpoint"), std::string::npos) << r4.err;
  fs::remove_all(full);
  fs::remove_all(split);
  fs::remove_all(cut);
  fs::remove_all(other);
}

// A folder holding an earlier run is never silently started over: without
// The run's report.html with the per-cycle table and the year plots; the
// consumption bars start at 0 (the axis started at the smallest cycle,
// exaggerating the differences).
TEST(SimulateCli, WritesTheReportAndTheYearPlots) {
  const std::string dir = TempDir("sim_report");
  auto r = RunCli({"simulate", kScenario, "--out", dir + "/a", "--cycles", "1", "--quiet"}, 300);
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const std::string html = ReadFile(dir + "/a/report.html");
  for (const char* part : {"<h1>year_test_4cycles</h1>", "1 of 4", "<h2>Cycles</h2>",
                           "2034-01-01T00:00:00Z", "consumption (m/s)", "inside the box"}) {
    EXPECT_NE(html.find(part), std::string::npos) << part;
  }
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_NE(ReadFile(dir + "/a/.thrustsched-run.json").find("report.html"), std::string::npos);
  EXPECT_NE(ReadFile(dir + "/a/consumption.gp").find("set yrange [0:*]"), std::string::npos);
  if (thrustsched::testing::HaveProgram("gnuplot")) {
    for (const char* f : {"gap.svg", "thrust_days.svg", "box.svg", "consumption.svg"}) {
      EXPECT_TRUE(fs::exists(dir + "/a/" + f)) << f;
    }
    // The left axis of consumption.svg has a tic labelled 0.
    const std::string svg = ReadFile(dir + "/a/consumption.svg");
    bool zero = false;
    for (size_t at = svg.find("text-anchor=\"end\""); at != std::string::npos && !zero;
         at = svg.find("text-anchor=\"end\"", at + 1)) {
      const size_t open = svg.find(">", svg.find("<tspan", at)) + 1;
      const std::string label = svg.substr(open, svg.find("</tspan>", open) - open);
      zero = label.find_first_not_of(" 0.") == std::string::npos;
    }
    EXPECT_TRUE(zero) << "no 0 on the consumption axis";
    size_t plots = 0;
    for (size_t at = html.find("<svg "); at != std::string::npos; at = html.find("<svg ", at + 1))
      ++plots;
    EXPECT_EQ(plots, 7u);
  }
  r = RunCli({"simulate", kScenario, "--out", dir + "/b", "--cycles", "1", "--quiet", "--no-plots",
              "--no-report"},
             300);
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_FALSE(fs::exists(dir + "/b/report.html"));
  fs::remove_all(dir);
}

// --resume or --force the command refuses (exit 2, naming both) and changes
// nothing; --force starts over with the earlier run's files removed (no stale
// cycles/cycle_002* left beside a one-cycle run).
TEST(SimulateCli, RefusesToStartOverAnEarlierRun) {
  const std::string dir = TempDir("sim_again");
  auto r = RunCli({"simulate", kScenario, "--out", dir, "--no-plots", "--cycles", "2"}, 300);
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  ASSERT_TRUE(fs::exists(dir + "/cycles/cycle_002.csv"));
  const std::string checkpoint = ReadFile(dir + "/checkpoint.json");

  r = RunCli({"simulate", kScenario, "--out", dir, "--no-plots", "--cycles", "1"}, 60);
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_NE(r.err.find("--resume"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_EQ(ReadFile(dir + "/checkpoint.json"), checkpoint);
  EXPECT_TRUE(fs::exists(dir + "/cycles/cycle_002.csv"));

  r = RunCli(
      {"simulate", kScenario, "--out", dir, "--no-plots", "--cycles", "1", "--resume", "--force"},
      60);
  EXPECT_EQ(r.exit_code, 2) << r.Describe();

  thrustsched::testing::WriteFile(dir + "/my_notes.txt", "mine");
  r = RunCli({"simulate", kScenario, "--out", dir, "--no-plots", "--cycles", "1", "--force"}, 300);
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_EQ(ReadJson(dir + "/checkpoint.json")["next_cycle"], 1);
  EXPECT_EQ(ReadCsvRows(dir + "/cycles.csv").size(), 2u);
  EXPECT_TRUE(fs::exists(dir + "/cycles/cycle_001.csv"));
  EXPECT_FALSE(fs::exists(dir + "/cycles/cycle_002.csv"));
  EXPECT_EQ(ReadFile(dir + "/my_notes.txt"), "mine");
  fs::remove_all(dir);
}

TEST(SimulateCli, BadInputExitsTwo) {
  const std::string dir = TempDir("sim_bad");
  thrustsched::testing::WriteFile(dir + "/s.json", ScenarioText(R"({"duration_s": -5})"));
  const auto r = RunCli({"simulate", dir + "/s.json", "--out", dir}, 60);
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_NE(r.err.find("scenario.long_horizon.duration_s"), std::string::npos) << r.err;
  const auto r2 = RunCli({"simulate", kScenario, "--cycles", "0", "--out", dir}, 60);
  EXPECT_EQ(r2.exit_code, 2) << r2.Describe();
  fs::remove_all(dir);
}

// Ctrl-C during the first cycle: nothing half-written, exit 4, and --resume
// runs the whole scenario.
TEST(SimulateCli, SigintStopsCleanlyAndResumes) {
  const std::string dir = TempDir("sim_int");
  // The CLI interrupts itself at the first incumbent of cycle 1 (injected
  // progress hook, app/run_hooks.h): a Ctrl-C that always lands inside the
  // first solve, through the real SIGINT path, in a child process.
  RunHooks hooks;
  hooks.on_progress = InterruptSelfAtFirstIncumbent;
  const auto r = thrustsched::testing::RunInChild([&] {
    return thrustsched::app::RunCli(
        {"thrustsched", "simulate", kScenario, "--out", dir, "--no-plots"}, hooks);
  });
  ASSERT_TRUE(r.exited) << r.Describe();
  ASSERT_EQ(r.exit_code, 4) << r.Describe();
  EXPECT_NE(r.err.find("--resume"), std::string::npos) << r.err;
  const nlohmann::json cp = ReadJson(dir + "/checkpoint.json");
  EXPECT_EQ(cp["next_cycle"], 0);
  EXPECT_EQ(ReadCsvRows(dir + "/cycles.csv").size(), 1u);  // header only
  const auto r2 =
      RunCli({"simulate", kScenario, "--out", dir, "--no-plots", "--resume", "--cycles", "1"}, 300);
  ASSERT_EQ(r2.exit_code, 0) << r2.Describe();
  EXPECT_EQ(ReadCsvRows(dir + "/cycles.csv").size(), 2u);
  fs::remove_all(dir);
}

// A process killed inside a cycle (a solver crash: CoinUtils was seen to
// SIGSEGV in CBC's postprocessing) leaves in_progress.json; --resume solves
// that cycle with CBC preprocessing off and says so; a second death in the
// same cycle stops with an error instead of looping.
TEST(SimulateCli, SolverCrashIsRetriedOnResume) {
  const std::string dir = TempDir("sim_crash");
  // Cycle 2 dies (injected hook: std::abort inside the cycle's crash guard).
  RunHooks die_in_cycle_2;
  die_in_cycle_2.in_cycle = [](int cycle) {
    if (cycle == 2) std::abort();
  };
  const auto r = thrustsched::testing::RunInChild([&] {
    return thrustsched::app::RunCli(
        {"thrustsched", "simulate", kScenario, "--out", dir, "--no-plots", "--cycles", "2"},
        die_in_cycle_2);
  });
  ASSERT_FALSE(r.exited && r.exit_code == 0) << r.Describe();
  ASSERT_TRUE(fs::exists(dir + "/in_progress.json")) << r.Describe();
  const nlohmann::json mark = ReadJson(dir + "/in_progress.json");
  EXPECT_EQ(mark["cycle"], 2);
  EXPECT_EQ(mark["solver_preprocessing_off"], false);
  EXPECT_EQ(ReadCsvRows(dir + "/cycles.csv").size(), 2u);  // header + cycle 1

  // The same death again, now in the preprocessing-off attempt...
  const auto r2 = thrustsched::testing::RunInChild([&] {
    return thrustsched::app::RunCli({"thrustsched", "simulate", kScenario, "--out", dir,
                                     "--no-plots", "--cycles", "2", "--resume"},
                                    die_in_cycle_2);
  });
  ASSERT_FALSE(r2.exited && r2.exit_code == 0) << r2.Describe();
  EXPECT_NE(r2.err.find("preprocessing off"), std::string::npos) << r2.err;
  EXPECT_EQ(ReadJson(dir + "/in_progress.json")["solver_preprocessing_off"], true);
  // ...is refused on the next resume, naming the cycle (exit 1, no loop).
  const auto r3 =
      RunCli({"simulate", kScenario, "--out", dir, "--no-plots", "--resume", "--cycles", "2"}, 300);
  ASSERT_TRUE(r3.exited) << r3.Describe();
  EXPECT_EQ(r3.exit_code, 1) << r3.Describe();
  EXPECT_NE(r3.err.find("cycle 2 ended the process twice"), std::string::npos) << r3.err;

  // The first case once more, resumed without the hook: cycle 2 is solved
  // with preprocessing off, noted, and the marker is gone.
  nlohmann::json first = ReadJson(dir + "/in_progress.json");
  first["solver_preprocessing_off"] = false;
  thrustsched::testing::WriteFile(dir + "/in_progress.json", first.dump());
  const auto r4 =
      RunCli({"simulate", kScenario, "--out", dir, "--no-plots", "--resume", "--cycles", "2"}, 300);
  ASSERT_EQ(r4.exit_code, 0) << r4.Describe();
  EXPECT_NE(r4.err.find("an earlier run died while solving cycle 2"), std::string::npos) << r4.err;
  EXPECT_FALSE(fs::exists(dir + "/in_progress.json"));
  const auto rows = ReadCsvRows(dir + "/cycles.csv");
  ASSERT_EQ(rows.size(), 3u);
  const int note = Column(rows[0], "note");
  ASSERT_GE(note, 0);
  EXPECT_EQ(rows[1][note], "");
  EXPECT_NE(rows[2][note].find("solver crash"), std::string::npos) << rows[2][note];
  EXPECT_EQ(rows[2][Column(rows[0], "rules_ok")], "true");
  // A normal cycle leaves no marker behind either.
  const auto r5 =
      RunCli({"simulate", kScenario, "--out", dir, "--no-plots", "--resume", "--cycles", "3"}, 300);
  ASSERT_EQ(r5.exit_code, 0) << r5.Describe();
  EXPECT_FALSE(fs::exists(dir + "/in_progress.json"));
  EXPECT_EQ(ReadCsvRows(dir + "/cycles.csv").size(), 4u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace thrustsched::app
