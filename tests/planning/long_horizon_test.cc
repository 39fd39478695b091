// One file on purpose, ~900 lines: the cases below share the short GEO
// fixture and its independent references, whose set-up is most of the file.
// LongHorizonSimulation (chained cycles, nonlinear hand-over) on short GEO
// cycles (1 day at a 10-min step, the thesis rules 5 / 20 / 5 min) so that the
// whole file runs in seconds. References are independent of the driver: the
// nonlinear simulator called directly on the applied burns, the continuous-time
// rule checker on the concatenated burns of all cycles, closed forms of the
// thruster geometry, and a second run (resume = uninterrupted).
#include "planning/long_horizon.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/geo_model.h"
#include "dynamics/geo_simulator.h"
#include "dynamics/models.h"
#include "milp/cbc_solver.h"
#include "milp/model.h"
#include "transcription/checker.h"

namespace thrustsched::planning {
namespace {

// The one-MILP vocabulary (transcription/) the loop is tested with.
using namespace thrustsched::transcription;  // NOLINT(build/namespaces)

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kDay = 86400.0;
constexpr double kInf = std::numeric_limits<double>::infinity();

const dynamics::GeoModelOptions& Geo() {
  static const dynamics::GeoModelOptions g;  // 118 E, 2034-01-01, full model
  return g;
}

std::shared_ptr<const dynamics::GeoLinearModel> Model() {
  static const auto m = std::make_shared<const dynamics::GeoLinearModel>(Geo());
  return m;
}

std::shared_ptr<const dynamics::GeoSimulator> Simulator() {
  static const auto s = std::make_shared<const dynamics::GeoSimulator>(Geo());
  return s;
}

std::shared_ptr<const milp::Solver> Solver() {
  static const std::shared_ptr<const milp::Solver> s(milp::MakeCbcSolver().release());
  return s;
}

// A start whose latitude oscillation (amplitude 2|i| = 0.0525 deg) exceeds
// the 0.05 deg window 6 h after t0 (Omega chosen so that lat = 0 and rising
// at t0): the first cycle must fire North/South thrusters near t0.
Eigen::VectorXd InclinedStart() {
  const double kappa0 = Geo().station_longitude_deg * kDeg + Model()->EarthRotationAngle(0.0);
  const double i = 0.5 * 0.0525 * kDeg;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(6);
  x(3) = i * std::cos(kappa0);
  x(4) = i * std::sin(kappa0);
  return x;
}

ScheduleProblem Base(const std::string& preset = "anzel4") {
  ScheduleProblem p;
  p.model = Model();
  p.thrusters = dynamics::ThrusterSet::FromPreset(preset, 0.265, 4850, 2005);
  p.initial_state = InclinedStart();
  p.rules.min_burn_s = 300;
  p.rules.min_off_same_s = 1200;
  p.rules.min_gap_other_s = 300;
  const double w = 0.05 * kDeg;
  p.window.outputs = {1, 2};
  p.window.half_widths = {w, w};
  return p;
}

LongHorizonOptions DailyCycles(int days) {
  LongHorizonOptions o;
  o.duration_s = days * kDay;
  o.cycle_s = kDay;
  o.step_s = 600;
  o.terminal.kind = TerminalKind::kStationKeepingSets;
  o.solve.build.discretisation.scheme = dynamics::Scheme::kHermiteSimpson;
  o.solve.milp.time_limit_s = 60;
  o.solve.milp.relative_gap = 1e-6;
  o.solve.milp.threads = 1;
  o.solve.check.samples_per_interval = 1;
  return o;
}

std::vector<CycleRecord> RunAll(const LongHorizonSimulation& run, LongHorizonState* state) {
  std::vector<CycleRecord> out;
  while (state->next_cycle < run.num_cycles()) out.push_back(run.RunCycle(state));
  return out;
}

std::vector<Burn> AllBurns(const std::vector<CycleRecord>& cycles) {
  std::vector<Burn> b;
  for (const CycleRecord& c : cycles) b.insert(b.end(), c.burns.begin(), c.burns.end());
  return b;
}

// ---------------------------------------------------------------------------

TEST(LongHorizonGeometry, OppositeThrustersAreThesisPairs) {
  const auto anzel = dynamics::ThrusterSet::Anzel4(0.265, 4850, 2005);  // NE, SE, NW, SW
  EXPECT_EQ(OppositeThruster(anzel, anzel.IndexOf("NE")), anzel.IndexOf("SW"));
  EXPECT_EQ(OppositeThruster(anzel, anzel.IndexOf("SW")), anzel.IndexOf("NE"));
  EXPECT_EQ(OppositeThruster(anzel, anzel.IndexOf("SE")), anzel.IndexOf("NW"));
  EXPECT_EQ(OppositeThruster(anzel, anzel.IndexOf("NW")), anzel.IndexOf("SE"));
  const auto ideal = dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005);
  EXPECT_EQ(OppositeThruster(ideal, ideal.IndexOf("+R")), ideal.IndexOf("-R"));
  EXPECT_EQ(OppositeThruster(ideal, ideal.IndexOf("+T")), ideal.IndexOf("-T"));
  EXPECT_EQ(OppositeThruster(ideal, ideal.IndexOf("-N")), ideal.IndexOf("+N"));
  EXPECT_THROW(OppositeThruster(anzel, 4), std::invalid_argument);
  const dynamics::ThrusterSet lonely(
      {{"A", Eigen::Vector3d(0, 1, 0)}, {"B", Eigen::Vector3d(0, 0, 1)}}, 0.1, 1000, 300);
  EXPECT_THROW(OppositeThruster(lonely, 0), std::invalid_argument);
}

TEST(LongHorizonGeometry, FacesFollowThesisTable57) {
  const auto anzel = dynamics::ThrusterSet::Anzel4(0.265, 4850, 2005);
  auto faces = [&](const char* n) { return FacesOf(anzel.thruster(anzel.IndexOf(n))); };
  // Table 5.7: North = NE + NO, South = SE + SO, East = NE + SE, West = NO + SO.
  EXPECT_TRUE(faces("NE").north && faces("NE").east && !faces("NE").south && !faces("NE").west);
  EXPECT_TRUE(faces("NW").north && faces("NW").west && !faces("NW").south && !faces("NW").east);
  EXPECT_TRUE(faces("SE").south && faces("SE").east && !faces("SE").north && !faces("SE").west);
  EXPECT_TRUE(faces("SW").south && faces("SW").west && !faces("SW").north && !faces("SW").east);
  const auto ideal = dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005);
  const ThrusterFaces r = FacesOf(ideal.thruster(ideal.IndexOf("+R")));
  EXPECT_FALSE(r.north || r.south || r.east || r.west);
  EXPECT_TRUE(FacesOf(ideal.thruster(ideal.IndexOf("-N"))).north);
  EXPECT_TRUE(FacesOf(ideal.thruster(ideal.IndexOf("+T"))).west);
}

