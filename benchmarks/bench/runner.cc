#include "benchmarks/bench/runner.h"

#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/json_reader.h"
#include "app/scenario.h"
#include "benchmarks/bench/accuracy.h"
#include "benchmarks/bench/case_common.h"
#include "benchmarks/bench/conjunction_case.h"
#include "benchmarks/bench/external_solvers.h"
#include "benchmarks/bench/transfer_case.h"
#include "common/timing.h"
#include "dynamics/discretisation.h"
#include "milp/allocator.h"
#include "milp/cbc_solver.h"
#include "milp/model_io.h"
#include "transcription/checker.h"
#include "transcription/schedule_milp.h"
#include "transcription/search.h"

namespace thrustsched::bench {

using common::Since;

namespace {

using common::Clock;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double SelfPeakRssMb() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return ru.ru_maxrss / 1024.0;  // Linux: kilobytes
}

double CpuSeconds(const rusage& ru) {
  return ru.ru_utime.tv_sec + 1e-6 * ru.ru_utime.tv_usec + ru.ru_stime.tv_sec +
         1e-6 * ru.ru_stime.tv_usec;
}

// User + system CPU time of this process so far (all its threads).
double SelfCpuSeconds() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return CpuSeconds(ru);
}

double LoadAverage1Min() {
  std::ifstream in("/proc/loadavg");
  double load = std::numeric_limits<double>::quiet_NaN();
  in >> load;
  return load;
}

std::string RunFileStem(const CaseSpec& spec, int repeat, const RunContext& ctx) {
  return ctx.runs_dir + "/" + spec.id + "-r" + std::to_string(repeat);
}

// A fixed on-off test pattern representable on every grid of the accuracy
// study (all times multiples of 30 min): a 30-min burn every 6 h starting
// 1 h into the horizon, cycling through the thrusters.
Eigen::MatrixXi TestPattern(const app::Scenario& s) {
  std::vector<transcription::Burn> burns;
  const double t0 = s.problem.grid.front(), tf = s.problem.grid.back();
  const int m = s.problem.thrusters.size();
  int k = 0;
  for (double t = t0 + 3600.0; t + 1800.0 <= tf; t += 6 * 3600.0, ++k) {
    burns.push_back({k % m, t, t + 1800.0});
  }
  return transcription::PatternFromBurns(burns, m, s.problem.grid);
}

std::vector<Row> ExecuteAccuracy(const CaseSpec& spec, int repeat) {
  std::vector<Row> rows;
  const std::vector<std::string>& schemes = ComparedSchemes();
  std::map<std::string, std::vector<double>> err_phi, err_gamma;
  std::map<std::string, std::vector<size_t>> row_index;
  for (double step : spec.accuracy_steps_s) {
    const app::Scenario s = LoadPatched(spec, {{"horizon", {{"step_s", step}}}});
    const dynamics::LinearModel& model = *s.problem.model;
    const Eigen::MatrixXd u = s.problem.thrusters.AccelerationMatrix();
    const Eigen::VectorXd scale = model.state_scale();
    const Eigen::MatrixXi pattern = TestPattern(s);
    dynamics::DiscretizationOptions ref_opt;
    ref_opt.scheme = dynamics::Scheme::kReference;
    auto t0 = Clock::now();
    const dynamics::DiscreteModel ref = dynamics::Discretize(model, u, s.problem.grid, ref_opt);
    {
      Row r = BaseRow(spec, repeat, s);
      r.Set("scheme", "reference");
      r.Set("formulation", "");
      r.Set("encoding", "");
      r.Set("discretise_s", Since(t0));
      rows.push_back(r);
    }
    for (const std::string& name : schemes) {
      dynamics::DiscretizationOptions opt;
      opt.scheme = dynamics::ParseScheme(name);
      t0 = Clock::now();
      const dynamics::DiscreteModel dm = dynamics::Discretize(model, u, s.problem.grid, opt);
      const double dt = Since(t0);
      const DiscretizationError e = CompareDiscretizations(dm, ref, scale);
      Row r = BaseRow(spec, repeat, s);
      r.Set("scheme", name);
      r.Set("formulation", "");
      r.Set("encoding", "");
      r.Set("discretise_s", dt);
      r.Set("max_rel_err_phi", e.max_rel_err_phi);
      r.Set("max_rel_err_gamma", e.max_rel_err_gamma);
      r.Set("global_rel_err",
            GlobalPropagationError(dm, ref, s.problem.initial_state, pattern, scale));
      err_phi[name].push_back(e.max_rel_err_phi);
      err_gamma[name].push_back(e.max_rel_err_gamma);
      row_index[name].push_back(rows.size());
      rows.push_back(r);
    }
  }
  // Observed orders: slopes over the points above the reference's own error
  // floor (its tolerance is 1e-12 relative; 1e-10 leaves a margin).
  constexpr double kFloor = 1e-10;
  for (const std::string& name : schemes) {
    const double op = FitLogLogSlope(spec.accuracy_steps_s, err_phi[name], kFloor);
    const double og = FitLogLogSlope(spec.accuracy_steps_s, err_gamma[name], kFloor);
    for (size_t i : row_index[name]) {
      rows[i].Set("observed_order_phi", op);
      rows[i].Set("observed_order_gamma", og);
    }
  }
  return rows;
}

