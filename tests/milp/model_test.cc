// Tests of the MILP builder (variable.h, linear_expr.h, model.h), the frozen
// standard form (lp_data.h) and the solver-independent parts of solver.h.
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "milp/linear_expr.h"
#include "milp/lp_data.h"
#include "milp/model.h"
#include "milp/solver.h"
#include "milp/variable.h"

namespace thrustsched::milp {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Dense copy of the frozen matrix, for exact comparisons.
Eigen::MatrixXd Dense(const LpData& lp) { return Eigen::MatrixXd(lp.a_matrix); }

TEST(VarBlockTest, IndexingAndSegments) {
  Model m;
  m.AddContinuous(0, 1);
  VarBlock b = m.AddVariables(5, 0, 1, VarType::kBinary, "u");
  EXPECT_EQ(b.start(), 1);
  EXPECT_EQ(b.size(), 5);
  EXPECT_EQ(b[4].index(), 5);
  VarBlock s = b.segment(1, 3);
  EXPECT_EQ(s.start(), 2);
  EXPECT_EQ(s[2].index(), 4);
  EXPECT_EQ(b.ToVector().size(), 5u);
  const std::vector<Variable> all = Concat({b.segment(0, 2), s});
  ASSERT_EQ(all.size(), 5u);
  EXPECT_EQ(all[2].index(), 2);
  EXPECT_EQ(ToString(VarType::kInteger), "integer");
}

TEST(VarBlockTest, OutOfRangeThrows) {
  Model m;
  VarBlock b = m.AddVariables(3, 0, 1, VarType::kBinary, "u");
  EXPECT_THAT([&] { (void)b[3]; }, ThrowsMessage<std::out_of_range>(HasSubstr("index 3")));
  EXPECT_THAT([&] { (void)b[-1]; }, ThrowsMessage<std::out_of_range>(HasSubstr("index -1")));
  EXPECT_THAT([&] { (void)b.segment(2, 2); },
              ThrowsMessage<std::out_of_range>(HasSubstr("segment(offset=2, size=2)")));
}

TEST(LinearExprTest, ArithmeticAndCanonicalize) {
  Model m;
  Variable x = m.AddContinuous(0, 1, "x");
  Variable y = m.AddContinuous(0, 1, "y");
  LinearExpr e = 2.0 * x - y + 3.0;
  e += x;
  e -= 0.5 * y;
  e *= 2.0;
  e.Canonicalize();
  ASSERT_EQ(e.terms().size(), 2u);
  EXPECT_EQ(e.terms()[0].index, 0);
  EXPECT_DOUBLE_EQ(e.terms()[0].coefficient, 6.0);
  EXPECT_DOUBLE_EQ(e.terms()[1].coefficient, -3.0);
  EXPECT_DOUBLE_EQ(e.constant(), 6.0);
  EXPECT_DOUBLE_EQ(e.Evaluate(Eigen::Vector2d(1.0, 2.0)), 6.0 - 6.0 + 6.0);
  LinearExpr zero = x - x;
  zero.Canonicalize();
  EXPECT_TRUE(zero.terms().empty());
  EXPECT_EQ(LinearExpr::Sum(m.AddVariables(3, 0, 1, VarType::kBinary, "b")).terms().size(), 3u);
  EXPECT_EQ(e.model_id(), m.id());
}

TEST(LinearExprTest, ComparisonsFoldTheConstant) {
  Model m;
  Variable x = m.AddContinuous(0, 10, "x");
  Variable y = m.AddContinuous(0, 10, "y");
  BoundedLinearExpr a = (2.0 * x - y + 3.0) <= 10.0;  // 2x - y <= 7
  EXPECT_DOUBLE_EQ(a.upper, 7.0);
  EXPECT_TRUE(std::isinf(a.lower) && a.lower < 0);
  EXPECT_DOUBLE_EQ(a.expr.constant(), 0.0);
  BoundedLinearExpr b = 1.0 <= (2.0 * x - y + 3.0);  // 2x - y >= -2
  EXPECT_DOUBLE_EQ(b.lower, -2.0);
  BoundedLinearExpr c = (x + 1.0) == (y - 1.0);  // x - y == -2
  EXPECT_DOUBLE_EQ(c.lower, -2.0);
  EXPECT_DOUBLE_EQ(c.upper, -2.0);
  BoundedLinearExpr d = 5.0 >= LinearExpr(x);
  EXPECT_DOUBLE_EQ(d.upper, 5.0);
}

TEST(LinearExprTest, InnerProductSizeMismatchThrows) {
  Model m;
  VarBlock b = m.AddVariables(3, 0, 1, VarType::kBinary, "b");
  EXPECT_THAT([&] { LinearExpr::InnerProduct(Eigen::Vector2d(1, 2), b); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("2 coefficients for a block of 3")));
  EXPECT_THAT([&] { LinearExpr::InnerProduct(Eigen::Vector2d(1, 2), b.ToVector()); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("2 coefficients for 3")));
}

TEST(LinearExprTest, EvaluateOutsideVectorThrows) {
  Model m;
  m.AddContinuous(0, 1);
  Variable y = m.AddContinuous(0, 1);
  EXPECT_THAT([&] { LinearExpr(y).Evaluate(Eigen::VectorXd::Zero(1)); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("column 1")));
}

TEST(ModelTest, BuildsColumnMajorStandardForm) {
  Model m("demo");
  Variable x = m.AddContinuous(-1, 2, "x");
  Variable y = m.AddInteger(0, 5, "y");
  Variable z = m.AddBinary("z");
  m.AddConstraint(x + 2 * y - z <= 4, "a");
  m.AddConstraint(3 * z - x, 1, 2, "b");
  m.AddConstraint(y + y == 2, "c");  // duplicate terms merged: 2y == 2
  m.Maximize(x - y + 0.5);
  const LpData lp = m.ToLpData();
  std::string error;
  ASSERT_TRUE(lp.IsValid(&error)) << error;
  EXPECT_TRUE(lp.a_matrix.isCompressed());
  Eigen::MatrixXd expected(3, 3);
  expected << 1, 2, -1,  //
      -1, 0, 3,          //
      0, 2, 0;
  EXPECT_EQ(Dense(lp), expected);
  EXPECT_EQ(lp.num_nonzeros(), 6);  // no explicit zeros
  EXPECT_EQ(lp.row_lower, Eigen::Vector3d(-kInfinity, 1, 2));
  EXPECT_EQ(lp.row_upper, Eigen::Vector3d(4, 2, 2));
  EXPECT_EQ(lp.col_lower, Eigen::Vector3d(-1, 0, 0));
  EXPECT_EQ(lp.col_upper, Eigen::Vector3d(2, 5, 1));
  EXPECT_EQ(lp.col_cost, Eigen::Vector3d(1, -1, 0));
  EXPECT_EQ(lp.sense, ObjectiveSense::kMaximize);
  EXPECT_DOUBLE_EQ(lp.objective_offset, 0.5);
  EXPECT_EQ(lp.col_type,
            (std::vector<VarType>{VarType::kContinuous, VarType::kInteger, VarType::kBinary}));
  EXPECT_EQ(lp.col_names, (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_EQ(lp.row_names, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(lp.num_integer_cols(), 2);
  EXPECT_EQ(m.num_integer_variables(), 2);
  EXPECT_EQ(m.num_nonzeros(), 6);
  EXPECT_DOUBLE_EQ(lp.Objective(Eigen::Vector3d(1, 2, 0)), 1 - 2 + 0.5);
}

TEST(ModelTest, GeneratedAndBlockNames) {
  Model m;
  Variable a = m.AddContinuous(0, 1);  // c0
  VarBlock u = m.AddVariables(2, 0, 1, VarType::kBinary, "u");
  Variable b = m.AddContinuous(0, 1, "c4");  // explicit name equal to a generated one
  Variable d = m.AddContinuous(0, 1);        // index 4 -> "c4" taken -> "c4_1"
  EXPECT_EQ(m.variable_name(a), "c0");
  EXPECT_EQ(m.variable_name(u[1]), "u[1]");
  EXPECT_EQ(m.variable_name(b), "c4");
  EXPECT_EQ(m.variable_name(d), "c4_1");
  Constraint r0 = m.AddConstraint(LinearExpr(a) <= 1);
  ConstraintBlock rows =
      m.AddRows({{0, 0, 1.0}, {1, 1, 1.0}}, Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), "dyn");
  EXPECT_EQ(m.constraint_name(r0), "r0");
  EXPECT_EQ(m.constraint_name(Constraint{rows.start + 1}), "dyn[1]");
  const LpData lp = m.ToLpData();
  EXPECT_EQ(lp.col_names, (std::vector<std::string>{"c0", "u[0]", "u[1]", "c4", "c4_1"}));
  EXPECT_EQ(lp.row_names, (std::vector<std::string>{"r0", "dyn[0]", "dyn[1]"}));
  std::string error;
  EXPECT_TRUE(lp.IsValid(&error)) << error;
}

TEST(ModelTest, ModelIdsAreUnique) {
  Model a, b;
  EXPECT_NE(a.id(), b.id());
  EXPECT_NE(a.id(), 0u);
}

TEST(ModelTest, BulkRowsFromTripletsAndSparseMatrix) {
  Model m;
  VarBlock x = m.AddVariables(3, -10, 10, VarType::kContinuous, "x");
  // Triplets out of order, with a duplicate (summed) and a cancelling pair.
  m.AddRows({{1, 2, 4.0}, {0, 0, 1.0}, {1, 0, -1.0}, {0, 0, 2.0}, {1, 1, 3.0}, {1, 1, -3.0}},
            Eigen::Vector2d(-1, 0), Eigen::Vector2d(1, kInfinity), "t");
  Eigen::SparseMatrix<double, Eigen::RowMajor> a(2, 2);
  a.insert(0, 0) = 5.0;
  a.insert(1, 1) = -2.0;
  a.makeCompressed();
  m.AddRows(a, std::vector<Variable>{x[2], x[0]}, Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 1),
            "s");
  m.AddRows(a, x.segment(1, 2), Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), "v");
  const LpData lp = m.ToLpData();
  Eigen::MatrixXd expected(6, 3);
  expected << 3, 0, 0,  //
      -1, 0, 4,         //
      0, 0, 5,          //
      -2, 0, 0,         //
      0, 5, 0,          //
      0, 0, -2;
  EXPECT_EQ(Dense(lp), expected);
  EXPECT_EQ(lp.num_nonzeros(), 7);  // the cancelled pair leaves no explicit zero
  EXPECT_EQ(lp.row_names[3], "s[1]");
  EXPECT_EQ(lp.row_names[4], "v[0]");
}

TEST(ModelTest, BulkRowsWithExplicitNames) {
  Model m;
  Variable x = m.AddContinuous(0, 1, "x");
  m.AddRows({{0, x.index(), 1.0}, {1, x.index(), 2.0}}, Eigen::Vector2d(0, 0),
            Eigen::Vector2d(1, 1), "ignored", {"first", ""});
  const LpData lp = m.ToLpData();
  EXPECT_EQ(lp.row_names, (std::vector<std::string>{"first", "r1"}));
}

TEST(ModelTest, SetBoundsTypeAndObjectiveTerms) {
  Model m;
  Variable x = m.AddContinuous(0, 1, "x");
  m.SetBounds(x, -2, 3);
  m.SetType(x, VarType::kInteger);
  m.AddObjectiveTerm(x, 1.5);
  m.AddObjectiveTerm(x, 1.0);
  EXPECT_EQ(m.lower_bound(x), -2);
  EXPECT_EQ(m.upper_bound(x), 3);
  EXPECT_EQ(m.type(x), VarType::kInteger);
  EXPECT_DOUBLE_EQ(m.objective_coefficient(x), 2.5);
  EXPECT_EQ(m.variable(0), x);
  m.Minimize(LinearExpr(x) * 3.0 + 1.0);
  EXPECT_DOUBLE_EQ(m.objective_coefficient(x), 3.0);
  EXPECT_DOUBLE_EQ(m.objective_offset(), 1.0);
  EXPECT_EQ(m.sense(), ObjectiveSense::kMinimize);
}

// ---- every @throws of model.h

TEST(ModelErrorsTest, AddVariableRejectsBadBounds) {
  Model m("M");
  EXPECT_THAT(
      [&] { m.AddContinuous(kNaN, 1, "x"); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("variable 'x': bounds must not be NaN")));
  EXPECT_THAT([&] { m.AddContinuous(2, 1, "x"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("lower bound 2 > upper bound 1")));
  EXPECT_THAT([&] { m.AddContinuous(kInfinity, kInfinity, "x"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("leave no finite value")));
  EXPECT_THAT(
      [&] { m.AddVariable(0, 2, VarType::kBinary, "b"); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("binary bounds [0, 2] outside [0, 1]")));
  EXPECT_THAT([&] { m.AddInteger(1, 0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("variable 'c0'")));
  EXPECT_EQ(m.num_variables(), 0);
}

TEST(ModelErrorsTest, DuplicateVariableNames) {
  Model m("M");
  m.AddBinary("x");
  EXPECT_THAT([&] { m.AddBinary("x"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("duplicate variable name 'x'")));
  m.AddVariables(3, 0, 1, VarType::kBinary, "u");
  EXPECT_THAT([&] { m.AddContinuous(0, 1, "u[2]"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("duplicate variable name 'u[2]'")));
  EXPECT_NO_THROW(m.AddContinuous(0, 1, "u[3]"));
  EXPECT_THAT([&] { m.AddVariables(2, 0, 1, VarType::kBinary, "u"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("block prefix 'u'")));
  m.AddContinuous(0, 1, "w[1]");
  EXPECT_THAT([&] { m.AddVariables(2, 0, 1, VarType::kBinary, "w"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("'w[1]'")));
  EXPECT_THAT([&] { m.AddVariables(-1, 0, 1, VarType::kBinary, "v"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("count must be >= 0")));
}

TEST(ModelErrorsTest, ForeignAndInvalidVariables) {
  Model m("M"), other("O");
  Variable mine = m.AddContinuous(0, 1, "x");
  Variable theirs = other.AddContinuous(0, 1, "y");
  EXPECT_THAT([&] { m.SetBounds(theirs, 0, 1); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("belongs to model #")));
  EXPECT_THAT([&] { m.SetBounds(Variable(), 0, 1); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("invalid (default-constructed)")));
  EXPECT_THAT([&] { m.AddConstraint(mine + theirs <= 1, "r"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("row 'r': expression mixes")));
  EXPECT_THAT([&] { m.AddConstraint(LinearExpr(theirs) <= 1, "r"); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("row 'r': expression uses variables of model")));
  EXPECT_THAT([&] { m.AddConstraint(LinearExpr(Variable()) <= 1, "r"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("invalid variable handle")));
  EXPECT_THAT([&] { m.Minimize(LinearExpr(theirs)); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("objective uses variables")));
  EXPECT_THAT([&] { m.Maximize(mine + theirs); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("objective mixes")));
  EXPECT_THAT([&] { m.AddObjectiveTerm(theirs, 1); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("AddObjectiveTerm")));
  EXPECT_THAT([&] { m.variable_name(theirs); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("variable_name")));
  EXPECT_THAT([&] { m.lower_bound(theirs); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("lower_bound")));
  EXPECT_THAT([&] { m.upper_bound(theirs); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("upper_bound")));
  EXPECT_THAT([&] { m.type(theirs); }, ThrowsMessage<std::invalid_argument>(HasSubstr("type")));
  EXPECT_THAT([&] { m.objective_coefficient(theirs); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("objective_coefficient")));
  EXPECT_THAT([&] { m.variable(1); }, ThrowsMessage<std::out_of_range>(HasSubstr("index 1")));
  EXPECT_THAT([&] { m.constraint_name(Constraint{0}); },
              ThrowsMessage<std::out_of_range>(HasSubstr("constraint index 0")));
}

TEST(ModelErrorsTest, SetBoundsAndSetType) {
  Model m("M");
  Variable x = m.AddContinuous(0, 3, "x");
  EXPECT_THAT([&] { m.SetBounds(x, 2, 1); }, ThrowsMessage<std::invalid_argument>(HasSubstr(
                                                 "variable 'x': lower bound 2 > upper bound 1")));
  EXPECT_THAT([&] { m.SetType(x, VarType::kBinary); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("binary bounds [0, 3]")));
  Variable b = m.AddBinary("b");
  EXPECT_THAT([&] { m.SetBounds(b, -1, 1); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("binary bounds [-1, 1]")));
}

TEST(ModelErrorsTest, AddConstraintRejectsBadData) {
  Model m("M");
  Variable x = m.AddContinuous(0, 1, "x");
  const double inf = kInfinity;
  EXPECT_THAT([&] { m.AddConstraint(kNaN * x <= 1, "r"); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("row 'r': coefficient of variable 'x' must be finite, got nan")));
  EXPECT_THAT([&] { m.AddConstraint(inf * x <= 1, "r"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("must be finite, got inf")));
  EXPECT_THAT([&] { m.AddConstraint(LinearExpr(x), kNaN, 1, "r"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("row 'r': bounds must not be NaN")));
  EXPECT_THAT([&] { m.AddConstraint(LinearExpr(x), 2, 1, "r"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("lower bound 2 > upper bound 1")));
  EXPECT_THAT([&] { m.AddConstraint(LinearExpr(x), inf, inf, "r"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("can never hold")));
  EXPECT_THAT(
      [&] { m.AddConstraint(x + kNaN, 0, 1, "r"); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("expression constant must be finite")));
  EXPECT_THAT([&] { m.AddConstraint(x + kNaN <= 1, "r"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("row 'r'")));
  m.AddConstraint(LinearExpr(x) <= 1, "r");
  EXPECT_THAT([&] { m.AddConstraint(LinearExpr(x) <= 1, "r"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("duplicate row name 'r'")));
  EXPECT_EQ(m.num_constraints(), 1);
}

TEST(ModelErrorsTest, AddRowsRejectsBadDataAndAddsNothing) {
  Model m("M");
  VarBlock x = m.AddVariables(2, 0, 1, VarType::kContinuous, "x");
  const Eigen::Vector2d lo(0, 0), up(1, 1);
  EXPECT_THAT(
      [&] { m.AddRows({}, lo, Eigen::Vector3d(1, 1, 1)); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("lower has size 2 but upper has size 3")));
  EXPECT_THAT([&] { m.AddRows({}, lo, up, "", {"a"}); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("1 names for 2 rows")));
  EXPECT_THAT(
      [&] {
        m.AddRows({{2, 0, 1.0}}, lo, up);
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("triplet row 2 outside [0, 2)")));
  EXPECT_THAT(
      [&] {
        m.AddRows({{0, 5, 1.0}}, lo, up, "d");
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("row 'd[0]': column 5 outside")));
  EXPECT_THAT(
      [&] {
        m.AddRows({{1, 1, kNaN}}, lo, up, "d");
      },
      ThrowsMessage<std::invalid_argument>(
          HasSubstr("row 'd[1]': coefficient of variable 'x[1]' must be finite")));
  EXPECT_THAT(
      [&] {
        m.AddRows({{0, 0, 1e308}, {0, 0, 1e308}}, lo, up, "d");
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("overflows")));
  EXPECT_THAT(
      [&] { m.AddRows({}, Eigen::Vector2d(2, 0), up, "d"); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("row 'd[0]': lower bound 2 > upper bound 1")));
  EXPECT_THAT(
      [&] {
        m.AddRows({}, lo, up, "", {"a", "a"});
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("duplicate row name 'a'")));
  m.AddRows({}, lo, up, "d");
  EXPECT_THAT([&] { m.AddRows({}, lo, up, "d"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("block prefix 'd'")));
  EXPECT_THAT([&] { m.AddConstraint(LinearExpr(x[0]) <= 1, "d[1]"); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("duplicate row name 'd[1]'")));
  EXPECT_EQ(m.num_constraints(), 2);
  EXPECT_EQ(m.num_nonzeros(), 0);
  Eigen::SparseMatrix<double, Eigen::RowMajor> a(2, 2);
  a.insert(0, 0) = 1.0;
  Model other;
  Variable theirs = other.AddContinuous(0, 1);
  EXPECT_THAT(
      [&] { m.AddRows(a, std::vector<Variable>{x[0]}, lo, up); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("matrix has 2 columns but 1 variables")));
  EXPECT_THAT(
      [&] {
        m.AddRows(a, std::vector<Variable>{x[0], theirs}, lo, up);
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("vars[1]")));
  EXPECT_THAT(
      [&] { m.AddRows(a, x.ToVector(), Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1)); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("matrix has 2 rows but lower has size 3")));
  EXPECT_THAT([&] { m.AddRows(a, x.segment(0, 1), lo, up); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("block has 1 variables")));
  EXPECT_THAT([&] { m.AddRows(a, other.AddVariables(2, 0, 1, VarType::kBinary, "z"), lo, up); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("block belongs to model")));
  EXPECT_EQ(m.num_constraints(), 2);
}

TEST(ModelErrorsTest, ObjectiveRejectsNonFinite) {
  Model m("M");
  Variable x = m.AddContinuous(0, 1, "x");
  EXPECT_THAT([&] { m.Minimize(kInfinity * x); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("coefficient of variable 'x' must be finite")));
  EXPECT_THAT([&] { m.Maximize(x + kNaN); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("constant must be finite")));
  EXPECT_THAT(
      [&] { m.AddObjectiveTerm(x, kNaN); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("objective coefficient of variable 'x'")));
}

// ---- LpData

TEST(LpDataTest, MaxViolationAndObjective) {
  Model m;
  Variable x = m.AddInteger(0, 3, "x");
  Variable y = m.AddContinuous(-1, 1, "y");
  m.AddConstraint(x + y, 1, 2, "r");
  m.Minimize(2 * x - y + 1);
  const LpData lp = m.ToLpData();
  EXPECT_DOUBLE_EQ(lp.MaxViolation(Eigen::Vector2d(1, 0.5)), 0.0);
  EXPECT_DOUBLE_EQ(lp.MaxViolation(Eigen::Vector2d(1.25, 0.5)), 0.25);  // integrality
  EXPECT_DOUBLE_EQ(lp.MaxViolation(Eigen::Vector2d(2, 1.0)), 1.0);      // row: 3 > 2
  EXPECT_DOUBLE_EQ(lp.MaxViolation(Eigen::Vector2d(1, -1.5)), 1.5);     // bound and row
  EXPECT_TRUE(std::isinf(lp.MaxViolation(Eigen::Vector2d(kNaN, 0))));
  EXPECT_DOUBLE_EQ(lp.Objective(Eigen::Vector2d(1, 0.5)), 2.5);
  EXPECT_THAT([&] { lp.Objective(Eigen::Vector3d(1, 2, 3)); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("x has size 3, expected 2")));
  EXPECT_THAT([&] { lp.MaxViolation(Eigen::VectorXd(1)); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("x has size 1, expected 2")));
}

TEST(LpDataTest, IsValidNamesTheProblem) {
  Model m;
  m.AddContinuous(0, 1, "x");
  m.AddBinary("b");
  m.AddConstraint(LinearExpr(m.variable(0)) <= 1, "r");
  const LpData good = m.ToLpData();
  std::string error;
  ASSERT_TRUE(good.IsValid(&error)) << error;
  auto expect_invalid = [&](LpData lp, const std::string& what) {
    std::string e;
    EXPECT_FALSE(lp.IsValid(&e));
    EXPECT_THAT(e, HasSubstr(what));
  };
  LpData bad = good;
  bad.col_cost.resize(1);
  expect_invalid(bad, "col_cost has size 1");
  bad = good;
  bad.col_lower[0] = 2;
  expect_invalid(bad, "column 0 'x' has invalid bounds [2, 1]");
  bad = good;
  bad.col_upper[1] = 2;
  expect_invalid(bad, "binary column 1 'b'");
  bad = good;
  bad.row_upper[0] = kNaN;
  expect_invalid(bad, "row 0 'r' has invalid bounds");
  bad = good;
  bad.a_matrix.coeffRef(0, 1) = kInfinity;
  expect_invalid(bad, "must be finite");
  bad = good;
  bad.col_names[1] = "x";
  expect_invalid(bad, "duplicate column name 'x'");
  bad = good;
  bad.objective_offset = kNaN;
  expect_invalid(bad, "objective_offset");
  bad = good;
  bad.col_cost[0] = kInfinity;
  expect_invalid(bad, "cost must be finite");
  bad = good;
  bad.row_names.push_back("extra");
  expect_invalid(bad, "row_names has size 2");
  EXPECT_FALSE(bad.IsValid(nullptr));
}

// ---- solver.h (no backend needed)

TEST(SolveOptionsTest, IsValid) {
  SolveOptions o;
  std::string error;
  EXPECT_TRUE(o.IsValid(&error)) << error;
  auto expect_invalid = [](SolveOptions o, const std::string& what) {
    std::string e;
    EXPECT_FALSE(o.IsValid(&e));
    EXPECT_THAT(e, HasSubstr(what));
  };
  o.time_limit_s = -1;
  expect_invalid(o, "time_limit_s");
  o = {};
  o.time_limit_s = kNaN;
  expect_invalid(o, "time_limit_s");
  o = {};
  o.relative_gap = -1e-3;
  expect_invalid(o, "relative_gap");
  o = {};
  o.absolute_gap = kInfinity;
  expect_invalid(o, "absolute_gap");
  o = {};
  o.threads = 0;
  expect_invalid(o, "threads");
  o = {};
  o.random_seed = -1;
  expect_invalid(o, "random_seed");
  o = {};
  o.log_level = -1;
  expect_invalid(o, "log_level");
  o = {};
  o.progress_interval_s = 0;
  expect_invalid(o, "progress_interval_s");
  o = {};
  o.initial_solution = Eigen::Vector2d(1, kNaN);
  expect_invalid(o, "initial_solution[1]");
}

TEST(SolveResultTest, TimeToGapUsesTheFinalBound) {
  SolveResult r;
  r.status = SolveStatus::kFeasible;
  r.best_bound = 100.0;  // minimisation: bound below the incumbents
  r.incumbents = {{0.5, 120.0, 90.0}, {1.5, 105.0, 95.0}, {3.0, 100.5, 99.0}};
  EXPECT_DOUBLE_EQ(r.TimeToGap(0.25), 0.5);  // 20/120 = 0.167
  EXPECT_DOUBLE_EQ(r.TimeToGap(0.05), 1.5);  // 5/105 = 0.048
  EXPECT_DOUBLE_EQ(r.TimeToGap(0.01), 3.0);  // 0.5/100.5 = 0.005
  EXPECT_TRUE(std::isnan(r.TimeToGap(0.001)));
  r.best_bound = kNaN;
  EXPECT_TRUE(std::isnan(r.TimeToGap(1.0)));
  EXPECT_EQ(ToString(SolveStatus::kNoSolutionFound), "no_solution_found");
  std::ostringstream os;
  os << SolveStatus::kInfeasible;
  EXPECT_EQ(os.str(), "infeasible");
}

}  // namespace
}  // namespace thrustsched::milp
