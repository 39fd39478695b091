// The state of a Gauss-equation propagation with the mass (the feedback's and
// PropagateGauss'): the scaled equinoctial elements (p, ex, ey, hx, hy, L),
// then the mass (kg), as the array internal::Integrate steps.
//
//   internal::ElementsMassState y = internal::ElementsMassStateOf(x0, mass_kg);
//   auto rhs = [&](const internal::ElementsMassState& y, internal::ElementsMassState& dy, double) {
//     internal::ElementsMassRates(y, command, thrust, flow, force_model, units, dy);
//   };
//
// thrust and flow (mass flow at full thrust) are in ScaledUnits; the command
// is the thrust in QSW as a fraction of the maximum (norm <= 1). Not
// installed: only transfer/ uses it.
#ifndef THRUSTSCHED_TRANSFER_INTERNAL_ELEMENTS_MASS_H_
#define THRUSTSCHED_TRANSFER_INTERNAL_ELEMENTS_MASS_H_

#include <array>

#include <Eigen/Core>

#include "transfer/force_model.h"

namespace thrustsched::transfer::internal {

using ElementsMassState = std::array<double, 7>;

inline Vector6 ElementsOf(const ElementsMassState& y) {
  Vector6 x;
  for (int i = 0; i < 6; ++i) x(i) = y[i];
  return x;
}

inline ElementsMassState ElementsMassStateOf(const Vector6& x, double mass_kg) {
  ElementsMassState y{};
  for (int i = 0; i < 6; ++i) y[i] = x(i);
  y[6] = mass_kg;
  return y;
}

// The Gauss equations under the command, and the mass flow it costs.
inline void ElementsMassRates(const ElementsMassState& y, const Eigen::Vector3d& command,
                              double thrust, double flow, const ForceModel& f, const ScaledUnits& u,
                              ElementsMassState& dy) {
  const Vector6 dx = GaussRates(ElementsOf(y), thrust / y[6] * command, f, u);
  for (int i = 0; i < 6; ++i) dy[i] = dx(i);
  dy[6] = -flow * command.norm();
}

}  // namespace thrustsched::transfer::internal

#endif  // THRUSTSCHED_TRANSFER_INTERNAL_ELEMENTS_MASS_H_
