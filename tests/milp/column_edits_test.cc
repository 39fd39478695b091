// The LP edits that copy a matrix column by column into compressed storage
// (RemoveFixedColumns, SelectRows, AppendRows; milp/internal/column_writer.h)
// against the same edit done on the dense matrix: on random sparse LPs every
// coefficient lands in its row and column, bit for bit, and the result is a
// valid compressed matrix.
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include "milp/internal/column_writer.h"
#include "milp/lazy_rows.h"
#include "milp/lp_data.h"

namespace thrustsched::milp {
namespace {

// rows x cols, about a third of the entries nonzero, every third column
// fixed at 1 (the rest in [0, 2]), rows 0 <= . <= 100.
LpData RandomLp(int rows, int cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-3.0, 3.0);
  std::bernoulli_distribution present(1.0 / 3.0);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(rows, cols);
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) {
      if (present(rng)) dense(i, j) = value(rng);
    }
  }
  LpData lp;
  lp.a_matrix = dense.sparseView();
  lp.a_matrix.makeCompressed();
  lp.col_cost = Eigen::VectorXd::Ones(cols);
  lp.col_lower = Eigen::VectorXd::Zero(cols);
  lp.col_upper = Eigen::VectorXd::Constant(cols, 2.0);
  for (int j = 0; j < cols; j += 3) lp.col_lower[j] = lp.col_upper[j] = 1.0;
  lp.col_type.assign(static_cast<size_t>(cols), VarType::kContinuous);
  lp.row_lower = Eigen::VectorXd::Zero(rows);
  lp.row_upper = Eigen::VectorXd::Constant(rows, 100.0);
  return lp;
}

void ExpectCompressedAndValid(const LpData& lp) {
  EXPECT_TRUE(lp.a_matrix.isCompressed());
  std::string error;
  EXPECT_TRUE(lp.IsValid(&error)) << error;
}

TEST(ColumnEdits, RemoveFixedColumnsKeepsTheDenseSubmatrix) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const LpData lp = RandomLp(40, 30, seed);
    std::vector<int> kept, kept_rows;
    const LpData small = RemoveFixedColumns(lp, &kept, nullptr, &kept_rows);
    ExpectCompressedAndValid(small);
    const Eigen::MatrixXd dense(lp.a_matrix), got(small.a_matrix);
    ASSERT_EQ(got.rows(), static_cast<Eigen::Index>(kept_rows.size()));
    ASSERT_EQ(got.cols(), static_cast<Eigen::Index>(kept.size()));
    EXPECT_EQ(kept.size(), 20u);  // columns 0, 3, ..., 27 fixed
    for (size_t r = 0; r < kept_rows.size(); ++r) {
      for (size_t k = 0; k < kept.size(); ++k) {
        EXPECT_EQ(got(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k)),
                  dense(kept_rows[r], kept[k]));
      }
    }
    EXPECT_EQ(small.num_nonzeros(), static_cast<int>((got.array() != 0.0).count()));
  }
}

TEST(ColumnEdits, SelectRowsKeepsTheDenseRows) {
  const LpData lp = RandomLp(40, 30, 7);
  const std::vector<int> rows = {0, 3, 4, 17, 39};
  const LpData subset = SelectRows(lp, rows);
  ExpectCompressedAndValid(subset);
  const Eigen::MatrixXd dense(lp.a_matrix), got(subset.a_matrix);
  ASSERT_EQ(got.rows(), 5);
  ASSERT_EQ(got.cols(), 30);
  for (size_t r = 0; r < rows.size(); ++r) {
    EXPECT_EQ(got.row(static_cast<Eigen::Index>(r)), dense.row(rows[r]));
  }
}

TEST(ColumnEdits, AppendRowsStacksTheNewRowsUnderTheDenseMatrix) {
  LpData lp = RandomLp(40, 30, 11);
  const Eigen::MatrixXd before(lp.a_matrix);
  SparseRow first{{29, 0, 5}, {1.5, -2.0, 0.25}, 0.0, 1.0, ""};
  SparseRow second{{}, {}, -1.0, 1.0, ""};  // empty
  SparseRow third{{12}, {7.0}, -kInfinity, 3.0, ""};
  AppendRows(&lp, {first, second, third});
  ExpectCompressedAndValid(lp);
  const Eigen::MatrixXd got(lp.a_matrix);
  ASSERT_EQ(got.rows(), 43);
  EXPECT_EQ(got.topRows(40), before);
  Eigen::MatrixXd added = Eigen::MatrixXd::Zero(3, 30);
  added(0, 29) = 1.5;
  added(0, 0) = -2.0;
  added(0, 5) = 0.25;
  added(2, 12) = 7.0;
  EXPECT_EQ(got.bottomRows(3), added);
}

TEST(ColumnWriter, RefusesMoreEntriesThanItsCapacityAndUnendedColumns) {
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> a;
  internal::ColumnWriter w(&a, 2, 2, 1);
  w.Push(0, 1.0);
  EXPECT_THROW(w.Push(1, 1.0), std::logic_error);
  w.EndColumn();
  EXPECT_THROW(w.Finish(), std::logic_error);
  w.EndColumn();
  w.Finish();
  EXPECT_EQ(Eigen::MatrixXd(a), (Eigen::MatrixXd(2, 2) << 1, 0, 0, 0).finished());
}

}  // namespace
}  // namespace thrustsched::milp