TEST(LongHorizonGeometry, ControllabilityCriterion) {
  const auto anzel = dynamics::ThrusterSet::Anzel4(0.265, 4850, 2005);  // NE, SE, NW, SW
  EXPECT_TRUE(CheckControllability(anzel, {true, true, true, true}).controllable);
  // Thesis 5.3.7: two opposite thrusters off (NE + SW) stays controllable ...
  EXPECT_TRUE(CheckControllability(anzel, {false, true, true, false}).controllable);
  EXPECT_TRUE(CheckControllability(anzel, {true, false, false, true}).controllable);
  // ... two non-opposite ones off loses station keeping.
  const Controllability north_lost = CheckControllability(anzel, {false, true, false, true});
  EXPECT_FALSE(north_lost.controllable);
  EXPECT_EQ(north_lost.reason,
            "uncontrollable: no available thruster pushes south (-N); available: SE, SW");
  const Controllability east_lost = CheckControllability(anzel, {false, false, true, true});
  EXPECT_FALSE(east_lost.controllable);
  EXPECT_NE(east_lost.reason.find("west (-T)"), std::string::npos);
  const auto ideal = dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005);  // +R +T +N -R -T -N
  EXPECT_TRUE(CheckControllability(ideal, {false, true, true, false, true, true}).controllable);
  EXPECT_FALSE(CheckControllability(ideal, {true, true, true, true, true, false}).controllable);
  EXPECT_THROW(CheckControllability(anzel, {true, true}), std::invalid_argument);
}

TEST(LongHorizonStats, DistributionNearestRank) {
  const Distribution d = Distribute({5, 1, 4, 2, 3, 6, 7, 8, 9, 10, std::nan("")});
  EXPECT_EQ(d.count, 10);
  EXPECT_DOUBLE_EQ(d.median, 5.5);
  EXPECT_DOUBLE_EQ(d.p90, 9.0);  // rank ceil(0.9 * 10) = 9
  EXPECT_DOUBLE_EQ(d.max, 10.0);
  EXPECT_DOUBLE_EQ(d.mean, 5.5);
  const Distribution one = Distribute({3.0});
  EXPECT_DOUBLE_EQ(one.median, 3.0);
  EXPECT_DOUBLE_EQ(one.p90, 3.0);
  EXPECT_EQ(Distribute({}).count, 0);
  EXPECT_TRUE(std::isnan(Distribute({}).median));
}

TEST(LongHorizonStats, SummaryThrustDaysSplitAndNormalDeltaV) {
  const auto anzel = dynamics::ThrusterSet::Anzel4(0.265, 4850, 2005);  // NE, SE, NW, SW
  CycleRecord a, b;
  a.start_s = 0;
  a.applied_end_s = 7 * kDay;
  a.on_time_s = {1 * kDay, 2 * kDay, 0, 0};
  a.consumption_l1_m_s = 1.0;
  a.solve_seconds = 10;
  a.gap = 0.01;
  a.status = milp::SolveStatus::kOptimal;
  b.start_s = 7 * kDay;
  b.applied_end_s = 14 * kDay;
  b.on_time_s = {0, 0, 4 * kDay, 8 * kDay};
  b.consumption_l1_m_s = 2.0;
  b.solve_seconds = 30;
  b.gap = 0.03;
  b.fallback = Fallback::kSoftWindow;
  b.status = milp::SolveStatus::kFeasible;
  b.time_outside_window_s = 60;
  b.max_window_violation_deg = 0.001;
  b.worst_time_s = 8 * kDay;
  const LongHorizonSummary s = Summarize({a, b}, anzel);
  EXPECT_EQ(s.cycles, 2);
  EXPECT_DOUBLE_EQ(s.simulated_s, 14 * kDay);
  EXPECT_DOUBLE_EQ(s.consumption_l1_m_s, 3.0);
  ASSERT_EQ(s.thrust_days.size(), 4u);
  EXPECT_DOUBLE_EQ(s.thrust_days[2], 4.0);
  EXPECT_DOUBLE_EQ(s.north_days, 1 + 4);  // NE + NW
  EXPECT_DOUBLE_EQ(s.south_days, 2 + 8);  // SE + SW
  EXPECT_DOUBLE_EQ(s.east_days, 1 + 2);   // NE + SE
  EXPECT_DOUBLE_EQ(s.west_days, 4 + 8);   // NW + SW
  EXPECT_EQ(s.fallback_soft_window, 1);
  EXPECT_EQ(s.time_limited_cycles, 1);
  EXPECT_DOUBLE_EQ(s.time_outside_window_s, 60);
  EXPECT_DOUBLE_EQ(s.worst_time_s, 8 * kDay);
  EXPECT_DOUBLE_EQ(s.solve_seconds.median, 20);
  EXPECT_DOUBLE_EQ(s.gap.max, 0.03);
}

TEST(LongHorizonOptionsTest, ValidationNamesTheField) {
  std::string err;
  LongHorizonOptions o = DailyCycles(3);
  EXPECT_TRUE(o.IsValid(&err)) << err;
  EXPECT_EQ(o.num_cycles(), 3);
  o.step_s = 700;
  EXPECT_FALSE(o.IsValid(&err));
  EXPECT_NE(err.find("step_s"), std::string::npos) << err;
  EXPECT_EQ(o.num_cycles(), 0);
  o = DailyCycles(3);
  o.mode = HorizonMode::kReceding;
  o.control_s = kDay;
  EXPECT_FALSE(o.IsValid(&err));
  EXPECT_NE(err.find("control_s"), std::string::npos) << err;
  o.control_s = 0.5 * kDay;
  EXPECT_TRUE(o.IsValid(&err)) << err;
  EXPECT_EQ(o.num_cycles(), 6);
  o.duration_s = -1;
  EXPECT_FALSE(o.IsValid(&err));
  EXPECT_NE(err.find("duration_s"), std::string::npos) << err;
  o = DailyCycles(3);
  o.solve.check.nonlinear = Simulator();
  EXPECT_FALSE(o.IsValid(&err));
  EXPECT_NE(err.find("nonlinear"), std::string::npos) << err;
  o = DailyCycles(3);
  o.outages.push_back({0, 5.0, 5.0});
  EXPECT_FALSE(o.IsValid(&err));
  EXPECT_NE(err.find("outages[0]"), std::string::npos) << err;
  o = DailyCycles(3);
  o.replay_samples_per_step = 0;
  EXPECT_FALSE(o.IsValid(&err));
  EXPECT_EQ(ParseHorizonMode("receding"), HorizonMode::kReceding);
  EXPECT_THROW(ParseHorizonMode("sliding"), std::invalid_argument);
  EXPECT_EQ(ParseFallback("soft_window_free_terminal"), Fallback::kSoftWindowFreeTerminal);
  EXPECT_THROW(ParseFallback("panic"), std::invalid_argument);
}

