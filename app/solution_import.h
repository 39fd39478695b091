// Readers for solution files of other MILP solvers, so that a model exported
// with `thrustsched export` (or `solve --export-mps`) and solved elsewhere can
// be mapped back to a schedule by the exported column names
// (milp::ExportedColumnNames; on-off binaries are named on_<thruster>_<interval>).
//
//   cbc model.mps sec 60 solve solu cbc.sol                   -> --format cbc
//   glpsol --freemps model.mps --tmlim 60 -o glpsol.txt        -> --format glpsol
//
//   app::ImportedSolution sol = app::ReadSolutionFile("cbc.sol", app::SolutionFormat::kCbc);
//   Eigen::VectorXd x = app::ToColumnVector(sol, milp::ExportedColumnNames(lp, false));
//   transcription::Schedule s = schedule_milp.Decode(x);
#ifndef THRUSTSCHED_APP_SOLUTION_IMPORT_H_
#define THRUSTSCHED_APP_SOLUTION_IMPORT_H_

#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace thrustsched::app {

enum class SolutionFormat {
  kCbc,      // `cbc ... solve solu FILE`: status line, then "index name value reduced_cost"
  kGlpsol,   // `glpsol ... -o FILE`: GLPK's printable report (columns section by name;
             // activities printed with 6 significant digits)
  kGlpkRaw,  // `glpsol ... -w FILE`: GLPK's raw solution (full precision, columns by
             // index in the exported order; the column count must match)
};
/// "cbc" | "glpsol" | "glpsol-raw". @throws ScenarioError listing the names.
SolutionFormat ParseSolutionFormat(std::string_view name);

struct ImportedSolution {
  std::string status;         // the solver's own words, e.g. "Optimal", "INTEGER OPTIMAL"
  bool has_solution = false;  // an integer-feasible point was reported
  double objective = std::numeric_limits<double>::quiet_NaN();  // as reported
  std::map<std::string, double> values;                         // column name -> value
  std::vector<double> values_by_index;  // kGlpkRaw: value of column j at [j - 1]
};

/// Largest column index or count a solution file may give: above the
/// columns of any model thrustsched exports (kMaxIntervals intervals), so
/// that a corrupt count fails instead of allocating gigabytes.
inline constexpr long kMaxSolutionColumns = 10'000'000;

/// @throws ScenarioError naming the file and line on unreadable content
/// (also a column index or count that is not an integer in
/// [0, kMaxSolutionColumns]).
ImportedSolution ReadSolutionFile(const std::string& path, SolutionFormat format);
/// ReadSolutionFile of text already read; `source` names it in messages.
ImportedSolution ParseSolutionText(std::string_view text, SolutionFormat format,
                                   const std::string& source);

/// Values in the order of `column_names`; columns absent from the file are 0
/// (CBC omits zero columns). @throws ScenarioError if the file names a
/// column that is not in `column_names`, or (raw files) has another number
/// of columns (wrong model).
Eigen::VectorXd ToColumnVector(const ImportedSolution& solution,
                               const std::vector<std::string>& column_names);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_SOLUTION_IMPORT_H_
