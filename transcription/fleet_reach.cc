#include "transcription/internal/fleet_reach.h"

#include <limits>

#include "transcription/internal/keep_out_bounds.h"

namespace thrustsched::transcription::internal {

Eigen::VectorXd StateScale(const ScheduleMilp& milp) {
  const int n = milp.problem().model->num_states();
  return milp.options().scale ? milp.problem().model->state_scale() : Eigen::VectorXd::Ones(n);
}

MemberReach::MemberReach(const ScheduleMilp& milp, const Eigen::MatrixXd& map,
                         const std::vector<double>& times, const BuildOptions& options)
    : milp_(milp), scale_(StateScale(milp)) {
  const ScheduleProblem& p = milp.problem();
  const dynamics::DiscreteModel& d = milp.discrete();
  const int n = p.model->num_states();
  map_ = map.size() == 0 ? Eigen::MatrixXd(Eigen::MatrixXd::Identity(3, n)) : map;
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
  for (const PartialMap& at : maps_)
    effects_.push_back(Effects(p, d, /*kick=*/{}, at, map_, cols_, bounds));
}

std::pair<double, double> MemberReach::Range(int q, const Eigen::VectorXd& a) const {
  const PartialMap& at = maps_[q];
  const double free = a.dot(map_ * (at.phi * free_[at.interval] + at.drift));
  const auto [lo, hi] = KnapsackRange(effects_[q], a, std::numeric_limits<double>::infinity());
  return {free + lo, free + hi};
}

Eigen::MatrixXd MemberReach::MapCovariance(int q, const Eigen::MatrixXd& sigma0) const {
  const PartialMap& at = maps_[q];
  const Eigen::MatrixXd m = map_ * at.phi * transition_[at.interval];
  return m * sigma0 * m.transpose();
}

}  // namespace thrustsched::transcription::internal
