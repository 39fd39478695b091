// libFuzzer harness: the MPS and LP writers (milp/model_io.h) on every model
// milp::ReadMpsFile accepts from the fuzzed text. The free MPS written is read
// back and must give the same model: costs, bounds (integer bounds rounded
// inward, as documented), types, rows, coefficients, the exported names, and
// the offset as the fixed column OBJ_CONST. Fixed MPS (when the names fit)
// and LP must write without error. (No LP reader: the LP text is written,
// not read back.) Values are compared to 1e-12 relative
// (absolute below 1): CoinMpsIO's number parser is not correctly rounded.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "milp/model_io.h"
#include "tests/fuzz/fuzz_common.h"
#include "tests/fuzz/mps_file.h"

namespace {

using thrustsched::milp::LpData;
using thrustsched::milp::VarType;

void Expect(bool ok, const std::string& what) {
  if (!ok) throw std::logic_error("MPS round trip: " + what);
}

bool Near(double a, double b) {
  if (a == b) return true;  // also equal infinities
  return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(a));
}

// The bounds and type WriteMps gives column j.
void Written(const LpData& lp, int j, double* lower, double* upper, VarType* type) {
  *lower = lp.col_lower[j];
  *upper = lp.col_upper[j];
  *type = lp.col_type[static_cast<size_t>(j)];
  if (*type == VarType::kContinuous) return;
  if (std::isfinite(*lower)) *lower = std::ceil(*lower);
  if (std::isfinite(*upper)) *upper = std::floor(*upper);
  *type = (*lower == 0.0 && *upper == 1.0) ? VarType::kBinary : VarType::kInteger;
}

void CompareColumns(const LpData& lp, const LpData& back) {
  const int n = lp.num_cols();
  const std::vector<std::string> names = thrustsched::milp::ExportedColumnNames(lp, false);
  Expect(back.num_cols() == n + (lp.objective_offset != 0.0 ? 1 : 0), "number of columns");
  for (int j = 0; j < n; ++j) {
    const std::string at = "column " + names[static_cast<size_t>(j)];
    double lower = 0.0, upper = 0.0;
    VarType type = VarType::kContinuous;
    Written(lp, j, &lower, &upper, &type);
    Expect(back.col_names[static_cast<size_t>(j)] == names[static_cast<size_t>(j)], at + " name");
    Expect(Near(lp.col_cost[j], back.col_cost[j]), at + " cost");
    Expect(Near(lower, back.col_lower[j]) && Near(upper, back.col_upper[j]), at + " bounds");
    Expect(type == back.col_type[static_cast<size_t>(j)], at + " type");
  }
  if (lp.objective_offset != 0.0) {
    Expect(back.col_names.back() == "OBJ_CONST", "offset column");
    Expect(Near(lp.objective_offset, back.col_cost[n]) && back.col_lower[n] == 1.0 &&
               back.col_upper[n] == 1.0,
           "offset column's cost and bounds");
  }
  Expect(back.objective_offset == 0.0, "offset read back");
}

void CompareRows(const LpData& lp, const LpData& back) {
  Expect(back.num_rows() == lp.num_rows(), "number of rows");
  Expect(back.row_names == thrustsched::milp::ExportedRowNames(lp, false), "row names");
  for (int i = 0; i < lp.num_rows(); ++i) {
    Expect(Near(lp.row_lower[i], back.row_lower[i]) && Near(lp.row_upper[i], back.row_upper[i]),
           "bounds of row " + back.row_names[static_cast<size_t>(i)]);
  }
  const Eigen::SparseMatrix<double> diff =
      lp.a_matrix - back.a_matrix.leftCols(lp.num_cols()).eval();
  for (int j = 0; j < diff.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(diff, j); it; ++it) {
      Expect(Near(lp.a_matrix.coeff(it.row(), it.col()), back.a_matrix.coeff(it.row(), it.col())),
             "coefficient (" + std::to_string(it.row()) + ", " + std::to_string(it.col()) + ")");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace thrustsched;
  LpData lp;
  try {
    lp = fuzz::ReadMpsText(fuzz::Text(data, size));
  } catch (const std::runtime_error&) {
    return 0;  // the reader's documented error: mps_fuzz.cc covers it
  }
  std::string mps;
  // The writer's documented refusal: an integer column whose bounds hold no integer.
  if (!fuzz::ExpectContract([&] { mps = milp::ToMpsString(lp); })) return 0;
  const LpData back = fuzz::ReadMpsText(mps);  // what we wrote must read: no catch
  CompareColumns(lp, back);
  CompareRows(lp, back);
  milp::MpsOptions fixed;
  fixed.free_format = false;
  fuzz::ExpectContract([&] { (void)milp::ToMpsString(lp, fixed); });  // long names: documented
  (void)milp::ToLpString(lp);
  return 0;
}
