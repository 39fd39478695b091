// Discretisation of a LinearModel over a time grid with on-off (piecewise
// constant) inputs:
//
//   x_{j+1} = Phi_j x_j + Gamma_j u_j + drift_j,     u_j in [0,1]^m held on [t_j, t_{j+1})
//
// where column i of the input matrix U (num_inputs x m, e.g.
// ThrusterSet::AccelerationMatrix()) is the acceleration of input i when on,
// so Gamma_j = "integral of Phi(t_{j+1}, s) B(s) ds" times U.
//
//   dynamics::DiscretizationOptions opt;
//   opt.scheme = dynamics::Scheme::kHermiteSimpson;
//   dynamics::DiscreteModel dm = dynamics::Discretize(model, thrusters.AccelerationMatrix(),
//                                                     dynamics::UniformGrid(0, 604800, 2016), opt);
//   Eigen::VectorXd x1 = dm.phi[0] * x0 + dm.gamma[0] * u0 + dm.drift[0];
//
// How: every scheme is a linear one-step method applied to the affine system
// with the input held constant on the interval (zero-order hold), i.e. to the
// augmented z = [x; u; 1], z' = [[A, B U, d], [0, 0, 0], [0, 0, 0]] z, so that
// Phi, Gamma and drift are blocks of one one-step map. All work is done on
// nondimensional matrices (time by model.time_scale(), states by
// model.state_scale()) and converted back to SI, so exponentials and
// tolerances act on numbers of order one.
//
// Schemes (order = global order for a smooth time-varying model):
//   kExactZoh       time-invariant: block matrix exponential (Van Loan) with
//                   scaling and squaring when ||M dt||_1 > 5.37: exact
//                   (HCW at GEO: 3e-15 relative at 1 day). Time-varying: there
//                   is no closed form, it is the same as kReference (same tolerance).
//   kFrozenStart    A, B, d frozen at t_j, exact exponential of the frozen
//                   system (the thesis "transition matrices" method). Order 1.
//   kFrozenMid      frozen at the midpoint (exponential midpoint rule). Order 2.
//   kHermiteSimpson thesis (4.52)-(4.55) with the drift sign corrected, order 4.
//                   On-off input: u_j is held over the whole interval, so B U
//                   (and d) enter at t_j, the midpoint and t_{j+1}, all times
//                   u_j; the thesis's piecewise-linear input (u_m = (u_j +
//                   u_{j+1})/2) is not an on-off input. The implicit scheme is
//                   solved for x_{j+1}:
//                     M = I - h/6 (A_1 + 2 A_m - h/2 A_m A_1)
//                     N = I + h/6 (A_0 + 2 A_m + h/2 A_m A_0)
//                     E = [B U, d]:  M [Phi | Gamma | drift] =
//                       [N | h/6 (E_0 + 4 E_m + E_1 + h/2 A_m (E_0 - E_1))].
//   kRk4            classical RK4 with `rk4_substeps` equal sub-steps. Order 4.
//   kTrapezoid      implicit trapezoid (Crank-Nicolson). Order 2.
//   kEuler          explicit Euler. Order 1.
//   kReference      variational equations Z' = A Z + [0 | E], Z(t_j) = [I | 0],
//                   integrated per interval by an adaptive Runge-Kutta-Fehlberg
//                   7(8) (Boost.Odeint) with absolute and relative tolerance
//                   `reference_tolerance` on the nondimensional Z.
// For the double integrator (A^2 = 0, constant B, d) RK4, Hermite-Simpson and
// the trapezoid rule are exact.
//
// Cost: Evaluate is called once for a time-invariant model (and intervals of
// equal length, to 1e-13 relative, share one step map). Time-varying models:
// per interval 1 call (Euler, frozen_*), 1 (trapezoid), 2 (Hermite-Simpson),
// 2 k (RK4 with k sub-steps), plus one at the first node where the scheme uses
// it: the shared endpoint of consecutive intervals is evaluated once. The
// reference needs ~9 calls per interval when one RKF78 step covers it.
#ifndef THRUSTSCHED_DYNAMICS_DISCRETISATION_H_
#define THRUSTSCHED_DYNAMICS_DISCRETISATION_H_

#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "dynamics/linear_model.h"

namespace thrustsched::dynamics {

enum class Scheme {
  kExactZoh,
  kFrozenStart,
  kFrozenMid,
  kHermiteSimpson,
  kRk4,
  kTrapezoid,
  kEuler,
  kReference,
};
/// Scenario-file names: "exact_zoh", "frozen_start", "frozen_mid",
/// "hermite_simpson", "rk4", "trapezoid", "euler", "reference".
std::string_view ToString(Scheme scheme);
/// @throws std::invalid_argument listing the valid names.
Scheme ParseScheme(std::string_view name);
std::vector<Scheme> AllSchemes();

struct DiscretizationOptions {
  Scheme scheme = Scheme::kExactZoh;
  int rk4_substeps = 1;
  double reference_tolerance = 1e-12;

  /// rk4_substeps >= 1; reference_tolerance finite and in (0, 1e-3]. On
  /// failure `*error` (if given) names the field and the value.
  bool IsValid(std::string* error) const;
};

struct DiscreteModel {
  std::vector<double> grid;            // t_0 < ... < t_N, seconds since model epoch
  std::vector<Eigen::MatrixXd> phi;    // N matrices n x n
  std::vector<Eigen::MatrixXd> gamma;  // N matrices n x m
  std::vector<Eigen::VectorXd> drift;  // N vectors n
  int num_intervals() const { return static_cast<int>(phi.size()); }
  int num_states() const { return phi.empty() ? 0 : static_cast<int>(phi[0].rows()); }
  int num_inputs() const { return gamma.empty() ? 0 : static_cast<int>(gamma[0].cols()); }
};

/// N equal intervals on [t0, t1]. @throws std::invalid_argument if N < 1,
/// t1 <= t0 or a bound is not finite.
std::vector<double> UniformGrid(double t0, double t1, int num_intervals);

/// @throws std::invalid_argument if the grid has < 2 points, is not strictly
///         increasing or not finite; if input_columns.rows() != model.num_inputs()
///         or holds non-finite values; if rk4_substeps < 1 or the tolerance is
///         not in (0, 1e-3]; if the model returns matrices of the wrong size or
///         non-finite values, or non-positive scales.
/// @throws std::runtime_error if the reference integration (kReference, or
///         kExactZoh on a time-varying model) cannot meet the tolerance (step
///         size underflow, e.g. a tolerance far below 1e-15).
DiscreteModel Discretize(const LinearModel& model, const Eigen::MatrixXd& input_columns,
                         const std::vector<double>& grid, const DiscretizationOptions& options);

// The names before the C++ API settled on -ize (as Minimize, Canonicalize).
using DiscretisationOptions [[deprecated("renamed DiscretizationOptions")]] = DiscretizationOptions;
[[deprecated("renamed Discretize")]] inline DiscreteModel Discretise(
    const LinearModel& model, const Eigen::MatrixXd& input_columns, const std::vector<double>& grid,
    const DiscretizationOptions& options) {
  return Discretize(model, input_columns, grid, options);
}

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_DISCRETISATION_H_
