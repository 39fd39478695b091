#include "transcription/conjunction_solve.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

#include "common/error.h"
#include "common/format.h"
#include "common/timing.h"
#include "milp/lp_data.h"
#include "transcription/search.h"
#include "transcription/terminal_sets.h"

namespace thrustsched::transcription {

using common::Since;

namespace {

using common::Clock;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The restricted MILP of a repair: slots within two intervals of the burns.
constexpr int kRepairNeighbourhood = 2;
constexpr long long kRepairMaxNodes = 20000;

// At every check with a disjunction: the face the thrust-free path satisfies
// best if it satisfies one; otherwise `face` if the check has it (any face
// if face < 0), else the face the free path misses least.
int PickFace(const KeepOutGroup& g, int face) {
  int pick = static_cast<int>(std::max_element(g.free_slack_m.begin(), g.free_slack_m.end()) -
                              g.free_slack_m.begin());
  if (face < 0 || g.free_slack_m[pick] >= 0.0) return pick;
  for (size_t q = 0; q < g.faces.size(); ++q) {
    if (g.faces[q] == face) return static_cast<int>(q);
  }
  return pick;
}

std::string FaceLabel(int face, int num_faces) {
  if (face < 0) return "least-missed face at every check";
  static const char* kCube[] = {"+R", "-R", "+T", "-T", "+N", "-N"};
  const std::string name = num_faces == 6 ? kCube[face] : "face " + std::to_string(face);
  return name + " face wherever the thrust-free path satisfies none";
}

// Fixes every disjunction of `lp` to the face `pick(group)` (w = 0), the others relaxed.
template <typename Pick>
void FixFaces(const KeepOutStats& ko, Pick pick, milp::LpData* lp) {
  for (const KeepOutGroup& g : ko.groups) {
    if (g.binaries.empty() || g.binaries[0] < 0) continue;
    const int chosen = pick(g);
    for (size_t q = 0; q < g.binaries.size(); ++q) {
      const double v = static_cast<int>(q) == chosen ? 0.0 : 1.0;
      lp->col_lower[g.binaries[q]] = lp->col_upper[g.binaries[q]] = v;
    }
  }
}

// The face of `g` whose row the row activities `act` (keep-out binaries at
// 0) satisfy best, in metres of slack.
int LeastMissedFace(const KeepOutGroup& g, const Eigen::VectorXd& act, const milp::LpData& lp) {
  int best = 0;
  double best_slack = -kInf;
  for (size_t q = 0; q < g.rows.size(); ++q) {
    const double slack_m = (act[g.rows[q]] - lp.row_lower[g.rows[q]]) / g.row_scale[q];
    if (slack_m > best_slack) best_slack = slack_m, best = static_cast<int>(q);
  }
  return best;
}

// The plan `x` of another build of the problem as a full start of `m`.
Eigen::VectorXd StartFor(const ScheduleMilp& m, const Eigen::VectorXd& x) {
  const int own = m.keep_out()->first_binary_column;
  Eigen::VectorXd out = Eigen::VectorXd::Zero(m.lp().num_cols());
  out.head(own) = x.head(own);
  CompleteKeepOut(m.lp(), *m.keep_out(), &out);
  return out;
}

// The slots a repair of `plan` may use: every thruster within
// `neighbourhood` intervals of the plan's burns, and every slot from half an
// orbital period before the first check to the last (a burn's radial and
// normal effects peak a quarter to half a period later).
Eigen::MatrixXi RepairSlots(const ScheduleMilp& m, const Eigen::VectorXd& plan, int neighbourhood) {
  const OperationalEncoding& enc = m.encoding();
  const ScheduleProblem& p = m.problem();
  const std::vector<double> checks = p.conjunction->CheckTimes(p.grid.front(), p.grid.back());
  const double half_period_s = M_PI / HcwMeanMotion(*p.model);
  const double from_s = checks.empty() ? kInf : checks.front() - half_period_s;
  const double to_s = checks.empty() ? -kInf : checks.back();
  const int num_thrusters = enc.num_thrusters, n = enc.num_intervals;
  std::vector<char> near_burn(n, 0);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < num_thrusters; ++i) {
      if (plan[enc.on[i][j].index()] < 0.5) continue;
      for (int d = -neighbourhood; d <= neighbourhood; ++d) {
        if (j + d >= 0 && j + d < n) near_burn[j + d] = 1;
      }
    }
  }
  Eigen::MatrixXi mask = Eigen::MatrixXi::Zero(num_thrusters, n);
  for (int j = 0; j < n; ++j) {
    const bool in_window = p.grid[j + 1] > from_s && p.grid[j] < to_s;
    if (!near_burn[j] && !in_window) continue;
    for (int i = 0; i < num_thrusters; ++i) mask(i, j) = 1;
  }
  return mask;
}

