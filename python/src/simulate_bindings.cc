// The year loop from Python: `thrustsched simulate` (app::RunSimulate) with
// the scenario given as JSON text, Python's Ctrl-C as the stop request, and
// one progress event per finished cycle; the run's files are the CLI's.
//
//   code, interrupted = _core.simulate(text, "data/scenarios/year/year_anzel4_fixed.json",
//                                      "out/year", cycles=2, resume=True, force=False,
//                                      plots=False, callback=lambda d: print(d))
#include <memory>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/simulate.h"
#include "bindings.h"
#include "convert.h"
#include "runner.h"

namespace thrustsched::python {

namespace {

py::tuple Simulate(const std::string& text, const std::string& source, const std::string& out_dir,
                   std::optional<int> cycles, bool resume, bool force, bool plots, bool quiet,
                   py::object callback) {
  if (cycles && *cycles < 1) {
    throw std::invalid_argument("cycles: must be >= 1, got " + std::to_string(*cycles));
  }
  auto job = std::make_shared<Job>();
  auto code = std::make_shared<int>(0);
  Job* j = job.get();
  app::SimulateArgs a;
  a.scenario = source;
  a.scenario_text = text;
  a.out_dir = out_dir;
  a.cycles = cycles.value_or(-1);
  a.resume = resume;
  a.force = force;
  a.no_plots = !plots;
  a.quiet = quiet;
  a.print_summary = false;
  a.command_line = "python: thrustsched.simulate";
  RunInterruptible(
      job,
      [a, code, j]() mutable {
        a.interrupt = &j->stop;
        a.on_cycle = [j](const planning::CycleRecord& c, int done, int target) {
          const double consumption = c.consumption_l1_m_s, gap = c.gap, solve = c.solve_seconds;
          const double lat = c.max_abs_lat_deg, lon = c.max_abs_lon_deg,
                       out = c.time_outside_window_s;
          const std::string status = StatusName(c.status);
          const std::string fallback(ToString(c.fallback));
          const int index = c.index;
          j->Post([=](const py::handle& cb) {
            py::dict d;
            d["phase"] = "cycle";
            d["cycle"] = index + 1;
            d["done"] = done;
            d["target"] = target;
            d["status"] = status;
            d["fallback"] = fallback;
            d["consumption_l1_m_s"] = consumption;
            d["gap"] = gap;
            d["solve_seconds"] = solve;
            d["max_abs_lat_deg"] = lat;
            d["max_abs_lon_deg"] = lon;
            d["time_outside_window_s"] = out;
            cb(d);
          });
        };
        *code = app::RunSimulate(a);
      },
      std::move(callback), "year simulation (the running cycle is not recorded; resume continues)");
  return py::make_tuple(*code, job->interrupted());
}

}  // namespace

void BindSimulate(py::module_& m) {
  m.def(
      "parse_simulation",
      [](const std::string& text, const std::string& source) {
        app::SimulationSetup setup =
            app::ParseSimulationText(text, source.empty() ? "scenario" : source);
        setup.scenario.path = source;
        return std::make_shared<app::Scenario>(std::move(setup.scenario));
      },
      py::arg("text"), py::arg("source") = "", py::call_guard<py::gil_scoped_release>(),
      "Parses a scenario with a \"long_horizon\" section as `thrustsched simulate` does.");
  m.def("simulate", &Simulate, py::arg("text"), py::arg("source"), py::arg("out_dir"),
        py::arg("cycles") = py::none(), py::arg("resume") = true, py::arg("force") = false,
        py::arg("plots") = true, py::arg("quiet") = true, py::arg("callback") = py::none(),
        "Runs `thrustsched simulate` on scenario JSON text; returns (exit code, interrupted).");
}

}  // namespace thrustsched::python
