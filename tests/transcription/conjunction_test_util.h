// A small impulsive avoidance problem for the keep-out tests: Serra 2015
// ch. 4's GEO reference orbit (n = 7.4996e-5 rad/s, e = 0.0119), the primary
// on its nominal orbit at t = 0 and back on it at t = 20000 s, impulses at 9
// nodes, and a secondary whose mean passes through the primary at
// t = 10000 s with a relative velocity of a few cm/s; 3 check times.
#ifndef THRUSTSCHED_TESTS_TRANSCRIPTION_CONJUNCTION_TEST_UTIL_H_
#define THRUSTSCHED_TESTS_TRANSCRIPTION_CONJUNCTION_TEST_UTIL_H_

#include <cmath>
#include <memory>

#include "dynamics/discretisation.h"
#include "dynamics/models.h"
#include "dynamics/thrusters.h"
#include "transcription/problem.h"

namespace thrustsched::transcription::testing {

inline std::shared_ptr<const dynamics::YamanakaAnkersenModel> SerraOrbit() {
  const double n = 7.4996e-5;
  const double a = std::cbrt(dynamics::YamanakaAnkersenModel::kEarthMu / (n * n));
  return std::make_shared<const dynamics::YamanakaAnkersenModel>(
      a, 0.0119, dynamics::YamanakaAnkersenModel::kEarthMu, -0.6258);
}

inline ScheduleProblem SmallAvoidance(int num_checks = 3, double budget = 0.05) {
  ScheduleProblem p;
  const auto ya = SerraOrbit();
  p.model = ya;
  p.thrusters = dynamics::ThrusterSet::Ideal6(10, 1000, 300);
  p.grid = dynamics::UniformGrid(0.0, 20000.0, 8);
  p.initial_state = Eigen::VectorXd::Zero(6);
  p.input_mode = InputMode::kImpulsive;
  p.terminal.kind = TerminalKind::kFixedState;
  p.terminal.target = Eigen::VectorXd::Zero(6);
  ConjunctionSpec c;
  Eigen::VectorXd at_tca(6);
  at_tca << 0.0, 0.0, 0.0, 0.01, -0.03, 0.005;  // through the primary at t = 10000 s
  c.secondary_state = ya->TransitionMatrix(0.0, 10000.0) * at_tca;
  c.state_time_s = 0.0;
  Eigen::VectorXd sd(6);
  sd << 20, 30, 5, 1e-3, 2e-3, 5e-4;
  c.covariance = sd.cwiseAbs2().asDiagonal();
  c.radius_m = 15.0;
  c.instantaneous_threshold = 1e-6;
  c.num_checks = num_checks;
  c.check_start_s = 9000.0;
  c.check_end_s = 11000.0;
  c.cost_budget = budget;
  p.conjunction = c;
  return p;
}

}  // namespace thrustsched::transcription::testing

#endif  // THRUSTSCHED_TESTS_TRANSCRIPTION_CONJUNCTION_TEST_UTIL_H_
