#include "transcription/min_time.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "common/error.h"
#include "common/format.h"
#include "common/timing.h"
#include "dynamics/discretisation.h"

namespace thrustsched::transcription {
namespace {

using common::FormatG;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Largest scaled excess over the tolerance the re-propagated state may have
// at the arrival (the MILP's own feasibility tolerance is 1e-6 on rows).
constexpr double kArrivalTolerance = 1e-6;

// The range of every state component at nodes 1..N over all on-off patterns
// with each slot free in [0, 1] (the rules and the budget left out):
// x_j = free_j + sum_{k<j} Phi(j, k+1) Gamma_k u_k.
struct Ranges {
  std::vector<Eigen::VectorXd> lo, hi;  // [node], model state units
};

Ranges ReachableRanges(const dynamics::DiscreteModel& d, const Eigen::VectorXd& x0,
                       const Eigen::MatrixXi& may_fire) {
  const int nn = d.num_intervals();
  const int n = d.num_states();
  Ranges r;
  r.lo.assign(nn + 1, x0);
  r.hi.assign(nn + 1, x0);
  Eigen::VectorXd free_path = x0;
  Eigen::MatrixXd effects(n, 0);  // one column per free slot before the node
  for (int j = 0; j < nn; ++j) {
    free_path = d.phi[j] * free_path + d.drift[j];
    Eigen::MatrixXd next(n, effects.cols() + may_fire.rows());
    next.leftCols(effects.cols()) = d.phi[j] * effects;
    int added = 0;
    for (int i = 0; i < may_fire.rows(); ++i) {
      if (may_fire(i, j) != 0) next.col(effects.cols() + added++) = d.gamma[j].col(i);
    }
    effects = next.leftCols(effects.cols() + added);
    r.lo[j + 1] = free_path + effects.cwiseMin(0.0).rowwise().sum();
    r.hi[j + 1] = free_path + effects.cwiseMax(0.0).rowwise().sum();
  }
  return r;
}

// Slots a thruster may fire in: enabled and not forced off (the range is
// still valid if a forced-off slot is counted; this only tightens it).
Eigen::MatrixXi MayFire(const ScheduleMilp& milp) {
  const ScheduleProblem& p = milp.problem();
  Eigen::MatrixXi may(p.thrusters.size(), p.num_intervals());
  for (int i = 0; i < may.rows(); ++i) {
    for (int j = 0; j < may.cols(); ++j) {
      may(i, j) = milp.model().upper_bound(milp.on(i, j)) > 0.5 ? 1 : 0;
    }
  }
  return may;
}

// The arrival binaries (Richards & How 2002).
struct Arrival {
  std::vector<milp::Variable> at;    // a_j, j = 1..N (index j - 1)
  std::vector<milp::Variable> held;  // hold: g_j = a_1 + ... + a_j
  milp::LinearExpr time_s;           // sum_j (t_j - t_0) a_j
  int indicator_rows = 0;
  double big_m_max = 0.0;
};

// The indicator rows of node j: the box around the target holds where g = 1.
void AddNodeRows(const MinTimeSpec& spec, const Ranges& ranges, const Eigen::VectorXd& scale,
                 const ScheduleMilp& milp, int node, milp::Variable g, milp::Model* model,
                 Arrival* arrival) {
  for (int c = 0; c < spec.target.size(); ++c) {
    if (!std::isfinite(spec.tolerance[c])) continue;
    const double up = spec.target[c] + spec.tolerance[c];
    const double down = spec.target[c] - spec.tolerance[c];
    const double big_up = std::max(0.0, ranges.hi[node][c] - up) / scale[c];
    const double big_down = std::max(0.0, down - ranges.lo[node][c]) / scale[c];
    const milp::Variable x = milp.state(node, c);  // scaled: x = S x~
    const std::string tag = "arrive_" + std::to_string(node) + "_" + std::to_string(c);
    if (big_up > 0.0) {
      model->AddConstraint(milp::LinearExpr(x) + big_up * milp::LinearExpr(g), -kInf,
                           up / scale[c] + big_up, tag + "_up");
      ++arrival->indicator_rows;
    }
    if (big_down > 0.0) {
      model->AddConstraint(milp::LinearExpr(x) - big_down * milp::LinearExpr(g),
                           down / scale[c] - big_down, kInf, tag + "_down");
      ++arrival->indicator_rows;
    }
    arrival->big_m_max = std::max({arrival->big_m_max, big_up, big_down});
  }
}

// A node from which the box is out of reach whatever fires.
bool Reachable(const MinTimeSpec& spec, const Ranges& ranges, int node) {
  for (int c = 0; c < spec.target.size(); ++c) {
    if (!std::isfinite(spec.tolerance[c])) continue;
    if (ranges.hi[node][c] < spec.target[c] - spec.tolerance[c] ||
        ranges.lo[node][c] > spec.target[c] + spec.tolerance[c]) {
      return false;
    }
  }
  return true;
}

Eigen::VectorXd StateScale(const ScheduleMilp& milp) {
  const ScheduleProblem& p = milp.problem();
  return milp.options().scale ? p.model->state_scale()
                              : Eigen::VectorXd::Ones(p.initial_state.size());
}

Arrival AddArrival(const MinTimeSpec& spec, const Ranges& ranges, ScheduleMilp* milp) {
  const ScheduleProblem& p = milp->problem();
  const Eigen::VectorXd scale = StateScale(*milp);
  Arrival arrival;
  milp->Modify([&](milp::Model& model) {
    milp::LinearExpr one_arrival;
    for (int j = 1; j <= p.num_intervals(); ++j) {
      const milp::Variable a = model.AddBinary("arrive_at_" + std::to_string(j));
      if (!Reachable(spec, ranges, j)) model.SetBounds(a, 0.0, 0.0);
      arrival.at.push_back(a);
      one_arrival.AddTerm(a, 1.0);
      arrival.time_s.AddTerm(a, p.grid[j] - p.grid.front());
      milp::Variable g = a;  // the box holds at node j where g = 1
      if (spec.hold) {       // g_j = a_1 + ... + a_j
        g = model.AddContinuous(0.0, 1.0, "arrived_by_" + std::to_string(j));
        milp::LinearExpr def = milp::LinearExpr(g) - milp::LinearExpr(a);
        if (!arrival.held.empty()) def.AddTerm(arrival.held.back(), -1.0);
        model.AddConstraint(def, 0.0, 0.0, "arrived_by_" + std::to_string(j) + "_def");
        arrival.held.push_back(g);
      }
      AddNodeRows(spec, ranges, scale, *milp, j, g, &model, &arrival);
    }
    model.AddConstraint(one_arrival, 1.0, 1.0, "arrive_once");
  });
  return arrival;
}

// A step every arrival time is a whole multiple of (uniform grids): the
// solver may then prune by whole steps. 0 otherwise.
double ArrivalStep(const std::vector<double>& grid) {
  double step = kInf;
  for (size_t j = 1; j < grid.size(); ++j) step = std::min(step, grid[j] - grid[j - 1]);
  for (size_t j = 1; j < grid.size(); ++j) {
    const double k = (grid[j] - grid.front()) / step;
    if (std::abs(k - std::round(k)) > 1e-9 * std::max(1.0, k)) return 0.0;
  }
  return step;
}

milp::LinearExpr FuelOf(const milp::LpData& lp, const milp::Model& model) {
  milp::LinearExpr fuel;
  for (int c = 0; c < lp.num_cols(); ++c) {
    if (lp.col_cost[c] != 0.0) fuel.AddTerm(model.variable(c), lp.col_cost[c]);
  }
  return fuel;
}

int ArrivalNode(const Arrival& arrival, const Eigen::VectorXd& x) {
  for (size_t j = 0; j < arrival.at.size(); ++j) {
    if (x[arrival.at[j].index()] > 0.5) return static_cast<int>(j) + 1;
  }
  return -1;
}

// The re-propagated state's largest scaled excess over the tolerance at the
// arrival node and, with hold, at every later node.
double ArrivalError(const ScheduleProblem& p, const MinTimeSpec& spec, const CheckReport& check,
                    int node) {
  const Eigen::VectorXd scale = p.model->state_scale();
  double worst = 0.0;
  int nodes_seen = 0;
  for (size_t s = 0; s < check.sample_times.size(); ++s) {
    const double t = check.sample_times[s];
    const auto at =
        std::lower_bound(p.grid.begin(), p.grid.end(), t - 1e-9 * std::max(1.0, std::abs(t)));
    if (at == p.grid.end() || std::abs(*at - t) > 1e-9 * std::max(1.0, std::abs(t))) continue;
    const int j = static_cast<int>(at - p.grid.begin());
    if (j < node || (!spec.hold && j != node)) continue;
    ++nodes_seen;
    for (int c = 0; c < spec.target.size(); ++c) {
      if (!std::isfinite(spec.tolerance[c])) continue;
      const double excess =
          std::abs(check.sample_states[s][c] - spec.target[c]) - spec.tolerance[c];
      worst = std::max(worst, excess / scale[c]);
    }
  }
  return nodes_seen > 0 ? worst : kInf;
}

}  // namespace

bool MinTimeSpec::IsValid(const ScheduleProblem& problem, std::string* error) const {
  const int n = problem.model != nullptr ? problem.model->num_states() : 0;
  if (problem.input_mode != InputMode::kOnOff) {
    return common::Fail(error, "min_time needs the on-off input mode");
  }
  if (target.size() != n) {
    return common::Fail(error, "min_time.target has " + std::to_string(target.size()) +
                                   " components, the model's state " + std::to_string(n));
  }
  if (tolerance.size() != n) {
    return common::Fail(error, "min_time.tolerance has " + std::to_string(tolerance.size()) +
                                   " components, the model's state " + std::to_string(n));
  }
  bool any_finite = false;
  for (int c = 0; c < n; ++c) {
    if (!std::isfinite(target[c])) {
      return common::Fail(error, "min_time.target[" + std::to_string(c) +
                                     "] is not finite: " + FormatG(target[c], 10));
    }
    if (!(tolerance[c] >= 0.0)) {
      return common::Fail(error, "min_time.tolerance[" + std::to_string(c) +
                                     "] must be >= 0, got " + FormatG(tolerance[c], 10));
    }
    any_finite = any_finite || std::isfinite(tolerance[c]);
  }
  if (!any_finite) {
    return common::Fail(error, "min_time.tolerance is infinite for every component: no target");
  }
  if (!(fuel_budget > 0.0)) {
    return common::Fail(error, "min_time.fuel_budget must be > 0, got " + FormatG(fuel_budget, 10));
  }
  return true;
}

bool MinTimeResult::verified() const {
  return has_schedule() && check.operational_ok && check.max_window_violation_at_nodes <= 1e-6 &&
         arrival_error <= kArrivalTolerance;
}

namespace {

// What an arrival search leaves: the earliest arrival found (its node and
// the MILP's point), the earliest node not proven infeasible, and the
// search's status (as MinTimeResult::time_status).
struct ArrivalFound {
  int node = -1;
  Eigen::VectorXd x;
  int bound_node = -1;
  milp::SolveStatus status = milp::SolveStatus::kError;
  Arrival arrival;  // its indicator columns
};

// The schedule MILP with the fuel budget, the arrival indicators and the
// arrival time as its objective: the first MILP.
struct ArrivalMilp {
  ScheduleMilp milp;
  milp::LinearExpr fuel;  // problem.objective's expression
  double fuel_offset = 0.0;
  double fuel_step = 0.0;
  Ranges ranges;
  Arrival arrival;
  int candidate_nodes = 0;

