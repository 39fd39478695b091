#include "milp/interior_point.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include "milp/lp_bound.h"

namespace thrustsched::milp {

namespace {

using SparseCol = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Eigen::VectorXd;

constexpr double kInf = std::numeric_limits<double>::infinity();

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// min c'z  s.t.  M z = b,  l <= z <= u, where z = (the LP's columns that are
// not fixed, then one activity column per inequality row): the form the
// iteration works on, with the maps back to the LP.
struct BoundedForm {
  SparseCol m;
  VectorXd b, c, l, u;
  std::vector<int> lp_col;  // z index -> LP column, for the first n_x entries
  std::vector<int> lp_row;  // M row -> LP row
  int n_x = 0;
  double sign = 1.0;        // -1: the LP maximises, c is its cost negated
  double fixed_cost = 0.0;  // c'x over the fixed columns, the LP's sense
};

BoundedForm ToBoundedForm(const LpData& lp) {
  BoundedForm f;
  f.sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
  const int n = lp.num_cols();
  std::vector<int> z_of_col(static_cast<size_t>(n), -1);
  VectorXd fixed_activity = VectorXd::Zero(lp.num_rows());
  for (int j = 0; j < n; ++j) {
    if (lp.col_lower[j] == lp.col_upper[j]) {
      for (SparseCol::InnerIterator it(lp.a_matrix, j); it; ++it)
        fixed_activity[it.row()] += it.value() * lp.col_lower[j];
      f.fixed_cost += lp.col_cost[j] * lp.col_lower[j];
      continue;
    }
    z_of_col[static_cast<size_t>(j)] = static_cast<int>(f.lp_col.size());
    f.lp_col.push_back(j);
  }
  f.n_x = static_cast<int>(f.lp_col.size());
  // Rows: equality rows keep their right-hand side; inequality rows get an
  // activity column w with the row's bounds (A x - w = 0); free rows drop.
  std::vector<int> m_row_of(static_cast<size_t>(lp.num_rows()), -1);
  std::vector<int> inequality_rows;
  for (int i = 0; i < lp.num_rows(); ++i) {
    const double lo = lp.row_lower[i], up = lp.row_upper[i];
    if (!std::isfinite(lo) && !std::isfinite(up)) continue;
    m_row_of[static_cast<size_t>(i)] = static_cast<int>(f.lp_row.size());
    f.lp_row.push_back(i);
    if (lo != up) inequality_rows.push_back(i);
  }
  const int m = static_cast<int>(f.lp_row.size());
  const int nz = f.n_x + static_cast<int>(inequality_rows.size());
  f.b = VectorXd::Zero(m);
  f.c = VectorXd::Zero(nz);
  f.l.resize(nz);
  f.u.resize(nz);
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(static_cast<size_t>(lp.num_nonzeros()) + inequality_rows.size());
  for (int k = 0; k < f.n_x; ++k) {
    const int j = f.lp_col[static_cast<size_t>(k)];
    f.c[k] = f.sign * lp.col_cost[j];
    f.l[k] = lp.col_lower[j];
    f.u[k] = lp.col_upper[j];
    for (SparseCol::InnerIterator it(lp.a_matrix, j); it; ++it) {
      const int r = m_row_of[static_cast<size_t>(it.row())];
      if (r >= 0) entries.emplace_back(r, k, it.value());
    }
  }
  for (size_t q = 0; q < inequality_rows.size(); ++q) {
    const int i = inequality_rows[q];
    const int k = f.n_x + static_cast<int>(q);
    const int r = m_row_of[static_cast<size_t>(i)];
    entries.emplace_back(r, k, -1.0);
    f.l[k] = lp.row_lower[i] - fixed_activity[i];
    f.u[k] = lp.row_upper[i] - fixed_activity[i];
  }
  for (int r = 0; r < m; ++r) {
    const int i = f.lp_row[static_cast<size_t>(r)];
    if (lp.row_lower[i] == lp.row_upper[i]) f.b[r] = lp.row_lower[i] - fixed_activity[i];
  }
  f.m.resize(m, nz);
  f.m.setFromTriplets(entries.begin(), entries.end());
  f.m.makeCompressed();
  return f;
}

// Ruiz equilibration (Ruiz 2001): M := R M S with every row's and column's
// largest |entry| near 1; then the cost scaled to a largest |entry| of 1.
// Returns (R, S, cost scale); the form is scaled in place.
struct Scaling {
  VectorXd row, col;
  double cost = 1.0;
};

Scaling Equilibrate(BoundedForm* f) {
  Scaling s;
  s.row = VectorXd::Ones(f->m.rows());
  s.col = VectorXd::Ones(f->m.cols());
  for (int pass = 0; pass < 10; ++pass) {
    VectorXd row_max = VectorXd::Zero(f->m.rows()), col_max = VectorXd::Zero(f->m.cols());
    for (int j = 0; j < f->m.outerSize(); ++j)
      for (SparseCol::InnerIterator it(f->m, j); it; ++it) {
        const double a = std::abs(it.value());
        row_max[it.row()] = std::max(row_max[it.row()], a);
        col_max[j] = std::max(col_max[j], a);
      }
    double worst = 0.0;
    for (int i = 0; i < row_max.size(); ++i) {
      const double r = row_max[i] > 0 ? 1.0 / std::sqrt(row_max[i]) : 1.0;
      worst = std::max(worst, std::abs(1.0 - row_max[i]));
      row_max[i] = r;
    }
    for (int j = 0; j < col_max.size(); ++j) {
      const double r = col_max[j] > 0 ? 1.0 / std::sqrt(col_max[j]) : 1.0;
      worst = std::max(worst, std::abs(1.0 - col_max[j]));
      col_max[j] = r;
    }
    if (worst < 1e-3) break;
    f->m = row_max.asDiagonal() * f->m * col_max.asDiagonal();
    s.row = s.row.cwiseProduct(row_max);
    s.col = s.col.cwiseProduct(col_max);
  }
  f->b = f->b.cwiseProduct(s.row);
  f->c = f->c.cwiseProduct(s.col);
  for (int j = 0; j < f->l.size(); ++j) {
    f->l[j] /= s.col[j];  // +-inf stays +-inf
    f->u[j] /= s.col[j];
  }
  const double c_max = f->c.size() > 0 ? f->c.cwiseAbs().maxCoeff() : 0.0;
  s.cost = c_max > 0 ? c_max : 1.0;
  f->c /= s.cost;
  return s;
}

// The quasi-definite augmented system, its pattern analysed once. The
// activity columns (one entry each, in their row) are eliminated first, so
// the factor sees only the LP's columns and rows:
//   [ -(D_x + rho I)   A'                          ]
//   [  A               delta I + v^2 / (D_w + rho) ]
// (v the activity column's entry in its row). No iterative refinement: the
// regularisations make each step the exact Newton step of the proximal
// problem (Friedlander & Orban 2012, Math. Program. Comput. 4), and the
// iteration converges to the LP's optimum all the same.
class KktSystem {
 public:
  KktSystem(const SparseCol& m, int n_x) : n_x_(n_x), n_rows_(static_cast<int>(m.rows())) {
    const int dim = n_x_ + n_rows_;
    // The lower triangle in the natural order: every diagonal, then M.
    std::vector<Eigen::Triplet<double, int>> lower;
    lower.reserve(static_cast<size_t>(m.nonZeros() + dim));
    for (int k = 0; k < dim; ++k) lower.emplace_back(k, k, 1.0);
    for (int j = 0; j < n_x_; ++j)
      for (SparseCol::InnerIterator it(m, j); it; ++it)
        lower.emplace_back(n_x_ + static_cast<int>(it.row()), j, it.value());
    for (int j = n_x_; j < m.cols(); ++j) {
      SparseCol::InnerIterator it(m, j);
      activity_row_.push_back(static_cast<int>(it.row()));
      activity_entry_.push_back(it.value());
    }
    // The ordering once, then the matrix stored permuted (upper triangle):
    // the factorisation reads it in place and the solves need no
    // permutation of their vectors.
    SparseCol full(dim, dim);
    full.setFromTriplets(lower.begin(), lower.end());
    SparseCol symmetric = full.selfadjointView<Eigen::Lower>();
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
    Eigen::AMDOrdering<int>()(symmetric, inverse);
    position_.resize(static_cast<size_t>(dim));
    for (int k = 0; k < dim; ++k) position_[static_cast<size_t>(inverse.indices()[k])] = k;
    std::vector<Eigen::Triplet<double, int>> upper;
    upper.reserve(lower.size());
    for (const auto& t : lower) {
      const int a = position_[static_cast<size_t>(t.row())],
                b = position_[static_cast<size_t>(t.col())];
      upper.emplace_back(std::min(a, b), std::max(a, b), t.value());
    }
    k_.resize(dim, dim);
    k_.setFromTriplets(upper.begin(), upper.end());
    k_.makeCompressed();
    // Upper triangle, rows sorted: the diagonal is each column's last entry.
    diagonal_.resize(static_cast<size_t>(dim));
    for (int k = 0; k < dim; ++k)
      diagonal_[static_cast<size_t>(k)] =
          k_.outerIndexPtr()[position_[static_cast<size_t>(k)] + 1] - 1;
    ldlt_.analyzePattern(k_);
  }

