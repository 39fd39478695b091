// numpy <-> Eigen conversions (see convert.h).
//
//   py::array_t<double> a = StackMatrices(discrete.phi);   // [N, n, n], C order
#include "convert.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace thrustsched::python {

namespace {

std::string Shape(const DoubleArray& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

void CheckDims(const DoubleArray& a, const std::string& name, const std::vector<int>& want,
               bool allow_infinite = false) {
  bool ok = a.ndim() == static_cast<py::ssize_t>(want.size());
  for (size_t i = 0; ok && i < want.size(); ++i) ok = want[i] < 0 || a.shape(i) == want[i];
  if (!ok) {
    std::string w = "(";
    for (size_t i = 0; i < want.size(); ++i) {
      w += (i ? ", " : "") + (want[i] < 0 ? std::string("any") : std::to_string(want[i]));
    }
    w += want.size() == 1 ? ",)" : ")";
    throw std::invalid_argument(name + ": expected an array of shape " + w + ", got shape " +
                                Shape(a));
  }
  const double* p = a.data();
  for (py::ssize_t i = 0; i < a.size(); ++i) {
    if (allow_infinite ? std::isnan(p[i]) : !std::isfinite(p[i])) {
      throw std::invalid_argument(name + ": entry " + std::to_string(i) + " (flat index) is " +
                                  (allow_infinite ? "NaN" : "not finite"));
    }
  }
}

}  // namespace

py::array_t<double> StackMatrices(const std::vector<Eigen::MatrixXd>& matrices) {
  const py::ssize_t n = static_cast<py::ssize_t>(matrices.size());
  const py::ssize_t r = n ? matrices[0].rows() : 0, c = n ? matrices[0].cols() : 0;
  py::array_t<double> out({n, r, c});
  double* p = out.mutable_data();
  for (const Eigen::MatrixXd& m : matrices) {
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(p, r, c) = m;
    p += r * c;
  }
  return out;
}

py::array_t<double> StackVectors(const std::vector<Eigen::VectorXd>& vectors) {
  const py::ssize_t n = static_cast<py::ssize_t>(vectors.size());
  const py::ssize_t k = n ? vectors[0].size() : 0;
  py::array_t<double> out({n, k});
  double* p = out.mutable_data();
  for (const Eigen::VectorXd& v : vectors) {
    std::memcpy(p, v.data(), sizeof(double) * k);
    p += k;
  }
  return out;
}

std::vector<Eigen::MatrixXd> UnstackMatrices(const DoubleArray& a, const std::string& name,
                                             int count, int rows, int cols) {
  CheckDims(a, name, {count, rows, cols});
  const py::ssize_t n = a.shape(0), r = a.shape(1), c = a.shape(2);
  std::vector<Eigen::MatrixXd> out;
  out.reserve(n);
  const double* p = a.data();
  for (py::ssize_t i = 0; i < n; ++i, p += r * c) {
    out.emplace_back(
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            p, r, c));
  }
  return out;
}

std::vector<Eigen::VectorXd> UnstackVectors(const DoubleArray& a, const std::string& name,
                                            int count, int size) {
  CheckDims(a, name, {count, size});
  const py::ssize_t n = a.shape(0), k = a.shape(1);
  std::vector<Eigen::VectorXd> out;
  out.reserve(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    out.emplace_back(Eigen::Map<const Eigen::VectorXd>(a.data() + i * k, k));
  }
  return out;
}

Eigen::VectorXd ToVector(const DoubleArray& a, const std::string& name, int size,
                         bool allow_infinite) {
  CheckDims(a, name, {size}, allow_infinite);
  return Eigen::Map<const Eigen::VectorXd>(a.data(), a.shape(0));
}

Eigen::MatrixXd ToMatrix(const DoubleArray& a, const std::string& name, int rows, int cols) {
  CheckDims(a, name, {rows, cols});
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      a.data(), a.shape(0), a.shape(1));
}

const char* PhaseName(milp::SolvePhase phase) {
  switch (phase) {
    case milp::SolvePhase::kRootLp:
      return "root_lp";
    case milp::SolvePhase::kPresolve:
      return "presolve";
    case milp::SolvePhase::kSearch:
      return "search";
    case milp::SolvePhase::kFinishing:
      return "finishing";
  }
  return "search";
}

py::dict ProgressDict(const milp::SolveProgress& p) {
  py::dict d;
  d["wall_seconds"] = p.wall_seconds;
  d["objective"] = p.objective;
  d["best_bound"] = p.best_bound;
  d["gap"] = p.gap;
  d["nodes"] = p.nodes;
  d["new_incumbent"] = p.new_incumbent;
  d["phase"] = PhaseName(p.phase);
  d["stage"] = std::string(p.stage());
  d["stage_begins"] = p.stage_begins;
  if (p.phase == milp::SolvePhase::kRootLp) {
    d["lp_iterations"] = p.lp_iterations;
    d["lp_objective"] = p.lp_objective;
  }
  return d;
}

py::object JsonLoads(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

}  // namespace thrustsched::python
