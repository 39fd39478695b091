// The initial orbit of a transfer scenario in every form it accepts: its own
// equinoctial and Keplerian (m, deg) forms, and the station-keeping
// scenarios' orbit forms (app/initial_orbit.h: ECI state, Keplerian in km,
// OPM), read by the same parser; bad input names the field and the value.
#include "app/transfer_scenario.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "common/constants.h"
#include "common/format.h"
#include "dynamics/frames.h"

namespace thrustsched::app {
namespace {

// Bombrun 2007 case 1 (Table 5.1) at its perigee: a = 24505.9 km, e = 0.725,
// i = 5.2 deg, W = w = 0; mu of the transfer (398600.47 km^3/s^2).
constexpr double kMu = 398600.47;
constexpr double kA = 24505.9, kE = 0.725, kIDeg = 5.2;

nlohmann::json Scenario(const nlohmann::json& initial) {
  return {{"transfer",
           {{"initial", initial},
            {"target", {{"a_m", 42165e3}, {"ex", 0}, {"ey", 0}, {"hx", 0}, {"hy", 0}}},
            {"thrust_n", 0.35},
            {"isp_s", 2000},
            {"mass_kg", 2000},
            {"method", "feedback"}}}};
}

// Position and velocity at the perigee, from the vis-viva closed form.
nlohmann::json EciState(const char* frame) {
  const double rp = kA * (1 - kE), vp = std::sqrt(kMu * (1 + kE) / rp);
  const double i = kIDeg * common::kDegToRad;
  return {{"eci_state",
           {{"frame", frame},
            {"epoch", "2034-01-01T00:00:00Z"},
            {"position_km", {rp, 0, 0}},
            {"velocity_km_s", {0, vp * std::cos(i), vp * std::sin(i)}}}}};
}

void ExpectSameOrbit(const transfer::Equinoctial& a, const transfer::Equinoctial& b, double tol) {
  EXPECT_NEAR(a.p_m, b.p_m, 1e-3);
  EXPECT_NEAR(a.ex, b.ex, tol);
  EXPECT_NEAR(a.ey, b.ey, tol);
  EXPECT_NEAR(a.hx, b.hx, tol);
  EXPECT_NEAR(a.hy, b.hy, tol);
  EXPECT_NEAR(std::remainder(a.l_rad - b.l_rad, 2 * common::kPi), 0.0, tol);
}

std::string Error(const nlohmann::json& j) {
  try {
    ParseTransferScenario(j, "x.json");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(TransferScenario, EveryOrbitFormGivesTheSameStart) {
  const TransferScenario own = ParseTransferScenario(Scenario({{"keplerian",
                                                                {{"a_m", kA * 1e3},
                                                                 {"e", kE},
                                                                 {"i_deg", kIDeg},
                                                                 {"raan_deg", 0},
                                                                 {"arg_perigee_deg", 0},
                                                                 {"true_anomaly_deg", 0}}}}),
                                                     "x.json");
  // p = a (1 - e^2), ex = e, hx = tan(i / 2), L = 0: the closed form.
  EXPECT_NEAR(own.problem.initial.p_m, kA * 1e3 * (1 - kE * kE), 1e-6);
  EXPECT_NEAR(own.problem.initial.hx, std::tan(kIDeg * common::kDegToRad / 2), 1e-15);
  EXPECT_FALSE(own.epoch.has_value());

  const TransferScenario eci = ParseTransferScenario(Scenario(EciState("EME2000")), "x.json");
  ExpectSameOrbit(eci.problem.initial, own.problem.initial, 1e-12);
  ASSERT_TRUE(eci.epoch.has_value());  // the state's epoch is the transfer's start
  EXPECT_EQ(eci.epoch->ToIso8601(), "2034-01-01T00:00:00Z");

  const TransferScenario kep = ParseTransferScenario(Scenario({{"keplerian",
                                                                {{"frame", "EME2000"},
                                                                 {"semi_major_axis_km", kA},
                                                                 {"eccentricity", kE},
                                                                 {"inclination_deg", kIDeg},
                                                                 {"ra_of_asc_node_deg", 0},
                                                                 {"arg_of_pericenter_deg", 0},
                                                                 {"mean_anomaly_deg", 0},
                                                                 {"gm_km3_s2", kMu}}}}),
                                                     "x.json");
  ExpectSameOrbit(kep.problem.initial, own.problem.initial, 1e-12);
  EXPECT_FALSE(kep.epoch.has_value());  // no epoch given: none

  // GCRF: the same numbers are a state rotated by the IERS 2003 frame bias
  // (23 mas): the inclination vector moves by about 1e-7, not more.
  const TransferScenario gcrf = ParseTransferScenario(Scenario(EciState("GCRF")), "x.json");
  const double dh = std::hypot(gcrf.problem.initial.hx - own.problem.initial.hx,
                               gcrf.problem.initial.hy - own.problem.initial.hy);
  EXPECT_GT(dh, 1e-9);
  EXPECT_LT(dh, 2e-7);

  // OPM, relative to the scenario file's folder.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "thrustsched_transfer_scenario_test";
  std::filesystem::create_directories(dir);
  const double rp = kA * (1 - kE), vp = std::sqrt(kMu * (1 + kE) / rp);
  const double i = kIDeg * common::kDegToRad;
  std::ofstream(dir / "gto.opm") << "CCSDS_OPM_VERS = 2.0\nCREATION_DATE = 2033-12-31T00:00:00\n"
                                    "ORIGINATOR = TEST\nOBJECT_NAME = GTO\nOBJECT_ID = 2034-000A\n"
                                    "CENTER_NAME = EARTH\nREF_FRAME = EME2000\nTIME_SYSTEM = UTC\n"
                                    "EPOCH = 2034-01-01T00:00:00\n"
                                 << "X = " << common::FormatG(rp, 17) << "\nY = 0\nZ = 0\n"
                                 << "X_DOT = 0\nY_DOT = " << common::FormatG(vp * std::cos(i), 17)
                                 << "\nZ_DOT = " << common::FormatG(vp * std::sin(i), 17) << "\n";
  nlohmann::json with_opm = Scenario({{"opm", {{"file", "gto.opm"}}}});
  with_opm["transfer"]["epoch"] = "2034-01-01T00:00:00Z";  // the same as the OPM's: accepted
  const TransferScenario opm = ParseTransferScenario(with_opm, (dir / "scn.json").string());
  ExpectSameOrbit(opm.problem.initial, own.problem.initial, 1e-12);
  EXPECT_EQ(opm.epoch->ToIso8601(), "2034-01-01T00:00:00Z");
  std::filesystem::remove_all(dir);
}

TEST(TransferScenario, BadOrbitFormsNameTheFieldAndTheValue) {
  nlohmann::json j = Scenario(EciState("ITRF"));
  std::string e = Error(j);
  EXPECT_NE(e.find("scenario.transfer.initial.eci_state.frame"), std::string::npos) << e;
  EXPECT_NE(e.find("ITRF"), std::string::npos) << e;

  j = Scenario(EciState("EME2000"));
  j["transfer"]["initial"]["eci_state"]["position_km"] = {6739.1, 0};
  e = Error(j);
  EXPECT_NE(e.find("scenario.transfer.initial.eci_state.position_km"), std::string::npos) << e;

  j = Scenario(EciState("EME2000"));
  j["transfer"]["initial"]["eci_state"]["velocity_km_s"] = {0, 12.0, 0};  // above escape
  e = Error(j);
  EXPECT_NE(e.find("scenario.transfer.initial.eci_state"), std::string::npos) << e;
  EXPECT_NE(e.find("not an ellipse"), std::string::npos) << e;

  j = Scenario(EciState("EME2000"));
  j["transfer"]["epoch"] = "2034-01-02T00:00:00Z";  // not the state's
  e = Error(j);
  EXPECT_NE(e.find("scenario.transfer.epoch"), std::string::npos) << e;
  EXPECT_NE(e.find("2034-01-02T00:00:00"), std::string::npos) << e;

  j = Scenario({{"opm", {{"file", "/nonexistent/gto.opm"}}}});
  e = Error(j);
  EXPECT_NE(e.find("scenario.transfer.initial.opm.file"), std::string::npos) << e;
  EXPECT_NE(e.find("/nonexistent/gto.opm"), std::string::npos) << e;

  j = Scenario({{"keplerian",
                 {{"frame", "EME2000"},
                  {"semi_major_axis_km", kA},
                  {"eccentricity", 1.2},
                  {"inclination_deg", kIDeg},
                  {"ra_of_asc_node_deg", 0},
                  {"arg_of_pericenter_deg", 0},
                  {"true_anomaly_deg", 0}}}});
  e = Error(j);
  EXPECT_NE(e.find("scenario.transfer.initial.keplerian.eccentricity"), std::string::npos) << e;
  EXPECT_NE(e.find("1.2"), std::string::npos) << e;

  // Two forms at once, and a perigee inside the Earth given as a state.
  j = Scenario(EciState("EME2000"));
  j["transfer"]["initial"]["equinoctial"] = {{"p_m", 1e7}};
  e = Error(j);
  EXPECT_NE(e.find("scenario.transfer.initial"), std::string::npos) << e;
  j = Scenario(EciState("EME2000"));
  j["transfer"]["initial"]["eci_state"]["position_km"] = {5000.0, 0, 0};
  e = Error(j);
  EXPECT_NE(e.find("below the Earth"), std::string::npos) << e;
}

// "force_model": "j2" is read for the feedback and minimum time; two_impulse
// (the Hohmann closed form) refuses it naming the field, also after a
// method override, and an unknown model is named with its value.
TEST(TransferScenario, ForceModelJ2IsReadAndRefusedByTwoImpulse) {
  nlohmann::json j = Scenario(EciState("EME2000"));
  EXPECT_EQ(ParseTransferScenario(j, "x.json").problem.force_model.kind,
            transfer::ForceModelKind::kTwoBody);
  j["transfer"]["force_model"] = "j2";
  const TransferScenario sc = ParseTransferScenario(j, "x.json");
  EXPECT_EQ(sc.problem.force_model.kind, transfer::ForceModelKind::kJ2);
  EXPECT_EQ(sc.problem.force_model.j2, transfer::kEarthJ2);
  j["transfer"]["method"] = "minimum_time";
  EXPECT_EQ(ParseTransferScenario(j, "x.json").problem.force_model.kind,
            transfer::ForceModelKind::kJ2);

  j["transfer"]["method"] = "two_impulse";
  std::string e = Error(j);
  EXPECT_NE(e.find("scenario.transfer.force_model: two_impulse"), std::string::npos) << e;
  EXPECT_NE(e.find("two_body only, got \"j2\""), std::string::npos) << e;

  j["transfer"]["method"] = "feedback";
  j["transfer"]["force_model"] = "j4";
  e = Error(j);
  EXPECT_NE(e.find("scenario.transfer.force_model"), std::string::npos) << e;
  EXPECT_NE(e.find("j4"), std::string::npos) << e;

  // The method overridden after parsing (--method, ts.transfer(method=...)).
  j["transfer"]["force_model"] = "j2";
  TransferScenario over = ParseTransferScenario(j, "x.json");
  over.method = TransferMethod::kTwoImpulse;
  EXPECT_THROW(CheckForceModel(over), ScenarioError);
}

}  // namespace
}  // namespace thrustsched::app