struct TracePoint {
  double t, objective, bound;
};

// milp::RelativeGap, except that a missing incumbent or bound gives NaN (an
// empty CSV cell and no point on the gap plot) where the solver reports +inf.
double GapOf(double objective, double bound) {
  if (!std::isfinite(objective) || !std::isfinite(bound)) return kNaN;
  return milp::RelativeGap(objective, bound);
}

std::vector<Row> ExecuteMilp(const CaseSpec& spec, int repeat, const RunContext& ctx) {
  const app::Scenario s = LoadPatched(spec);
  Row r = BaseRow(spec, repeat, s);
  // Both arms with the malloc thresholds of milp/allocator.h (the previous
  // release tuned them too); the column records it.
  const bool tuned = milp::TuneAllocatorForLargeModels();
  r.Set("allocator_tuned", tuned);
  const transcription::ScheduleProblem& p = s.problem;
  const dynamics::LinearModel& model = *p.model;

  // Discretize (timed) and build from that discretisation (timed by the library).
  auto t0 = Clock::now();
  dynamics::DiscreteModel dm =
      dynamics::Discretize(model, p.thrusters.AccelerationMatrix(), p.grid, s.build.discretisation);
  r.Set("discretise_s", Since(t0));
  std::unique_ptr<transcription::ScheduleMilp> milp;
  {
    dynamics::DiscreteModel copy = dm;  // keep dm for the error metrics
    milp = std::make_unique<transcription::ScheduleMilp>(p, std::move(copy), s.build);
  }
  const transcription::BuildStats& st = milp->stats();
  r.Set("build_s", st.build_seconds);
  r.Set("n_binaries", st.num_binaries);
  r.Set("n_rows", st.num_rows);
  r.Set("n_columns", st.num_columns);
  r.Set("n_nonzeros", st.num_nonzeros);
  r.Set("objective_step", milp->objective_step());

  if (spec.error_metrics && s.build.discretisation.scheme != dynamics::Scheme::kReference) {
    dynamics::DiscretizationOptions ref_opt = s.build.discretisation;
    ref_opt.scheme = dynamics::Scheme::kReference;
    const dynamics::DiscreteModel ref =
        dynamics::Discretize(model, p.thrusters.AccelerationMatrix(), p.grid, ref_opt);
    const DiscretizationError e = CompareDiscretizations(dm, ref, model.state_scale());
    r.Set("max_rel_err_phi", e.max_rel_err_phi);
    r.Set("max_rel_err_gamma", e.max_rel_err_gamma);
  }
  dm = dynamics::DiscreteModel{};

  if (spec.kind == CaseKind::kBuild || spec.kind == CaseKind::kDiscretise) {
    r.Set("peak_rss_mb", SelfPeakRssMb());
    r.Set("cpu_s", SelfCpuSeconds());
    return {r};
  }

  const std::unique_ptr<milp::Solver> solver = milp::MakeCbcSolver();
  milp::SolveOptions so = s.solve;
  so.time_limit_s = spec.time_limit_s;
  so.max_nodes = spec.max_nodes;
  so.relative_gap = spec.relative_gap;
  so.threads = spec.threads;
  so.lp_algorithm = spec.lp_algorithm;
  so.log_level = 0;
  so.objective_step = spec.use_objective_step ? milp->objective_step() : 0.0;
  r.Set("threads", spec.threads);
  r.Set("time_limit_s", spec.time_limit_s);
  r.Set("relative_gap", spec.relative_gap);
  r.Set("lp_algorithm", std::string(milp::ToString(spec.lp_algorithm)));
  r.Set("objective_step", so.objective_step);

  if (spec.lp_relaxation) {
    milp::SolveOptions lo = so;
    lo.objective_step = 0.0;
    lo.lp_algorithm = spec.lp_relaxation_algorithm.value_or(spec.lp_algorithm);
    if (spec.lp_relaxation_time_limit_s > 0.0) lo.time_limit_s = spec.lp_relaxation_time_limit_s;
    r.Set("lp_relaxation_algorithm", std::string(milp::ToString(lo.lp_algorithm)));
    const milp::LpRelaxationResult lp = solver->SolveLpRelaxation(milp->lp(), lo);
    r.Set("lp_s", lp.wall_seconds);
    if (lp.status == milp::SolveStatus::kOptimal) {
      r.Set("lp_bound", lp.objective);
    } else {
      r.Set("note", "LP relaxation: " + std::string(milp::ToString(lp.status)) + " " + lp.detail);
    }
  }

  std::vector<TracePoint> trace;
  so.progress_interval_s = 0.25;
  so.progress = [&trace](const milp::SolveProgress& pr) {
    trace.push_back({pr.wall_seconds, pr.objective, pr.best_bound});
  };
  milp::SolveResult sr;
  r.Set("solver_path", SolverPath(spec));
  if (spec.search) {
    transcription::SearchReport report;
    transcription::SearchOptions search;
    // The arms (matrix.h, SearchArm).
    search.disabled_phases = ctx.disabled_phases;
    milp::LazyRowOptions& lazy = search.restricted.lazy_row_options;
    if (spec.search_arm == SearchArm::kPreviousRelease) {
      search.relaxation.lp_method = transcription::RelaxationOptions::LpMethod::kClpBarrier;
    }
    if (spec.search_arm == SearchArm::kLazyLpUnpresolved) lazy.presolve_lp_relaxation = false;
    sr = transcription::SearchSchedule(*milp, *solver, so, search, {}, &report);
    std::string steps;
    for (const std::string& step : report.steps) steps += (steps.empty() ? "" : " | ") + step;
    r.Set("search_steps", steps);
  } else {
    sr = solver->Solve(milp->lp(), so);
  }
  for (const milp::Incumbent& inc : sr.incumbents) {
    trace.push_back({inc.wall_seconds, inc.objective, inc.best_bound});
  }
  std::stable_sort(trace.begin(), trace.end(),
                   [](const TracePoint& a, const TracePoint& b) { return a.t < b.t; });
  {
    std::ofstream tf(RunFileStem(spec, repeat, ctx) + ".trace.csv");
    tf << "wall_s,objective,best_bound\n";
    auto v = [](double x) { return std::isfinite(x) ? FormatValue(x) : std::string("NaN"); };
    for (const TracePoint& tp : trace) {
      tf << v(tp.t) << "," << v(tp.objective) << "," << v(tp.bound) << "\n";
    }
    if (sr.has_solution()) {
      tf << v(sr.wall_seconds) << "," << v(sr.objective) << "," << v(sr.best_bound) << "\n";
    }
  }

  r.Set("status", std::string(milp::ToString(sr.status)));
  r.Set("solve_s", sr.wall_seconds);
  r.Set("nodes", sr.nodes);
  if (sr.has_solution()) {
    r.Set("objective", sr.objective);
    r.Set("best_bound", sr.best_bound);
    r.Set("gap", sr.gap);
    if (!sr.incumbents.empty()) r.Set("time_to_first_s", sr.incumbents.front().wall_seconds);
    // Time to a proven 1 % gap: the first moment (incumbent or progress
    // report) where (incumbent - bound at that time) / incumbent <= 1 %.
    double best_obj = kNaN, t1 = kNaN;
    for (const TracePoint& tp : trace) {
      if (std::isfinite(tp.objective) && !(tp.objective >= best_obj)) best_obj = tp.objective;
      const double g = GapOf(best_obj, tp.bound);
      if (std::isfinite(g) && g <= 0.01 + 1e-12) {
        t1 = tp.t;
        break;
      }
    }
    if (!std::isfinite(t1) && sr.gap <= 0.01 + 1e-12) t1 = sr.wall_seconds;
    r.Set("time_to_1pct_s", t1);
    if (sr.status == milp::SolveStatus::kOptimal && spec.relative_gap <= 1e-4) {
      r.Set("time_to_opt_s", sr.wall_seconds);
    }
    // Time to an incumbent within 1 % of the optimum (the published value
    // where there is one, else this run's final best bound).
    const double ref = std::isfinite(spec.published) ? spec.published : sr.best_bound;
    for (const milp::Incumbent& inc : sr.incumbents) {
      if (inc.objective <= ref + 0.01 * std::abs(ref) + 1e-12) {
        r.Set("time_within_1pct_of_opt_s", inc.wall_seconds);
        break;
      }
    }
    if (std::isfinite(spec.published) && spec.published != 0.0) {
      r.Set("ratio", sr.objective / spec.published);
    }
    const transcription::Schedule sched = milp->Decode(sr.x);
    r.Set("consumption_l1_m_s", sched.consumption_l1_m_s);
    r.Set("delta_v_m_s", sched.delta_v_m_s);
    r.Set("n_burns", sched.num_burns());
    const transcription::CheckReport cr = transcription::CheckSchedule(p, sched.burns, s.check);
    r.Set("operational_ok", cr.operational_ok);
    r.Set("max_window_violation", cr.max_window_violation * s.window_unit_per_output_unit);
    r.Set("max_window_violation_nodes",
          cr.max_window_violation_at_nodes * s.window_unit_per_output_unit);
    r.Set("window_unit", s.window_unit);
    if (cr.nonlinear_checked) {
      r.Set("max_window_violation_nonlinear_deg", cr.max_window_violation_nonlinear_deg);
    }
    r.Set("terminal_ok", cr.terminal_ok);
    r.Set("terminal_error", cr.terminal_error);
  } else if (!sr.detail.empty() && !r.Has("note")) {
    r.Set("note", sr.detail);
  }
  r.Set("peak_rss_mb", SelfPeakRssMb());
  r.Set("cpu_s", SelfCpuSeconds());

  if (spec.external) {
    const std::string stem = RunFileStem(spec, repeat, ctx);
    const std::string mps = stem + ".mps";
    milp::WriteMpsFile(mps, milp->lp());
    milp.reset();
    RunExternalSolvers(mps, stem, spec.external_time_limit_s, &r);
    if (!ctx.keep_mps) {
      // The figures are in the row; the model and the solvers' raw output
      // (megabytes per case) are kept only when asked for.
      std::remove(mps.c_str());
      for (const std::string& f : ExternalOutputFiles(stem)) std::remove(f.c_str());
    }
  }
  return {r};
}

