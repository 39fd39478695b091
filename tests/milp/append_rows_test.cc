// milp::AppendRows and milp::AppendColumns against the rows and columns
// written out by hand: coefficients, bounds and names land where asked, the
// model's own rows and columns are untouched, and bad ones are refused with
// their index named.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "milp/lp_data.h"
#include "milp/model.h"

namespace thrustsched::milp {
namespace {

// min x + 2y + 3z  s.t.  x + y >= 1,  y - z <= 4,  0 <= x, y, z <= 10.
LpData Small() {
  Model m;
  const Variable x = m.AddContinuous(0, 10, "x");
  const Variable y = m.AddContinuous(0, 10, "y");
  const Variable z = m.AddContinuous(0, 10, "z");
  LinearExpr a(x);
  a.AddTerm(y, 1.0);
  m.AddConstraint(a, 1.0, kInfinity, "a");
  LinearExpr b(y);
  b.AddTerm(z, -1.0);
  m.AddConstraint(b, -kInfinity, 4.0, "b");
  LinearExpr cost(x);
  cost.AddTerm(y, 2.0);
  cost.AddTerm(z, 3.0);
  m.Minimize(cost);
  return m.ToLpData();
}

TEST(AppendRows, AddsTheRowsAfterTheModelsOwn) {
  LpData lp = Small();
  const LpData before = lp;
  AppendRows(&lp, {{{2, 0}, {5.0, -1.5}, 0.5, 7.0, "c"}, {{1}, {1.0}, -kInfinity, 3.0, ""}});
  ASSERT_EQ(lp.num_rows(), 4);
  ASSERT_EQ(lp.num_cols(), 3);
  std::string error;
  EXPECT_TRUE(lp.IsValid(&error)) << error;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_EQ(lp.a_matrix.coeff(i, j), before.a_matrix.coeff(i, j));
    EXPECT_EQ(lp.row_lower[i], before.row_lower[i]);
    EXPECT_EQ(lp.row_upper[i], before.row_upper[i]);
  }
  EXPECT_EQ(lp.a_matrix.coeff(2, 0), -1.5);
  EXPECT_EQ(lp.a_matrix.coeff(2, 1), 0.0);
  EXPECT_EQ(lp.a_matrix.coeff(2, 2), 5.0);
  EXPECT_EQ(lp.a_matrix.coeff(3, 1), 1.0);
  EXPECT_EQ(lp.num_nonzeros(), before.num_nonzeros() + 3);
  EXPECT_EQ(lp.row_lower[2], 0.5);
  EXPECT_EQ(lp.row_upper[2], 7.0);
  EXPECT_EQ(lp.row_lower[3], -kInfinity);
  EXPECT_EQ(lp.row_upper[3], 3.0);
  ASSERT_EQ(lp.row_names.size(), 4u);
  EXPECT_EQ(lp.row_names[2], "c");
  EXPECT_EQ(lp.row_names[3], "R3");  // unnamed row in a named model
  // x = (1, 2, 0) meets rows a, b and the new row 3 (y <= 3) but not row 2
  // (5z - 1.5x = -1.5 < 0.5): violation 2.
  const Eigen::Vector3d point(1.0, 2.0, 0.0);
  EXPECT_NEAR(lp.MaxViolation(point), 2.0, 1e-12);
}

TEST(AppendRows, RefusesBadRowsNamingThem) {
  LpData lp = Small();
  auto message = [&](const SparseRow& row) {
    try {
      AppendRows(&lp, {row});
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({{0, 3}, {1.0, 1.0}, 0.0, 1.0, "r"}),
            "AppendRows: row 2 'r': column 3 out of range [0, 3)");
  EXPECT_EQ(message({{1, 1}, {1.0, 2.0}, 0.0, 1.0, ""}), "AppendRows: row 2: column 1 repeated");
  EXPECT_EQ(message({{1}, {1.0, 2.0}, 0.0, 1.0, "r"}),
            "AppendRows: row 2 'r': 1 columns but 2 coefficients");
  EXPECT_EQ(lp.num_rows(), 2);  // nothing appended
}

TEST(AppendColumns, AddsEmptyColumnsThatRowsCanThenUse) {
  LpData lp = Small();
  const LpData before = lp;
  // w, defined below as x + y by a row, and a binary of cost 4.
  const int w = AppendColumns(&lp, {{-kInfinity, 1.5, 0.0, VarType::kContinuous, "w"},
                                    {0.0, 1.0, 4.0, VarType::kBinary, ""}});
  ASSERT_EQ(w, 3);
  ASSERT_EQ(lp.num_cols(), 5);
  ASSERT_EQ(lp.num_rows(), 2);
  std::string error;
  EXPECT_TRUE(lp.IsValid(&error)) << error;
  EXPECT_EQ(lp.num_nonzeros(), before.num_nonzeros());
  for (int j = 0; j < 3; ++j) {
    EXPECT_EQ(lp.col_cost[j], before.col_cost[j]);
    for (int i = 0; i < 2; ++i) EXPECT_EQ(lp.a_matrix.coeff(i, j), before.a_matrix.coeff(i, j));
  }
  EXPECT_EQ(lp.col_lower[3], -kInfinity);
  EXPECT_EQ(lp.col_upper[3], 1.5);
  EXPECT_EQ(lp.col_cost[3], 0.0);
  EXPECT_EQ(lp.col_cost[4], 4.0);
  EXPECT_EQ(lp.col_type[3], VarType::kContinuous);
  EXPECT_EQ(lp.col_type[4], VarType::kBinary);
  EXPECT_EQ(lp.num_integer_cols(), 1);
  ASSERT_EQ(lp.col_names.size(), 5u);
  EXPECT_EQ(lp.col_names[3], "w");
  EXPECT_EQ(lp.col_names[4], "C4");  // unnamed column in a named model
  AppendRows(&lp, {{{0, 1, 3}, {1.0, 1.0, -1.0}, 0.0, 0.0, "w_def"}});
  EXPECT_TRUE(lp.IsValid(&error)) << error;
  // (x, y, z, w, b) = (1, 0.5, 0, 1.5, 0) meets every row; w = 2 breaks w's
  // upper bound and the definition row by 0.5 each.
  Eigen::VectorXd point(5);
  point << 1.0, 0.5, 0.0, 1.5, 0.0;
  EXPECT_EQ(lp.MaxViolation(point), 0.0);
  EXPECT_DOUBLE_EQ(lp.Objective(point), 2.0);
  point[3] = 2.0;
  EXPECT_NEAR(lp.MaxViolation(point), 0.5, 1e-12);
}

TEST(AppendColumns, RefusesBadColumnsNamingThem) {
  LpData lp = Small();
  try {
    AppendColumns(&lp, {{0.0, 1.0, 0.0, VarType::kContinuous, "ok"},
                        {2.0, 1.0, 0.0, VarType::kContinuous, "w"}});
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "AppendColumns: column 4 'w': bounds [2, 1], cost 0");
  }
  EXPECT_EQ(lp.num_cols(), 3);  // nothing appended
}

}  // namespace
}  // namespace thrustsched::milp
