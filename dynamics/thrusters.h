// Thruster sets: what a firing does (direction, thrust, Isp), independent of
// when it fires.
//
//   auto anzel = dynamics::ThrusterSet::Anzel4(/*thrust_n=*/0.265, /*mass_kg=*/4850,
//                                              /*isp_s=*/2005);   // NE, SE, NW, SW
//   auto ideal = dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005);  // +R,+T,+N,-R,-T,-N
//   Eigen::MatrixXd u = anzel.AccelerationMatrix();   // 3 x 4, m/s^2 per thruster, RTN
//   double l1 = anzel.L1Factor(0);                    // ||Gamma_NE||_1 = 1.44296 F/m
//
// Directions are unit vectors in the local RTN frame (R radial outward,
// T along-track, N orbit normal). Anzel layout (Gazzino 2018, eqs. (1.72)-(1.77)):
// every thruster pushes toward the Earth; the North-located ones push South,
// the East-located ones push West.
#ifndef THRUSTSCHED_DYNAMICS_THRUSTERS_H_
#define THRUSTSCHED_DYNAMICS_THRUSTERS_H_

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace thrustsched::dynamics {

struct Thruster {
  std::string name;
  Eigen::Vector3d direction;  // unit vector, RTN
  bool enabled = true;
};

class ThrusterSet {
 public:
  /// Empty set (size() == 0); assign a real set before use.
  ThrusterSet() = default;
  /// @throws std::invalid_argument if thrust, mass or isp is not finite and
  ///         > 0, a direction is not finite or has zero norm (it is
  ///         normalised otherwise), names repeat or the list is empty.
  ThrusterSet(std::vector<Thruster> thrusters, double thrust_n, double mass_kg, double isp_s);

  /// Thesis layout: deviation theta from the N-S axis, deflection alpha in the
  /// R-T plane, order NE, SE, NW, SW.
  static ThrusterSet Anzel4(double thrust_n, double mass_kg, double isp_s, double theta_deg = 63.64,
                            double alpha_deg = 7.03);
  /// One thruster per face, order +R, +T, +N, -R, -T, -N.
  static ThrusterSet Ideal6(double thrust_n, double mass_kg, double isp_s);
  /// Preset by name: "anzel4" or "ideal6". @throws std::invalid_argument naming it.
  static ThrusterSet FromPreset(std::string_view preset, double thrust_n, double mass_kg,
                                double isp_s, double theta_deg = 63.64, double alpha_deg = 7.03);

  /// Keeps only the named thrusters, in the given order.
  /// @throws std::invalid_argument naming an unknown thruster.
  ThrusterSet Subset(const std::vector<std::string>& names) const;
  /// Marks thrusters disabled (they stay in the set; schedules force them off).
  /// @throws std::invalid_argument naming an unknown thruster.
  void Disable(const std::vector<std::string>& names);

  int size() const { return static_cast<int>(thrusters_.size()); }
  const Thruster& thruster(int i) const { return thrusters_.at(i); }
  const std::vector<Thruster>& thrusters() const { return thrusters_; }
  /// @throws std::invalid_argument naming an unknown thruster.
  int IndexOf(std::string_view name) const;
  std::vector<std::string> names() const;

  double thrust_n() const { return thrust_n_; }
  double mass_kg() const { return mass_kg_; }
  double isp_s() const { return isp_s_; }
  /// F / m (m/s^2): the Euclidean acceleration of any thruster when on.
  double acceleration() const { return thrust_n_ / mass_kg_; }
  /// Thesis L1 cost factor ||Gamma_i||_1 = (F/m) ||d_i||_1 (m/s^2).
  double L1Factor(int i) const;
  /// 3 x size(): column i = (F/m) d_i, m/s^2 in RTN (disabled ones included).
  Eigen::MatrixXd AccelerationMatrix() const;
  /// Propellant mass flow of one thruster when on: F / (g0 Isp), kg/s.
  double MassFlow() const;

 private:
  std::vector<Thruster> thrusters_;
  double thrust_n_ = 0.0, mass_kg_ = 0.0, isp_s_ = 0.0;
};

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_THRUSTERS_H_
