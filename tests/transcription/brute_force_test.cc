// The whole scheduling MILP (rules + dynamics + window + terminal + objective)
// against exhaustive enumeration: on small 3-D double-integrator problems with
// a non-uniform grid, every on/off pattern of the thrusters is evaluated
// independently of the transcription,
//   rules     : CheckOperationalRules on the pattern's burns (continuous time;
//               itself cross-checked against the encodings exhaustively in
//               encodings_exhaustive_test.cc),
//   dynamics  : closed-form constant-acceleration motion (x + v h + a h^2 / 2),
//               no discretisation code,
//   window    : |position| at the nodes (and at the interior points when
//               intersample points are asked for), with the planning margin,
//               hard or soft (penalty x violation / half width),
//   terminal  : a box on the final state,
//   cost      : L1 (sum |a| components x time), Euclidean delta-v, propellant,
//               plus a penalty per burn start,
// and the minimum over all patterns must be the MILP's proven optimum (or the
// MILP must prove infeasibility when no pattern qualifies), for both
// formulations and both encodings.
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/models.h"
#include "milp/cbc_solver.h"
#include "transcription/checker.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"

namespace thrustsched::transcription {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kG0 = 9.80665;  // standard gravity (m/s^2), for the propellant mass flow

struct Case {
  std::string name;
  ObjectiveKind objective = ObjectiveKind::kL1;
  double burn_start_penalty = 0.0;
  int intersample_points = 0;
  bool soft = false;
  double soft_penalty = 1.0;
  double margin = 0.0;
  double half_width_m = 146.3;
  bool terminal_box = false;
  double terminal_position_m = 80.0;  // terminal box: |x|, |y| at the end (velocity free)
  Formulation formulation = Formulation::kSparse;
  Encoding encoding = Encoding::kTight;
  Eigen::Vector3d v0 = Eigen::Vector3d(0.843, 0.408, 0.0);  // m/s
  double thrust_n = 0.38;
  double enforce_from_s = 0;
  // Path constraints (ScheduleProblem::state_constraints): one between nodes,
  // one at the last node, on positions and velocities together.
  std::vector<StateConstraint> path{};
  Case& WithPathConstraints(double y_plus_vy_max, double x_minus_vx_min) {
    path = {
        {250.0, (Eigen::VectorXd(6) << 0, 1, 0, 0, 40, 0).finished(), -kInf, y_plus_vy_max,
         "y_plus_vy_at_250"},
        {600.0, (Eigen::VectorXd(6) << 1, 0, 0, -60, 0, 0).finished(), x_minus_vx_min, kInf, ""}};
    return *this;
  }
  // A start for which the motion between nodes matters: with 2 interior
  // points per interval the optimum costs more (found by a parameter search).
  Case& WithInterSampleDrift(int points) {
    v0 = Eigen::Vector3d(0.880, 0.378, 0.0);
    half_width_m = 137.1;
    thrust_n = 0.596;
    intersample_points = points;
    return *this;
  }
};

// gtest prints a failing case's parameter: its name, not raw bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

// Thrust ~0.4-0.6 N on 100 kg, Isp 300 s. Directions (RTN = x, y, z of
// the double integrator): B pushes -x (L1 factor a), C pushes -x-y at 45 deg
// (L1 factor sqrt(2) a): the L1 and Euclidean objectives weigh them differently.
dynamics::ThrusterSet Thrusters(double thrust_n) {
  return dynamics::ThrusterSet(
      {{"B", Eigen::Vector3d(-1, 0, 0), true}, {"C", Eigen::Vector3d(-1, -1, 0), true}}, thrust_n,
      100.0, 300.0);
}

const std::vector<double> kGrid = {0, 60, 150, 210, 300, 360, 480, 540, 600};  // 8 intervals

ScheduleProblem MakeProblem(const Case& c) {
  ScheduleProblem p;
  p.model = std::make_shared<dynamics::DoubleIntegrator3d>(100.0, 100.0);
  p.thrusters = Thrusters(c.thrust_n);
  p.grid = kGrid;
  p.initial_state = Eigen::VectorXd::Zero(6);
  p.initial_state.segment<3>(3) = c.v0;
  p.rules.max_simultaneous = 1;
  p.rules.min_burn_s = 100;  // 2 intervals of 60 s, or one of 120 s
  p.rules.min_off_same_s = 150;
  p.rules.min_gap_other_s = 60;
  p.window.outputs = {0, 1};  // x, y (m)
  p.window.half_widths = {c.half_width_m, c.half_width_m};
  p.window.enforce_from_s = c.enforce_from_s;  // nodes (and interior points) from then on
  p.window.intersample_points = c.intersample_points;
  p.window.soft = c.soft;
  p.window.soft_penalty = c.soft_penalty;
  p.window.margin = c.margin;
  if (c.terminal_box) {
    p.terminal.kind = TerminalKind::kStateBox;
    p.terminal.target = Eigen::VectorXd::Zero(6);
    const double d = c.terminal_position_m;
    p.terminal.tolerance = (Eigen::VectorXd(6) << d, d, kInf, kInf, kInf, kInf).finished();
  }
  p.objective.kind = c.objective;
  p.objective.burn_start_penalty = c.burn_start_penalty;
  p.state_constraints = c.path;
  return p;
}

std::vector<Burn> BurnsOfPattern(unsigned pattern, int m, const std::vector<double>& grid) {
  const int n = static_cast<int>(grid.size()) - 1;
  std::vector<Burn> burns;
  for (int i = 0; i < m; ++i) {
    int j = 0;
    while (j < n) {
      if (((pattern >> (i * n + j)) & 1u) == 0) {
        ++j;
        continue;
      }
      int k = j;
      while (k < n && ((pattern >> (i * n + k)) & 1u) != 0) ++k;
      burns.push_back({i, grid[j], grid[k]});
      j = k;
    }
  }
  return burns;
}

struct Reference {
  bool feasible = false;
  double cost = kInf;
  unsigned pattern = 0;
  long long rule_ok_patterns = 0;
};

// Exhaustive minimum, independent of the transcription code.
Reference Enumerate(const Case& c) {
  const ScheduleProblem p = MakeProblem(c);
  const int m = p.thrusters.size();
  const int n = p.num_intervals();
  const double a = p.thrusters.acceleration();
  const double w = c.half_width_m * (1.0 - c.margin);
  std::vector<Eigen::Vector3d> accel(m);
  std::vector<double> rate(m);
  for (int i = 0; i < m; ++i) {
    const Eigen::Vector3d d = p.thrusters.thruster(i).direction.normalized();
    accel[i] = a * d;
    switch (c.objective) {
      case ObjectiveKind::kL1:
        rate[i] = accel[i].lpNorm<1>();
        break;
      case ObjectiveKind::kDeltaV:
        rate[i] = a;
        break;
      case ObjectiveKind::kPropellant:
        rate[i] = c.thrust_n / (kG0 * 300.0);
        break;  // F/(g0 Isp)
    }
  }
  // The rules, grid and thruster count are the same in every case: the
  // patterns that pass the rule checker are found once.
  static const std::vector<std::pair<unsigned, int>> kRuleOk = [&] {
    std::vector<std::pair<unsigned, int>> ok;  // pattern, number of burns
    for (unsigned pattern = 0; pattern < (1u << (m * n)); ++pattern) {
      const std::vector<Burn> burns = BurnsOfPattern(pattern, m, p.grid);
      if (CheckOperationalRules(p.rules, p.history, p.forced_off, m, p.grid.front(), p.grid.back(),
                                burns)
              .empty()) {
        ok.emplace_back(pattern, static_cast<int>(burns.size()));
      }
    }
    return ok;
  }();
  Reference ref;
  for (const auto& [pattern, num_burns] : kRuleOk) {
    ++ref.rule_ok_patterns;
    double cost = c.burn_start_penalty * num_burns;
    double violation = 0.0;  // sum over constrained points and outputs of max(0, |y| / w - 1)
    bool window_ok = true;
    auto judge = [&](const Eigen::Vector3d& r, double t) {
      if (t < p.window.enforce_from_s - 1e-9) return;
      for (int k = 0; k < 2; ++k) {
        const double excess = std::abs(r[k]) / w - 1.0;
        if (excess > 1e-9) window_ok = false;
        violation += std::max(0.0, excess);
      }
    };
    bool path_ok = true;
    auto judge_path = [&](const StateConstraint& s, const Eigen::Vector3d& r,
                          const Eigen::Vector3d& v) {
      Eigen::VectorXd x(6);
      x << r, v;
      const double value = s.a.dot(x);
      if (value < s.lower - 1e-9 || value > s.upper + 1e-9) path_ok = false;
    };
    Eigen::Vector3d r = Eigen::Vector3d::Zero(), v = c.v0;
    for (int j = 0; j < n; ++j) {
      const double h = p.grid[j + 1] - p.grid[j];
      Eigen::Vector3d acc = Eigen::Vector3d::Zero();
      for (int i = 0; i < m; ++i) {
        if (((pattern >> (i * n + j)) & 1u) != 0) {
          acc += accel[i];
          cost += rate[i] * h;
        }
      }
      for (const StateConstraint& s : c.path) {
        const double tau = s.t_s - p.grid[j];
        if (tau >= 0.0 && tau < h) {
          judge_path(s, r + v * tau + 0.5 * acc * tau * tau, v + acc * tau);
        }
      }
      for (int s = 1; s <= c.intersample_points; ++s) {
        const double tau = h * s / (c.intersample_points + 1);
        judge(r + v * tau + 0.5 * acc * tau * tau, p.grid[j] + tau);
      }
      r += v * h + 0.5 * acc * h * h;
      v += acc * h;
      judge(r, p.grid[j + 1]);
    }
    for (const StateConstraint& s : c.path) {
      if (s.t_s >= p.grid.back()) judge_path(s, r, v);  // at the last node
    }
    if (!path_ok) continue;
    if (c.terminal_box && (std::abs(r[0]) > c.terminal_position_m + 1e-9 ||
                           std::abs(r[1]) > c.terminal_position_m + 1e-9)) {
      continue;
    }
    if (c.soft) {
      cost += c.soft_penalty * violation;
    } else if (!window_ok) {
      continue;
    }
    if (cost < ref.cost) {
      ref.cost = cost;
      ref.pattern = pattern;
      ref.feasible = true;
    }
  }
  return ref;
}

class BruteForceTest : public ::testing::TestWithParam<Case> {};

TEST_P(BruteForceTest, MilpOptimumEqualsExhaustiveMinimum) {
  const Case& c = GetParam();
  const Reference ref = Enumerate(c);
  ASSERT_GT(ref.rule_ok_patterns, 100);  // the rules leave real choices
  const ScheduleProblem p = MakeProblem(c);
  SolveScheduleOptions o;
  o.build.formulation = c.formulation;
  o.build.encoding = c.encoding;
  o.milp.relative_gap = 0.0;
  o.milp.absolute_gap = 0.0;
  o.milp.time_limit_s = 120;
  const auto solver = milp::MakeCbcSolver();
  const ScheduleResult r = SolveSchedule(p, *solver, o);
  if (!ref.feasible) {
    EXPECT_EQ(r.solve.status, milp::SolveStatus::kInfeasible) << r.solve.detail;
    return;
  }
  ASSERT_EQ(r.solve.status, milp::SolveStatus::kOptimal) << r.solve.detail;
  const double tol = 1e-7 * std::max(1.0, std::abs(ref.cost));
  EXPECT_NEAR(r.solve.objective, ref.cost, tol)
      << "exhaustive optimum: " << BurnsOfPattern(ref.pattern, 2, kGrid).size() << " burns";
  // The decoded schedule passes the rule checker and its totals match the
  // objective's physics (no penalties in these terms).
  EXPECT_TRUE(r.check.operational_ok);
  EXPECT_LE(r.check.max_state_constraint_violation, 1e-6);
  double on_time = 0.0;
  for (const Burn& b : r.schedule.burns) on_time += b.duration_s();
  EXPECT_NEAR(r.schedule.delta_v_m_s, c.thrust_n / 100.0 * on_time, 1e-9);
}

// The cases must not be trivial: the optimum fires both thrusters, and each
// option changes it.
TEST(BruteForceReference, CasesAreDiscriminating) {
  const Case base{"base"};
  const Reference l1 = Enumerate(base);
  ASSERT_TRUE(l1.feasible);
  EXPECT_NE(l1.pattern & 0xffu, 0u);    // B fires
  EXPECT_NE(l1.pattern & 0xff00u, 0u);  // C fires
  Case free = base;
  free.half_width_m = 1e6;  // no window in effect: firing only costs
  EXPECT_EQ(Enumerate(free).cost, 0.0);
  Case dv = base;
  dv.objective = ObjectiveKind::kDeltaV;
  EXPECT_NE(Enumerate(dv).pattern, l1.pattern);  // C is relatively cheaper in delta-v
  Case drift = base;
  drift.WithInterSampleDrift(0);
  const Reference at_nodes = Enumerate(drift);
  ASSERT_TRUE(at_nodes.feasible);
  drift.intersample_points = 2;
  const Reference between = Enumerate(drift);
  ASSERT_TRUE(between.feasible);
  EXPECT_GT(between.cost, at_nodes.cost + 1e-6);  // excursions between nodes cost fuel
  Case margin = base;
  margin.margin = 0.2;
  EXPECT_GT(Enumerate(margin).cost, l1.cost + 1e-6);
  Case terminal = base;
  terminal.terminal_box = true;
  EXPECT_GT(Enumerate(terminal).cost, l1.cost + 1e-6);
  drift.terminal_box = true;  // (intersample points 2)
  const Reference drift_terminal = Enumerate(drift);
  ASSERT_TRUE(drift_terminal.feasible);
  EXPECT_GT(drift_terminal.cost, between.cost + 1e-6);
  Case path = base;
  path.WithPathConstraints(90.0, 100.0);
  const Reference constrained = Enumerate(path);
  ASSERT_TRUE(constrained.feasible);
  EXPECT_GT(constrained.cost, l1.cost + 1e-6);  // the optimum without them breaks them ...
  const CheckReport unconstrained =
      CheckSchedule(MakeProblem(path), BurnsOfPattern(l1.pattern, 2, kGrid));
  // ... the first: y + 40 vy = 111.87 m at 250 s, not <= 90 m
  EXPECT_NEAR(unconstrained.max_state_constraint_violation, 111.871 - 90.0, 0.01);
  EXPECT_EQ(unconstrained.worst_state_constraint, 0);
  Case tight = base;
  tight.half_width_m = 40.0;
  EXPECT_FALSE(Enumerate(tight).feasible);  // hard: infeasible ...
  tight.soft = true;
  tight.soft_penalty = 0.5;
  EXPECT_TRUE(Enumerate(tight).feasible);  // ... soft: the least-violating schedule
}

std::vector<Case> Cases() {
  std::vector<Case> v;
  v.push_back({"l1"});
  Case c{"delta_v"};
  c.objective = ObjectiveKind::kDeltaV;
  v.push_back(c);
  c = Case{"propellant"};
  c.objective = ObjectiveKind::kPropellant;
  v.push_back(c);
  c = Case{"burn_start_penalty"};
  c.burn_start_penalty = 0.05;
  v.push_back(c);
  c = Case{"intersample"};
  c.WithInterSampleDrift(2);
  v.push_back(c);
  c = Case{"intersample_reference_at_nodes"};
  c.WithInterSampleDrift(0);
  v.push_back(c);
  c = Case{"margin"};
  c.margin = 0.2;
  v.push_back(c);
  c = Case{"terminal_box"};
  c.terminal_box = true;
  v.push_back(c);
  c = Case{"infeasible"};
  c.half_width_m = 40.0;
  v.push_back(c);
  c = Case{"soft_window"};
  c.half_width_m = 40.0;
  c.soft = true;
  c.soft_penalty = 0.5;
  v.push_back(c);
  c = Case{"soft_window_intersample"};
  c.half_width_m = 40.0;
  c.soft = true;
  c.soft_penalty = 0.5;
  c.intersample_points = 1;
  v.push_back(c);
  c = Case{"path_constraints"};
  c.WithPathConstraints(90.0, 100.0);
  v.push_back(c);
  c = Case{"path_constraints_condensed"};
  c.WithPathConstraints(90.0, 100.0);
  c.formulation = Formulation::kCondensed;
  v.push_back(c);
  c = Case{"path_constraints_intersample_terminal"};
  c.WithInterSampleDrift(2);
  c.terminal_box = true;
  c.WithPathConstraints(90.0, 100.0);
  v.push_back(c);
  // Formulations and encodings on the richer cases.
  for (Formulation f : {Formulation::kSparse, Formulation::kCondensed}) {
    for (Encoding e : {Encoding::kTight, Encoding::kThesis}) {
      if (f == Formulation::kSparse && e == Encoding::kTight) continue;  // the cases above
      const std::string tag = std::string(f == Formulation::kSparse ? "sparse" : "condensed") +
                              "_" + (e == Encoding::kTight ? "tight" : "thesis");
      c = Case{tag + "_intersample_terminal"};
      c.WithInterSampleDrift(2);
      c.terminal_box = true;
      c.formulation = f;
      c.encoding = e;
      v.push_back(c);
      c = Case{tag + "_soft_penalty"};
      c.half_width_m = 40.0;
      c.soft = true;
      c.soft_penalty = 0.5;
      c.burn_start_penalty = 0.05;
      c.objective = ObjectiveKind::kDeltaV;
      c.formulation = f;
      c.encoding = e;
      v.push_back(c);
    }
  }
  return v;
}

// Bad path constraints are refused by name and value, never built.
TEST(BruteForceReference, BadStateConstraintsNameTheField) {
  const auto refused = [](const Case& c, const std::string& what) {
    std::string error;
    EXPECT_FALSE(MakeProblem(c).IsValid(&error)) << what;
    EXPECT_NE(error.find(what), std::string::npos) << error;
  };
  Case c{"bad"};
  c.WithPathConstraints(90.0, 100.0);
  c.path[1].t_s = 601.0;
  refused(c, "state_constraints[1].t_s 601 s is outside the horizon [0, 600] s");
  c.WithPathConstraints(90.0, 100.0);
  c.path[0].a = Eigen::VectorXd::Ones(3);
  refused(c, "state_constraints[0].a must have 6 finite entries, got 3");
  c.WithPathConstraints(90.0, 100.0);
  c.path[0].upper = kInf;
  refused(c, "state_constraints[0]: bounds [-inf, inf] must be ordered, one of them finite");
  c.WithPathConstraints(90.0, 100.0);
  c.path[1].name = c.path[0].name;
  refused(c, "state_constraints[1].name \"y_plus_vy_at_250\" is used twice");
  c.WithPathConstraints(90.0, 100.0);
  c.path[0].name = "1";  // the other's index
  refused(c, "state_constraints[1].name \"\" is used twice");
  c.WithPathConstraints(90.0, 100.0);
  ScheduleProblem impulsive = MakeProblem(c);
  impulsive.input_mode = InputMode::kImpulsive;
  std::string error;
  EXPECT_FALSE(impulsive.IsValid(&error));
  EXPECT_NE(error.find("state_constraints: only in the on-off input mode"), std::string::npos)
      << error;
}

// CLP 1.17's interior point aborts the process on this relaxation ("primal
// off to infinity"): in its child process the abort costs only the attempt,
// the primal simplex gives the relaxation, and the caller lives on.
TEST(BruteForceReference, InteriorPointAbortIsContained) {
  Case c{"condensed_tight_intersample_terminal"};
  c.WithInterSampleDrift(2);
  c.terminal_box = true;
  c.formulation = Formulation::kCondensed;
  BuildOptions b;
  b.formulation = c.formulation;
  b.encoding = c.encoding;
  const ScheduleMilp milp(MakeProblem(c), b);
  const auto solver = milp::MakeCbcSolver();
  milp::SolveOptions o;
  o.lp_algorithm = milp::LpAlgorithm::kPrimal;
  const milp::LpRelaxationResult simplex = solver->SolveLpRelaxation(milp.lp(), o);
  ASSERT_EQ(simplex.status, milp::SolveStatus::kOptimal);
  o.lp_algorithm = milp::LpAlgorithm::kBarrierNoCrossover;
  ASSERT_TRUE(o.cbc.separate_process);
  const milp::LpRelaxationResult interior = solver->SolveLpRelaxation(milp.lp(), o);
  ASSERT_EQ(interior.status, milp::SolveStatus::kOptimal) << interior.detail;
  EXPECT_NEAR(interior.objective, simplex.objective,
              1e-6 * std::max(1.0, std::abs(simplex.objective)));
  std::cerr << "interior point on this case: " << interior.detail << "\n";
}

INSTANTIATE_TEST_SUITE_P(AllCases, BruteForceTest, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace thrustsched::transcription
