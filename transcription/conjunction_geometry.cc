#include "transcription/conjunction_geometry.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <Eigen/LU>

#include "transcription/collision_probability.h"
#include "transcription/terminal_sets.h"

namespace thrustsched::transcription {
namespace {

// Local coordinates of a model state must be invertible to read the
// secondary's state and covariance given in that frame.
Eigen::MatrixXd InverseLocalMap(const AffineMap& local) {
  Eigen::FullPivLU<Eigen::MatrixXd> lu(local.map);
  if (local.map.rows() != local.map.cols() || !lu.isInvertible()) {
    throw std::invalid_argument("conjunction: the model's local coordinates are not invertible");
  }
  return lu.inverse();
}

}  // namespace

ConjunctionGeometry ComputeConjunctionGeometry(const ScheduleProblem& p,
                                               const dynamics::DiscreteModel& discrete,
                                               const dynamics::DiscretizationOptions& options) {
  if (!p.conjunction) throw std::invalid_argument("ComputeConjunctionGeometry: no conjunction");
  const ConjunctionSpec& c = *p.conjunction;
  std::string err;
  if (!c.IsValid(&err)) throw std::invalid_argument(err);
  const dynamics::LinearModel& model = *p.model;
  const int n = model.num_states();
  const int nn = p.num_intervals();
  if (n != 6 || discrete.num_intervals() != nn) {
    throw std::invalid_argument(
        "conjunction: needs a 6-state model and its discretisation on the grid");
  }
  ConjunctionGeometry g;
  g.polytope = c.EffectivePolytope();
  g.quantile = NormalUpperQuantile(c.instantaneous_threshold);

  // Covariance as given (local frame), repaired if asked.
  const Eigen::MatrixXd sigma_local =
      EffectiveCovariance(c, model.time_scale(), &g.covariance_min_eigenvalue);
  g.covariance_repaired =
      c.repair == CovarianceRepair::kClipEigenvalues && g.covariance_min_eigenvalue < 0.0;

  // Every time at which a map is needed: the checks and the state time.
  std::vector<double> times = c.CheckTimes(p.grid.front(), p.grid.back());
  times.push_back(c.state_time_s);
  std::vector<int> order(times.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return times[a] < times[b]; });
  std::vector<double> sorted;
  for (int i : order) sorted.push_back(times[i]);
  if (sorted.front() < p.grid.front() || sorted.back() > p.grid.back()) {
    throw std::invalid_argument(
        "conjunction: the check window and state_time_s must lie in the horizon");
  }
  const std::vector<PartialMap> maps =
      PartialMaps(model, p.thrusters.AccelerationMatrix(), p.grid, sorted, options);

  // Secondary state and covariance at the state time, then at the grid start.
  const int state_slot = static_cast<int>(
      std::find(order.begin(), order.end(), static_cast<int>(times.size()) - 1) - order.begin());
  const PartialMap& at_state = maps[state_slot];
  const AffineMap local = HcwCoordinates(model, c.state_time_s);
  const Eigen::MatrixXd to_state = InverseLocalMap(local);
  Eigen::VectorXd x = to_state * (c.secondary_state - local.offset);
  Eigen::MatrixXd cov = to_state * sigma_local * to_state.transpose();
  {
    const Eigen::MatrixXd back = at_state.phi.inverse();
    x = back * (x - at_state.drift);
    cov = back * cov * back.transpose();
  }
  for (int j = at_state.interval - 1; j >= 0; --j) {
    const Eigen::MatrixXd back = discrete.phi[j].inverse();
    x = back * (x - discrete.drift[j]);
    cov = back * cov * back.transpose();
  }
  g.secondary_state0 = x;
  g.covariance0 = 0.5 * (cov + cov.transpose());

  // Forward to every node, then to every check time.
  std::vector<Eigen::VectorXd> xs(nn + 1);
  std::vector<Eigen::MatrixXd> covs(nn + 1);
  xs[0] = g.secondary_state0;
  covs[0] = g.covariance0;
  for (int j = 0; j < nn; ++j) {
    xs[j + 1] = discrete.phi[j] * xs[j] + discrete.drift[j];
    covs[j + 1] = discrete.phi[j] * covs[j] * discrete.phi[j].transpose();
  }
  for (size_t s = 0; s < sorted.size(); ++s) {
    if (order[s] == static_cast<int>(times.size()) - 1) continue;  // the state time
    const PartialMap& m = maps[s];
    CheckGeometry k;
    k.map = m;
    const AffineMap at = HcwCoordinates(model, m.t);
    k.position = at.map.topRows(3);
    k.position_offset = at.offset.head(3);
    const Eigen::VectorXd xk = m.phi * xs[m.interval] + m.drift;
    const Eigen::MatrixXd ck = m.phi * covs[m.interval] * m.phi.transpose();
    k.secondary = k.position * xk + k.position_offset;
    k.covariance = k.position * ck * k.position.transpose();
    k.covariance = 0.5 * (k.covariance + k.covariance.transpose()).eval();
    k.margins.resize(g.polytope.size());
    for (int f = 0; f < g.polytope.size(); ++f) {
      const Eigen::Vector3d a = g.polytope.faces.row(f).transpose();
      k.margins[f] = g.quantile * std::sqrt(std::max(0.0, a.dot(k.covariance * a)));
    }
    g.checks.push_back(std::move(k));
  }
  return g;
}

}  // namespace thrustsched::transcription