// The MILP `m` with every disjunction fixed to the face `plan` misses least
// (keep-out binaries at 0 for the activities), restricted to `mask` when it
// has entries (the sparse build of m with those free slots, without its
// fixed columns). A full column vector of `m`, or empty.
Eigen::VectorXd SolveFixedFaces(const ScheduleMilp& m, const Eigen::VectorXd& plan,
                                const Eigen::MatrixXi& mask, const milp::Solver& solver,
                                const milp::SolveOptions& o, std::string* note) {
  std::unique_ptr<ScheduleMilp> restricted;
  const ScheduleMilp* model = &m;
  if (mask.size() > 0) {
    BuildOptions b = m.options();
    b.free_slots = mask;
    restricted = std::make_unique<ScheduleMilp>(m.problem(), m.discrete(), b);
    if (!restricted->infeasibility_reasons().empty()) return {};
    model = restricted.get();
  }
  const KeepOutStats& ko = *model->keep_out();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(model->lp().num_cols());
  x.head(ko.first_binary_column) = plan.head(ko.first_binary_column);
  const Eigen::VectorXd act = model->lp().a_matrix * x;  // keep-out binaries at 0
  milp::LpData lp = model->lp();
  FixFaces(
      ko, [&](const KeepOutGroup& g) { return LeastMissedFace(g, act, lp); }, &lp);
  std::vector<int> kept;
  bool feasible = true;
  const milp::LpData small = milp::RemoveFixedColumns(lp, &kept, &feasible);
  if (!feasible) return {};
  const milp::SolveResult r = solver.Solve(small, o);
  *note = std::to_string(small.num_cols()) + " columns, " + std::to_string(r.nodes) + " nodes";
  if (!r.has_solution()) return {};
  // The plan as an on-off pattern, its states propagated in `m` (exact, where
  // the solver's columns hold only to its tolerances).
  Eigen::VectorXd x_model = lp.col_lower;  // the fixed columns' values
  for (size_t k = 0; k < kept.size(); ++k) x_model[kept[k]] = r.x[static_cast<Eigen::Index>(k)];
  return m.StartFromPattern(model->encoding().OnPattern(x_model));
}

