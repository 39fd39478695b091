// ColumnWriter: fills a column-major Eigen sparse matrix column by column,
// each column's entries in increasing row order, straight into compressed
// storage. The LP edits of the search (fixed columns removed, rows selected
// or appended) copy matrices of millions of entries (a restricted
// six-thruster GEO week's condensed window rows hold 8.5 M); a triplet list
// and setFromTriplets would copy them three more times.
//
//   Eigen::SparseMatrix<double, Eigen::ColMajor, int> a;
//   internal::ColumnWriter w(&a, /*rows=*/3, /*cols=*/2, /*capacity=*/4);
//   w.Push(0, 1.0);  w.Push(2, 5.0);  w.EndColumn();   // column 0
//   w.Push(1, -2.0);                  w.EndColumn();   // column 1
//   w.Finish();                                        // a has 3 nonzeros
#ifndef THRUSTSCHED_MILP_INTERNAL_COLUMN_WRITER_H_
#define THRUSTSCHED_MILP_INTERNAL_COLUMN_WRITER_H_

#include <stdexcept>

#include <Eigen/SparseCore>

namespace thrustsched::milp::internal {

class ColumnWriter {
 public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  // `capacity`: at least the number of entries that will be pushed.
  ColumnWriter(Matrix* matrix, int rows, int cols, Eigen::Index capacity)
      : matrix_(matrix), cols_(cols), capacity_(capacity) {
    matrix_->resize(rows, cols);
    matrix_->resizeNonZeros(capacity);
    matrix_->outerIndexPtr()[0] = 0;
  }
  void Push(int row, double value) {
    if (position_ == capacity_) throw std::logic_error("ColumnWriter: capacity exceeded");
    matrix_->innerIndexPtr()[position_] = row;
    matrix_->valuePtr()[position_] = value;
    ++position_;
  }
  void EndColumn() { matrix_->outerIndexPtr()[++column_] = static_cast<int>(position_); }
  // Every column ended: drops the unused capacity from the nonzero count.
  void Finish() {
    if (column_ != cols_) throw std::logic_error("ColumnWriter: not every column was ended");
    matrix_->resizeNonZeros(position_);
  }

 private:
  Matrix* matrix_;
  int cols_;
  Eigen::Index capacity_;
  Eigen::Index position_ = 0;
  int column_ = 0;
};

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_COLUMN_WRITER_H_
