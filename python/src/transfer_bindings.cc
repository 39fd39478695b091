// Orbit transfers from Python: `thrustsched transfer`'s run
// (app::RunTransferScenario) on a transfer scenario given as JSON text, with
// no run folder, interruptible as ts.solve is (python/src/runner.h: the first
// Ctrl-C stops the shooting or the feedback and returns the best result so
// far, summary "status" "interrupted"; the second raises KeyboardInterrupt);
// python/thrustsched/_transfer.py turns the result into a dict and DataFrames.
//
//   summary_json, trajectory_csv, orbit_csv, interrupted =
//       _core.transfer(text, "60n.json", method=None, callback=lambda d: print(d))
#include <memory>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/transfer_run.h"
#include "app/transfer_scenario.h"
#include "bindings.h"
#include "convert.h"
#include "runner.h"

namespace thrustsched::python {

namespace {

struct TransferData {
  std::string text, source;
  std::optional<std::string> method;
  std::string summary, trajectory, orbit;
};

py::tuple Transfer(const std::string& text, const std::string& source,
                   const std::optional<std::string>& method, py::object callback) {
  auto job = std::make_shared<Job>();
  auto data = std::make_shared<TransferData>();
  data->text = text, data->source = source, data->method = method;
  Job* j = job.get();
  RunInterruptible(
      job,
      [data, j] {
        const std::string what = data->source.empty() ? "scenario" : data->source;
        app::TransferScenario sc =
            app::ParseTransferScenario(app::ParseJsonText(data->text, what), what);
        if (data->method) sc.method = app::ParseTransferMethod(*data->method, "method");
        app::TransferHooks hooks;
        hooks.interrupt = &j->stop;
        hooks.progress = [j](const nlohmann::json& event) {
          j->Post([text = event.dump()](const py::handle& cb) { cb(JsonLoads(text)); });
        };
        const app::TransferRun run = app::RunTransferScenario(sc, data->source, true, hooks);
        data->summary = run.summary.dump();
        data->trajectory = run.trajectory_csv;
        data->orbit = app::OrbitCsv(run.orbit);
      },
      std::move(callback), "transfer");
  return py::make_tuple(data->summary, data->trajectory, data->orbit, job->interrupted());
}

}  // namespace

void BindTransfer(py::module_& m) {
  m.def("transfer", &Transfer, py::arg("text"), py::arg("source") = "",
        py::arg("method") = py::none(), py::arg("callback") = py::none(),
        "Runs `thrustsched transfer` on transfer scenario JSON text (no files); returns "
        "(summary.json text, trajectory.csv text, orbit.csv text, interrupted). The GIL is "
        "released; the first Ctrl-C stops the transfer and returns its best result so far, the "
        "second raises KeyboardInterrupt. callback(dict) receives the continuation steps and the "
        "feedback's end tries.");
}

}  // namespace thrustsched::python
