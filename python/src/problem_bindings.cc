// Bring your own dynamics: a scheduling problem from numpy arrays
// x_{j+1} = Phi_j x_j + Gamma_j u_j + d_j (u_j in {0, 1}^m, one column per
// thruster), y_j = C_j x_j, transcribed by the same MILP builder as the
// shipped models (ScheduleMilp's constructor from a DiscreteModel).
//
//   p = _core.ArrayProblem(phi, gamma, grid_s, x0, C, thrusters, drift=None,
//                          window_outputs=[1, 2], window_half_widths=[36800, 36800],
//                          rules_json='{"min_burn_s": 300}')
//   r = p.solve(time_limit_s=60)          # a SolveOutcome, as for scenarios
//
// There is no continuous-time model behind the arrays: the check is the
// operational rules in continuous time and the arrays propagated through the
// on-off pattern (the window judged at the grid nodes); impulsive mode,
// inter-sample window points and the station-keeping terminal sets, which
// need the continuous model, are refused.
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

#include "app/json_reader.h"
#include "bindings.h"
#include "convert.h"
#include "dynamics/discretisation.h"
#include "dynamics/linear_model.h"
#include "dynamics/thrusters.h"
#include "transcription/problem.h"

namespace thrustsched::python {

namespace {

// A time is a grid node's when it is this close, relative to max(1 s, |t|).
constexpr double kGridNodeRelativeTolerance = 1e-9;

constexpr double kInf = std::numeric_limits<double>::infinity();
const char* const kNoContinuousModel =
    "this problem was built from arrays (Phi, Gamma, drift): its continuous-time matrices are "
    "unknown (impulsive mode, window intersample points and station-keeping terminal sets need a "
    "continuous model)";

// The model behind an array problem: sizes, output matrices at the grid
// nodes, scales and names; no continuous-time dynamics.
class ArrayModel final : public dynamics::LinearModel {
 public:
  ArrayModel(int num_states, std::vector<Eigen::MatrixXd> c, std::vector<double> grid,
             Eigen::VectorXd scale, std::vector<std::string> state_names,
             std::vector<std::string> output_names)
      : n_(num_states),
        c_(std::move(c)),
        grid_(std::move(grid)),
        scale_(std::move(scale)),
        state_names_(std::move(state_names)),
        output_names_(std::move(output_names)) {}

  std::string_view name() const override { return "arrays"; }
  int num_states() const override { return n_; }
  int num_inputs() const override { return 3; }  // nominal: thruster sets act in RTN
  int num_outputs() const override { return static_cast<int>(c_[0].rows()); }
  bool is_time_invariant() const override { return false; }
  dynamics::ModelMatrices Evaluate(double) const override {
    throw std::invalid_argument(kNoContinuousModel);
  }
  dynamics::OutputMatrices EvaluateOutput(double t) const override {
    dynamics::OutputMatrices o;
    o.c_dot = Eigen::MatrixXd::Zero(c_[0].rows(), n_);
    if (c_.size() == 1) {
      o.c = c_[0];
      return o;
    }
    for (size_t j = 0; j < grid_.size(); ++j) {
      if (std::abs(grid_[j] - t) <= kGridNodeRelativeTolerance * std::max(1.0, std::abs(t))) {
        o.c = c_[j];
        return o;
      }
    }
    throw std::invalid_argument(
        "the output matrix of an array problem is known at the grid nodes "
        "only, not at t = " +
        app::FormatNumber(t) + " s");
  }
  std::vector<std::string> state_names() const override { return state_names_; }
  std::vector<std::string> output_names() const override { return output_names_; }
  Eigen::VectorXd state_scale() const override { return scale_; }
  double time_scale() const override { return grid_[1] - grid_[0]; }

