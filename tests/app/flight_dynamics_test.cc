// Flight-dynamics interoperability end to end: GEO initial states given as
// orbits (OPM file, ECI state vector, Keplerian elements), schedule.csv's UTC
// and burn columns, and the CCSDS files of a plan (--oem, --opm-maneuvers):
// the OEM is re-read with our own parser and re-propagated line to line with
// the nonlinear model. No MILP solve is timed: the plan is a given burn list
// checked with `check`, and the `solve`/`simulate` runs use tiny horizons.
//
// The shipped scenario's outputs are written to
// <build>/geo_week_from_opm/ (plan.oem, plan.opm, schedule.csv, check.json).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "app/ccsds_oem.h"
#include "app/ccsds_opm.h"
#include "app/outputs.h"
#include "app/scenario.h"
#include "dynamics/frames.h"
#include "dynamics/geo_model.h"
#include "dynamics/geo_simulator.h"
#include "tests/app/cli_runner.h"

namespace thrustsched::app {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using thrustsched::testing::ReadFile;
using thrustsched::testing::RunCli;
using thrustsched::testing::TempDir;
using thrustsched::testing::WriteFile;

const std::string kScenarios = THRUSTSCHED_DATA_DIR "/scenarios/";
const std::string kShipped = kScenarios + "geo_week_from_opm.json";
const std::string kOpmFile = kScenarios + "geo_week_from_opm.opm";
constexpr const char* kCreation =
    "2000000000";  // SOURCE_DATE_EPOCH of the tests: 2033-05-18T03:33:20Z

// The burns of the shipped week, as `solve` found them (proven optimal,
// 1.86856 m/s L1; README): the CCSDS products are checked on this plan
// without solving again.
const char* kWeekSchedule = R"(thruster,start_s,end_s,duration_s
NE,45900,47100,1200
NW,404700,405600,900
NW,489300,495300,6000
NW,564900,571800,6900
NW,585900,594600,8700
)";

// The shipped scenario with its OPM path made absolute and the given
// changes (so that the copy can live in a temporary directory).
nlohmann::json ShippedWith(const nlohmann::json& patch) {
  nlohmann::json j = nlohmann::json::parse(ReadFile(kShipped));
  j["initial_state"]["opm"]["file"] = kOpmFile;
  if (!patch.is_null()) j.merge_patch(patch);
  return j;
}

Eigen::VectorXd Relative(const nlohmann::json& scenario) {
  return ParseScenario(scenario).problem.initial_state;
}

double MaxRelativeError(const Eigen::VectorXd& got, const Eigen::VectorXd& want) {
  const Eigen::VectorXd scale = dynamics::GeoLinearModel(dynamics::GeoModelOptions{}).state_scale();
  double worst = 0;
  for (int i = 0; i < 6; ++i) {
    worst = std::max(worst, std::abs(got(i) - want(i)) / std::max(std::abs(want(i)), scale(i)));
  }
  return worst;
}

// Distance (m) between the positions of two relative states at t = 0.
double PositionGap(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const dynamics::GeoSimulator sim(dynamics::GeoModelOptions{});
  return (sim.EciFromRelative(a, 0.0) - sim.EciFromRelative(b, 0.0)).head<3>().norm();
}

