// thrustsched.milp: building MILPs (variables, linear expressions with Python
// operators, constraints, objective), solving them with CBC, writing MPS/LP;
// and BuiltSchedule, a schedule MILP the user extends before solving again.
//
//   from thrustsched import milp
//   m = milp.Model("knapsack")
//   take = m.add_variables(3, 0, 1, "binary", "take")
//   m.add_constraint(milp.dot([2, 3, 4], take) <= 5, "weight")
//   m.maximize(milp.dot([3, 4, 5], take))
//   r = milp.solve(m)                        # CBC, GIL released; r.objective == 7
//   milp.write(m, "knapsack.mps")
//
//   b = ts.build(scn)                        # _core.build_scenario
//   for j in range(10, 20): b.add_constraint(b.on("+T", j) == 0)   # forbidden window
//   r = b.solve()                            # CBC on the whole MILP (the search would not see the
//   rows)
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/outputs.h"
#include "app/scenario.h"
#include "bindings.h"
#include "convert.h"
#include "milp/cbc_solver.h"
#include "milp/linear_expr.h"
#include "milp/lp_data.h"
#include "milp/model.h"
#include "milp/model_io.h"
#include "milp/variable.h"
#include "runner.h"

namespace thrustsched::python {

namespace {

using milp::BoundedLinearExpr;
using milp::LinearExpr;
using milp::VarBlock;
using milp::Variable;

milp::VarType ParseVarType(const std::string& t) {
  if (t == "continuous") return milp::VarType::kContinuous;
  if (t == "integer") return milp::VarType::kInteger;
  if (t == "binary") return milp::VarType::kBinary;
  throw std::invalid_argument("type: expected \"continuous\", \"integer\" or \"binary\", got \"" +
                              t + "\"");
}

// Variables from a VarBlock, a Variable or an iterable of Variables.
std::vector<Variable> VariableList(const py::handle& h) {
  if (py::isinstance<VarBlock>(h)) return h.cast<const VarBlock&>().ToVector();
  if (py::isinstance<Variable>(h)) return {h.cast<Variable>()};
  std::vector<Variable> out;
  for (py::handle x : h) out.push_back(x.cast<Variable>());
  return out;
}

LinearExpr QuickSum(const py::iterable& items) {
  LinearExpr e;
  for (py::handle x : items) {
    if (py::isinstance<Variable>(x)) {
      e.AddTerm(x.cast<Variable>(), 1.0);
    } else if (py::isinstance<LinearExpr>(x)) {
      e += x.cast<const LinearExpr&>();
    } else {
      e.AddConstant(x.cast<double>());
    }
  }
  return e;
}

LinearExpr Dot(const DoubleArray& coefficients, const py::handle& vars) {
  const std::vector<Variable> v = VariableList(vars);
  return LinearExpr::InnerProduct(
      ToVector(coefficients, "coefficients", static_cast<int>(v.size())), v);
}

milp::LpData LpOf(const py::handle& h) {
  if (py::isinstance<milp::Model>(h)) return h.cast<const milp::Model&>().ToLpData();
  return h.cast<const milp::LpData&>();
}

std::shared_ptr<milp::SolveResult> SolveLp(
    const py::handle& model, std::optional<double> time_limit_s, std::optional<double> relative_gap,
    std::optional<int> threads, std::optional<long long> max_nodes, std::optional<int> log_level,
    std::optional<DoubleArray> initial_solution, double progress_interval_s, py::object callback) {
  auto lp = std::make_shared<const milp::LpData>(LpOf(model));
  milp::SolveOptions o;
  if (time_limit_s) o.time_limit_s = *time_limit_s;
  if (relative_gap) o.relative_gap = *relative_gap;
  if (threads) o.threads = *threads;
  if (max_nodes) o.max_nodes = *max_nodes;
  if (log_level) o.log_level = *log_level;
  if (initial_solution)
    o.initial_solution = ToVector(*initial_solution, "initial_solution", lp->num_cols());
  o.progress_interval_s = progress_interval_s;
  std::string err;
  if (!o.IsValid(&err)) throw std::invalid_argument(err);
  auto job = std::make_shared<Job>();
  auto out = std::make_shared<milp::SolveResult>();
  Job* j = job.get();
  RunInterruptible(
      job,
      [lp, o, out, j]() mutable {
        o.interrupt = &j->stop;
        o.progress = [j](const milp::SolveProgress& p) {
          j->Post([p](const py::handle& cb) { cb(ProgressDict(p)); });
        };
        *out = milp::MakeCbcSolver()->Solve(*lp, o);
      },
      std::move(callback), "solve");
  return out;
}

// The state scale S of a built schedule (x = S x~ on the state columns).
Eigen::VectorXd StateScale(const BuiltSchedule& b) {
  const int n = b.ctx.problem->model->num_states();
  return b.milp->options().scale ? b.ctx.problem->model->state_scale() : Eigen::VectorXd::Ones(n);
}

int ThrusterIndex(const BuiltSchedule& b, const py::handle& thruster) {
  if (py::isinstance<py::str>(thruster))
    return b.ctx.problem->thrusters.IndexOf(thruster.cast<std::string>());
  const int i = thruster.cast<int>();
  if (i < 0 || i >= b.ctx.problem->thrusters.size()) {
    throw std::out_of_range("thruster index " + std::to_string(i) + " out of range");
  }
  return i;
}

void RequireSparse(const BuiltSchedule& b) {
  if (b.milp->options().formulation != transcription::Formulation::kSparse) {
    throw std::invalid_argument(
        "state columns exist in the sparse formulation only (this MILP is " +
        std::string(ToString(b.milp->options().formulation)) + ")");
  }
}

void CheckInterval(const BuiltSchedule& b, int j) {
  if (j < 0 || j >= b.ctx.problem->num_intervals()) {
    throw std::out_of_range("interval " + std::to_string(j) + " out of range [0, " +
                            std::to_string(b.ctx.problem->num_intervals()) + ")");
  }
}

}  // namespace

std::shared_ptr<SolveOutcome> SolveBuiltSchedule(const BuiltSchedule& built,
                                                 const SolveSettings& settings,
                                                 py::object callback) {
  SolveSettings st = settings;
  if (built.modified && !st.search) st.search = false;
  transcription::SolveScheduleOptions opt = built.options;
  ApplySettings(st, &opt);
  SolveRequest req;
  req.options = opt;
  req.check = st.check;
  if (!built.modified) req.conjunction = built.conjunction;
  std::shared_ptr<const transcription::ScheduleMilp> milp = built.milp;
  return SolveAndCheck(
      built.ctx, [milp] { return milp; }, req, std::make_shared<Job>(), std::move(callback));
}

namespace {

// Arithmetic and comparisons on expressions and (through them) variables:
// `+`, `-`, `*`, `/` by a number, and `<=`, `>=`, `==` giving constraints.
template <typename Class>
void BindArithmetic(Class& cls) {
  using T = typename Class::type;
  cls.def(
         "__add__", [](const T& a, const LinearExpr& b) { return LinearExpr(a) + b; },
         py::is_operator())
      .def(
          "__radd__", [](const T& a, const LinearExpr& b) { return b + LinearExpr(a); },
          py::is_operator())
      .def(
          "__sub__", [](const T& a, const LinearExpr& b) { return LinearExpr(a) - b; },
          py::is_operator())
      .def(
          "__rsub__", [](const T& a, const LinearExpr& b) { return b - LinearExpr(a); },
          py::is_operator())
      .def(
          "__mul__", [](const T& a, double c) { return LinearExpr(a) * c; }, py::is_operator())
      .def(
          "__rmul__", [](const T& a, double c) { return c * LinearExpr(a); }, py::is_operator())
      .def(
          "__truediv__", [](const T& a, double c) { return LinearExpr(a) * (1.0 / c); },
          py::is_operator())
      .def(
          "__neg__", [](const T& a) { return -LinearExpr(a); }, py::is_operator())
      .def(
          "__le__", [](const T& a, const LinearExpr& b) { return LinearExpr(a) <= b; },
          py::is_operator())
      .def(
          "__ge__", [](const T& a, const LinearExpr& b) { return LinearExpr(a) >= b; },
          py::is_operator())
      .def(
          "__eq__", [](const T& a, const LinearExpr& b) { return LinearExpr(a) == b; },
          py::is_operator());
  cls.attr("__hash__") = py::none();
}

// Variable, LinearExpr and BoundedLinearExpr.
void BindExpressions(py::module_& m) {
  py::class_<Variable> var_cls(m, "Variable", "One column of a Model (a handle: index and model).");
  var_cls.def_property_readonly("index", &Variable::index).def("__repr__", [](const Variable& v) {
    return "Variable(" + std::to_string(v.index()) + ")";
  });
  py::class_<LinearExpr> expr_cls(m, "LinearExpr",
                                  "sum_i c_i x_i + constant over the columns of one Model.");
  expr_cls.def(py::init<>())
      .def(py::init<double>(), py::arg("constant"))
      .def(py::init<Variable>(), py::arg("variable"))
      .def_property_readonly("constant", &LinearExpr::constant)
      .def_property_readonly(
          "terms",
          [](LinearExpr e) {
            e.Canonicalize();
            std::vector<int> idx;
            std::vector<double> c;
            for (const auto& t : e.terms()) {
              idx.push_back(t.index);
              c.push_back(t.coefficient);
            }
            return py::make_tuple(
                py::array_t<int>(static_cast<py::ssize_t>(idx.size()), idx.data()),
                py::array_t<double>(static_cast<py::ssize_t>(c.size()), c.data()));
          },
          "(column indices, coefficients), merged and sorted.")
      .def(
          "evaluate",
          [](const LinearExpr& e, const DoubleArray& x) {
            return e.Evaluate(ToVector(x, "x", -1));
          },
          py::arg("x"), "Value at the column vector x.")
      .def("__repr__", [](LinearExpr e) {
        e.Canonicalize();
        std::string s;
        for (const auto& t : e.terms()) {
          s += (s.empty() ? "" : " + ") + app::FormatNumber(t.coefficient) + " c" +
               std::to_string(t.index);
        }
        if (e.constant() != 0.0 || s.empty())
          s += (s.empty() ? "" : " + ") + app::FormatNumber(e.constant());
        return "LinearExpr(" + s + ")";
      });
  py::implicitly_convertible<Variable, LinearExpr>();
  py::implicitly_convertible<double, LinearExpr>();
  py::implicitly_convertible<int, LinearExpr>();

  py::class_<BoundedLinearExpr>(m, "BoundedLinearExpr",
                                "lower <= expr <= upper (made by <=, >=, == on expressions).")
      .def(py::init([](const LinearExpr& e, double lower, double upper) {
             LinearExpr x = e;
             const double c = x.constant();
             x.AddConstant(-c);
             return BoundedLinearExpr{x, lower - c, upper - c};
           }),
           py::arg("expr"), py::arg("lower"), py::arg("upper"))
      .def_readonly("expr", &BoundedLinearExpr::expr)
      .def_readonly("lower", &BoundedLinearExpr::lower)
      .def_readonly("upper", &BoundedLinearExpr::upper)
      .def("__bool__",
           [](const BoundedLinearExpr&) -> bool {
             throw std::invalid_argument(
                 "a constraint has no truth value (use it in add_constraint)");
           })
      .def("__repr__", [](const BoundedLinearExpr& b) {
        return app::FormatNumber(b.lower) +
               " <= " + py::repr(py::cast(b.expr)).cast<std::string>() +
               " <= " + app::FormatNumber(b.upper);
      });

  BindArithmetic(var_cls);
  BindArithmetic(expr_cls);
}

// VarBlock and LpData (a frozen MILP).
void BindVarBlockAndLpData(py::module_& m) {
  py::class_<VarBlock>(m, "VarBlock", "Contiguous columns of one Model.")
      .def("__len__", &VarBlock::size)
      .def("__getitem__",
           [](const VarBlock& b, int i) {
             if (i < 0) i += b.size();
             return b[i];
           })
      .def_property_readonly("start", &VarBlock::start)
      .def_property_readonly("size", &VarBlock::size)
      .def("to_list", &VarBlock::ToVector);

  py::class_<milp::LpData>(m, "LpData", "A frozen MILP in column-major standard form.")
      .def_readonly("name", &milp::LpData::name)
      .def_property_readonly("num_cols", &milp::LpData::num_cols)
      .def_property_readonly("num_rows", &milp::LpData::num_rows)
      .def_property_readonly("num_nonzeros", &milp::LpData::num_nonzeros)
      .def_property_readonly("num_integer_cols", &milp::LpData::num_integer_cols)
      .def_property_readonly(
          "maximize",
          [](const milp::LpData& lp) { return lp.sense == milp::ObjectiveSense::kMaximize; })
      .def_readonly("col_cost", &milp::LpData::col_cost)
      .def_readonly("objective_offset", &milp::LpData::objective_offset)
      .def_readonly("col_lower", &milp::LpData::col_lower)
      .def_readonly("col_upper", &milp::LpData::col_upper)
      .def_readonly("row_lower", &milp::LpData::row_lower)
      .def_readonly("row_upper", &milp::LpData::row_upper)
      .def_readonly("col_names", &milp::LpData::col_names)
      .def_readonly("row_names", &milp::LpData::row_names)
      .def_property_readonly(
          "matrix", [](const milp::LpData& lp) { return Eigen::SparseMatrix<double>(lp.a_matrix); },
          "The constraint matrix (scipy.sparse.csc_matrix).")
      .def_property_readonly("integer",
                             [](const milp::LpData& lp) {
                               std::vector<bool> v;
                               for (milp::VarType t : lp.col_type)
                                 v.push_back(t != milp::VarType::kContinuous);
                               return v;
                             })
      .def(
          "objective",
          [](const milp::LpData& lp, const DoubleArray& x) {
            return lp.Objective(ToVector(x, "x", lp.num_cols()));
          },
          py::arg("x"))
      .def(
          "max_violation",
          [](const milp::LpData& lp, const DoubleArray& x) {
            return lp.MaxViolation(ToVector(x, "x", lp.num_cols()));
          },
          py::arg("x"));
}

// Model, a MILP under construction.
void BindModel(py::module_& m) {
  py::class_<milp::Model>(m, "Model", "A MILP under construction (milp/model.h).")
      .def(py::init<std::string>(), py::arg("name") = "")
      .def_property_readonly("name", &milp::Model::name)
      .def(
          "add_variable",
          [](milp::Model& mo, double lower, double upper, const std::string& type,
             std::string name) {
            return mo.AddVariable(lower, upper, ParseVarType(type), std::move(name));
          },
          py::arg("lower") = 0.0, py::arg("upper") = milp::kInfinity,
          py::arg("type") = "continuous", py::arg("name") = "")
      .def("add_binary", &milp::Model::AddBinary, py::arg("name") = "")
      .def(
          "add_variables",
          [](milp::Model& mo, int count, double lower, double upper, const std::string& type,
             const std::string& prefix) {
            return mo.AddVariables(count, lower, upper, ParseVarType(type), prefix);
          },
          py::arg("count"), py::arg("lower") = 0.0, py::arg("upper") = milp::kInfinity,
          py::arg("type") = "continuous", py::arg("prefix") = "")
      .def("set_bounds", &milp::Model::SetBounds, py::arg("variable"), py::arg("lower"),
           py::arg("upper"))
      .def(
          "add_constraint",
          [](milp::Model& mo, const BoundedLinearExpr& c, std::string name) {
            return mo.AddConstraint(c, std::move(name)).index;
          },
          py::arg("constraint"), py::arg("name") = "", "Adds a row; returns its index.")
      .def(
          "add_rows",
          [](milp::Model& mo, const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
             const py::handle& vars, const DoubleArray& lower, const DoubleArray& upper,
             const std::string& prefix) {
            const milp::ConstraintBlock b = mo.AddRows(
                a, VariableList(vars), ToVector(lower, "lower", static_cast<int>(a.rows()), true),
                ToVector(upper, "upper", static_cast<int>(a.rows()), true), prefix);
            return py::make_tuple(b.start, b.size);
          },
          py::arg("matrix"), py::arg("variables"), py::arg("lower"), py::arg("upper"),
          py::arg("prefix") = "",
          "lower <= matrix @ variables <= upper in bulk (matrix: scipy.sparse or a dense array); "
          "returns (first row, number of rows).")
      .def("minimize", &milp::Model::Minimize, py::arg("objective"))
      .def("maximize", &milp::Model::Maximize, py::arg("objective"))
      .def("add_objective_term", &milp::Model::AddObjectiveTerm, py::arg("variable"),
           py::arg("coefficient"))
      .def_property_readonly("num_variables", &milp::Model::num_variables)
      .def_property_readonly("num_constraints", &milp::Model::num_constraints)
      .def_property_readonly("num_nonzeros", &milp::Model::num_nonzeros)
      .def("variable", &milp::Model::variable, py::arg("index"))
      .def("variable_name", &milp::Model::variable_name, py::arg("variable"))
      .def("to_lp", &milp::Model::ToLpData, "Freezes into an LpData (the model stays usable).");
}

// SolveResult and the module's functions: quicksum, dot, solve, write, to_*_string.
void BindSolveAndWrite(py::module_& m) {
  py::class_<milp::SolveResult, std::shared_ptr<milp::SolveResult>>(m, "SolveResult",
                                                                    "A MILP solve's result.")
      .def_property_readonly("status",
                             [](const milp::SolveResult& r) { return StatusName(r.status); })
      .def_readonly("objective", &milp::SolveResult::objective)
      .def_readonly("best_bound", &milp::SolveResult::best_bound)
      .def_readonly("gap", &milp::SolveResult::gap)
      .def_readonly("nodes", &milp::SolveResult::nodes)
      .def_readonly("wall_seconds", &milp::SolveResult::wall_seconds)
      .def_readonly("detail", &milp::SolveResult::detail)
      .def_readonly("solver_version", &milp::SolveResult::solver_version)
      .def_property_readonly("has_solution", &milp::SolveResult::has_solution)
      .def_readonly("x", &milp::SolveResult::x)
      .def(
          "value",
          [](const milp::SolveResult& r, const LinearExpr& e) {
            if (!r.has_solution()) throw std::invalid_argument("the solve has no solution");
            return e.Evaluate(r.x);
          },
          py::arg("expr"), "Value of a variable or expression at the solution.")
      .def("__repr__", [](const milp::SolveResult& r) {
        return "SolveResult(status=" + StatusName(r.status) +
               ", objective=" + app::FormatNumber(r.objective) + ")";
      });

  m.def("quicksum", &QuickSum, py::arg("items"),
        "Sum of variables, expressions and numbers (linear time).");
  m.def("dot", &Dot, py::arg("coefficients"), py::arg("variables"),
        "sum_i coefficients[i] * variables[i].");
  m.def("solve", &SolveLp, py::arg("model"), py::arg("time_limit_s") = py::none(),
        py::arg("relative_gap") = py::none(), py::arg("threads") = py::none(),
        py::arg("max_nodes") = py::none(), py::arg("log_level") = py::none(),
        py::arg("initial_solution") = py::none(), py::arg("progress_interval_s") = 1.0,
        py::arg("callback") = py::none(),
        "Solves a Model or LpData with CBC (GIL released; Ctrl-C stops and keeps the best "
        "solution).");
  m.def(
      "write",
      [](const py::handle& model, const std::string& path, bool obfuscate_names) {
        app::WriteModelFile(path, LpOf(model), obfuscate_names);
      },
      py::arg("model"), py::arg("path"), py::arg("obfuscate_names") = false,
      "Writes a Model or LpData as free MPS (.mps) or CPLEX LP (.lp).");
  m.def(
      "to_mps_string", [](const py::handle& model) { return milp::ToMpsString(LpOf(model)); },
      py::arg("model"));
  m.def(
      "to_lp_string", [](const py::handle& model) { return milp::ToLpString(LpOf(model)); },
      py::arg("model"));
}

using BuiltClass = py::class_<BuiltSchedule, std::shared_ptr<BuiltSchedule>>;

// The columns and expressions of a built schedule: on, state, outputs, intervals.
void BindBuiltColumns(BuiltClass& cls) {
  cls.def(
         "on",
         [](const BuiltSchedule& b, const py::handle& thruster, int interval) {
           CheckInterval(b, interval);
           return b.milp->on(ThrusterIndex(b, thruster), interval);
         },
         py::arg("thruster"), py::arg("interval"),
         "The binary \"thruster on in interval j\" (thruster by name or index).")
      .def_property_readonly(
          "on_columns",
          [](const BuiltSchedule& b) {
            const int mm = b.ctx.problem->thrusters.size(), nn = b.ctx.problem->num_intervals();
            py::array_t<int> a({mm, nn});
            auto r = a.mutable_unchecked<2>();
            for (int i = 0; i < mm; ++i) {
              for (int j = 0; j < nn; ++j) r(i, j) = b.milp->on(i, j).index();
            }
            return a;
          },
          "Column indices of the on-off binaries, thrusters x intervals.")
      .def(
          "state",
          [](const BuiltSchedule& b, int node, int component) {
            RequireSparse(b);
            return b.milp->state(node, component);
          },
          py::arg("node"), py::arg("component"),
          "The column of state component c at node j, scaled (x = S x~; sparse formulation).")
      .def(
          "state_expr",
          [](const BuiltSchedule& b, int node, int component) {
            RequireSparse(b);
            const Eigen::VectorXd s = StateScale(b);
            return s(component) * LinearExpr(b.milp->state(node, component));
          },
          py::arg("node"), py::arg("component"),
          "State component c at node j in the model's units (sparse formulation).")
      .def(
          "output_expr",
          [](const BuiltSchedule& b, int node, int output) {
            RequireSparse(b);
            const Eigen::VectorXd s = StateScale(b);
            const auto& p = *b.ctx.problem;
            if (node < 0 || node > p.num_intervals()) throw std::out_of_range("node out of range");
            const Eigen::MatrixXd c = p.model->EvaluateOutput(p.grid[node]).c;
            if (output < 0 || output >= c.rows()) throw std::out_of_range("output out of range");
            if (node == 0) return LinearExpr((c.row(output) * p.initial_state)(0));
            LinearExpr e;
            for (int k = 0; k < c.cols(); ++k) {
              if (c(output, k) != 0.0) e.AddTerm(b.milp->state(node, k), c(output, k) * s(k));
            }
            return e;
          },
          py::arg("node"), py::arg("output"),
          "Model output k at node j (y = C x) in its units (sparse formulation).")
      .def(
          "interval_at",
          [](const BuiltSchedule& b, double t_s) {
            const auto& g = b.ctx.problem->grid;
            if (!(t_s >= g.front() && t_s < g.back()))
              throw std::out_of_range("t_s outside the horizon");
            return static_cast<int>(std::upper_bound(g.begin(), g.end(), t_s) - g.begin()) - 1;
          },
          py::arg("t_s"), "Index of the interval holding t.");
}

// Rows, columns, bounds and objective terms added to a built schedule (refrozen).
void BindBuiltEdits(BuiltClass& cls) {
  cls.def(
         "add_variable",
         [](BuiltSchedule& b, double lower, double upper, const std::string& type,
            std::string name) {
           Variable v;
           b.milp->Modify([&](milp::Model& mo) {
             v = mo.AddVariable(lower, upper, ParseVarType(type), std::move(name));
           });
           b.modified = true;
           return v;
         },
         py::arg("lower") = 0.0, py::arg("upper") = milp::kInfinity, py::arg("type") = "continuous",
         py::arg("name") = "")
      .def(
          "add_constraint",
          [](BuiltSchedule& b, const BoundedLinearExpr& c, std::string name) {
            int row = -1;
            b.milp->Modify(
                [&](milp::Model& mo) { row = mo.AddConstraint(c, std::move(name)).index; });
            b.modified = true;
            return row;
          },
          py::arg("constraint"), py::arg("name") = "",
          "Adds a row (the MILP is refrozen); returns its index.")
      .def(
          "add_constraints",
          [](BuiltSchedule& b, const std::vector<BoundedLinearExpr>& rows,
             const std::string& prefix) {
            b.milp->Modify([&](milp::Model& mo) {
              for (size_t k = 0; k < rows.size(); ++k) {
                mo.AddConstraint(rows[k],
                                 prefix.empty() ? "" : prefix + "[" + std::to_string(k) + "]");
              }
            });
            b.modified = true;
          },
          py::arg("constraints"), py::arg("prefix") = "", "Adds rows, refreezing once.")
      .def(
          "set_bounds",
          [](BuiltSchedule& b, Variable v, double lower, double upper) {
            b.milp->Modify([&](milp::Model& mo) { mo.SetBounds(v, lower, upper); });
            b.modified = true;
          },
          py::arg("variable"), py::arg("lower"), py::arg("upper"))
      .def(
          "add_objective_term",
          [](BuiltSchedule& b, Variable v, double c) {
            b.milp->Modify([&](milp::Model& mo) { mo.AddObjectiveTerm(v, c); });
            b.modified = true;
          },
          py::arg("variable"), py::arg("coefficient"));
}

// Read-only facts of a built schedule: its size, grid, scaling and names.
void BindBuiltProperties(BuiltClass& cls) {
  cls.def_property_readonly("modified", [](const BuiltSchedule& b) { return b.modified; })
      .def_property_readonly(
          "lp", [](const BuiltSchedule& b) { return b.milp->lp(); }, "A copy of the frozen MILP.")
      .def_property_readonly("num_rows",
                             [](const BuiltSchedule& b) { return b.milp->lp().num_rows(); })
      .def_property_readonly("num_columns",
                             [](const BuiltSchedule& b) { return b.milp->lp().num_cols(); })
      .def_property_readonly("num_binaries",
                             [](const BuiltSchedule& b) { return b.milp->lp().num_integer_cols(); })
      .def_property_readonly("num_nonzeros",
                             [](const BuiltSchedule& b) { return b.milp->lp().num_nonzeros(); })
      .def_property_readonly("objective_step",
                             [](const BuiltSchedule& b) { return b.milp->objective_step(); })
      .def_property_readonly("formulation",
                             [](const BuiltSchedule& b) {
                               return std::string(ToString(b.milp->options().formulation));
                             })
      .def_property_readonly("state_scale",
                             [](const BuiltSchedule& b) {
                               const Eigen::VectorXd s = StateScale(b);
                               return py::array_t<double>(s.size(), s.data());
                             })
      .def_property_readonly("grid_s",
                             [](const BuiltSchedule& b) {
                               const auto& g = b.ctx.problem->grid;
                               return py::array_t<double>(static_cast<py::ssize_t>(g.size()),
                                                          g.data());
                             })
      .def_property_readonly("thruster_names",
                             [](const BuiltSchedule& b) { return b.ctx.thruster_names(); })
      .def("variable_name",
           [](const BuiltSchedule& b, Variable v) { return b.milp->model().variable_name(v); });
}

// The model file (MPS or LP) and the solve of a built schedule.
void BindBuiltWriteAndSolve(BuiltClass& cls) {
  cls.def(
         "write",
         [](const BuiltSchedule& b, const std::string& path, bool obfuscate_names) {
           milp::LpData lp = b.milp->lp();
           if (b.ctx.scenario) lp.name = b.ctx.scenario->name;
           app::WriteModelFile(path, lp, obfuscate_names);
         },
         py::arg("path"), py::arg("obfuscate_names") = false, "Writes MPS (.mps) or LP (.lp).")
      .def(
          "solve",
          [](const BuiltSchedule& b, std::optional<double> time_limit_s,
             std::optional<double> relative_gap, std::optional<int> threads,
             std::optional<long long> max_nodes, std::optional<bool> search,
             std::optional<double> diagnosis_time_limit_s, std::optional<int> log_level,
             std::optional<int> random_seed, bool check, double progress_interval_s,
             py::object callback) {
            const SolveSettings st = MakeSolveSettings(
                time_limit_s, relative_gap, threads, max_nodes, search, diagnosis_time_limit_s,
                log_level, random_seed, check, progress_interval_s);
            return SolveBuiltSchedule(b, st, std::move(callback));
          },
          py::arg("time_limit_s") = py::none(), py::arg("relative_gap") = py::none(),
          py::arg("threads") = py::none(), py::arg("max_nodes") = py::none(),
          py::arg("search") = py::none(), py::arg("diagnosis_time_limit_s") = py::none(),
          py::arg("log_level") = py::none(), py::arg("random_seed") = py::none(),
          py::arg("check") = true, py::arg("progress_interval_s") = 1.0,
          py::arg("callback") = py::none());
}

// build_scenario: a scenario's schedule MILP, to extend.
void BindBuildScenario(py::module_& m) {
  m.def(
      "build_scenario",
      [](const std::shared_ptr<app::Scenario>& s, std::optional<std::string> scheme,
         std::optional<std::string> formulation, std::optional<std::string> encoding) {
        auto sc = std::make_shared<app::Scenario>(*s);
        ApplyBuildSettings(scheme, formulation, encoding, &sc->build);
        auto b = std::make_shared<BuiltSchedule>();
        b->ctx = ScenarioContext(sc);
        b->options.build = sc->build;
        b->options.milp = sc->solve;
        b->options.search.enabled = sc->search;
        b->options.prefix_diagnosis_s = sc->diagnosis_time_limit_s;
        if (sc->problem.conjunction) b->conjunction = sc->conjunction_solve;
        py::gil_scoped_release nogil;
        b->milp = std::make_shared<transcription::ScheduleMilp>(sc->problem, sc->build);
        return b;
      },
      py::arg("scenario"), py::arg("scheme") = py::none(), py::arg("formulation") = py::none(),
      py::arg("encoding") = py::none(),
      "Builds a scenario's schedule MILP (to extend, then solve).");
}

}  // namespace

void BindMilp(py::module_& m) {
  BindExpressions(m);
  BindVarBlockAndLpData(m);
  BindModel(m);
  BindSolveAndWrite(m);
}

void BindBuilt(py::module_& m) {
  BuiltClass cls(m, "BuiltSchedule",
                 "A schedule MILP, to extend with rows and columns and solve again.");
  BindBuiltColumns(cls);
  BindBuiltEdits(cls);
  BindBuiltProperties(cls);
  BindBuiltWriteAndSolve(cls);
  BindBuildScenario(m);
}

}  // namespace thrustsched::python