  bool analysed() const { return ldlt_.info() == Eigen::Success; }
  long long factor_nonzeros() const { return ldlt_.matrixL().nestedExpression().nonZeros(); }
  int dimension() const { return static_cast<int>(k_.rows()); }

  // The system for the barrier diagonal d (one per column of M); false if the
  // factorisation failed.
  bool Factor(const VectorXd& d, double rho, double delta) {
    inverse_activity_ = VectorXd::Zero(static_cast<int>(activity_row_.size()));
    VectorXd row_diagonal = VectorXd::Constant(n_rows_, delta);
    for (size_t q = 0; q < activity_row_.size(); ++q) {
      const double inverse = 1.0 / (d[n_x_ + static_cast<int>(q)] + rho);
      inverse_activity_[static_cast<int>(q)] = inverse;
      row_diagonal[activity_row_[q]] += activity_entry_[q] * activity_entry_[q] * inverse;
    }
    double* value = k_.valuePtr();
    for (int k = 0; k < n_x_; ++k) value[diagonal_[static_cast<size_t>(k)]] = -(d[k] + rho);
    for (int i = 0; i < n_rows_; ++i)
      value[diagonal_[static_cast<size_t>(n_x_ + i)]] = row_diagonal[i];
    ldlt_.factorize(k_);
    return ldlt_.info() == Eigen::Success;
  }

