#include "planning/long_horizon.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <sstream>
#include <stdexcept>

#include "common/constants.h"
#include "common/error.h"
#include "common/format.h"
#include "common/timing.h"
#include "dynamics/geo_model.h"
#include "dynamics/propagation.h"
#include "planning/internal/long_horizon_cycle.h"
#include "transcription/schedule_milp.h"

namespace thrustsched::planning {

using common::Clock;
using common::Fail;
using common::FormatG;
using common::Since;
using transcription::BoundaryHistory;
using transcription::ForcedOff;
using transcription::InputMode;
using transcription::kTimeTolerance;
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double CpuSince(std::clock_t c0) { return static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC; }

// True if `value` is an integer multiple of `step` (relative 1e-9).
bool Divides(double step, double value) {
  const double r = value / step;
  return std::abs(r - std::round(r)) <= 1e-9 * std::max(1.0, r);
}

int Steps(double step, double value) { return static_cast<int>(std::llround(value / step)); }

bool Interrupted(const milp::SolveOptions& o) {
  return o.interrupt != nullptr && o.interrupt->load();
}

}  // namespace

// ---------------------------------------------------------------------------
// Names.

std::string_view ToString(HorizonMode mode) {
  return mode == HorizonMode::kFixed ? "fixed" : "receding";
}

HorizonMode ParseHorizonMode(std::string_view name) {
  if (name == "fixed") return HorizonMode::kFixed;
  if (name == "receding") return HorizonMode::kReceding;
  throw std::invalid_argument("horizon mode must be \"fixed\" or \"receding\", got \"" +
                              std::string(name) + "\"");
}

std::string_view ToString(Fallback fallback) {
  switch (fallback) {
    case Fallback::kNone:
      return "none";
    case Fallback::kSoftWindow:
      return "soft_window";
    case Fallback::kSoftWindowFreeTerminal:
      return "soft_window_free_terminal";
    case Fallback::kZeroThrust:
      return "zero_thrust";
  }
  return "unknown";
}

Fallback ParseFallback(std::string_view name) {
  for (Fallback f : {Fallback::kNone, Fallback::kSoftWindow, Fallback::kSoftWindowFreeTerminal,
                     Fallback::kZeroThrust}) {
    if (name == ToString(f)) return f;
  }
  throw std::invalid_argument(
      "fallback must be one of none, soft_window, soft_window_free_terminal, zero_thrust; got \"" +
      std::string(name) + "\"");
}

// ---------------------------------------------------------------------------
// Options.

int LongHorizonOptions::num_cycles() const {
  if (!IsValid(nullptr)) return 0;
  const double applied = mode == HorizonMode::kFixed ? cycle_s : control_s;
  return static_cast<int>(std::ceil(duration_s / applied - 1e-9));
}

