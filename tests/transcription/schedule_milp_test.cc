// ScheduleMilp against independent references: closed forms of the double
// integrator (Serra 2015 sec. 5.2.3; its on-off variant derived here), the
// published optima of the thesis Table 4.1 (exact multiples of one 5-min
// slot), agreement of formulations and encodings, and internal consistency of
// decoding.
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>

#include <gtest/gtest.h>

#include "dynamics/geo_model.h"
#include "dynamics/models.h"
#include "milp/cbc_solver.h"
#include "tests/transcription/thesis_cases.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"

namespace thrustsched::dynamics {
// gtest prints a failing case's scheme by its scenario-file name, not as an
// integer (found by argument-dependent lookup, hence this namespace).
static void PrintTo(Scheme s, std::ostream* os) { *os << ToString(s); }
}  // namespace thrustsched::dynamics

namespace thrustsched::transcription {
namespace {

constexpr double kGeoN = 7.2921159e-5;  // rad/s, thesis HCW mean motion
constexpr double kPi = 3.14159265358979323846;

ScheduleProblem DoubleIntegratorRestToRest(int intervals, InputMode mode) {
  // Unit distance in unit time along x (R axis of an ideal thruster set).
  ScheduleProblem p;
  p.model = std::make_shared<dynamics::DoubleIntegrator3d>();
  p.thrusters = dynamics::ThrusterSet::Ideal6(/*thrust_n=*/1000.0, /*mass_kg=*/1.0, /*isp_s=*/300);
  p.grid = dynamics::UniformGrid(0.0, 1.0, intervals);
  p.initial_state = Eigen::VectorXd::Zero(6);
  p.terminal.kind = TerminalKind::kFixedState;
  p.terminal.target = Eigen::VectorXd::Zero(6);
  p.terminal.target[0] = 1.0;
  p.objective.kind = ObjectiveKind::kDeltaV;
  p.input_mode = mode;
  return p;
}

milp::SolveOptions Exact(double time_limit = 120) {
  milp::SolveOptions o;
  o.time_limit_s = time_limit;
  o.relative_gap = 1e-9;
  o.absolute_gap = 1e-9;
  return o;
}

class DoubleIntegratorSchemeTest : public ::testing::TestWithParam<dynamics::Scheme> {};

// LP relaxation (continuous thrust fraction in [0, 1], thrust large enough
// not to bind): J_N = 2 N / (N - 1), pulses in the first and last intervals.
TEST_P(DoubleIntegratorSchemeTest, ZohGridLpOptimumIsTwoNOverNMinusOne) {
  auto solver = milp::MakeCbcSolver();
  for (int n : {4, 10, 40}) {
    const ScheduleProblem p = DoubleIntegratorRestToRest(n, InputMode::kOnOff);
    BuildOptions b;
    b.discretisation.scheme = GetParam();
    const ScheduleMilp m(p, b);
    const milp::LpRelaxationResult r = solver->SolveLpRelaxation(m.lp());
    ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << n;
    EXPECT_NEAR(r.objective, 2.0 * n / (n - 1), 1e-7) << "N = " << n;
  }
}

INSTANTIATE_TEST_SUITE_P(
    ExactForDoubleIntegrator, DoubleIntegratorSchemeTest,
    ::testing::Values(dynamics::Scheme::kExactZoh, dynamics::Scheme::kFrozenStart,
                      dynamics::Scheme::kFrozenMid, dynamics::Scheme::kHermiteSimpson,
                      dynamics::Scheme::kRk4, dynamics::Scheme::kTrapezoid,
                      dynamics::Scheme::kReference),
    [](const auto& info) { return std::string(dynamics::ToString(info.param)); });

// Impulses at the nodes including both ends: the continuous optimum 2 is
// attained for every N >= 1 (impulse +1 at t = 0, -1 at t = 1).
TEST(ScheduleMilpTest, DoubleIntegratorImpulsiveOptimumIsTwo) {
  auto solver = milp::MakeCbcSolver();
  for (int n : {1, 2, 7, 30}) {
    const ScheduleProblem p = DoubleIntegratorRestToRest(n, InputMode::kImpulsive);
    const ScheduleResult r = SolveSchedule(p, *solver, {});
    ASSERT_EQ(r.solve.status, milp::SolveStatus::kOptimal);
    EXPECT_NEAR(r.solve.objective, 2.0, 1e-8);
    EXPECT_NEAR(r.schedule.delta_v_m_s, 2.0, 1e-8);
    EXPECT_LT(r.impulsive_check.terminal_error, 1e-6);
  }
}

// Thesis Table 4.1: all burns tangential at the start of the horizon; the
// optimum is k slots of 0.016392 m/s. Published: 1 d 0.0164, 2 d 0.0819,
// 3 d 0.0984 (5 and 8 days run in the benchmark).
TEST(ScheduleMilpTest, ThesisTable41ShortHorizons) {
  auto solver = milp::MakeCbcSolver();
  const double slot = 0.265 / 4850 * 300;  // m/s per 5-min slot of an ideal thruster
  const std::vector<std::pair<double, int>> cases = {{1, 1}, {2, 5}, {3, 6}};
  const std::vector<double> published = {0.0164, 0.0819, 0.0984};
  for (size_t k = 0; k < cases.size(); ++k) {
    const ScheduleProblem p = ThesisTable41(cases[k].first);
    SolveScheduleOptions o;
    o.milp = Exact();
    const ScheduleResult r = SolveSchedule(p, *solver, o);
    ASSERT_EQ(r.solve.status, milp::SolveStatus::kOptimal) << cases[k].first << " days";
    EXPECT_NEAR(r.schedule.consumption_l1_m_s, cases[k].second * slot, 1e-9);
    EXPECT_LE(r.schedule.consumption_l1_m_s, published[k] + 2e-4);
    EXPECT_TRUE(r.check.operational_ok) << r.check.Summary();
    EXPECT_LE(r.check.max_window_violation_at_nodes, 1e-3) << r.check.Summary();  // m
  }
}

// Sparse and condensed transcriptions, thesis and tight encodings: one optimum.
TEST(ScheduleMilpTest, FormulationsAndEncodingsAgree) {
  auto solver = milp::MakeCbcSolver();
  ScheduleProblem p = ThesisTable41(1.0);
  p.grid = dynamics::UniformGrid(0.0, 86400.0, 144);  // 10-min steps
  p.initial_state[0] = 3000.0;
  double reference = std::nan("");
  for (Formulation f : {Formulation::kSparse, Formulation::kCondensed}) {
    for (Encoding e : {Encoding::kThesis, Encoding::kTight}) {
      SolveScheduleOptions o;
      o.build.formulation = f;
      o.build.encoding = e;
      o.milp = Exact();
      const ScheduleResult r = SolveSchedule(p, *solver, o);
      ASSERT_EQ(r.solve.status, milp::SolveStatus::kOptimal) << ToString(f) << " " << ToString(e);
      if (std::isnan(reference)) reference = r.solve.objective;
      EXPECT_NEAR(r.solve.objective, reference, 1e-9) << ToString(f) << " " << ToString(e);
      EXPECT_TRUE(r.check.operational_ok);
    }
  }
}

// The state columns of the sparse model equal the decoded discrete
// trajectory, and StartFromBurns rebuilds a feasible point of equal cost.
TEST(ScheduleMilpTest, DecodeAndWarmStartAreConsistent) {
  auto solver = milp::MakeCbcSolver();
  ScheduleProblem p = ThesisTable41(1.0);
  p.initial_state[0] = 2000.0;
  const ScheduleMilp m(p, {});
  milp::SolveOptions exact = Exact();
  exact.objective_step = m.objective_step();
  EXPECT_NEAR(m.objective_step(), 0.265 / 4850 * 300, 1e-15);  // one 5-min slot
  const milp::SolveResult r = solver->Solve(m.lp(), exact);
  ASSERT_TRUE(r.has_solution());
  const Schedule s = m.Decode(r.x);
  EXPECT_NEAR(s.consumption_l1_m_s, r.objective, 1e-12);
  const Eigen::VectorXd start = m.StartFromBurns(s.burns);
  EXPECT_LE(m.lp().MaxViolation(start), 1e-7);
  EXPECT_NEAR(m.lp().Objective(start), r.objective, 1e-12);
  // The decoded states match the solver's own state columns (scaled back).
  const Eigen::VectorXd scale = p.model->state_scale();
  for (int j : {0, 50, 288}) {
    for (int c = 0; c < 6; ++c) {
      const double from_solver = r.x[m.state(j, c).index()] * scale[c];
      EXPECT_NEAR(from_solver, s.states[j][c], 1e-6 * scale[c]) << "node " << j << " state " << c;
    }
  }
  // MIP start is accepted: solving with it is still optimal and equal.
  SolveScheduleOptions o;
  o.milp = Exact();
  o.warm_start = s.burns;
  const ScheduleResult warm = SolveBuilt(m, *solver, o);
  ASSERT_EQ(warm.solve.status, milp::SolveStatus::kOptimal);
  EXPECT_NEAR(warm.solve.objective, r.objective, 1e-9);
}

// X0 = [10 km, 0, 0, 0, 0, 0] over 7 days is infeasible with the window
// enforced from t0 (thesis §4.3.3); at a 10-min step, 2 days suffice to show
// it. A soft window returns the least-violating schedule instead.
// The least objective of a schedule that fires (a lower bound wherever
// the zero schedule is infeasible): the minimum burn's slots of the cheapest
// slot, one slot where a burn may be shorter (across the end, from the
// history); the dearest schedule: every interval's max_simultaneous dearest
// slots; neither where the slots do not carry the whole objective.
TEST(ScheduleMilpTest, FiringObjectivesAreTheShortestBurnAndTheBusiestSchedule) {
  const double slot = 0.265 / 4850 * 300;
  ScheduleProblem p = ThesisTable41(1.0);
  EXPECT_NEAR(ScheduleMilp(p, BuildOptions{}).least_firing_objective(), slot, 1e-15);
  // The dearest: one thruster on in each of the 288 intervals (two if two may fire at once).
  EXPECT_NEAR(ScheduleMilp(p, BuildOptions{}).dearest_schedule_objective(), 288 * slot, 1e-12);
  ScheduleProblem two = p;
  two.rules.max_simultaneous = 2;
  EXPECT_NEAR(ScheduleMilp(two, BuildOptions{}).dearest_schedule_objective(), 576 * slot, 1e-12);
  p.rules.min_burn_s = 780;  // 13 min: 3 slots of 5 min
  EXPECT_NEAR(ScheduleMilp(p, BuildOptions{}).least_firing_objective(), 3 * slot, 1e-15);
  for (const int variant : {0, 1}) {
    ScheduleProblem q = p;
    if (variant == 0) q.rules.allow_burn_across_end = true;
    if (variant == 1) {
      q.history = BoundaryHistory::AllOff(6);
      q.history.on_for_s[2] = 300;  // +N on for 5 min at t0
    }
    EXPECT_NEAR(ScheduleMilp(q, BuildOptions{}).least_firing_objective(), slot, 1e-15) << variant;
  }
  ScheduleProblem soft = p;
  soft.window.soft = true;
  EXPECT_EQ(ScheduleMilp(soft, BuildOptions{}).least_firing_objective(),
            -std::numeric_limits<double>::infinity());
  EXPECT_EQ(ScheduleMilp(soft, BuildOptions{}).dearest_schedule_objective(),
            std::numeric_limits<double>::infinity());
  ScheduleProblem impulsive = p;
  impulsive.input_mode = InputMode::kImpulsive;
  EXPECT_EQ(ScheduleMilp(impulsive, BuildOptions{}).least_firing_objective(),
            -std::numeric_limits<double>::infinity());
}

TEST(ScheduleMilpTest, InfeasibleStartAndSoftWindow) {
  auto solver = milp::MakeCbcSolver();
  ScheduleProblem p = ThesisTable41(2.0);
  p.grid = dynamics::UniformGrid(0.0, 2 * 86400.0, 288);
  p.initial_state[0] = 10000.0;
  p.initial_state[1] = 36000.0;  // near the edge, drifting out fast
  SolveScheduleOptions o;
  o.milp = Exact(60);
  const ScheduleResult hard = SolveSchedule(p, *solver, o);
  EXPECT_EQ(hard.solve.status, milp::SolveStatus::kInfeasible);
  // The soft problem is a hard MILP: one day at 10-minute steps and a time
  // limit are enough to get the least-violating schedule found so far.
  p.grid = dynamics::UniformGrid(0.0, 86400.0, 144);
  p.window.soft = true;
  p.window.soft_penalty = 10.0;
  o.milp.time_limit_s = 20;
  const ScheduleResult soft = SolveSchedule(p, *solver, o);
  ASSERT_TRUE(soft.has_schedule());
  EXPECT_GT(soft.check.max_window_violation_at_nodes, 1.0);  // m: it does leave the box
}

// Thesis sec. 4.3.3: X0 = [10 km, 0, 0, ...] over 7 days cannot be held in
// the window. CBC alone cannot decide the week (minutes in its root LP); a
// solve stopped by its time limit is then diagnosed on prefixes of the
// horizon, each a relaxation of the whole problem: an infeasible prefix proves
// the week infeasible. A feasible problem stopped the same way is never
// declared infeasible.
TEST(ScheduleMilpTest, PrefixDiagnosisProvesAWeekInfeasible) {
  auto solver = milp::MakeCbcSolver();
  ScheduleProblem p = ThesisTable41(7.0);
  p.initial_state[0] = 10000.0;
  SolveScheduleOptions o;
  o.milp.time_limit_s = 0.5;  // stops CBC inside its root LP
  o.prefix_diagnosis_s = 0.0;
  const ScheduleResult undecided = SolveSchedule(p, *solver, o);
  EXPECT_EQ(undecided.solve.status, milp::SolveStatus::kNoSolutionFound) << undecided.solve.detail;
  // The diagnosis runs inside the time limit (ShareTimeLimit): 0.5 s of
  // solve, the rest of a 60.5 s limit (at most 60 s) for the diagnosis.
  o.milp.time_limit_s = 60.5;
  o.diagnosis_share = 60.0 / 60.5;
  o.prefix_diagnosis_s = 60.0;
  const ScheduleResult r = SolveSchedule(p, *solver, o);
  EXPECT_NEAR(r.solve_time_limit_s, 0.5, 1e-12);
  EXPECT_GT(r.diagnosis_time_limit_s, 0.0);
  EXPECT_LE(r.solve_time_limit_s + r.diagnosis_time_limit_s, 60.5 + 1e-12);
  ASSERT_EQ(r.solve.status, milp::SolveStatus::kInfeasible) << r.solve.detail;
  ASSERT_FALSE(r.infeasibility_reasons.empty());
  EXPECT_NE(r.infeasibility_reasons.back().find("are infeasible on their own"), std::string::npos)
      << r.infeasibility_reasons.back();
  // Feasible (thesis Table 4.1, 2 days), stopped before any schedule: stays undecided.
  const ScheduleProblem feasible = ThesisTable41(2.0);
  o.milp.time_limit_s = 0.01;
  const ScheduleResult f = SolveSchedule(feasible, *solver, o);
  EXPECT_NE(f.solve.status, milp::SolveStatus::kInfeasible) << f.solve.detail;
}

// The time limit bounds the solve and the diagnosis together: the solve
// stops early by the diagnosis's share (at most its cap), and the diagnosis
// gets what the solve left of the limit, at most its cap.
TEST(ScheduleMilpTest, TimeLimitIsSharedWithTheDiagnosis) {
  const double inf = std::numeric_limits<double>::infinity();
  TimeLimitShares s = ShareTimeLimit(5.0, 30.0, 0.25);  // `--time-limit 5`, default cap
  EXPECT_DOUBLE_EQ(s.solve_s, 3.75);
  EXPECT_DOUBLE_EQ(s.diagnosis_s, 1.25);
  s = ShareTimeLimit(600.0, 30.0, 0.25);  // the cap binds: 30 s of 600
  EXPECT_DOUBLE_EQ(s.solve_s, 570.0);
  EXPECT_DOUBLE_EQ(s.diagnosis_s, 30.0);
  s = ShareTimeLimit(5.0, 0.0, 0.25);  // no diagnosis (--no-diagnose): the whole limit solves
  EXPECT_DOUBLE_EQ(s.solve_s, 5.0);
  EXPECT_DOUBLE_EQ(s.diagnosis_s, 0.0);
  s = ShareTimeLimit(5.0, std::nan(""), 0.25);
  EXPECT_DOUBLE_EQ(s.solve_s, 5.0);
  EXPECT_DOUBLE_EQ(s.diagnosis_s, 0.0);
  s = ShareTimeLimit(inf, 30.0, 0.25);  // no limit to share
  EXPECT_EQ(s.solve_s, inf);
  EXPECT_DOUBLE_EQ(s.diagnosis_s, 30.0);
  // After the solve: what is left of the limit, at most the cap, never < 0.
  EXPECT_DOUBLE_EQ(DiagnosisTimeLeft(5.0, 30.0, 3.8), 1.2);
  EXPECT_DOUBLE_EQ(DiagnosisTimeLeft(5.0, 30.0, 7.0), 0.0);     // the solve overran
  EXPECT_DOUBLE_EQ(DiagnosisTimeLeft(600.0, 30.0, 2.0), 30.0);  // a node limit stopped it early
  EXPECT_DOUBLE_EQ(DiagnosisTimeLeft(inf, 30.0, 100.0), 30.0);
  EXPECT_DOUBLE_EQ(DiagnosisTimeLeft(5.0, 0.0, 1.0), 0.0);

  // In a solve: a feasible problem (thesis Table 4.1, 1 day) under a 20 s
  // limit: the solve was given 15 s (the diagnosis's 5 s were kept); an
  // impulsive or soft-window problem, which the diagnosis never follows,
  // keeps the whole limit.
  auto solver = milp::MakeCbcSolver();
  ScheduleProblem p = ThesisTable41(1.0);
  SolveScheduleOptions o;
  o.milp.time_limit_s = 20.0;
  const ScheduleResult r = SolveSchedule(p, *solver, o);
  EXPECT_DOUBLE_EQ(r.solve_time_limit_s, 15.0);
  EXPECT_DOUBLE_EQ(r.diagnosis_time_limit_s, 5.0);
  EXPECT_EQ(r.diagnosis_seconds, 0.0);  // a schedule was found: no diagnosis
  p.window.soft = true;
  const ScheduleResult soft = SolveSchedule(p, *solver, o);
  EXPECT_DOUBLE_EQ(soft.solve_time_limit_s, 20.0);
  EXPECT_DOUBLE_EQ(soft.diagnosis_time_limit_s, 0.0);
  o.diagnosis_share = 1.0;
  std::string error;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("diagnosis_share: must be in [0, 1), got 1"), std::string::npos) << error;
}

// The GEO week's matrix is scaled (every row's largest coefficient is 1) and
// cleaned: nothing below 1e-8 of its row's largest survives. With entries
// down to 1e-14 (roundoff and negligible couplings of the transition
// matrices), CBC 2.10 "proved" feasible GEO weeks infeasible.
TEST(ScheduleMilpTest, GeoWeekMatrixIsScaledAndClean) {
  ScheduleProblem p;
  p.model = std::make_shared<dynamics::GeoLinearModel>(dynamics::GeoModelOptions{});
  p.thrusters = dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005);
  p.grid = dynamics::UniformGrid(0.0, 7 * 86400.0, 2016);
  p.initial_state = Eigen::VectorXd::Zero(6);
  p.window.outputs = {1, 2};
  p.window.half_widths = {0.05 * kPi / 180, 0.05 * kPi / 180};
  p.rules.min_burn_s = 300;
  p.rules.min_off_same_s = 1200;
  p.rules.min_gap_other_s = 300;
  p.terminal.kind = TerminalKind::kStationKeepingSets;
  BuildOptions b;
  b.discretisation.scheme = dynamics::Scheme::kHermiteSimpson;
  const ScheduleMilp m(p, b);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> a = m.lp().a_matrix;
  double smallest_ratio = 1.0;
  for (int r = 0; r < a.outerSize(); ++r) {
    double big = 0.0, small = std::numeric_limits<double>::infinity();
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(a, r); it; ++it) {
      big = std::max(big, std::abs(it.value()));
      small = std::min(small, std::abs(it.value()));
    }
    if (big > 0.0) {
      EXPECT_NEAR(big, 1.0, 1e-12) << m.lp().row_names[r];
      smallest_ratio = std::min(smallest_ratio, small / big);
    }
  }
  EXPECT_GE(smallest_ratio, 1e-8);
}

