// The thrustsched command line inside the Python package, so that
// `python3 -m thrustsched solve scenario.json --out out/x` is the CLI wherever
// the package is importable (campaign workers run tasks that way: a crash of
// a task's process leaves the worker alive).
//
//   code = _core.run_cli(["thrustsched", "solve", "scenario.json", "--out", "out/x"])
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/cli.h"
#include "bindings.h"

namespace thrustsched::python {

void BindCli(py::module_& m) {
  m.def(
      "run_cli", [](const std::vector<std::string>& args) { return app::RunCli(args); },
      py::arg("args"), py::call_guard<py::gil_scoped_release>(),
      "Runs the thrustsched command line (args[0] is the program name); returns its exit code. "
      "It installs its own SIGINT/SIGTERM handling for the run: meant for `python3 -m "
      "thrustsched`, a process of its own.");
}

}  // namespace thrustsched::python