bool LongHorizonOptions::IsValid(std::string* error) const {
  if (!std::isfinite(start_s))
    return Fail(error, "long_horizon.start_s must be finite, got " + FormatG(start_s, 12));
  auto positive = [&](double v, const char* name) {
    if (!std::isfinite(v) || v <= 0.0) {
      return Fail(error, std::string("long_horizon.") + name + " must be finite and > 0, got " +
                             FormatG(v, 12));
    }
    return true;
  };
  if (!positive(duration_s, "duration_s") || !positive(cycle_s, "cycle_s") ||
      !positive(step_s, "step_s")) {
    return false;
  }
  if (!Divides(step_s, cycle_s)) {
    return Fail(error, "long_horizon.step_s " + FormatG(step_s, 12) +
                           " s does not divide cycle_s " + FormatG(cycle_s, 12) + " s");
  }
  if (!Divides(step_s, duration_s)) {
    return Fail(error, "long_horizon.step_s " + FormatG(step_s, 12) +
                           " s does not divide duration_s " + FormatG(duration_s, 12) + " s");
  }
  if (mode == HorizonMode::kReceding) {
    if (!positive(control_s, "control_s")) return false;
    if (!(control_s < cycle_s)) {
      return Fail(error, "long_horizon.control_s " + FormatG(control_s, 12) +
                             " s must be shorter than cycle_s " + FormatG(cycle_s, 12) +
                             " s in receding mode");
    }
    if (!Divides(step_s, control_s)) {
      return Fail(error, "long_horizon.step_s " + FormatG(step_s, 12) +
                             " s does not divide control_s " + FormatG(control_s, 12) + " s");
    }
  }
  const double applied = mode == HorizonMode::kFixed ? cycle_s : control_s;
  if (duration_s / applied > 100000.0) {
    return Fail(error,
                "long_horizon: duration_s / cycle length = " + FormatG(duration_s / applied, 12) +
                    " cycles; at most 100000 are allowed");
  }
  for (size_t k = 0; k < outages.size(); ++k) {
    const ThrusterOutage& o = outages[k];
    if (std::isnan(o.from_s) || std::isnan(o.until_s) || !(o.until_s > o.from_s)) {
      return Fail(error, "long_horizon.outages[" + std::to_string(k) +
                             "] must have from_s < until_s, got [" + FormatG(o.from_s, 12) + ", " +
                             FormatG(o.until_s, 12) + ")");
    }
  }
  if (!std::isfinite(soft_penalty) || soft_penalty <= 0.0) {
    return Fail(error, "long_horizon.soft_penalty must be finite and > 0, got " +
                           FormatG(soft_penalty, 12));
  }
  if (!std::isfinite(improve_above_gap)) {
    return Fail(error, "long_horizon.improve_above_gap must be finite, got " +
                           FormatG(improve_above_gap, 12));
  }
  if (replay_samples_per_step < 1 || replay_samples_per_step > 1000) {
    return Fail(error, "long_horizon.replay_samples_per_step must be in [1, 1000], got " +
                           std::to_string(replay_samples_per_step));
  }
  if (solve.check.nonlinear) {
    return Fail(error,
                "long_horizon.solve.check.nonlinear must be null (the cycle replay is done from "
                "the true state by the long-horizon driver)");
  }
  std::string e;
  if (!solve.milp.IsValid(&e)) return Fail(error, "long_horizon.solve: " + e);
  return true;
}

// ---------------------------------------------------------------------------
// The driver.

LongHorizonSimulation::LongHorizonSimulation(
    ScheduleProblem base, LongHorizonOptions options,
    std::shared_ptr<const dynamics::GeoSimulator> simulator,
    std::shared_ptr<const milp::Solver> solver)
    : base_(std::move(base)),
      options_(std::move(options)),
      simulator_(std::move(simulator)),
      solver_(std::move(solver)) {
  std::string err;
  if (!options_.IsValid(&err)) throw std::invalid_argument(err);
  if (!simulator_) throw std::invalid_argument("LongHorizonSimulation: simulator is null");
  if (!solver_) throw std::invalid_argument("LongHorizonSimulation: solver is null");
  if (!base_.model) throw std::invalid_argument("LongHorizonSimulation: base.model is null");
  const auto* geo = dynamic_cast<const dynamics::GeoLinearModel*>(base_.model.get());
  if (geo == nullptr) {
    throw std::invalid_argument("LongHorizonSimulation: base.model must be the GEO model, got '" +
                                std::string(base_.model->name()) + "'");
  }
  if (geo->options().station_longitude_deg != simulator_->options().station_longitude_deg ||
      geo->options().epoch != simulator_->options().epoch) {
    throw std::invalid_argument("LongHorizonSimulation: the simulator's station (" +
                                FormatG(simulator_->options().station_longitude_deg, 12) +
                                " deg, epoch " + simulator_->options().epoch +
                                ") differs from the model's (" +
                                FormatG(geo->options().station_longitude_deg, 12) + " deg, epoch " +
                                geo->options().epoch + ")");
  }
  if (base_.input_mode != InputMode::kOnOff) {
    throw std::invalid_argument("LongHorizonSimulation: input_mode must be on-off");
  }
  // The base grid is replaced; give it one valid cycle grid so that IsValid
  // judges the remaining fields.
  base_.grid = dynamics::UniformGrid(options_.start_s, options_.start_s + options_.step_s, 1);
  base_.terminal = TerminalSpec{};
  base_.window.soft = false;
  base_.window.enforce_from_s = -kInf;
  if (!base_.IsValid(&err))
    throw std::invalid_argument("LongHorizonSimulation: base problem: " + err);
  if (!base_.window.enabled()) {
    throw std::invalid_argument("LongHorizonSimulation: base.window must constrain lat and lon");
  }
  for (int i = 0; i < base_.thrusters.size(); ++i) {
    if (base_.history.is_on(i)) {
      throw std::invalid_argument("LongHorizonSimulation: base.history.on_for_s[" +
                                  std::to_string(i) +
                                  "] > 0 is not supported (start with every thruster off)");
    }
  }
  for (size_t k = 0; k < options_.outages.size(); ++k) {
    const int t = options_.outages[k].thruster;
    if (t < 0 || t >= base_.thrusters.size()) {
      throw std::invalid_argument("long_horizon.outages[" + std::to_string(k) + "].thruster " +
                                  std::to_string(t) + " is not a thruster index (0.." +
                                  std::to_string(base_.thrusters.size() - 1) + ")");
    }
  }
  if (options_.mode == HorizonMode::kFixed || options_.terminal_in_receding) {
    TerminalSpec t = options_.terminal;
    ScheduleProblem probe = base_;
    probe.terminal = t;
    if (!probe.IsValid(&err)) throw std::invalid_argument("long_horizon.terminal: " + err);
  }
  num_cycles_ = options_.num_cycles();
}

