#include "milp/lp_blocks.h"

#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace thrustsched::milp {

namespace {

// Union-find over the columns, with path halving.
class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(static_cast<size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int Find(int a) {
    while (parent_[static_cast<size_t>(a)] != a) {
      int& p = parent_[static_cast<size_t>(a)];
      p = parent_[static_cast<size_t>(p)];
      a = p;
    }
    return a;
  }
  void Join(int a, int b) {
    a = Find(a);
    b = Find(b);
    if (a == b) return;
    if (b < a) std::swap(a, b);
    parent_[static_cast<size_t>(b)] = a;  // the smaller index is the root
  }

 private:
  std::vector<int> parent_;
};

}  // namespace

std::vector<int> ColumnBlocks(const LpData& lp, const std::vector<bool>& coupling,
                              int* num_blocks) {
  const int n = lp.num_cols(), m = lp.num_rows();
  if (!coupling.empty() && static_cast<int>(coupling.size()) != m) {
    throw std::invalid_argument("ColumnBlocks: coupling has " + std::to_string(coupling.size()) +
                                " entries for " + std::to_string(m) + " rows");
  }
  DisjointSets sets(n);
  std::vector<int> first_column(static_cast<size_t>(m), -1);  // per row
  for (int j = 0; j < n; ++j) {
    for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(lp.a_matrix, j); it;
         ++it) {
      const int r = static_cast<int>(it.row());
      if (!coupling.empty() && coupling[static_cast<size_t>(r)]) continue;
      int& first = first_column[static_cast<size_t>(r)];
      if (first < 0) {
        first = j;
      } else {
        sets.Join(first, j);
      }
    }
  }
  std::vector<int> block(static_cast<size_t>(n), -1), number(static_cast<size_t>(n), -1);
  int count = 0;
  for (int j = 0; j < n; ++j) {
    int& b = number[static_cast<size_t>(sets.Find(j))];
    if (b < 0) b = count++;
    block[static_cast<size_t>(j)] = b;
  }
  if (num_blocks != nullptr) *num_blocks = count;
  return block;
}

}  // namespace thrustsched::milp
