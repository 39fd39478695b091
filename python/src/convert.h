// numpy <-> Eigen conversions of the Python bindings (whole arrays copied in
// C++, never element by element in Python) and small shared helpers.
//
//   py::array_t<double> phi = StackMatrices(discrete.phi);            // [N, n, n]
//   std::vector<Eigen::MatrixXd> g = UnstackMatrices(gamma, "gamma", N, n, -1);
#ifndef THRUSTSCHED_PYTHON_CONVERT_H_
#define THRUSTSCHED_PYTHON_CONVERT_H_

#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <Eigen/Core>

#include "app/outputs.h"
#include "milp/solver.h"

namespace thrustsched::python {

namespace py = pybind11;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// [count, rows, cols] array of equally sized matrices (empty list: [0, 0, 0]).
py::array_t<double> StackMatrices(const std::vector<Eigen::MatrixXd>& matrices);
/// [count, size] array of equally sized vectors.
py::array_t<double> StackVectors(const std::vector<Eigen::VectorXd>& vectors);
/// Splits a 3-D array into matrices. `count`, `rows`, `cols` < 0: any.
/// @throws std::invalid_argument naming `name` and the shapes on a mismatch
///         or a non-finite entry.
std::vector<Eigen::MatrixXd> UnstackMatrices(const DoubleArray& a, const std::string& name,
                                             int count, int rows, int cols);
/// Splits a 2-D array into row vectors, as UnstackMatrices.
std::vector<Eigen::VectorXd> UnstackVectors(const DoubleArray& a, const std::string& name,
                                            int count, int size);
/// 1-D array to a vector (`size` < 0: any); `allow_infinite` admits +-inf
/// (bounds), never NaN. @throws as UnstackMatrices.
Eigen::VectorXd ToVector(const DoubleArray& a, const std::string& name, int size,
                         bool allow_infinite = false);
/// 2-D array to a matrix. @throws as UnstackMatrices.
Eigen::MatrixXd ToMatrix(const DoubleArray& a, const std::string& name, int rows, int cols);

/// A progress report as a dict: wall_seconds, objective, best_bound, gap,
/// nodes, new_incumbent, phase ("root_lp", "presolve", "search", "finishing").
py::dict ProgressDict(const milp::SolveProgress& p);
/// "root_lp" | "presolve" | "search" | "finishing".
const char* PhaseName(milp::SolvePhase phase);
/// "optimal" | "feasible" | "infeasible" | "unbounded" | "no_solution" | "error":
/// summary.json's names (the CLI's function, so that both always agree).
using app::StatusName;

/// Python's json.loads of a JSON text (for nlohmann::json dumps).
py::object JsonLoads(const std::string& text);

}  // namespace thrustsched::python

#endif  // THRUSTSCHED_PYTHON_CONVERT_H_