void WriteRowsJson(const std::string& path, const std::vector<Row>& rows) {
  nlohmann::json j = nlohmann::json::array();
  for (const Row& r : rows) j.push_back(r.values());
  std::ofstream out(path);
  out << j.dump(1) << "\n";
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::vector<Row> ReadRowsJson(const std::string& path) {
  const nlohmann::json j = nlohmann::json::parse(ReadTextFile(path));
  std::vector<Row> rows;
  for (const auto& obj : j) {
    Row r;
    for (auto it = obj.begin(); it != obj.end(); ++it)
      r.Set(it.key(), it.value().get<std::string>());
    rows.push_back(r);
  }
  return rows;
}

Row FailureRow(const CaseSpec& spec, int repeat, const std::string& status,
               const std::string& why) {
  Row r = CaseHeaderRow(spec, repeat);
  r.Set("status", status);
  r.Set("note", why);
  return r;
}

double DeadlineSeconds(const CaseSpec& spec) {
  // A conjunction case: rounds within the time limit, then the Monte Carlo.
  if (spec.kind == CaseKind::kConjunction) return 600.0 + 1.5 * spec.time_limit_s;
  if (spec.kind != CaseKind::kSolve) return 1800.0;
  double d = 300.0 + 2.0 * spec.time_limit_s;  // LP relaxation + MILP, each limited
  // Each external solver is killed at its limit + 60 s (external_solvers.cc).
  if (spec.external) {
    d += static_cast<double>(ExternalSolverNames().size()) * (spec.external_time_limit_s + 60.0);
  }
  return d;
}

}  // namespace

