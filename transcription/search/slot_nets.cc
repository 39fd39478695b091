#include "transcription/search/slot_nets.h"

#include <algorithm>
#include <vector>

#include "transcription/total_branching.h"

namespace thrustsched::transcription {

Eigen::MatrixXi CandidateSlots(const SearchState& state, const Eigen::VectorXd& x, double threshold,
                               int k, bool all_thrusters) {
  const OperationalEncoding& enc = state.milp().encoding();
  const milp::LpData& lp = state.lp();
  const Eigen::VectorXd& incumbent = state.incumbent();
  const int m = enc.num_thrusters, n = enc.num_intervals;
  Eigen::MatrixXi used = Eigen::MatrixXi::Zero(m, n);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      const int c = enc.on[i][j].index();
      if (x[c] > threshold || lp.col_lower[c] > 0.5 ||
          (state.has_incumbent() && incumbent[c] > 0.5)) {
        used(i, j) = 1;
      }
    }
  }
  Eigen::MatrixXi mask = Eigen::MatrixXi::Zero(m, n);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      if (lp.col_upper[enc.on[i][j].index()] < 0.5 || state.Dormant(i)) continue;
      bool near = false;
      for (int d = -k; d <= k && !near; ++d) {
        const int jj = j + d;
        near = jj >= 0 && jj < n && (all_thrusters ? used.col(jj).any() : used(i, jj) != 0);
      }
      if (near) mask(i, j) = 1;
    }
  }
  return mask;
}

Eigen::MatrixXi WideningMask(const SearchState& state, const Eigen::VectorXd& x, int level) {
  double threshold = state.search().nets.candidate_threshold;
  int k = state.search().nets.neighbourhood;
  for (int w = 0; w < level; ++w) {
    k = std::max(2 * k, k + 1);
    threshold /= 10.0;
  }
  return CandidateSlots(state, x, threshold, k, level > 0);
}

Eigen::MatrixXi FiredThrusterSlots(const SearchState& state, const Eigen::VectorXd& x) {
  const OperationalEncoding& enc = state.milp().encoding();
  const std::vector<double> totals = ThrusterTotals(enc, x);
  Eigen::MatrixXi mask = Eigen::MatrixXi::Zero(enc.num_thrusters, enc.num_intervals);
  for (int i = 0; i < enc.num_thrusters; ++i) {
    if (totals[static_cast<size_t>(i)] >= state.search().nets.candidate_threshold)
      mask.row(i).setOnes();
  }
  return mask;
}

}  // namespace thrustsched::transcription