  // Solves [-(d + rho) M'; M delta] (dz; dl) = (r1; r2) with the last factor.
  void Solve(const VectorXd& r1, const VectorXd& r2, VectorXd* dz, VectorXd* dl) const {
    VectorXd rhs(dimension());
    for (int k = 0; k < n_x_; ++k) rhs[position_[static_cast<size_t>(k)]] = r1[k];
    for (int i = 0; i < n_rows_; ++i) rhs[position_[static_cast<size_t>(n_x_ + i)]] = r2[i];
    for (size_t q = 0; q < activity_row_.size(); ++q) {
      const int k = n_x_ + static_cast<int>(q);
      rhs[position_[static_cast<size_t>(n_x_ + activity_row_[q])]] +=
          activity_entry_[q] * r1[k] * inverse_activity_[static_cast<int>(q)];
    }
    rhs = ldlt_.solve(rhs).eval();
    dz->resize(r1.size());
    dl->resize(n_rows_);
    for (int k = 0; k < n_x_; ++k) (*dz)[k] = rhs[position_[static_cast<size_t>(k)]];
    for (int i = 0; i < n_rows_; ++i) (*dl)[i] = rhs[position_[static_cast<size_t>(n_x_ + i)]];
    for (size_t q = 0; q < activity_row_.size(); ++q) {
      const int k = n_x_ + static_cast<int>(q);
      (*dz)[k] = (activity_entry_[q] * (*dl)[activity_row_[q]] - r1[k]) *
                 inverse_activity_[static_cast<int>(q)];
    }
  }

