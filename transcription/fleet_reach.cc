#include "transcription/internal/fleet_reach.h"

#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "transcription/internal/keep_out_bounds.h"

namespace thrustsched::transcription::internal {

Eigen::VectorXd StateScale(const ScheduleMilp& milp) {
  const int n = milp.problem().model->num_states();
  return milp.options().scale ? milp.problem().model->state_scale() : Eigen::VectorXd::Ones(n);
}

MemberReach::MemberReach(const ScheduleMilp& milp, std::vector<Eigen::MatrixXd> maps,
                         const std::vector<double>& times, const BuildOptions& options)
    : milp_(milp), maps_at_(std::move(maps)), scale_(StateScale(milp)) {
  if (maps_at_.size() != 1 && maps_at_.size() != times.size()) {
    throw std::invalid_argument("MemberReach: " + std::to_string(maps_at_.size()) + " maps for " +
                                std::to_string(times.size()) + " times");
  }
  const ScheduleProblem& p = milp.problem();
  const dynamics::DiscreteModel& d = milp.discrete();
  const int n = p.model->num_states();
  maps_ = PartialMaps(*p.model, p.thrusters.AccelerationMatrix(), p.grid, times,
                      options.discretisation);
  free_.resize(p.grid.size());
  free_[0] = p.initial_state;
  transition_.assign(p.grid.size(), Eigen::MatrixXd::Identity(n, n));
  for (int j = 0; j < p.num_intervals(); ++j) {
    free_[j + 1] = d.phi[j] * free_[j] + d.drift[j];
    transition_[j + 1] = d.phi[j] * transition_[j];
  }
  for (int node = 0; node <= p.num_intervals(); ++node) {
    cols_.state.emplace_back();
    for (int c = 0; c < n; ++c) cols_.state.back().push_back(milp.state(node, c));
  }
  cols_.scale = scale_;
  cols_.thrust = milp.encoding().on;
  const ThrustBounds bounds = ReadBounds(cols_, milp.model());
  for (size_t q = 0; q < maps_.size(); ++q)
    effects_.push_back(
        Effects(p, d, /*kick=*/{}, maps_[q], MapAt(static_cast<int>(q)), cols_, bounds));
}

std::pair<double, double> MemberReach::Range(int q, const Eigen::VectorXd& a) const {
  const PartialMap& at = maps_[q];
  const double free = a.dot(MapAt(q) * (at.phi * free_[at.interval] + at.drift));
  const auto [lo, hi] = KnapsackRange(effects_[q], a, std::numeric_limits<double>::infinity());
  return {free + lo, free + hi};
}

Eigen::MatrixXd MemberReach::MapCovariance(int q, const Eigen::MatrixXd& sigma0) const {
  const PartialMap& at = maps_[q];
  const Eigen::MatrixXd m = MapAt(q) * at.phi * transition_[at.interval];
  return m * sigma0 * m.transpose();
}

}  // namespace thrustsched::transcription::internal
