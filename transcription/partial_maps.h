// Affine maps from the start of a grid interval to times inside it, for
// constraints between nodes (window inter-sample points, keep-out checks):
//
//   x(t) = phi x_j + gamma u_j + drift,    t_j <= t <= t_{j+1},
//
// with the on-off input u_j held from t_j (Gamma's columns as in
// dynamics/discretisation.h). They come from one discretisation of the grid
// refined by the requested times, with the MILP's own scheme, so they agree
// with the node-to-node maps the MILP uses.
//
//   std::vector<transcription::PartialMap> maps = transcription::PartialMaps(
//       model, thrusters.AccelerationMatrix(), grid, {150.0, 450.0}, options);
//   // maps[0].interval == 0, maps[0].phi = Phi(150, t_0), ...
#ifndef THRUSTSCHED_TRANSCRIPTION_PARTIAL_MAPS_H_
#define THRUSTSCHED_TRANSCRIPTION_PARTIAL_MAPS_H_

#include <vector>

#include <Eigen/Core>

#include "dynamics/discretisation.h"
#include "dynamics/linear_model.h"

namespace thrustsched::transcription {

struct PartialMap {
  double t = 0.0;
  /// j with t_j <= t < t_{j+1}; N - 1 for t = t_N. A time within 1e-9 (relative to the
  /// step) of a node t_j (j < N) is that node: phi = I, gamma = 0, drift = 0.
  int interval = 0;
  Eigen::MatrixXd phi;    // n x n
  Eigen::MatrixXd gamma;  // n x m
  Eigen::VectorXd drift;  // n
};

/// One map per entry of `times` (sorted, non-decreasing, inside [grid.front(),
/// grid.back()]), in that order.
/// @throws std::invalid_argument if the times are unsorted or outside the
///         grid, and as dynamics::Discretize.
std::vector<PartialMap> PartialMaps(const dynamics::LinearModel& model,
                                    const Eigen::MatrixXd& input_columns,
                                    const std::vector<double>& grid,
                                    const std::vector<double>& times,
                                    const dynamics::DiscretizationOptions& options);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_PARTIAL_MAPS_H_
