#include "dynamics/thrusters.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <unordered_set>
#include <utility>

#include "common/constants.h"

namespace thrustsched::dynamics {
namespace {

// Standard gravity used in the definition of specific impulse (m/s^2).
using common::kDegToRad;

void RequirePositive(const char* where, const char* field, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    std::ostringstream msg;
    msg << where << ": " << field << " must be finite and > 0, got " << value;
    throw std::invalid_argument(msg.str());
  }
}

void RequireFinite(const char* where, const char* field, double value) {
  if (!std::isfinite(value)) {
    std::ostringstream msg;
    msg << where << ": " << field << " must be finite, got " << value;
    throw std::invalid_argument(msg.str());
  }
}

std::string KnownNames(const std::vector<Thruster>& thrusters) {
  std::string out;
  for (const Thruster& t : thrusters) {
    if (!out.empty()) out += ", ";
    out += "'" + t.name + "'";
  }
  return out;
}

}  // namespace

ThrusterSet::ThrusterSet(std::vector<Thruster> thrusters, double thrust_n, double mass_kg,
                         double isp_s)
    : thrusters_(std::move(thrusters)), thrust_n_(thrust_n), mass_kg_(mass_kg), isp_s_(isp_s) {
  RequirePositive("ThrusterSet", "thrust_n", thrust_n);
  RequirePositive("ThrusterSet", "mass_kg", mass_kg);
  RequirePositive("ThrusterSet", "isp_s", isp_s);
  if (thrusters_.empty()) {
    throw std::invalid_argument("ThrusterSet: the thruster list is empty");
  }
  std::unordered_set<std::string> seen;
  for (Thruster& t : thrusters_) {
    if (t.name.empty()) {
      throw std::invalid_argument("ThrusterSet: a thruster has an empty name");
    }
    if (!seen.insert(t.name).second) {
      throw std::invalid_argument("ThrusterSet: thruster name '" + t.name + "' is repeated");
    }
    if (!t.direction.allFinite()) {
      std::ostringstream msg;
      msg << "ThrusterSet: direction of thruster '" << t.name << "' is not finite: ["
          << t.direction.transpose() << "]";
      throw std::invalid_argument(msg.str());
    }
    const double norm = t.direction.norm();
    if (!(norm > 0.0)) {
      throw std::invalid_argument("ThrusterSet: direction of thruster '" + t.name +
                                  "' has zero norm");
    }
    t.direction /= norm;
  }
}

ThrusterSet ThrusterSet::Anzel4(double thrust_n, double mass_kg, double isp_s, double theta_deg,
                                double alpha_deg) {
  RequireFinite("ThrusterSet::Anzel4", "theta_deg", theta_deg);
  RequireFinite("ThrusterSet::Anzel4", "alpha_deg", alpha_deg);
  const double st = std::sin(theta_deg * kDegToRad), ct = std::cos(theta_deg * kDegToRad);
  const double sa = std::sin(alpha_deg * kDegToRad), ca = std::cos(alpha_deg * kDegToRad);
  // (1.73a-d): all push toward the Earth (-R); North-located push South (-N),
  // East-located push West (-T).
  std::vector<Thruster> list = {
      {"NE", Eigen::Vector3d(-st * ca, -st * sa, -ct), true},
      {"SE", Eigen::Vector3d(-st * ca, -st * sa, +ct), true},
      {"NW", Eigen::Vector3d(-st * ca, +st * sa, -ct), true},
      {"SW", Eigen::Vector3d(-st * ca, +st * sa, +ct), true},
  };
  return ThrusterSet(std::move(list), thrust_n, mass_kg, isp_s);
}

ThrusterSet ThrusterSet::Ideal6(double thrust_n, double mass_kg, double isp_s) {
  std::vector<Thruster> list = {
      {"+R", Eigen::Vector3d(1, 0, 0), true},  {"+T", Eigen::Vector3d(0, 1, 0), true},
      {"+N", Eigen::Vector3d(0, 0, 1), true},  {"-R", Eigen::Vector3d(-1, 0, 0), true},
      {"-T", Eigen::Vector3d(0, -1, 0), true}, {"-N", Eigen::Vector3d(0, 0, -1), true},
  };
  return ThrusterSet(std::move(list), thrust_n, mass_kg, isp_s);
}

ThrusterSet ThrusterSet::FromPreset(std::string_view preset, double thrust_n, double mass_kg,
                                    double isp_s, double theta_deg, double alpha_deg) {
  if (preset == "anzel4") return Anzel4(thrust_n, mass_kg, isp_s, theta_deg, alpha_deg);
  if (preset == "ideal6") return Ideal6(thrust_n, mass_kg, isp_s);
  throw std::invalid_argument("ThrusterSet::FromPreset: unknown preset '" + std::string(preset) +
                              "' (valid: 'anzel4', 'ideal6')");
}

int ThrusterSet::IndexOf(std::string_view name) const {
  for (int i = 0; i < size(); ++i) {
    if (thrusters_[i].name == name) return i;
  }
  throw std::invalid_argument("ThrusterSet: unknown thruster '" + std::string(name) +
                              "' (known: " + KnownNames(thrusters_) + ")");
}

ThrusterSet ThrusterSet::Subset(const std::vector<std::string>& names) const {
  std::vector<Thruster> list;
  list.reserve(names.size());
  for (const std::string& name : names) list.push_back(thrusters_[IndexOf(name)]);
  // The constructor rejects an empty list and repeated names.
  return ThrusterSet(std::move(list), thrust_n_, mass_kg_, isp_s_);
}

void ThrusterSet::Disable(const std::vector<std::string>& names) {
  std::vector<int> indices;
  indices.reserve(names.size());
  for (const std::string& name : names) indices.push_back(IndexOf(name));  // all-or-nothing
  for (int i : indices) thrusters_[i].enabled = false;
}

std::vector<std::string> ThrusterSet::names() const {
  std::vector<std::string> out;
  out.reserve(thrusters_.size());
  for (const Thruster& t : thrusters_) out.push_back(t.name);
  return out;
}

double ThrusterSet::L1Factor(int i) const {
  return acceleration() * thrusters_.at(i).direction.lpNorm<1>();
}

Eigen::MatrixXd ThrusterSet::AccelerationMatrix() const {
  Eigen::MatrixXd u(3, size());
  for (int i = 0; i < size(); ++i) u.col(i) = acceleration() * thrusters_[i].direction;
  return u;
}

double ThrusterSet::MassFlow() const {
  return thrust_n_ / (common::kStandardGravity_m_s2 * isp_s_);
}

}  // namespace thrustsched::dynamics