TEST(InitialOrbit, TheThreeFormsGiveTheSameModelState) {
  const Opm opm = ParseOpm(ReadFile(kOpmFile), kOpmFile);
  const Eigen::VectorXd from_opm = Relative(ShippedWith({}));
  // The OPM's state vector typed inline.
  nlohmann::json eci = {{"frame", "EME2000"},
                        {"epoch", opm.epoch.ToIso8601()},
                        {"position_km", {opm.rv[0] / 1e3, opm.rv[1] / 1e3, opm.rv[2] / 1e3}},
                        {"velocity_km_s", {opm.rv[3] / 1e3, opm.rv[4] / 1e3, opm.rv[5] / 1e3}}};
  nlohmann::json patch = {{"initial_state", {{"opm", nullptr}, {"eci_state", eci}}}};
  EXPECT_LT(MaxRelativeError(Relative(ShippedWith(patch)), from_opm), 1e-12);
  // Its Keplerian elements, written to 1e-10 deg and 1 mm: the same orbit to
  // the file's precision (1 mm), the conversion itself being exact
  // (keplerian_test, geo_orbit_state_test).
  const dynamics::KeplerianElements& k = opm.keplerian->elements;
  constexpr double kDeg = 3.14159265358979323846 / 180.0;
  nlohmann::json kep = {{"frame", "EME2000"},
                        {"epoch", opm.epoch.ToIso8601()},
                        {"semi_major_axis_km", k.a_m / 1e3},
                        {"eccentricity", k.e},
                        {"inclination_deg", k.i_rad / kDeg},
                        {"ra_of_asc_node_deg", k.raan_rad / kDeg},
                        {"arg_of_pericenter_deg", k.arg_perigee_rad / kDeg},
                        {"true_anomaly_deg", k.anomaly_rad / kDeg},
                        {"gm_km3_s2", opm.keplerian->gm_m3_s2 / 1e9}};
  patch = {{"initial_state", {{"opm", nullptr}, {"keplerian", kep}}}};
  EXPECT_LT(PositionGap(Relative(ShippedWith(patch)), from_opm), 1e-3);
  patch = {{"initial_state", {{"opm", {{"file", kOpmFile}, {"use", "keplerian"}}}}}};
  EXPECT_LT(PositionGap(Relative(ShippedWith(patch)), from_opm), 1e-3);
  EXPECT_GT(PositionGap(Relative(ShippedWith(patch)), from_opm), 0.0);  // it did read the elements
  // The OPM is 2 h before the week: its state was propagated, not just converted.
  const Scenario s = ParseScenario(ShippedWith({}));
  ASSERT_TRUE(s.initial_orbit.has_value());
  EXPECT_EQ(s.initial_orbit->object_id, "2033-900A");
  EXPECT_EQ(s.initial_orbit->given.epoch, dynamics::Epoch::Parse("2033-12-31T22:00:00Z"));
  // Near the station: inside the window, inclination ~0.03 deg in the 2034 frame
  // (0.17 deg in EME2000: the equator moved by the precession since 2000).
  EXPECT_LT(std::abs(from_opm(0)), 5000.0);
  EXPECT_NEAR(2 * std::atan(std::hypot(from_opm(3), from_opm(4))) / kDeg, 0.0305, 0.002);
  EXPECT_NEAR(k.i_rad / kDeg, 0.1738, 0.001);
}

