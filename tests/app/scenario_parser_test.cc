// Scenario parser: every documented field reaches the problem/options it
// names, and every rejection class (unknown fields, wrong types, missing
// fields, bad durations, non-finite numbers, ...) produces a ScenarioError whose
// message names the field (full path) and the value.
#include "app/json_reader.h"
#include "app/scenario.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "dynamics/geo_simulator.h"
#include "dynamics/models.h"
#include "dynamics/schweighart_sedwick.h"
#include "tests/app/test_messages.h"

namespace thrustsched::app {
namespace {

using nlohmann::json;
constexpr double kPi = 3.14159265358979323846;

// An HCW example (Table 4.1-like) with all contract fields.
json HcwBase() {
  return json::parse(R"({
    "name": "hcw_test",
    "model": {"type": "hcw", "mean_motion_rad_s": 7.2921159e-5},
    "spacecraft": {"mass_kg": 4850, "isp_s": 2005, "thrust_n": 0.265,
                   "thrusters": {"preset": "ideal6"}, "disabled": []},
    "initial_state": {"hcw_position_m": [1000, 0, 0], "hcw_velocity_m_s": [0, 0, 0]},
    "horizon": {"duration_s": 259200, "step_s": 300},
    "window": {"half_width_m": 36800, "enforce_from_s": 0},
    "operations": {"max_simultaneous": 1, "min_burn_s": 300, "min_off_same_s": 1200, "min_gap_other_s": 300},
    "objective": "l1",
    "discretisation": {"scheme": "exact_zoh"},
    "solver": {"time_limit_s": 60, "relative_gap": 0.0, "threads": 1}
  })");
}

// A GEO example (thesis Table 5.1 set-up).
json GeoBase() {
  return json::parse(R"({
    "name": "geo_test",
    "model": {"type": "geo", "station_longitude_deg": 118, "epoch": "2034-01-01T00:00:00Z",
              "perturbations": ["j2", "tesseral", "sun", "moon", "srp"], "area_to_mass_m2_kg": 0.0227},
    "spacecraft": {"mass_kg": 4850, "isp_s": 2005, "thrust_n": 0.265,
                   "thrusters": {"preset": "anzel4", "theta_deg": 63.64, "alpha_deg": 7.03},
                   "disabled": []},
    "initial_state": {"station_point": true},
    "horizon": {"duration_s": 86400, "step_s": 600},
    "window": {"half_width_deg": 0.05, "enforce_from_s": 0},
    "operations": {"max_simultaneous": 1, "min_burn_s": 300, "min_off_same_s": 1200, "min_gap_other_s": 300},
    "objective": "propellant",
    "discretisation": {"scheme": "hermite_simpson"},
    "solver": {"time_limit_s": 90, "relative_gap": 0.01, "threads": 2}
  })");
}

Scenario Parse(const json& j, const ScenarioParseOptions& o = {}) { return ParseScenario(j, o); }

// The ScenarioError message for j, or a test failure if it parses.
std::string ErrorOf(const json& j, const ScenarioParseOptions& o = {}) {
  try {
    ParseScenario(j, o);
  } catch (const ScenarioError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a ScenarioError: " << e.what();
    return e.what();
  }
  ADD_FAILURE() << "parsed without error: " << j.dump();
  return "";
}