 private:
  int n_x_, n_rows_;
  std::vector<int> activity_row_;
  std::vector<double> activity_entry_;
  VectorXd inverse_activity_;
  SparseCol k_;
  std::vector<int> position_;  // natural index -> index in the ordered system
  std::vector<int> diagonal_;  // natural index -> its diagonal entry in k_
  Eigen::SimplicialLDLT<SparseCol, Eigen::Upper, Eigen::NaturalOrdering<int>> ldlt_;
};

// The iterate: z strictly inside its bounds, y_l, y_u > 0 on the finite ones.
struct Iterate {
  VectorXd z, lambda, y_l, y_u;
};

struct Direction {
  VectorXd dz, dl, dy_l, dy_u;
};

class MehrotraIteration {
 public:
  MehrotraIteration(const BoundedForm& f, KktSystem* kkt)
      : f_(f), kkt_(kkt), has_l_(f.l.size()), has_u_(f.u.size()) {
    for (int j = 0; j < f.l.size(); ++j) {
      has_l_[j] = std::isfinite(f.l[j]) ? 1.0 : 0.0;
      has_u_[j] = std::isfinite(f.u[j]) ? 1.0 : 0.0;
      n_bounds_ += static_cast<int>(has_l_[j] + has_u_[j]);
    }
  }

  Iterate Start() const {
    Iterate it;
    const int nz = static_cast<int>(f_.c.size());
    it.z.resize(nz);
    for (int j = 0; j < nz; ++j) {
      const double l = f_.l[j], u = f_.u[j];
      if (has_l_[j] && has_u_[j]) {
        it.z[j] = 0.5 * (l + u);
      } else if (has_l_[j]) {
        it.z[j] = l + 1.0;
      } else if (has_u_[j]) {
        it.z[j] = u - 1.0;
      } else {
        it.z[j] = 0.0;
      }
    }
    it.lambda = VectorXd::Zero(f_.b.size());
    it.y_l = has_l_;
    it.y_u = has_u_;
    return it;
  }

  // z - l and u - z; 0 where the bound is infinite. Never below a few ulps
  // of the bound: near the optimum z - l cancels, and an exact 0 would make
  // the barrier's diagonal 0/0.
  VectorXd SlackLower(const Iterate& it) const {
    VectorXd s = VectorXd::Zero(it.z.size());
    for (int j = 0; j < s.size(); ++j)
      if (has_l_[j]) s[j] = std::max(it.z[j] - f_.l[j], MinSlack(f_.l[j]));
    return s;
  }
  VectorXd SlackUpper(const Iterate& it) const {
    VectorXd s = VectorXd::Zero(it.z.size());
    for (int j = 0; j < s.size(); ++j)
      if (has_u_[j]) s[j] = std::max(f_.u[j] - it.z[j], MinSlack(f_.u[j]));
    return s;
  }
  static double MinSlack(double bound) { return 1e-15 * (1.0 + std::abs(bound)); }
  VectorXd PrimalResidual(const Iterate& it) const { return f_.b - f_.m * it.z; }
  VectorXd DualResidual(const Iterate& it) const {
    return f_.c - f_.m.transpose() * it.lambda - it.y_l + it.y_u;
  }
  double Mu(const Iterate& it) const {
    if (n_bounds_ == 0) return 0.0;
    return (SlackLower(it).dot(it.y_l) + SlackUpper(it).dot(it.y_u)) / n_bounds_;
  }
  double PrimalObjective(const Iterate& it) const { return f_.c.dot(it.z); }
  double DualObjective(const Iterate& it) const {
    double d = f_.b.dot(it.lambda);
    for (int j = 0; j < f_.l.size(); ++j) {
      if (has_l_[j]) d += f_.l[j] * it.y_l[j];
      if (has_u_[j]) d -= f_.u[j] * it.y_u[j];
    }
    return d;
  }

