// Model: builder for a mixed-integer linear program, frozen by ToLpData().
//
//   #include "milp/model.h"
//   namespace milp = thrustsched::milp;
//   milp::Model model("knapsack");
//   milp::VarBlock take = model.AddVariables(3, 0, 1, milp::VarType::kBinary, "take");
//   model.AddConstraint(milp::LinearExpr::InnerProduct(Eigen::Vector3d(2, 3, 4), take) <= 5,
//                       "weight");
//   model.Maximize(milp::LinearExpr::InnerProduct(Eigen::Vector3d(3, 4, 5), take));
//   milp::LpData lp = model.ToLpData();      // column-major standard form
//
// Two ways to add rows: one expression at a time (AddConstraint), or in bulk
// from sparse triplets (AddRows), which is the fast path for transcriptions
// with 10^5 columns and 10^6 nonzeros.
//
// Errors: every misuse (NaN or infinite coefficient, lower > upper, NaN bound,
// binary bounds outside [0,1], duplicate names, a variable of another model,
// size mismatch) throws std::invalid_argument naming the variable or row, and
// leaves the model unchanged.
// Memory: rows are stored as (row, column, value) nonzeros until ToLpData(),
// which builds the compressed column-major matrix in O(nnz) (no sort).
// Names: unnamed columns/rows get "c<index>"/"r<index>" (a suffix "_1", "_2"
// is added only if such a name was also given explicitly); blocks get
// "<prefix>[i]". Names are made on request, never stored per element.
#ifndef THRUSTSCHED_MILP_MODEL_H_
#define THRUSTSCHED_MILP_MODEL_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "milp/linear_expr.h"
#include "milp/lp_data.h"
#include "milp/variable.h"

namespace thrustsched::milp {

/// Handle to one row.
struct Constraint {
  int index = -1;
};
/// Handle to rows [start, start + size).
struct ConstraintBlock {
  int start = 0;
  int size = 0;
};

/// One nonzero of a bulk row block: `row` is relative to the block,
/// `column` is the absolute column index (Variable::index()).
struct RowTriplet {
  int row;
  int column;
  double value;
};

class Model {
 public:
  explicit Model(std::string name = "");
  Model(Model&&) = default;
  Model& operator=(Model&&) = default;
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  const std::string& name() const { return name_; }
  /// Unique per Model object (process-wide atomic counter, never 0).
  std::uint32_t id() const { return id_; }

  /// Empty name -> generated "c<index>" (made only when asked for, so unnamed
  /// columns cost nothing). Infinite bounds allowed.
  /// @throws std::invalid_argument if a bound is NaN, lower > upper,
  ///         lower == +inf or upper == -inf, a binary has bounds outside
  ///         [0, 1], or the name is already used by another column.
  Variable AddVariable(double lower, double upper, VarType type, std::string name = "");
  /// @throws as AddVariable.
  Variable AddContinuous(double lower, double upper, std::string name = "");
  /// @throws as AddVariable.
  Variable AddInteger(double lower, double upper, std::string name = "");
  /// Binary in [0, 1]. @throws std::invalid_argument on a duplicate name.
  Variable AddBinary(std::string name = "");
  /// `count` columns named "<prefix>[i]" (or unnamed if prefix is empty).
  /// @throws as AddVariable, or if count < 0, or if the prefix was already
  ///         used by another block (its names would collide).
  VarBlock AddVariables(int count, double lower, double upper, VarType type,
                        std::string_view name_prefix = "");
  /// @throws std::invalid_argument for a variable of another model or the
  ///         bound errors of AddVariable.
  void SetBounds(Variable v, double lower, double upper);
  /// @throws std::invalid_argument for a variable of another model, or kBinary
  ///         while the bounds are outside [0, 1].
  void SetType(Variable v, VarType type);

  /// lower <= expr <= upper; the expression constant is moved into the bounds.
  /// Empty name -> generated "r<index>".
  /// @throws std::invalid_argument naming the row if a bound is NaN, lower >
  ///         upper, lower == +inf or upper == -inf, a coefficient or the
  ///         constant is NaN or infinite, the expression holds a variable of
  ///         another model (or an invalid handle), or the name is taken.
  Constraint AddConstraint(const LinearExpr& expr, double lower, double upper,
                           std::string name = "");
  /// @throws as above.
  Constraint AddConstraint(const BoundedLinearExpr& c, std::string name = "");

