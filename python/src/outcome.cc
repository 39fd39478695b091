// Solve and check results of the Python bindings (see outcome.h).
//
//   auto r = SolveAndCheck(ScenarioContext(s), [s] { return std::make_shared<...>(...); },
//                          request, job, callback);
#include "outcome.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "app/conjunction_report.h"
#include "app/min_time_report.h"
#include "app/outputs.h"
#include "common/format.h"
#include "common/timing.h"
#include "convert.h"
#include "milp/cbc_solver.h"

namespace thrustsched::python {

using common::FormatG;
using common::Since;

namespace {

using common::Clock;

}  // namespace

ProblemContext ScenarioContext(std::shared_ptr<const app::Scenario> scenario) {
  ProblemContext ctx;
  ctx.problem = std::shared_ptr<const transcription::ScheduleProblem>(scenario, &scenario->problem);
  ctx.scenario = std::move(scenario);
  return ctx;
}

DiscreteCheck CheckDiscrete(const transcription::ScheduleProblem& p,
                            const dynamics::DiscreteModel& dm,
                            const std::vector<transcription::Burn>& burns) {
  DiscreteCheck c;
  const int m = p.thrusters.size();
  c.rule_violations = transcription::CheckOperationalRules(p.rules, p.history, p.forced_off, m,
                                                           p.grid.front(), p.grid.back(), burns);
  c.operational_ok = c.rule_violations.empty();
  for (const transcription::RuleViolation& v : c.rule_violations) {
    c.findings.push_back("rule " + v.rule + " at t = " + FormatG(v.time_s, 17) +
                         " s: " + v.message);
  }
  const Eigen::MatrixXi pattern = transcription::PatternFromBurns(burns, m, p.grid);
  Eigen::VectorXd x = p.initial_state;
  const int nn = p.num_intervals();
  c.states.reserve(nn + 1);
  c.outputs.reserve(nn + 1);
  for (int j = 0; j <= nn; ++j) {
    const Eigen::MatrixXd cm = p.model->EvaluateOutput(p.grid[j]).c;
    c.states.push_back(x);
    c.outputs.push_back(cm * x);
    if (j >= 1 && p.grid[j] >= p.window.enforce_from_s - transcription::kTimeTolerance) {
      for (size_t k = 0; k < p.window.outputs.size(); ++k) {
        const double excess =
            std::abs(c.outputs.back()[p.window.outputs[k]]) - p.window.half_widths[k];
        if (excess > c.max_window_violation_at_nodes) {
          c.max_window_violation_at_nodes = excess;
          c.worst_time_s = p.grid[j];
          c.worst_output = p.window.outputs[k];
        }
      }
    }
    if (j == nn) break;
    x = dm.phi[j] * x + dm.gamma[j] * pattern.col(j).cast<double>() + dm.drift[j];
  }
  if (c.max_window_violation_at_nodes > 0.0) {
    c.findings.push_back("window violated at grid nodes by " +
                         FormatG(c.max_window_violation_at_nodes, 17) + " (output " +
                         std::to_string(c.worst_output) + ", t = " + FormatG(c.worst_time_s, 17) +
                         " s)");
  }
  const transcription::TerminalSpec& term = p.terminal;
  if (term.kind == transcription::TerminalKind::kFixedState ||
      term.kind == transcription::TerminalKind::kStateBox) {
    c.terminal_error = transcription::TerminalError(term, x, p.model->state_scale());
    c.terminal_ok = c.terminal_error <= transcription::kTerminalTolerance;
    if (!c.terminal_ok) {
      c.findings.push_back("terminal constraint violated (scaled error " +
                           FormatG(c.terminal_error, 17) + ")");
    }
  }
  return c;
}

void RunCheck(CheckedSchedule* c) {
  const Clock::time_point t0 = Clock::now();
  const ProblemContext& ctx = c->ctx;
  if (ctx.discrete) {
    if (ctx.impulsive()) {
      throw std::invalid_argument("array problems are on-off problems (no impulsive mode)");
    }
    c->discrete = CheckDiscrete(*ctx.problem, *ctx.discrete, c->burns);
  } else if (ctx.impulsive()) {
    c->impulsive_check = transcription::CheckImpulses(*ctx.problem, c->impulses);
  } else {
    // As the CLI: a failing nonlinear replay is reported and the linear check kept.
    c->report = app::CheckWithLinearFallback(*ctx.scenario, c->burns, &c->nonlinear_error);
  }
  if (ctx.scenario && ctx.scenario->problem.conjunction) {
    c->conjunction = app::VerifyConjunction(*ctx.scenario, c->burns, c->impulses);
  }
  c->checked = true;
  c->check_seconds = Since(t0);
}

std::string CheckedSchedule::CheckJson() const {
  if (!checked) return "null";
  nlohmann::json j;
  if (discrete) {
    const DiscreteCheck& d = *discrete;
    j["kind"] = "discrete";
    j["passed"] = d.passed();
    j["findings"] = d.findings;
    j["operational_ok"] = d.operational_ok;
    app::AddRuleViolations(d.rule_violations, ctx.thruster_names(), &j);
    j["window_unit"] = nullptr;
    j["max_window_violation_nodes"] = d.max_window_violation_at_nodes;
    j["max_window_violation"] = d.max_window_violation_at_nodes;
    j["worst_time_s"] = d.worst_output >= 0 ? app::FiniteOrNull(d.worst_time_s) : nullptr;
    j["worst_output"] =
        d.worst_output >= 0 && d.worst_output < static_cast<int>(ctx.output_names.size())
            ? nlohmann::json(ctx.output_names[d.worst_output])
            : nlohmann::json(nullptr);
    j["terminal_ok"] = d.terminal_ok;
    j["terminal_error"] = d.terminal_error;
    const Eigen::VectorXd& xf = d.states.back();
    j["final_state"] = std::vector<double>(xf.data(), xf.data() + xf.size());
  } else {
    const app::Scenario& s = *ctx.scenario;
    if (ctx.impulsive()) {
      j = app::ImpulsiveCheckJson(s, impulsive_check, app::JudgeImpulsive(s, impulsive_check),
                                  check_seconds);
    } else {
      j = app::CheckJson(s, report, app::Judge(s, report), check_seconds);
    }
    j["kind"] = "continuous";
    if (!nonlinear_error.empty()) j["nonlinear_error"] = nonlinear_error;
    if (conjunction) {
      j["conjunction"] = app::ConjunctionJson(std::nullopt, nullptr, &*conjunction);
      j["passed"] = j["passed"].get<bool>() && conjunction->passed();
    }
  }
  j["check_seconds"] = check_seconds;
  return j.dump();
}

std::string CheckedSchedule::ScheduleCsv() const {
  const std::vector<std::string> names = ctx.thruster_names();
  if (ctx.scenario) {
    return ctx.impulsive() ? app::ImpulsesCsvText(*ctx.scenario, impulses)
                           : app::ScheduleCsvText(*ctx.scenario, burns);
  }
  std::ostringstream os;
  os << "thruster,start_s,end_s,duration_s\n";
  for (const transcription::Burn& b : burns) {
    os << names.at(b.thruster) << "," << FormatG(b.start_s, 17) << "," << FormatG(b.end_s, 17)
       << "," << FormatG(b.duration_s(), 17) << "\n";
  }
  return os.str();
}

std::string CheckedSchedule::TrajectoryCsv() const {
  if (ctx.scenario) {
    if (ctx.impulsive()) return app::ImpulsiveTrajectoryCsvText(*ctx.scenario, impulses);
    if (!checked) return "";
    return app::TrajectoryCsvText(*ctx.scenario, report, burns);
  }
  if (!discrete) return "";
  const transcription::ScheduleProblem& p = *ctx.problem;
  std::ostringstream os;
  os << "t_s";
  for (const std::string& n : ctx.state_names) os << "," << n;
  for (const std::string& n : ctx.output_names) os << ",out_" << n;
  for (const std::string& n : ctx.thruster_names()) os << ",on_" << n;
  os << "\n";
  const Eigen::MatrixXi pattern =
      transcription::PatternFromBurns(burns, p.thrusters.size(), p.grid);
  for (int j = 0; j <= p.num_intervals(); ++j) {
    os << FormatG(p.grid[j], 17);
    for (int i = 0; i < discrete->states[j].size(); ++i)
      os << "," << FormatG(discrete->states[j][i], 17);
    for (int i = 0; i < discrete->outputs[j].size(); ++i)
      os << "," << FormatG(discrete->outputs[j][i], 17);
    // As trajectory.csv: on_<thruster> = 1 while a burn covers t (the last node: none).
    for (int i = 0; i < p.thrusters.size(); ++i) {
      os << "," << (j < p.num_intervals() ? pattern(i, j) : 0);
    }
    os << "\n";
  }
  return os.str();
}

std::shared_ptr<SolveOutcome> SolveAndCheck(
    const ProblemContext& ctx,
    std::function<std::shared_ptr<const transcription::ScheduleMilp>()> build, SolveRequest request,
    const std::shared_ptr<Job>& job, py::object callback) {
  auto out = std::make_shared<SolveOutcome>();
  out->checked->ctx = ctx;
  Job* j = job.get();
  // The work owns copies of everything it uses (it may outlive this call
  // after a second Ctrl-C).
  auto work = [out, ctx, build = std::move(build), request = std::move(request), j] {
    const Clock::time_point t_start = Clock::now();
    const std::shared_ptr<const transcription::ScheduleMilp> milp = build();
    transcription::SolveScheduleOptions opt = request.options;
    opt.check_schedule = false;  // checked below, as the CLI does
    opt.milp.interrupt = &j->stop;
    opt.milp.progress = [j](const milp::SolveProgress& p) {
      j->Post([p](const py::handle& cb) { cb(ProgressDict(p)); });
    };
    opt.announce = [j](const std::string& what) {
      j->Post([what](const py::handle& cb) {
        py::dict d;
        d["phase"] = "announce";
        d["message"] = what;
        cb(d);
      });
    };
    const std::unique_ptr<milp::Solver> solver = milp::MakeCbcSolver();
    std::optional<transcription::ConjunctionSolve> rounds;
    std::optional<transcription::MinTimeResult> min_time;
    transcription::ScheduleResult& r = out->result;
    if (ctx.scenario && ctx.scenario->min_time) {
      min_time = app::SolveScenarioMinTime(*ctx.scenario, *solver, opt);
      r = app::MinTimeScheduleResult(*min_time, *ctx.scenario->min_time);
    } else if (request.conjunction && ctx.problem->conjunction) {
      rounds = transcription::SolveConjunction(*milp, *solver, opt, *request.conjunction);
      r = rounds->result;
    } else {
      r = transcription::SolveBuilt(*milp, *solver, opt);
    }
    out->interrupted = j->stop.load();
    if (r.has_schedule()) {
      out->x = r.solve.x;
      out->checked->burns = r.schedule.burns;
      out->checked->impulses = r.schedule.impulses;
      if (request.check) {
        RunCheck(out->checked.get());
        r.checked = true;
        r.check_seconds = out->checked->check_seconds;
        r.check = std::move(out->checked->report);  // moved back below
        r.impulsive_check = out->checked->impulsive_check;
      }
    }
    out->total_seconds = Since(t_start);
    nlohmann::json summary;
    if (ctx.scenario) {
      // The CLI's summary.json (app::SummaryJson), with the check's kind.
      app::RunFacts facts;
      facts.interrupted = out->interrupted;
      facts.command_line = "python: thrustsched.solve";
      facts.total_seconds = out->total_seconds;
      facts.nonlinear_error = out->checked->nonlinear_error;
      facts.conjunction_solve = rounds ? &*rounds : nullptr;
      facts.conjunction_check = out->checked->conjunction ? &*out->checked->conjunction : nullptr;
      facts.min_time = min_time ? &*min_time : nullptr;
      summary = app::SummaryJson(*ctx.scenario, *milp, r, facts);
      if (summary["check"].is_object()) summary["check"]["kind"] = "continuous";
    } else {
      // Array problems: the summary's fields that need no scenario.
      summary = app::SolveResultJson(r, ctx.thruster_names(), ctx.problem->objective.kind,
                                     out->interrupted, out->total_seconds);
      summary["model"] = "arrays";
      summary["input_mode"] = "on_off";
      summary["check"] = nlohmann::json::parse(out->checked->CheckJson());
    }
    out->summary_json = summary.dump();
    out->checked->report = std::move(r.check);
  };
  RunInterruptible(job, std::move(work), std::move(callback), "solve");
  return out;
}

}  // namespace thrustsched::python