// Why the builder scales: thesis Table 4.1 in SI units spans many orders of
// magnitude (positions in m, velocities in m/s, a 5-min slot of 5.5e-5 m/s^2);
// on such a version CBC's presolve once returned "optimal" 0.180 m/s for a
// problem whose optimum is 0.098. Scaled, every row's coefficients lie in
// [1e-8, 1] and the published optima are reproduced (ThesisTable41ShortHorizons).
TEST(ScheduleMilpTest, ScalingNarrowsTheCoefficientRange) {
  auto range = [](const milp::LpData& lp) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (int k = 0; k < lp.a_matrix.outerSize(); ++k) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(lp.a_matrix, k); it; ++it) {
        lo = std::min(lo, std::abs(it.value()));
        hi = std::max(hi, std::abs(it.value()));
      }
    }
    return hi / lo;
  };
  const ScheduleProblem p = ThesisTable41(3.0);
  BuildOptions scaled, raw;
  raw.scale = false;
  const double r_scaled = range(ScheduleMilp(p, scaled).lp());
  const double r_raw = range(ScheduleMilp(p, raw).lp());
  EXPECT_LE(r_scaled, 1e8);
  EXPECT_GT(r_raw, 1e3 * r_scaled);
}

TEST(ScheduleMilpTest, InvalidProblemThrowsNamingTheField) {
  ScheduleProblem p = ThesisTable41(1.0);
  p.window.half_widths = {36800.0, -1.0};
  try {
    ScheduleMilp m(p, {});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("window.half_widths[1]"), std::string::npos) << e.what();
  }
  p = ThesisTable41(1.0);
  p.initial_state = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(ScheduleMilp(p, {}), std::invalid_argument);
  EXPECT_THROW(ParseFormulation("dense"), std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::transcription