TEST(LongHorizonOptionsTest, ConstructorRejectsBadInput) {
  EXPECT_NO_THROW(LongHorizonSimulation(Base(), DailyCycles(2), Simulator(), Solver()));
  LongHorizonOptions bad = DailyCycles(2);
  bad.cycle_s = 0;
  EXPECT_THROW(LongHorizonSimulation(Base(), bad, Simulator(), Solver()), std::invalid_argument);
  ScheduleProblem hcw = Base();
  hcw.model = std::make_shared<dynamics::HcwModel>(7.2921159e-5);
  EXPECT_THROW(LongHorizonSimulation(hcw, DailyCycles(2), Simulator(), Solver()),
               std::invalid_argument);
  dynamics::GeoModelOptions other = Geo();
  other.station_longitude_deg = 119;
  EXPECT_THROW(LongHorizonSimulation(Base(), DailyCycles(2),
                                     std::make_shared<dynamics::GeoSimulator>(other), Solver()),
               std::invalid_argument);
  EXPECT_THROW(LongHorizonSimulation(Base(), DailyCycles(2), nullptr, Solver()),
               std::invalid_argument);
  EXPECT_THROW(LongHorizonSimulation(Base(), DailyCycles(2), Simulator(), nullptr),
               std::invalid_argument);
  ScheduleProblem on = Base();
  on.history = BoundaryHistory::AllOff(4);
  on.history.on_for_s[1] = 600;
  EXPECT_THROW(LongHorizonSimulation(on, DailyCycles(2), Simulator(), Solver()),
               std::invalid_argument);
  LongHorizonOptions out = DailyCycles(2);
  out.outages.push_back({7, 0.0, kInf});
  EXPECT_THROW(LongHorizonSimulation(Base(), out, Simulator(), Solver()), std::invalid_argument);
  ScheduleProblem impulsive = Base();
  impulsive.input_mode = InputMode::kImpulsive;
  EXPECT_THROW(LongHorizonSimulation(impulsive, DailyCycles(2), Simulator(), Solver()),
               std::invalid_argument);
  ScheduleProblem no_window = Base();
  no_window.window = WindowSpec{};
  EXPECT_THROW(LongHorizonSimulation(no_window, DailyCycles(2), Simulator(), Solver()),
               std::invalid_argument);
  LongHorizonOptions bad_term = DailyCycles(2);
  bad_term.terminal.facets_out_of_plane = 2;
  EXPECT_THROW(LongHorizonSimulation(Base(), bad_term, Simulator(), Solver()),
               std::invalid_argument);

  const LongHorizonSimulation run(Base(), DailyCycles(2), Simulator(), Solver());
  EXPECT_THROW(run.Times(2), std::out_of_range);
  EXPECT_THROW(run.Times(-1), std::out_of_range);
  LongHorizonState s = run.InitialState();
  s.time_s += 600;
  EXPECT_THROW(run.CycleProblem(s), std::invalid_argument);
  EXPECT_THROW(run.RunCycle(&s), std::invalid_argument);
  s = run.InitialState();
  s.last_burn_end_s.pop_back();
  EXPECT_THROW(run.CycleProblem(s), std::invalid_argument);
  s = run.InitialState();
  s.next_cycle = 2;
  EXPECT_THROW(run.CycleProblem(s), std::invalid_argument);
  s = run.InitialState();
  s.last_burn_end_s[0] = 600;  // after the cycle start
  EXPECT_THROW(run.CycleProblem(s), std::invalid_argument);
}

TEST(LongHorizonTimes, FixedAndRecedingCycles) {
  LongHorizonOptions o = DailyCycles(3);
  o.duration_s = 2.5 * kDay;  // the last fixed cycle is shortened
  const LongHorizonSimulation fixed(Base(), o, Simulator(), Solver());
  ASSERT_EQ(fixed.num_cycles(), 3);
  EXPECT_DOUBLE_EQ(fixed.Times(1).start_s, kDay);
  EXPECT_DOUBLE_EQ(fixed.Times(1).prediction_end_s, 2 * kDay);
  EXPECT_DOUBLE_EQ(fixed.Times(2).applied_end_s, 2.5 * kDay);
  EXPECT_DOUBLE_EQ(fixed.Times(2).prediction_end_s, 2.5 * kDay);
  o.mode = HorizonMode::kReceding;
  o.control_s = 0.5 * kDay;
  const LongHorizonSimulation receding(Base(), o, Simulator(), Solver());
  ASSERT_EQ(receding.num_cycles(), 5);
  EXPECT_DOUBLE_EQ(receding.Times(3).start_s, 1.5 * kDay);
  EXPECT_DOUBLE_EQ(receding.Times(3).applied_end_s, 2 * kDay);
  EXPECT_DOUBLE_EQ(receding.Times(3).prediction_end_s, 2.5 * kDay);
  EXPECT_DOUBLE_EQ(receding.Times(4).applied_end_s, 2.5 * kDay);
  EXPECT_DOUBLE_EQ(receding.Times(4).prediction_end_s, 3 * kDay);
  // Receding drops the terminal sets (thesis 5.4), fixed keeps them.
  EXPECT_EQ(receding.CycleProblem(receding.InitialState()).terminal.kind, TerminalKind::kFree);
  EXPECT_EQ(fixed.CycleProblem(fixed.InitialState()).terminal.kind,
            TerminalKind::kStationKeepingSets);
}