std::string TextErrorOf(const std::string& text) {
  try {
    ParseScenarioText(text);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  ADD_FAILURE() << "parsed without error: " << text;
  return "";
}

TEST(ScenarioParser, HcwContractFieldsReachTheProblem) {
  const Scenario s = Parse(HcwBase());
  EXPECT_EQ(s.name, "hcw_test");
  EXPECT_EQ(s.model_type, ModelType::kHcw);
  const auto* hcw = dynamic_cast<const dynamics::HcwModel*>(s.problem.model.get());
  ASSERT_NE(hcw, nullptr);
  EXPECT_DOUBLE_EQ(hcw->mean_motion(), 7.2921159e-5);
  EXPECT_EQ(s.problem.thrusters.size(), 6);
  EXPECT_EQ(s.thruster_names(), (std::vector<std::string>{"+R", "+T", "+N", "-R", "-T", "-N"}));
  EXPECT_DOUBLE_EQ(s.problem.thrusters.mass_kg(), 4850);
  EXPECT_DOUBLE_EQ(s.problem.thrusters.isp_s(), 2005);
  EXPECT_DOUBLE_EQ(s.problem.thrusters.thrust_n(), 0.265);
  EXPECT_EQ(s.problem.initial_state, (Eigen::VectorXd(6) << 1000, 0, 0, 0, 0, 0).finished());
  // 3 days of 5-min steps: 864 intervals, grid 0 .. 259200 s.
  ASSERT_EQ(s.problem.grid.size(), 865u);
  EXPECT_EQ(s.num_intervals, 864);
  EXPECT_DOUBLE_EQ(s.problem.grid.front(), 0.0);
  EXPECT_DOUBLE_EQ(s.problem.grid.back(), 259200.0);
  EXPECT_NEAR(s.problem.grid[1], 300.0, 1e-9);
  EXPECT_EQ(s.problem.window.outputs, (std::vector<int>{1, 2}));
  EXPECT_EQ(s.problem.window.half_widths, (std::vector<double>{36800, 36800}));
  EXPECT_EQ(s.window_unit, "m");
  EXPECT_DOUBLE_EQ(s.problem.window.enforce_from_s, 0.0);
  EXPECT_EQ(s.problem.rules.max_simultaneous, 1);
  EXPECT_DOUBLE_EQ(s.problem.rules.min_burn_s, 300);
  EXPECT_DOUBLE_EQ(s.problem.rules.min_off_same_s, 1200);
  EXPECT_DOUBLE_EQ(s.problem.rules.min_gap_other_s, 300);
  EXPECT_EQ(s.problem.objective.kind, transcription::ObjectiveKind::kL1);
  EXPECT_EQ(s.build.discretisation.scheme, dynamics::Scheme::kExactZoh);
  EXPECT_DOUBLE_EQ(s.solve.time_limit_s, 60);
  EXPECT_DOUBLE_EQ(s.solve.relative_gap, 0.0);
  EXPECT_EQ(s.solve.threads, 1);
  EXPECT_FALSE(s.check.nonlinear);  // only GEO replays nonlinearly
  EXPECT_FALSE(s.impulsive());
  // Default verdict tolerance: 1e-3 of the half width.
  EXPECT_DOUBLE_EQ(s.verdict.window_tolerance, 36.8);
}

TEST(ScenarioParser, GeoContractFieldsReachTheProblem) {
  json j = GeoBase();
  j["spacecraft"]["disabled"] = {"NE"};
  j["model"]["perturbations"] = {"j2", "sun"};
  j["model"]["area_to_mass_m2_kg"] = 0.03;
  const Scenario s = Parse(j);
  EXPECT_EQ(s.model_type, ModelType::kGeo);
  ASSERT_TRUE(s.geo.has_value());
  EXPECT_DOUBLE_EQ(s.geo->station_longitude_deg, 118);
  EXPECT_EQ(s.geo->epoch, "2034-01-01T00:00:00Z");
  EXPECT_TRUE(s.geo->j2);
  EXPECT_FALSE(s.geo->tesseral);
  EXPECT_TRUE(s.geo->sun);
  EXPECT_FALSE(s.geo->moon);
  EXPECT_FALSE(s.geo->srp);
  EXPECT_DOUBLE_EQ(s.geo->area_to_mass_m2_kg, 0.03);
  EXPECT_EQ(s.thruster_names(), (std::vector<std::string>{"NE", "SE", "NW", "SW"}));
  // Thesis (1.73): m ||Gamma||_1 / F = sin(theta)(cos(alpha) + sin(alpha)) + cos(theta) = 1.44296.
  EXPECT_NEAR(s.problem.thrusters.L1Factor(0) * 4850 / 0.265, 1.44296, 1e-5);
  EXPECT_FALSE(s.problem.thrusters.thruster(0).enabled);
  EXPECT_TRUE(s.problem.thrusters.thruster(1).enabled);
  EXPECT_EQ(s.problem.initial_state, Eigen::VectorXd::Zero(6));
  // Window in degrees -> radians on latitude (1) and longitude (2).
  EXPECT_EQ(s.problem.window.outputs, (std::vector<int>{1, 2}));
  EXPECT_NEAR(s.problem.window.half_widths[0], 0.05 * kPi / 180, 1e-15);
  EXPECT_EQ(s.window_unit, "deg");
  EXPECT_NEAR(s.window_unit_per_output_unit, 180 / kPi, 1e-12);
  EXPECT_DOUBLE_EQ(s.verdict.window_tolerance, 5e-5);
  EXPECT_EQ(s.problem.objective.kind, transcription::ObjectiveKind::kPropellant);
  EXPECT_EQ(s.build.discretisation.scheme, dynamics::Scheme::kHermiteSimpson);
  EXPECT_EQ(s.solve.threads, 2);
  ASSERT_TRUE(s.check.nonlinear);  // GEO default: nonlinear replay on
  EXPECT_DOUBLE_EQ(s.check.nonlinear->options().station_longitude_deg, 118);
  EXPECT_EQ(s.num_intervals, 144);
}

TEST(ScenarioParser, GeoRelativeEquinoctialAndStateForms) {
  json j = GeoBase();
  j["initial_state"] = {{"relative_equinoctial", {100, 1e-5, -2e-5, 3e-5, 4e-5, 1e-4}}};
  Scenario s = Parse(j);
  EXPECT_EQ(s.problem.initial_state,
            (Eigen::VectorXd(6) << 100, 1e-5, -2e-5, 3e-5, 4e-5, 1e-4).finished());
  j["initial_state"] = {{"state", {1, 2, 3, 4, 5, 6}}};
  s = Parse(j);
  EXPECT_EQ(s.problem.initial_state, (Eigen::VectorXd(6) << 1, 2, 3, 4, 5, 6).finished());
  j = HcwBase();
  j["initial_state"] = {{"hcw_position_m", {1, 2, 3}}};  // velocity defaults to zero
  s = Parse(j);
  EXPECT_EQ(s.problem.initial_state, (Eigen::VectorXd(6) << 1, 2, 3, 0, 0, 0).finished());
}

TEST(ScenarioParser, ModelExtensions) {
  json j = HcwBase();
  j["model"]["length_scale_m"] = 5000;
  Scenario s = Parse(j);
  EXPECT_DOUBLE_EQ(s.problem.model->state_scale()[0], 5000);

  j = GeoBase();
  j["model"]["reflectivity_cr"] = 1.5;
  j["model"]["gravity_degree"] = 2;
  j["model"].erase("perturbations");  // default: all five
  s = Parse(j);
  EXPECT_DOUBLE_EQ(s.geo->reflectivity_cr, 1.5);
  EXPECT_EQ(s.geo->gravity_degree, 2);
  EXPECT_TRUE(s.geo->j2 && s.geo->tesseral && s.geo->sun && s.geo->moon && s.geo->srp);
  j["model"]["perturbations"] = json::array();
  s = Parse(j);
  EXPECT_FALSE(s.geo->j2 || s.geo->tesseral || s.geo->sun || s.geo->moon || s.geo->srp);

  j = HcwBase();
  j["model"] = {{"type", "double_integrator"}, {"time_scale_s", 2.0}, {"length_scale_m", 3.0}};
  s = Parse(j);
  EXPECT_EQ(s.model_type, ModelType::kDoubleIntegrator);
  EXPECT_EQ(s.problem.model->name(), "double_integrator_3d");
  EXPECT_DOUBLE_EQ(s.problem.model->time_scale(), 2.0);
  EXPECT_DOUBLE_EQ(s.problem.model->state_scale()[0], 3.0);
}

TEST(ScenarioParser, YamanakaAnkersenHorizonByTrueAnomaly) {
  json j = HcwBase();
  j.erase("window");
  j["model"] = {{"type", "yamanaka_ankersen"}, {"semi_major_axis_m", 24616e3},
                {"eccentricity", 0.73074},     {"true_anomaly_at_epoch_rad", 0.1 * kPi},
                {"mu_m3_s2", 3.986004418e14},  {"length_scale_m", 1000}};
  j["horizon"] = {{"end_true_anomaly_rad", 5.2}, {"num_intervals", 400}};
  const Scenario s = Parse(j);
  const dynamics::YamanakaAnkersenModel ref(24616e3, 0.73074, 3.986004418e14, 0.1 * kPi);
  EXPECT_EQ(s.num_intervals, 400);
  EXPECT_NEAR(s.problem.grid.back(), ref.TimeAtTrueAnomaly(5.2), 1e-6);
  EXPECT_NEAR(ref.TrueAnomalyAt(s.problem.grid.back()), 5.2, 1e-9);
  // end_true_anomaly_rad is only for this model.
  json h = HcwBase();
  h["horizon"] = {{"end_true_anomaly_rad", 5.2}, {"num_intervals", 10}};
  EXPECT_HAS(ErrorOf(h), "scenario.horizon");
}

TEST(ScenarioParser, SchweighartSedwickModel) {
  json j = HcwBase();
  j["model"] = {{"type", "schweighart_sedwick"}, {"altitude_m", 650e3}, {"inclination_deg", 98}};
  Scenario s = Parse(j);
  EXPECT_EQ(s.model_type, ModelType::kSchweighartSedwick);
  EXPECT_EQ(ToString(s.model_type), "schweighart_sedwick");
  const auto& ss = dynamic_cast<const dynamics::SchweighartSedwickModel&>(*s.problem.model);
  EXPECT_DOUBLE_EQ(ss.reference_radius(), 6378137.0 + 650e3);
  EXPECT_DOUBLE_EQ(ss.inclination(), 98.0 * kPi / 180.0);
  EXPECT_NEAR(ss.s(), -6.2987e-4, 1e-8);  // tests/dynamics/schweighart_sedwick_test.cc
  EXPECT_EQ(ss.cross_track(), dynamics::CrossTrack::kEqualInclination);
  // The same orbit by its radius, the simple cross-track form, a length scale.
  j["model"] = {{"type", "schweighart_sedwick"},
                {"radius_m", 7028137.0},
                {"inclination_deg", 45},
                {"cross_track", "simple"},
                {"length_scale_m", 500}};
  s = Parse(j);
  const auto& simple = dynamic_cast<const dynamics::SchweighartSedwickModel&>(*s.problem.model);
  EXPECT_DOUBLE_EQ(simple.reference_radius(), 7028137.0);
  EXPECT_EQ(simple.cross_track(), dynamics::CrossTrack::kSimple);
  EXPECT_DOUBLE_EQ(simple.state_scale()[0], 500.0);
  // Boundary values are accepted: a polar and a retrograde equatorial orbit.
  j["model"] = {{"type", "schweighart_sedwick"}, {"altitude_m", 0}, {"inclination_deg", 180}};
  EXPECT_NO_THROW(Parse(j));
}

TEST(ScenarioParser, SchweighartSedwickModelRejectsBadValues) {
  const auto error_with = [](json model) {
    json j = HcwBase();
    j["model"] = std::move(model);
    return ErrorOf(j);
  };
  const json base = {
      {"type", "schweighart_sedwick"}, {"altitude_m", 650e3}, {"inclination_deg", 98}};
  json m = base;
  m["altitude_m"] = -1.0;
  EXPECT_HAS(error_with(m), "scenario.model.altitude_m");
  EXPECT_HAS(error_with(m), "-1");
  m = base;
  m["inclination_deg"] = 180.5;
  EXPECT_HAS(error_with(m), "scenario.model.inclination_deg: must be in [0, 180], got 180.5");
  m["inclination_deg"] = -3;
  EXPECT_HAS(error_with(m), "scenario.model.inclination_deg");
  EXPECT_HAS(error_with(m), "-3");
  m = base;
  m["radius_m"] = 7e6;  // both forms
  EXPECT_HAS(error_with(m), "altitude_m");
  EXPECT_HAS(error_with(m), "radius_m");
  m = base;
  m.erase("altitude_m");  // neither
  EXPECT_HAS(error_with(m), "scenario.model");
  m = {{"type", "schweighart_sedwick"}, {"radius_m", 0.0}, {"inclination_deg", 98}};
  EXPECT_HAS(error_with(m), "scenario.model.radius_m");
  m = base;
  m.erase("inclination_deg");
  EXPECT_HAS(error_with(m), "scenario.model.inclination_deg");
  m = base;
  m["cross_track"] = "full";
  EXPECT_HAS(error_with(m), "scenario.model.cross_track");
  EXPECT_HAS(error_with(m), "full");
  m = base;
  m["mean_motion_rad_s"] = 1e-3;  // an HCW field
  EXPECT_HAS(error_with(m), "scenario.model.mean_motion_rad_s: unknown field");
}

TEST(ScenarioParser, ThrusterExtensions) {
  json j = HcwBase();
  j["spacecraft"]["thrusters"] = {{"preset", "ideal6"}, {"use", {"-N", "+N"}}};
  Scenario s = Parse(j);
  EXPECT_EQ(s.thruster_names(), (std::vector<std::string>{"-N", "+N"}));
  j["spacecraft"]["thrusters"] = {{"custom",
                                   {{{"name", "+X"}, {"direction_rtn", {2, 0, 0}}},
                                    {{"name", "-X"}, {"direction_rtn", {-1, 0, 0}}}}}};
  s = Parse(j);
  EXPECT_EQ(s.thruster_names(), (std::vector<std::string>{"+X", "-X"}));
  EXPECT_NEAR(s.problem.thrusters.thruster(0).direction.norm(), 1.0, 1e-15);  // normalised
  EXPECT_DOUBLE_EQ(s.problem.thrusters.thruster(0).direction[0], 1.0);
  // anzel4 angles: theta = 90 deg puts every thruster in the R-T plane: L1 = cos a + sin a.
  j["spacecraft"]["thrusters"] = {{"preset", "anzel4"}, {"theta_deg", 90}, {"alpha_deg", 0}};
  s = Parse(j);
  EXPECT_NEAR(s.problem.thrusters.L1Factor(2) * 4850 / 0.265, 1.0, 1e-12);
}

TEST(ScenarioParser, HorizonExtensions) {
  json j = HcwBase();
  j["horizon"] = {{"start_s", 3600}, {"duration_s", 7200}, {"num_intervals", 12}};
  j["window"]["enforce_from_s"] = 5400;
  const Scenario s = Parse(j);
  EXPECT_DOUBLE_EQ(s.problem.grid.front(), 3600);
  EXPECT_DOUBLE_EQ(s.problem.grid.back(), 10800);
  EXPECT_DOUBLE_EQ(s.step_s, 600);
  EXPECT_DOUBLE_EQ(s.problem.window.enforce_from_s, 5400);
  // enforce_from_s defaults to the horizon start.
  j["window"].erase("enforce_from_s");
  EXPECT_DOUBLE_EQ(Parse(j).problem.window.enforce_from_s, 3600);
}

TEST(ScenarioParser, WindowOperationsObjectiveExtensions) {
  json j = HcwBase();
  j["window"]["soft"] = true;
  j["window"]["soft_penalty"] = 50;
  j["window"]["intersample_points"] = 3;
  j["operations"]["max_burn_s"] = 3600;
  j["operations"]["max_burns_per_thruster"] = 4;
  j["operations"]["allow_burn_across_end"] = true;
  j["objective"] = {{"kind", "delta_v"}, {"burn_start_penalty", 0.001}};
  const Scenario s = Parse(j);
  EXPECT_TRUE(s.problem.window.soft);
  EXPECT_DOUBLE_EQ(s.problem.window.soft_penalty, 50);
  EXPECT_EQ(s.problem.window.intersample_points, 3);
  EXPECT_DOUBLE_EQ(s.problem.rules.max_burn_s, 3600);
  EXPECT_EQ(s.problem.rules.max_burns_per_thruster, 4);
  EXPECT_TRUE(s.problem.rules.allow_burn_across_end);
  EXPECT_EQ(s.problem.objective.kind, transcription::ObjectiveKind::kDeltaV);
  EXPECT_DOUBLE_EQ(s.problem.objective.burn_start_penalty, 0.001);
  // Defaults without the optional sections.
  json d = HcwBase();
  d.erase("operations");
  d.erase("objective");
  d.erase("window");
  d.erase("solver");
  d.erase("discretisation");
  const Scenario e = Parse(d);
  EXPECT_EQ(e.problem.rules.max_simultaneous, 1);
  EXPECT_DOUBLE_EQ(e.problem.rules.min_burn_s, 0);
  EXPECT_TRUE(std::isinf(e.problem.rules.max_burn_s));
  EXPECT_EQ(e.problem.rules.max_burns_per_thruster, -1);
  EXPECT_EQ(e.problem.objective.kind, transcription::ObjectiveKind::kL1);
  EXPECT_FALSE(e.problem.window.enabled());
  EXPECT_TRUE(std::isinf(e.solve.time_limit_s));
  EXPECT_DOUBLE_EQ(e.solve.relative_gap, 1e-4);
  EXPECT_EQ(e.build.discretisation.scheme, dynamics::Scheme::kExactZoh);
}

TEST(ScenarioParser, DiscretisationTranscriptionSolverExtensions) {
  json j = HcwBase();
  j["discretisation"] = {{"scheme", "rk4"}, {"rk4_substeps", 7}, {"reference_tolerance", 1e-10}};
  j["transcription"] = {{"formulation", "condensed"}, {"encoding", "thesis"}, {"scale", false}};
  j["solver"] = {{"time_limit_s", 5},    {"relative_gap", 0.02},       {"threads", 2},
                 {"absolute_gap", 1e-6}, {"random_seed", 42},          {"log_level", 2},
                 {"presolve", false},    {"progress_interval_s", 1.5}, {"max_nodes", 2000}};
  const Scenario s = Parse(j);
  EXPECT_EQ(s.build.discretisation.scheme, dynamics::Scheme::kRk4);
  EXPECT_EQ(s.build.discretisation.rk4_substeps, 7);
  EXPECT_DOUBLE_EQ(s.build.discretisation.reference_tolerance, 1e-10);
  EXPECT_EQ(s.build.formulation, transcription::Formulation::kCondensed);
  EXPECT_EQ(s.build.encoding, transcription::Encoding::kThesis);
  EXPECT_FALSE(s.build.scale);
  EXPECT_DOUBLE_EQ(s.solve.time_limit_s, 5);
  EXPECT_DOUBLE_EQ(s.solve.relative_gap, 0.02);
  EXPECT_EQ(s.solve.threads, 2);
  EXPECT_DOUBLE_EQ(s.solve.absolute_gap, 1e-6);
  EXPECT_EQ(s.solve.random_seed, 42);
  EXPECT_EQ(s.solve.log_level, 2);
  EXPECT_FALSE(s.solve.presolve);
  EXPECT_DOUBLE_EQ(s.solve.progress_interval_s, 1.5);
  EXPECT_EQ(s.solve.max_nodes, 2000);
  EXPECT_EQ(Parse(HcwBase()).solve.max_nodes, -1);  // unlimited unless given
  for (const char* scheme : {"exact_zoh", "frozen_start", "frozen_mid", "hermite_simpson", "rk4",
                             "trapezoid", "euler", "reference"}) {
    j["discretisation"] = {{"scheme", scheme}};
    EXPECT_EQ(dynamics::ToString(Parse(j).build.discretisation.scheme), scheme);
  }
}

TEST(ScenarioParser, SearchRelaxationLpMethod) {
  json j = HcwBase();
  using Method = transcription::RelaxationOptions::LpMethod;
  EXPECT_EQ(Parse(j).search_options.relaxation.lp_method, Method::kInteriorPoint);  // default
  j["solver"]["search"] = {{"relaxation", {{"lp_method", "clp_barrier"}}}};
  EXPECT_EQ(Parse(j).search_options.relaxation.lp_method, Method::kClpBarrier);
  j["solver"]["search"] = {{"relaxation", {{"lp_method", "interior_point"}}}};
  EXPECT_EQ(Parse(j).search_options.relaxation.lp_method, Method::kInteriorPoint);
  j["solver"]["search"] = {{"relaxation", {{"lp_method", "simplex"}}}};
  const std::string m = ErrorOf(j);
  EXPECT_HAS(m, "scenario.solver.search.relaxation.lp_method");
  EXPECT_HAS(m, "simplex");
}

TEST(ScenarioParser, HistoryForcedOffTerminalInputModeCheck) {
  json j = HcwBase();
  j["history"] = {{"-T", {{"on_for_s", 600}}}, {"+R", {{"off_for_s", 900}}}};
  j["forced_off"] = {{{"thruster", "+N"}, {"start_s", 3600}, {"end_s", 7200}}};
  j["terminal"] = {
      {"type", "station_keeping"}, {"facets_out_of_plane", 8},          {"facets_cone_plus", 12},
      {"facets_cone_minus", 10},   {"lookahead_s", {0, 86400, 172800}}, {"margin", 0.1}};
  j["check"] = {{"samples_per_interval", 2},
                {"propagation_tolerance", 1e-9},
                {"window_tolerance", 5},
                {"include_intersample", true}};
  Scenario s = Parse(j);
  ASSERT_EQ(s.problem.history.on_for_s.size(), 6u);
  EXPECT_DOUBLE_EQ(s.problem.history.on_for_s[4], 600);  // -T is index 4
  EXPECT_DOUBLE_EQ(s.problem.history.off_for_s[0], 900);
  EXPECT_TRUE(std::isinf(s.problem.history.off_for_s[1]));
  ASSERT_EQ(s.problem.forced_off.size(), 1u);
  EXPECT_EQ(s.problem.forced_off[0].thruster, 2);
  EXPECT_DOUBLE_EQ(s.problem.forced_off[0].end_s, 7200);
  EXPECT_EQ(s.problem.terminal.kind, transcription::TerminalKind::kStationKeepingSets);
  EXPECT_EQ(s.problem.terminal.facets_out_of_plane, 8);
  EXPECT_EQ(s.problem.terminal.facets_cone_plus, 12);
  EXPECT_EQ(s.problem.terminal.facets_cone_minus, 10);
  EXPECT_EQ(s.problem.terminal.lookahead_s, (std::vector<double>{0, 86400, 172800}));
  EXPECT_DOUBLE_EQ(s.problem.terminal.margin, 0.1);
  EXPECT_EQ(s.check.samples_per_interval, 2);
  EXPECT_DOUBLE_EQ(s.check.propagation_tolerance, 1e-9);
  EXPECT_DOUBLE_EQ(s.verdict.window_tolerance, 5);
  EXPECT_TRUE(s.verdict.include_intersample);

  j = HcwBase();
  j["terminal"] = {{"type", "state_box"},
                   {"hcw_position_m", {1, 2, 3}},
                   {"hcw_velocity_m_s", {0, 0, 0}},
                   {"tolerance", {10, nullptr, 10, 0.1, 0.1, nullptr}}};
  s = Parse(j);
  EXPECT_EQ(s.problem.terminal.kind, transcription::TerminalKind::kStateBox);
  EXPECT_EQ(s.problem.terminal.target, (Eigen::VectorXd(6) << 1, 2, 3, 0, 0, 0).finished());
  EXPECT_TRUE(std::isinf(s.problem.terminal.tolerance[1]));
  EXPECT_DOUBLE_EQ(s.problem.terminal.tolerance[3], 0.1);

  j = HcwBase();
  j.erase("operations");
  j["input_mode"] = "impulsive";
  j["max_impulse_m_s"] = 0.5;
  j["terminal"] = {{"type", "fixed_state"}, {"state", {0, 0, 0, 0, 0, 0}}};
  s = Parse(j);
  EXPECT_TRUE(s.impulsive());
  EXPECT_DOUBLE_EQ(s.problem.max_impulse_m_s, 0.5);
  EXPECT_EQ(s.problem.terminal.kind, transcription::TerminalKind::kFixedState);
  EXPECT_EQ(s.problem.terminal.target, Eigen::VectorXd::Zero(6));

  j = GeoBase();
  j["check"] = {{"nonlinear", false}};
  EXPECT_FALSE(Parse(j).check.nonlinear);
  j["check"] = {{"include_nonlinear", true}};
  EXPECT_TRUE(Parse(j).verdict.include_nonlinear);
  j["description"] = "free text";
  EXPECT_NO_THROW(Parse(j));
}

// ---- rejections: every documented class, message names the field and the value ----

TEST(ScenarioParserRejects, UnknownFieldsAtEveryLevel) {
  json j = HcwBase();
  j["window"]["half_width_mm"] = 36800;
  std::string m = ErrorOf(j);
  EXPECT_HAS(m, "scenario.window.half_width_mm: unknown field");
  j = HcwBase();
  j["colour"] = "red";
  EXPECT_HAS(ErrorOf(j), "scenario.colour: unknown field");
  j = HcwBase();
  j["spacecraft"]["thrusters"]["extra"] = 1;
  EXPECT_HAS(ErrorOf(j), "scenario.spacecraft.thrusters.extra: unknown field");
  j = GeoBase();
  j["window"] = {{"half_width_m", 36800}};  // a Cartesian key on a GEO model
  m = ErrorOf(j);
  EXPECT_HAS(m, "scenario.window");
  EXPECT_HAS(m, "half_width");
  j = HcwBase();
  j["spacecraft"]["thrusters"]["theta_deg"] = 60;  // anzel4-only key on ideal6
  EXPECT_HAS(ErrorOf(j), "scenario.spacecraft.thrusters.theta_deg: unknown field");
}

TEST(ScenarioParserRejects, ExtraSectionsOnlyWhenDeclared) {
  json j = HcwBase();
  j["long_horizon"] = {{"weeks", 52}};
  EXPECT_HAS(ErrorOf(j), "scenario.long_horizon: unknown field");
  ScenarioParseOptions o;
  o.extra_sections = {"long_horizon"};
  const Scenario s = Parse(j, o);
  EXPECT_EQ(s.raw.at("long_horizon").at("weeks"), 52);  // kept for the caller
  j["other"] = 1;
  EXPECT_HAS(ErrorOf(j, o), "scenario.other: unknown field");
}

TEST(ScenarioParserRejects, WrongTypes) {
  json j = HcwBase();
  j["spacecraft"]["mass_kg"] = "4850";
  std::string m = ErrorOf(j);
  EXPECT_HAS(m, "scenario.spacecraft.mass_kg");
  EXPECT_HAS(m, "\"4850\"");
  j = HcwBase();
  j["solver"]["threads"] = true;
  m = ErrorOf(j);
  EXPECT_HAS(m, "scenario.solver.threads");
  EXPECT_HAS(m, "true");
  j = HcwBase();
  j["horizon"] = 86400;
  m = ErrorOf(j);
  EXPECT_HAS(m, "scenario.horizon: expected an object");
  EXPECT_HAS(m, "86400");
  j = HcwBase();
  j["model"]["type"] = 3;
  EXPECT_HAS(ErrorOf(j), "scenario.model.type: expected a string, got number 3");
  j = HcwBase();
  j["solver"]["threads"] = 1.5;
  EXPECT_HAS(ErrorOf(j), "scenario.solver.threads: expected an integer, got 1.5");
  j = HcwBase();
  j["solver"]["max_nodes"] = -1;
  EXPECT_HAS(ErrorOf(j), "scenario.solver.max_nodes");
  EXPECT_HAS(ErrorOf(j), "-1");
  j = HcwBase();
  j["initial_state"]["hcw_position_m"] = {1000, "0", 0};
  EXPECT_HAS(ErrorOf(j), "scenario.initial_state.hcw_position_m[1]: expected a number");
  j = HcwBase();
  j["initial_state"]["hcw_position_m"] = {1000, 0};
  EXPECT_HAS(ErrorOf(j), "scenario.initial_state.hcw_position_m: expected 3 numbers, got 2");
  j = HcwBase();
  j["model"]["type"] = "keplerian";
  m = ErrorOf(j);
  EXPECT_HAS(m, "scenario.model.type");
  EXPECT_HAS(m, "\"keplerian\"");
  j = HcwBase();
  j["discretisation"]["scheme"] = "magic";
  EXPECT_HAS(ErrorOf(j), "scenario.discretisation.scheme: unknown value \"magic\"");
}

TEST(ScenarioParserRejects, MissingRequiredFields) {
  for (const char* key : {"name", "model", "spacecraft", "initial_state", "horizon"}) {
    json j = HcwBase();
    j.erase(key);
    EXPECT_HAS(ErrorOf(j), std::string("scenario.") + key + ": required field is missing");
  }
  json j = HcwBase();
  j["model"].erase("mean_motion_rad_s");
  EXPECT_HAS(ErrorOf(j), "scenario.model.mean_motion_rad_s: required field is missing");
  j = HcwBase();
  j["spacecraft"].erase("thrust_n");
  EXPECT_HAS(ErrorOf(j), "scenario.spacecraft.thrust_n: required field is missing");
  j = HcwBase();
  j["horizon"].erase("step_s");
  EXPECT_HAS(ErrorOf(j), "scenario.horizon: one of step_s, num_intervals is required");
  j = HcwBase();
  j["initial_state"] = json::object();
  EXPECT_HAS(ErrorOf(j), "scenario.initial_state: one of hcw_position_m, state is required");
  j = GeoBase();
  j["model"].erase("epoch");
  EXPECT_HAS(ErrorOf(j), "scenario.model.epoch: required field is missing");
}

TEST(ScenarioParserRejects, NonPositiveDurationsAndWidths) {
  const std::vector<std::pair<std::vector<std::string>, double>> cases = {
      {{"horizon", "duration_s"}, -86400},  {{"horizon", "duration_s"}, 0},
      {{"horizon", "step_s"}, 0},           {{"horizon", "step_s"}, -300},
      {{"window", "half_width_m"}, 0},      {{"window", "half_width_m"}, -1},
      {{"spacecraft", "mass_kg"}, 0},       {{"spacecraft", "thrust_n"}, -0.265},
      {{"spacecraft", "isp_s"}, 0},         {{"model", "mean_motion_rad_s"}, 0},
      {{"operations", "min_burn_s"}, -300}, {{"solver", "time_limit_s"}, 0},
  };
  for (const auto& [path, value] : cases) {
    json j = HcwBase();
    j[path[0]][path[1]] = value;
    const std::string m = ErrorOf(j);
    EXPECT_HAS(m, "scenario." + path[0] + "." + path[1] + ": must be");
    EXPECT_HAS(m, "got " + FormatNumber(value));
  }
  json g = GeoBase();
  g["window"]["half_width_deg"] = 0;
  EXPECT_HAS(ErrorOf(g), "scenario.window.half_width_deg: must be > 0, got 0");
}

TEST(ScenarioParserRejects, StepThatDoesNotDivideTheHorizon) {
  json j = HcwBase();
  j["horizon"]["step_s"] = 700;
  const std::string m = ErrorOf(j);
  EXPECT_HAS(m, "scenario.horizon.step_s: 700 s does not divide the horizon duration 259200 s");
  j["horizon"]["step_s"] = 300000;
  EXPECT_HAS(ErrorOf(j), "scenario.horizon.step_s: 300000 s is longer than the horizon");
  j["horizon"] = {{"duration_s", 1e9}, {"step_s", 1}};
  EXPECT_HAS(ErrorOf(j), "intervals; at most 100000");
}

TEST(ScenarioParserRejects, NonFiniteNumbers) {
  json j = HcwBase();
  j["spacecraft"]["mass_kg"] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_HAS(ErrorOf(j), "scenario.spacecraft.mass_kg: must be finite, got NaN");
  j = HcwBase();
  j["initial_state"]["hcw_position_m"][0] = std::numeric_limits<double>::infinity();
  EXPECT_HAS(ErrorOf(j), "scenario.initial_state.hcw_position_m[0]: must be finite, got inf");
  // In text: JSON has no NaN literal, and an overflowing number is rejected.
  std::string text = HcwBase().dump();
  std::string t1 = text;
  t1.replace(t1.find("4850"), 4, "NaN");
  EXPECT_HAS(TextErrorOf(t1), "not valid JSON");
  std::string t2 = text;
  t2.replace(t2.find("4850"), 4, "1e999");
  // The field and the literal are both named.
  EXPECT_HAS(TextErrorOf(t2), "not valid JSON at scenario.spacecraft.mass_kg");
  EXPECT_HAS(TextErrorOf(t2), "1e999");
  std::string t3 = text;
  t3.replace(t3.find("[1000"), 5, "[-1e400");
  EXPECT_HAS(TextErrorOf(t3), "at scenario.initial_state.hcw_position_m[0]");
}

TEST(ScenarioParserRejects, EmptyThrusterSets) {
  json j = HcwBase();
  j["spacecraft"]["thrusters"]["use"] = json::array();
  EXPECT_HAS(ErrorOf(j), "scenario.spacecraft.thrusters.use: selects no thruster");
  j = HcwBase();
  j["spacecraft"]["thrusters"] = {{"custom", json::array()}};
  EXPECT_HAS(ErrorOf(j), "scenario.spacecraft.thrusters.custom: is empty");
  j = GeoBase();
  j["spacecraft"]["disabled"] = {"NE", "SE", "NW", "SW"};
  EXPECT_HAS(ErrorOf(j), "scenario.spacecraft.disabled: disables every thruster (NE, SE, NW, SW)");
  j = GeoBase();
  j["spacecraft"]["disabled"] = {"XX"};
  EXPECT_HAS(ErrorOf(j), "scenario.spacecraft.disabled[0]: \"XX\" is not a thruster");
  j = HcwBase();
  j["spacecraft"]["thrusters"] = json::object();
  EXPECT_HAS(ErrorOf(j), "scenario.spacecraft.thrusters: one of preset, custom is required");
  j = HcwBase();
  j["spacecraft"]["thrusters"] = {{"custom", {{{"name", "a b"}, {"direction_rtn", {1, 0, 0}}}}}};
  EXPECT_HAS(ErrorOf(j), "scenario.spacecraft.thrusters.custom[0].name: \"a b\"");
  j["spacecraft"]["thrusters"] = {{"custom", {{{"name", "Z"}, {"direction_rtn", {0, 0, 0}}}}}};
  EXPECT_HAS(ErrorOf(j),
             "scenario.spacecraft.thrusters.custom[0].direction_rtn: must not be the zero");
}

TEST(ScenarioParserRejects, BrokenJsonAndDuplicateKeys) {
  EXPECT_HAS(TextErrorOf("{\"name\": \"x\", "), "not valid JSON");
  EXPECT_HAS(TextErrorOf(""), "not valid JSON");
  std::string text = HcwBase().dump();
  text.insert(1, "\"name\": \"first\", ");
  EXPECT_HAS(TextErrorOf(text), "scenario.name: duplicate key");
  std::string nested = R"({"name":"x","model":{"type":"hcw","type":"geo"}})";
  EXPECT_HAS(TextErrorOf(nested), "scenario.model.type: duplicate key");
  EXPECT_HAS(TextErrorOf("[1, 2]"), "scenario: expected an object");
}

TEST(ScenarioParserRejects, ModelSpecificAndModeSpecificErrors) {
  json j = GeoBase();
  j["initial_state"] = {{"station_point", false}};
  EXPECT_HAS(ErrorOf(j), "scenario.initial_state.station_point: must be true");
  j = GeoBase();
  j["initial_state"] = {{"station_point", true}, {"state", {0, 0, 0, 0, 0, 0}}};
  EXPECT_HAS(ErrorOf(j), "scenario.initial_state: give only one of");
  j = GeoBase();
  j["model"]["epoch"] = "2034-13-01";
  EXPECT_HAS(ErrorOf(j), "scenario.model.epoch");
  j = GeoBase();
  j["model"]["perturbations"] = {"j2", "drag"};
  EXPECT_HAS(ErrorOf(j), "scenario.model.perturbations[1]: unknown perturbation \"drag\"");
  j = GeoBase();
  j["model"]["station_longitude_deg"] = 400;
  EXPECT_HAS(ErrorOf(j), "scenario.model.station_longitude_deg: must be in [-180, 360], got 400");
  j = HcwBase();
  j["input_mode"] = "impulsive";
  EXPECT_HAS(ErrorOf(j), "scenario.operations: is not used with \"input_mode\": \"impulsive\"");
  j = HcwBase();
  j["max_impulse_m_s"] = 1;  // only with impulsive
  EXPECT_HAS(ErrorOf(j), "scenario.max_impulse_m_s: unknown field");
  j = HcwBase();
  j["history"] = {{"NE", {{"on_for_s", 60}}}};
  EXPECT_HAS(ErrorOf(j), "scenario.history.NE: \"NE\" is not a thruster");
  j = HcwBase();
  j["forced_off"] = {{{"thruster", "+R"}, {"start_s", 100}, {"end_s", 50}}};
  EXPECT_HAS(ErrorOf(j), "scenario.forced_off[0].end_s: must be after start_s (100 s), got 50 s");
  j = HcwBase();
  j["window"]["enforce_from_s"] = 1e6;
  EXPECT_HAS(ErrorOf(j), "scenario.window.enforce_from_s: 1000000 s is after the horizon end");
  j = HcwBase();
  j["window"]["soft_penalty"] = 10;  // without soft
  EXPECT_HAS(ErrorOf(j), "scenario.window.soft_penalty: is only used with");
  j = HcwBase();
  j["operations"]["max_burn_s"] = 100;  // < min_burn_s
  EXPECT_HAS(ErrorOf(j), "scenario.operations.max_burn_s: 100 s is shorter than min_burn_s 300 s");
  j = HcwBase();
  j.erase("window");
  j["terminal"] = {{"type", "station_keeping"}};
  EXPECT_HAS(ErrorOf(j), "scenario.terminal.type: \"station_keeping\" needs a window section");
  j = HcwBase();
  j["terminal"] = {{"type", "state_box"}, {"state", {0, 0, 0, 0, 0, 0}}, {"tolerance", {1, 2}}};
  EXPECT_HAS(ErrorOf(j), "scenario.terminal.tolerance: expected an array of 6 numbers");
  j = HcwBase();
  j["check"] = {{"nonlinear", true}};  // GEO only
  EXPECT_HAS(ErrorOf(j), "scenario.check.nonlinear: unknown field");
  j = HcwBase();
  j["model"]["type"] = "yamanaka_ankersen";
  j["model"].erase("mean_motion_rad_s");
  j["model"]["semi_major_axis_m"] = 7e6;
  j["model"]["eccentricity"] = 1.2;
  EXPECT_HAS(ErrorOf(j), "scenario.model.eccentricity: must be in [0, 0.99], got 1.2");
}

TEST(ScenarioParserRejects, OverridesNameTheOption) {
  Scenario s = Parse(HcwBase());
  auto error_of = [&](const ScenarioOverrides& o) {
    try {
      ApplyOverrides(o, &s);
    } catch (const ScenarioError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  ScenarioOverrides o;
  o.relative_gap = -1;
  EXPECT_HAS(error_of(o), "--gap: must be finite and >= 0, got -1");
  o = {};
  o.time_limit_s = 0;
  EXPECT_HAS(error_of(o), "--time-limit: must be > 0, got 0");
  o = {};
  o.threads = 0;
  EXPECT_HAS(error_of(o), "--threads: must be in [1, 64], got 0");
  o = {};
  o.scheme = "bogus";
  EXPECT_HAS(error_of(o), "--scheme");
  o = {};
  o.formulation = "dense";
  EXPECT_HAS(error_of(o), "--formulation");
  o = {};
  o.encoding = "loose";
  EXPECT_HAS(error_of(o), "--encoding");
  // Valid overrides win over the scenario.
  o = {};
  o.time_limit_s = 7;
  o.relative_gap = 0.5;
  o.threads = 2;
  o.scheme = "euler";
  o.formulation = "condensed";
  o.encoding = "thesis";
  ApplyOverrides(o, &s);
  EXPECT_DOUBLE_EQ(s.solve.time_limit_s, 7);
  EXPECT_DOUBLE_EQ(s.solve.relative_gap, 0.5);
  EXPECT_EQ(s.solve.threads, 2);
  EXPECT_EQ(s.build.discretisation.scheme, dynamics::Scheme::kEuler);
  EXPECT_EQ(s.build.formulation, transcription::Formulation::kCondensed);
  EXPECT_EQ(s.build.encoding, transcription::Encoding::kThesis);
}

TEST(ScenarioParserRejects, UnreadableFile) {
  try {
    LoadScenario("/nonexistent/scenario.json");
    FAIL() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_HAS(e.what(), "/nonexistent/scenario.json: cannot open");
  }
}

// Every scenario shipped in data/scenarios and tests/app/data parses.
TEST(ScenarioFiles, AllShippedScenariosParse) {
  int count = 0;
  for (const char* dir : {THRUSTSCHED_DATA_DIR "/scenarios", THRUSTSCHED_APP_TEST_DATA}) {
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.path().extension() != ".json") continue;
      SCOPED_TRACE(entry.path().string());
      const Scenario s = LoadScenario(entry.path().string());
      EXPECT_EQ(s.path, entry.path().string());
      EXPECT_EQ(s.name + ".json", entry.path().filename().string());
      ++count;
    }
  }
  EXPECT_GE(count, 27);
}

TEST(ScenarioOptionsIsValid, VerdictOptionsNamesTheWindowTolerance) {
  VerdictOptions o;
  std::string e;
  EXPECT_TRUE(o.IsValid(&e));
  o.window_tolerance = -0.5;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "window_tolerance must be finite and >= 0, got -0.5");
  o.window_tolerance = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(o.IsValid(nullptr));
}

