#include "dynamics/geo_orbit_state.h"

#include <sstream>
#include <stdexcept>
#include <string>

namespace thrustsched::dynamics {

Eigen::VectorXd RelativeStateFromOrbit(const GeoSimulator& sim, const OrbitState& state, double t) {
  const Epoch model_epoch = Epoch::Parse(sim.options().epoch);
  const double t_state = state.epoch.SecondsSince(model_epoch);
  if (t_state > t) {
    std::ostringstream os;
    os << "RelativeStateFromOrbit: the state's epoch " << state.epoch.ToIso8601() << " is "
       << t_state - t << " s after the requested time " << model_epoch.PlusSeconds(t).ToIso8601()
       << " (states are only propagated forward)";
    throw std::invalid_argument(os.str());
  }
  Vector6d eci = ToModelFrame(state.rv, state.frame, model_epoch);
  if (t_state < t) {
    eci = sim.Propagate(eci, t_state, Eigen::MatrixXd::Zero(3, 1), {}, {t}).front();
  }
  return sim.RelativeFromEci(eci, t);
}

OrbitState OrbitFromRelativeState(const GeoSimulator& sim, const Eigen::VectorXd& x, double t,
                                  InertialFrame frame) {
  const Epoch model_epoch = Epoch::Parse(sim.options().epoch);
  OrbitState s;
  s.epoch = model_epoch.PlusSeconds(t);
  s.frame = frame;
  s.rv = FromModelFrame(sim.EciFromRelative(x, t), frame, model_epoch);
  return s;
}

}  // namespace thrustsched::dynamics
