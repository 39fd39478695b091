// The structure of an MPS file, checked before CoinMpsIO reads it
// (milp/mps_reader.cc). CoinMpsIO (CoinUtils 2.11) trusts the layout: a
// section that appears twice, a section missing or out of order, a stray
// word in column 1 or a byte outside printable ASCII made it dereference
// null or ask malloc for ~2^64 bytes (found by tests/fuzz/mps_fuzz.cc).
//
//   std::ifstream in(path);
//   milp::internal::CheckMpsStructure(path, in);   // throws before CoinMpsIO sees it
//
// Accepted: comment lines ('*' in column 1) and blank lines anywhere; section
// headers in column 1 (NAME, OBJSENSE/OBJSENS, ROWS, COLUMNS, RHS, RANGES,
// BOUNDS, SOS, the quadratic sections, ENDATA), each at most once, NAME first
// (CoinMpsIO asked malloc for ~2^64 bytes without it), ROWS before
// COLUMNS before RHS, RANGES and BOUNDS, ENDATA last; data lines indented;
// tabs and printable ASCII only; fields and lines that fit CoinMpsIO's fixed
// buffers (159 and 879 characters: a longer problem name overflowed one).
#ifndef THRUSTSCHED_MILP_INTERNAL_MPS_STRUCTURE_H_
#define THRUSTSCHED_MILP_INTERNAL_MPS_STRUCTURE_H_

#include <istream>
#include <string>

namespace thrustsched::milp::internal {

/// @throws std::runtime_error "ReadMpsFile: '<path>' line <n>: <keyword or
///         text>: <why>" on the first violation.
void CheckMpsStructure(const std::string& path, std::istream& in);

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_MPS_STRUCTURE_H_