app::Scenario LoadPatched(const CaseSpec& spec, const nlohmann::json& extra) {
  nlohmann::json j = app::ParseJsonText(ReadTextFile(spec.scenario_path), spec.scenario_path);
  j = MergePatch(j, spec.patch);
  if (!extra.is_null()) j = MergePatch(j, extra);
  app::ScenarioParseOptions po;
  po.source = spec.scenario_path;
  app::Scenario s = app::ParseScenario(j, po);
  s.path = spec.scenario_path;
  return s;
}

Row CaseHeaderRow(const CaseSpec& spec, int repeat) {
  Row r;
  r.Set("section", spec.section);
  r.Set("case_id", spec.id);
  r.Set("repeat", repeat);
  r.Set("variant", spec.variant);
  r.Set("scenario", spec.scenario);
  return r;
}

Row BaseRow(const CaseSpec& spec, int repeat, const app::Scenario& s) {
  Row r = CaseHeaderRow(spec, repeat);
  r.Set("target_1pct_s", spec.target_1pct_s);  // NaN (not a target): empty cells
  r.Set("target_opt_s", spec.target_opt_s);
  r.Set("target_gap", spec.target_gap);
  r.Set("target_gap_s", spec.target_gap_s);
  r.Set("model", std::string(app::ToString(s.model_type)));
  r.Set("scheme", std::string(dynamics::ToString(s.build.discretisation.scheme)));
  r.Set("formulation", std::string(ToString(s.build.formulation)));
  r.Set("encoding", std::string(ToString(s.build.encoding)));
  r.Set("step_s", s.step_s);
  r.Set("horizon_s", s.problem.horizon_s());
  r.Set("n_thrusters", s.problem.thrusters.size());
  if (std::isfinite(spec.published)) {
    r.Set("published", spec.published);
    r.Set("published_source", spec.published_source);
  }
  if (!spec.note.empty()) r.Set("note", spec.note);
  return r;
}

