// Thruster geometry of the long-horizon loop: which faces a thruster pushes
// along, its diametrically opposite thruster (the failure rule of Gazzino
// 2018 sec. 5.3.7, after Gopinath & Srinivasamurthy 2003), and whether the
// available thrusters can still control inclination and longitude drift.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "planning/long_horizon.h"

namespace thrustsched::planning {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDirectionTolerance = 1e-6;

}  // namespace

int OppositeThruster(const dynamics::ThrusterSet& thrusters, int thruster) {
  if (thruster < 0 || thruster >= thrusters.size()) {
    throw std::invalid_argument("OppositeThruster: thruster index " + std::to_string(thruster) +
                                " out of range (0.." + std::to_string(thrusters.size() - 1) + ")");
  }
  const Eigen::Vector3d d = thrusters.thruster(thruster).direction;
  int best = -1;
  double best_r = kInf;
  for (int j = 0; j < thrusters.size(); ++j) {
    if (j == thruster) continue;
    const Eigen::Vector3d s = d + thrusters.thruster(j).direction;
    if (std::abs(s(1)) > kDirectionTolerance || std::abs(s(2)) > kDirectionTolerance) continue;
    if (std::abs(s(0)) < best_r) {
      best_r = std::abs(s(0));
      best = j;
    }
  }
  if (best < 0) {
    throw std::invalid_argument("OppositeThruster: no thruster is diametrically opposite to " +
                                thrusters.thruster(thruster).name +
                                " (none has its along-track and normal components reversed)");
  }
  return best;
}

ThrusterFaces FacesOf(const dynamics::Thruster& thruster) {
  const Eigen::Vector3d& d = thruster.direction;
  ThrusterFaces f;
  f.north = d(2) < -kDirectionTolerance;
  f.south = d(2) > kDirectionTolerance;
  f.east = d(1) < -kDirectionTolerance;
  f.west = d(1) > kDirectionTolerance;
  return f;
}

Controllability CheckControllability(const dynamics::ThrusterSet& thrusters,
                                     const std::vector<bool>& available) {
  if (static_cast<int>(available.size()) != thrusters.size()) {
    throw std::invalid_argument("CheckControllability: available has " +
                                std::to_string(available.size()) + " entries for " +
                                std::to_string(thrusters.size()) + " thrusters");
  }
  bool plus_n = false, minus_n = false, plus_t = false, minus_t = false;
  std::string names;
  for (int i = 0; i < thrusters.size(); ++i) {
    if (!available[i]) continue;
    const Eigen::Vector3d& d = thrusters.thruster(i).direction;
    plus_n = plus_n || d(2) > kDirectionTolerance;
    minus_n = minus_n || d(2) < -kDirectionTolerance;
    plus_t = plus_t || d(1) > kDirectionTolerance;
    minus_t = minus_t || d(1) < -kDirectionTolerance;
    names += (names.empty() ? "" : ", ") + thrusters.thruster(i).name;
  }
  std::vector<std::string> missing;
  if (!plus_n) missing.push_back("north (+N)");
  if (!minus_n) missing.push_back("south (-N)");
  if (!plus_t) missing.push_back("east (+T)");
  if (!minus_t) missing.push_back("west (-T)");
  Controllability c;
  if (missing.empty()) return c;
  c.controllable = false;
  c.reason = "uncontrollable: no available thruster pushes ";
  for (size_t k = 0; k < missing.size(); ++k) c.reason += (k ? ", " : "") + missing[k];
  c.reason += "; available: " + (names.empty() ? std::string("none") : names);
  return c;
}

}  // namespace thrustsched::planning