LongHorizonSimulation::CycleTimes LongHorizonSimulation::Times(int k) const {
  if (k < 0 || k >= num_cycles_) {
    throw std::out_of_range("LongHorizonSimulation: cycle " + std::to_string(k) +
                            " out of range (0.." + std::to_string(num_cycles_ - 1) + ")");
  }
  const LongHorizonOptions& o = options_;
  const double end = o.start_s + o.duration_s;
  const double step = o.step_s;
  const int total = Steps(step, o.duration_s);
  CycleTimes t;
  if (o.mode == HorizonMode::kFixed) {
    const int per = Steps(step, o.cycle_s);
    const int a = k * per;
    const int b = std::min(total, a + per);
    t.start_s = o.start_s + a * step;
    t.applied_end_s = b == total ? end : o.start_s + b * step;
    t.prediction_end_s = t.applied_end_s;
  } else {
    const int per = Steps(step, o.control_s);
    const int a = k * per;
    const int b = std::min(total, a + per);
    t.start_s = o.start_s + a * step;
    t.applied_end_s = b == total ? end : o.start_s + b * step;
    t.prediction_end_s = o.start_s + (a + Steps(step, o.cycle_s)) * step;
  }
  return t;
}

LongHorizonState LongHorizonSimulation::InitialState() const {
  LongHorizonState s;
  s.next_cycle = 0;
  s.time_s = options_.start_s;
  s.eci = simulator_->EciFromRelative(base_.initial_state, options_.start_s);
  const int m = base_.thrusters.size();
  s.last_burn_end_s.assign(m, -kInf);
  for (int i = 0; i < m; ++i) {
    const double off = base_.history.off_for(i);
    if (std::isfinite(off)) s.last_burn_end_s[i] = options_.start_s - off;
  }
  return s;
}

std::vector<bool> LongHorizonSimulation::Available(int k) const {
  const CycleTimes t = Times(k);
  const int m = base_.thrusters.size();
  std::vector<bool> a(m, true);
  for (int i = 0; i < m; ++i) a[i] = base_.thrusters.thruster(i).enabled;
  // A thruster is unavailable if outages (and fixed forced-off windows) cover
  // the whole prediction [start, prediction_end).
  for (int i = 0; i < m; ++i) {
    if (!a[i]) continue;
    std::vector<std::pair<double, double>> cover;
    for (const ThrusterOutage& o : options_.outages) {
      if (o.thruster == i) cover.emplace_back(o.from_s, o.until_s);
    }
    for (const ForcedOff& f : base_.forced_off) {
      if (f.thruster == i) cover.emplace_back(f.start_s, f.end_s);
    }
    std::sort(cover.begin(), cover.end());
    double reached = t.start_s;
    for (const auto& [from, until] : cover) {
      if (from > reached + kTimeTolerance) break;
      reached = std::max(reached, until);
    }
    if (reached >= t.prediction_end_s - kTimeTolerance) a[i] = false;
  }
  return a;
}

