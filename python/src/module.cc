// thrustsched._core: the C++ side of the Python package (python/thrustsched/).
// Users import `thrustsched`, not this module:
//
//   import thrustsched as ts
//   scn = ts.Scenario.load("data/scenarios/hcw_table41_1d.json")
//   res = ts.solve(scn, time_limit_s=60)          # _core.solve_scenario underneath
//
// Submodules: _core.dynamics (models, thruster sets, discretisation),
// _core.milp (model building, CBC, MPS/LP). Errors: app::ScenarioError ->
// thrustsched.ScenarioError (a ValueError: the CLI's "field path: value"
// message); std::invalid_argument -> ValueError; other C++ exceptions ->
// RuntimeError (pybind11's translators): none reaches the interpreter
// unhandled.
#include <pybind11/pybind11.h>

#include "app/json_reader.h"
#include "bindings.h"
#include "milp/cbc_solver.h"

#ifndef THRUSTSCHED_VERSION
#define THRUSTSCHED_VERSION "unknown"
#endif

namespace py = pybind11;

PYBIND11_MODULE(_core, m) {
  m.doc() = "C++ core of the thrustsched package (use `import thrustsched`).";
  m.attr("__version__") = THRUSTSCHED_VERSION;
  m.def("solver_version", &thrustsched::milp::CbcVersion, "CBC and CLP versions.");
  py::register_exception<thrustsched::app::ScenarioError>(m, "ScenarioError", PyExc_ValueError);

  py::module_ dynamics =
      m.def_submodule("dynamics", "Linear models, thruster sets, discretisation.");
  py::module_ milp = m.def_submodule("milp", "MILP model building, CBC, MPS/LP writers.");
  thrustsched::python::BindDynamics(dynamics);
  thrustsched::python::BindMilp(milp);
  thrustsched::python::BindOutcomes(m);
  thrustsched::python::BindScenario(m);
  thrustsched::python::BindProblem(m);
  thrustsched::python::BindBuilt(m);
  thrustsched::python::BindSimulate(m);
  thrustsched::python::BindCli(m);
  thrustsched::python::BindTransfer(m);
  thrustsched::python::BindFleet(m);
}