TEST(InitialOrbit, UnsupportedInputIsRejectedNamingFieldAndValue) {
  auto fails = [](const nlohmann::json& patch, const std::string& message) {
    EXPECT_THAT([&] { ParseScenario(ShippedWith(patch)); },
                ThrowsMessage<ScenarioError>(HasSubstr(message)))
        << patch.dump();
  };
  const nlohmann::json eci = {{"frame", "EME2000"},
                              {"position_km", {-41738.5, -6016.8, 122.5}},
                              {"velocity_km_s", {0.4388, -3.0428, -0.0027}}};
  nlohmann::json bad = eci;
  bad["frame"] = "ITRF2014";
  fails({{"initial_state", {{"opm", nullptr}, {"eci_state", bad}}}},
        "scenario.initial_state.eci_state.frame: unknown value \"ITRF2014\" (expected one of: "
        "EME2000, GCRF)");
  bad = eci;
  bad["epoch"] = "2034-01-01T00:00:01Z";
  fails({{"initial_state", {{"opm", nullptr}, {"eci_state", bad}}}},
        "scenario.initial_state.eci_state: the state's epoch 2034-01-01T00:00:01Z is after the "
        "horizon start");
  bad = eci;
  bad["position_km"] = {7000, 0, 0};
  bad["velocity_km_s"] = {0, 7.5, 0};
  fails({{"initial_state", {{"opm", nullptr}, {"eci_state", bad}}}},
        "not a near-geostationary orbit");
  fails({{"initial_state", {{"station_point", true}}}},
        "scenario.initial_state: give only one of station_point");
  fails({{"initial_state", {{"opm", {{"file", "no/such.opm"}}}}}},
        "cannot open the OPM file no/such.opm");
  // An OPM in an Earth-fixed frame, or with maneuvers.
  const std::string dir = TempDir("opm_bad");
  std::string text = ReadFile(kOpmFile);
  text.replace(text.find("EME2000"), 7, "ITRF2014");
  WriteFile(dir + "/itrf.opm", text);
  fails({{"initial_state", {{"opm", {{"file", dir + "/itrf.opm"}}}}}},
        "REF_FRAME = ITRF2014: unsupported reference frame");
  WriteFile(dir + "/man.opm",
            ReadFile(kOpmFile) +
                "MAN_EPOCH_IGNITION = 2034-01-01T01:00:00\nMAN_DURATION = 1 [s]\nMAN_DELTA_MASS = "
                "-0.1 [kg]\nMAN_REF_FRAME = RTN\nMAN_DV_1 = 0\nMAN_DV_2 = 0\nMAN_DV_3 = 0\n");
  fails({{"initial_state", {{"opm", {{"file", dir + "/man.opm"}}}}}}, "holds 1 maneuver block(s)");
  // Orbit forms belong to GEO initial states only.
  nlohmann::json hcw = nlohmann::json::parse(ReadFile(kScenarios + "hcw_table41_1d.json"));
  hcw["initial_state"] = {{"eci_state", eci}};
  EXPECT_THAT([&] { ParseScenario(hcw); },
              ThrowsMessage<ScenarioError>(
                  HasSubstr("scenario.initial_state.eci_state: an orbit needs a \"geo\" model")));
  std::filesystem::remove_all(dir);
}

// Re-propagates the OEM line to line with the nonlinear model (the burns of
// each segment from the schedule) and returns the largest position error (m).
double ReplayErrorOfOem(const Scenario& s, const OemFile& oem,
                        const std::vector<transcription::Burn>& burns) {
  const dynamics::GeoSimulator sim(*s.geo);
  const dynamics::Epoch epoch = dynamics::Epoch::Parse(s.geo->epoch);
  const Eigen::MatrixXd accel = s.problem.thrusters.AccelerationMatrix();
  std::vector<dynamics::InputPulse> pulses;
  for (const auto& b : burns) pulses.push_back({b.thruster, b.start_s, b.end_s});
  double worst = 0;
  for (const OemSegment& seg : oem.segments) {
    EXPECT_EQ(seg.frame, dynamics::InertialFrame::kEme2000);
    for (size_t k = 0; k + 1 < seg.points.size(); ++k) {
      const double t0 = seg.points[k].epoch.SecondsSince(epoch),
                   t1 = seg.points[k + 1].epoch.SecondsSince(epoch);
      const dynamics::Vector6d x0 = dynamics::ToModelFrame(seg.points[k].rv, seg.frame, epoch);
      const dynamics::Vector6d x1 = sim.Propagate(x0, t0, accel, pulses, {t1}).front();
      const dynamics::Vector6d want =
          dynamics::ToModelFrame(seg.points[k + 1].rv, seg.frame, epoch);
      worst = std::max(worst, (x1 - want).head<3>().norm());
    }
  }
  return worst;
}