// On-off mode: the plan of the problem without its conjunction (the
// problem-aware search, transcription/search.h), then the same MILP with
// every disjunction fixed to the face that plan misses least: its station
// keeping is kept and bent just enough. The bent plan is first looked for
// over the slots near the plan's burns and the half orbit before the
// encounter (a node-limited restricted MILP), then over every slot. Each
// solve gets `share` of the time limit (300 s when unlimited).
ConjunctionStart RepairedPlanStart(const ScheduleMilp& m, const milp::Solver& solver,
                                   const milp::SolveOptions& base, double share) {
  ConjunctionStart out;
  const Clock::time_point t0 = Clock::now();
  const double limit = std::isfinite(base.time_limit_s) ? share * base.time_limit_s : 300.0;
  milp::SolveOptions o = base;
  o.initial_solution.reset();
  o.time_limit_s = limit;
  // Progress on the caller's clock. The plan without the conjunction is not
  // a plan of this problem (no incumbent is reported from it), its bound is.
  double bound = -kInf;
  const auto forward = [&](bool own_incumbents) -> std::function<void(const milp::SolveProgress&)> {
    if (!base.progress) return nullptr;
    const double offset = Since(t0);
    return [&, offset, own_incumbents](const milp::SolveProgress& sub) {
      milp::SolveProgress p = sub;
      p.wall_seconds += offset;
      if (!own_incumbents) {
        p.objective = kNaN;
        p.new_incumbent = false;
      } else {
        p.best_bound = bound;
      }
      p.gap = std::isfinite(p.objective) ? milp::RelativeGap(p.objective, p.best_bound) : kNaN;
      base.progress(p);
    };
  };
  ScheduleProblem plain = m.problem();
  plain.conjunction.reset();
  const ScheduleMilp without(plain, m.discrete(), m.options());
  o.objective_step = without.objective_step();
  o.progress = forward(false);
  const milp::SolveResult r0 = SearchSchedule(without, solver, o, SearchOptions{}, {});
  if (!r0.has_solution()) return out;
  bound = r0.best_bound;
  o.progress = forward(true);
  out.lower_bound = r0.best_bound;
  out.without_objective = r0.objective;
  out.without_x = StartFor(m, r0.x);
  o.objective_step = m.objective_step();
  const struct {
    int neighbourhood;  // -1: every slot
    long long max_nodes;
  } levels[] = {{kRepairNeighbourhood, kRepairMaxNodes}, {-1, o.max_nodes}};
  for (const auto& level : levels) {
    const Eigen::MatrixXi mask =
        level.neighbourhood < 0 ? Eigen::MatrixXi() : RepairSlots(m, r0.x, level.neighbourhood);
    milp::SolveOptions lo = o;
    if (level.max_nodes >= 0) lo.max_nodes = level.max_nodes;
    std::string note;
    const Eigen::VectorXd x = SolveFixedFaces(m, r0.x, mask, solver, lo, &note);
    if (x.size() == 0 || m.lp().MaxViolation(x) > 1e-6) continue;
    out.objective = m.lp().Objective(x);
    out.x = x;
    out.label = "the plan without the conjunction, repaired at its least-missed faces (" +
                (mask.size() > 0 ? "over " + std::to_string(mask.sum()) + " slots"
                                 : std::string("over every slot")) +
                ", " + note + ")";
    break;
  }
  return out;
}

}  // namespace

ConjunctionStart FixedFaceStart(const ScheduleMilp& m, const milp::Solver& solver,
                                const milp::SolveOptions& base) {
  if (!m.keep_out()) throw std::invalid_argument("FixedFaceStart: the problem has no conjunction");
  ConjunctionStart best;
  if (m.problem().input_mode != InputMode::kImpulsive)
    return RepairedPlanStart(m, solver, base, 0.25);
  const KeepOutStats& ko = *m.keep_out();
  const int num_faces = m.problem().conjunction->EffectivePolytope().size();
  const Clock::time_point t0 = Clock::now();
  const double time_left = base.time_limit_s;
  for (int face = -1; face < num_faces; ++face) {
    milp::LpData lp = m.lp();
    FixFaces(
        ko, [face](const KeepOutGroup& g) { return PickFace(g, face); }, &lp);
    milp::SolveOptions o = base;
    o.initial_solution.reset();
    o.progress = nullptr;
    o.time_limit_s = std::max(0.0, time_left - Since(t0));
    const milp::LpRelaxationResult r = solver.SolveLpRelaxation(lp, o);
    if (r.status == milp::SolveStatus::kOptimal && r.objective < best.objective) {
      best.objective = r.objective;
      best.x = r.x;
      best.label = FaceLabel(face, num_faces);
    }
  }
  return best;
}

