#include "benchmarks/bench/accuracy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace thrustsched::bench {
namespace {

void CheckSameShape(const dynamics::DiscreteModel& a, const dynamics::DiscreteModel& b,
                    const Eigen::VectorXd& scale) {
  if (a.num_intervals() != b.num_intervals() || a.num_states() != b.num_states() ||
      a.num_inputs() != b.num_inputs()) {
    throw std::invalid_argument(
        "CompareDiscretizations: models differ in shape: " + std::to_string(a.num_intervals()) +
        " vs " + std::to_string(b.num_intervals()) + " intervals, " +
        std::to_string(a.num_states()) + " vs " + std::to_string(b.num_states()) + " states, " +
        std::to_string(a.num_inputs()) + " vs " + std::to_string(b.num_inputs()) + " inputs");
  }
  if (scale.size() != a.num_states()) {
    throw std::invalid_argument("CompareDiscretizations: state_scale has " +
                                std::to_string(scale.size()) + " entries, expected " +
                                std::to_string(a.num_states()));
  }
  for (int i = 0; i < scale.size(); ++i) {
    if (!(scale[i] > 0.0) || !std::isfinite(scale[i])) {
      throw std::invalid_argument("CompareDiscretizations: state_scale[" + std::to_string(i) +
                                  "] must be finite and > 0, got " + std::to_string(scale[i]));
    }
  }
}

}  // namespace

DiscretizationError CompareDiscretizations(const dynamics::DiscreteModel& model,
                                           const dynamics::DiscreteModel& reference,
                                           const Eigen::VectorXd& state_scale) {
  CheckSameShape(model, reference, state_scale);
  const Eigen::VectorXd inv = state_scale.cwiseInverse();
  DiscretizationError e;
  for (int j = 0; j < model.num_intervals(); ++j) {
    const Eigen::MatrixXd ref_phi = inv.asDiagonal() * reference.phi[j] * state_scale.asDiagonal();
    const Eigen::MatrixXd d_phi =
        inv.asDiagonal() * (model.phi[j] - reference.phi[j]) * state_scale.asDiagonal();
    const double ep = d_phi.norm() / std::max(ref_phi.norm(), 1e-300);
    if (ep > e.max_rel_err_phi || e.worst_interval_phi < 0) {
      e.max_rel_err_phi = ep;
      e.worst_interval_phi = j;
    }
    const Eigen::MatrixXd ref_gamma = inv.asDiagonal() * reference.gamma[j];
    const Eigen::MatrixXd d_gamma = inv.asDiagonal() * (model.gamma[j] - reference.gamma[j]);
    const double eg = d_gamma.norm() / std::max(ref_gamma.norm(), 1e-300);
    if (eg > e.max_rel_err_gamma || e.worst_interval_gamma < 0) {
      e.max_rel_err_gamma = eg;
      e.worst_interval_gamma = j;
    }
  }
  return e;
}

double GlobalPropagationError(const dynamics::DiscreteModel& model,
                              const dynamics::DiscreteModel& reference, const Eigen::VectorXd& x0,
                              const Eigen::MatrixXi& pattern, const Eigen::VectorXd& state_scale) {
  CheckSameShape(model, reference, state_scale);
  if (x0.size() != model.num_states() || pattern.rows() != model.num_inputs() ||
      pattern.cols() != model.num_intervals()) {
    throw std::invalid_argument("GlobalPropagationError: x0 has " + std::to_string(x0.size()) +
                                " entries and the pattern is " + std::to_string(pattern.rows()) +
                                " x " + std::to_string(pattern.cols()) + ", expected " +
                                std::to_string(model.num_states()) + " and " +
                                std::to_string(model.num_inputs()) + " x " +
                                std::to_string(model.num_intervals()));
  }
  const Eigen::VectorXd inv = state_scale.cwiseInverse();
  Eigen::VectorXd x = x0, xr = x0;
  double max_diff = 0.0, max_ref = inv.cwiseProduct(x0).lpNorm<Eigen::Infinity>();
  for (int j = 0; j < model.num_intervals(); ++j) {
    const Eigen::VectorXd u = pattern.col(j).cast<double>();
    x = model.phi[j] * x + model.gamma[j] * u + model.drift[j];
    xr = reference.phi[j] * xr + reference.gamma[j] * u + reference.drift[j];
    max_diff = std::max(max_diff, inv.cwiseProduct(x - xr).lpNorm<Eigen::Infinity>());
    max_ref = std::max(max_ref, inv.cwiseProduct(xr).lpNorm<Eigen::Infinity>());
  }
  return max_diff / std::max(max_ref, 1e-300);
}

double FitLogLogSlope(const std::vector<double>& x, const std::vector<double>& y, double floor) {
  if (x.size() != y.size()) {
    throw std::invalid_argument("FitLogLogSlope: " + std::to_string(x.size()) + " x values but " +
                                std::to_string(y.size()) + " y values");
  }
  std::vector<double> lx, ly;
  for (size_t i = 0; i < x.size(); ++i) {
    if (std::isfinite(x[i]) && std::isfinite(y[i]) && x[i] > 0.0 && y[i] > floor && y[i] > 0.0) {
      lx.push_back(std::log(x[i]));
      ly.push_back(std::log(y[i]));
    }
  }
  const size_t n = lx.size();
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  double mx = 0, my = 0;
  for (size_t i = 0; i < n; ++i) {
    mx += lx[i];
    my += ly[i];
  }
  mx /= n;
  my /= n;
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < n; ++i) {
    sxy += (lx[i] - mx) * (ly[i] - my);
    sxx += (lx[i] - mx) * (lx[i] - mx);
  }
  if (sxx <= 0.0) return std::numeric_limits<double>::quiet_NaN();
  return sxy / sxx;
}

}  // namespace thrustsched::bench
