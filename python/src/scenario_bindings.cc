// Scenario files from Python: parse (the CLI's parser and messages), solve,
// check, export, and the result objects.
//
//   s = _core.parse_scenario(json_text, "data/scenarios/hcw_table41_1d.json")
//   r = _core.solve_scenario(s, time_limit_s=60, threads=2, callback=None)
//   r.status, r.objective, r.checked.check_json(), r.checked.schedule_csv()
//   c = _core.check_scenario(s, ["+T"], [0.0], [300.0])
//   _core.export_scenario(s, "week.mps", False)
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/json_reader.h"
#include "app/outputs.h"
#include "app/scenario.h"
#include "bindings.h"
#include "convert.h"
#include "dynamics/discretisation.h"
#include "dynamics/models.h"
#include "milp/model_io.h"
#include "outcome.h"
#include "transcription/export_lp.h"

namespace thrustsched::python {

namespace {

std::string F(double v) { return app::FormatNumber(v); }

using ScenarioPtr = std::shared_ptr<app::Scenario>;

std::shared_ptr<SolveOutcome> SolveScenario(const ScenarioPtr& parsed,
                                            const std::optional<std::string>& scheme,
                                            const std::optional<std::string>& formulation,
                                            const std::optional<std::string>& encoding,
                                            const SolveSettings& settings, py::object callback) {
  auto s = std::make_shared<app::Scenario>(*parsed);
  ApplyBuildSettings(scheme, formulation, encoding, &s->build);
  transcription::SolveScheduleOptions opt;
  opt.build = s->build;
  opt.milp = s->solve;
  opt.search = s->search_options;
  opt.search.enabled = s->search;
  opt.prefix_diagnosis_s = s->diagnosis_time_limit_s;
  ApplySettings(settings, &opt);
  s->solve = opt.milp;  // summary.json reports the settings used
  SolveRequest request;
  request.options = opt;
  request.check = settings.check;
  if (s->problem.conjunction) request.conjunction = s->conjunction_solve;
  std::shared_ptr<const app::Scenario> cs = s;
  auto build = [cs] {
    return std::make_shared<const transcription::ScheduleMilp>(cs->problem, cs->build);
  };
  return SolveAndCheck(ScenarioContext(cs), build, request, std::make_shared<Job>(),
                       std::move(callback));
}

std::shared_ptr<CheckedSchedule> CheckScenarioBurns(const ScenarioPtr& s,
                                                    const std::vector<std::string>& thrusters,
                                                    const std::vector<double>& start_s,
                                                    const std::vector<double>& end_s) {
  auto c = std::make_shared<CheckedSchedule>();
  c->ctx = ScenarioContext(s);
  if (s->impulsive()) {
    throw std::invalid_argument(
        "the scenario is impulsive: give impulses (thruster, node, "
        "delta_v_m_s), not burns");
  }
  c->burns = BurnsFromColumns(c->ctx, thrusters, start_s, end_s);
  py::gil_scoped_release nogil;
  RunCheck(c.get());
  return c;
}

std::shared_ptr<CheckedSchedule> CheckScenarioImpulses(const ScenarioPtr& s,
                                                       const std::vector<std::string>& thrusters,
                                                       const std::vector<double>& nodes,
                                                       const std::vector<double>& delta_v_m_s) {
  auto c = std::make_shared<CheckedSchedule>();
  c->ctx = ScenarioContext(s);
  if (!s->impulsive()) {
    throw std::invalid_argument("the scenario is on-off: give burns (thruster, start_s, end_s)");
  }
  if (nodes.size() != thrusters.size() || delta_v_m_s.size() != thrusters.size()) {
    throw std::invalid_argument(
        "schedule: thruster, node and delta_v_m_s columns differ in length");
  }
  const std::vector<std::string> names = s->thruster_names();
  for (size_t k = 0; k < thrusters.size(); ++k) {
    const std::string where = "schedule row " + std::to_string(k);
    transcription::Impulse im;
    im.thruster = -1;
    for (size_t i = 0; i < names.size(); ++i) {
      if (names[i] == thrusters[k]) im.thruster = static_cast<int>(i);
    }
    if (im.thruster < 0) {
      throw std::invalid_argument(where + ": thruster \"" + thrusters[k] + "\" is not a thruster");
    }
    const double node = nodes[k];
    if (node != std::floor(node) || node < 0 || node > s->problem.num_intervals()) {
      throw std::invalid_argument(where + ": node must be an integer in [0, " +
                                  std::to_string(s->problem.num_intervals()) + "], got " + F(node));
    }
    im.node = static_cast<int>(node);
    im.time_s = s->problem.grid[im.node];
    im.delta_v_m_s = delta_v_m_s[k];
    if (!(im.delta_v_m_s >= 0.0) || !std::isfinite(im.delta_v_m_s)) {
      throw std::invalid_argument(where + ": delta_v_m_s must be finite and >= 0, got " +
                                  F(im.delta_v_m_s));
    }
    c->impulses.push_back(im);
  }
  py::gil_scoped_release nogil;
  RunCheck(c.get());
  return c;
}

py::dict BuildStatsDict(const transcription::BuildStats& st) {
  py::dict d;
  d["n_binaries"] = st.num_binaries;
  d["n_columns"] = st.num_columns;
  d["n_rows"] = st.num_rows;
  d["n_nonzeros"] = st.num_nonzeros;
  d["discretise_seconds"] = st.discretise_seconds;
  d["build_seconds"] = st.build_seconds;
  return d;
}

// The model file of a scenario (the CLI's `export`): its NAME is the scenario's name.
py::dict ExportScenario(const ScenarioPtr& s, const std::string& path, bool obfuscate,
                        const std::optional<std::string>& scheme,
                        const std::optional<std::string>& formulation,
                        const std::optional<std::string>& encoding) {
  app::Scenario sc = *s;
  ApplyBuildSettings(scheme, formulation, encoding, &sc.build);
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".mps" && ext.substr(1) != ".lp") {
    throw std::invalid_argument(path + ": the model file must end in .mps or .lp");
  }
  transcription::BuildStats stats;
  {
    py::gil_scoped_release nogil;
    const transcription::ScheduleMilp milp(sc.problem, sc.build);
    milp::LpData lp = transcription::ExportLp(milp);
    lp.name = sc.name;
    if (ext == ".mps") {
      milp::MpsOptions o;
      o.obfuscate_names = obfuscate;
      milp::WriteMpsFile(path, lp, o);
    } else {
      milp::LpFormatOptions o;
      o.obfuscate_names = obfuscate;
      milp::WriteLpFile(path, lp, o);
    }
    stats = milp.stats();
  }
  py::dict d = BuildStatsDict(stats);
  d["path"] = path;
  d["objective_kind"] = std::string(ToString(sc.problem.objective.kind));
  return d;
}

py::array_t<double> Grid(const transcription::ScheduleProblem& p) {
  return py::array_t<double>(static_cast<py::ssize_t>(p.grid.size()), p.grid.data());
}

}  // namespace