ScheduleProblem LongHorizonSimulation::CycleProblem(const LongHorizonState& state) const {
  const int k = state.next_cycle;
  if (k < 0 || k >= num_cycles_) {
    throw std::invalid_argument("LongHorizonSimulation: state.next_cycle " + std::to_string(k) +
                                " is not a cycle (0.." + std::to_string(num_cycles_ - 1) + ")");
  }
  const CycleTimes t = Times(k);
  if (std::abs(state.time_s - t.start_s) > 1e-6) {
    throw std::invalid_argument("LongHorizonSimulation: state.time_s " + FormatG(state.time_s, 12) +
                                " s is not the start of cycle " + std::to_string(k) + " (" +
                                FormatG(t.start_s, 12) + " s)");
  }
  const int m = base_.thrusters.size();
  if (static_cast<int>(state.last_burn_end_s.size()) != m) {
    throw std::invalid_argument("LongHorizonSimulation: state.last_burn_end_s has " +
                                std::to_string(state.last_burn_end_s.size()) + " entries for " +
                                std::to_string(m) + " thrusters");
  }
  ScheduleProblem p = base_;
  const int n = Steps(options_.step_s, t.prediction_end_s - t.start_s);
  p.grid = dynamics::UniformGrid(t.start_s, t.prediction_end_s, n);
  p.initial_state = simulator_->RelativeFromEci(state.eci, t.start_s);
  p.rules.allow_burn_across_end = false;
  p.history = BoundaryHistory::AllOff(m);
  for (int i = 0; i < m; ++i) {
    const double e = state.last_burn_end_s[i];
    if (std::isnan(e) || e > t.start_s + kTimeTolerance) {
      throw std::invalid_argument("LongHorizonSimulation: state.last_burn_end_s[" +
                                  std::to_string(i) + "] = " + FormatG(e, 12) +
                                  " s is after the cycle start " + FormatG(t.start_s, 12) + " s");
    }
    p.history.off_for_s[i] = std::isfinite(e) ? std::max(0.0, t.start_s - e) : kInf;
  }
  for (const ThrusterOutage& o : options_.outages) {
    if (o.until_s <= t.start_s || o.from_s >= t.prediction_end_s) continue;
    p.forced_off.push_back(
        {o.thruster, std::max(o.from_s, t.start_s), std::min(o.until_s, t.prediction_end_s)});
  }
  if (options_.mode == HorizonMode::kFixed || options_.terminal_in_receding) {
    p.terminal = options_.terminal;
  } else {
    p.terminal = TerminalSpec{};
  }
  p.window.soft = false;
  p.window.soft_penalty = options_.soft_penalty;
  p.window.enforce_from_s = -kInf;
  return p;
}

ScheduleMilp LongHorizonSimulation::BuildCycleMilp(const ScheduleProblem& p,
                                                   int control_node) const {
  ScheduleMilp milp(p, options_.solve.build);
  if (control_node > 0 && control_node < p.num_intervals()) {
    // No burn across the control boundary: on[c-1] + on[c] <= 1.
    const int m = p.thrusters.size();
    milp.Modify([&](milp::Model& model) {
      for (int i = 0; i < m; ++i) {
        milp::LinearExpr e(milp.on(i, control_node - 1));
        e.AddTerm(milp.on(i, control_node), 1.0);
        model.AddConstraint(e, -kInf, 1.0, "control_boundary_" + std::to_string(i));
      }
    });
  }
  return milp;
}