  // One predictor-corrector step; false if the factorisation failed.
  bool Step(Iterate* it) {
    const VectorXd s_l = SlackLower(*it), s_u = SlackUpper(*it);
    VectorXd d(it->z.size());
    for (int j = 0; j < d.size(); ++j)
      d[j] = (has_l_[j] ? it->y_l[j] / s_l[j] : 0.0) + (has_u_[j] ? it->y_u[j] / s_u[j] : 0.0);
    if (!kkt_->Factor(d, regularisation_, regularisation_)) return false;
    const VectorXd r_p = PrimalResidual(*it), r_d = DualResidual(*it);
    const double mu = Mu(*it);
    // Predictor (affine scaling).
    VectorXd r_cl = -s_l.cwiseProduct(it->y_l), r_cu = -s_u.cwiseProduct(it->y_u);
    const Direction affine = Solve(*it, s_l, s_u, r_p, r_d, r_cl, r_cu);
    const double a_p = PrimalStep(s_l, s_u, affine.dz, 1.0);
    const double a_d = DualStep(*it, affine, 1.0);
    const VectorXd s_l_aff = s_l + a_p * affine.dz.cwiseProduct(has_l_);
    const VectorXd s_u_aff = s_u - a_p * affine.dz.cwiseProduct(has_u_);
    const double mu_aff = n_bounds_ == 0 ? 0.0
                                         : (s_l_aff.dot(it->y_l + a_d * affine.dy_l) +
                                            s_u_aff.dot(it->y_u + a_d * affine.dy_u)) /
                                               n_bounds_;
    double sigma = mu > 0 ? std::pow(std::clamp(mu_aff / mu, 0.0, 1.0), 3) : 0.0;
    // Complementarity never far ahead of feasibility: where mu falls below
    // the primal residual (a week that needs almost no thrust: the zero
    // schedule misses the window by little), the slacks reach the boundary
    // while the iterate is still infeasible, the barrier diagonal grows to
    // 1e15 and the steps no longer lower the residual (it stalled at 1e-6 on
    // such a week); centring in proportion to the residual keeps the iterate
    // interior until it is feasible (cf. the "mu-infeasibility balance" of
    // Wright 1997, Primal-Dual Interior-Point Methods, ch. 6).
    if (mu > 0) {
      const double residual =
          r_p.lpNorm<Eigen::Infinity>() / (1.0 + f_.b.lpNorm<Eigen::Infinity>());
      sigma = std::max(sigma, std::min(0.9, kCentringPerResidual * residual / mu));
    }
    // Corrector: centring and the second-order term.
    for (int j = 0; j < d.size(); ++j) {
      if (has_l_[j]) r_cl[j] += sigma * mu - affine.dz[j] * affine.dy_l[j];
      if (has_u_[j]) r_cu[j] += sigma * mu + affine.dz[j] * affine.dy_u[j];
    }
    const Direction step = Solve(*it, s_l, s_u, r_p, r_d, r_cl, r_cu);
    // Never the whole way to the boundary: a slack at exactly 0 makes the next
    // diagonal infinite.
    const double eta = std::clamp(1.0 - mu, 0.9, 0.99995);
    const double p = PrimalStep(s_l, s_u, step.dz, eta);
    const double q = DualStep(*it, step, eta);
    it->z += p * step.dz;
    it->lambda += q * step.dl;
    it->y_l += q * step.dy_l;
    it->y_u += q * step.dy_u;
    return true;
  }

  // Raised where the factorisation fails or the iterate runs away: the
  // pivots of a quasi-definite system stay away from 0 by about the
  // regularisation, so a larger one trades a little of each step's accuracy
  // for a factorisation that holds (the proximal steps still converge).
  bool RaiseRegularisation() {
    if (regularisation_ >= kMaxRegularisation) return false;
    regularisation_ *= 100.0;
    return true;
  }