void ApplySettings(const SolveSettings& st, transcription::SolveScheduleOptions* o) {
  if (st.time_limit_s) {
    if (!(*st.time_limit_s > 0.0)) {
      throw std::invalid_argument("time_limit_s: must be > 0, got " + F(*st.time_limit_s));
    }
    o->milp.time_limit_s = *st.time_limit_s;
  }
  if (st.relative_gap) {
    if (!(*st.relative_gap >= 0.0) || !std::isfinite(*st.relative_gap)) {
      throw std::invalid_argument("relative_gap: must be finite and >= 0, got " +
                                  F(*st.relative_gap));
    }
    o->milp.relative_gap = *st.relative_gap;
  }
  if (st.threads) {
    if (*st.threads < 1 || *st.threads > 64) {
      throw std::invalid_argument("threads: must be in [1, 64], got " +
                                  std::to_string(*st.threads));
    }
    o->milp.threads = *st.threads;
  }
  if (st.max_nodes) o->milp.max_nodes = *st.max_nodes;
  if (st.log_level) {
    if (*st.log_level < 0) throw std::invalid_argument("log_level: must be >= 0");
    o->milp.log_level = *st.log_level;
  }
  if (st.random_seed) {
    if (*st.random_seed < 0) throw std::invalid_argument("random_seed: must be >= 0");
    o->milp.random_seed = *st.random_seed;
  }
  if (st.search) o->search.enabled = *st.search;
  if (st.diagnosis_time_limit_s) {
    if (!(*st.diagnosis_time_limit_s >= 0.0)) {
      throw std::invalid_argument("diagnosis_time_limit_s: must be >= 0, got " +
                                  F(*st.diagnosis_time_limit_s));
    }
    o->prefix_diagnosis_s = *st.diagnosis_time_limit_s;
  }
  if (!(st.progress_interval_s > 0.0) || !std::isfinite(st.progress_interval_s)) {
    throw std::invalid_argument("progress_interval_s: must be finite and > 0, got " +
                                F(st.progress_interval_s));
  }
  o->milp.progress_interval_s = st.progress_interval_s;
  std::string err;
  if (!o->milp.IsValid(&err)) throw std::invalid_argument(err);
}

