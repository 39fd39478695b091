// Accuracy of a discretisation against the adaptive reference on the same
// grid (dynamics::Scheme::kReference), and log-log fits for observed orders
// and growth exponents.
//
//   dynamics::DiscreteModel dm = dynamics::Discretize(model, u, grid, {Scheme::kRk4});
//   dynamics::DiscreteModel ref = dynamics::Discretize(model, u, grid, {Scheme::kReference});
//   bench::DiscretizationError e = bench::CompareDiscretizations(dm, ref, model.state_scale());
//   double slope = bench::FitLogLogSlope({60, 300, 1800}, {e1, e2, e3}, 1e-12);
//
// Definitions (nondimensional with the model's state scale S = diag(s)):
//   rel_err_phi_j   = ||S^-1 (Phi_j - Phi*_j) S||_F / ||S^-1 Phi*_j S||_F
//   rel_err_gamma_j = ||S^-1 (Gamma_j - Gamma*_j)||_F / ||S^-1 Gamma*_j||_F
// (* = reference), and the reported value is the maximum over intervals j.
// These are one-step (local) errors. For a scheme of global order p the
// one-step map is wrong by O(h^(p+1)); Phi = I + O(h), so its relative error
// slope is p + 1, while Gamma = O(h), so its relative error slope is p.
// The global error propagates one fixed on-off pattern through both
// discrete models: max_j ||S^-1 (x_j - x*_j)||_inf / max_j ||S^-1 x*_j||_inf.
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_ACCURACY_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_ACCURACY_H_

#include <vector>

#include <Eigen/Core>

#include "dynamics/discretisation.h"

namespace thrustsched::bench {

struct DiscretizationError {
  double max_rel_err_phi = 0.0;
  double max_rel_err_gamma = 0.0;
  int worst_interval_phi = -1;
  int worst_interval_gamma = -1;
};

/// @throws std::invalid_argument if the two models do not have the same
///         grid size and matrix sizes, or the scale has the wrong size or a
///         non-positive entry.
DiscretizationError CompareDiscretizations(const dynamics::DiscreteModel& model,
                                           const dynamics::DiscreteModel& reference,
                                           const Eigen::VectorXd& state_scale);

/// x_{j+1} = Phi_j x_j + Gamma_j u_j + d_j with u_j = pattern.col(j) (0/1),
/// for both models from x0; returns the global relative error defined above.
/// @throws std::invalid_argument on size mismatches.
double GlobalPropagationError(const dynamics::DiscreteModel& model,
                              const dynamics::DiscreteModel& reference, const Eigen::VectorXd& x0,
                              const Eigen::MatrixXi& pattern, const Eigen::VectorXd& state_scale);

/// Least-squares slope of log(y) against log(x) over the points with
/// y > floor and x > 0 (both finite); NaN if fewer than two such points.
/// @throws std::invalid_argument if x and y differ in size.
double FitLogLogSlope(const std::vector<double>& x, const std::vector<double>& y,
                      double floor = 0.0);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_ACCURACY_H_
