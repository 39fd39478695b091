#include "app/min_time_report.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "app/format_units.h"
#include "app/outputs.h"
#include "common/format.h"

namespace thrustsched::app {
namespace {

using milp::SolveStatus;

// The schedule result's status (the file comment).
SolveStatus CombinedStatus(const transcription::MinTimeResult& r,
                           const transcription::MinTimeSpec& spec) {
  if (r.time_status != SolveStatus::kOptimal) return r.time_status;
  if (!spec.minimise_fuel_after) return SolveStatus::kOptimal;
  if (r.fuel_solve && r.fuel_solve->has_solution()) return r.fuel_solve->status;
  return SolveStatus::kFeasible;
}

nlohmann::json VectorOrNulls(const Eigen::VectorXd& v) {
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < v.size(); ++i) a.push_back(FiniteOrNull(v[i]));
  return a;
}

}  // namespace

transcription::MinTimeResult SolveScenarioMinTime(const Scenario& scenario,
                                                  const milp::Solver& solver,
                                                  transcription::SolveScheduleOptions options) {
  options.check = scenario.check;
  options.check.nonlinear = nullptr;
  options.check.nonlinear_default = false;
  return transcription::SolveMinTime(scenario.problem, *scenario.min_time, solver, options);
}

transcription::ScheduleResult MinTimeScheduleResult(const transcription::MinTimeResult& r,
                                                    const transcription::MinTimeSpec& spec) {
  transcription::ScheduleResult out;
  out.stats = r.stats;
  const bool fuel_found = r.fuel_solve && r.fuel_solve->has_solution();
  out.solve = fuel_found ? *r.fuel_solve : r.time_solve;
  if (fuel_found) {
    // The first incumbent of the whole solve is the first MILP's.
    out.solve.incumbents = r.time_solve.incumbents;
    out.solve.wall_seconds += r.time_solve.wall_seconds;
    out.solve.nodes += r.time_solve.nodes;
  } else if (r.has_schedule()) {
    out.solve.objective = r.fuel;
    out.solve.best_bound = std::numeric_limits<double>::quiet_NaN();
    out.solve.gap = std::numeric_limits<double>::quiet_NaN();
    if (r.fuel_solve) out.solve.wall_seconds += r.fuel_solve->wall_seconds;
  }
  out.solve.status = CombinedStatus(r, spec);
  out.schedule = r.schedule;
  out.infeasibility_reasons = r.infeasibility_reasons;
  return out;
}

nlohmann::json MinTimeJson(const transcription::MinTimeResult& r,
                           const transcription::MinTimeSpec& spec) {
  nlohmann::json j;
  j["arrival_time_s"] = FiniteOrNull(r.arrival_time_s);
  j["arrival_node"] = r.has_schedule() ? nlohmann::json(r.arrival_node) : nlohmann::json(nullptr);
  j["arrival_bound_s"] = FiniteOrNull(r.arrival_bound_s);
  j["time_status"] = StatusName(r.time_status);
  j["fuel_status"] =
      r.fuel_solve ? nlohmann::json(StatusName(r.fuel_solve->status)) : nlohmann::json(nullptr);
  j["fuel"] = FiniteOrNull(r.fuel);
  j["arrival_error"] = FiniteOrNull(r.arrival_error);
  j["verified"] = r.verified();
  j["hold"] = spec.hold;
  j["fuel_budget"] = FiniteOrNull(spec.fuel_budget);
  j["target"] = VectorOrNulls(spec.target);
  j["tolerance"] = VectorOrNulls(spec.tolerance);
  j["candidate_nodes"] = r.candidate_nodes;
  j["indicator_rows"] = r.indicator_rows;
  j["big_m_max"] = FiniteOrNull(r.big_m_max);
  j["time_nodes"] = r.time_solve.nodes;
  j["time_solve_seconds"] = FiniteOrNull(r.time_solve.wall_seconds);
  return j;
}

void PrintMinTime(std::ostream& os, const transcription::MinTimeResult& r) {
  os << "arrival       ";
  if (!r.has_schedule()) {
    os << "none found (" << StatusName(r.time_status) << ")";
    if (std::isfinite(r.arrival_bound_s))
      os << ", not before " << common::FormatG(r.arrival_bound_s, 8) << " s";
    os << "\n";
    return;
  }
  os << "t = " << common::FormatG(r.arrival_time_s, 8) << " s (node " << r.arrival_node << "), ";
  if (r.time_status == milp::SolveStatus::kOptimal) {
    os << "proven earliest";
  } else {
    os << "bound " << common::FormatG(r.arrival_bound_s, 8) << " s";
  }
  os << "; arrival error " << common::FormatG(r.arrival_error, 3) << " (scaled), "
     << (r.verified() ? "verified" : "NOT verified") << "; " << r.candidate_nodes
     << " candidate nodes, " << r.indicator_rows << " indicator rows\n";
}

}  // namespace thrustsched::app
