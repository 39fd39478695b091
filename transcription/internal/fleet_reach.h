// The positions (or any linear map of the state) of one fleet member at a set
// of times, as affine functions of its MILP's columns, and their exact range
// over every on-off plan: what the fleet's keep-out and assignment big-M are
// derived from (transcription/fleet.h). The range is that of
// transcription/internal/keep_out_bounds.h (Effects, KnapsackRange) with no
// cost budget: each binary anywhere in [0, 1].
//
//   internal::MemberReach reach(member_milp, {position_map}, check_times, options);
//   auto [low, high] = reach.Range(q, a);               // a^T map x(t_q)
//   double drift = reach.AddPositionTerms(q, a, +1.0, offset, add_coef);
#ifndef THRUSTSCHED_TRANSCRIPTION_INTERNAL_FLEET_REACH_H_
#define THRUSTSCHED_TRANSCRIPTION_INTERNAL_FLEET_REACH_H_

#include <utility>
#include <vector>

#include <Eigen/Core>

#include "transcription/internal/keep_out_bounds.h"
#include "transcription/keep_out.h"
#include "transcription/partial_maps.h"
#include "transcription/schedule_milp.h"

namespace thrustsched::transcription::internal {

/// The state scale S of a member's MILP (x = S x~ on its state columns).
Eigen::VectorXd StateScale(const ScheduleMilp& milp);

class MemberReach {
 public:
  /// maps: one (rows x n) per time, or one for every time; times sorted
  /// inside the member's grid. Keeps a reference to `milp`.
  /// @throws std::invalid_argument if maps has neither one matrix nor one
  ///         per time.
  MemberReach(const ScheduleMilp& milp, std::vector<Eigen::MatrixXd> maps,
              const std::vector<double>& times, const BuildOptions& options);

  /// Lowest and highest a^T map x(times[q]) over every on-off plan (exact
  /// over the box of binaries: the member's own rules only narrow it).
  std::pair<double, double> Range(int q, const Eigen::VectorXd& a) const;

  /// Covariance of map x(times[q]) for an initial-state covariance sigma0 at
  /// the grid start (n x n, SI): map Phi(t_q, t_0) sigma0 Phi^T map^T, the
  /// MILP's own transition maps; the thrust does not change it.
  Eigen::MatrixXd MapCovariance(int q, const Eigen::MatrixXd& sigma0) const;

  /// Calls add(column, coefficient) for sign * a^T map x(times[q]) written on
  /// the member's state columns at the interval's start node and its on-off
  /// columns of that interval (column indices shifted by `offset`, the
  /// member's first column in the fleet model); returns the constant part
  /// a^T map drift (unsigned), which the caller moves into the row bounds.
  template <typename Add>
  double AddPositionTerms(int q, const Eigen::VectorXd& a, double sign, int offset,
                          Add&& add) const {
    const PartialMap& at = maps_[q];
    const Eigen::MatrixXd& map = MapAt(q);
    const Eigen::RowVectorXd on_state = a.transpose() * map * at.phi;
    const Eigen::RowVectorXd on_thrust = a.transpose() * map * at.gamma;
    const int j = at.interval;
    for (int c = 0; c < on_state.size(); ++c)
      add(offset + milp_.state(j, c).index(), sign * on_state[c] * scale_[c]);
    for (int i = 0; i < on_thrust.size(); ++i)
      add(offset + milp_.on(i, j).index(), sign * on_thrust[i]);
    return a.dot(map * at.drift);
  }

  /// map x(times[q]) (3 rows: a position) of the member's block of the
  /// column vector x (its columns from `offset`), as the MILP writes it.
  Eigen::Vector3d Position(int q, int offset, const Eigen::VectorXd& x) const {
    Eigen::Vector3d r;
    for (int i = 0; i < 3; ++i) {
      double terms = 0.0;
      const double drift = AddPositionTerms(q, Eigen::Vector3d::Unit(i), 1.0, offset,
                                            [&](int c, double v) { terms += v * x[c]; });
      r[i] = terms + drift;
    }
    return r;
  }

 private:
  const Eigen::MatrixXd& MapAt(int q) const {
    return maps_at_.size() == 1 ? maps_at_[0] : maps_at_[q];
  }

  const ScheduleMilp& milp_;
  std::vector<Eigen::MatrixXd> maps_at_;
  Eigen::VectorXd scale_;
  std::vector<PartialMap> maps_;
  std::vector<Eigen::VectorXd> free_;        // thrust-free states at the nodes
  std::vector<Eigen::MatrixXd> transition_;  // Phi(t_j, t_0) at the nodes
  KeepOutColumns cols_;
  std::vector<std::vector<Effect>> effects_;  // per time
};

}  // namespace thrustsched::transcription::internal

#endif  // THRUSTSCHED_TRANSCRIPTION_INTERNAL_FLEET_REACH_H_
