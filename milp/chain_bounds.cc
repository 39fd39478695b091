#include "milp/chain_bounds.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/SparseCore>

namespace thrustsched::milp {
namespace {

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// One step x_{j+1} = P x_j + G u + d of the chain, read from its rows; u are
// the step's input columns.
struct Step {
  Eigen::MatrixXd p, g;
  Eigen::VectorXd d;
  std::vector<int> inputs;
};

std::string RowName(const LpData& lp, int row) {
  return row >= 0 && row < static_cast<int>(lp.row_names.size()) ? lp.row_names[row]
                                                                 : "R" + std::to_string(row);
}

Step ReadStep(const LpData& lp, const RowMajor& by_row, const EqualityChain& chain, int j,
              const std::vector<int>& block_of, const std::vector<int>& position) {
  const int n = static_cast<int>(chain.blocks[0].size());
  Step s;
  s.p = Eigen::MatrixXd::Zero(n, n);
  s.d = Eigen::VectorXd::Zero(n);
  std::vector<std::vector<std::pair<int, double>>> input_coefs(n);  // (input slot, coef)
  for (int k = 0; k < n; ++k) {
    const int row = chain.rows[j][k];
    if (row < 0 || row >= lp.num_rows()) {
      throw std::invalid_argument("ChainImpliedBounds: row index " + std::to_string(row) +
                                  " out of range");
    }
    if (!(lp.row_lower[row] == lp.row_upper[row]) || !std::isfinite(lp.row_lower[row])) {
      throw std::invalid_argument("ChainImpliedBounds: row " + RowName(lp, row) +
                                  " is not an equality");
    }
    const int lead_col = chain.blocks[j + 1][k];
    double lead = 0.0;
    for (RowMajor::InnerIterator it(by_row, row); it; ++it) {
      if (it.col() == lead_col) lead = it.value();
    }
    if (lead == 0.0) {
      throw std::invalid_argument("ChainImpliedBounds: row " + RowName(lp, row) +
                                  " does not hold the column it defines");
    }
    s.d[k] = lp.row_lower[row] / lead;
    for (RowMajor::InnerIterator it(by_row, row); it; ++it) {
      const int c = it.col();
      if (c == lead_col) continue;
      if (block_of[c] == j) {
        s.p(k, position[c]) = -it.value() / lead;
      } else if (block_of[c] < 0) {
        const auto at = std::find(s.inputs.begin(), s.inputs.end(), c);
        const int slot = static_cast<int>(at - s.inputs.begin());
        if (at == s.inputs.end()) s.inputs.push_back(c);
        input_coefs[k].push_back({slot, -it.value() / lead});
      } else {
        throw std::invalid_argument("ChainImpliedBounds: row " + RowName(lp, row) +
                                    " holds a column of block " + std::to_string(block_of[c]));
      }
    }
  }
  s.g = Eigen::MatrixXd::Zero(n, static_cast<int>(s.inputs.size()));
  for (int k = 0; k < n; ++k) {
    for (const auto& [slot, coef] : input_coefs[k]) s.g(k, slot) = coef;
  }
  return s;
}

// A column's value as ref + t, t in [t_lo, t_hi] with t_lo <= 0 <= t_hi:
// ref is a finite bound when there is one (0 for a free column).
struct Range {
  double ref, t_lo, t_hi;
};
Range RangeOf(const LpData& lp, int col) {
  const double lo = lp.col_lower[col], hi = lp.col_upper[col];
  const double ref = std::isfinite(lo) ? lo : std::isfinite(hi) ? hi : 0.0;
  return {ref, lo - ref, hi - ref};
}

// Adds, for each column of m (the response at one node to one source
// column per column of m), the extremes of m.col(i) * t_i over t_i's range.
void Accumulate(const Eigen::MatrixXd& m, const std::vector<Range>& ranges, Eigen::VectorXd* lo,
                Eigen::VectorXd* hi) {
  for (int i = 0; i < m.cols(); ++i) {
    for (int k = 0; k < m.rows(); ++k) {
      const double g = m(k, i);
      if (g == 0.0) continue;  // also keeps 0 * inf out
      const double a = g * ranges[i].t_lo, b = g * ranges[i].t_hi;
      (*lo)[k] += std::min(a, b);  // <= 0: t's range holds 0
      (*hi)[k] += std::max(a, b);  // >= 0
    }
  }
}

}  // namespace

ChainBounds ChainImpliedBounds(const LpData& lp, const EqualityChain& chain) {
  const int nodes = static_cast<int>(chain.blocks.size());
  if (nodes == 0 || static_cast<int>(chain.rows.size()) != nodes - 1) {
    throw std::invalid_argument("ChainImpliedBounds: " + std::to_string(nodes) + " blocks need " +
                                std::to_string(std::max(nodes - 1, 0)) + " row blocks, got " +
                                std::to_string(chain.rows.size()));
  }
  const int n = static_cast<int>(chain.blocks[0].size());
  std::vector<int> block_of(lp.num_cols(), -1), position(lp.num_cols(), -1);
  for (int j = 0; j < nodes; ++j) {
    if (static_cast<int>(chain.blocks[j].size()) != n ||
        (j + 1 < nodes && static_cast<int>(chain.rows[j].size()) != n)) {
      throw std::invalid_argument("ChainImpliedBounds: block " + std::to_string(j) +
                                  " does not have " + std::to_string(n) + " columns and rows");
    }
    for (int k = 0; k < n; ++k) {
      const int c = chain.blocks[j][k];
      if (c < 0 || c >= lp.num_cols() || block_of[c] >= 0) {
        throw std::invalid_argument("ChainImpliedBounds: column " + std::to_string(c) +
                                    " of block " + std::to_string(j) +
                                    " is out of range or repeated");
      }
      block_of[c] = j;
      position[c] = k;
    }
  }
  const RowMajor by_row = lp.a_matrix;
  std::vector<Step> steps;
  steps.reserve(nodes - 1);
  for (int j = 0; j + 1 < nodes; ++j) {
    steps.push_back(ReadStep(lp, by_row, chain, j, block_of, position));
  }

  // Free response (every column at its reference value) and the spread.
  ChainBounds out;
  std::vector<Eigen::VectorXd> base(nodes), lo(nodes, Eigen::VectorXd::Zero(n)),
      hi(nodes, Eigen::VectorXd::Zero(n));
  std::vector<Range> first(n);
  base[0].resize(n);
  for (int k = 0; k < n; ++k) {
    first[k] = RangeOf(lp, chain.blocks[0][k]);
    base[0][k] = first[k].ref;
  }
  // Sources: block 0 (response I at node 0), then each step's inputs.
  Eigen::MatrixXd response = Eigen::MatrixXd::Identity(n, n);
  for (int t = 0; t < nodes; ++t) {
    Accumulate(response, first, &lo[t], &hi[t]);
    if (t + 1 < nodes) response = steps[t].p * response;
  }
  for (int j = 0; j + 1 < nodes; ++j) {
    const Step& s = steps[j];
    std::vector<Range> ranges;
    Eigen::VectorXd ref(s.inputs.size());
    for (size_t i = 0; i < s.inputs.size(); ++i) {
      ranges.push_back(RangeOf(lp, s.inputs[i]));
      ref[static_cast<int>(i)] = ranges.back().ref;
    }
    base[j + 1] = s.p * base[j] + s.g * ref + s.d;
    if (s.inputs.empty()) continue;
    response = s.g;
    for (int t = j + 1; t < nodes; ++t) {
      Accumulate(response, ranges, &lo[t], &hi[t]);
      if (t + 1 < nodes) response = steps[t].p * response;
    }
  }
  out.lower.resize(nodes);
  out.upper.resize(nodes);
  for (int t = 0; t < nodes; ++t) {
    // Padding on the finite spread only: an unbounded side must not take the
    // other side's finite bound with it.
    const Eigen::ArrayXd spread = (hi[t].array().isFinite()).select(hi[t].array(), 0.0) -
                                  (lo[t].array().isFinite()).select(lo[t].array(), 0.0);
    const Eigen::ArrayXd pad = kChainBoundPadding * (1.0 + base[t].array().abs() + spread);
    out.lower[t] = base[t].array() + lo[t].array() - pad;  // -inf stays -inf
    out.upper[t] = base[t].array() + hi[t].array() + pad;
  }
  return out;
}

void TightenToChainBounds(LpData* lp, const EqualityChain& chain, double widen_fraction) {
  if (!(widen_fraction >= 0.0) || !std::isfinite(widen_fraction)) {
    throw std::invalid_argument(
        "TightenToChainBounds: widen_fraction must be finite and >= 0, got " +
        std::to_string(widen_fraction));
  }
  const ChainBounds b = ChainImpliedBounds(*lp, chain);
  for (size_t j = 0; j < chain.blocks.size(); ++j) {
    for (size_t k = 0; k < chain.blocks[j].size(); ++k) {
      const int c = chain.blocks[j][k];
      if (lp->col_type[c] != VarType::kContinuous) continue;
      const double lo = b.lower[j][static_cast<int>(k)], hi = b.upper[j][static_cast<int>(k)];
      const bool finite = std::isfinite(lo) && std::isfinite(hi);
      const double size =
          std::max(std::isfinite(lo) ? std::abs(lo) : 0.0, std::isfinite(hi) ? std::abs(hi) : 0.0);
      const double margin = widen_fraction * (finite ? hi - lo : 0.0) + 1e-3 * (1.0 + size);
      const double lower = std::max(lp->col_lower[c], lo - margin);  // -inf stays -inf
      const double upper = std::min(lp->col_upper[c], hi + margin);
      if (lower > upper) continue;  // infeasible model: its own bounds say so
      lp->col_lower[c] = lower;
      lp->col_upper[c] = upper;
    }
  }
}

}  // namespace thrustsched::milp
