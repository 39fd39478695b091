// MPS reader (target thrustsched::milp_cbc, built on CoinMpsIO), used for
// round-trip tests and by tools that take a model from another program.
//
//   milp::LpData lp = milp::ReadMpsFile("week.mps");
#ifndef THRUSTSCHED_MILP_MPS_READER_H_
#define THRUSTSCHED_MILP_MPS_READER_H_

#include <string>

#include "milp/lp_data.h"

namespace thrustsched::milp {

/// Reads free or fixed MPS. The result is always a minimisation; an OBJ_CONST
/// column written by WriteMps is kept as a column; integer columns with bounds
/// [0, 1] come back as kBinary. CoinMpsIO's own number parser is not
/// correctly rounded: most values written with %.17g come back exactly, but
/// e.g. 1e-20 reads as 9.9999999999999995e-21 and 1e-300 as 0.
/// @throws std::runtime_error naming the file if it cannot be opened, breaks
///         the section structure (naming the line and the keyword:
///         milp/internal/mps_structure.h), has read errors (with their count)
///         or gives an invalid model.
LpData ReadMpsFile(const std::string& path);

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_MPS_READER_H_