void LongHorizonSimulation::ImproveAccepted(const ScheduleProblem& p, int control_node,
                                            bool accepted_raw, ScheduleResult* accepted,
                                            CycleRecord* rec) const {
  const milp::SolveOptions& so = options_.solve.milp;
  long long nodes = options_.improve_max_nodes;
  if (nodes < 0) nodes = so.max_nodes >= 0 ? 5 * std::max(so.max_nodes, 1LL) : 0;
  if (options_.improve_above_gap <= 0.0 || nodes <= 0) return;
  if (rec->fallback != Fallback::kNone || p.window.soft) return;  // fallbacks: as they are
  // Two passes, each only while the gap is still above the threshold:
  //  1. the same MILP from the accepted schedule (MIP start and cutoff);
  //  2. its elastic (soft-window) version, solved cold (no MIP start: with
  //     the incumbent as start and cutoff CBC skips the heuristics that find
  //     the good schedules) with the cycle's own node budget. The elastic
  //     problem is a relaxation: a schedule of it without window violation is
  //     a schedule of the cycle. CBC finds good schedules of it far more
  //     easily on some weeks (six thrusters, 2034-01-15: 0.82 m/s in 100
  //     nodes cold, where the hard problem's first incumbent was 5.8 m/s and
  //     500 more nodes from it, hard or elastic, found nothing better).
  //  3. (retry_without_preprocessing) the same MILP with CBC's preprocessing
  //     and presolve off, cold, with the cycle's node budget: on the same
  //     six-thruster weeks CBC's preprocessed model leads the search astray
  //     (2034-09-24: 5.49 m/s at a 94 % gap with it, 0.38 m/s without).
  // A schedule accepted from the preprocessing-off retry (CBC's preprocessed
  // model found none) keeps that configuration for passes 1 and 2, and needs
  // no pass 3 (2034-04-02, six thrusters: the elastic pass gives 3.25 m/s with
  // preprocessing, 0.36 m/s without).
  const int passes = options_.retry_without_preprocessing && so.presolve && !accepted_raw ? 3 : 2;
  for (int pass = 0; pass < passes; ++pass) {
    if (!(accepted->solve.gap > options_.improve_above_gap)) return;
    const bool elastic = pass == 1;
    const bool raw = pass == 2;
    ScheduleProblem q = p;
    if (elastic) {
      q.window.soft = true;
      q.window.soft_penalty = options_.soft_penalty;
    }
    CycleAttempt attempt;
    attempt.level = Fallback::kNone;
    ScheduleResult r;
    try {
      const Clock::time_point tb = Clock::now();
      const ScheduleMilp milp = BuildCycleMilp(q, control_node);
      rec->build_seconds += Since(tb);
      SolveScheduleOptions opt = options_.solve;
      opt.check.nonlinear.reset();
      opt.check.nonlinear_default = false;
      if (accepted_raw || raw) opt.milp.presolve = false;
      if (elastic || raw) {
        opt.warm_start.clear();
        opt.milp.max_nodes = so.max_nodes >= 0 ? so.max_nodes : nodes;
      } else {
        opt.warm_start = accepted->schedule.burns;
        opt.milp.max_nodes = nodes;
      }
      r = SolveBuilt(milp, *solver_, opt);
      attempt.status = r.solve.status;
      attempt.solve_seconds = r.solve.wall_seconds;
      attempt.detail = std::string("improvement pass ") +
                       (raw       ? "(CBC preprocessing and presolve off, cold"
                        : elastic ? "(elastic window, cold"
                                  : "(from the accepted schedule") +
                       (accepted_raw ? ", CBC preprocessing and presolve off" : "") + ", gap " +
                       FormatG(accepted->solve.gap, 12) + ", " +
                       std::to_string(opt.milp.max_nodes) + " nodes): " + r.solve.detail;
      rec->check_seconds += r.check_seconds;
    } catch (const std::exception& e) {
      attempt.status = milp::SolveStatus::kError;
      attempt.detail = std::string("improvement pass: ") + e.what();
    }
    // An elastic schedule counts only without window violation (the nodes
    // within 1e-6 of the half width, as the hard rows hold them).
    double tolerance = 0.0;
    for (double w : p.window.half_widths) tolerance = std::max(tolerance, 1e-6 * w);
    const bool usable =
        r.has_schedule() && (!elastic || (r.checked && r.check.operational_ok &&
                                          r.check.max_window_violation_at_nodes <= tolerance));
    if (usable && r.solve.objective < accepted->solve.objective - 1e-9) {
      // Either problem's bound is a valid bound of the cycle's MILP.
      const double bound = std::max(accepted->solve.best_bound, r.solve.best_bound);
      *accepted = std::move(r);
      accepted->solve.best_bound = bound;
      accepted->solve.gap = milp::RelativeGap(accepted->solve.objective, bound);
      accepted->solve.status = accepted->solve.gap <= so.relative_gap
                                   ? milp::SolveStatus::kOptimal
                                   : milp::SolveStatus::kFeasible;
      attempt.detail += "; kept";
    } else if (usable && r.solve.best_bound > accepted->solve.best_bound) {
      accepted->solve.best_bound = r.solve.best_bound;  // same schedule, better proof
      accepted->solve.gap = milp::RelativeGap(accepted->solve.objective, r.solve.best_bound);
      attempt.detail += "; no better schedule, better bound";
    } else {
      attempt.detail += usable ? "; no better schedule" : "; no usable schedule";
    }
    rec->solve_seconds += attempt.solve_seconds;
    rec->attempts.push_back(attempt);
    if (so.interrupt != nullptr && so.interrupt->load()) return;
  }
}

