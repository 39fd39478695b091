// Fleets from Python: `thrustsched solve` on a fleet scenario
// (app::RunFleetScenario) given as JSON text, with no run folder,
// interruptible as ts.solve is (python/src/runner.h: the first Ctrl-C stops
// the MILP and keeps the best schedules, the second raises
// KeyboardInterrupt); python/thrustsched/_fleet.py makes the dict and
// DataFrames.
//
//   summary_json, fleet_csv, schedule_csvs, trajectory_csvs, interrupted =
//       _core.fleet(text, "swap.json", base_dir, time_limit_s=None, relative_gap=None,
//                   threads=None, callback=None)
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/fleet_command.h"
#include "app/fleet_scenario.h"
#include "bindings.h"
#include "convert.h"
#include "runner.h"

namespace thrustsched::python {

namespace {

struct FleetData {
  std::string text, source, base_dir;
  app::ScenarioOverrides overrides;
  app::FleetRun run;
};

py::tuple Fleet(const std::string& text, const std::string& source, const std::string& base_dir,
                std::optional<double> time_limit_s, std::optional<double> relative_gap,
                std::optional<int> threads, py::object callback) {
  auto job = std::make_shared<Job>();
  auto data = std::make_shared<FleetData>();
  data->text = text, data->source = source, data->base_dir = base_dir;
  data->overrides.time_limit_s = time_limit_s;
  data->overrides.relative_gap = relative_gap;
  data->overrides.threads = threads;
  Job* j = job.get();
  RunInterruptible(
      job,
      [data, j] {
        const std::string what = data->source.empty() ? "fleet scenario" : data->source;
        app::FleetScenario f =
            app::ParseFleetScenario(app::ParseJsonText(data->text, what), data->base_dir);
        f.path = data->source;
        app::ApplyFleetOverrides(data->overrides, &f);
        app::FleetRunHooks hooks;
        hooks.interrupt = &j->stop;
        hooks.command_line = "python: thrustsched.fleet";
        hooks.progress = [j](const milp::SolveProgress& p) {
          j->Post([p](const py::handle& cb) { cb(ProgressDict(p)); });
        };
        data->run = app::RunFleetScenario(f, hooks);
      },
      std::move(callback), "fleet");
  const app::FleetRun& r = data->run;
  return py::make_tuple(r.summary.dump(), r.fleet_csv, r.schedule_csv, r.trajectory_csv,
                        r.interrupted);
}

}  // namespace

void BindFleet(py::module_& m) {
  m.def("fleet", &Fleet, py::arg("text"), py::arg("source") = "", py::arg("base_dir") = "",
        py::arg("time_limit_s") = py::none(), py::arg("relative_gap") = py::none(),
        py::arg("threads") = py::none(), py::arg("callback") = py::none(),
        "Solves a fleet scenario given as JSON text (member paths relative to base_dir) as "
        "`thrustsched solve` does, without files; returns (summary.json text, fleet.csv text, "
        "[schedule csv per member], [trajectory csv per member], interrupted). The GIL is "
        "released; the first Ctrl-C stops the MILP and keeps the best schedules.");
}

}  // namespace thrustsched::python