// The hand-over invariants of a 3-cycle fixed-horizon run.
TEST(LongHorizonRun, HandOverInvariants) {
  const ScheduleProblem base = Base();
  const LongHorizonSimulation run(base, DailyCycles(3), Simulator(), Solver());
  LongHorizonState state = run.InitialState();
  const dynamics::Vector6d eci0 = state.eci;
  const std::vector<CycleRecord> cycles = RunAll(run, &state);
  ASSERT_EQ(cycles.size(), 3u);
  EXPECT_EQ(state.next_cycle, 3);
  EXPECT_DOUBLE_EQ(state.time_s, 3 * kDay);

  // The first cycle must act (the latitude amplitude exceeds the window).
  EXPECT_FALSE(cycles[0].burns.empty());
  EXPECT_EQ(cycles[0].eci_start, eci0);
  for (size_t k = 0; k < cycles.size(); ++k) {
    const CycleRecord& c = cycles[k];
    SCOPED_TRACE("cycle " + std::to_string(k));
    EXPECT_EQ(c.fallback, Fallback::kNone);
    EXPECT_EQ(c.status, milp::SolveStatus::kOptimal);
    EXPECT_TRUE(c.controllable);
    EXPECT_TRUE(c.checked);
    EXPECT_TRUE(c.rules_ok);
    // Independent replay: the simulator called directly on the applied
    // burns from the recorded start state reproduces the recorded end.
    std::vector<dynamics::InputPulse> pulses;
    for (const Burn& b : c.burns) pulses.push_back({b.thruster, b.start_s, b.end_s});
    const dynamics::Vector6d end = Simulator()->Propagate(
        c.eci_start, c.start_s, base.thrusters.AccelerationMatrix(), pulses, {c.applied_end_s})[0];
    EXPECT_LT((end.head<3>() - c.eci_end.head<3>()).norm(), 1e-3);
    // The initial state of the MILP is the true state's relative state.
    EXPECT_LT((c.initial_state - Simulator()->RelativeFromEci(c.eci_start, c.start_s)).norm(),
              1e-15);
    // Nonlinear replay inside the box (the linear plan holds it, the model
    // error over a day is tiny).
    EXPECT_EQ(c.max_window_violation_deg, 0.0);
    EXPECT_EQ(c.time_outside_window_s, 0.0);
    EXPECT_LT(c.max_abs_lat_deg, 0.05);
    EXPECT_LT(c.prediction_error_deg, 1e-3);
    // Totals of the applied burns.
    double on = 0;
    for (const Burn& b : c.burns) on += b.duration_s();
    EXPECT_NEAR(c.delta_v_m_s, base.thrusters.acceleration() * on, 1e-12);
    EXPECT_NEAR(c.consumption_l1_m_s, base.thrusters.L1Factor(0) * on, 1e-12);
    // Anzel: every burn has the normal component cos(theta) of the acceleration.
    EXPECT_NEAR(c.normal_delta_v_m_s, base.thrusters.acceleration() * std::cos(63.64 * kDeg) * on,
                1e-12);
    for (const Burn& b : c.burns) {
      EXPECT_GE(b.start_s, c.start_s - 1e-9);
      EXPECT_LE(b.end_s, c.applied_end_s + 1e-9);  // fixed mode: every burn ends in its cycle
    }
    if (k + 1 < cycles.size()) {
      // State continuity: bitwise equal ECI states, equal relative states.
      EXPECT_EQ(cycles[k + 1].eci_start, c.eci_end);
      EXPECT_DOUBLE_EQ(cycles[k + 1].start_s, c.applied_end_s);
      EXPECT_EQ((cycles[k + 1].initial_state - c.final_state).norm(), 0.0);
    }
  }
  // The operational rules hold across the cycle boundaries: the independent
  // continuous-time checker on the concatenation of all applied burns.
  const std::vector<RuleViolation> v = CheckOperationalRules(
      base.rules, BoundaryHistory::AllOff(4), {}, 4, 0.0, 3 * kDay, AllBurns(cycles));
  for (const RuleViolation& r : v) ADD_FAILURE() << r.message;
  // The last switch-off times handed over are those of the burns.
  for (int i = 0; i < 4; ++i) {
    double last = -kInf;
    for (const Burn& b : AllBurns(cycles)) {
      if (b.thruster == i) last = std::max(last, b.end_s);
    }
    EXPECT_EQ(state.last_burn_end_s[i], last);
  }
  // Summary = sum of the cycles.
  const LongHorizonSummary s = Summarize(cycles, base.thrusters);
  EXPECT_NEAR(
      s.consumption_l1_m_s,
      cycles[0].consumption_l1_m_s + cycles[1].consumption_l1_m_s + cycles[2].consumption_l1_m_s,
      1e-12);
  EXPECT_EQ(s.burns, static_cast<int>(AllBurns(cycles).size()));
  EXPECT_TRUE(s.rules_ok);
}

// A thruster that stopped 10 min before the boundary cannot restart before
// its 20-min same-thruster gap (and no other thruster within 5 min).
// A schedule accepted with a gap above improve_above_gap is solved again from
// itself with a larger node budget; the kept schedule is never worse, the pass
// is recorded, and a node budget keeps the whole thing deterministic.
TEST(LongHorizonRun, ImprovementPassAfterAPoorIncumbent) {
  const ScheduleProblem base = Base();
  LongHorizonOptions o = DailyCycles(1);
  o.solve.milp.relative_gap = 0.0;
  o.solve.milp.max_nodes = 0;  // the root's incumbent only ...
  o.improve_above_gap = 1e-9;  // ... and any gap triggers the pass
  // The passes act on CBC's gap; the problem-aware search proves this cycle
  // optimal at once, so it is off here.
  o.solve.search.enabled = false;
  o.improve_max_nodes = 200;
  const LongHorizonSimulation run(base, o, Simulator(), Solver());
  LongHorizonState state = run.InitialState();
  const CycleRecord c = run.RunCycle(&state);
  ASSERT_GE(c.attempts.size(), 1u);
  LongHorizonOptions off = o;
  off.improve_above_gap = 0.0;
  const LongHorizonSimulation plain_run(base, off, Simulator(), Solver());
  LongHorizonState plain_state = plain_run.InitialState();
  const CycleRecord plain = plain_run.RunCycle(&plain_state);
  ASSERT_EQ(plain.attempts.size(), 1u);
  // Measured: the root incumbent 1.2299 m/s (gap 4.4 %), improved to 1.1826.
  ASSERT_GT(plain.gap, 1e-9);
  // The hard pass, then (the gap still above 1e-9) the elastic one.
  ASSERT_EQ(c.attempts.size(), 3u);
  EXPECT_EQ(c.attempts[1].detail.rfind("improvement pass (from the accepted schedule", 0), 0u)
      << c.attempts[1].detail;
  EXPECT_EQ(c.attempts[2].detail.rfind("improvement pass (elastic window, cold", 0), 0u)
      << c.attempts[2].detail;
  EXPECT_LT(c.objective, plain.objective - 1e-6) << c.attempts.back().detail;
  // Deterministic: the same cycle again gives the same schedule.
  LongHorizonState again = run.InitialState();
  const CycleRecord d = run.RunCycle(&again);
  EXPECT_EQ(d.objective, c.objective);
  EXPECT_EQ(d.burns.size(), c.burns.size());
}

