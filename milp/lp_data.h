// LpData: the frozen, solver-independent standard form of a MILP
//
//   min or max   col_cost' x + objective_offset
//   subject to   row_lower <= a_matrix x <= row_upper
//                col_lower <= x <= col_upper,   x_j integer for col_type[j] != kContinuous
//
// Field names follow HiGHS `HighsLp`. Solvers and file writers read only this
// struct; `Model::ToLpData()` produces it. Infinite bounds are +-kInfinity.
// An equality row has row_lower == row_upper; a free row has both infinite.
//
//   milp::LpData lp = model.ToLpData();
//   std::string error;
//   if (!lp.IsValid(&error)) throw std::invalid_argument(error);
//   double worst = lp.MaxViolation(x);   // 0 for a feasible x
//   double f = lp.Objective(x);          // c'x + offset, the model's own sense
#ifndef THRUSTSCHED_MILP_LP_DATA_H_
#define THRUSTSCHED_MILP_LP_DATA_H_

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "milp/variable.h"

namespace thrustsched::milp {

enum class ObjectiveSense { kMinimize, kMaximize };

/// Integer bounds rounded inward, after a 1e-9 relative allowance so that
/// 2.9999999999 still admits 3 (the convention the MPS/LP writers and the
/// solver backend share: GLPK rejects an integer column with a fractional
/// bound). Infinite bounds are returned unchanged; never -0.
double IntegerLowerBound(double lower);
double IntegerUpperBound(double upper);

struct LpData {
  std::string name;
  ObjectiveSense sense = ObjectiveSense::kMinimize;
  Eigen::VectorXd col_cost;
  double objective_offset = 0.0;
  Eigen::VectorXd col_lower, col_upper;
  Eigen::VectorXd row_lower, row_upper;
  /// rows x cols, column-major, compressed; no explicit zeros.
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> a_matrix;
  std::vector<VarType> col_type;
  /// Either empty (writers generate C000001 / R000001) or one per column/row.
  std::vector<std::string> col_names, row_names;

  int num_cols() const { return static_cast<int>(a_matrix.cols()); }
  int num_rows() const { return static_cast<int>(a_matrix.rows()); }
  int num_nonzeros() const { return static_cast<int>(a_matrix.nonZeros()); }
  int num_integer_cols() const;
  bool is_mip() const { return num_integer_cols() > 0; }

  /// Objective value c'x + offset at x (in the model's own sense).
  /// @throws std::invalid_argument if x.size() != num_cols().
  double Objective(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  /// Largest violation of bounds, rows and integrality (|x - round(x)|) at x,
  /// absolute; 0 if feasible, +inf if x holds NaN or inf.
  /// @throws std::invalid_argument if x.size() != num_cols().
  double MaxViolation(const Eigen::Ref<const Eigen::VectorXd>& x) const;

  /// Sizes agree, no NaN, finite costs/offset/coefficients, lower <= upper
  /// (and lower < +inf, upper > -inf), binaries within [0,1], row indices
  /// strictly increasing within each column, names non-empty and unique. On
  /// failure fills *error (if not null) naming the row/column and value.
  bool IsValid(std::string* error) const;
};

/// The model without its fixed columns (col_lower == col_upper): their values
/// folded into the row bounds and the objective offset, and the rows left
/// with no column dropped. A dropped row whose constant violates its bounds
/// by more than 1e-9 (relative) makes *feasible false (if not null).
/// `kept` (if not null) receives, for each remaining column, its index in
/// `lp`. Names are kept when `lp` has them. `kept_rows` (if not null)
/// receives, for each remaining row, its index in `lp`.
LpData RemoveFixedColumns(const LpData& lp, std::vector<int>* kept = nullptr,
                          bool* feasible = nullptr, std::vector<int>* kept_rows = nullptr);

/// A row to append: lower <= sum_k coefficients[k] * x[columns[k]] <= upper.
struct SparseRow {
  std::vector<int> columns;
  std::vector<double> coefficients;
  double lower = -kInfinity;
  double upper = kInfinity;
  std::string name;  // used when the model has row names ("" gets R<index>)
};

/// Appends `rows` after lp's own rows, rebuilding the matrix once.
/// @throws std::invalid_argument naming the row for a column out of range,
/// a repeated column or columns and coefficients of different lengths.
void AppendRows(LpData* lp, const std::vector<SparseRow>& rows);

/// A column to append (no matrix entries: AppendRows gives it its rows).
struct ColumnSpec {
  double lower = 0.0;
  double upper = kInfinity;
  double cost = 0.0;
  VarType type = VarType::kContinuous;
  std::string name;  // used when the model has column names ("" gets C<index>)
};

/// Appends empty columns after lp's own; returns the index of the first.
/// @throws std::invalid_argument naming the column for lower > upper or a
/// bound or cost that is NaN.
int AppendColumns(LpData* lp, const std::vector<ColumnSpec>& columns);

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_LP_DATA_H_
