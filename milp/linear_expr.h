// Sparse affine expressions  sum_i c_i x_i + constant  over the columns of one
// Model, and bounded expressions  lower <= expr <= upper  built with <=, >=, ==.
//
//   LinearExpr e = 2.0 * x - y + 3.0;        // constant folded into the row bounds
//   model.AddConstraint(e <= 10.0, "r");     // 2x - y <= 7
//   model.AddConstraint(1.0 <= e, "s");      // 2x - y >= -2
//
// Duplicate terms are allowed until Canonicalize() (sort by column, merge,
// drop exact zeros); Model canonicalises every row it receives. Do not build
// long sums with repeated `a = a + b` (quadratic copying): use `+=` or Sum().
#ifndef THRUSTSCHED_MILP_LINEAR_EXPR_H_
#define THRUSTSCHED_MILP_LINEAR_EXPR_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "milp/variable.h"

namespace thrustsched::milp {

class LinearExpr {
 public:
  struct Term {
    int index;
    double coefficient;
  };

  LinearExpr() = default;
  LinearExpr(double constant);  // NOLINT(runtime/explicit): enables 2 * x + 3
  LinearExpr(Variable v);       // NOLINT(runtime/explicit)

  LinearExpr& AddTerm(Variable v, double coefficient);
  LinearExpr& AddConstant(double value);
  LinearExpr& operator+=(const LinearExpr& other);
  LinearExpr& operator-=(const LinearExpr& other);
  LinearExpr& operator*=(double scale);

  static LinearExpr Sum(const VarBlock& vars);
  static LinearExpr Sum(const std::vector<Variable>& vars);
  /// sum_i coefficients[i] * vars[i].
  /// @throws std::invalid_argument if the sizes differ.
  static LinearExpr InnerProduct(const Eigen::Ref<const Eigen::VectorXd>& coefficients,
                                 const VarBlock& vars);
  /// @throws std::invalid_argument if the sizes differ.
  static LinearExpr InnerProduct(const Eigen::Ref<const Eigen::VectorXd>& coefficients,
                                 const std::vector<Variable>& vars);

  const std::vector<Term>& terms() const { return terms_; }
  double constant() const { return constant_; }
  /// Model that owns the variables: 0 when there are none, kMixedModels when
  /// variables of two models were combined (rejected by Model).
  std::uint32_t model_id() const { return model_id_; }
  static constexpr std::uint32_t kMixedModels = 0xffffffffu;

  /// Sorts terms by column, merges duplicates and drops exact zeros.
  void Canonicalize();
  /// Value at the column vector x.
  /// @throws std::invalid_argument if a term's column is outside x.
  double Evaluate(const Eigen::Ref<const Eigen::VectorXd>& x) const;

 private:
  void MergeModel(std::uint32_t id);
  std::vector<Term> terms_;
  double constant_ = 0.0;
  std::uint32_t model_id_ = 0;
};

LinearExpr operator+(LinearExpr a, const LinearExpr& b);
LinearExpr operator-(LinearExpr a, const LinearExpr& b);
LinearExpr operator-(LinearExpr a);
LinearExpr operator*(double c, LinearExpr e);
LinearExpr operator*(LinearExpr e, double c);

/// lower <= expr <= upper, with the expression constant already folded into
/// the bounds (expr.constant() == 0).
struct BoundedLinearExpr {
  LinearExpr expr;
  double lower;
  double upper;
};
BoundedLinearExpr operator<=(LinearExpr e, double upper);
BoundedLinearExpr operator>=(LinearExpr e, double lower);
BoundedLinearExpr operator==(LinearExpr e, double value);
BoundedLinearExpr operator<=(double lower, LinearExpr e);
BoundedLinearExpr operator>=(double upper, LinearExpr e);
/// Both sides may hold variables: moves everything to the left.
BoundedLinearExpr operator<=(LinearExpr a, const LinearExpr& b);
BoundedLinearExpr operator>=(LinearExpr a, const LinearExpr& b);
BoundedLinearExpr operator==(LinearExpr a, const LinearExpr& b);

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_LINEAR_EXPR_H_