// CBC with switches: with preprocessing/presolve on it stops "at a limit"
// without a schedule (as CBC did on six-thruster weeks) when starve_presolved
// is set; with weaken_first_raw its first solve with presolve off reports a
// node-limit stop with the valid bound 0 (as if CBC had not closed the gap);
// it always records the presolve flag of each call.
class PresolveSpySolver final : public milp::Solver {
 public:
  explicit PresolveSpySolver(bool starve_presolved, bool weaken_first_raw = false)
      : starve_presolved_(starve_presolved), weaken_first_raw_(weaken_first_raw) {}
  std::string_view name() const override { return "presolve-spy"; }
  std::string version() const override { return "0"; }
  mutable std::vector<bool> presolve_calls;

 private:
  milp::SolveResult DoSolve(const milp::LpData& lp, const milp::SolveOptions& o) const override {
    presolve_calls.push_back(o.presolve);
    if (starve_presolved_ && o.presolve) {
      milp::SolveResult r;
      r.status = milp::SolveStatus::kNoSolutionFound;
      r.detail = "spy: node limit without a schedule";
      return r;
    }
    milp::SolveResult r = planning::Solver()->Solve(lp, o);
    if (weaken_first_raw_ && !o.presolve &&
        std::count(presolve_calls.begin(), presolve_calls.end(), false) == 1 && r.has_solution()) {
      r.status = milp::SolveStatus::kFeasible;
      r.best_bound = 0.0;  // L1 consumption >= 0: still a valid bound
      r.gap = 1.0;
    }
    return r;
  }
  milp::LpRelaxationResult DoSolveLpRelaxation(const milp::LpData& lp,
                                               const milp::SolveOptions& o) const override {
    return planning::Solver()->SolveLpRelaxation(lp, o);
  }
  bool starve_presolved_;
  bool weaken_first_raw_;
};

// The first cycle of a fresh run of (base, o) with this solver.
CycleRecord FirstCycle(const ScheduleProblem& base, const LongHorizonOptions& o,
                       std::shared_ptr<const milp::Solver> solver) {
  const LongHorizonSimulation run(base, o, Simulator(), std::move(solver));
  LongHorizonState state = run.InitialState();
  return run.RunCycle(&state);
}

// retry_without_preprocessing, first half: a nominal attempt stopped without a
// schedule is solved again with preprocessing and presolve off before any
// fallback; the schedule is the nominal problem's optimum (the same as CBC's
// with presolve on), not a soft-window one.
TEST(LongHorizonRun, RetryWithoutPreprocessingBeforeTheSoftWindow) {
  const ScheduleProblem base = Base();
  LongHorizonOptions o = DailyCycles(1);
  o.retry_without_preprocessing = true;
  const auto spy = std::make_shared<PresolveSpySolver>(true);
  const CycleRecord c = FirstCycle(base, o, spy);
  ASSERT_EQ(c.attempts.size(), 2u);
  EXPECT_EQ(c.attempts[0].status, milp::SolveStatus::kNoSolutionFound);
  EXPECT_EQ(c.attempts[1].level, Fallback::kNone);
  EXPECT_EQ(c.attempts[1].detail.rfind("retry with CBC preprocessing and presolve off: ", 0), 0u)
      << c.attempts[1].detail;
  // The nominal solve and its prefix diagnosis (SolveScheduleOptions::
  // prefix_diagnosis_s) with presolve on, then the one retry with it off.
  ASSERT_GE(spy->presolve_calls.size(), 2u);
  EXPECT_EQ(std::count(spy->presolve_calls.begin(), spy->presolve_calls.end(), false), 1);
  EXPECT_FALSE(spy->presolve_calls.back());
  EXPECT_EQ(c.fallback, Fallback::kNone);
  EXPECT_EQ(c.status, milp::SolveStatus::kOptimal);
  EXPECT_TRUE(c.rules_ok);
  // The reference: plain CBC, presolve on, no retry.
  const CycleRecord ref = FirstCycle(base, DailyCycles(1), Solver());
  ASSERT_EQ(ref.fallback, Fallback::kNone);
  EXPECT_NEAR(c.objective, ref.objective, 3e-6 * ref.objective);  // both within 1e-6 of it
  EXPECT_GT(c.objective, 0.1);  // the start needs North/South firing

  // Without the option the same solver drives the cycle to the fallbacks.
  o.retry_without_preprocessing = false;
  const auto spy_off = std::make_shared<PresolveSpySolver>(true);
  const CycleRecord off = FirstCycle(base, o, spy_off);
  EXPECT_NE(off.fallback, Fallback::kNone);
  for (bool presolve : spy_off->presolve_calls) EXPECT_TRUE(presolve);
  // With presolve already off (the crash guard's retry), no second attempt.
  o.retry_without_preprocessing = true;
  o.solve.milp.presolve = false;
  const auto spy_raw = std::make_shared<PresolveSpySolver>(true);
  const CycleRecord raw = FirstCycle(base, o, spy_raw);
  for (bool presolve : spy_raw->presolve_calls) EXPECT_FALSE(presolve);
  ASSERT_EQ(raw.attempts.size(), 1u);  // CBC (presolve off) solves it at once
  EXPECT_EQ(raw.attempts[0].detail.find("retry"), std::string::npos);
}