void ApplyBuildSettings(const std::optional<std::string>& scheme,
                        const std::optional<std::string>& formulation,
                        const std::optional<std::string>& encoding,
                        transcription::BuildOptions* build) {
  if (scheme)
    build->discretisation.scheme =
        app::Wrap("scheme", [&] { return dynamics::ParseScheme(*scheme); });
  if (formulation) {
    build->formulation =
        app::Wrap("formulation", [&] { return transcription::ParseFormulation(*formulation); });
  }
  if (encoding) {
    build->encoding =
        app::Wrap("encoding", [&] { return transcription::ParseEncoding(*encoding); });
  }
}

std::vector<transcription::Burn> BurnsFromColumns(const ProblemContext& ctx,
                                                  const std::vector<std::string>& thrusters,
                                                  const std::vector<double>& start_s,
                                                  const std::vector<double>& end_s) {
  if (start_s.size() != thrusters.size() || end_s.size() != thrusters.size()) {
    throw std::invalid_argument("schedule: thruster, start_s and end_s columns differ in length (" +
                                std::to_string(thrusters.size()) + ", " +
                                std::to_string(start_s.size()) + ", " +
                                std::to_string(end_s.size()) + ")");
  }
  const std::vector<std::string> names = ctx.thruster_names();
  std::vector<transcription::Burn> burns;
  for (size_t k = 0; k < thrusters.size(); ++k) {
    const std::string where = "schedule row " + std::to_string(k);
    transcription::Burn b;
    b.thruster = -1;
    for (size_t i = 0; i < names.size(); ++i) {
      if (names[i] == thrusters[k]) b.thruster = static_cast<int>(i);
    }
    if (b.thruster < 0) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      throw std::invalid_argument(where + ": thruster \"" + thrusters[k] +
                                  "\" is not a thruster (thrusters: " + list + ")");
    }
    b.start_s = start_s[k];
    b.end_s = end_s[k];
    if (!std::isfinite(b.start_s) || !std::isfinite(b.end_s)) {
      throw std::invalid_argument(where + ": start_s and end_s must be finite, got " +
                                  F(b.start_s) + ", " + F(b.end_s));
    }
    if (b.end_s < b.start_s) {
      throw std::invalid_argument(where + ": end_s " + F(b.end_s) + " is before start_s " +
                                  F(b.start_s));
    }
    burns.push_back(b);
  }
  return burns;
}