 private:
  int n_;
  std::vector<Eigen::MatrixXd> c_;
  std::vector<double> grid_;
  Eigen::VectorXd scale_;
  std::vector<std::string> state_names_, output_names_;
};

// The "operations" section's fields (same names and checks as the scenario
// file's), from JSON text; `path` names it in messages.
transcription::OperationalRules ParseRules(const std::string& json_text, const std::string& path) {
  transcription::OperationalRules r;
  const nlohmann::json j = app::ParseJsonText(json_text, path);
  app::JsonObject o(j, path);
  r.max_simultaneous = o.OptionalInteger("max_simultaneous", 1, 64).value_or(1);
  r.min_burn_s = o.OptionalNumber("min_burn_s", app::Bound::kNonNegative).value_or(0.0);
  r.min_off_same_s = o.OptionalNumber("min_off_same_s", app::Bound::kNonNegative).value_or(0.0);
  r.min_gap_other_s = o.OptionalNumber("min_gap_other_s", app::Bound::kNonNegative).value_or(0.0);
  r.max_burn_s = o.OptionalNumber("max_burn_s", app::Bound::kPositive).value_or(kInf);
  r.max_burns_per_thruster = o.OptionalInteger("max_burns_per_thruster", 0, 1000000).value_or(-1);
  r.allow_burn_across_end = o.OptionalBool("allow_burn_across_end").value_or(false);
  if (r.max_burn_s < r.min_burn_s) {
    o.Fail("max_burn_s", app::FormatNumber(r.max_burn_s) + " s is shorter than min_burn_s " +
                             app::FormatNumber(r.min_burn_s) + " s");
  }
  o.Finish();
  std::string err;
  if (!r.IsValid(&err)) throw app::ScenarioError(path + ": " + err);
  return r;
}

std::vector<std::string> DefaultNames(const std::optional<std::vector<std::string>>& given,
                                      int count, const std::string& prefix,
                                      const std::string& what) {
  if (given) {
    if (static_cast<int>(given->size()) != count) {
      throw std::invalid_argument(what + ": expected " + std::to_string(count) + " names, got " +
                                  std::to_string(given->size()));
    }
    return *given;
  }
  std::vector<std::string> out;
  for (int i = 0; i < count; ++i) out.push_back(prefix + std::to_string(i));
  return out;
}

struct ArrayProblem {
  ProblemContext ctx;
};

std::shared_ptr<ArrayProblem> MakeArrayProblem(
    const DoubleArray& phi, const DoubleArray& gamma, const std::vector<double>& grid_s,
    const DoubleArray& initial_state, const DoubleArray& output_matrix,
    const dynamics::ThrusterSet& thrusters, const std::optional<DoubleArray>& drift,
    const std::vector<int>& window_outputs, const std::vector<double>& window_half_widths,
    std::optional<double> window_enforce_from_s, bool window_soft, double window_soft_penalty,
    double window_margin, const std::string& rules_json, const std::string& objective,
    double burn_start_penalty, const std::string& terminal,
    const std::optional<DoubleArray>& terminal_target,
    const std::optional<DoubleArray>& terminal_tolerance,
    const std::optional<DoubleArray>& state_scale,
    const std::optional<std::vector<std::string>>& state_names,
    const std::optional<std::vector<std::string>>& output_names,
    const std::vector<std::tuple<std::string, double, double>>& forced_off) {
  if (phi.ndim() != 3) {
    throw std::invalid_argument("phi: expected an array of shape (N, n, n), got " +
                                std::to_string(phi.ndim()) + " dimensions");
  }
  const int nn = static_cast<int>(phi.shape(0)), n = static_cast<int>(phi.shape(1));
  const int m = thrusters.size();
  if (static_cast<int>(grid_s.size()) != nn + 1) {
    throw std::invalid_argument("grid_s: expected N + 1 = " + std::to_string(nn + 1) +
                                " node times (phi has N = " + std::to_string(nn) +
                                " intervals), got " + std::to_string(grid_s.size()));
  }
  auto dm = std::make_shared<dynamics::DiscreteModel>();
  dm->grid = grid_s;
  dm->phi = UnstackMatrices(phi, "phi", nn, n, n);
  dm->gamma =
      UnstackMatrices(gamma, "gamma (columns = thrusters " + std::to_string(m) + ")", nn, n, m);
  dm->drift = drift ? UnstackVectors(*drift, "drift", nn, n)
                    : std::vector<Eigen::VectorXd>(nn, Eigen::VectorXd::Zero(n));
  std::vector<Eigen::MatrixXd> c;
  if (output_matrix.ndim() == 2) {
    c.push_back(ToMatrix(output_matrix, "output_matrix", -1, n));
  } else {
    c = UnstackMatrices(output_matrix, "output_matrix (per node)", nn + 1, -1, n);
  }
  const int p = static_cast<int>(c[0].rows());
  Eigen::VectorXd scale =
      state_scale ? ToVector(*state_scale, "state_scale", n) : Eigen::VectorXd::Ones(n);
  if (!(scale.array() > 0.0).all()) throw std::invalid_argument("state_scale: entries must be > 0");

  auto prob = std::make_shared<transcription::ScheduleProblem>();
  ArrayProblem out;
  out.ctx.state_names = DefaultNames(state_names, n, "x", "state_names");
  out.ctx.output_names = DefaultNames(output_names, p, "y", "output_names");
  prob->model =
      std::make_shared<ArrayModel>(n, c, grid_s, scale, out.ctx.state_names, out.ctx.output_names);
  prob->thrusters = thrusters;
  prob->grid = grid_s;
  prob->initial_state = ToVector(initial_state, "initial_state", n);
  prob->rules = ParseRules(rules_json.empty() ? "{}" : rules_json, "rules");
  prob->window.outputs = window_outputs;
  prob->window.half_widths = window_half_widths;
  if (window_enforce_from_s) prob->window.enforce_from_s = *window_enforce_from_s;
  prob->window.soft = window_soft;
  prob->window.soft_penalty = window_soft_penalty;
  prob->window.margin = window_margin;
  prob->objective.kind =
      app::Wrap("objective", [&] { return transcription::ParseObjectiveKind(objective); });
  prob->objective.burn_start_penalty = burn_start_penalty;
  if (terminal == "free") {
    prob->terminal.kind = transcription::TerminalKind::kFree;
  } else if (terminal == "fixed" || terminal == "box") {
    prob->terminal.kind = terminal == "fixed" ? transcription::TerminalKind::kFixedState
                                              : transcription::TerminalKind::kStateBox;
    if (!terminal_target)
      throw std::invalid_argument("terminal_target: needed with terminal=\"" + terminal + "\"");
    prob->terminal.target = ToVector(*terminal_target, "terminal_target", n);
    if (terminal == "box") {
      if (!terminal_tolerance)
        throw std::invalid_argument("terminal_tolerance: needed with terminal=\"box\"");
      prob->terminal.tolerance = ToVector(*terminal_tolerance, "terminal_tolerance", n);
    }
  } else {
    throw std::invalid_argument("terminal: expected \"free\", \"fixed\" or \"box\", got \"" +
                                terminal + "\" (station-keeping sets need a continuous model)");
  }
  for (const auto& [name, from, until] : forced_off) {
    transcription::ForcedOff f;
    f.thruster = app::Wrap("forced_off", [&] { return thrusters.IndexOf(name); });
    f.start_s = from;
    f.end_s = until;
    prob->forced_off.push_back(f);
  }
  std::string err;
  if (!prob->IsValid(&err)) throw std::invalid_argument(err);
  out.ctx.problem = prob;
  out.ctx.discrete = dm;
  return std::make_shared<ArrayProblem>(std::move(out));
}

}  // namespace

void BindProblem(py::module_& m) {
  py::class_<ArrayProblem, std::shared_ptr<ArrayProblem>>(
      m, "ArrayProblem",
      "A scheduling problem from numpy arrays (see thrustsched.ScheduleProblem).")
      .def(py::init(&MakeArrayProblem), py::arg("phi"), py::arg("gamma"), py::arg("grid_s"),
           py::arg("initial_state"), py::arg("output_matrix"), py::arg("thrusters"),
           py::arg("drift") = py::none(), py::arg("window_outputs") = std::vector<int>{},
           py::arg("window_half_widths") = std::vector<double>{},
           py::arg("window_enforce_from_s") = py::none(), py::arg("window_soft") = false,
           py::arg("window_soft_penalty") = 1e3, py::arg("window_margin") = 0.0,
           py::arg("rules_json") = "{}", py::arg("objective") = "l1",
           py::arg("burn_start_penalty") = 0.0, py::arg("terminal") = "free",
           py::arg("terminal_target") = py::none(), py::arg("terminal_tolerance") = py::none(),
           py::arg("state_scale") = py::none(), py::arg("state_names") = py::none(),
           py::arg("output_names") = py::none(),
           py::arg("forced_off") = std::vector<std::tuple<std::string, double, double>>{})
      .def_property_readonly("num_intervals",
                             [](const ArrayProblem& a) { return a.ctx.problem->num_intervals(); })
      .def_property_readonly(
          "num_states", [](const ArrayProblem& a) { return a.ctx.problem->model->num_states(); })
      .def_property_readonly("grid_s",
                             [](const ArrayProblem& a) {
                               const auto& g = a.ctx.problem->grid;
                               return py::array_t<double>(static_cast<py::ssize_t>(g.size()),
                                                          g.data());
                             })
      .def_property_readonly("thruster_names",
                             [](const ArrayProblem& a) { return a.ctx.thruster_names(); })
      .def_property_readonly("state_names", [](const ArrayProblem& a) { return a.ctx.state_names; })
      .def_property_readonly("output_names",
                             [](const ArrayProblem& a) { return a.ctx.output_names; })
      .def_property_readonly("window_outputs",
                             [](const ArrayProblem& a) {
                               std::vector<std::string> out;
                               for (int o : a.ctx.problem->window.outputs)
                                 out.push_back(a.ctx.output_names.at(o));
                               return out;
                             })
      .def_property_readonly(
          "window_half_widths",
          [](const ArrayProblem& a) { return a.ctx.problem->window.half_widths; })
      .def(
          "solve",
          [](const ArrayProblem& a, std::optional<double> time_limit_s,
             std::optional<double> relative_gap, std::optional<int> threads,
             std::optional<long long> max_nodes, std::optional<bool> search,
             std::optional<int> log_level, std::optional<int> random_seed,
             std::optional<std::string> formulation, std::optional<std::string> encoding,
             bool check, double progress_interval_s, py::object callback) {
            const SolveSettings st =
                MakeSolveSettings(time_limit_s, relative_gap, threads, max_nodes, search,
                                  std::nullopt, log_level, random_seed, check, progress_interval_s);
            transcription::SolveScheduleOptions opt;
            ApplyBuildSettings(std::nullopt, formulation, encoding, &opt.build);
            ApplySettings(st, &opt);
            SolveRequest req;
            req.options = opt;
            req.check = check;
            const ProblemContext ctx = a.ctx;
            const transcription::BuildOptions build = opt.build;
            auto make = [ctx, build] {
              return std::make_shared<const transcription::ScheduleMilp>(*ctx.problem,
                                                                         *ctx.discrete, build);
            };
            return SolveAndCheck(ctx, make, req, std::make_shared<Job>(), std::move(callback));
          },
          py::arg("time_limit_s") = py::none(), py::arg("relative_gap") = py::none(),
          py::arg("threads") = py::none(), py::arg("max_nodes") = py::none(),
          py::arg("search") = py::none(), py::arg("log_level") = py::none(),
          py::arg("random_seed") = py::none(), py::arg("formulation") = py::none(),
          py::arg("encoding") = py::none(), py::arg("check") = true,
          py::arg("progress_interval_s") = 1.0, py::arg("callback") = py::none())
      .def(
          "build",
          [](const ArrayProblem& a, std::optional<std::string> formulation,
             std::optional<std::string> encoding) {
            auto b = std::make_shared<BuiltSchedule>();
            b->ctx = a.ctx;
            ApplyBuildSettings(std::nullopt, formulation, encoding, &b->options.build);
            py::gil_scoped_release nogil;
            b->milp = std::make_shared<transcription::ScheduleMilp>(*a.ctx.problem, *a.ctx.discrete,
                                                                    b->options.build);
            return b;
          },
          py::arg("formulation") = py::none(), py::arg("encoding") = py::none())
      .def(
          "check",
          [](const ArrayProblem& a, const std::vector<std::string>& thrusters,
             const std::vector<double>& start_s, const std::vector<double>& end_s) {
            auto c = std::make_shared<CheckedSchedule>();
            c->ctx = a.ctx;
            c->burns = BurnsFromColumns(a.ctx, thrusters, start_s, end_s);
            RunCheck(c.get());
            return c;
          },
          py::arg("thrusters"), py::arg("start_s"), py::arg("end_s"));
}

}  // namespace thrustsched::python
