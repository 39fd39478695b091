// Writers for MPS (free and fixed) and CPLEX LP files. No COIN-OR dependency:
// output is deterministic and byte-for-byte testable.
//
//   milp::WriteMpsFile("week.mps", lp);                         // free MPS
//   milp::WriteLpFile("week.lp", lp);                           // CPLEX LP
//   milp::MpsOptions o; o.obfuscate_names = true;               // C000001 / R000001
//
// Conventions (each guards against a pitfall some reader hits, since MPS is
// not standardised: e.g. CBC 2.10 reads a two-line OBJSENSE MAX and still
// minimises, glpsol rejects OBJSENSE): numbers with %.17g (exact double round
// trip); minimisation only (a maximisation model is written with negated
// costs, and the header comment says so); a nonzero objective offset becomes a
// column OBJ_CONST fixed to 1 with cost = offset; integer columns between quoted
// 'MARKER' 'INTORG'/'INTEND' lines and always with explicit LO and UP bounds
// (binary: LO 0, UP 1); infinite bounds as MI/PL/FR; RANGES only for ranged
// rows (finite lower < finite upper); names sanitised (no spaces or characters
// readers reject, unique after sanitising) or obfuscated on request. Fixed MPS
// is written only when every name fits 8 characters, otherwise
// std::invalid_argument; its numbers must fit 12-character fields, so they
// keep full precision only when they fit (free MPS is the exact format), and
// its offset column is called OBJCONST.
//
// Name rules (shared by MPS and LP so that one name list serves both):
// letters, digits, '_', '.', '(' and ')' ('[' -> '(', ']' -> ')', anything
// else -> '_'); a leading digit, '.', or exponent-like 'e1'/'E'/'ee' gets a
// '_' prefix, as do LP keywords (st, bounds, free, inf, end, ...); at most 96
// characters; duplicates (and the reserved OBJ, OBJ_CONST, OBJCONST) get the
// smallest free suffix "_k". Missing names become C000001 / R000001.
// Integer bounds are written rounded inward (GLPK rejects fractional bounds on
// integer columns): 0..3.5 becomes 0..3, never a binary.
#ifndef THRUSTSCHED_MILP_MODEL_IO_H_
#define THRUSTSCHED_MILP_MODEL_IO_H_

#include <ostream>
#include <string>
#include <vector>

#include "milp/lp_data.h"

namespace thrustsched::milp {

struct MpsOptions {
  bool free_format = true;
  bool obfuscate_names = false;
};

/// Streams the model (nothing is buffered whole).
/// @throws std::invalid_argument if !problem.IsValid(), or if fixed format is
///         asked for and an exported name has more than 8 characters.
void WriteMps(std::ostream& out, const LpData& problem, const MpsOptions& options = {});
/// @throws as WriteMps.
std::string ToMpsString(const LpData& problem, const MpsOptions& options = {});
/// @throws std::runtime_error naming the path on I/O failure; as WriteMps.
void WriteMpsFile(const std::string& path, const LpData& problem, const MpsOptions& options = {});

struct LpFormatOptions {
  bool obfuscate_names = false;
};
/// CPLEX LP: "Minimize / Subject To / Bounds / Generals / Binaries / End".
/// A ranged row  l <= a'x <= u  is written as  a'x - ~row = l  with a column
/// 0 <= ~row <= u - l, and a free row as  a'x - ~row = 0  with ~row free
/// (GLPK's own convention; neither CBC nor GLPK reads "l <= a'x <= u").
/// Integer columns get explicit bounds; only binaries with bounds exactly
/// [0, 1] go to Binaries. Columns used nowhere else appear with cost 0. A
/// model without rows gets the always-true row "~no_rows: 0 x >= -1" (GLPK
/// rejects an empty Subject To section); a model without columns gets the
/// fixed column OBJ_CONST.
/// @throws std::invalid_argument if !problem.IsValid().
void WriteLp(std::ostream& out, const LpData& problem, const LpFormatOptions& options = {});
/// @throws as WriteLp.
std::string ToLpString(const LpData& problem, const LpFormatOptions& options = {});
/// @throws std::runtime_error naming the path on I/O failure; as WriteLp.
void WriteLpFile(const std::string& path, const LpData& problem,
                 const LpFormatOptions& options = {});

/// The column and row names exactly as the writers emit them (sanitised or
/// obfuscated, deduplicated), so a solution file of another solver can be
/// mapped back to columns.
std::vector<std::string> ExportedColumnNames(const LpData& problem, bool obfuscate);
std::vector<std::string> ExportedRowNames(const LpData& problem, bool obfuscate);

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_MODEL_IO_H_