 private:
  static constexpr double kMaxRegularisation = 1e-4;
  /// sigma mu >= kCentringPerResidual * relative primal residual.
  static constexpr double kCentringPerResidual = 0.01;
  double regularisation_ = 1e-8;

  Direction Solve(const Iterate& it, const VectorXd& s_l, const VectorXd& s_u, const VectorXd& r_p,
                  const VectorXd& r_d, const VectorXd& r_cl, const VectorXd& r_cu) const {
    VectorXd r1 = r_d;
    for (int j = 0; j < r1.size(); ++j) {
      if (has_l_[j]) r1[j] -= r_cl[j] / s_l[j];
      if (has_u_[j]) r1[j] += r_cu[j] / s_u[j];
    }
    Direction dir;
    kkt_->Solve(r1, r_p, &dir.dz, &dir.dl);
    dir.dy_l = VectorXd::Zero(r1.size());
    dir.dy_u = VectorXd::Zero(r1.size());
    for (int j = 0; j < r1.size(); ++j) {
      if (has_l_[j]) dir.dy_l[j] = (r_cl[j] - it.y_l[j] * dir.dz[j]) / s_l[j];
      if (has_u_[j]) dir.dy_u[j] = (r_cu[j] + it.y_u[j] * dir.dz[j]) / s_u[j];
    }
    return dir;
  }

  double PrimalStep(const VectorXd& s_l, const VectorXd& s_u, const VectorXd& dz,
                    double eta) const {
    double alpha = 1.0;
    for (int j = 0; j < dz.size(); ++j) {
      if (has_l_[j] && dz[j] < 0) alpha = std::min(alpha, -eta * s_l[j] / dz[j]);
      if (has_u_[j] && dz[j] > 0) alpha = std::min(alpha, eta * s_u[j] / dz[j]);
    }
    return alpha;
  }

  double DualStep(const Iterate& it, const Direction& dir, double eta) const {
    double alpha = 1.0;
    for (int j = 0; j < dir.dz.size(); ++j) {
      if (has_l_[j] && dir.dy_l[j] < 0) alpha = std::min(alpha, -eta * it.y_l[j] / dir.dy_l[j]);
      if (has_u_[j] && dir.dy_u[j] < 0) alpha = std::min(alpha, -eta * it.y_u[j] / dir.dy_u[j]);
    }
    return alpha;
  }