// Second half: after the two improvement passes a gap still above the
// threshold gets a third, cold with preprocessing and presolve off; the kept
// schedule is never worse than the two-pass one.
TEST(LongHorizonRun, RetryWithoutPreprocessingIsTheThirdImprovementPass) {
  const ScheduleProblem base = Base();
  LongHorizonOptions o = DailyCycles(1);
  o.solve.milp.relative_gap = 0.0;
  o.solve.milp.max_nodes = 0;  // the root's incumbent only (gap 4.4 %, see above)
  o.improve_above_gap = 1e-9;
  o.solve.search.enabled = false;  // as above: CBC's gap is what the passes act on
  o.improve_max_nodes = 200;
  const CycleRecord c2 = FirstCycle(base, o, Solver());
  ASSERT_EQ(c2.attempts.size(), 3u);
  ASSERT_GT(c2.gap, 1e-9);  // still above after two passes, so a third would run

  o.retry_without_preprocessing = true;
  const auto spy = std::make_shared<PresolveSpySolver>(false);
  const CycleRecord c3 = FirstCycle(base, o, spy);
  ASSERT_EQ(c3.attempts.size(), 4u);
  EXPECT_EQ(spy->presolve_calls, (std::vector<bool>{true, true, true, false}));
  EXPECT_EQ(
      c3.attempts[3].detail.rfind("improvement pass (CBC preprocessing and presolve off, cold", 0),
      0u)
      << c3.attempts[3].detail;
  EXPECT_LE(c3.objective, c2.objective + 1e-9);
  EXPECT_GE(c3.best_bound, c2.best_bound - 1e-9);
  EXPECT_EQ(c3.fallback, Fallback::kNone);
  EXPECT_TRUE(c3.rules_ok);

  // A schedule accepted from the retry keeps preprocessing off in its
  // improvement passes (and gets no third pass).
  // (CBC without preprocessing solves this cycle at its root; the spy
  // reports that first solve with a gap, so that the passes run.)
  const auto starved = std::make_shared<PresolveSpySolver>(true, true);
  const CycleRecord r = FirstCycle(base, o, starved);
  ASSERT_GE(r.attempts.size(), 3u) << r.attempts.back().detail;
  ASSERT_LE(r.attempts.size(), 4u) << r.attempts.back().detail;  // two passes at most
  EXPECT_EQ(r.attempts[1].detail.rfind("retry with CBC preprocessing and presolve off", 0), 0u)
      << r.attempts[1].detail;
  for (size_t i = 2; i < r.attempts.size(); ++i) {
    EXPECT_NE(r.attempts[i].detail.find(", CBC preprocessing and presolve off, gap"),
              std::string::npos)
        << r.attempts[i].detail;
  }
  const auto first_off =
      std::find(starved->presolve_calls.begin(), starved->presolve_calls.end(), false);
  ASSERT_NE(first_off, starved->presolve_calls.end());
  EXPECT_EQ(std::count(first_off, starved->presolve_calls.end(), true), 0);
  EXPECT_EQ(r.fallback, Fallback::kNone);
  EXPECT_TRUE(r.rules_ok);
}

TEST(LongHorizonRun, HistoryCarriedAcrossTheBoundary) {
  const LongHorizonSimulation run(Base(), DailyCycles(1), Simulator(), Solver());
  LongHorizonState state = run.InitialState();
  for (double& e : state.last_burn_end_s) e = -600.0;  // all stopped 10 min before t0
  const ScheduleProblem p = run.CycleProblem(state);
  for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(p.history.off_for_s[i], 600.0);
  const CycleRecord c = run.RunCycle(&state);
  ASSERT_FALSE(c.burns.empty());
  for (const Burn& b : c.burns) EXPECT_GE(b.start_s, 600.0 - 1e-9) << b.thruster;
  // Without the history the optimal schedule fires at t0 (the node where the
  // inclination correction is cheapest), so the rule is what moved it.
  const LongHorizonSimulation fresh(Base(), DailyCycles(1), Simulator(), Solver());
  LongHorizonState s0 = fresh.InitialState();
  const CycleRecord c0 = fresh.RunCycle(&s0);
  ASSERT_FALSE(c0.burns.empty());
  EXPECT_LT(c0.burns.front().start_s, 600.0);
  EXPECT_LE(c0.consumption_l1_m_s, c.consumption_l1_m_s + 1e-12);
}

// Failure of NE from a date inside the second cycle, with its opposite SW
// switched off too (thesis 5.3.7).
TEST(LongHorizonRun, FailureForcedOffFromItsDate) {
  const ScheduleProblem base = Base();
  LongHorizonOptions o = DailyCycles(3);
  const int ne = base.thrusters.IndexOf("NE");
  const int sw = OppositeThruster(base.thrusters, ne);
  const double fail = 1.25 * kDay;
  o.outages = {{ne, fail, kInf}, {sw, fail, kInf}};
  const LongHorizonSimulation run(base, o, Simulator(), Solver());
  LongHorizonState state = run.InitialState();
  EXPECT_TRUE(run.CycleProblem(state).forced_off.empty());
  const CycleRecord c0 = run.RunCycle(&state);
  const ScheduleProblem p1 = run.CycleProblem(state);
  ASSERT_EQ(p1.forced_off.size(), 2u);
  EXPECT_DOUBLE_EQ(p1.forced_off[0].start_s, fail);
  EXPECT_DOUBLE_EQ(p1.forced_off[0].end_s, 2 * kDay);
  EXPECT_EQ(run.Available(1), std::vector<bool>({true, true, true, true}));  // partly available
  EXPECT_EQ(run.Available(2), std::vector<bool>({false, true, true, false}));
  const CycleRecord c1 = run.RunCycle(&state);
  const CycleRecord c2 = run.RunCycle(&state);
  for (const CycleRecord* c : {&c0, &c1, &c2}) {
    for (const Burn& b : c->burns) {
      if (b.thruster == ne || b.thruster == sw) {
        EXPECT_LE(b.end_s, fail + 1e-9);
      }
    }
  }
  EXPECT_TRUE(c2.controllable);  // SE + NW still push both ways
  EXPECT_NE(c2.note.find("unavailable (outage): NE, SW"), std::string::npos) << c2.note;
  EXPECT_EQ(c2.fallback, Fallback::kNone);
}

TEST(LongHorizonRun, UncontrollableCombinationIsReportedAndPropagated) {
  const ScheduleProblem base = Base();
  LongHorizonOptions o = DailyCycles(1);
  o.outages = {{base.thrusters.IndexOf("NE"), 0.0, kInf},
               {base.thrusters.IndexOf("NW"), 0.0, kInf}};
  const LongHorizonSimulation run(base, o, Simulator(), Solver());
  LongHorizonState state = run.InitialState();
  const CycleRecord c = run.RunCycle(&state);
  EXPECT_FALSE(c.controllable);
  EXPECT_EQ(c.note.rfind("uncontrollable: no available thruster pushes south (-N)", 0), 0u)
      << c.note;
  // Best effort only (no nominal attempt), not a solver error; the year goes on.
  ASSERT_FALSE(c.attempts.empty());
  EXPECT_EQ(c.attempts.front().level, Fallback::kSoftWindowFreeTerminal);
  EXPECT_NE(c.status, milp::SolveStatus::kError);
  EXPECT_EQ(state.next_cycle, 1);
  EXPECT_DOUBLE_EQ(state.time_s, kDay);
  for (const Burn& b : c.burns) {
    EXPECT_NE(b.thruster, base.thrusters.IndexOf("NE"));
    EXPECT_NE(b.thruster, base.thrusters.IndexOf("NW"));
  }
  // The latitude amplitude cannot be reduced (only +N thrusters are left): outside.
  EXPECT_GT(c.time_outside_window_s, 0.0);
  EXPECT_EQ(Summarize({c}, base.thrusters).uncontrollable_cycles, 1);
}

