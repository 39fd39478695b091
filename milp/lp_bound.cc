#include "milp/lp_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

namespace thrustsched::milp {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using SparseCol = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// In the minimisation form: the contribution of row i at dual y_i (the
// bound side the sign needs), and whether that side is finite.
double RowTerm(double y, double lo, double up) {
  if (y > 0.0) return y * lo;
  if (y < 0.0) return y * up;
  return 0.0;
}

// Whether column j's bound on the side its reduced cost d needs is infinite.
bool Unsafe(double d, double lo, double up) {
  return (d > 0.0 && !std::isfinite(lo)) || (d < 0.0 && !std::isfinite(up));
}

// A_RJ: the rows `rows` of the columns `cols`.
SparseCol Block(const SparseCol& a, const std::vector<int>& rows, const std::vector<int>& cols) {
  std::vector<int> row_pos(static_cast<size_t>(a.rows()), -1);
  for (size_t k = 0; k < rows.size(); ++k)
    row_pos[static_cast<size_t>(rows[k])] = static_cast<int>(k);
  std::vector<Eigen::Triplet<double>> t;
  for (size_t k = 0; k < cols.size(); ++k) {
    for (SparseCol::InnerIterator it(a, cols[k]); it; ++it) {
      const int r = row_pos[static_cast<size_t>(it.row())];
      if (r >= 0) t.emplace_back(r, static_cast<int>(k), it.value());
    }
  }
  SparseCol block(static_cast<int>(rows.size()), static_cast<int>(cols.size()));
  block.setFromTriplets(t.begin(), t.end());
  return block;
}

// When the equality rows holding the columns are exactly as many as the
// columns (the schedule MILPs: one dynamics row per state column), A_RJ' dy
// = d_J is square (block triangular in time: the adjoint recursion), solved
// by LU to full accuracy. False if not square or singular.
bool ProjectOutSquare(const SparseCol& a, const std::vector<int>& equality_rows,
                      const std::vector<int>& cols, Eigen::VectorXd* y, const Eigen::VectorXd& d) {
  std::vector<char> touched(static_cast<size_t>(a.rows()), 0);
  for (int j : cols) {
    for (SparseCol::InnerIterator it(a, j); it; ++it) touched[static_cast<size_t>(it.row())] = 1;
  }
  std::vector<int> rows;
  for (int i : equality_rows) {
    if (touched[static_cast<size_t>(i)]) rows.push_back(i);
  }
  if (rows.size() != cols.size()) return false;
  const SparseCol at = SparseCol(Block(a, rows, cols).transpose());
  Eigen::SparseLU<SparseCol> lu;
  lu.compute(at);
  if (lu.info() != Eigen::Success) return false;
  Eigen::VectorXd dj(static_cast<Eigen::Index>(cols.size()));
  for (size_t k = 0; k < cols.size(); ++k) dj[static_cast<Eigen::Index>(k)] = d[cols[k]];
  const Eigen::VectorXd dy = lu.solve(dj);
  if (lu.info() != Eigen::Success || !dy.allFinite()) return false;
  for (size_t k = 0; k < rows.size(); ++k) (*y)[rows[k]] += dy[static_cast<Eigen::Index>(k)];
  return true;
}

// Zeroes the reduced costs of `cols` by changing the duals of `rows` (whose
// dual sign is free) by the least-norm step: dy = A_RJ z, (A_RJ' A_RJ) z = d_J.
// Returns false if the normal matrix is singular (a column of J in no row of R).
bool ProjectOut(const SparseCol& a, const std::vector<int>& rows, const std::vector<int>& cols,
                Eigen::VectorXd* y, Eigen::VectorXd* d) {
  const SparseCol arj = Block(a, rows, cols);
  const SparseCol normal = SparseCol(arj.transpose() * arj);
  Eigen::SimplicialLDLT<SparseCol> ldlt(normal);
  if (ldlt.info() != Eigen::Success) return false;
  Eigen::VectorXd dj(static_cast<Eigen::Index>(cols.size()));
  for (size_t k = 0; k < cols.size(); ++k) dj[static_cast<Eigen::Index>(k)] = (*d)[cols[k]];
  const Eigen::VectorXd z = ldlt.solve(dj);
  if (ldlt.info() != Eigen::Success || !z.allFinite()) return false;
  const Eigen::VectorXd dy = arj * z;
  for (size_t k = 0; k < rows.size(); ++k) (*y)[rows[k]] += dy[static_cast<Eigen::Index>(k)];
  return true;
}

}  // namespace

bool DualBound::finite() const { return std::isfinite(bound); }