namespace {

// objective >= lower as one row (every objective term is >= 0 here, see AddKeepOut).
void AddObjectiveFloor(double lower, milp::Model* model) {
  milp::LinearExpr objective;
  for (int c = 0; c < model->num_variables(); ++c) {
    const milp::Variable v = model->variable(c);
    const double cost = model->objective_coefficient(v);
    if (cost != 0.0) objective.AddTerm(v, cost);
  }
  const double floor =
      lower - 1e-9 * std::abs(lower) - model->objective_offset();  // solver tolerance
  model->AddConstraint(objective, floor, kInf, "keep_out_floor");
}

// Re-solves the LP of `m` with every integer column fixed at its value in
// r's solution, and keeps that solution if it violates the model less. CBC
// can return impulses of ~1e-4 m/s with bound violations near 1e-6 (its
// tolerances are absolute); the plain LP puts nonbasic columns exactly on
// their bounds.
void Polish(const ScheduleMilp& m, const milp::Solver& solver, const milp::SolveOptions& base,
            milp::SolveResult* r) {
  milp::LpData lp = m.lp();
  for (int j = 0; j < lp.num_cols(); ++j) {
    if (lp.col_type[j] == milp::VarType::kContinuous) continue;
    lp.col_lower[j] = lp.col_upper[j] = std::round(r->x[j]);
  }
  milp::SolveOptions o = base;
  o.initial_solution.reset();
  o.progress = nullptr;
  o.interrupt = nullptr;
  o.time_limit_s = 60.0;
  const milp::LpRelaxationResult lr = solver.SolveLpRelaxation(lp, o);
  if (lr.status != milp::SolveStatus::kOptimal) return;
  if (m.lp().MaxViolation(lr.x) >= m.lp().MaxViolation(r->x)) return;
  r->x = lr.x;
  r->objective = m.lp().Objective(lr.x);
  r->gap = milp::RelativeGap(r->objective, r->best_bound);
  r->detail += "; polished by the LP with the integers fixed";
  if (r->status == milp::SolveStatus::kOptimal && r->gap > base.relative_gap) {
    // The bound came from a solution that leaned on the tolerances: say so.
    r->status = milp::SolveStatus::kFeasible;
    r->detail += " (the polished plan is above the solver's bound by more than the requested gap)";
  }
}

// Decode and check the final plan, as SolveBuilt does when asked to.
void DecodeAndCheck(const ScheduleMilp& m, const SolveScheduleOptions& options, ScheduleResult* r) {
  r->schedule = m.Decode(r->solve.x);
  if (!options.check_schedule) return;
  const Clock::time_point t0 = Clock::now();
  const ScheduleProblem& p = m.problem();
  if (p.input_mode == InputMode::kOnOff) {
    r->check = CheckSchedule(p, r->schedule.burns, options.check);
  } else {
    r->impulsive_check = CheckImpulses(p, r->schedule.impulses);
  }
  r->checked = true;
  r->check_seconds = Since(t0);
}

}  // namespace

bool ConjunctionSolveOptions::IsValid(std::string* error) const {
  if (!(restart_ratio > 0.0 && restart_ratio <= 1.0)) {
    return common::Fail(
        error, "restart_ratio must be in (0, 1], got " + common::FormatG(restart_ratio, 10));
  }
  if (max_rounds < 1) {
    return common::Fail(error, "max_rounds must be >= 1, got " + std::to_string(max_rounds));
  }
  return true;
}

