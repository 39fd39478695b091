// Independent blocks of a model: the connected components of its columns,
// two columns being joined by every row that has both (rows the caller
// names as coupling excepted).
//
//   std::vector<bool> coupling(lp.num_rows(), false);   // e.g. rows that only
//   coupling[r] = true;                                 // limit firing together
//   int blocks = 0;
//   std::vector<int> block = milp::ColumnBlocks(lp, coupling, &blocks);
//   // block[j] in [0, blocks): columns j, k share a block iff a chain of
//   // non-coupling rows links them; blocks are numbered by their first column.
//
// Why: a model made of subsystems that only the coupling rows tie together
// (the in-plane and out-of-plane motions of the Hill-Clohessy-Wiltshire
// equations, say, tied by "one thruster at a time") can be reduced block by
// block; the caller decides what a block may drop (transcription/dormant.h).
#ifndef THRUSTSCHED_MILP_LP_BLOCKS_H_
#define THRUSTSCHED_MILP_LP_BLOCKS_H_

#include <vector>

#include "milp/lp_data.h"

namespace thrustsched::milp {

/// Block index of each column (see above); `coupling` has one entry per row
/// (empty: no coupling row). *num_blocks (if not null) receives the count.
/// @throws std::invalid_argument if `coupling` has the wrong size.
std::vector<int> ColumnBlocks(const LpData& lp, const std::vector<bool>& coupling,
                              int* num_blocks = nullptr);

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_LP_BLOCKS_H_