DualBound SafeDualBound(const LpData& lp, const Eigen::VectorXd& row_duals) {
  std::string error;
  if (!lp.IsValid(&error)) throw std::invalid_argument("SafeDualBound: " + error);
  if (row_duals.size() != lp.num_rows()) {
    throw std::invalid_argument("SafeDualBound: " + std::to_string(row_duals.size()) +
                                " duals for " + std::to_string(lp.num_rows()) + " rows");
  }
  const double sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
  const int m = lp.num_rows(), n = lp.num_cols();
  SparseCol a = lp.a_matrix;
  a.makeCompressed();
  // Minimisation form: costs and duals times sign.
  Eigen::VectorXd y = sign * row_duals;
  for (int i = 0; i < m; ++i) {
    if (!std::isfinite(y[i])) y[i] = 0.0;
    if ((y[i] > 0.0 && !std::isfinite(lp.row_lower[i])) ||
        (y[i] < 0.0 && !std::isfinite(lp.row_upper[i]))) {
      y[i] = 0.0;  // that side is not a constraint
    }
  }
  const Eigen::VectorXd c = sign * lp.col_cost;
  Eigen::VectorXd d = c - a.transpose() * y;
  // (An LP without columns, e.g. a restricted MILP with every column fixed
  // out, has no largest cost: maxCoeff of an empty vector is undefined.)
  const double scale = n > 0 ? std::max(1.0, c.cwiseAbs().maxCoeff()) : 1.0;
  const double tiny = 1e-12 * scale;
  std::vector<int> free_rows;  // equality or ranged rows: any dual sign
  std::vector<int> equality_rows;
  for (int i = 0; i < m; ++i) {
    if (std::isfinite(lp.row_lower[i]) && std::isfinite(lp.row_upper[i])) free_rows.push_back(i);
    if (lp.row_lower[i] == lp.row_upper[i]) equality_rows.push_back(i);
  }
  DualBound b;
  // Columns whose needed bound side is infinite get a zero reduced cost; the
  // step changes other reduced costs, so look again (the set only grows).
  // Free columns are in it from the start (whatever their reduced cost now):
  // the step is then the whole adjoint system, square and exact.
  std::vector<char> in_set(static_cast<size_t>(n), 0);
  std::vector<int> set;
  for (int j = 0; j < n; ++j) {
    if (!std::isfinite(lp.col_lower[j]) && !std::isfinite(lp.col_upper[j])) {
      in_set[static_cast<size_t>(j)] = 1;
      set.push_back(j);
    }
  }
  // (A few passes: each also refines the last one, whose normal equations
  // lose digits on the scaled state columns.)
  for (int pass = 0; pass < 6; ++pass) {
    double left = 0.0;
    for (int j = 0; j < n; ++j) {
      if (!in_set[static_cast<size_t>(j)] && std::abs(d[j]) > tiny &&
          Unsafe(d[j], lp.col_lower[j], lp.col_upper[j])) {
        in_set[static_cast<size_t>(j)] = 1;
        set.push_back(j);
      }
    }
    for (int j : set) left = std::max(left, std::abs(d[j]));
    if (left <= tiny) break;
    if (!ProjectOutSquare(a, equality_rows, set, &y, d) && !ProjectOut(a, free_rows, set, &y, &d)) {
      b.detail = "the columns without a finite bound are not all in equality or ranged rows";
      break;
    }
    d = c - a.transpose() * y;
  }
  double bound = 0.0;
  for (int i = 0; i < m; ++i) bound += RowTerm(y[i], lp.row_lower[i], lp.row_upper[i]);
  for (int j = 0; j < n; ++j) {
    if (Unsafe(d[j], lp.col_lower[j], lp.col_upper[j])) {
      b.free_residual = std::max(b.free_residual, std::abs(d[j]));
      continue;
    }
    bound += d[j] > 0.0 ? d[j] * lp.col_lower[j] : (d[j] < 0.0 ? d[j] * lp.col_upper[j] : 0.0);
  }
  if (b.free_residual > 1e-9 * scale) {
    bound = -kInf;
    if (b.detail.empty()) b.detail = "reduced costs left on columns without a finite bound";
  }
  b.bound = std::isfinite(bound) ? sign * bound + lp.objective_offset : -sign * kInf;
  b.row_duals = sign * y;
  b.reduced_costs = sign * d;
  return b;
}

LpData FixByReducedCost(const LpData& lp, const DualBound& bound, double incumbent, double step,
                        int* fixed) {
  LpData out = lp;
  int count = 0;
  if (fixed != nullptr) *fixed = 0;
  if (!bound.finite() || !std::isfinite(incumbent)) return out;
  const double sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
  const double l_min = sign * (bound.bound - lp.objective_offset);
  const double z_min = sign * (incumbent - lp.objective_offset);
  // A column is fixed when moving it one unit would cost more than what is
  // left to gain (with a margin that keeps rounding from fixing wrongly).
  const double threshold = z_min - std::max(step, 0.0) + 1e-7 * std::max(1.0, std::abs(z_min));
  if (l_min > threshold) return out;  // nothing can improve: the caller has its proof
  for (int j = 0; j < lp.num_cols(); ++j) {
    if (lp.col_type[static_cast<size_t>(j)] == VarType::kContinuous) continue;
    const double d = sign * bound.reduced_costs[j];
    const double lo = IntegerLowerBound(lp.col_lower[j]);
    const double up = IntegerUpperBound(lp.col_upper[j]);
    if (lo == up) continue;
    if (d > 0.0 && std::isfinite(lo) && l_min + d > threshold) {
      out.col_upper[j] = lo;
      out.col_lower[j] = lo;
      ++count;
    } else if (d < 0.0 && std::isfinite(up) && l_min - d > threshold) {
      out.col_lower[j] = up;
      out.col_upper[j] = up;
      ++count;
    }
  }
  if (fixed != nullptr) *fixed = count;
  return out;
}

double RoundBoundToStep(const LpData& lp, double bound, double step) {
  if (!(step > 0.0) || !std::isfinite(bound)) return bound;
  const double sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
  const double l_min = sign * (bound - lp.objective_offset);
  const double k = std::ceil(l_min / step - 1e-6);
  return sign * k * step + lp.objective_offset;
}

}  // namespace thrustsched::milp
