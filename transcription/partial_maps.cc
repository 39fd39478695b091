#include "transcription/partial_maps.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace thrustsched::transcription {

std::vector<PartialMap> PartialMaps(const dynamics::LinearModel& model,
                                    const Eigen::MatrixXd& input_columns,
                                    const std::vector<double>& grid,
                                    const std::vector<double>& times,
                                    const dynamics::DiscretizationOptions& options) {
  const int nn = static_cast<int>(grid.size()) - 1;
  if (nn < 1) throw std::invalid_argument("PartialMaps: the grid needs at least 2 points");
  const int n = model.num_states();
  const int m = static_cast<int>(input_columns.cols());
  std::vector<PartialMap> out(times.size());
  // Refined grid: every node, and every time strictly between two nodes.
  // slot[q] = index of times[q]'s point in the refined grid (-1: at a node).
  std::vector<double> fine;
  std::vector<int> slot(times.size(), -1);
  size_t q = 0;
  for (int j = 0; j < nn; ++j) {
    fine.push_back(grid[j]);
    const double tol = 1e-9 * (grid[j + 1] - grid[j]);
    for (; q < times.size() && times[q] < grid[j + 1] - tol; ++q) {
      const double t = times[q];
      if (t < grid[j] - tol || (q > 0 && t < times[q - 1])) {
        throw std::invalid_argument("PartialMaps: times must be sorted and inside the grid");
      }
      out[q].t = t;
      out[q].interval = j;
      if (t <= grid[j] + tol) continue;  // at node j: identity
      if (t > fine.back()) fine.push_back(t);
      slot[q] = static_cast<int>(fine.size()) - 1;
    }
  }
  fine.push_back(grid[nn]);
  for (; q < times.size(); ++q) {  // at the last node
    if (std::abs(times[q] - grid[nn]) > 1e-9 * (grid[nn] - grid[nn - 1])) {
      throw std::invalid_argument("PartialMaps: times must be sorted and inside the grid");
    }
    out[q].t = times[q];
    out[q].interval = nn - 1;
    slot[q] = static_cast<int>(fine.size()) - 1;
  }
  const dynamics::DiscreteModel d = dynamics::Discretize(model, input_columns, fine, options);
  // Walk the refined grid, accumulating the map from the current node.
  Eigen::MatrixXd phi = Eigen::MatrixXd::Identity(n, n), gamma = Eigen::MatrixXd::Zero(n, m);
  Eigen::VectorXd drift = Eigen::VectorXd::Zero(n);
  std::vector<int> node_of_point(fine.size(), 0);
  for (size_t k = 0, j = 0; k < fine.size(); ++k) {
    while (j + 1 < grid.size() && fine[k] >= grid[j + 1]) ++j;
    node_of_point[k] = static_cast<int>(fine[k] == grid[j] ? 1 : 0);
  }
  std::vector<Eigen::MatrixXd> phis(fine.size()), gammas(fine.size());
  std::vector<Eigen::VectorXd> drifts(fine.size());
  phis[0] = phi;
  gammas[0] = gamma;
  drifts[0] = drift;
  for (size_t k = 1; k < fine.size(); ++k) {
    if (node_of_point[k - 1] == 1) {  // restart from the node before this step
      phi.setIdentity();
      gamma.setZero();
      drift.setZero();
    }
    gamma = d.phi[k - 1] * gamma + d.gamma[k - 1];
    drift = d.phi[k - 1] * drift + d.drift[k - 1];
    phi = d.phi[k - 1] * phi;
    phis[k] = phi;
    gammas[k] = gamma;
    drifts[k] = drift;
  }
  for (size_t i = 0; i < times.size(); ++i) {
    if (slot[i] < 0) {
      out[i].phi = Eigen::MatrixXd::Identity(n, n);
      out[i].gamma = Eigen::MatrixXd::Zero(n, m);
      out[i].drift = Eigen::VectorXd::Zero(n);
    } else {
      out[i].phi = phis[slot[i]];
      out[i].gamma = gammas[slot[i]];
      out[i].drift = drifts[slot[i]];
    }
  }
  return out;
}

}  // namespace thrustsched::transcription
