// Nets of free slots around a relaxation point: the masks (thrusters x
// intervals, 1 = free) the search's restricted MILPs are built over.
//
//   Eigen::MatrixXi net = WideningMask(state, state.relaxation().x, /*level=*/0);
//   Eigen::MatrixXi all = FiredThrusterSlots(state, leaf_x);
//
// Contract: a net never frees a slot the MILP fixes off, never frees the
// dormant thrusters' slots (the nets only look for schedules), and always
// frees the incumbent's slots and the slots fixed on.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_SLOT_NETS_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_SLOT_NETS_H_

#include <Eigen/Core>

#include "transcription/search/search_state.h"

namespace thrustsched::transcription {

/// Slots a point `x` uses (on-value above `threshold`, with the slots fixed
/// on and the incumbent's), and the same thruster's within `k` intervals of
/// them; `all_thrusters` frees every thruster there.
Eigen::MatrixXi CandidateSlots(const SearchState& state, const Eigen::VectorXd& x, double threshold,
                               int k, bool all_thrusters);

/// The net of widening level w around `x`: threshold / 10^w, the
/// neighbourhood doubled w times, every thruster from level 1 on
/// (SearchOptions::nets).
Eigen::MatrixXi WideningMask(const SearchState& state, const Eigen::VectorXd& x, int level);

/// Every slot of the thrusters `x` fires (their total on-value at least the
/// nets' candidate threshold).
Eigen::MatrixXi FiredThrusterSlots(const SearchState& state, const Eigen::VectorXd& x);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_SLOT_NETS_H_
