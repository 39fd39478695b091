#include "transfer/second_order.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

#include "transfer/force_model.h"

namespace thrustsched::transfer {
namespace {

// An orthonormal basis of the hyperplane orthogonal to p0 (columns): the
// unit vectors made orthogonal to p0 and to each other (Gram-Schmidt), the
// one nearest p0 skipped.
Eigen::Matrix<double, 6, 5> TangentBasis(const Vector6& p0) {
  Eigen::Matrix<double, 6, 5> e;
  int n = 0;
  const Vector6 d = p0.normalized();
  for (int k = 0; k < 6 && n < 5; ++k) {
    Vector6 v = Vector6::Unit(k) - d * d(k);
    for (int j = 0; j < n; ++j) v -= e.col(j) * e.col(j).dot(v);
    if (v.norm() > 0.3) e.col(n++) = v.normalized();
  }
  return e;
}

// The determinant's sign with rows and columns scaled to unit infinity norm
// (a few Sinkhorn-like passes: positive factors, so the sign is the
// determinant's and the value is that of a matrix of O(1) entries whatever
// the elements' units).
double EquilibratedDeterminant(Eigen::Matrix<double, 6, 6> a) {
  for (int pass = 0; pass < 4; ++pass) {
    for (int r = 0; r < 6; ++r) {
      const double n = a.row(r).cwiseAbs().maxCoeff();
      if (n > 0) a.row(r) /= n;
    }
    for (int k = 0; k < 6; ++k) {
      const double n = a.col(k).cwiseAbs().maxCoeff();
      if (n > 0) a.col(k) /= n;
    }
  }
  return a.determinant();
}

Vector6 Scaled(const TrajectorySample& s, const ScaledUnits& u) { return u.ToScaled(s.elements); }

// The Jacobi fields dx(t_i)/dp0 e_k (columns 0..4) by central differences of
// step h, on the sample grid of Extremal.
std::vector<Eigen::Matrix<double, 6, 6>> JacobiFields(const MinTimeProblem& p,
                                                      const MinTimeSolution& s, const Vector6& p0,
                                                      double h, const SecondOrderOptions& o) {
  ScaledUnits u;
  u.mu_si = p.mu;
  const Eigen::Matrix<double, 6, 5> e = TangentBasis(p0);
  std::vector<Eigen::Matrix<double, 6, 6>> m;
  for (int k = 0; k < 5; ++k) {
    const MinTimeSolution plus =
        Extremal(p, s.duration_s, p0 + h * e.col(k), o.shooting, o.samples_per_hour);
    const MinTimeSolution minus =
        Extremal(p, s.duration_s, p0 - h * e.col(k), o.shooting, o.samples_per_hour);
    m.resize(plus.trajectory.size(), Eigen::Matrix<double, 6, 6>::Zero());
    for (std::size_t i = 0; i < m.size(); ++i) {
      m[i].col(k) = (Scaled(plus.trajectory[i], u) - Scaled(minus.trajectory[i], u)) / (2 * h);
    }
  }
  return m;
}

}  // namespace

SecondOrderCheck CheckSecondOrder(const MinTimeProblem& p, const MinTimeSolution& s,
                                  const SecondOrderOptions& o) {
  if (s.trajectory.size() < 2 || !(s.duration_s > 0)) {
    throw std::invalid_argument("second-order check: needs an extremal (a converged solution)");
  }
  ScaledUnits u;
  u.mu_si = p.mu;
  const Vector6 p0 = s.costate.normalized();
  const MinTimeSolution nominal = Extremal(p, s.duration_s, p0, o.shooting, o.samples_per_hour);
  std::vector<Eigen::Matrix<double, 6, 6>> m = JacobiFields(p, s, p0, o.costate_step, o);
  std::vector<Eigen::Matrix<double, 6, 6>> m2 = JacobiFields(p, s, p0, o.check_step, o);
  SecondOrderCheck c;
  double max_switch = 0, min_switch = HUGE_VAL;
  for (const TrajectorySample& x : nominal.trajectory) {
    max_switch = std::max(max_switch, x.switching_norm);
    min_switch = std::min(min_switch, x.switching_norm);
  }
  c.min_switching_norm = max_switch > 0 ? min_switch / max_switch : 0.0;
  c.legendre_holds = min_switch > 0;
  const double thrust = u.Thrust(p.thrust_n);
  c.min_abs_determinant = HUGE_VAL;
  double last_resolved = 0;  // the last resolved determinant (0: none yet)
  int second_half = 0, second_half_resolved = 0;
  for (std::size_t i = 1; i < nominal.trajectory.size(); ++i) {
    const TrajectorySample& x = nominal.trajectory[i];
    m[i].col(5) = m2[i].col(5) =  // dx/dt
        GaussRates(Scaled(x, u), thrust / x.mass_kg * x.direction_qsw, p.force_model, u);
    const double det = EquilibratedDeterminant(m[i]), check = EquilibratedDeterminant(m2[i]);
    const bool resolved = std::abs(det - check) <= 0.1 * std::max(std::abs(det), std::abs(check));
    if (resolved) {
      if (c.resolved_from_s < 0) c.resolved_from_s = x.t_s;
      if (last_resolved != 0 && (det > 0) != (last_resolved > 0)) {
        c.conjugate_times_s.push_back((x.t_s + c.last_resolved_s) / 2);
      }
      last_resolved = det;
      c.last_resolved_s = x.t_s;
      ++c.resolved_samples;
    }
    c.t_s.push_back(x.t_s);
    c.determinant.push_back(det);
    if (x.t_s >= s.duration_s / 2) {
      c.min_abs_determinant = std::min(c.min_abs_determinant, std::abs(det));
      ++second_half;
      if (resolved) ++second_half_resolved;
    }
  }
  c.resolved_fraction_second_half =
      second_half > 0 ? static_cast<double>(second_half_resolved) / second_half : 0.0;
  c.final_determinant = c.determinant.back();
  c.no_conjugate_point = c.conjugate_times_s.empty() && c.last_resolved_s == c.t_s.back();
  const bool determined =
      c.resolved_fraction_second_half >= 0.9 && c.last_resolved_s == c.t_s.back();
  c.verdict = !determined                   ? "undetermined"
              : c.conjugate_times_s.empty() ? "no_conjugate_point"
                                            : "conjugate_point";
  return c;
}

}  // namespace thrustsched::transfer
