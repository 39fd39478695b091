// The Monte Carlo of a fleet's initial states (transcription/fleet_monte_carlo.h).
#include "transcription/fleet_monte_carlo.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "common/format.h"
#include "dynamics/propagation.h"
#include "transcription/collision_probability.h"
#include "transcription/fleet.h"

namespace thrustsched::transcription {
namespace {

// Samples drawn together: the deviations of a batch are one matrix product.
constexpr int kBatch = 256;

// One member on the fine grid: the planned positions (3 per time, stacked)
// and the map from standard normal numbers to position deviations.
struct MemberPaths {
  Eigen::VectorXd planned;    // 3 T
  Eigen::MatrixXd deviation;  // 3 T x n, or empty (no covariance)
};

MemberPaths Paths(const FleetProblem& fleet, int k, const Schedule& schedule,
                  const std::vector<double>& times, double tol) {
  const FleetMember& m = fleet.members[k];
  const ScheduleProblem& p = m.problem;
  std::vector<dynamics::InputPulse> pulses;
  for (const Burn& b : schedule.burns) pulses.push_back({b.thruster, b.start_s, b.end_s});
  const auto xs = dynamics::PropagateLinear(*p.model, p.thrusters.AccelerationMatrix(),
                                            p.initial_state, p.grid.front(), pulses, times, tol);
  const int count = static_cast<int>(times.size());
  MemberPaths out;
  out.planned.resize(3 * count);
  const std::vector<Eigen::MatrixXd> position = FleetPositionMaps(fleet, k, times);
  const auto position_at = [&](int i) -> const Eigen::MatrixXd& {
    return position.size() == 1 ? position[0] : position[i];
  };
  for (int i = 0; i < count; ++i) out.planned.segment<3>(3 * i) = position_at(i) * xs[i];
  if (m.initial_covariance.size() == 0) return out;
  const Eigen::MatrixXd factor = CovarianceFactor(m.initial_covariance);
  const dynamics::LinearFlow flow = dynamics::PropagateFlow(*p.model, p.grid.front(), times, tol);
  out.deviation.resize(3 * count, factor.cols());
  for (int i = 0; i < count; ++i)
    out.deviation.middleRows(3 * i, 3) = position_at(i) * flow.phi[i] * factor;
  return out;
}

void Validate(const FleetProblem& fleet, const std::vector<Schedule>& schedules,
              const FleetMonteCarloOptions& o) {
  std::string error;
  if (!fleet.IsValid(&error)) throw std::invalid_argument("fleet Monte Carlo: " + error);
  if (!o.IsValid(&error)) throw std::invalid_argument("fleet Monte Carlo: " + error);
  if (!fleet.keep_out) throw std::invalid_argument("fleet Monte Carlo: the fleet has no keep_out");
  if (schedules.size() != fleet.members.size()) {
    throw std::invalid_argument("fleet Monte Carlo: " + std::to_string(schedules.size()) +
                                " schedules for " + std::to_string(fleet.members.size()) +
                                " members");
  }
  if (!fleet.HasInitialCovariance()) {
    throw std::invalid_argument("fleet Monte Carlo: no member has an initial_covariance");
  }
}

}  // namespace

bool FleetMonteCarloOptions::IsValid(std::string* error) const {
  std::string why;
  if (samples < 0) why = "samples: " + std::to_string(samples) + " (must be >= 0)";
  if (steps < 1) why = "steps: " + std::to_string(steps) + " (must be >= 1)";
  if (!(propagation_tolerance > 0.0 && propagation_tolerance <= 1e-3)) {
    why = "propagation_tolerance: " + common::FormatG(propagation_tolerance, 6) +
          " (must be in (0, 1e-3])";
  }
  if (!why.empty() && error != nullptr) *error = why;
  return why.empty();
}

FleetMonteCarloReport CheckFleetMonteCarlo(const FleetProblem& fleet,
                                           const std::vector<Schedule>& schedules,
                                           const FleetMonteCarloOptions& options) {
  Validate(fleet, schedules, options);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<double>& grid = fleet.members[0].problem.grid;
  FleetMonteCarloReport r;
  r.samples = options.samples;
  r.radius_m = fleet.keep_out->half_size_m;
  r.step_s = (grid.back() - grid.front()) / options.steps;
  std::vector<double> times;
  for (int i = 0; i <= options.steps; ++i)
    times.push_back(i == options.steps ? grid.back() : grid.front() + i * r.step_s);
  const int count = static_cast<int>(fleet.members.size());
  std::vector<MemberPaths> paths;
  for (int k = 0; k < count; ++k)
    paths.push_back(Paths(fleet, k, schedules[k], times, options.propagation_tolerance));
  for (int a = 0; a < count; ++a)
    for (int b = a + 1; b < count; ++b) r.pairs.push_back({a, b, 0, r.min_distance_m});

  GaussianSampler gauss(options.seed);
  const int points = static_cast<int>(times.size());
  std::vector<Eigen::MatrixXd> position(count);  // 3 T x batch, per member
  for (int first = 0; first < options.samples; first += kBatch) {
    const int batch = std::min(kBatch, options.samples - first);
    std::vector<Eigen::MatrixXd> xi(count);
    for (int k = 0; k < count; ++k) xi[k].resize(paths[k].deviation.cols(), batch);
    for (int s = 0; s < batch; ++s) {  // sample by sample: the sequence does not depend on kBatch
      for (int k = 0; k < count; ++k)
        for (int c = 0; c < xi[k].rows(); ++c) xi[k](c, s) = gauss.Next();
    }
    for (int k = 0; k < count; ++k) {
      position[k] = paths[k].planned.replicate(1, batch);
      if (xi[k].rows() > 0) position[k].noalias() += paths[k].deviation * xi[k];
    }
    for (int s = 0; s < batch; ++s) {
      bool collided = false;
      for (FleetMonteCarloPair& pair : r.pairs) {
        double closest = std::numeric_limits<double>::infinity();
        Eigen::Vector3d previous;
        for (int i = 0; i < points; ++i) {
          const Eigen::Vector3d rel =
              position[pair.a].block<3, 1>(3 * i, s) - position[pair.b].block<3, 1>(3 * i, s);
          closest = std::min(closest, i == 0 ? rel.norm() : SegmentDistanceToOrigin(previous, rel));
          previous = rel;
        }
        pair.min_distance_m = std::min(pair.min_distance_m, closest);
        if (closest < r.radius_m) ++pair.collisions, collided = true;
      }
      if (collided) ++r.collisions;
    }
  }
  for (const FleetMonteCarloPair& pair : r.pairs)
    r.min_distance_m = std::min(r.min_distance_m, pair.min_distance_m);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace thrustsched::transcription
