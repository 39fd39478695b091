// ColumnBlocks (milp/lp_blocks.h) on models whose blocks are known by
// construction, and RemoveFixedColumns' map of the rows it keeps.
#include "milp/lp_blocks.h"

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "milp/lp_data.h"
#include "milp/model.h"

namespace thrustsched::milp {
namespace {

// Columns a..e; rows {a,b}, {b,c}, {d,e}, and a coupling row {c,d}.
struct Chain {
  LpData lp;
  int coupling_row = 3;
};

Chain MakeChain() {
  Model m;
  const Variable a = m.AddContinuous(0, 1, "a"), b = m.AddContinuous(0, 1, "b");
  const Variable c = m.AddBinary("c"), d = m.AddBinary("d"), e = m.AddContinuous(0, 1, "e");
  m.AddConstraint(LinearExpr(a) + b <= 1.0);
  m.AddConstraint(LinearExpr(b) - c == 0.0);
  m.AddConstraint(LinearExpr(d) + 2.0 * LinearExpr(e) >= 0.5);
  m.AddConstraint(LinearExpr(c) + d <= 1.0);
  return {m.ToLpData()};
}

TEST(ColumnBlocks, JoinsColumnsThroughEveryRowButTheCouplingOnes) {
  const Chain chain = MakeChain();
  int count = 0;
  EXPECT_EQ(ColumnBlocks(chain.lp, {}, &count), (std::vector<int>{0, 0, 0, 0, 0}));
  EXPECT_EQ(count, 1);
  std::vector<bool> coupling(4, false);
  coupling[static_cast<size_t>(chain.coupling_row)] = true;
  EXPECT_EQ(ColumnBlocks(chain.lp, coupling, &count), (std::vector<int>{0, 0, 0, 1, 1}));
  EXPECT_EQ(count, 2);
  // Every row ignored: each column is its own block, numbered in order.
  EXPECT_EQ(ColumnBlocks(chain.lp, std::vector<bool>(4, true), &count),
            (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(count, 5);
  EXPECT_THROW(ColumnBlocks(chain.lp, std::vector<bool>(3, false)), std::invalid_argument);
}

TEST(ColumnBlocks, AColumnInNoRowIsABlockOfItsOwn) {
  Model m;
  const Variable x = m.AddContinuous(0, 1, "x");
  m.AddContinuous(0, 1, "lonely");
  const Variable z = m.AddContinuous(0, 1, "z");
  m.AddConstraint(LinearExpr(x) + z <= 1.0);
  int count = 0;
  EXPECT_EQ(ColumnBlocks(m.ToLpData(), {}, &count), (std::vector<int>{0, 1, 0}));
  EXPECT_EQ(count, 2);
}

// The rows RemoveFixedColumns keeps are reported in order; a row whose
// columns are all fixed is dropped (and checked).
TEST(RemoveFixedColumns, ReportsTheRowsItKeeps) {
  LpData lp = MakeChain().lp;
  lp.col_lower[3] = lp.col_upper[3] = 0.0;  // d
  lp.col_lower[4] = lp.col_upper[4] = 0.5;  // e: row {d, e} is 1.0 >= 0.5, dropped
  std::vector<int> kept, kept_rows;
  bool feasible = false;
  const LpData small = RemoveFixedColumns(lp, &kept, &feasible, &kept_rows);
  EXPECT_TRUE(feasible);
  EXPECT_EQ(kept, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(kept_rows, (std::vector<int>{0, 1, 3}));
  ASSERT_EQ(small.num_rows(), 3);
  EXPECT_DOUBLE_EQ(small.row_upper[2], 1.0);  // c + d <= 1 with d = 0
}

}  // namespace
}  // namespace thrustsched::milp