void BindOutcomes(py::module_& m) {
  py::class_<CheckedSchedule, std::shared_ptr<CheckedSchedule>>(
      m, "CheckedSchedule", "A schedule and the checker's verdict on it.")
      .def("check_json", &CheckedSchedule::CheckJson,
           "The verdict as summary.json's \"check\" object (JSON text; \"null\" if not checked).")
      .def("schedule_csv", &CheckedSchedule::ScheduleCsv, py::call_guard<py::gil_scoped_release>(),
           "schedule.csv (impulses.csv) as text.")
      .def("trajectory_csv", &CheckedSchedule::TrajectoryCsv,
           py::call_guard<py::gil_scoped_release>(), "trajectory.csv as text.")
      .def_property_readonly("checked", [](const CheckedSchedule& c) { return c.checked; })
      .def_property_readonly("burn_thrusters",
                             [](const CheckedSchedule& c) {
                               std::vector<std::string> out;
                               const std::vector<std::string> names = c.ctx.thruster_names();
                               for (const auto& b : c.burns) out.push_back(names[b.thruster]);
                               return out;
                             })
      .def_property_readonly("burn_start_s",
                             [](const CheckedSchedule& c) {
                               std::vector<double> v;
                               for (const auto& b : c.burns) v.push_back(b.start_s);
                               return py::array_t<double>(static_cast<py::ssize_t>(v.size()),
                                                          v.data());
                             })
      .def_property_readonly("burn_end_s",
                             [](const CheckedSchedule& c) {
                               std::vector<double> v;
                               for (const auto& b : c.burns) v.push_back(b.end_s);
                               return py::array_t<double>(static_cast<py::ssize_t>(v.size()),
                                                          v.data());
                             })
      .def_property_readonly("discrete_states", [](const CheckedSchedule& c) -> py::object {
        if (!c.discrete) return py::none();
        return StackVectors(c.discrete->states);
      });

  py::class_<SolveOutcome, std::shared_ptr<SolveOutcome>>(m, "SolveOutcome",
                                                          "What a solve returned (C++ side).")
      .def_property_readonly(
          "status", [](const SolveOutcome& o) { return StatusName(o.result.solve.status); })
      .def_property_readonly("objective",
                             [](const SolveOutcome& o) { return o.result.solve.objective; })
      .def_property_readonly("best_bound",
                             [](const SolveOutcome& o) { return o.result.solve.best_bound; })
      .def_property_readonly("gap", [](const SolveOutcome& o) { return o.result.solve.gap; })
      .def_property_readonly("nodes", [](const SolveOutcome& o) { return o.result.solve.nodes; })
      .def_property_readonly("detail", [](const SolveOutcome& o) { return o.result.solve.detail; })
      .def_property_readonly("solve_seconds",
                             [](const SolveOutcome& o) { return o.result.solve.wall_seconds; })
      .def_property_readonly("interrupted", [](const SolveOutcome& o) { return o.interrupted; })
      .def_property_readonly("total_seconds", [](const SolveOutcome& o) { return o.total_seconds; })
      .def_property_readonly("has_schedule",
                             [](const SolveOutcome& o) { return o.result.has_schedule(); })
      .def_property_readonly("summary_json", [](const SolveOutcome& o) { return o.summary_json; })
      .def_readonly("checked", &SolveOutcome::checked)
      .def_property_readonly(
          "x", [](const SolveOutcome& o) { return py::array_t<double>(o.x.size(), o.x.data()); })
      .def_property_readonly(
          "states", [](const SolveOutcome& o) { return StackVectors(o.result.schedule.states); },
          "Discrete-model states at the grid nodes, [N + 1, n].")
      .def_property_readonly(
          "outputs", [](const SolveOutcome& o) { return StackVectors(o.result.schedule.outputs); },
          "Model outputs at the grid nodes, [N + 1, p].")
      .def_property_readonly(
          "pattern",
          [](const SolveOutcome& o) {
            const Eigen::MatrixXi& p = o.result.schedule.pattern;
            py::array_t<int> a(
                {static_cast<py::ssize_t>(p.rows()), static_cast<py::ssize_t>(p.cols())});
            auto r = a.mutable_unchecked<2>();
            for (int i = 0; i < p.rows(); ++i) {
              for (int j = 0; j < p.cols(); ++j) r(i, j) = p(i, j);
            }
            return a;
          },
          "On-off pattern, thrusters x intervals (0/1).");
}

