#include "dynamics/discretisation.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

#include "common/error.h"
#include "common/format.h"
#include "dynamics/internal/adaptive_integrator.h"
#include "dynamics/internal/scaled_model.h"

namespace thrustsched::dynamics {
namespace {

using internal::ScaledModel;
using Frozen = ScaledModel::Frozen;

// Error messages keep the name they always had (scripts may match them).
constexpr const char* kWhere = "Discretise";

// Largest 1-norm of h*M handed to Eigen's Pade approximant; larger arguments
// are scaled by 2^-s and squared back s times. 5.37 is the Pade-13 bound of
// Higham (2005) that Eigen itself uses; measured on HCW at GEO (nondimensional),
// smaller bounds only add squarings and lose accuracy (0.5: 4e-13 at 1 day
// instead of 3e-15).
constexpr double kMaxExpNorm = 5.371920351148152;
// Time-invariant models: consecutive intervals whose nondimensional lengths
// agree to this relative tolerance share one step map (a uniform grid built
// from doubles has lengths differing by a few ulps).
constexpr double kLtiReuseTolerance = 1e-13;

// All per-interval work buffers, allocated once per Discretize call.
struct Workspace {
  Workspace(int n, int m)
      : n(n),
        m(m),
        z(n, n + m + 1),
        y(n, n + m + 1),
        k1(n, n + m + 1),
        k2(n, n + m + 1),
        k3(n, n + m + 1),
        k4(n, n + m + 1),
        lhs(n, n),
        rhs(n, n + m + 1),
        aug(n + m + 1, n + m + 1),
        aug_exp(n + m + 1, n + m + 1),
        aug_tmp(n + m + 1, n + m + 1),
        identity(Eigen::MatrixXd::Identity(n, n)),
        lu(n),
        col_scale(m + 1),
        flat(static_cast<size_t>(n) * (n + m + 1)) {}
  int n, m;
  Eigen::MatrixXd z;  // [Phi^ | Gamma^ | drift^], nondimensional
  Eigen::MatrixXd y, k1, k2, k3, k4, lhs, rhs, aug, aug_exp, aug_tmp, identity;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  Eigen::VectorXd col_scale;
  std::vector<double> flat;
};

// ws.z = top rows of exp(h [[A, E], [0, 0]]) (Van Loan) = [Phi | int Phi E],
// with scaling and squaring. The top-right block is linear in each column of
// E, so every column of h E is first normalised to unit 1-norm and the result
// column scaled back: large or tiny input/drift magnitudes then neither
// inflate the norm (over-scaling: Eigen's exp() follows Higham 2005, without
// the fix of Al-Mohy & Higham 2009) nor drive the squarings.
void AffineExponential(const Frozen& f, double h, Workspace& ws) {
  const int n = ws.n, m1 = ws.m + 1;
  ws.aug.setZero();
  ws.aug.topLeftCorner(n, n) = h * f.a;
  for (int k = 0; k < m1; ++k) {
    const double c = std::abs(h) * f.e.col(k).lpNorm<1>();
    ws.col_scale[k] = (c > 0.0) ? c : 1.0;
    ws.aug.col(n + k).head(n) = (h / ws.col_scale[k]) * f.e.col(k);
  }
  const double norm = ws.aug.cwiseAbs().colwise().sum().maxCoeff();
  int squarings = 0;
  if (norm > kMaxExpNorm) {
    squarings = static_cast<int>(std::ceil(std::log2(norm / kMaxExpNorm)));
    ws.aug *= std::ldexp(1.0, -squarings);
  }
  ws.aug_exp = ws.aug.exp();
  for (int i = 0; i < squarings; ++i) {
    ws.aug_tmp.noalias() = ws.aug_exp * ws.aug_exp;
    ws.aug_exp.swap(ws.aug_tmp);
  }
  ws.z = ws.aug_exp.topRows(n);
  for (int k = 0; k < m1; ++k) ws.z.col(n + k) *= ws.col_scale[k];
}

// F(Y) = A Y + [0 | E] for the matrix ODE of the one-step map.
void MatrixRhs(const Frozen& f, const Eigen::MatrixXd& y, Eigen::MatrixXd& out, int n) {
  out.noalias() = f.a * y;
  out.rightCols(out.cols() - n) += f.e;
}

void StepEuler(const Frozen& f0, double h, Workspace& ws) {
  const int n = ws.n;
  ws.z.leftCols(n) = ws.identity + h * f0.a;
  ws.z.rightCols(ws.m + 1) = h * f0.e;
}

void StepTrapezoid(const Frozen& f0, const Frozen& f1, double h, Workspace& ws) {
  const int n = ws.n;
  ws.lhs = ws.identity - (0.5 * h) * f1.a;
  ws.rhs.leftCols(n) = ws.identity + (0.5 * h) * f0.a;
  ws.rhs.rightCols(ws.m + 1) = (0.5 * h) * (f0.e + f1.e);
  ws.lu.compute(ws.lhs);
  ws.z = ws.lu.solve(ws.rhs);
}

// Hermite-Simpson (thesis (4.52)-(4.55), D sign corrected) with the input
// held constant on the interval: the E terms (input columns and drift) are
//   h/6 [E_0 + 4 E_m + E_1 + h/2 A_m (E_0 - E_1)].
void StepHermiteSimpson(const Frozen& f0, const Frozen& fm, const Frozen& f1, double h,
                        Workspace& ws) {
  const int n = ws.n;
  const double h6 = h / 6.0;
  // M = I - h/6 (A_1 + 2 A_m - h/2 A_m A_1).
  ws.lhs.noalias() = (0.5 * h) * (fm.a * f1.a);
  ws.lhs = ws.identity - h6 * (f1.a + 2.0 * fm.a - ws.lhs);
  // N = I + h/6 (A_0 + 2 A_m + h/2 A_m A_0).
  auto n_block = ws.rhs.leftCols(n);
  n_block.noalias() = (0.5 * h) * (fm.a * f0.a);
  n_block = ws.identity + h6 * (f0.a + 2.0 * fm.a + n_block);
  auto e_block = ws.rhs.rightCols(ws.m + 1);
  e_block.noalias() = (0.5 * h) * (fm.a * (f0.e - f1.e));
  e_block = h6 * (f0.e + 4.0 * fm.e + f1.e + e_block);
  ws.lu.compute(ws.lhs);
  ws.z = ws.lu.solve(ws.rhs);
}

// Classical RK4 on Z' = A Z + [0 | E], Z(t0) = [I | 0], with `substeps`
// equal sub-steps; stage times are shared through the ScaledModel cache.
void StepRk4(ScaledModel& sm, double t0, double t1, int substeps, Workspace& ws) {
  const int n = ws.n;
  const double T = sm.time_scale();
  ws.z.setZero();
  ws.z.leftCols(n).setIdentity();
  const double len = t1 - t0;
  for (int i = 0; i < substeps; ++i) {
    const double ta = (i == 0) ? t0 : t0 + len * i / substeps;
    const double tb = (i == substeps - 1) ? t1 : t0 + len * (i + 1) / substeps;
    const double tm = ta + 0.5 * (tb - ta);
    const double h = (tb - ta) / T;
    const Frozen& fa = sm.At(ta);
    const Frozen& fm = sm.At(tm);
    const Frozen& fb = sm.At(tb);
    MatrixRhs(fa, ws.z, ws.k1, n);
    ws.y = ws.z + (0.5 * h) * ws.k1;
    MatrixRhs(fm, ws.y, ws.k2, n);
    ws.y = ws.z + (0.5 * h) * ws.k2;
    MatrixRhs(fm, ws.y, ws.k3, n);
    ws.y = ws.z + h * ws.k3;
    MatrixRhs(fb, ws.y, ws.k4, n);
    ws.z += (h / 6.0) * (ws.k1 + 2.0 * ws.k2 + 2.0 * ws.k3 + ws.k4);
  }
}

// Variational equations Z' = A Z + [0 | E] integrated adaptively.
void StepReference(ScaledModel& sm, double t0, double t1, internal::AdaptiveIntegrator& integ,
                   Workspace& ws) {
  const int n = ws.n, cols = ws.n + ws.m + 1;
  const double T = sm.time_scale();
  const double s_end = (t1 - t0) / T;
  const double s_snap = s_end * (1.0 - 1e-14);
  Eigen::Map<Eigen::MatrixXd> z0(ws.flat.data(), n, cols);
  z0.setZero();
  z0.leftCols(n).setIdentity();
  auto rhs = [&](const std::vector<double>& y, std::vector<double>& dy, double s) {
    const double t = (s >= s_snap) ? t1 : t0 + s * T;
    const Frozen& f = sm.At(t);
    Eigen::Map<const Eigen::MatrixXd> ym(y.data(), n, cols);
    Eigen::Map<Eigen::MatrixXd> dym(dy.data(), n, cols);
    dym.noalias() = f.a * ym;
    dym.rightCols(cols - n) += f.e;
  };
  integ.Integrate(rhs, ws.flat, s_end);
  ws.z = Eigen::Map<const Eigen::MatrixXd>(ws.flat.data(), n, cols);
}

void ValidateGrid(const std::vector<double>& grid) {
  if (grid.size() < 2) {
    throw std::invalid_argument(std::string(kWhere) + ": grid needs at least 2 points, got " +
                                std::to_string(grid.size()));
  }
  for (size_t j = 0; j < grid.size(); ++j) {
    if (!std::isfinite(grid[j])) {
      std::ostringstream msg;
      msg << kWhere << ": grid[" << j << "] is not finite (" << grid[j] << ")";
      throw std::invalid_argument(msg.str());
    }
    if (j > 0 && !(grid[j] > grid[j - 1])) {
      std::ostringstream msg;
      msg.precision(17);
      msg << kWhere << ": grid must be strictly increasing, but grid[" << j << "] = " << grid[j]
          << " <= grid[" << j - 1 << "] = " << grid[j - 1];
      throw std::invalid_argument(msg.str());
    }
  }
}

void ValidateOptions(const DiscretizationOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(std::string(kWhere) + ": " + error);
}

}  // namespace

std::string_view ToString(Scheme scheme) {
  switch (scheme) {
    case Scheme::kExactZoh:
      return "exact_zoh";
    case Scheme::kFrozenStart:
      return "frozen_start";
    case Scheme::kFrozenMid:
      return "frozen_mid";
    case Scheme::kHermiteSimpson:
      return "hermite_simpson";
    case Scheme::kRk4:
      return "rk4";
    case Scheme::kTrapezoid:
      return "trapezoid";
    case Scheme::kEuler:
      return "euler";
    case Scheme::kReference:
      return "reference";
  }
  return "unknown";
}

bool DiscretizationOptions::IsValid(std::string* error) const {
  if (rk4_substeps < 1) {
    return common::Fail(error, "rk4_substeps must be >= 1, got " + std::to_string(rk4_substeps));
  }
  const double tol = reference_tolerance;
  if (!std::isfinite(tol) || tol <= 0.0 || tol > 1e-3) {
    return common::Fail(error,
                        "reference_tolerance must be in (0, 1e-3], got " + common::FormatG(tol, 6));
  }
  return true;
}

std::vector<Scheme> AllSchemes() {
  return {Scheme::kExactZoh, Scheme::kFrozenStart, Scheme::kFrozenMid, Scheme::kHermiteSimpson,
          Scheme::kRk4,      Scheme::kTrapezoid,   Scheme::kEuler,     Scheme::kReference};
}

Scheme ParseScheme(std::string_view name) {
  std::string valid;
  for (Scheme s : AllSchemes()) {
    if (name == ToString(s)) return s;
    if (!valid.empty()) valid += ", ";
    valid += "'" + std::string(ToString(s)) + "'";
  }
  throw std::invalid_argument("ParseScheme: unknown scheme '" + std::string(name) +
                              "' (valid: " + valid + ")");
}

std::vector<double> UniformGrid(double t0, double t1, int num_intervals) {
  if (num_intervals < 1) {
    throw std::invalid_argument("UniformGrid: num_intervals must be >= 1, got " +
                                std::to_string(num_intervals));
  }
  if (!std::isfinite(t0) || !std::isfinite(t1) || !(t1 > t0)) {
    std::ostringstream msg;
    msg << "UniformGrid: need finite t0 < t1, got t0 = " << t0 << ", t1 = " << t1;
    throw std::invalid_argument(msg.str());
  }
  std::vector<double> grid(static_cast<size_t>(num_intervals) + 1);
  const double step = (t1 - t0) / num_intervals;
  for (int j = 0; j < num_intervals; ++j) grid[j] = t0 + step * j;
  grid[num_intervals] = t1;
  return grid;
}

DiscreteModel Discretize(const LinearModel& model, const Eigen::MatrixXd& input_columns,
                         const std::vector<double>& grid, const DiscretizationOptions& options) {
  ValidateGrid(grid);
  ValidateOptions(options);
  ScaledModel sm(model, input_columns, kWhere);
  const int n = sm.n(), m = sm.m();
  const double T = sm.time_scale();
  const int num_intervals = static_cast<int>(grid.size()) - 1;

  Scheme scheme = options.scheme;
  // Time-varying: no exact closed form, the exact ZOH map is what the
  // reference integration computes.
  if (scheme == Scheme::kExactZoh && !sm.time_invariant()) scheme = Scheme::kReference;

  DiscreteModel out;
  out.grid = grid;
  out.phi.reserve(num_intervals);
  out.gamma.reserve(num_intervals);
  out.drift.reserve(num_intervals);

  Workspace ws(n, m);
  internal::AdaptiveIntegrator integ(options.reference_tolerance, kWhere);
  const Eigen::VectorXd& sc = sm.scale();
  const Eigen::VectorXd& inv_sc = sm.inv_scale();
  double last_h = -1.0;  // nondimensional length of the last computed LTI step

  for (int j = 0; j < num_intervals; ++j) {
    const double t0 = grid[j], t1 = grid[j + 1];
    const double h = (t1 - t0) / T;
    if (sm.time_invariant() && last_h > 0.0 && std::abs(h - last_h) <= kLtiReuseTolerance * h) {
      out.phi.push_back(out.phi.back());
      out.gamma.push_back(out.gamma.back());
      out.drift.push_back(out.drift.back());
      continue;
    }
    switch (scheme) {
      case Scheme::kExactZoh:
      case Scheme::kFrozenStart:
        AffineExponential(sm.At(t0), h, ws);
        break;
      case Scheme::kFrozenMid:
        AffineExponential(sm.At(t0 + 0.5 * (t1 - t0)), h, ws);
        break;
      case Scheme::kHermiteSimpson: {
        const Frozen& f0 = sm.At(t0);
        const Frozen& fm = sm.At(t0 + 0.5 * (t1 - t0));
        const Frozen& f1 = sm.At(t1);
        StepHermiteSimpson(f0, fm, f1, h, ws);
        break;
      }
      case Scheme::kRk4:
        StepRk4(sm, t0, t1, options.rk4_substeps, ws);
        break;
      case Scheme::kTrapezoid: {
        const Frozen& f0 = sm.At(t0);
        const Frozen& f1 = sm.At(t1);
        StepTrapezoid(f0, f1, h, ws);
        break;
      }
      case Scheme::kEuler:
        StepEuler(sm.At(t0), h, ws);
        break;
      case Scheme::kReference:
        StepReference(sm, t0, t1, integ, ws);
        break;
    }
    // Back to SI: Phi = S Phi^ S^-1, Gamma = S Gamma^, drift = S drift^.
    out.phi.emplace_back(sc.asDiagonal() * ws.z.leftCols(n) * inv_sc.asDiagonal());
    out.gamma.emplace_back(sc.asDiagonal() * ws.z.middleCols(n, m));
    out.drift.emplace_back(sc.cwiseProduct(ws.z.col(n + m)));
    last_h = h;
  }
  return out;
}

}  // namespace thrustsched::dynamics
