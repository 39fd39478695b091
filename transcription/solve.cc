#include "transcription/solve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/format.h"
#include "dynamics/propagation.h"

namespace thrustsched::transcription {
namespace {

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// See SolveScheduleOptions::prefix_diagnosis_s; at most budget_s seconds.
// Returns the reason if a prefix of the horizon is proven infeasible, empty
// otherwise.
std::string DiagnosePrefixes(const ScheduleMilp& milp, const milp::Solver& solver,
                             const SolveScheduleOptions& options, double budget_s) {
  const auto t0 = std::chrono::steady_clock::now();
  const ScheduleProblem& full = milp.problem();
  const int n = full.num_intervals();
  std::vector<int> lengths;
  for (int divisor : {32, 8, 2}) {
    const int k = std::max(2, n / divisor);
    if (k < n && (lengths.empty() || k > lengths.back())) lengths.push_back(k);
  }
  for (size_t q = 0; q < lengths.size(); ++q) {
    const double left = budget_s - Seconds(t0);
    if (left <= 0.0) break;
    const int k = lengths[q];
    ScheduleProblem p = full;
    p.grid.assign(full.grid.begin(), full.grid.begin() + k + 1);
    p.terminal = TerminalSpec{};
    p.rules.allow_burn_across_end = true;
    // A window that starts after the prefix constrains nothing in it.
    if (p.window.enforce_from_s > p.grid.back()) continue;
    std::vector<ForcedOff> forced;
    for (const ForcedOff& f : full.forced_off) {
      if (f.start_s < p.grid.back()) forced.push_back(f);
    }
    p.forced_off = forced;
    std::vector<StateConstraint> constraints;
    for (const StateConstraint& c : full.state_constraints) {
      if (c.t_s <= p.grid.back()) constraints.push_back(c);
    }
    p.state_constraints = constraints;
    milp::SolveOptions o = options.milp;
    o.time_limit_s = left / static_cast<double>(lengths.size() - q);
    o.progress = nullptr;
    o.initial_solution.reset();
    o.objective_step = 0.0;
    try {
      const ScheduleMilp prefix(p, milp.options());
      const milp::SolveResult r = solver.Solve(prefix.lp(), o);
      if (r.status == milp::SolveStatus::kInfeasible) {
        const double hours = (p.grid.back() - p.grid.front()) / 3600.0;
        char buf[256];
        std::snprintf(buf, sizeof(buf),
                      "the first %.4g h of the horizon (%d of %d intervals) are infeasible on "
                      "their own (proven in %.3g s), so the whole problem is",
                      hours, k, n, r.wall_seconds);
        return buf;
      }
      if (r.has_solution()) continue;  // this prefix is feasible: try a longer one
    } catch (const std::exception&) {
      return "";
    }
    if (options.milp.interrupt != nullptr && options.milp.interrupt->load()) return "";
  }
  return "";
}

// The diagnosis may follow the solve (SolveScheduleOptions::prefix_diagnosis_s).
bool DiagnosisMayRun(const ScheduleProblem& p, const SolveScheduleOptions& options) {
  return options.prefix_diagnosis_s > 0.0 && p.input_mode == InputMode::kOnOff &&
         p.window.enabled() && !p.window.soft;
}

}  // namespace

TimeLimitShares ShareTimeLimit(double time_limit_s, double diagnosis_cap_s,
                               double diagnosis_share) {
  TimeLimitShares s;
  s.solve_s = time_limit_s;
  if (!(diagnosis_cap_s > 0.0)) return s;
  if (!std::isfinite(time_limit_s)) {
    s.diagnosis_s = diagnosis_cap_s;
    return s;
  }
  s.diagnosis_s = std::max(0.0, std::min(diagnosis_cap_s, diagnosis_share * time_limit_s));
  s.solve_s = time_limit_s - s.diagnosis_s;
  return s;
}

double DiagnosisTimeLeft(double time_limit_s, double diagnosis_cap_s, double used_s) {
  if (!(diagnosis_cap_s > 0.0)) return 0.0;
  return std::max(0.0, std::min(diagnosis_cap_s, time_limit_s - used_s));
}

ImpulsiveCheck CheckImpulses(const ScheduleProblem& p, const std::vector<Impulse>& impulses) {
  std::string err;
  if (!p.IsValid(&err)) throw std::invalid_argument(err);
  const dynamics::LinearModel& model = *p.model;
  const int nn = p.num_intervals();
  // Impulse delta-v (m/s) along each thruster direction, per node.
  std::vector<Eigen::Vector3d> kick(nn + 1, Eigen::Vector3d::Zero());
  for (const Impulse& im : impulses) {
    if (im.node < 0 || im.node > nn || im.thruster < 0 || im.thruster >= p.thrusters.size()) {
      throw std::invalid_argument("CheckImpulses: impulse at node " + std::to_string(im.node) +
                                  " of thruster " + std::to_string(im.thruster) + " out of range");
    }
    kick[im.node] += im.delta_v_m_s * p.thrusters.thruster(im.thruster).direction;
  }
  ImpulsiveCheck out;
  Eigen::VectorXd x = p.initial_state;
  const Eigen::MatrixXd no_input = Eigen::MatrixXd::Zero(3, 1);
  for (int j = 0; j <= nn; ++j) {
    if (j > 0 && p.window.enabled() && p.grid[j] >= p.window.enforce_from_s - kTimeTolerance) {
      const Eigen::VectorXd y = model.EvaluateOutput(p.grid[j]).c * x;
      for (size_t k = 0; k < p.window.outputs.size(); ++k) {
        out.max_window_violation = std::max(
            out.max_window_violation, std::abs(y[p.window.outputs[k]]) - p.window.half_widths[k]);
      }
    }
    x += model.Evaluate(p.grid[j]).b * kick[j];
    if (j == nn) break;
    x = dynamics::PropagateLinear(model, no_input, x, p.grid[j], {}, {p.grid[j + 1]})[0];
  }
  out.final_state = x;
  out.terminal_error = TerminalError(p.terminal, x, model.state_scale());
  return out;
}

ScheduleResult SolveBuilt(const ScheduleMilp& milp, const milp::Solver& solver,
                          const SolveScheduleOptions& options) {
  const auto t_start = std::chrono::steady_clock::now();
  ScheduleResult r;
  r.stats = milp.stats();
  r.infeasibility_reasons = milp.infeasibility_reasons();
  milp::SolveOptions solve_options = options.milp;
  if (solve_options.objective_step == 0.0) solve_options.objective_step = milp.objective_step();
  const ScheduleProblem& p = milp.problem();
  // The time limit bounds the solve and the diagnosis together.
  const bool may_diagnose = DiagnosisMayRun(p, options);
  const TimeLimitShares shares =
      ShareTimeLimit(options.milp.time_limit_s, may_diagnose ? options.prefix_diagnosis_s : 0.0,
                     options.diagnosis_share);
  solve_options.time_limit_s = shares.solve_s;
  r.solve_time_limit_s = shares.solve_s;
  r.diagnosis_time_limit_s = shares.diagnosis_s;
  if (p.input_mode == InputMode::kOnOff) {
    if (!options.warm_start.empty()) {
      solve_options.initial_solution = milp.StartFromBurns(options.warm_start);
    }
    // Solutions are completed from their on-off pattern (states propagated)
    // rather than by an LP over the continuous columns.
    solve_options.complete_solution = [&milp](Eigen::VectorXd* x) {
      return milp.CompleteFromPattern(x);
    };
  }
  if (p.input_mode == InputMode::kOnOff && options.search.enabled) {
    std::vector<Eigen::VectorXd> starts;
    if (solve_options.initial_solution) starts.push_back(*solve_options.initial_solution);
    r.solve = SearchSchedule(milp, solver, solve_options, options.search, starts, &r.search);
  } else {
    r.solve = solver.Solve(milp.lp(), solve_options);
  }
  const bool interrupted = options.milp.interrupt != nullptr && options.milp.interrupt->load();
  if (r.solve.status == milp::SolveStatus::kNoSolutionFound && !interrupted && may_diagnose) {
    r.diagnosis_time_limit_s =
        DiagnosisTimeLeft(options.milp.time_limit_s, options.prefix_diagnosis_s, Seconds(t_start));
  }
  if (r.solve.status == milp::SolveStatus::kNoSolutionFound && !interrupted && may_diagnose &&
      r.diagnosis_time_limit_s > 0.0) {
    if (options.announce) {
      char buf[320];
      std::snprintf(buf, sizeof(buf),
                    "no schedule and no proof: looking for a proof of infeasibility on the first "
                    "1/32, 1/8 and 1/2 of the horizon (at most %.3g s%s)",
                    r.diagnosis_time_limit_s,
                    std::isfinite(options.milp.time_limit_s) ? ", the rest of the time limit" : "");
      options.announce(buf);
    }
    const auto t_diagnosis = std::chrono::steady_clock::now();
    const std::string reason = DiagnosePrefixes(milp, solver, options, r.diagnosis_time_limit_s);
    r.diagnosis_seconds = Seconds(t_diagnosis);
    if (!reason.empty()) {
      r.solve.status = milp::SolveStatus::kInfeasible;
      r.solve.detail += "; " + reason + " infeasible";
      r.infeasibility_reasons.push_back(reason + " infeasible");
    }
  }
  if (!r.solve.has_solution()) return r;
  r.schedule = milp.Decode(r.solve.x);
  if (!options.check_schedule) return r;
  const auto t0 = std::chrono::steady_clock::now();
  if (p.input_mode == InputMode::kOnOff) {
    r.check = CheckSchedule(p, r.schedule.burns, options.check);
  } else {
    r.impulsive_check = CheckImpulses(p, r.schedule.impulses);
  }
  r.checked = true;
  r.check_seconds = Seconds(t0);
  return r;
}

bool SolveScheduleOptions::IsValid(std::string* error) const {
  std::string e;
  if (!build.IsValid(&e)) return common::Fail(error, "build." + e);
  if (!milp.IsValid(&e)) return common::Fail(error, "milp: " + e);
  if (search.enabled && !search.IsValid(&e)) return common::Fail(error, "search: " + e);
  if (check_schedule && !check.IsValid(&e)) return common::Fail(error, "check." + e);
  if (!(diagnosis_share >= 0.0 && diagnosis_share < 1.0)) {
    return common::Fail(
        error, "diagnosis_share: must be in [0, 1), got " + common::FormatG(diagnosis_share, 10));
  }
  return true;
}

ScheduleResult SolveSchedule(const ScheduleProblem& problem, const milp::Solver& solver,
                             const SolveScheduleOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument("SolveSchedule: options." + error);
  const ScheduleMilp milp(problem, options.build);
  return SolveBuilt(milp, solver, options);
}

}  // namespace thrustsched::transcription