void BindScenario(py::module_& m) {
  py::class_<app::Scenario, ScenarioPtr>(m, "ParsedScenario",
                                         "A scenario as the C++ parser understood it (read-only).")
      .def_readonly("name", &app::Scenario::name)
      .def_readonly("path", &app::Scenario::path)
      .def_property_readonly(
          "model_type",
          [](const app::Scenario& s) { return std::string(app::ToString(s.model_type)); })
      .def_property_readonly("impulsive", &app::Scenario::impulsive)
      .def_readonly("num_intervals", &app::Scenario::num_intervals)
      .def_readonly("step_s", &app::Scenario::step_s)
      .def_property_readonly("start_s",
                             [](const app::Scenario& s) { return s.problem.grid.front(); })
      .def_property_readonly("end_s", [](const app::Scenario& s) { return s.problem.grid.back(); })
      .def_property_readonly("grid_s", [](const app::Scenario& s) { return Grid(s.problem); })
      .def_property_readonly("thruster_names", &app::Scenario::thruster_names)
      .def_readonly("window_unit", &app::Scenario::window_unit)
      .def_readonly("window_half_widths", &app::Scenario::window_half_widths)
      .def_readonly("window_unit_per_output_unit", &app::Scenario::window_unit_per_output_unit)
      .def_property_readonly("window_outputs",
                             [](const app::Scenario& s) {
                               std::vector<std::string> out;
                               const auto names = s.problem.model->output_names();
                               for (int o : s.problem.window.outputs) out.push_back(names.at(o));
                               return out;
                             })
      .def_property_readonly("state_names",
                             [](const app::Scenario& s) { return s.problem.model->state_names(); })
      .def_property_readonly("output_names",
                             [](const app::Scenario& s) { return s.problem.model->output_names(); })
      .def_property_readonly("epoch",
                             [](const app::Scenario& s) -> py::object {
                               if (!s.geo) return py::none();
                               return py::str(s.geo->epoch);
                             })
      .def_property_readonly(
          "objective_kind",
          [](const app::Scenario& s) { return std::string(ToString(s.problem.objective.kind)); })
      .def_property_readonly(
          "mean_motion_rad_s",
          [](const app::Scenario& s) -> py::object {
            if (const auto* h = dynamic_cast<const dynamics::HcwModel*>(s.problem.model.get())) {
              return py::float_(h->mean_motion());
            }
            return py::none();
          })
      .def_property_readonly("time_limit_s",
                             [](const app::Scenario& s) { return s.solve.time_limit_s; })
      .def_property_readonly("threads", [](const app::Scenario& s) { return s.solve.threads; })
      .def_property_readonly("initial_state",
                             [](const app::Scenario& s) {
                               return py::array_t<double>(s.problem.initial_state.size(),
                                                          s.problem.initial_state.data());
                             })
      .def_property_readonly("state_scale",
                             [](const app::Scenario& s) {
                               const Eigen::VectorXd v = s.problem.model->state_scale();
                               return py::array_t<double>(v.size(), v.data());
                             })
      .def_property_readonly("raw_json", [](const app::Scenario& s) { return s.raw.dump(); });

  m.def(
      "parse_scenario",
      [](const std::string& text, const std::string& source,
         const std::vector<std::string>& extra_sections) {
        app::ScenarioParseOptions o;
        o.source = source.empty() ? "scenario" : source;
        o.extra_sections = extra_sections;
        auto s = std::make_shared<app::Scenario>(app::ParseScenarioText(text, o));
        s->path = source;
        return s;
      },
      py::arg("text"), py::arg("source") = "",
      py::arg("extra_sections") = std::vector<std::string>{},
      py::call_guard<py::gil_scoped_release>(),
      "Parses scenario JSON text with the CLI's parser. `source` (the file path) names the text "
      "in messages and resolves relative paths. @raises ScenarioError (a ValueError) naming the "
      "field path and the value.");

  m.def(
      "parse_json_text",
      [](const std::string& text, const std::string& source) {
        return app::ParseJsonText(text, source).dump();
      },
      py::arg("text"), py::arg("source"),
      "Checks JSON text as the CLI does (syntax, duplicate keys); returns it re-serialised.");

  m.def(
      "solve_scenario",
      [](const ScenarioPtr& s, std::optional<double> time_limit_s,
         std::optional<double> relative_gap, std::optional<int> threads,
         std::optional<long long> max_nodes, std::optional<bool> search,
         std::optional<double> diagnosis_time_limit_s, std::optional<int> log_level,
         std::optional<int> random_seed, std::optional<std::string> scheme,
         std::optional<std::string> formulation, std::optional<std::string> encoding, bool check,
         double progress_interval_s, py::object callback) {
        const SolveSettings st = MakeSolveSettings(time_limit_s, relative_gap, threads, max_nodes,
                                                   search, diagnosis_time_limit_s, log_level,
                                                   random_seed, check, progress_interval_s);
        return SolveScenario(s, scheme, formulation, encoding, st, std::move(callback));
      },
      py::arg("scenario"), py::arg("time_limit_s") = py::none(),
      py::arg("relative_gap") = py::none(), py::arg("threads") = py::none(),
      py::arg("max_nodes") = py::none(), py::arg("search") = py::none(),
      py::arg("diagnosis_time_limit_s") = py::none(), py::arg("log_level") = py::none(),
      py::arg("random_seed") = py::none(), py::arg("scheme") = py::none(),
      py::arg("formulation") = py::none(), py::arg("encoding") = py::none(),
      py::arg("check") = true, py::arg("progress_interval_s") = 1.0,
      py::arg("callback") = py::none(),
      "Builds, solves and checks a parsed scenario as `thrustsched solve` does (GIL released, "
      "Ctrl-C stops and keeps the best schedule).");

  m.def("check_scenario", &CheckScenarioBurns, py::arg("scenario"), py::arg("thrusters"),
        py::arg("start_s"), py::arg("end_s"),
        "The independent checker on burns (as `thrustsched check`).");
  m.def("check_scenario_impulses", &CheckScenarioImpulses, py::arg("scenario"),
        py::arg("thrusters"), py::arg("nodes"), py::arg("delta_v_m_s"),
        "The impulsive check on impulses (as `thrustsched check`).");
  m.def(
      "read_schedule_csv",
      [](const ScenarioPtr& s, const std::string& path) {
        const std::vector<transcription::Burn> burns = app::ReadScheduleCsv(path, *s);
        std::vector<std::string> names;
        std::vector<double> start, end;
        const std::vector<std::string> all = s->thruster_names();
        for (const auto& b : burns) {
          names.push_back(all[b.thruster]);
          start.push_back(b.start_s);
          end.push_back(b.end_s);
        }
        return py::make_tuple(names, start, end);
      },
      py::arg("scenario"), py::arg("path"),
      "Reads schedule.csv with the CLI's reader: (thrusters, start_s, end_s).");
  m.def(
      "read_impulses_csv",
      [](const ScenarioPtr& s, const std::string& path) {
        const std::vector<transcription::Impulse> imp = app::ReadImpulsesCsv(path, *s);
        std::vector<std::string> names;
        std::vector<double> nodes, dv;
        const std::vector<std::string> all = s->thruster_names();
        for (const auto& i : imp) {
          names.push_back(all[i.thruster]);
          nodes.push_back(i.node);
          dv.push_back(i.delta_v_m_s);
        }
        return py::make_tuple(names, nodes, dv);
      },
      py::arg("scenario"), py::arg("path"),
      "Reads impulses.csv with the CLI's reader: (thrusters, nodes, delta_v_m_s).");
  m.def("export_scenario", &ExportScenario, py::arg("scenario"), py::arg("path"),
        py::arg("obfuscate_names") = false, py::arg("scheme") = py::none(),
        py::arg("formulation") = py::none(), py::arg("encoding") = py::none(),
        "Writes the scenario's MILP as MPS or LP (by the file's extension), as `thrustsched "
        "export`; returns the model's size.");
}

}  // namespace thrustsched::python