// A start outside the window makes the nominal cycle infeasible: the soft
// window takes over, the violation is measured on the replay, the run goes on.
TEST(LongHorizonRun, InfeasibleCycleFallsBack) {
  ScheduleProblem base = Base();
  base.initial_state = Eigen::VectorXd::Zero(6);
  base.initial_state(5) = 0.06 * kDeg;  // 0.01 deg east of the box
  const LongHorizonSimulation run(base, DailyCycles(1), Simulator(), Solver());
  LongHorizonState state = run.InitialState();
  const CycleRecord c = run.RunCycle(&state);
  ASSERT_GE(c.attempts.size(), 2u);
  EXPECT_EQ(c.attempts[0].level, Fallback::kNone);
  EXPECT_EQ(c.attempts[0].status, milp::SolveStatus::kInfeasible);
  EXPECT_TRUE(c.fallback == Fallback::kSoftWindow ||
              c.fallback == Fallback::kSoftWindowFreeTerminal)
      << ToString(c.fallback);
  EXPECT_GT(c.soft_violation_deg, 0.0);
  EXPECT_GT(c.max_window_violation_deg, 0.005);
  EXPECT_GT(c.time_outside_window_s, 3600.0);
  EXPECT_EQ(state.next_cycle, 1);

  // No time at all: the nominal and soft-window attempts end without a
  // schedule; the last attempt starts from zero thrust (feasible once the
  // window is soft and the end free), so the cycle still has a schedule.
  LongHorizonOptions none = DailyCycles(1);
  none.solve.milp.time_limit_s = 0.0;
  const LongHorizonSimulation starved(Base(), none, Simulator(), Solver());
  LongHorizonState s = starved.InitialState();
  const CycleRecord z = starved.RunCycle(&s);
  ASSERT_EQ(z.attempts.size(), 3u);
  EXPECT_EQ(z.attempts[0].status, milp::SolveStatus::kNoSolutionFound);
  EXPECT_EQ(z.attempts[1].status, milp::SolveStatus::kNoSolutionFound);
  EXPECT_EQ(z.fallback, Fallback::kSoftWindowFreeTerminal);
  EXPECT_TRUE(z.burns.empty());
  EXPECT_EQ(s.next_cycle, 1);
  // Free drift from this start leaves the box (amplitude 0.0525 deg).
  EXPECT_GT(z.time_outside_window_s, 0.0);
}

// A solver that always fails: every attempt errs, the cycle drifts freely.
class FailingSolver final : public milp::Solver {
 public:
  std::string_view name() const override { return "failing"; }
  std::string version() const override { return "0"; }

 private:
  milp::SolveResult DoSolve(const milp::LpData&, const milp::SolveOptions&) const override {
    milp::SolveResult r;
    r.status = milp::SolveStatus::kError;
    r.detail = "simulated solver failure";
    return r;
  }
  milp::LpRelaxationResult DoSolveLpRelaxation(const milp::LpData&,
                                               const milp::SolveOptions&) const override {
    return {};
  }
};

TEST(LongHorizonRun, SolverFailureGivesZeroThrustAndTheRunGoesOn) {
  // The solver alone (no search, which would keep the last level's zero-thrust
  // start itself; see SolverFailureWithTheSearchKeepsTheZeroStart).
  LongHorizonOptions o = DailyCycles(2);
  o.solve.search.enabled = false;
  const LongHorizonSimulation run(Base(), o, Simulator(), std::make_shared<FailingSolver>());
  LongHorizonState s = run.InitialState();
  const CycleRecord z = run.RunCycle(&s);
  EXPECT_EQ(z.fallback, Fallback::kZeroThrust);
  ASSERT_EQ(z.attempts.size(), 3u);
  for (const CycleAttempt& a : z.attempts) {
    EXPECT_EQ(a.status, milp::SolveStatus::kError);
    EXPECT_EQ(a.detail, "simulated solver failure");
  }
  EXPECT_TRUE(z.burns.empty());
  EXPECT_EQ(z.consumption_l1_m_s, 0.0);
  EXPECT_TRUE(std::isnan(z.prediction_error_deg));
  EXPECT_EQ(s.next_cycle, 1);
  // The free drift is still propagated: the simulator alone gives the same end.
  const dynamics::Vector6d drift = Simulator()->Propagate(
      z.eci_start, 0.0, Base().thrusters.AccelerationMatrix(), {}, {kDay})[0];
  EXPECT_LT((drift.head<3>() - z.eci_end.head<3>()).norm(), 1e-3);
  EXPECT_GT(z.time_outside_window_s, 0.0);
  EXPECT_EQ(Summarize({z}, Base().thrusters).fallback_zero_thrust, 1);
  const CycleRecord z2 = run.RunCycle(&s);
  EXPECT_EQ(z2.index, 1);
  EXPECT_EQ(z2.eci_start, z.eci_end);
}

// With the search (the default), a failing solver still errs on the first two
// levels (LP relaxation, then the whole MILP); the last level's zero-thrust
// start is verified by the search and kept as that level's schedule.
TEST(LongHorizonRun, SolverFailureWithTheSearchKeepsTheZeroStart) {
  const LongHorizonSimulation run(Base(), DailyCycles(2), Simulator(),
                                  std::make_shared<FailingSolver>());
  LongHorizonState s = run.InitialState();
  const CycleRecord z = run.RunCycle(&s);
  ASSERT_EQ(z.attempts.size(), 3u);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(z.attempts[k].status, milp::SolveStatus::kError);
    EXPECT_NE(z.attempts[k].detail.find("failing: simulated solver failure"), std::string::npos)
        << z.attempts[k].detail;
  }
  EXPECT_EQ(z.attempts[2].status, milp::SolveStatus::kFeasible);
  EXPECT_NE(z.attempts[2].detail.find("from the given start"), std::string::npos)
      << z.attempts[2].detail;
  EXPECT_EQ(z.fallback, Fallback::kSoftWindowFreeTerminal);
  EXPECT_TRUE(z.burns.empty());
  EXPECT_EQ(z.consumption_l1_m_s, 0.0);
  EXPECT_GT(z.time_outside_window_s, 0.0);
}