ConjunctionSolve SolveConjunction(const ScheduleMilp& first, const milp::Solver& solver,
                                  const SolveScheduleOptions& options,
                                  const ConjunctionSolveOptions& co) {
  if (!first.problem().conjunction || !first.keep_out()) {
    throw std::invalid_argument("SolveConjunction: the problem has no conjunction");
  }
  std::string err;
  if (!co.IsValid(&err)) throw std::invalid_argument("SolveConjunction: " + err);
  const Clock::time_point t0 = Clock::now();
  const double limit = options.milp.time_limit_s;
  ConjunctionSolve out;
  double best = kInf;
  Eigen::VectorXd best_x;
  if (co.fixed_face_start) {
    const ConjunctionStart s = FixedFaceStart(first, solver, options.milp);
    out.start_seconds = Since(t0);
    if (s.x.size() > 0) {
      best = s.objective;
      best_x = s.x;
      out.start_objective = s.objective;
      out.start_label = s.label;
    }
    out.lower_bound = s.lower_bound;
    out.without_objective = s.without_objective;
    out.without_x = s.without_x;
  }
  if (best_x.size() > 0 && milp::GapClosed(best, out.lower_bound, options.milp)) {
    // The start is within the requested gap of the optimum without the
    // conjunction, a lower bound: no round can do better than the gap asks.
    ScheduleResult& r = out.result;
    r.stats = first.stats();
    r.solve.status = milp::SolveStatus::kOptimal;
    r.solve.objective = best;
    r.solve.best_bound = std::min(best, out.lower_bound);
    r.solve.gap = milp::RelativeGap(best, r.solve.best_bound);
    r.solve.x = best_x;
    r.solve.wall_seconds = Since(t0);
    r.solve.incumbents.push_back({out.start_seconds, best, r.solve.best_bound});
    r.solve.detail =
        "the start is within the requested gap of the optimum without the conjunction (a lower "
        "bound): no budget round needed";
    r.solve.solver_version = solver.version();
    DecodeAndCheck(first, options, &r);  // the start's states are propagated, not CBC's
    return out;
  }
  const ScheduleMilp* current = &first;
  for (int round = 0;; ++round) {
    const Clock::time_point tr = Clock::now();
    const double budget = current->problem().conjunction->cost_budget;
    if (co.tighten_budget && best < budget) {
      // Rebuilt with the best known cost, 0.1 % above: that plan satisfies the
      // rows only to the solver's absolute tolerances, and the exact pruning
      // of a budget at its cost could drop a face it relies on.
      ScheduleProblem p = current->problem();
      p.conjunction->cost_budget = best * (1.0 + 1e-3) + 1e-12;
      BuildOptions b = first.options();
      if (co.lp_bounds) b.keep_out_bound_solver = &solver;
      auto rebuilt = std::make_shared<ScheduleMilp>(p, first.discrete(), b);
      if (std::isfinite(out.lower_bound)) {
        rebuilt->Modify([&](milp::Model& model) { AddObjectiveFloor(out.lower_bound, &model); });
      }
      out.milp = rebuilt;
      current = out.milp.get();
    }
    BudgetRound br;
    br.budget = current->problem().conjunction->cost_budget;
    br.binaries = current->keep_out()->num_binaries;
    SolveScheduleOptions o = options;
    o.prefix_diagnosis_s = 0.0;  // prefixes would cut the conjunction's times off
    o.check_schedule = false;    // the final plan is polished, then checked
    o.warm_start.clear();
    if (best_x.size() > 0) o.milp.initial_solution = StartFor(*current, best_x);
    o.milp.time_limit_s = std::max(0.0, limit - Since(t0));
    std::atomic<bool> stop{false};
    bool restart = false;
    const bool last_round = round + 1 >= co.max_rounds;
    const double offset = Since(t0);
    double forwarded = -kInf;
    o.milp.interrupt = &stop;
    o.milp.progress_interval_s = std::min(options.milp.progress_interval_s, 1.0);
    o.milp.progress = [&](const milp::SolveProgress& p) {
      if (options.milp.interrupt != nullptr && options.milp.interrupt->load()) stop = true;
      if (co.tighten_budget && !last_round && p.new_incumbent &&
          p.objective < co.restart_ratio * br.budget) {
        restart = true;
        stop = true;
      }
      if (options.milp.progress &&
          (p.new_incumbent || p.wall_seconds - forwarded >= options.milp.progress_interval_s)) {
        forwarded = p.wall_seconds;
        milp::SolveProgress q = p;
        q.wall_seconds += offset;
        options.milp.progress(q);
      }
    };
    // The budget rounds drive CBC on the whole MILP (restarts on a new
    // incumbent, budget-derived big-M): the problem-aware search, built for
    // the plain schedule MILP, is not used here.
    o.search.enabled = false;
    ScheduleResult r = SolveBuilt(*current, solver, o);
    br.status = r.solve.status;
    br.objective = r.solve.objective;
    br.best_bound = r.solve.best_bound;
    br.seconds = Since(tr);
    br.restarted = restart && r.has_schedule() && r.solve.objective < best;
    out.rounds.push_back(br);
    if (br.restarted) {
      best = r.solve.objective;
      best_x = r.solve.x;
      continue;
    }
    if (r.has_schedule()) {
      Polish(*current, solver, options.milp, &r.solve);
      DecodeAndCheck(*current, options, &r);
    }
    out.result = std::move(r);
    return out;
  }
}

}  // namespace thrustsched::transcription