namespace {

// Thrusters enabled but under an outage during the cycle, as a note.
std::string OutageNote(const dynamics::ThrusterSet& thrusters, const std::vector<bool>& available) {
  std::string off;
  for (int i = 0; i < thrusters.size(); ++i) {
    if (thrusters.thruster(i).enabled && !available[i]) {
      off += (off.empty() ? "" : ", ") + thrusters.thruster(i).name;
    }
  }
  return off.empty() ? std::string() : "unavailable (outage): " + off;
}

}  // namespace

std::vector<LongHorizonSimulation::Level> LongHorizonSimulation::Levels(
    bool controllable, const ScheduleProblem& nominal) const {
  // Attempts in order of escalation. An uncontrollable cycle goes straight to
  // the best-effort problem (the nominal one is infeasible in general).
  // raw: the nominal problem again with CBC's preprocessing and presolve off
  // (retry_without_preprocessing), only after a nominal attempt that a limit
  // stopped without a schedule.
  std::vector<Level> levels;
  if (!controllable) return {{Fallback::kSoftWindowFreeTerminal, false}};
  levels.push_back({Fallback::kNone, false});
  if (options_.retry_without_preprocessing && options_.solve.milp.presolve) {
    levels.push_back({Fallback::kNone, true});
  }
  levels.push_back({Fallback::kSoftWindow, false});
  if (nominal.terminal.kind != TerminalKind::kFree) {
    levels.push_back({Fallback::kSoftWindowFreeTerminal, false});
  }
  return levels;
}

ScheduleResult LongHorizonSimulation::Attempt(const ScheduleProblem& p, const Level& lv,
                                              int control_node, CycleAttempt* attempt,
                                              CycleRecord* rec) const {
  attempt->level = lv.level;
  ScheduleResult r;
  try {
    const Clock::time_point tb = Clock::now();
    ScheduleMilp milp = BuildCycleMilp(p, control_node);
    rec->build_seconds += Since(tb);
    SolveScheduleOptions opt = options_.solve;
    opt.check.nonlinear.reset();
    opt.check.nonlinear_default = false;  // replayed below, from the true state
    if (lv.level == Fallback::kSoftWindowFreeTerminal) {
      // Zero thrust is feasible here (the window is soft, the end free):
      // start from it, so that a schedule exists whatever the time limit.
      opt.warm_start.clear();
      opt.milp.initial_solution = milp.StartFromBurns({});
    }
    if (lv.raw) opt.milp.presolve = false;
    r = SolveBuilt(milp, *solver_, opt);
    attempt->status = r.solve.status;
    attempt->solve_seconds = r.solve.wall_seconds;
    attempt->detail = std::string(lv.raw ? "retry with CBC preprocessing and presolve off: " : "") +
                      r.solve.detail;
    for (const std::string& reason : r.infeasibility_reasons) {
      attempt->detail += (attempt->detail.empty() ? "" : "; ") + reason;
    }
    rec->check_seconds += r.check_seconds;
  } catch (const std::exception& e) {
    attempt->status = milp::SolveStatus::kError;
    attempt->detail = e.what();
  }
  return r;
}