  const BoundedForm& f_;
  KktSystem* kkt_;
  VectorXd has_l_, has_u_;
  int n_bounds_ = 0;
};

// Relative residuals in the LP's own units (the scaling undone).
struct Residuals {
  double primal = kInf, dual = kInf, gap = kInf;
};

Residuals Measure(const MehrotraIteration& ipm, const Iterate& it, const Scaling& s, double b_norm,
                  double c_norm) {
  Residuals r;
  r.primal = ipm.PrimalResidual(it).cwiseQuotient(s.row).lpNorm<Eigen::Infinity>() / (1.0 + b_norm);
  r.dual =
      s.cost * ipm.DualResidual(it).cwiseQuotient(s.col).lpNorm<Eigen::Infinity>() / (1.0 + c_norm);
  const double p = s.cost * ipm.PrimalObjective(it), d = s.cost * ipm.DualObjective(it);
  r.gap = std::abs(p - d) / (1.0 + std::abs(p));
  return r;
}

}  // namespace

InteriorPointResult SolveLpByInteriorPoint(const LpData& lp, const InteriorPointOptions& options) {
  std::string error;
  if (!lp.IsValid(&error)) throw std::invalid_argument("SolveLpByInteriorPoint: " + error);
  const auto t0 = std::chrono::steady_clock::now();
  InteriorPointResult result;
  BoundedForm f = ToBoundedForm(lp);
  const double b_norm = f.b.size() > 0 ? f.b.lpNorm<Eigen::Infinity>() : 0.0;
  const double c_norm = f.c.size() > 0 ? f.c.lpNorm<Eigen::Infinity>() : 0.0;
  const Scaling scaling = Equilibrate(&f);
  KktSystem kkt(f.m, f.n_x);
  result.kkt_dimension = kkt.dimension();
  result.seconds_analysis = Seconds(t0);
  if (!kkt.analysed()) {
    result.status = SolveStatus::kNoSolutionFound;
    result.detail = "interior point: the KKT pattern could not be analysed";
    return result;
  }
  MehrotraIteration ipm(f, &kkt);
  Iterate it = ipm.Start();
  Iterate last = it;
  Residuals r;
  int reported = 0;  // the last iteration handed to on_iteration
  for (;;) {
    r = Measure(ipm, it, scaling, b_norm, c_norm);
    if (options.on_iteration && result.iterations > reported) {
      reported = result.iterations;
      const double objective =
          f.sign * scaling.cost * ipm.PrimalObjective(it) + f.fixed_cost + lp.objective_offset;
      options.on_iteration(result.iterations, objective, r.primal);
    }
    if (r.primal <= options.tolerance && r.dual <= options.tolerance &&
        r.gap <= options.tolerance) {
      result.status = SolveStatus::kOptimal;
      result.detail = "interior point: " + std::to_string(result.iterations) + " iterations";
      break;
    }
    if (result.iterations >= options.max_iterations) {
      result.status = SolveStatus::kNoSolutionFound;
      result.detail =
          "interior point: no convergence in " + std::to_string(result.iterations) + " iterations";
      break;
    }
    if (options.should_stop && options.should_stop()) {
      result.status = SolveStatus::kNoSolutionFound;
      result.detail = "interior point: stopped";
      break;
    }
    if (!(it.z.lpNorm<Eigen::Infinity>() < 1e14) || !(it.lambda.lpNorm<Eigen::Infinity>() < 1e14)) {
      if (ipm.RaiseRegularisation()) {
        it = last;  // the step before it ran away, again with the larger regularisation
        continue;
      }
      result.status = SolveStatus::kNoSolutionFound;
      result.detail = "interior point: the iterate diverges (an infeasible or unbounded LP?)";
      break;
    }
    last = it;
    if (!ipm.Step(&it)) {
      if (ipm.RaiseRegularisation()) continue;
      result.status = SolveStatus::kNoSolutionFound;
      result.detail = "interior point: the KKT factorisation failed";
      break;
    }
    ++result.iterations;
  }
  result.primal_residual = r.primal;
  result.dual_residual = r.dual;
  result.relative_gap = r.gap;
  result.factor_nonzeros = kkt.factor_nonzeros();
  // Back to the LP: columns (fixed ones at their value), row duals.
  result.x.resize(lp.num_cols());
  for (int j = 0; j < lp.num_cols(); ++j) result.x[j] = lp.col_lower[j];
  for (int k = 0; k < f.n_x; ++k) {
    const int j = f.lp_col[static_cast<size_t>(k)];
    result.x[j] = std::clamp(it.z[k] * scaling.col[k], lp.col_lower[j], lp.col_upper[j]);
  }
  result.row_duals = VectorXd::Zero(lp.num_rows());
  for (int r_m = 0; r_m < static_cast<int>(f.lp_row.size()); ++r_m)
    result.row_duals[f.lp_row[static_cast<size_t>(r_m)]] =
        f.sign * scaling.cost * scaling.row[r_m] * it.lambda[r_m];
  result.objective = lp.Objective(result.x);
  result.seconds = Seconds(t0);
  return result;
}

LpRelaxationResult ToLpRelaxationResult(const LpData& lp, InteriorPointResult result) {
  LpRelaxationResult r;
  r.status = result.status;
  r.detail = std::move(result.detail);
  r.objective = result.objective;
  r.wall_seconds = result.seconds;
  r.iterations = result.iterations;
  if (result.status == SolveStatus::kOptimal)
    r.dual_bound = SafeDualBound(lp, result.row_duals).bound;
  r.x = std::move(result.x);
  r.row_duals = std::move(result.row_duals);
  return r;
}

}  // namespace thrustsched::milp
