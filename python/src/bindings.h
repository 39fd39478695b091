// The binding functions of thrustsched._core, one per source file, and the
// helpers they share.
//
//   PYBIND11_MODULE(_core, m) { BindScenario(m); ... }     // module.cc
#ifndef THRUSTSCHED_PYTHON_BINDINGS_H_
#define THRUSTSCHED_PYTHON_BINDINGS_H_

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "outcome.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"

namespace thrustsched::python {

namespace py = pybind11;

void BindDynamics(py::module_& m);  // dynamics_bindings.cc
void BindMilp(py::module_& m);      // milp_bindings.cc
void BindBuilt(py::module_& m);     // milp_bindings.cc (schedule MILPs users edit)
void BindOutcomes(py::module_& m);  // scenario_bindings.cc
void BindScenario(py::module_& m);  // scenario_bindings.cc
void BindProblem(py::module_& m);   // problem_bindings.cc
void BindSimulate(py::module_& m);  // simulate_bindings.cc
void BindCli(py::module_& m);       // cli_bindings.cc
void BindTransfer(py::module_& m);  // transfer_bindings.cc
void BindFleet(py::module_& m);     // fleet_bindings.cc

/// Solve settings given by keyword in Python; unset ones keep the problem's
/// (scenario file) values.
struct SolveSettings {
  std::optional<double> time_limit_s, relative_gap, diagnosis_time_limit_s;
  std::optional<int> threads, log_level, random_seed;
  std::optional<long long> max_nodes;
  std::optional<bool> search;
  double progress_interval_s = 1.0;
  bool check = true;
};
/// The solve keywords of ts.solve, BuiltSchedule.solve and
/// ScheduleProblem.solve as SolveSettings (array problems have no
/// diagnosis limit: nullopt).
inline SolveSettings MakeSolveSettings(
    std::optional<double> time_limit_s, std::optional<double> relative_gap,
    std::optional<int> threads, std::optional<long long> max_nodes, std::optional<bool> search,
    std::optional<double> diagnosis_time_limit_s, std::optional<int> log_level,
    std::optional<int> random_seed, bool check, double progress_interval_s) {
  SolveSettings st;
  st.time_limit_s = time_limit_s;
  st.relative_gap = relative_gap;
  st.threads = threads;
  st.max_nodes = max_nodes;
  st.search = search;
  st.diagnosis_time_limit_s = diagnosis_time_limit_s;
  st.log_level = log_level;
  st.random_seed = random_seed;
  st.check = check;
  st.progress_interval_s = progress_interval_s;
  return st;
}
/// @throws std::invalid_argument naming the keyword and value.
void ApplySettings(const SolveSettings& settings, transcription::SolveScheduleOptions* options);

/// Build settings by keyword (scheme, formulation, encoding names).
/// @throws std::invalid_argument naming the keyword and listing the names.
void ApplyBuildSettings(const std::optional<std::string>& scheme,
                        const std::optional<std::string>& formulation,
                        const std::optional<std::string>& encoding,
                        transcription::BuildOptions* build);

/// A schedule MILP built for a problem, which users may extend (rows,
/// columns, objective terms) before solving it again.
struct BuiltSchedule {
  ProblemContext ctx;
  std::shared_ptr<transcription::ScheduleMilp> milp;
  /// The problem's own solve settings (a scenario's solver section).
  transcription::SolveScheduleOptions options;
  std::optional<transcription::ConjunctionSolveOptions> conjunction;
  bool modified = false;
};
/// Solves as ts.solve does. A modified MILP is handed whole to CBC unless
/// `search` is given true (the problem-aware search restricts and rebuilds
/// MILPs from the problem, without the user's rows).
std::shared_ptr<SolveOutcome> SolveBuiltSchedule(const BuiltSchedule& built,
                                                 const SolveSettings& settings,
                                                 py::object callback);

/// Burns from thruster names and times (validated: known names, finite
/// times, end >= start); `what` names the source in messages.
std::vector<transcription::Burn> BurnsFromColumns(const ProblemContext& ctx,
                                                  const std::vector<std::string>& thrusters,
                                                  const std::vector<double>& start_s,
                                                  const std::vector<double>& end_s);

}  // namespace thrustsched::python

#endif  // THRUSTSCHED_PYTHON_BINDINGS_H_