TEST(ScenarioOptionsIsValid, ParseOptionsRefuseABuiltInOrEmptySection) {
  ScenarioParseOptions o;
  std::string e;
  EXPECT_TRUE(o.IsValid(&e));
  o.extra_sections = {"long_horizon", "window"};
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "extra_sections[1] \"window\" is a section the scenario parser reads itself");
  o.extra_sections = {""};
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "extra_sections[0] must not be empty");
  o.extra_sections.clear();
  o.source.clear();
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "source must not be empty");
  // The parser refuses such options before it reads the scenario.
  ScenarioParseOptions bad;
  bad.extra_sections = {"model"};
  try {
    ParseScenario(HcwBase(), bad);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& ex) {
    EXPECT_NE(std::string(ex.what()).find("ScenarioParseOptions: extra_sections[0] \"model\""),
              std::string::npos)
        << ex.what();
  }
}

TEST(ScenarioOptionsIsValid, ConjunctionSolveAndVerificationValuesNameTheirField) {
  const json base = json::parse(std::ifstream(std::string(THRUSTSCHED_SOURCE_DIR) +
                                              "/data/scenarios/serra_avoidance_ex1.json"));
  json j = base;
  j["conjunction"]["solve"]["restart_ratio"] = 1.5;
  try {
    ParseScenario(j);
    FAIL() << "no exception";
  } catch (const ScenarioError& ex) {
    EXPECT_NE(std::string(ex.what()).find("restart_ratio"), std::string::npos) << ex.what();
    EXPECT_NE(std::string(ex.what()).find("1.5"), std::string::npos) << ex.what();
  }
  EXPECT_NO_THROW(ParseScenario(base));
}

}  // namespace
}  // namespace thrustsched::app

namespace thrustsched::app {
namespace {

// A document nested deeper than any scenario is refused as bad input naming
// where, before anything could recurse that deep (the fuzzer's stack
// overflow at 5000 levels); 64 levels are still read.
TEST(ScenarioJson, NestingDeeperThan64LevelsIsBadInput) {
  const auto nested = [](int levels) {
    return std::string(static_cast<size_t>(levels), '[') + "1" +
           std::string(static_cast<size_t>(levels), ']');
  };
  EXPECT_NO_THROW(ParseJsonText(nested(64), "doc.json"));
  try {
    ParseJsonText(nested(5000), "doc.json");
    FAIL() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("doc.json: nested deeper than 64 levels at scenario[0]"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace thrustsched::app
