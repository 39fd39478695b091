// The control-independent data of the keep-out constraints (Serra 2015,
// (4.2), (4.5), (4.12), (4.19)): at each check time the secondary's mean
// position, the relative-position covariance and the margin c_j of every
// polytope face, plus the map from the MILP's state at the start of the grid
// interval to the primary's position there.
//
//   transcription::ConjunctionGeometry g = transcription::ComputeConjunctionGeometry(
//       problem, milp.discrete(), build_options.discretisation);
//   for (const auto& c : g.checks) std::cout << c.t << " " << c.margins.transpose() << "\n";
//
// Positions are in the local Cartesian frame of HcwCoordinates
// (transcription/terminal_sets.h): r = position * x + position_offset for a
// model state x. The secondary moves freely with the problem's own linear
// model (its drift included, so that the drift cancels in the relative
// motion); its state and the covariance are carried from state_time_s to the
// grid start with the inverse transition maps, then forward to every check.
#ifndef THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_GEOMETRY_H_
#define THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_GEOMETRY_H_

#include <vector>

#include <Eigen/Core>

#include "dynamics/discretisation.h"
#include "transcription/conjunction.h"
#include "transcription/partial_maps.h"
#include "transcription/problem.h"

namespace thrustsched::transcription {

struct CheckGeometry {
  PartialMap map;            // from t_{map.interval} to map.t
  Eigen::MatrixXd position;  // 3 x n: local position of a model state at t
  Eigen::Vector3d position_offset;
  Eigen::Vector3d secondary;   // secondary's mean local position (m)
  Eigen::Matrix3d covariance;  // relative position covariance (m^2)
  Eigen::VectorXd margins;     // c_j (m), one per polytope face
  double t() const { return map.t; }
};

struct ConjunctionGeometry {
  KeepOutPolytope polytope;
  double quantile = 0.0;                 // Phi^-1(1 - eps')
  Eigen::VectorXd secondary_state0;      // model state of the secondary at the grid start
  Eigen::MatrixXd covariance0;           // model-state covariance at the grid start (repaired)
  double covariance_min_eigenvalue = 0;  // as given, before any repair (EffectiveCovariance units)
  bool covariance_repaired = false;      // an eigenvalue was clipped
  std::vector<CheckGeometry> checks;     // in time order
};

/// Model states (6) and local coordinates: the model must be one that
/// HcwCoordinates supports (HCW, Yamanaka-Ankersen, GEO).
/// @throws std::invalid_argument if problem.conjunction is empty or invalid,
///         a time lies outside the horizon, the model is not supported, or
///         the discretisation does not match the grid.
ConjunctionGeometry ComputeConjunctionGeometry(const ScheduleProblem& problem,
                                               const dynamics::DiscreteModel& discrete,
                                               const dynamics::DiscretizationOptions& options);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_GEOMETRY_H_
