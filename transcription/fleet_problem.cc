// FleetProblem's validation and small helpers (transcription/fleet.h).
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "common/format.h"
#include "transcription/fleet.h"

namespace thrustsched::transcription {
namespace {

using common::FormatG;

bool Fail(std::string* error, std::string message) {
  if (error != nullptr) *error = std::move(message);
  return false;
}

bool ValidMember(const FleetProblem& /*fleet*/, int index, int count, const std::string& field,
                 bool allow_none, std::string* error) {
  if ((allow_none && index == -1) || (index >= 0 && index < count)) return true;
  return Fail(error, field + ": no member " + std::to_string(index) + " (the fleet has " +
                         std::to_string(count) + ")");
}

bool ValidMap(const Eigen::MatrixXd& map, int n, const std::string& field, std::string* error) {
  if (map.rows() < 1 || map.cols() != n) {
    return Fail(error, field + ".map: " + std::to_string(map.rows()) + " x " +
                           std::to_string(map.cols()) + ", expected rows x " + std::to_string(n) +
                           " (the members' state size)");
  }
  if (!map.allFinite()) return Fail(error, field + ".map: not finite");
  return true;
}

bool ValidVector(const Eigen::VectorXd& v, int rows, const std::string& field, std::string* error) {
  if (v.size() != rows) {
    return Fail(error, field + ": " + std::to_string(v.size()) + " entries, expected " +
                           std::to_string(rows) + " (the map's rows)");
  }
  if (!v.allFinite()) return Fail(error, field + ": not finite");
  return true;
}

bool ValidCovariance(const Eigen::MatrixXd& c, int n, const std::string& field,
                     std::string* error) {
  if (c.size() == 0) return true;
  if (c.rows() != n || c.cols() != n) {
    return Fail(error, field + ": " + std::to_string(c.rows()) + " x " + std::to_string(c.cols()) +
                           ", expected " + std::to_string(n) + " x " + std::to_string(n));
  }
  if (!c.allFinite()) return Fail(error, field + ": not finite");
  const double scale = c.cwiseAbs().maxCoeff();
  if ((c - c.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale)
    return Fail(error, field + ": not symmetric");
  const double lowest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(c).eigenvalues().minCoeff();
  if (lowest < -1e-12 * scale) {
    return Fail(error,
                field + ": not positive semi-definite (eigenvalue " + FormatG(lowest, 6) + ")");
  }
  return true;
}

bool ValidMembers(const FleetProblem& f, std::string* error) {
  if (f.members.empty()) return Fail(error, "members: empty");
  std::set<std::string> names;
  const ScheduleProblem& first = f.members[0].problem;
  for (size_t k = 0; k < f.members.size(); ++k) {
    const std::string field = "members[" + std::to_string(k) + "]";
    const FleetMember& m = f.members[k];
    if (m.name.empty()) return Fail(error, field + ".name: empty");
    if (!names.insert(m.name).second)
      return Fail(error, field + ".name: '" + m.name + "' repeated");
    std::string why;
    if (!m.problem.IsValid(&why)) return Fail(error, field + "." + why);
    if (m.problem.input_mode != InputMode::kOnOff) {
      return Fail(error, field + ".input_mode: the fleet needs on-off members");
    }
    if (m.problem.model->num_states() != first.model->num_states()) {
      return Fail(error, field + ".model: " + std::to_string(m.problem.model->num_states()) +
                             " states, members[0] has " +
                             std::to_string(first.model->num_states()));
    }
    if (!ValidCovariance(m.initial_covariance, m.problem.model->num_states(),
                         field + ".initial_covariance", error)) {
      return false;
    }
    if (m.problem.grid.size() != first.grid.size()) {
      return Fail(error, field + ".grid: " + std::to_string(m.problem.num_intervals()) +
                             " intervals, members[0] has " + std::to_string(first.num_intervals()));
    }
    for (size_t j = 0; j < first.grid.size(); ++j) {
      const double tol = 1e-9 * std::max(1.0, std::abs(first.grid[j]));
      if (std::abs(m.problem.grid[j] - first.grid[j]) > tol) {
        return Fail(error, field + ".grid[" + std::to_string(j) +
                               "]: " + FormatG(m.problem.grid[j], 12) + " s, members[0] has " +
                               FormatG(first.grid[j], 12) + " s");
      }
    }
  }
  return true;
}

bool ValidCouplings(const FleetProblem& f, int n, std::string* error) {
  const int count = static_cast<int>(f.members.size());
  for (size_t c = 0; c < f.couplings.size(); ++c) {
    const std::string field = "couplings[" + std::to_string(c) + "]";
    const TerminalCoupling& t = f.couplings[c];
    if (!ValidMember(f, t.member, count, field + ".member", false, error) ||
        !ValidMember(f, t.reference, count, field + ".reference", true, error) ||
        !ValidMap(t.map, n, field, error) ||
        !ValidVector(t.offset, static_cast<int>(t.map.rows()), field + ".offset", error)) {
      return false;
    }
    if (t.reference == t.member) return Fail(error, field + ".reference: the member itself");
    if (t.tolerance.size() != 0) {
      if (!ValidVector(t.tolerance, static_cast<int>(t.map.rows()), field + ".tolerance", error))
        return false;
      if ((t.tolerance.array() < 0.0).any()) return Fail(error, field + ".tolerance: negative");
    }
  }
  return true;
}

bool ValidAssignment(const FleetProblem& f, int n, std::string* error) {
  if (!f.assignment) return true;
  const SlotAssignment& a = *f.assignment;
  const int count = static_cast<int>(f.members.size());
  if (a.members.empty()) return Fail(error, "assignment.members: empty");
  if (a.slots.size() != a.members.size()) {
    return Fail(error, "assignment.slots: " + std::to_string(a.slots.size()) + " slots for " +
                           std::to_string(a.members.size()) + " members");
  }
  if (!ValidMember(f, a.reference, count, "assignment.reference", true, error) ||
      !ValidMap(a.map, n, "assignment", error)) {
    return false;
  }
  if (a.tolerance.size() != 0) {
    if (!ValidVector(a.tolerance, static_cast<int>(a.map.rows()), "assignment.tolerance", error))
      return false;
    if ((a.tolerance.array() < 0.0).any()) return Fail(error, "assignment.tolerance: negative");
  }
  std::set<int> seen;
  for (size_t i = 0; i < a.members.size(); ++i) {
    const std::string field = "assignment.members[" + std::to_string(i) + "]";
    if (!ValidMember(f, a.members[i], count, field, false, error)) return false;
    if (a.members[i] == a.reference) return Fail(error, field + ": the reference itself");
    if (!seen.insert(a.members[i]).second) return Fail(error, field + ": repeated");
    if (!ValidVector(a.slots[i], static_cast<int>(a.map.rows()),
                     "assignment.slots[" + std::to_string(i) + "]", error))
      return false;
  }
  return true;
}

}  // namespace

std::string_view ToString(FuelBalanceKind kind) {
  switch (kind) {
    case FuelBalanceKind::kNone:
      return "none";
    case FuelBalanceKind::kMaxExcessOverMean:
      return "max_excess_over_mean";
    case FuelBalanceKind::kMinMax:
      return "min_max";
  }
  return "?";
}

FuelBalanceKind ParseFuelBalanceKind(std::string_view name) {
  for (FuelBalanceKind k :
       {FuelBalanceKind::kNone, FuelBalanceKind::kMaxExcessOverMean, FuelBalanceKind::kMinMax}) {
    if (name == ToString(k)) return k;
  }
  throw std::invalid_argument("fuel balance '" + std::string(name) +
                              "': expected none, max_excess_over_mean or min_max");
}

int FleetProblem::MemberIndex(std::string_view name) const {
  for (size_t k = 0; k < members.size(); ++k) {
    if (members[k].name == name) return static_cast<int>(k);
  }
  return -1;
}

bool FleetProblem::HasInitialCovariance() const {
  for (const FleetMember& m : members)
    if (m.initial_covariance.size() != 0) return true;
  return false;
}

bool FleetProblem::IsValid(std::string* error) const {
  if (!ValidMembers(*this, error)) return false;
  const int n = members[0].problem.model->num_states();
  if (position_map.size() != 0 &&
      (position_map.rows() != 3 || position_map.cols() != n || !position_map.allFinite())) {
    return Fail(error, "position_map: " + std::to_string(position_map.rows()) + " x " +
                           std::to_string(position_map.cols()) + ", expected finite 3 x " +
                           std::to_string(n));
  }
  if (position_map.size() == 0 && n < 3 &&
      members[0].problem.model->LocalPositionMap(members[0].problem.grid.front()).size() == 0) {
    return Fail(error,
                "position_map: empty and the state has " + std::to_string(n) + " components (< 3)");
  }
  if (position_map.size() == 0) {  // the models' local frames must be one frame
    const double t0 = members[0].problem.grid.front();
    const Eigen::MatrixXd first = members[0].problem.model->LocalPositionMap(t0);
    for (size_t k = 1; k < members.size(); ++k) {
      const Eigen::MatrixXd local = members[k].problem.model->LocalPositionMap(t0);
      const bool same =
          local.rows() == first.rows() && local.cols() == first.cols() &&
          (first.size() == 0 || (local - first).cwiseAbs().maxCoeff() <=
                                    1e-12 * std::max(1.0, first.cwiseAbs().maxCoeff()));
      if (!same) {
        return Fail(error, "members[" + std::to_string(k) +
                               "].problem.model: its local position frame differs from "
                               "members[0]'s (co-located members share one station point)");
      }
    }
  }
  if (!ValidCouplings(*this, n, error) || !ValidAssignment(*this, n, error)) return false;
  if (balance.kind == FuelBalanceKind::kMaxExcessOverMean &&
      !(balance.max_excess_fraction >= 0.0 && std::isfinite(balance.max_excess_fraction))) {
    return Fail(error, "balance.max_excess_fraction: " + FormatG(balance.max_excess_fraction, 10) +
                           " (must be finite and >= 0)");
  }
  if (balance.kind == FuelBalanceKind::kMinMax &&
      !(balance.sum_weight >= 0.0 && std::isfinite(balance.sum_weight))) {
    return Fail(error, "balance.sum_weight: " + FormatG(balance.sum_weight, 10) +
                           " (must be finite and >= 0)");
  }
  if (keep_out) {
    if (members.size() < 2) return Fail(error, "keep_out: needs two members or more");
    if (!(keep_out->half_size_m > 0.0 && std::isfinite(keep_out->half_size_m))) {
      return Fail(error, "keep_out.half_size_m: " + FormatG(keep_out->half_size_m, 10) +
                             " (must be finite and > 0)");
    }
    if (!(keep_out->instantaneous_threshold >= 0.0 && keep_out->instantaneous_threshold < 0.5)) {
      return Fail(error, "keep_out.instantaneous_threshold: " +
                             FormatG(keep_out->instantaneous_threshold, 10) +
                             " (must be in [0, 0.5); 0: no margin)");
    }
    const std::vector<double>& grid = members[0].problem.grid;
    const std::vector<double>& t = keep_out->check_times_s;
    if (t.empty()) return Fail(error, "keep_out.check_times_s: empty");
    for (size_t i = 0; i < t.size(); ++i) {
      if (!(t[i] >= grid.front() && t[i] <= grid.back()) || (i > 0 && t[i] < t[i - 1])) {
        return Fail(error, "keep_out.check_times_s[" + std::to_string(i) +
                               "]: " + FormatG(t[i], 12) + " s (sorted, within [" +
                               FormatG(grid.front(), 12) + ", " + FormatG(grid.back(), 12) +
                               "] s)");
      }
    }
  }
  return true;
}

Eigen::MatrixXd FleetPositionMap(const FleetProblem& fleet, int k, double t) {
  if (fleet.position_map.size() != 0) return fleet.position_map;
  const dynamics::LinearModel& model = *fleet.members.at(k).problem.model;
  Eigen::MatrixXd local = model.LocalPositionMap(t);
  if (local.size() != 0) return local;
  return Eigen::MatrixXd::Identity(3, model.num_states());
}

std::vector<Eigen::MatrixXd> FleetPositionMaps(const FleetProblem& fleet, int k,
                                               const std::vector<double>& times) {
  const bool constant =
      fleet.position_map.size() != 0 ||
      fleet.members.at(k).problem.model->LocalPositionMap(times.front()).size() == 0;
  if (constant) return {FleetPositionMap(fleet, k, times.front())};
  std::vector<Eigen::MatrixXd> out;
  for (double t : times) out.push_back(FleetPositionMap(fleet, k, t));
  return out;
}

Eigen::Vector3d FleetPosition(const FleetProblem& fleet, int k, double t,
                              const Eigen::VectorXd& state) {
  return FleetPositionMap(fleet, k, t) * state;
}

}  // namespace thrustsched::transcription
