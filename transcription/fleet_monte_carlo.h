// A Monte Carlo of a fleet's initial states (Serra 2015 sec. 4.4: 10^5
// samples): each member's initial state is drawn from N(x_k(t_0),
// Sigma_k) (FleetMember::initial_covariance, independent between members),
// every member flies its planned burns open loop, and a sample collides when
// some pair comes closer than the keep-out half size R (Euclidean distance,
// closest approach on each step of a fine grid, linear in between). The
// keep-out cube of half size R contains the ball of radius R, so a plan whose
// chance-constrained keep-out rows hold leaves (almost) no sample inside it.
//
// Shares no code with the fleet MILP: the paths come from adaptive
// integration of each member's continuous model (dynamics::PropagateLinear),
// the deviations from its flow (dynamics::PropagateFlow).
//
//   transcription::FleetMonteCarloOptions o;          // 100 000 samples, seed 1
//   transcription::FleetMonteCarloReport mc =
//       transcription::CheckFleetMonteCarlo(fleet, result.schedules, o);
//   std::cout << mc.collisions << " of " << mc.samples << ", closest " << mc.min_distance_m <<
//   "\n";
#ifndef THRUSTSCHED_TRANSCRIPTION_FLEET_MONTE_CARLO_H_
#define THRUSTSCHED_TRANSCRIPTION_FLEET_MONTE_CARLO_H_

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace thrustsched::transcription {

struct FleetProblem;  // transcription/fleet.h, which includes this header
struct Schedule;      // transcription/schedule_milp.h

struct FleetMonteCarloOptions {
  int samples = 100000;  // 0: none
  std::uint64_t seed = 1;
  int steps = 2000;  // of the fine grid over the horizon
  double propagation_tolerance = 1e-11;
  /// samples >= 0, steps >= 1, tolerance in (0, 1e-3]. On failure `*error`
  /// (if given) names the field and the value.
  bool IsValid(std::string* error) const;
};

struct FleetMonteCarloPair {
  int a = 0, b = 1;          // member indices, a < b
  long long collisions = 0;  // samples in which this pair came within R
  double min_distance_m = std::numeric_limits<double>::infinity();
};

struct FleetMonteCarloReport {
  int samples = 0;
  double step_s = 0.0;
  double radius_m = 0.0;     // R, the keep-out half size
  long long collisions = 0;  // samples in which some pair came within R
  double min_distance_m = std::numeric_limits<double>::infinity();  // over samples, pairs, times
  std::vector<FleetMonteCarloPair> pairs;
  double seconds = 0.0;
  bool passed() const { return collisions == 0; }
};

/// @throws std::invalid_argument if the fleet is invalid or has no keep-out,
///         no member has an initial covariance, `schedules` does not hold one
///         schedule per member, or the options are out of range.
FleetMonteCarloReport CheckFleetMonteCarlo(const FleetProblem& fleet,
                                           const std::vector<Schedule>& schedules,
                                           const FleetMonteCarloOptions& options = {});

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_FLEET_MONTE_CARLO_H_
