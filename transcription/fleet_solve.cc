// SolveFleet: build, solve, decode, and re-check a fleet (transcription/fleet.h).
#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "transcription/fleet.h"
#include "transcription/fleet_in_turn.h"
#include "transcription/fleet_neighbourhood.h"
#include "transcription/fleet_start.h"
#include "transcription/internal/fleet_reach.h"

namespace thrustsched::transcription {
namespace {

// Positions (metres) of every member at `times`, as the MILP writes them:
// the affine map of its columns (internal::MemberReach), evaluated at x.
std::vector<std::vector<Eigen::Vector3d>> PlannedPositions(const FleetMilp& fleet,
                                                           const std::vector<double>& times,
                                                           const BuildOptions& options,
                                                           const Eigen::VectorXd& x) {
  std::vector<std::vector<Eigen::Vector3d>> out;
  for (int k = 0; k < fleet.num_members(); ++k) {
    const internal::MemberReach reach(fleet.member(k), FleetPositionMaps(fleet.fleet(), k, times),
                                      times, options);
    out.emplace_back();
    for (size_t q = 0; q < times.size(); ++q)
      out.back().push_back(reach.Position(static_cast<int>(q), fleet.column_offset(k), x));
  }
  return out;
}

void Closest(const Eigen::Vector3d& ra, const Eigen::Vector3d& rb, double t, PairDistance* d) {
  const Eigen::Vector3d rel = ra - rb;
  d->min_box_distance_m = std::min(d->min_box_distance_m, rel.cwiseAbs().maxCoeff());
  if (rel.norm() < d->min_distance_m) d->min_distance_m = rel.norm(), d->time_s = t;
}

std::vector<PairDistance> PairsOf(const std::vector<std::vector<Eigen::Vector3d>>& r,
                                  const std::vector<double>& times) {
  std::vector<PairDistance> out;
  for (size_t a = 0; a < r.size(); ++a) {
    for (size_t b = a + 1; b < r.size(); ++b) {
      PairDistance d;
      d.a = static_cast<int>(a), d.b = static_cast<int>(b);
      for (size_t q = 0; q < times.size(); ++q) Closest(r[a][q], r[b][q], times[q], &d);
      out.push_back(d);
    }
  }
  return out;
}

// Pairs on the checker's sample times: the members share the grid, so the
// samples coincide; times one member lacks (a burn edge) are skipped.
// relative(a, i, b, j): member a's position at its sample i minus b's at j.
template <typename Relative>
std::vector<PairDistance> PairsOnSamples(const std::vector<CheckReport>& checks,
                                         Relative&& relative) {
  std::vector<PairDistance> out;
  for (size_t a = 0; a < checks.size(); ++a) {
    for (size_t b = a + 1; b < checks.size(); ++b) {
      PairDistance d;
      d.a = static_cast<int>(a), d.b = static_cast<int>(b);
      const auto& ta = checks[a].sample_times;
      const auto& tb = checks[b].sample_times;
      size_t i = 0, j = 0;
      while (i < ta.size() && j < tb.size()) {
        if (std::abs(ta[i] - tb[j]) <= 1e-6) {
          Closest(relative(d.a, i, d.b, j), Eigen::Vector3d::Zero(), ta[i], &d);
          ++i, ++j;
        } else if (ta[i] < tb[j]) {
          ++i;
        } else {
          ++j;
        }
      }
      out.push_back(d);
    }
  }
  return out;
}

std::vector<PairDistance> CheckedPairs(const FleetProblem& fleet,
                                       const std::vector<CheckReport>& checks) {
  return PairsOnSamples(checks, [&](int a, size_t i, int b, size_t j) {
    const double t = checks[a].sample_times[i];
    return Eigen::Vector3d(FleetPosition(fleet, a, t, checks[a].sample_states[i]) -
                           FleetPosition(fleet, b, t, checks[b].sample_states[j]));
  });
}

// Pairs of the nonlinear replays (GEO): the exact inertial separation, in
// the radial, east, north axes of the pair's midpoint (the max-norm is the
// cube's). Empty unless every member was replayed.
std::vector<PairDistance> NonlinearPairs(const std::vector<CheckReport>& checks) {
  for (const CheckReport& c : checks) {
    if (!c.nonlinear_checked || c.nonlinear_eci.size() != c.sample_times.size()) return {};
  }
  return PairsOnSamples(checks, [&](int a, size_t i, int b, size_t j) {
    const Eigen::Vector3d ra = checks[a].nonlinear_eci[i].head<3>();
    const Eigen::Vector3d rb = checks[b].nonlinear_eci[j].head<3>();
    const Eigen::Vector3d radial = (ra + rb).normalized();
    const Eigen::Vector3d east = Eigen::Vector3d::UnitZ().cross(radial).normalized();
    const Eigen::Vector3d north = radial.cross(east);
    const Eigen::Vector3d d = ra - rb;
    return Eigen::Vector3d(d.dot(radial), d.dot(east), d.dot(north));
  });
}

double Residual(const Eigen::MatrixXd& map, const Eigen::VectorXd& x, const Eigen::VectorXd* ref,
                const Eigen::VectorXd& target, const Eigen::VectorXd& tolerance) {
  Eigen::VectorXd v = map * x - target;
  if (ref != nullptr) v -= map * *ref;
  double worst = 0.0;
  for (int r = 0; r < v.size(); ++r) {
    const double tol = tolerance.size() == 0 ? 0.0 : tolerance[r];
    worst = std::max(worst, std::abs(v[r]) - tol);
  }
  return std::max(worst, 0.0);
}

std::vector<double> CouplingResiduals(const FleetProblem& fleet, const std::vector<int>& slots,
                                      const std::vector<Eigen::VectorXd>& final_states) {
  std::vector<double> out;
  for (const TerminalCoupling& c : fleet.couplings) {
    const Eigen::VectorXd* ref = c.reference >= 0 ? &final_states[c.reference] : nullptr;
    out.push_back(Residual(c.map, final_states[c.member], ref, c.offset, c.tolerance));
  }
  if (fleet.assignment) {
    const SlotAssignment& a = *fleet.assignment;
    const Eigen::VectorXd* ref = a.reference >= 0 ? &final_states[a.reference] : nullptr;
    double worst = 0.0;
    for (size_t i = 0; i < a.members.size(); ++i) {
      worst = std::max(
          worst, Residual(a.map, final_states[a.members[i]], ref, a.slots[slots[i]], a.tolerance));
    }
    out.push_back(worst);
  }
  return out;
}

// What a step of the start took is taken from the solve's time limit.
void Spend(double seconds, milp::SolveOptions* solve) {
  if (std::isfinite(solve->time_limit_s))
    solve->time_limit_s = std::max(solve->time_limit_s - seconds, 1e-3);
}

// A start the keep-out rejected, replaced by the fleet plan over the slots
// near the members' own burns where one is found; its time taken from the
// solve's limit.
void RepairInNeighbourhood(const FleetMilp& milp, const milp::Solver& solver,
                           const FleetSolveOptions& options, milp::SolveOptions* solve,
                           FleetStart* start) {
  if (options.announce) {
    options.announce("start: repairing member by member over the slots within " +
                     std::to_string(options.neighbourhood_radius_intervals) +
                     " intervals of their own burns");
  }
  milp::SolveOptions restricted = *solve;
  restricted.initial_solution.reset();
  if (std::isfinite(solve->time_limit_s))
    restricted.time_limit_s = options.neighbourhood_time_share * solve->time_limit_s;
  const FleetNeighbourhood n = RepairMemberByMember(milp, start->x, solver, restricted,
                                                    options.neighbourhood_radius_intervals);
  start->neighbourhood_tried = true;
  start->neighbourhood_radius_intervals = n.radius_intervals;
  start->neighbourhood_free_binaries = n.free_binaries;
  start->neighbourhood_seconds = n.seconds;
  start->seconds += n.seconds;
  Spend(n.seconds, solve);
  if (!n.found) {
    start->note += "; not repaired: " + n.note;
    return;
  }
  start->x = n.x;
  start->objective = n.objective;
  start->accepted = start->repaired = true;
  start->note += "; repaired member by member (" + std::to_string(n.members_replanned) +
                 " re-planned within " + std::to_string(n.radius_intervals) +
                 " intervals of their own burns)";
}

// A start the keep-out rejected, replaced by the members re-planned in turn
// against each other's fixed plans where they all find one; its time taken
// from the solve's limit.
void PlanInTurn(const FleetMilp& milp, const milp::Solver& solver, const FleetSolveOptions& options,
                const SolveScheduleOptions& member, milp::SolveOptions* solve, FleetStart* start) {
  SolveScheduleOptions o = member;
  o.announce = options.announce;
  o.milp.time_limit_s = std::isfinite(solve->time_limit_s)
                            ? options.in_turn_time_share * solve->time_limit_s
                            : std::numeric_limits<double>::infinity();
  const FleetInTurn t = PlanMembersInTurn(milp, start->x, start->slots, solver, o);
  start->in_turn_tried = true;
  start->in_turn_members_replanned = t.members_replanned;
  start->in_turn_searches = t.searches;
  start->in_turn_constraints = t.constraints;
  start->in_turn_seconds = t.seconds;
  start->seconds += t.seconds;
  Spend(t.seconds, solve);
  if (!t.found) {
    start->note += "; not planned in turn: " + t.note;
    return;
  }
  start->x = t.x;
  start->objective = t.objective;
  start->accepted = start->in_turn_found = true;
  start->note += "; planned in turn (" + std::to_string(t.members_replanned) +
                 " re-planned against the fixed plans before them, " + std::to_string(t.searches) +
                 " searches, " + std::to_string(t.constraints) + " keep-out faces)";
}

// The decoupled start as the solve's MIP start, its time taken from the
// solve's limit.
FleetStart StartFromMembersAlone(const FleetMilp& milp, const milp::Solver& solver,
                                 const FleetSolveOptions& options, milp::SolveOptions* solve) {
  const FleetProblem& fleet = milp.fleet();
  size_t solves = fleet.members.size();
  if (fleet.assignment) {
    const size_t a = fleet.assignment->members.size();
    solves += a * a - a;
  }
  SolveScheduleOptions member;
  member.build = options.build;
  member.milp.threads = options.milp.threads;
  member.milp.random_seed = options.milp.random_seed;
  member.milp.relative_gap = 1e-4;
  member.milp.interrupt = options.milp.interrupt;
  if (std::isfinite(options.milp.time_limit_s)) {
    member.milp.time_limit_s =
        options.start_time_share * options.milp.time_limit_s / static_cast<double>(solves);
  }
  if (options.announce) {
    options.announce(
        "start: the " + std::to_string(solves) + " member solves alone by the search (at most " +
        std::to_string(static_cast<int>(options.start_time_share * 100)) + " % of the time limit)");
  }
  FleetStart start = DecoupledStart(milp, solver, member);
  Spend(start.seconds, solve);
  if (start.built && !start.accepted && fleet.keep_out && options.in_turn)
    PlanInTurn(milp, solver, options, member, solve, &start);
  if (start.built && !start.accepted && fleet.keep_out &&
      options.neighbourhood_radius_intervals > 0)
    RepairInNeighbourhood(milp, solver, options, solve, &start);
  if (start.built) solve->initial_solution = start.x;
  return start;
}

// The fleet MILP from the decoupled start: when the start is feasible for the
// fleet and within the gap of the decoupled bound, it is optimal and the
// solver is not called; otherwise the solver starts from it, and its bound is
// raised to the decoupled bound where that is higher.
milp::SolveResult SolveWithStart(const FleetMilp& milp, const milp::Solver& solver,
                                 const milp::SolveOptions& solve, const FleetStart& start) {
  const milp::LpData& lp = milp.lp();
  const double bound = start.bound;
  if (start.accepted) {
    const double objective = lp.Objective(start.x);
    if (milp::GapClosed(objective, bound, solve)) {
      milp::SolveResult r;
      r.status = milp::SolveStatus::kOptimal;
      r.x = start.x;
      r.objective = objective;
      r.best_bound = bound;
      r.gap = milp::RelativeGap(objective, bound);
      r.detail =
          "the members planned alone keep every fleet row; optimal by the decoupled bound "
          "(no fleet solve)";
      return r;
    }
  }
  milp::SolveResult r = solver.Solve(lp, solve);
  if (!r.has_solution() && start.accepted) {  // a limit before the solver took the start: keep it
    r.x = start.x;
    r.objective = lp.Objective(start.x);
    r.status = milp::SolveStatus::kFeasible;
    r.detail += "; the start kept (the solver stopped without taking it)";
  }
  if (bound > -std::numeric_limits<double>::infinity() &&
      (!std::isfinite(r.best_bound) || bound > r.best_bound)) {
    if (bound == std::numeric_limits<double>::infinity()) {
      r.status = milp::SolveStatus::kInfeasible;  // a member alone is proven infeasible
      r.detail += "; a member alone is infeasible (decoupled bound)";
      return r;
    }
    r.best_bound = bound;
    r.detail += "; bound raised to the decoupled bound";
    if (r.has_solution()) {
      r.gap = milp::RelativeGap(r.objective, bound);
      if (milp::GapClosed(r.objective, bound, solve)) r.status = milp::SolveStatus::kOptimal;
    }
  }
  return r;
}

}  // namespace

FleetResult SolveFleet(const FleetProblem& fleet, const milp::Solver& solver,
                       const FleetSolveOptions& options) {
  const FleetMilp milp(fleet, options.build);
  FleetResult r;
  r.stats = milp.stats();
  milp::SolveOptions solve = options.milp;
  if (options.decoupled_start) r.start = StartFromMembersAlone(milp, solver, options, &solve);
  const milp::SolveResult s = SolveWithStart(milp, solver, solve, r.start);
  r.status = s.status;
  r.detail = s.detail;
  r.objective = s.objective;
  r.best_bound = s.best_bound;
  r.gap = s.gap;
  r.solve_seconds = s.wall_seconds;
  if (!s.has_solution()) return r;
  r.schedules = milp.Decode(s.x);
  r.consumption = milp.Consumptions(s.x);
  r.slots = milp.Slots(s.x);
  std::vector<double> times =
      fleet.keep_out ? fleet.keep_out->check_times_s : fleet.members[0].problem.grid;
  r.planned_pairs = PairsOf(PlannedPositions(milp, times, options.build, s.x), times);
  std::vector<Eigen::VectorXd> final_states;
  for (const Schedule& sc : r.schedules) final_states.push_back(sc.states.back());
  if (options.check) {
    for (int k = 0; k < milp.num_members(); ++k) {
      r.checks.push_back(
          CheckSchedule(fleet.members[k].problem, r.schedules[k].burns, options.checker));
      final_states[k] = r.checks.back().final_state;
    }
    r.checked_pairs = CheckedPairs(fleet, r.checks);
    r.nonlinear_pairs = NonlinearPairs(r.checks);
    if (fleet.keep_out && fleet.HasInitialCovariance() && options.monte_carlo.samples > 0)
      r.monte_carlo = CheckFleetMonteCarlo(fleet, r.schedules, options.monte_carlo);
  }
  r.coupling_residuals = CouplingResiduals(fleet, r.slots, final_states);
  return r;
}

}  // namespace thrustsched::transcription
