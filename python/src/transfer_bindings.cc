// Orbit transfers from Python: `thrustsched transfer`'s run
// (app::RunTransferScenario) on a transfer scenario given as JSON text, with
// no run folder; python/thrustsched/_transfer.py turns the result into a
// dict and DataFrames.
//
//   summary_json, trajectory_csv, orbit_csv = _core.transfer(text, "60n.json", method=None)
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/transfer_run.h"
#include "app/transfer_scenario.h"
#include "bindings.h"

namespace thrustsched::python {

namespace {

py::tuple Transfer(const std::string& text, const std::string& source,
                   const std::optional<std::string>& method) {
  std::string summary, trajectory, orbit;
  {
    py::gil_scoped_release release;
    const std::string what = source.empty() ? "scenario" : source;
    app::TransferScenario sc = app::ParseTransferScenario(app::ParseJsonText(text, what), what);
    if (method) sc.method = app::ParseTransferMethod(*method, "method");
    const app::TransferRun run = app::RunTransferScenario(sc, source, /*quiet=*/true);
    summary = run.summary.dump();
    trajectory = run.trajectory_csv;
    orbit = app::OrbitCsv(run.orbit);
  }
  return py::make_tuple(summary, trajectory, orbit);
}

}  // namespace

void BindTransfer(py::module_& m) {
  m.def("transfer", &Transfer, py::arg("text"), py::arg("source") = "",
        py::arg("method") = py::none(),
        "Runs `thrustsched transfer` on transfer scenario JSON text (no files); returns "
        "(summary.json text, trajectory.csv text, orbit.csv text). The GIL is released.");
}

}  // namespace thrustsched::python