std::string ReadTextFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool ProgramAvailable(const std::string& program) {
  const std::string cmd = "command -v '" + program + "' > /dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

std::vector<Row> ExecuteCase(const CaseSpec& spec, int repeat, const RunContext& context) {
  if (spec.kind == CaseKind::kAccuracy) return ExecuteAccuracy(spec, repeat);
  if (spec.kind == CaseKind::kConjunction) return ExecuteConjunction(spec, repeat, context);
  if (spec.kind == CaseKind::kTransfer) return ExecuteTransfer(spec, repeat, context);
  return ExecuteMilp(spec, repeat, context);
}

std::vector<Row> RunCase(const CaseSpec& spec, int repeat, const RunContext& context) {
  const std::string stem = RunFileStem(spec, repeat, context);
  const std::string rows_path = stem + ".json";
  const double load = LoadAverage1Min();
  const auto t0 = Clock::now();
  if (!context.fork) {
    std::vector<Row> rows;
    try {
      rows = ExecuteCase(spec, repeat, context);
    } catch (const std::exception& e) {
      rows = {FailureRow(spec, repeat, "error", e.what())};
    }
    for (Row& r : rows) {
      r.Set("wall_s", Since(t0));
      r.Set("load_1min", load);
    }
    return rows;
  }
  std::remove(rows_path.c_str());
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid < 0) return {FailureRow(spec, repeat, "error", "fork failed")};
  if (pid == 0) {
    int code = 0;
    try {
      WriteRowsJson(rows_path, ExecuteCase(spec, repeat, context));
    } catch (const std::exception& e) {
      try {
        WriteRowsJson(rows_path, {FailureRow(spec, repeat, "error", e.what())});
      } catch (...) {
      }
      code = 3;
    }
    std::fflush(stdout);
    std::fflush(stderr);
    _exit(code);
  }
  const double deadline = DeadlineSeconds(spec);
  int wstatus = 0;
  rusage ru{};
  bool killed = false;
  for (;;) {
    const pid_t w = wait4(pid, &wstatus, WNOHANG, &ru);
    if (w == pid) break;
    if (w < 0) return {FailureRow(spec, repeat, "error", "wait4 failed")};
    if (!killed && Since(t0) > deadline) {
      kill(pid, SIGKILL);
      killed = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const double wall = Since(t0);
  const double child_rss_mb = ru.ru_maxrss / 1024.0;
  std::vector<Row> rows;
  if (killed) {
    rows = {FailureRow(spec, repeat, "killed",
                       "no result after " + FormatValue(deadline) + " s (deadline)")};
  } else if (WIFSIGNALED(wstatus)) {
    rows = {FailureRow(spec, repeat, "crashed",
                       "child killed by signal " + std::to_string(WTERMSIG(wstatus)))};
  } else {
    try {
      rows = ReadRowsJson(rows_path);
    } catch (const std::exception& e) {
      rows = {FailureRow(spec, repeat, "error", std::string("no result file: ") + e.what())};
    }
  }
  for (Row& r : rows) {
    r.Set("wall_s", wall);
    r.Set("load_1min", load);
    if (!r.Has("cpu_s")) r.Set("cpu_s", CpuSeconds(ru));
    r.Set("exit", WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1);
    if (!r.Has("peak_rss_mb")) r.Set("peak_rss_mb", child_rss_mb);
  }
  return rows;
}

}  // namespace thrustsched::bench
