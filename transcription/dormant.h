// Thrusters an optimal schedule can leave off: those whose subsystem stays
// within its constraints without them.
//
//   transcription::DormantThrusters d = transcription::FindDormantThrusters(milp);
//   if (d.any()) {
//     // d.thruster[i]: thruster i may stay off in every slot at no cost;
//     // d.column[c]:   column c belongs to their blocks, d.all_off[c] its value
//     //                when they stay off (states coasting)
//   }
//
// Why: in the Hill-Clohessy-Wiltshire equations the out-of-plane motion is
// independent of the in-plane one, and the on-off rules tie the thrusters
// only by rows that limit firing together (at most K on, a gap between two
// thrusters' burns). A transfer that starts out of plane only (thesis
// Table 4.2) has an in-plane block that coasts inside its box: its four
// thrusters are never needed, yet they are two thirds of the MILP and, with
// the coupling rows, most of the fill of the interior point's Cholesky
// factor (measured on Table 4.2, t1 = 2 d: 5.0 s for the LP with them, 0.7 s
// without).
//
// Exactness: the blocks are the connected components of the MILP's columns
// over its rows, the rows that only hold the operational encoding's columns
// of two or more thrusters set aside (milp::ColumnBlocks). Removing every
// burn of some thrusters never breaks an on-off rule (operations.h: burn and
// rest lengths are per thruster; the gap between thrusters and the limit on
// simultaneous firing only get easier), and the encodings accept exactly the
// patterns the rules accept, so a block whose all-off point satisfies its
// own rows and column bounds can be switched off in any schedule, at no
// cost (costs are >= 0) and without touching the other blocks' rows. The
// search only uses this to make its LP smaller; its bound stays the safe dual
// bound of the whole MILP (milp/lp_bound.h) and every schedule is verified on
// the whole MILP, so neither relies on it.
#ifndef THRUSTSCHED_TRANSCRIPTION_DORMANT_H_
#define THRUSTSCHED_TRANSCRIPTION_DORMANT_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "transcription/schedule_milp.h"

namespace thrustsched::transcription {

struct DormantThrusters {
  std::vector<bool> thruster;  // per thruster
  std::vector<bool> column;    // per column of the MILP: in a dormant block
  Eigen::VectorXd all_off;     // the MILP's point with every thruster off
  /// Blocks of the MILP without the rows that tie several thrusters
  /// (1: nothing to split). A column found only in such rows is a block of
  /// its own: each shared gamma column of the thesis encoding (Gazzino
  /// 2018, sec. 4.2.1) is, so a GEO week counts thousands of blocks with
  /// its orbit plane and normal in one. Two or more blocks do not mean
  /// that the thrusters split.
  int num_blocks = 0;

  bool any() const;
  /// "+R, +T" (names of the dormant thrusters).
  std::string Names(const ScheduleMilp& milp) const;
};

/// As above, for an on-off MILP whose objective costs are >= 0 (otherwise,
/// or in impulsive mode, nothing is dormant).
DormantThrusters FindDormantThrusters(const ScheduleMilp& milp);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_DORMANT_H_
