// The problem-aware search (SearchSchedule, SolveBuilt's default in on-off
// mode) against independent references:
//  - the published optima of the thesis Table 4.1 (whole numbers of 5-min
//    slots) and CBC alone on the whole MILP (search disabled, gap 1e-9);
//  - its LP bound never above a proven optimum;
//  - the restricted MILP (BuildOptions::free_slots, condensed), solved whole
//    and by row generation, against the full sparse MILP with the same slots
//    forbidden by column bounds;
//  - the exchange along an axis reaching CBC alone's optimum from a start
//    whose in-plane firings lie away from it;
//  - determinism, a given start kept, an interrupt honoured.
// Every solve has a node limit or is small enough that CBC needs a handful of
// nodes; none depends on the wall clock.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/format.h"
#include "dynamics/discretisation.h"
#include "milp/cbc_solver.h"
#include "milp/lazy_rows.h"
#include "milp/lp_data.h"
#include "tests/transcription/thesis_cases.h"
#include "transcription/dormant.h"
#include "transcription/internal/build_time.h"
#include "transcription/search.h"
#include "transcription/solve.h"
#include "transcription/total_branching.h"

namespace thrustsched::transcription {
namespace {

milp::SolveOptions Exact() {
  milp::SolveOptions o;
  o.relative_gap = 1e-9;
  o.absolute_gap = 1e-9;
  o.threads = 1;
  o.max_nodes = 200000;
  return o;
}

// The reference: CBC alone on the whole MILP (search disabled), gap 1e-9.
ScheduleResult CbcAlone(const ScheduleProblem& p, const milp::Solver& solver) {
  SolveScheduleOptions o;
  o.milp = Exact();
  o.search.enabled = false;
  return SolveSchedule(p, solver, o);
}

// Thesis Table 4.1 with the start further out and 10-min steps: a one-day
// problem with several burns, small enough for CBC alone in a second.
ScheduleProblem SmallHcwDay() {
  ScheduleProblem p = ThesisTable41(1.0);
  p.grid = dynamics::UniformGrid(0.0, 86400.0, 144);
  p.initial_state[0] = 3000.0;
  return p;
}

// Thesis Table 4.1 (Gazzino 2018, sec. 4.3.3): the optimum is k slots of an
// ideal thruster, published 0.0819 m/s (2 d, 5 slots) and 0.0984 (3 d, 6);
// CBC alone proves the same in schedule_milp_test.cc.
TEST(SearchSchedule, ProvesTheThesisTable41Optima) {
  auto solver = milp::MakeCbcSolver();
  const double slot = 0.265 / 4850 * 300;
  const std::vector<std::pair<double, int>> cases = {{2, 5}, {3, 6}};
  for (const auto& [days, slots] : cases) {
    const ScheduleProblem p = ThesisTable41(days);
    SolveScheduleOptions o;
    o.milp = Exact();
    const ScheduleResult r = SolveSchedule(p, *solver, o);
    ASSERT_EQ(r.solve.status, milp::SolveStatus::kOptimal) << r.solve.detail;
    EXPECT_NEAR(r.solve.objective, slots * slot, 1e-9) << r.solve.detail;
    // The bounds: from the duals (any accuracy), never above the optimum.
    EXPECT_LE(r.search.lp_bound, slots * slot + 1e-9);
    EXPECT_GT(r.search.lp_bound, 0.5 * slots * slot);  // a real bound, not -inf
    EXPECT_LE(r.solve.best_bound, r.solve.objective + 1e-12);
    EXPECT_FALSE(r.search.steps.empty());
    EXPECT_TRUE(r.check.operational_ok) << r.check.Summary();
    EXPECT_LE(r.check.max_window_violation_at_nodes, 1e-3) << r.check.Summary();
  }
}

// The relaxation by either interior point (the project's, CLP's barrier):
// the same proven optimum of Table 4.1 (3 d, 6 slots) and bounds never above
// it; the step names the method that gave the bound.
TEST(SearchSchedule, EitherLpMethodOfTheRelaxationProvesTheSameOptimum) {
  auto solver = milp::MakeCbcSolver();
  const double optimum = 6 * 0.265 / 4850 * 300;
  const ScheduleProblem p = ThesisTable41(3);
  using Method = RelaxationOptions::LpMethod;
  for (const Method method : {Method::kInteriorPoint, Method::kClpBarrier}) {
    SCOPED_TRACE(ToString(method));
    SolveScheduleOptions o;
    o.milp = Exact();
    o.search.relaxation.lp_method = method;
    const ScheduleResult r = SolveSchedule(p, *solver, o);
    ASSERT_EQ(r.solve.status, milp::SolveStatus::kOptimal) << r.solve.detail;
    EXPECT_NEAR(r.solve.objective, optimum, 1e-9);
    EXPECT_LE(r.search.lp_bound, optimum + 1e-9);
    EXPECT_GT(r.search.lp_bound, 0.5 * optimum);
    ASSERT_FALSE(r.search.steps.empty());
    const bool own =
        r.search.steps.front().find("the project's interior point") != std::string::npos;
    EXPECT_EQ(own, method == Method::kInteriorPoint) << r.search.steps.front();
  }
}

// Thesis Table 4.1 over one day needs less than one slot of thrust by the
// LP; with burns of at least 13 min (3 slots) every schedule costs at least
// 3 slots (ScheduleMilp::least_firing_objective), which the search proves at
// its first 3-slot incumbent: the optimum CBC alone proves on the whole MILP.
TEST(SearchSchedule, ABoundAboveZeroRaisesToTheShortestBurn) {
  auto solver = milp::MakeCbcSolver();
  const double slot = 0.265 / 4850 * 300;
  ScheduleProblem p = ThesisTable41(1.0);
  p.rules.min_burn_s = 780;
  const ScheduleResult reference = CbcAlone(p, *solver);
  ASSERT_EQ(reference.solve.status, milp::SolveStatus::kOptimal) << reference.solve.detail;
  EXPECT_NEAR(reference.solve.objective, 3 * slot, 1e-9);
  SolveScheduleOptions o;
  o.milp = Exact();
  const ScheduleResult r = SolveSchedule(p, *solver, o);
  ASSERT_EQ(r.solve.status, milp::SolveStatus::kOptimal) << r.solve.detail;
  EXPECT_NEAR(r.solve.objective, 3 * slot, 1e-9);
  EXPECT_NEAR(r.solve.best_bound, 3 * slot, 1e-9);
  EXPECT_LT(r.search.lp_bound, slot);  // the LP alone: less than one slot
  EXPECT_GT(r.search.lp_bound, 0.0);
  ASSERT_FALSE(r.search.steps.empty());
  EXPECT_NE(r.search.steps.front().find("every schedule fires"), std::string::npos)
      << r.search.steps.front();
  EXPECT_TRUE(r.check.operational_ok) << r.check.Summary();
}

// On a problem with several burns the search and CBC alone agree, and the
// search is deterministic (node limits only).
TEST(SearchSchedule, AgreesWithCbcAloneAndIsDeterministic) {
  auto solver = milp::MakeCbcSolver();
  const ScheduleProblem p = SmallHcwDay();
  for (Encoding e : {Encoding::kThesis, Encoding::kTight}) {
    SolveScheduleOptions o;
    o.build.encoding = e;
    o.milp = Exact();
    const ScheduleResult a = SolveSchedule(p, *solver, o);
    const ScheduleResult b = SolveSchedule(p, *solver, o);
    // Lazy-row rounds that keep only their final solution (an earlier
    // release): the same optimum.
    o.search.restricted.lazy_row_options.keep_model_incumbents = false;
    const ScheduleResult final_solutions_only = SolveSchedule(p, *solver, o);
    o.search.restricted.lazy_rows = false;
    const ScheduleResult whole_rows = SolveSchedule(p, *solver, o);
    o.search.enabled = false;
    const ScheduleResult ref = SolveSchedule(p, *solver, o);
    ASSERT_EQ(ref.solve.status, milp::SolveStatus::kOptimal);
    ASSERT_EQ(a.solve.status, milp::SolveStatus::kOptimal) << a.solve.detail;
    EXPECT_NEAR(a.solve.objective, ref.solve.objective, 1e-9 * ref.solve.objective)
        << a.solve.detail;
    EXPECT_LE(a.search.lp_bound, ref.solve.objective + 1e-9);
    EXPECT_EQ(a.solve.objective, b.solve.objective);
    EXPECT_NEAR(whole_rows.solve.objective, ref.solve.objective, 1e-9 * ref.solve.objective);
    EXPECT_NEAR(final_solutions_only.solve.objective, ref.solve.objective,
                1e-9 * ref.solve.objective);
    EXPECT_EQ(a.schedule.pattern, b.schedule.pattern);
    EXPECT_EQ(a.search.steps.size(), b.search.steps.size());
    EXPECT_TRUE(a.check.operational_ok) << a.check.Summary();
  }
}

// The exact MILP on the tree's open leaves: with exact.max_slots below the whole
// MILP's free slots (782) and max_exact_leaf_slots above every slot (864),
// the search goes through the tree and then solves its open leaves exactly; it still ends at CBC's
// proven optimum (47 slots here; the tree alone stops at 45, total_branching_test.cc) with a bound
// never above it.
// The tree's root basis either by the crossover from step 1's interior point
// in the tree's LP session or by a second interior point: the same optimum.
TEST(SearchSchedule, SolvesTheTreesOpenLeavesExactly) {
  auto solver = milp::MakeCbcSolver();
  ScheduleProblem p = SmallHcwDay();
  p.initial_state[0] = 6000.0;
  p.initial_state[4] = 0.05;
  const ScheduleResult ref = CbcAlone(p, *solver);
  ASSERT_EQ(ref.solve.status, milp::SolveStatus::kOptimal);
  for (const bool from_relaxation : {true, false}) {
    SCOPED_TRACE(from_relaxation ? "root basis from the relaxation" : "second interior point");
    SolveScheduleOptions o;
    o.milp = Exact();
    o.search.exact.max_slots = 700;
    o.search.tree.max_exact_leaf_slots = 900;
    o.search.tree.root_from_relaxation = from_relaxation;
    const ScheduleResult r = SolveSchedule(p, *solver, o);
    std::string steps;
    for (const std::string& step : r.search.steps) steps += step + "\n";
    EXPECT_NE(steps.find("exact MILP of the leaf"), std::string::npos) << steps;
    EXPECT_NE(steps.find(from_relaxation ? "the root's by crossover from the relaxation's "
                                           "interior point"
                                         : "the root's by interior point and crossover"),
              std::string::npos)
        << steps;
    EXPECT_NEAR(r.solve.objective, ref.solve.objective, 1e-9 * ref.solve.objective) << steps;
    EXPECT_LE(r.solve.best_bound, ref.solve.objective + 1e-9) << steps;
    EXPECT_TRUE(r.check.operational_ok) << r.check.Summary();
  }
}

// The restricted MILP (condensed, only the free slots' columns) has the same
// optimum as the full sparse MILP with the other slots' on-columns fixed at 0.
TEST(FreeSlots, RestrictedCondensedMilpEqualsTheFullMilpWithSlotsForbidden) {
  auto solver = milp::MakeCbcSolver();
  ScheduleProblem p = SmallHcwDay();
  p.grid = dynamics::UniformGrid(0.0, 43200.0, 72);  // half a day: CBC proves each case quickly
  BuildOptions full_options;
  const ScheduleMilp full(p, full_options);
  const OperationalEncoding& enc = full.encoding();
  std::mt19937 rng(7);
  std::bernoulli_distribution keep(0.4);
  for (int trial = 0; trial < 2; ++trial) {
    Eigen::MatrixXi mask = Eigen::MatrixXi::Zero(enc.num_thrusters, enc.num_intervals);
    for (int i = 0; i < enc.num_thrusters; ++i) {
      for (int j = 0; j < enc.num_intervals; ++j) mask(i, j) = (j < 12 || keep(rng)) ? 1 : 0;
    }
    milp::LpData forbidden = full.lp();
    for (int i = 0; i < enc.num_thrusters; ++i) {
      for (int j = 0; j < enc.num_intervals; ++j) {
        if (mask(i, j) == 0) forbidden.col_upper[enc.on[i][j].index()] = 0.0;
      }
    }
    BuildOptions restricted_options;
    restricted_options.formulation = Formulation::kCondensed;
    restricted_options.free_slots = mask;
    const ScheduleMilp restricted(p, restricted_options);
    std::vector<int> kept;
    bool feasible = true;
    const milp::LpData small = milp::RemoveFixedColumns(restricted.lp(), &kept, &feasible);
    ASSERT_TRUE(feasible);
    EXPECT_LT(small.num_cols(), full.lp().num_cols() / 2);
    const milp::SolveResult a = solver->Solve(forbidden, Exact());
    const milp::SolveResult b = solver->Solve(small, Exact());
    // And by row generation over its dense window rows (milp/lazy_rows.h).
    milp::LazyRowOptions lazy;
    lazy.dense_row_min_nonzeros = 8;
    milp::LazyRowReport lazy_report;
    const milp::SolveResult c =
        milp::SolveWithLazyRows(*solver, small, Exact(), lazy, &lazy_report);
    ASSERT_EQ(a.status, milp::SolveStatus::kOptimal) << trial;
    ASSERT_EQ(b.status, milp::SolveStatus::kOptimal) << trial;
    ASSERT_EQ(c.status, milp::SolveStatus::kOptimal) << trial << " " << c.detail;
    EXPECT_NEAR(a.objective, b.objective, 1e-7 * std::max(1.0, a.objective)) << trial;
    EXPECT_NEAR(a.objective, c.objective, 1e-7 * std::max(1.0, a.objective)) << trial;
    EXPECT_TRUE(lazy_report.used) << c.detail;
    EXPECT_LT(lazy_report.final_rows, small.num_rows()) << c.detail;
    EXPECT_LE(small.MaxViolation(c.x), 1e-6);
    // The restricted optimum fires only free slots.
    for (size_t k = 0; k < kept.size(); ++k) {
      EXPECT_LE(restricted.lp().col_lower[kept[k]], restricted.lp().col_upper[kept[k]]);
    }
    for (int i = 0; i < enc.num_thrusters; ++i) {
      for (int j = 0; j < enc.num_intervals; ++j) {
        if (mask(i, j) == 0) {
          EXPECT_EQ(restricted.lp().col_upper[restricted.on(i, j).index()], 0.0);
        }
      }
    }
  }
}

// A verified start is kept even when no node may be explored, and an
// interrupt raised before the solve returns at once with that start.
TEST(SearchSchedule, KeepsAGivenStartAndHonoursAnInterrupt) {
  auto solver = milp::MakeCbcSolver();
  const ScheduleProblem p = SmallHcwDay();
  const ScheduleResult ref = CbcAlone(p, *solver);
  ASSERT_EQ(ref.solve.status, milp::SolveStatus::kOptimal);

  const ScheduleMilp milp(p, BuildOptions{});
  const Eigen::VectorXd start = milp.StartFromPattern(ref.schedule.pattern);
  std::atomic<bool> stop{true};
  milp::SolveOptions so = Exact();
  so.interrupt = &stop;
  SearchReport report;
  const milp::SolveResult r = SearchSchedule(milp, *solver, so, SearchOptions{}, {start}, &report);
  ASSERT_TRUE(r.has_solution()) << r.detail;
  EXPECT_NEAR(r.objective, ref.solve.objective, 1e-9);
  EXPECT_NE(r.detail.find("interrupted"), std::string::npos) << r.detail;
  EXPECT_EQ(report.steps.front().find("incumbent"), 0u) << report.steps.front();

  // An invalid start (wrong size) is ignored, not trusted.
  stop = false;
  so.max_nodes = 0;
  const milp::SolveResult s =
      SearchSchedule(milp, *solver, so, SearchOptions{}, {Eigen::VectorXd::Ones(3)}, &report);
  ASSERT_TRUE(s.has_solution()) << s.detail;
  EXPECT_GE(s.objective, ref.solve.objective - 1e-9);
  EXPECT_LE(s.best_bound, ref.solve.objective + 1e-9);
}

// Step 5, CBC on the whole MILP (forced: no exact restricted solve, of the
// MILP or of the tree's leaves, no improvement, no objective step): on its own (the default) or
// from the search's incumbent, it ends at CBC alone's optimum; with no node for it, the incumbent
// of the restricted MILP is kept, never a worse or missing schedule.
TEST(SearchSchedule, WholeMilpWithOrWithoutTheIncumbentKeepsTheBest) {
  auto solver = milp::MakeCbcSolver();
  ScheduleProblem p = SmallHcwDay();
  // A cost per burn start that is no multiple of a slot's: no objective
  // step, so the LP bound alone cannot prove the restricted MILP's schedule.
  p.objective.burn_start_penalty = 0.0037;
  const ScheduleResult ref = CbcAlone(p, *solver);
  ASSERT_EQ(ref.solve.status, milp::SolveStatus::kOptimal);

  const ScheduleMilp milp(p, BuildOptions{});
  SearchOptions forced;
  forced.exact.max_slots = 0;
  forced.tree.max_exact_leaf_slots = 0;
  forced.nets.improvement_rounds = 0;
  forced.disabled_phases = {"exchange"};
  forced.nets.neighbourhood = 0;
  {
    SearchReport report;
    const milp::SolveResult r = SearchSchedule(milp, *solver, Exact(), forced, {}, &report);
    ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << r.detail;
    EXPECT_NEAR(r.objective, ref.solve.objective, 1e-9 * ref.solve.objective) << r.detail;
    ASSERT_TRUE(report.whole_milp) << r.detail;
  }
  // No node for the whole MILP: the restricted MILP's schedule is the result.
  milp::SolveOptions none = Exact();
  none.max_nodes = 0;
  SearchReport report;
  const milp::SolveResult r = SearchSchedule(milp, *solver, none, forced, {}, &report);
  ASSERT_TRUE(r.has_solution()) << r.detail;
  EXPECT_GE(r.objective, ref.solve.objective - 1e-9);
  EXPECT_LE(milp.lp().MaxViolation(r.x), 1e-6);
}

// Step 4c, the exchange along an axis. Ideal six in Hill-Clohessy-Wiltshire:
// three axes, and the rows split into the orbit plane's block and its
// normal's, tied only by the rules; Anzel's four thrusters, one axis each.

// The exchange needs two axes, one of them a pair, whatever the encoding:
// the ideal six (and the ideal six without -R) have pairs on three axes;
// the thesis' four Anzel thrusters lie on four axes, one each; +N and -N
// alone are one axis, nothing to keep while it is exchanged.
TEST(AxisExchangeApplies, NeedsTwoAxesOneOfThemAPair) {
  const dynamics::ThrusterSet six = dynamics::ThrusterSet::Ideal6(1, 1, 1);
  EXPECT_TRUE(AxisExchangeApplies(six));
  EXPECT_TRUE(AxisExchangeApplies(six.Subset({"+R", "+T", "+N", "-T", "-N"})));
  EXPECT_FALSE(AxisExchangeApplies(six.Subset({"+N", "-N"})));
  EXPECT_FALSE(AxisExchangeApplies(six.Subset({"+R", "+T", "+N"})));
  EXPECT_FALSE(AxisExchangeApplies(dynamics::ThrusterSet::Anzel4(1, 1, 1)));
}

// From the restricted MILP's schedule the exchange along one axis reaches
// CBC alone's proven optimum, where without it the search only gets there
// by CBC on the whole MILP (step 5).
TEST(SearchSchedule, ExchangeAlongAnAxisReachesCbcAlonesOptimum) {
  const std::vector<ThrusterGroup> six = ThrusterAxes(dynamics::ThrusterSet::Ideal6(1, 1, 1));
  ASSERT_EQ(six.size(), 3u);
  EXPECT_EQ(six[0].thrusters, (std::vector<int>{0, 3}));
  EXPECT_EQ(six[1].thrusters, (std::vector<int>{1, 4}));
  EXPECT_EQ(six[2].thrusters, (std::vector<int>{2, 5}));
  EXPECT_EQ(six[1].name, "+T and -T");
  EXPECT_EQ(ThrusterAxes(dynamics::ThrusterSet::Anzel4(1, 1, 1)).size(), 4u);

  auto solver = milp::MakeCbcSolver();
  ScheduleProblem p = SmallHcwDay();
  p.initial_state[5] = 3.0;  // out of plane: 41 km amplitude, the window 36.8 km
  const ScheduleResult ref = CbcAlone(p, *solver);
  ASSERT_EQ(ref.solve.status, milp::SolveStatus::kOptimal);
  const ScheduleMilp milp(p, BuildOptions{});
  EXPECT_EQ(FindDormantThrusters(milp).num_blocks, 2);  // the plane, its normal
  // The start: a schedule whose in-plane firings (+-R, +-T) keep 6 slots
  // away from the optimum's (CBC with those slots forbidden).
  const OperationalEncoding& enc = milp.encoding();
  milp::LpData away = milp.lp();
  for (int i = 0; i < enc.num_thrusters; ++i) {
    if (i == 2 || i == 5) continue;  // +N, -N
    for (int j = 0; j < enc.num_intervals; ++j) {
      for (int d = -6; d <= 6; ++d) {
        if (j + d >= 0 && j + d < enc.num_intervals && ref.schedule.pattern(i, j + d) != 0)
          away.col_upper[enc.on[i][j].index()] = 0.0;
      }
    }
  }
  milp::SolveOptions loose = Exact();
  loose.relative_gap = 0.2;
  const milp::SolveResult start = solver->Solve(away, loose);
  ASSERT_TRUE(start.has_solution()) << start.detail;
  SearchOptions only;  // the heuristic's first net, then the exchange, then step 5
  only.exact.max_slots = 0;
  only.nets.improvement_rounds = 0;
  only.tree.max_lps = 0;
  only.nets.neighbourhood = 0;
  only.nets.max_widenings = 0;
  for (const bool exchange : {true, false}) {
    only.disabled_phases =
        exchange ? std::vector<std::string>{} : std::vector<std::string>{"exchange"};
    SearchReport report;
    const milp::SolveResult r = SearchSchedule(milp, *solver, Exact(), only, {start.x}, &report);
    std::string steps;
    for (const std::string& step : report.steps) steps += step + "\n";
    ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << steps;
    EXPECT_NEAR(r.objective, ref.solve.objective, 1e-9) << steps;
    const std::string optimum = "incumbent " + common::FormatG(ref.solve.objective, 6) + " from ";
    const bool by_exchange =
        steps.find(optimum + "the exchange along an axis") != std::string::npos;
    const bool by_cbc = steps.find(optimum + "cbc on the whole MILP") != std::string::npos;
    EXPECT_EQ(by_exchange, exchange) << steps;
    EXPECT_EQ(by_cbc, !exchange) << steps;
  }
}

// Step 2's widening ends at a net above max_widened_slots, with a step that
// says so, and the search goes on to CBC on the whole MILP (its optimum).
// With every slot of LP on-value above 0.99 and no neighbours, this day's
// first net (8 slots) holds no schedule and its first widening has 48.
TEST(SearchSchedule, TheCapOnTheNetsEndsTheWidening) {
  auto solver = milp::MakeCbcSolver();
  const ScheduleProblem p = SmallHcwDay();
  const ScheduleResult ref = CbcAlone(p, *solver);
  ASSERT_EQ(ref.solve.status, milp::SolveStatus::kOptimal);
  const ScheduleMilp milp(p, BuildOptions{});
  SearchOptions only;
  only.nets.candidate_threshold = 0.99;
  only.nets.neighbourhood = 0;
  only.exact.max_slots = 0;
  only.nets.improvement_rounds = 0;
  only.tree.max_lps = 0;
  only.disabled_phases = {"exchange"};
  for (const int cap : {40, 48}) {
    only.nets.max_widened_slots = cap;
    SearchReport report;
    const milp::SolveResult r = SearchSchedule(milp, *solver, Exact(), only, {}, &report);
    std::string steps;
    for (const std::string& step : report.steps) steps += step + "\n";
    ASSERT_EQ(r.status, milp::SolveStatus::kOptimal) << steps;
    EXPECT_NEAR(r.objective, ref.solve.objective, 1e-9) << steps;
    EXPECT_NE(steps.find("MILP restricted to 8 candidate slots (26 columns, 229 rows): infeasible, "
                         "widened"),
              std::string::npos)
        << steps;
    const bool capped =
        steps.find("the next net has 48 slots (more than 40): not widened further") !=
        std::string::npos;
    EXPECT_EQ(capped, cap == 40) << steps;
    EXPECT_EQ(report.whole_milp, cap == 40) << steps;
    EXPECT_EQ(steps.find("MILP restricted to 48 candidate slots") != std::string::npos, cap == 48)
        << steps;
  }
}

// The search does not start condensing a net that would not be ready before
// its time limit; the estimate scales the largest net built so far.
TEST(RestrictionBuildSeconds, ScalesTheLargestNetBuiltLinearly) {
  EXPECT_NEAR(internal::RestrictionBuildSeconds(4043, 546, 0.71), 0.71 * 4043.0 / 546.0, 1e-12);
  EXPECT_NEAR(internal::RestrictionBuildSeconds(273, 546, 0.71), 0.355, 1e-12);
  EXPECT_EQ(internal::RestrictionBuildSeconds(4043, 0, 0.0), 0.0);  // none built yet
  EXPECT_EQ(internal::RestrictionBuildSeconds(0, 546, 0.71), 0.0);  // an empty net
  // A net built within the clock's tick says nothing of the next one.
  EXPECT_EQ(internal::RestrictionBuildSeconds(100, 546, 0.0), 0.0);
}

// The one-day problem of SolvesTheTreesOpenLeavesExactly, where the
// exact MILP is capped below its free slots so that the tree, its leaves
// and the later phases run.
struct HcwDayWithTree {
  std::unique_ptr<milp::Solver> solver = milp::MakeCbcSolver();
  ScheduleProblem problem = [] {
    ScheduleProblem p = SmallHcwDay();
    p.initial_state[0] = 6000.0;
    p.initial_state[4] = 0.05;
    return p;
  }();
  ScheduleResult ref = CbcAlone(problem, *solver);
  SolveScheduleOptions Options() const {
    SolveScheduleOptions o;
    o.milp = Exact();
    o.search.exact.max_slots = 700;
    o.search.tree.max_exact_leaf_slots = 900;
    return o;
  }
};

bool RanPhase(const SearchReport& report, const std::string& phase) {
  for (const std::string& step : report.steps) {
    if (step.rfind(phase + ": ", 0) == 0) return true;
  }
  return false;
}

// Each phase left out in turn (SearchOptions::disabled_phases): the result
// is still right against CBC alone (perhaps slower, perhaps unproven when
// the phase left out is the one that proves it), the step log never names
// the phase, and every schedule passes the checker.
TEST(SearchPlan, EachPhaseDisabledInTurnKeepsTheResultRight) {
  const HcwDayWithTree day;
  ASSERT_EQ(day.ref.solve.status, milp::SolveStatus::kOptimal);
  const double optimum = day.ref.solve.objective, tol = 1e-9 * optimum;
  {
    const ScheduleResult all = SolveSchedule(day.problem, *day.solver, day.Options());
    for (const char* phase : {"relaxation", "nets", "tree", "exact"})
      EXPECT_TRUE(RanPhase(all.search, phase)) << phase << "\n" << all.solve.detail;
  }
  for (const std::string& phase : SearchPhaseNames()) {
    SCOPED_TRACE("without " + phase);
    SolveScheduleOptions o = day.Options();
    o.search.disabled_phases = {phase};
    const ScheduleResult r = SolveSchedule(day.problem, *day.solver, o);
    EXPECT_FALSE(RanPhase(r.search, phase)) << r.solve.detail;
    ASSERT_TRUE(r.solve.has_solution()) << r.solve.detail;
    EXPECT_GE(r.solve.objective, optimum - tol) << r.solve.detail;
    EXPECT_LE(r.solve.best_bound, optimum + tol) << r.solve.detail;
    if (r.solve.status == milp::SolveStatus::kOptimal) {
      EXPECT_NEAR(r.solve.objective, optimum, tol) << r.solve.detail;
    }
    // Only the whole MILP's solver can be needed for the proof here.
    if (phase != "whole_milp") {
      EXPECT_EQ(r.solve.status, milp::SolveStatus::kOptimal);
    }
    EXPECT_TRUE(r.check.operational_ok) << r.check.Summary();
  }
}

// A technique's place is one line of the plan: the nets moved after every
// other phase (and the whole MILP left out) run last, on the same state,
// and their schedule is the result. Nothing of the search but the plan
// changes.
TEST(SearchPlan, APhaseMovedLastInThePlanRunsLast) {
  const HcwDayWithTree day;
  const ScheduleMilp milp(day.problem, BuildOptions{});
  SearchPlan plan = DefaultSearchPlan();
  const auto nets = std::find_if(plan.begin(), plan.end(),
                                 [](const PlanStep& s) { return s.phase->name() == "nets"; });
  ASSERT_NE(nets, plan.end());
  const PlanStep moved = *nets;
  plan.erase(nets);
  plan.push_back(moved);
  SearchOptions search;
  search.disabled_phases = {"whole_milp"};
  SearchReport report;
  const milp::SolveResult r =
      SearchScheduleWithPlan(plan, milp, *day.solver, Exact(), search, {}, &report);
  ASSERT_TRUE(r.has_solution()) << r.detail;
  ASSERT_GE(report.steps.size(), 3u);
  EXPECT_EQ(report.steps.front().rfind("relaxation: ", 0), 0u) << r.detail;
  EXPECT_EQ(report.steps.back().rfind("nets: incumbent ", 0), 0u) << r.detail;
  EXPECT_GE(r.objective, day.ref.solve.objective - 1e-9 * day.ref.solve.objective);
  EXPECT_LE(milp.lp().MaxViolation(r.x), 1e-6);
}

TEST(SearchOptions, InvalidValuesAreNamedByTheirPath) {
  std::string error;
  EXPECT_TRUE(SearchOptions{}.IsValid(&error));
  struct Case {
    std::function<void(SearchOptions*)> set;
    std::string message;
  };
  const std::vector<Case> cases = {
      {[](SearchOptions* s) { s->nets.candidate_threshold = 1.5; },
       "search.nets.candidate_threshold must be in (0, 1), got 1.5"},
      {[](SearchOptions* s) { s->nets.max_widened_slots = -3; },
       "search.nets.max_widened_slots must be >= 0, got -3"},
      {[](SearchOptions* s) { s->nets.neighbourhood = -1; },
       "search.nets.neighbourhood must be >= 0, got -1"},
      {[](SearchOptions* s) { s->nets.improvement_rounds = -2; },
       "search.nets.improvement_rounds must be >= 0, got -2"},
      {[](SearchOptions* s) { s->nets.time_share = 0.0; },
       "search.nets.time_share must be in (0, 1], got 0"},
      {[](SearchOptions* s) { s->nets.improvement_time_share = 1.5; },
       "search.nets.improvement_time_share must be in (0, 1], got 1.5"},
      {[](SearchOptions* s) { s->tree.window_levels = 17; },
       "search.tree.window_levels must be in [0, 16], got 17"},
      {[](SearchOptions* s) { s->tree.max_exact_leaf_slots = -5; },
       "search.tree.max_exact_leaf_slots must be >= 0, got -5"},
      {[](SearchOptions* s) { s->tree.other_leaf_nets = -1; },
       "search.tree.other_leaf_nets must be >= 0, got -1"},
      {[](SearchOptions* s) { s->tree.max_lps = -3; }, "search.tree.max_lps must be >= 0, got -3"},
      {[](SearchOptions* s) { s->exchange.max_slots = -4; },
       "search.exchange.max_slots must be >= 0, got -4"},
      {[](SearchOptions* s) { s->exchange.time_share = 1.5; },
       "search.exchange.time_share must be in (0, 1], got 1.5"},
      {[](SearchOptions* s) { s->exact.time_share_before_tree = -0.5; },
       "search.exact.time_share_before_tree must be in (0, 1], got -0.5"},
      {[](SearchOptions* s) { s->restricted.max_nodes = -1; },
       "search.restricted.max_nodes must be >= 0, got -1"},
      {[](SearchOptions* s) { s->restricted.lazy_row_options.max_rounds = 0; },
       "search.restricted.lazy_row_options: LazyRowOptions: max_rounds"},
      {[](SearchOptions* s) { s->plan = "fastest"; },
       "search.plan must be one of default, exact_first, got \"fastest\""},
      {[](SearchOptions* s) {
         s->disabled_phases = {"nets", "exchnage"};
       },
       "search.disabled_phases[1] must be a phase (relaxation, nets, tree, exact, improvement, "
       "exchange, windows, whole_milp), got \"exchnage\""},
  };
  for (const Case& c : cases) {
    SearchOptions s;
    c.set(&s);
    error.clear();
    EXPECT_FALSE(s.IsValid(&error)) << c.message;
    EXPECT_NE(error.find(c.message), std::string::npos) << error;
  }
}

}  // namespace
}  // namespace thrustsched::transcription