bool LongHorizonSimulation::SolveCycle(const ScheduleProblem& nominal, bool controllable,
                                       int control_node, ScheduleResult* accepted,
                                       CycleRecord* rec) const {
  const milp::SolveOptions& so = options_.solve.milp;
  for (const Level& lv : Levels(controllable, nominal)) {
    if (lv.raw && rec->attempts.back().status != milp::SolveStatus::kNoSolutionFound) continue;
    ScheduleProblem p = nominal;
    if (lv.level != Fallback::kNone) p.window.soft = true;
    if (lv.level == Fallback::kSoftWindowFreeTerminal) p.terminal = TerminalSpec{};
    CycleAttempt attempt;
    ScheduleResult r = Attempt(p, lv, control_node, &attempt, rec);
    rec->solve_seconds += attempt.solve_seconds;
    rec->attempts.push_back(attempt);
    if (Interrupted(so)) {
      rec->interrupted = true;
      return false;
    }
    if (r.has_schedule()) {
      *accepted = std::move(r);
      rec->fallback = lv.level;
      ImproveAccepted(p, control_node, lv.raw, accepted, rec);
      if (Interrupted(so)) rec->interrupted = true;
      return !rec->interrupted;
    }
  }
  return false;
}

CycleRecord LongHorizonSimulation::RunCycle(LongHorizonState* state) const {
  const Clock::time_point t_cycle = Clock::now();
  const std::clock_t cpu_cycle = std::clock();
  const ScheduleProblem nominal = CycleProblem(*state);
  const int k = state->next_cycle;
  const CycleTimes t = Times(k);

  CycleRecord rec;
  rec.index = k;
  rec.start_s = t.start_s;
  rec.applied_end_s = t.applied_end_s;
  rec.prediction_end_s = t.prediction_end_s;
  rec.eci_start = state->eci;
  rec.initial_state = nominal.initial_state;
  rec.on_time_s.assign(base_.thrusters.size(), 0.0);

  const std::vector<bool> available = Available(k);
  const Controllability ctrl = CheckControllability(base_.thrusters, available);
  rec.controllable = ctrl.controllable;
  if (!ctrl.controllable) rec.note = ctrl.reason;
  const std::string outage = OutageNote(base_.thrusters, available);
  if (!outage.empty()) rec.note += std::string(rec.note.empty() ? "" : "; ") + outage;

  // Receding mode: the boundary node of the applied part.
  const int control_node = options_.mode == HorizonMode::kReceding
                               ? Steps(options_.step_s, t.applied_end_s - t.start_s)
                               : -1;
  ScheduleResult accepted;
  const bool have = SolveCycle(nominal, ctrl.controllable, control_node, &accepted, &rec);
  if (rec.interrupted) {
    rec.wall_seconds = Since(t_cycle);
    rec.cpu_seconds = CpuSince(cpu_cycle);
    return rec;
  }
  if (have) {
    internal::RecordAccepted(accepted, &rec);
  } else {
    rec.fallback = Fallback::kZeroThrust;
    rec.status = rec.attempts.empty() ? milp::SolveStatus::kError : rec.attempts.back().status;
  }
  internal::ApplyPlan(have ? accepted.schedule.burns : std::vector<Burn>{}, t.applied_end_s,
                      base_.thrusters, &rec);
  internal::ReplaySpec replay;
  replay.simulator = simulator_.get();
  replay.thrusters = &base_.thrusters;
  replay.window = &nominal.window;
  replay.start_s = t.start_s;
  replay.applied_end_s = t.applied_end_s;
  replay.step_s = options_.step_s;
  replay.samples_per_step = options_.replay_samples_per_step;
  internal::ReplayApplied(replay, have ? &accepted : nullptr, state->eci, &rec);

  // Hand over.
  state->next_cycle = k + 1;
  state->time_s = t.applied_end_s;
  state->eci = rec.eci_end;
  for (const Burn& b : rec.burns) {
    state->last_burn_end_s[b.thruster] = std::max(state->last_burn_end_s[b.thruster], b.end_s);
  }
  rec.wall_seconds = Since(t_cycle);
  rec.cpu_seconds = CpuSince(cpu_cycle);
  return rec;
}

}  // namespace thrustsched::planning
