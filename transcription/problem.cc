#include "transcription/problem.h"

#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/error.h"
#include "common/format.h"

namespace thrustsched::transcription {

using common::Fail;
using common::FormatG;

namespace {

bool AllFinite(const Eigen::VectorXd& v) { return v.allFinite(); }

// A conjunction's times are inside the horizon up to this fraction of its length.
constexpr double kHorizonRelativeSlack = 1e-9;

// The model, thrusters, grid and initial state.
bool ModelAndGridValid(const ScheduleProblem& p, std::string* error) {
  if (p.model == nullptr) return Fail(error, "problem.model is not set");
  const int n = p.model->num_states();
  const int m = p.thrusters.size();
  if (m == 0) return Fail(error, "problem.thrusters is empty");
  if (p.model->num_inputs() != 3) {
    return Fail(error, "problem.model takes " + std::to_string(p.model->num_inputs()) +
                           " acceleration components; thruster sets need 3 (RTN)");
  }
  if (p.grid.size() < 2) {
    return Fail(error,
                "problem.grid needs at least 2 points, got " + std::to_string(p.grid.size()));
  }
  for (size_t j = 0; j < p.grid.size(); ++j) {
    if (!std::isfinite(p.grid[j])) {
      return Fail(error, "problem.grid[" + std::to_string(j) +
                             "] is not finite: " + FormatG(p.grid[j], 10));
    }
    if (j > 0 && !(p.grid[j] > p.grid[j - 1])) {
      return Fail(error, "problem.grid is not strictly increasing at index " + std::to_string(j) +
                             ": " + FormatG(p.grid[j - 1], 10) + " then " + FormatG(p.grid[j], 10));
    }
  }
  if (p.initial_state.size() != n) {
    return Fail(error, "problem.initial_state has " + std::to_string(p.initial_state.size()) +
                           " components, the model has " + std::to_string(n) + " states");
  }
  if (!AllFinite(p.initial_state))
    return Fail(error, "problem.initial_state has non-finite values");
  return true;
}

bool ForcedOffValid(const ScheduleProblem& p, int m, std::string* error) {
  for (size_t k = 0; k < p.forced_off.size(); ++k) {
    const ForcedOff& f = p.forced_off[k];
    const std::string where = "problem.forced_off[" + std::to_string(k) + "]";
    if (f.thruster < 0 || f.thruster >= m) {
      return Fail(error, where + ".thruster " + std::to_string(f.thruster) +
                             " is not a thruster index (0.." + std::to_string(m - 1) + ")");
    }
    if (std::isnan(f.start_s) || std::isnan(f.end_s) || !(f.end_s > f.start_s)) {
      return Fail(error, where + " must have start_s < end_s, got [" + FormatG(f.start_s, 10) +
                             ", " + FormatG(f.end_s, 10) + ")");
    }
  }
  return true;
}

bool WindowValid(const ScheduleProblem& p, std::string* error) {
  if (p.window.outputs.size() != p.window.half_widths.size()) {
    return Fail(error, "window: " + std::to_string(p.window.outputs.size()) + " outputs but " +
                           std::to_string(p.window.half_widths.size()) + " half widths");
  }
  std::set<int> seen;
  for (size_t k = 0; k < p.window.outputs.size(); ++k) {
    const int o = p.window.outputs[k];
    if (o < 0 || o >= p.model->num_outputs()) {
      return Fail(error, "window.outputs[" + std::to_string(k) + "] = " + std::to_string(o) +
                             " is not an output of model " + std::string(p.model->name()) +
                             " (0.." + std::to_string(p.model->num_outputs() - 1) + ")");
    }
    if (!seen.insert(o).second) {
      return Fail(error, "window.outputs lists output " + std::to_string(o) + " twice");
    }
    const double w = p.window.half_widths[k];
    if (!std::isfinite(w) || w <= 0.0) {
      return Fail(error, "window.half_widths[" + std::to_string(k) +
                             "] must be finite and > 0, got " + FormatG(w, 10));
    }
  }
  if (!(p.window.margin >= 0.0 && p.window.margin < 1.0)) {
    return Fail(error, "window.margin must be in [0, 1), got " + FormatG(p.window.margin, 10));
  }
  if (std::isnan(p.window.enforce_from_s)) return Fail(error, "window.enforce_from_s is NaN");
  if (p.window.enabled() && p.window.enforce_from_s > p.grid.back()) {
    return Fail(error, "window.enforce_from_s = " + FormatG(p.window.enforce_from_s, 10) +
                           " s is after the horizon end " + FormatG(p.grid.back(), 10) + " s");
  }
  if (!std::isfinite(p.window.soft_penalty) || p.window.soft_penalty <= 0.0) {
    return Fail(error, "window.soft_penalty must be finite and > 0, got " +
                           FormatG(p.window.soft_penalty, 10));
  }
  if (p.window.intersample_points < 0 || p.window.intersample_points > 100) {
    return Fail(error, "window.intersample_points must be in [0, 100], got " +
                           std::to_string(p.window.intersample_points));
  }
  return true;
}

bool TerminalValid(const ScheduleProblem& p, int n, std::string* error) {
  switch (p.terminal.kind) {
    case TerminalKind::kFree:
      break;
    case TerminalKind::kFixedState:
      if (p.terminal.target.size() != n || !AllFinite(p.terminal.target)) {
        return Fail(error, "terminal.target must have " + std::to_string(n) +
                               " finite components, got " +
                               std::to_string(p.terminal.target.size()));
      }
      break;
    case TerminalKind::kStateBox:
      if (p.terminal.target.size() != n || !AllFinite(p.terminal.target)) {
        return Fail(error, "terminal.target must have " + std::to_string(n) +
                               " finite components, got " +
                               std::to_string(p.terminal.target.size()));
      }
      if (p.terminal.tolerance.size() != n) {
        return Fail(error, "terminal.tolerance must have " + std::to_string(n) +
                               " components, got " + std::to_string(p.terminal.tolerance.size()));
      }
      for (int i = 0; i < n; ++i) {
        if (std::isnan(p.terminal.tolerance[i]) || p.terminal.tolerance[i] < 0.0) {
          return Fail(error, "terminal.tolerance[" + std::to_string(i) +
                                 "] must be >= 0 (or infinite), got " +
                                 FormatG(p.terminal.tolerance[i], 10));
        }
      }
      break;
    case TerminalKind::kStationKeepingSets:
      if (p.terminal.facets_out_of_plane < 3 || p.terminal.facets_cone_plus < 3 ||
          p.terminal.facets_cone_minus < 3) {
        return Fail(error, "terminal facets must be >= 3, got " +
                               std::to_string(p.terminal.facets_out_of_plane) + ", " +
                               std::to_string(p.terminal.facets_cone_plus) + ", " +
                               std::to_string(p.terminal.facets_cone_minus));
      }
      for (double t : p.terminal.lookahead_s) {
        if (!std::isfinite(t) || t < 0.0) {
          return Fail(
              error, "terminal.lookahead_s entries must be finite and >= 0, got " + FormatG(t, 10));
        }
      }
      if (!(p.terminal.margin >= 0.0 && p.terminal.margin < 1.0)) {
        return Fail(error,
                    "terminal.margin must be in [0, 1), got " + FormatG(p.terminal.margin, 10));
      }
      if (p.window.outputs.size() < 2) {
        return Fail(error, "terminal station-keeping sets need a window on two outputs");
      }
      break;
  }
  return true;
}

// The objective's burn-start penalty and the impulse bounds.
bool ObjectiveAndImpulsesValid(const ScheduleProblem& p, int m, std::string* error) {
  if (!std::isfinite(p.objective.burn_start_penalty) || p.objective.burn_start_penalty < 0.0) {
    return Fail(error, "objective.burn_start_penalty must be finite and >= 0, got " +
                           FormatG(p.objective.burn_start_penalty, 10));
  }
  if (std::isnan(p.max_impulse_m_s) || p.max_impulse_m_s <= 0.0) {
    return Fail(error,
                "problem.max_impulse_m_s must be > 0, got " + FormatG(p.max_impulse_m_s, 10));
  }
  if (!p.max_impulse_per_thruster_m_s.empty()) {
    if (static_cast<int>(p.max_impulse_per_thruster_m_s.size()) != m) {
      return Fail(error, "problem.max_impulse_per_thruster_m_s needs " + std::to_string(m) +
                             " entries (one per thruster), got " +
                             std::to_string(p.max_impulse_per_thruster_m_s.size()));
    }
    for (double v : p.max_impulse_per_thruster_m_s) {
      if (std::isnan(v) || v < 0.0) {
        return Fail(error, "problem.max_impulse_per_thruster_m_s entries must be >= 0, got " +
                               FormatG(v, 10));
      }
    }
  }
  return true;
}

// The conjunction (if any) against the model and the horizon.
bool ConjunctionValid(const ScheduleProblem& p, int n, std::string* error) {
  if (!p.conjunction->IsValid(error)) return false;
  if (n != 6) {
    return Fail(error, "conjunction: needs a model with the 6-component relative state, got " +
                           std::to_string(n) + " states");
  }
  const double t0 = p.grid.front(), tf = p.grid.back();
  const double tol = kHorizonRelativeSlack * (tf - t0);
  auto inside = [&](double t) { return std::isnan(t) || (t >= t0 - tol && t <= tf + tol); };
  if (!inside(p.conjunction->state_time_s)) {
    return Fail(error, "conjunction.state_time_s " + FormatG(p.conjunction->state_time_s, 10) +
                           " s is outside the horizon [" + FormatG(t0, 10) + ", " +
                           FormatG(tf, 10) + "] s");
  }
  if (!inside(p.conjunction->check_start_s) || !inside(p.conjunction->check_end_s)) {
    return Fail(error, "conjunction check window [" + FormatG(p.conjunction->check_start_s, 10) +
                           ", " + FormatG(p.conjunction->check_end_s, 10) +
                           "] s is not inside the horizon [" + FormatG(t0, 10) + ", " +
                           FormatG(tf, 10) + "] s");
  }
  const double a = std::isnan(p.conjunction->check_start_s) ? t0 : p.conjunction->check_start_s;
  const double b = std::isnan(p.conjunction->check_end_s) ? tf : p.conjunction->check_end_s;
  if (!(b > a)) {
    return Fail(error, "conjunction check window [" + FormatG(a, 10) + ", " + FormatG(b, 10) +
                           "] s is empty");
  }
  return true;
}

// The path constraints on the state against the model and the horizon.
bool StateConstraintsValid(const ScheduleProblem& p, int n, std::string* error) {
  if (p.state_constraints.empty()) return true;
  if (p.input_mode != InputMode::kOnOff) {
    return Fail(error, "state_constraints: only in the on-off input mode");
  }
  const double t0 = p.grid.front(), tf = p.grid.back();
  const double tol = kHorizonRelativeSlack * (tf - t0);
  std::set<std::string> names;
  for (size_t k = 0; k < p.state_constraints.size(); ++k) {
    const StateConstraint& c = p.state_constraints[k];
    const std::string field = "state_constraints[" + std::to_string(k) + "]";
    if (!names.insert(c.name.empty() ? std::to_string(k) : c.name).second) {
      return Fail(error, field + ".name \"" + c.name + "\" is used twice (as a name or an index)");
    }
    if (!std::isfinite(c.t_s) || c.t_s < t0 - tol || c.t_s > tf + tol) {
      return Fail(error, field + ".t_s " + FormatG(c.t_s, 10) + " s is outside the horizon [" +
                             FormatG(t0, 10) + ", " + FormatG(tf, 10) + "] s");
    }
    if (c.a.size() != n || !AllFinite(c.a)) {
      return Fail(error, field + ".a must have " + std::to_string(n) + " finite entries, got " +
                             std::to_string(c.a.size()));
    }
    if (std::isnan(c.lower) || std::isnan(c.upper) || c.lower > c.upper ||
        c.lower == std::numeric_limits<double>::infinity() ||
        c.upper == -std::numeric_limits<double>::infinity() ||
        (!std::isfinite(c.lower) && !std::isfinite(c.upper))) {
      return Fail(error, field + ": bounds [" + FormatG(c.lower, 10) + ", " + FormatG(c.upper, 10) +
                             "] must be ordered, one of them finite");
    }
  }
  return true;
}

}  // namespace

std::string_view ToString(ObjectiveKind kind) {
  switch (kind) {
    case ObjectiveKind::kL1:
      return "l1";
    case ObjectiveKind::kDeltaV:
      return "delta_v";
    case ObjectiveKind::kPropellant:
      return "propellant";
  }
  return "unknown";
}

ObjectiveKind ParseObjectiveKind(std::string_view name) {
  if (name == "l1") return ObjectiveKind::kL1;
  if (name == "delta_v") return ObjectiveKind::kDeltaV;
  if (name == "propellant") return ObjectiveKind::kPropellant;
  throw std::invalid_argument("objective: unknown kind \"" + std::string(name) +
                              "\" (expected l1, delta_v or propellant)");
}

bool ScheduleProblem::IsValid(std::string* error) const {
  if (!ModelAndGridValid(*this, error)) return false;
  const int n = model->num_states();
  const int m = thrusters.size();
  if (!rules.IsValid(error)) return false;
  if (!history.IsValid(m, error)) return false;
  if (!ForcedOffValid(*this, m, error)) return false;
  if (!WindowValid(*this, error)) return false;
  if (!TerminalValid(*this, n, error)) return false;
  if (!ObjectiveAndImpulsesValid(*this, m, error)) return false;
  if (conjunction && !conjunction->IsValid(error)) return false;
  if (conjunction && !ConjunctionValid(*this, n, error)) return false;
  return StateConstraintsValid(*this, n, error);
}

}  // namespace thrustsched::transcription