// The shipped week from its OPM, with a given burn list: `check` writes the
// schedule with UTC and burn columns, the OEM and the OPM maneuvers, into
// <build>/geo_week_from_opm (the outputs the README shows).
TEST(FlightDynamicsCli, ShippedWeekRoundTripsThroughTheCcsdsFiles) {
  const std::string dir = std::string(THRUSTSCHED_BINARY_DIR) + "/geo_week_from_opm";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  WriteFile(dir + "/given_schedule.csv", kWeekSchedule);
  setenv("SOURCE_DATE_EPOCH", kCreation, 1);
  const testing::RunResult r =
      RunCli({"check", kShipped, dir + "/given_schedule.csv", "--out", dir, "--no-plots", "--oem",
              dir + "/plan.oem", "--opm-maneuvers", dir + "/plan.opm"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_THAT(r.out, HasSubstr("wrote         " + dir + "/plan.oem"));

  const Scenario s = LoadScenario(kShipped);
  const std::vector<transcription::Burn> burns = ReadScheduleCsv(dir + "/given_schedule.csv", s);
  ASSERT_GT(burns.size(), 2u);

  // schedule.csv: the contract columns, then the GEO ones.
  const testing::CsvRows csv = testing::ReadCsv(dir + "/schedule.csv");
  EXPECT_EQ(csv.header,
            "thruster,start_s,end_s,duration_s,start_utc,end_utc,dir_r,dir_t,dir_n,delta_v_m_s");
  ASSERT_EQ(csv.rows.size(), burns.size());
  const double accel = 0.265 / 4850;
  const dynamics::Epoch epoch = dynamics::Epoch::Parse("2034-01-01T00:00:00Z");
  double worst_ratio = 1;
  for (size_t k = 0; k < burns.size(); ++k) {
    const auto& row = csv.rows[k];
    EXPECT_EQ(row[4], epoch.PlusSeconds(burns[k].start_s).FormatUtc(3, true));
    EXPECT_EQ(row[4].size(), std::string("2034-01-01T00:00:00.000Z").size());
    EXPECT_EQ(row[5], epoch.PlusSeconds(burns[k].end_s).FormatUtc(3, true));
    const Eigen::Vector3d d = s.problem.thrusters.thruster(burns[k].thruster).direction;
    EXPECT_NEAR(std::stod(row[6]), d.x(), 1e-14);
    EXPECT_NEAR(std::stod(row[7]), d.y(), 1e-14);
    EXPECT_NEAR(std::stod(row[8]), d.z(), 1e-14);
    // Delivered delta-v: just below F/m x duration (the RTN frame turns
    // during the burn by omega x duration; the loss is ~ (omega T)^2 / 24 in plane).
    const double ratio = std::stod(row[9]) / (accel * burns[k].duration_s());
    const double turn = 7.2921e-5 * burns[k].duration_s();
    EXPECT_LT(ratio, 1.0 + 1e-6);
    EXPECT_GT(ratio, 1.0 - turn * turn / 24 - 1e-4);
    worst_ratio = std::min(worst_ratio, ratio);
  }
  std::printf("[ fd ] %zu burns, delivered/nominal delta-v >= %.6f\n", burns.size(), worst_ratio);
  // check reads its own output back (UTC cells must agree with the seconds).
  EXPECT_EQ(ReadScheduleCsv(dir + "/schedule.csv", s).size(), burns.size());

  // OEM: header and metadata as CCSDS 502.0-B-3 §5.2, segments split at every burn.
  const std::string oem_text = ReadFile(dir + "/plan.oem");
  for (const char* key :
       {"CCSDS_OEM_VERS       = 2.0\n", "CREATION_DATE        = 2033-05-18T03:33:20.000\n",
        "ORIGINATOR           = THRUSTSCHED\n", "OBJECT_NAME          = GEO-118E\n",
        "OBJECT_ID            = 2033-900A\n", "CENTER_NAME          = EARTH\n",
        "REF_FRAME            = EME2000\n", "TIME_SYSTEM          = UTC\n",
        "START_TIME           = 2034-01-01T00:00:00.000\n", "INTERPOLATION        = HERMITE\n"}) {
    EXPECT_THAT(oem_text, HasSubstr(key));
  }
  const OemFile oem = ParseOem(oem_text, dir + "/plan.oem");
  EXPECT_EQ(oem.segments.size(),
            2 * burns.size() + 1);  // the burns are apart: coast, burn, coast, ...
  for (size_t k = 0; k < burns.size(); ++k) {
    const OemSegment& arc = oem.segments[2 * k + 1];
    EXPECT_NEAR(arc.start_time.SecondsSince(epoch), burns[k].start_s, 1e-6);
    EXPECT_NEAR(arc.stop_time.SecondsSince(epoch), burns[k].end_s, 1e-6);
    EXPECT_EQ(oem.segments[2 * k].stop_time, arc.start_time);
  }
  EXPECT_NEAR(oem.segments.back().stop_time.SecondsSince(epoch), 7 * 86400.0, 1e-6);
  // Re-propagation between consecutive lines with the nonlinear model: 1 m.
  const double err = ReplayErrorOfOem(s, oem, burns);
  std::printf("[ fd ] OEM re-propagated line to line: largest position error %.3g m\n", err);
  EXPECT_LT(err, 1.0);
  // The first line is the replay start: the OPM state propagated 2 h (not the OPM state itself).
  const dynamics::Vector6d start = dynamics::FromModelFrame(
      dynamics::GeoSimulator(*s.geo).EciFromRelative(s.problem.initial_state, 0.0),
      dynamics::InertialFrame::kEme2000, epoch);
  EXPECT_LT((oem.segments[0].points[0].rv - start).head<3>().norm(), 1e-3);

  // OPM: the same start state, one maneuver block per burn.
  const Opm plan = ParseOpm(ReadFile(dir + "/plan.opm"), dir + "/plan.opm");
  EXPECT_EQ(plan.object_id, "2033-900A");
  EXPECT_EQ(plan.epoch, epoch);
  EXPECT_LT((plan.rv - start).head<3>().norm(), 1e-3);
  ASSERT_EQ(plan.maneuvers.size(), burns.size());
  for (size_t k = 0; k < burns.size(); ++k) {
    const OpmManeuver& m = plan.maneuvers[k];
    EXPECT_NEAR(m.ignition.SecondsSince(epoch), burns[k].start_s, 1e-6);
    EXPECT_NEAR(m.duration_s, burns[k].duration_s(), 1e-9);
    EXPECT_EQ(m.ref_frame, "RTN");
    const Eigen::Vector3d dv =
        accel * burns[k].duration_s() * s.problem.thrusters.thruster(burns[k].thruster).direction;
    EXPECT_LT((m.dv_m_s - dv).norm(), 1e-9);
    EXPECT_NEAR(m.delta_mass_kg, -0.265 / (9.80665 * 2005) * burns[k].duration_s(), 1e-6);
  }
  // Deterministic: the same command gives the same bytes.
  const testing::RunResult again =
      RunCli({"check", kShipped, dir + "/given_schedule.csv", "--oem", dir + "/again.oem"});
  EXPECT_EQ(again.exit_code, 0) << again.Describe();
  EXPECT_EQ(ReadFile(dir + "/again.oem"), oem_text);
  unsetenv("SOURCE_DATE_EPOCH");
}

TEST(FlightDynamicsCli, BadOptionsExitTwoNamingTheValue) {
  const std::string dir = TempDir("fd_bad");
  WriteFile(dir + "/s.csv", "thruster,start_s,end_s\n+T,0,300\n");
  testing::RunResult r = RunCli(
      {"check", kScenarios + "hcw_table41_1d.json", dir + "/s.csv", "--oem", dir + "/x.oem"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_THAT(
      r.err,
      HasSubstr("--oem " + dir +
                "/x.oem: CCSDS files need a GEO scenario (model.type \"geo\"), got \"hcw\""));
  // A scenario whose OPM is in an unsupported time system.
  std::string opm = ReadFile(kOpmFile);
  opm.replace(opm.find("TIME_SYSTEM          = UTC"), 26, "TIME_SYSTEM = TDB");
  WriteFile(dir + "/tdb.opm", opm);
  nlohmann::json sc = ShippedWith({{"initial_state", {{"opm", {{"file", dir + "/tdb.opm"}}}}}});
  WriteFile(dir + "/tdb.json", sc.dump(2));
  r = RunCli({"validate", dir + "/tdb.json", "--no-build"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_THAT(r.err, HasSubstr("tdb.opm:11: TIME_SYSTEM = TDB: unsupported time system"));
  // A GEO schedule.csv whose UTC column disagrees with its seconds.
  WriteFile(dir + "/utc.csv",
            "thruster,start_s,end_s,start_utc\nNE,3600,3900,2034-01-01T02:00:00.000Z\n");
  r = RunCli({"check", kShipped, dir + "/utc.csv"});
  EXPECT_EQ(r.exit_code, 2) << r.Describe();
  EXPECT_THAT(r.err,
              HasSubstr("start_utc \"2034-01-01T02:00:00.000Z\" is not the UTC time of 3600 s"));
  std::filesystem::remove_all(dir);
}

// `solve` and `simulate` write the same files (tiny horizons: these MILPs
// take well under a second).
TEST(FlightDynamicsCli, SolveAndSimulateWriteTheFiles) {
  const std::string dir = TempDir("fd_solve");
  nlohmann::json sc = ShippedWith({{"horizon", {{"duration_s", 10800}, {"step_s", 900}}},
                                   {"terminal", nullptr},
                                   {"solver", {{"time_limit_s", 60}, {"threads", 1}}}});
  WriteFile(dir + "/short.json", sc.dump(2));
  testing::RunResult r =
      RunCli({"solve", dir + "/short.json", "--out", dir + "/out", "--no-plots", "--quiet", "--oem",
              dir + "/short.oem", "--opm-maneuvers", dir + "/short.opm"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const OemFile oem = ParseOem(ReadFile(dir + "/short.oem"), "short.oem");
  EXPECT_NEAR(oem.segments.back().stop_time.SecondsSince(oem.segments.front().start_time), 10800.0,
              1e-6);
  const Opm opm = ParseOpm(ReadFile(dir + "/short.opm"), "short.opm");
  EXPECT_EQ(opm.object_name, "GEO-118E");

  // Two daily cycles of the year-simulation test scenario: one OEM across both.
  r = RunCli({"simulate", kScenarios + "year/year_test_4cycles.json", "--out", dir + "/sim",
              "--cycles", "2", "--quiet", "--no-plots", "--oem", dir + "/sim.oem",
              "--opm-maneuvers", dir + "/sim.opm"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const Scenario year =
      LoadScenario(kScenarios + "year/year_test_4cycles.json",
                   ScenarioParseOptions{{"long_horizon"}, "year_test_4cycles.json"});
  std::vector<transcription::Burn> burns;
  for (const char* c : {"/sim/cycles/cycle_001.csv", "/sim/cycles/cycle_002.csv"}) {
    for (const auto& b : ReadScheduleCsv(dir + c, year)) burns.push_back(b);
  }
  const OemFile sim = ParseOem(ReadFile(dir + "/sim.oem"), "sim.oem");
  EXPECT_NEAR(sim.segments.back().stop_time.SecondsSince(sim.segments.front().start_time),
              2 * 86400.0, 1e-6);
  EXPECT_EQ(ParseOpm(ReadFile(dir + "/sim.opm"), "sim.opm").maneuvers.size(), burns.size());
  const double err = ReplayErrorOfOem(year, sim, burns);
  std::printf("[ fd ] simulate: %zu burns in 2 cycles, OEM re-propagation error %.3g m\n",
              burns.size(), err);
  EXPECT_LT(err, 1.0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace thrustsched::app