// Resume: 2 cycles, then a new simulation object continues from the saved
// state for the third: identical to 3 uninterrupted cycles.
TEST(LongHorizonRun, ResumedRunEqualsUninterrupted) {
  const LongHorizonSimulation full(Base(), DailyCycles(3), Simulator(), Solver());
  LongHorizonState s = full.InitialState();
  const std::vector<CycleRecord> a = RunAll(full, &s);

  const LongHorizonSimulation first(Base(), DailyCycles(3), Simulator(), Solver());
  LongHorizonState r = first.InitialState();
  std::vector<CycleRecord> b;
  b.push_back(first.RunCycle(&r));
  b.push_back(first.RunCycle(&r));
  const LongHorizonState saved = r;  // what a checkpoint holds
  const LongHorizonSimulation second(Base(), DailyCycles(3), Simulator(), Solver());
  LongHorizonState resumed = saved;
  b.push_back(second.RunCycle(&resumed));

  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) {
    SCOPED_TRACE("cycle " + std::to_string(k));
    EXPECT_EQ(a[k].objective, b[k].objective);
    EXPECT_EQ(a[k].consumption_l1_m_s, b[k].consumption_l1_m_s);
    ASSERT_EQ(a[k].burns.size(), b[k].burns.size());
    for (size_t i = 0; i < a[k].burns.size(); ++i) {
      EXPECT_EQ(a[k].burns[i].thruster, b[k].burns[i].thruster);
      EXPECT_EQ(a[k].burns[i].start_s, b[k].burns[i].start_s);
      EXPECT_EQ(a[k].burns[i].end_s, b[k].burns[i].end_s);
    }
    EXPECT_EQ(a[k].eci_end, b[k].eci_end);
    EXPECT_EQ(a[k].max_abs_lat_deg, b[k].max_abs_lat_deg);
  }
  EXPECT_EQ(s.eci, resumed.eci);
  EXPECT_EQ(s.last_burn_end_s, resumed.last_burn_end_s);
}

TEST(LongHorizonRun, InterruptLeavesTheStateUnchanged) {
  std::atomic<bool> stop{true};
  LongHorizonOptions o = DailyCycles(2);
  o.solve.milp.interrupt = &stop;
  const LongHorizonSimulation run(Base(), o, Simulator(), Solver());
  LongHorizonState s = run.InitialState();
  const LongHorizonState before = s;
  const CycleRecord c = run.RunCycle(&s);
  EXPECT_TRUE(c.interrupted);
  EXPECT_EQ(s.next_cycle, 0);
  EXPECT_EQ(s.eci, before.eci);
}

// Receding horizon: 1-day prediction, 12-h control; no burn crosses the
// control boundary, the applied parts chain.
TEST(LongHorizonRun, RecedingAppliesOnlyTheControlHorizon) {
  const ScheduleProblem base = Base();
  LongHorizonOptions o = DailyCycles(1);
  o.mode = HorizonMode::kReceding;
  o.control_s = 0.5 * kDay;
  const LongHorizonSimulation run(base, o, Simulator(), Solver());
  ASSERT_EQ(run.num_cycles(), 2);
  LongHorizonState s = run.InitialState();
  const std::vector<CycleRecord> c = RunAll(run, &s);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_FALSE(c[0].burns.empty());
  for (const CycleRecord& r : c) {
    EXPECT_EQ(r.fallback, Fallback::kNone);
    EXPECT_DOUBLE_EQ(r.prediction_end_s, r.start_s + kDay);
    EXPECT_DOUBLE_EQ(r.applied_end_s, r.start_s + 0.5 * kDay);
    for (const Burn& b : r.burns) EXPECT_LE(b.end_s, r.applied_end_s + 1e-9);
    EXPECT_GE(r.planned_burns, static_cast<int>(r.burns.size()));
    EXPECT_EQ(r.max_window_violation_deg, 0.0);
  }
  EXPECT_EQ(c[1].eci_start, c[0].eci_end);
  EXPECT_DOUBLE_EQ(s.time_s, kDay);
  const std::vector<RuleViolation> v =
      CheckOperationalRules(base.rules, BoundaryHistory::AllOff(4), {}, 4, 0.0, kDay, AllBurns(c));
  for (const RuleViolation& r : v) ADD_FAILURE() << r.message;
}

// milp::SolveOptions::max_nodes (added for deterministic cycle budgets): a
// strongly correlated 0-1 knapsack (60 items) that CBC solves in ~50 nodes.
milp::LpData HardKnapsack() {
  milp::Model m;
  milp::LinearExpr weight, value;
  unsigned s = 12345;
  double total = 0;
  for (int i = 0; i < 60; ++i) {
    s = s * 1103515245u + 12345u;
    const double w = 100 + (s >> 16) % 900;
    const milp::Variable x = m.AddBinary();
    weight.AddTerm(x, w);
    value.AddTerm(x, w + 100);
    total += w;
  }
  m.AddConstraint(weight, -kInf, std::floor(total / 2) + 0.5);
  m.Maximize(value);
  return m.ToLpData();
}

TEST(NodeLimit, StopsDeterministicallyAfterTheBudget) {
  milp::SolveOptions o;
  o.relative_gap = 0;
  const milp::SolveResult full = Solver()->Solve(HardKnapsack(), o);
  ASSERT_EQ(full.status, milp::SolveStatus::kOptimal);
  ASSERT_GT(full.nodes, 5);  // the instance needs branching
  o.max_nodes = 3;
  const milp::SolveResult a = Solver()->Solve(HardKnapsack(), o);
  const milp::SolveResult b = Solver()->Solve(HardKnapsack(), o);
  EXPECT_EQ(a.status, milp::SolveStatus::kFeasible);
  EXPECT_LE(a.nodes, 3);
  EXPECT_NE(a.detail.find("node limit"), std::string::npos) << a.detail;
  EXPECT_LT(a.objective, full.objective + 1e-9);  // maximisation: not better than the optimum
  EXPECT_GE(a.best_bound, full.objective - 1e-9);
  EXPECT_EQ(a.objective, b.objective);
  EXPECT_EQ(a.x, b.x);
}

}  // namespace
}  // namespace thrustsched::planning