  ArrivalMilp(const ScheduleProblem& problem, const MinTimeSpec& spec, const BuildOptions& options)
      : milp(problem, SparseOf(options)) {
    fuel = FuelOf(milp.lp(), milp.model());
    fuel_offset = milp.lp().objective_offset;
    fuel_step = milp.objective_step();
    if (std::isfinite(spec.fuel_budget)) {
      milp.Modify([&](milp::Model& m) {
        m.AddConstraint(fuel, -kInf, spec.fuel_budget - fuel_offset, "fuel_budget");
      });
    }
    ranges = ReachableRanges(milp.discrete(), problem.initial_state, MayFire(milp));
    arrival = AddArrival(spec, ranges, &milp);
    for (int j = 1; j <= problem.num_intervals(); ++j) {
      candidate_nodes += Reachable(spec, ranges, j) ? 1 : 0;
    }
    milp.Modify([&](milp::Model& model) { model.Minimize(arrival.time_s); });
  }

  // The box needs the state columns.
  static BuildOptions SparseOf(BuildOptions options) {
    options.formulation = Formulation::kSparse;
    return options;
  }
};

// The first MILP's solve: the earliest arrival found, with the arrival
// columns from that node on fixed to 0 for the fuel MILP.
ArrivalFound IndicatorArrival(const milp::Solver& solver, const milp::SolveOptions& options,
                              common::SolveClock* clock, ArrivalMilp* am, MinTimeResult* r) {
  ScheduleMilp* milp = &am->milp;
  const Arrival& arrival = am->arrival;
  r->indicator_rows = arrival.indicator_rows;
  r->big_m_max = arrival.big_m_max;
  r->candidate_nodes = am->candidate_nodes;
  milp::SolveOptions o = options;
  o.objective_step = ArrivalStep(milp->problem().grid);
  o.time_limit_s = std::max(0.0, clock->Remaining());
  r->time_solve = solver.Solve(milp->lp(), o);
  const milp::SolveResult& result = r->time_solve;
  ArrivalFound found;
  found.arrival = arrival;
  found.status = result.status;
  if (!result.has_solution()) return found;
  found.node = ArrivalNode(arrival, result.x);
  found.x = result.x;
  const std::vector<double>& grid = milp->problem().grid;
  found.bound_node = found.node;
  if (result.status != milp::SolveStatus::kOptimal) {
    // The first node at or after the proven bound on the arrival time.
    const double t = grid.front() + std::max(0.0, result.best_bound);
    found.bound_node = static_cast<int>(
        std::lower_bound(grid.begin(), grid.end(), t - 1e-9 * std::max(1.0, std::abs(t))) -
        grid.begin());
  }
  milp->Modify([&](milp::Model& model) {
    for (size_t j = found.node; j < arrival.at.size(); ++j)
      model.SetBounds(arrival.at[j], 0.0, 0.0);
  });
  return found;
}

void CheckArguments(const ScheduleProblem& problem, const MinTimeSpec& spec,
                    const BuildOptions& build, const char* who) {
  std::string err;
  if (!problem.IsValid(&err)) throw std::invalid_argument(std::string(who) + ": " + err);
  if (!spec.IsValid(problem, &err)) throw std::invalid_argument(std::string(who) + ": " + err);
  if (!build.IsValid(&err)) throw std::invalid_argument(std::string(who) + ": build." + err);
}

}  // namespace

milp::LpData MinTimeArrivalLp(const ScheduleProblem& problem, const MinTimeSpec& spec,
                              const BuildOptions& options) {
  CheckArguments(problem, spec, options, "MinTimeArrivalLp");
  return ArrivalMilp(problem, spec, options).milp.lp();
}

MinTimeResult SolveMinTime(const ScheduleProblem& problem, const MinTimeSpec& spec,
                           const milp::Solver& solver, const SolveScheduleOptions& options) {
  CheckArguments(problem, spec, options.build, "SolveMinTime");
  std::string err;
  if (!options.milp.IsValid(&err)) throw std::invalid_argument("SolveMinTime: milp: " + err);
  if (!options.check.IsValid(&err)) throw std::invalid_argument("SolveMinTime: check." + err);
  common::SolveClock clock(options.milp.time_limit_s, options.milp.interrupt);

  ArrivalMilp am(problem, spec, options.build);
  ScheduleMilp& milp = am.milp;
  MinTimeResult r;
  r.infeasibility_reasons = milp.infeasibility_reasons();
  const ArrivalFound found = IndicatorArrival(solver, options.milp, &clock, &am, &r);
  r.stats = milp.stats();
  r.time_status = found.status;
  if (r.candidate_nodes == 0) {
    r.infeasibility_reasons.push_back("the target box is out of reach at every node up to t_N = " +
                                      FormatG(problem.grid.back(), 10) + " s, whatever fires");
  }
  if (found.bound_node >= 0 && found.bound_node < static_cast<int>(problem.grid.size())) {
    r.arrival_bound_s = problem.grid[found.bound_node] - problem.grid.front();
  }
  if (found.node < 0) return r;
  Eigen::VectorXd x = found.x;
  if (spec.minimise_fuel_after && !clock.ShouldStop()) {
    milp.Modify([&](milp::Model& model) { model.Minimize(am.fuel + am.fuel_offset); });
    milp::SolveOptions fuel_options = options.milp;
    fuel_options.time_limit_s = std::max(0.0, clock.Remaining());
    fuel_options.objective_step = am.fuel_step;
    fuel_options.initial_solution = x;
    r.fuel_solve = solver.Solve(milp.lp(), fuel_options);
    if (r.fuel_solve->has_solution()) x = r.fuel_solve->x;
  }
  // The fuel MILP may arrive earlier than a first MILP stopped by a limit.
  r.arrival_node = ArrivalNode(found.arrival, x);
  r.arrival_time_s = problem.grid[r.arrival_node] - problem.grid.front();
  r.fuel = am.fuel.Evaluate(x) + am.fuel_offset;
  r.schedule = milp.Decode(x);
  r.check = CheckSchedule(problem, r.schedule.burns, options.check);
  r.arrival_error = ArrivalError(problem, spec, r.check, r.arrival_node);
  return r;
}

}  // namespace thrustsched::transcription