  /// Bulk add: rows [0, lower.size()) of the block, nonzeros from triplets
  /// (duplicates summed, exact zeros dropped). Names "<prefix>[i]" or `names`
  /// if non-empty (names win over the prefix); unnamed if both are empty.
  /// @throws std::invalid_argument naming the row if lower/upper/names sizes
  ///         differ, a triplet's row or column is out of range, a value is NaN
  ///         or infinite, a bound is invalid (as AddConstraint), or a name or
  ///         prefix is already used. Nothing is added when it throws.
  ConstraintBlock AddRows(const std::vector<RowTriplet>& triplets,
                          const Eigen::Ref<const Eigen::VectorXd>& lower,
                          const Eigen::Ref<const Eigen::VectorXd>& upper,
                          std::string_view name_prefix = "", std::vector<std::string> names = {});
  /// Bulk add: lower <= A * vars <= upper, vars.size() == A.cols().
  /// @throws as the triplet overload, or if vars.size() != A.cols() or a
  ///         variable belongs to another model.
  ConstraintBlock AddRows(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                          const std::vector<Variable>& vars,
                          const Eigen::Ref<const Eigen::VectorXd>& lower,
                          const Eigen::Ref<const Eigen::VectorXd>& upper,
                          std::string_view name_prefix = "");
  /// Same, with the columns of one block.
  ConstraintBlock AddRows(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                          const VarBlock& vars, const Eigen::Ref<const Eigen::VectorXd>& lower,
                          const Eigen::Ref<const Eigen::VectorXd>& upper,
                          std::string_view name_prefix = "");

  /// Replaces the objective (costs and offset = expr constant).
  /// @throws std::invalid_argument if a coefficient or the constant is NaN or
  ///         infinite, or a variable belongs to another model.
  void Minimize(const LinearExpr& objective);
  /// @throws as Minimize.
  void Maximize(const LinearExpr& objective);
  /// Adds c * v to the current objective (sense unchanged).
  /// @throws std::invalid_argument if c is not finite or v is foreign.
  void AddObjectiveTerm(Variable v, double c);
  ObjectiveSense sense() const { return sense_; }
  double objective_offset() const { return objective_offset_; }

  int num_variables() const { return static_cast<int>(col_lower_.size()); }
  int num_constraints() const { return static_cast<int>(row_lower_.size()); }
  int num_nonzeros() const { return static_cast<int>(entries_.size()); }
  int num_integer_variables() const;
  Variable variable(int index) const;  // throws std::out_of_range
  /// Explicit, block ("<prefix>[i]") or generated ("c<index>") name.
  /// @throws std::invalid_argument for a variable of another model.
  std::string variable_name(Variable v) const;
  /// @throws std::invalid_argument for a variable of another model.
  double lower_bound(Variable v) const;
  /// @throws std::invalid_argument for a variable of another model.
  double upper_bound(Variable v) const;
  /// @throws std::invalid_argument for a variable of another model.
  VarType type(Variable v) const;
  double objective_coefficient(Variable v) const;
  /// Explicit, block or generated ("r<index>") name.
  /// @throws std::out_of_range for an index outside [0, num_constraints()).
  std::string constraint_name(Constraint c) const;

  /// Freezes into column-major standard form with every name filled in.
  /// The Model stays usable.
  LpData ToLpData() const;

 private:
  // Names of columns or of rows. Explicit names are stored; names of blocks
  // ("<prefix>[i]") and generated names ("c<index>") are made on request, so
  // 10^6 unnamed rows cost 4 bytes each.
  class NameTable {
   public:
    explicit NameTable(char generated_prefix) : generated_prefix_(generated_prefix) {}
    int size() const { return static_cast<int>(slot_.size()); }
    // Throw std::invalid_argument (mentioning `what`) if the name is taken.
    void CheckNew(const std::string& name, const char* what) const;
    void CheckNewBlock(std::string_view prefix, int count, const char* what) const;
    void AddUnnamed(int count);
    void AddNamed(std::string name);
    void AddBlock(std::string_view prefix, int count);
    std::string Name(int index) const;
    void AppendAll(std::vector<std::string>* out) const;

   private:
    std::string Generated(int index) const;
    char generated_prefix_;
    // Per entry: >= 0 index into explicit_; -1 unnamed; <= -2 block -2 - k.
    std::vector<int> slot_;
    std::vector<std::string> explicit_;
    struct Block {
      std::string prefix;
      int start;
      int count;
    };
    std::vector<Block> blocks_;
    std::unordered_map<std::string, int> explicit_index_;  // name -> entry
    std::unordered_map<std::string, int> block_index_;     // prefix -> block
    // Explicit names of the form "p[k]": p -> k values, to detect collisions
    // with a block "p" added later.
    std::unordered_map<std::string, std::vector<long long>> bracketed_;
  };

  void CheckOwned(Variable v, std::string_view what) const;
  std::string ColumnLabel(int index) const;
  void CheckColumnBounds(double lower, double upper, VarType type, const std::string& label) const;
  void CheckRowBounds(double lower, double upper, const std::string& label) const;
  void SetObjective(const LinearExpr& objective, ObjectiveSense sense);

  struct Entry {
    int row;
    int column;
    double value;
  };

  std::string name_;
  std::uint32_t id_;
  // Columns.
  std::vector<double> col_lower_, col_upper_, col_cost_;
  std::vector<VarType> col_type_;
  NameTable col_names_{'c'};
  // Rows, stored as nonzeros sorted by (row, column) until frozen.
  std::vector<double> row_lower_, row_upper_;
  NameTable row_names_{'r'};
  std::vector<Entry> entries_;
  ObjectiveSense sense_ = ObjectiveSense::kMinimize;
  double objective_offset_ = 0.0;
};

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_MODEL_H_
