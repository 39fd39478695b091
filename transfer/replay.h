// Independent re-propagation of a low-thrust transfer in Cartesian
// coordinates: the two-body problem with thrust and mass (Bombrun 2007,
// (1.23)-(1.26)) integrated on position, velocity and mass, with the thrust
// direction given in the local QSW frame, and the final orbit read with the
// classical-element conversion of dynamics/keplerian.h. Nothing of the Gauss
// equations (transfer/equinoctial.h) is used, so an error there shows here;
// with the problem's force_model j2 the J2 acceleration is added in its
// Cartesian form (the gradient of the zonal potential), independently of
// the QSW form of transfer/force_model.h.
//
//   transfer::MinTimeSolution s = transfer::SolveMinTime(p, guess);
//   transfer::ReplayResult r = transfer::ReplaySamples(p, s.trajectory, s.duration_s);
//   // r.final_a_m, r.final_e, r.final_i_rad, r.final_mass_kg against s.final_elements
//
// The dynamics/ GEO simulator is not used: it models GEO perturbations
// around a station, not a two-body transfer from GTO.
#ifndef THRUSTSCHED_TRANSFER_REPLAY_H_
#define THRUSTSCHED_TRANSFER_REPLAY_H_

#include <functional>
#include <vector>

#include "dynamics/orbital_elements.h"
#include "transfer/min_time_shooting.h"

namespace thrustsched::transfer {

/// Thrust command at time t (s) and Cartesian state (m, m/s, kg): the thrust
/// in QSW as a fraction of the maximum thrust (norm <= 1).
using QswCommand =
    std::function<Eigen::Vector3d(double t_s, const dynamics::Vector6d& rv, double mass_kg)>;

/// One accepted integration step of the replay.
struct ReplayState {
  double t_s = 0.0;
  dynamics::Vector6d rv = dynamics::Vector6d::Zero();  // m, m/s
  double mass_kg = 0.0;
};

struct ReplayResult {
  /// The start and every accepted step (at most 0.25 h apart), for plots
  /// and ephemerides; the last one is the final state.
  std::vector<ReplayState> states;
  dynamics::Vector6d final_rv = dynamics::Vector6d::Zero();
  double final_mass_kg = 0.0;
  double final_a_m = 0.0, final_e = 0.0, final_i_rad = 0.0;  // dynamics::KeplerianFromCartesian
};

/// Integrates from p.initial (its Cartesian state) for duration_s under
/// `command` (Runge-Kutta-Fehlberg 7(8), tolerance on the state scaled by
/// Mm and hours). @throws std::invalid_argument if p is invalid or
/// duration_s <= 0.
ReplayResult Replay(const MinTimeProblem& p, double duration_s, const QswCommand& command,
                    double tolerance = 1e-12);

/// The command of a sampled trajectory: the thrust directions of the samples
/// (at full thrust) interpolated by Catmull-Rom splines in time and
/// normalised. @throws std::invalid_argument with fewer than 2 samples.
QswCommand SampledCommand(const std::vector<TrajectorySample>& samples);

/// Replay(p, duration_s, SampledCommand(samples)).
ReplayResult ReplaySamples(const MinTimeProblem& p, const std::vector<TrajectorySample>& samples,
                           double duration_s, double tolerance = 1e-12);

}  // namespace thrustsched::transfer

#endif  // THRUSTSCHED_TRANSFER_REPLAY_H_
