// Micro-benchmarks of the MILP builder and writers (no solver).
//
//   build/benchmarks/milp_benchmark --benchmark_filter=BuildAndFreeze
//
// BM_BuildAndFreeze builds a model of `cols` columns and `cols * 10` nonzeros
// (rows of 10 terms) and freezes it with ToLpData(), either one expression per
// row (AddConstraint) or in bulk (AddRows from triplets). Requirement: 1e5
// columns and 1e6 nonzeros in < 1 s on either path.
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "milp/model.h"
#include "milp/model_io.h"

namespace thrustsched::milp {
namespace {

constexpr int kTermsPerRow = 10;

int Column(int row, int k, int cols) {
  return static_cast<int>((static_cast<long long>(row) * 7 + static_cast<long long>(k) * 9973) %
                          cols);
}

double Value(int row, int k) { return 1.0 + 0.001 * ((row + 3 * k) % 97); }

// args: cols, named (0: generated names, 1: "<prefix>[i]" block names)
void BM_BuildAndFreezeExpressions(benchmark::State& state) {
  const int cols = static_cast<int>(state.range(0));
  const bool named = state.range(1) != 0;
  const int rows = cols;
  long long nnz = 0;
  for (auto _ : state) {
    Model m("bench");
    VarBlock x = m.AddVariables(cols, 0, 1, VarType::kBinary, named ? "x" : "");
    LinearExpr e;
    for (int i = 0; i < rows; ++i) {
      e = LinearExpr();
      for (int k = 0; k < kTermsPerRow; ++k) e.AddTerm(x[Column(i, k, cols)], Value(i, k));
      m.AddConstraint(e, -kInfinity, 5.0, named ? "row" + std::to_string(i) : std::string());
    }
    m.Minimize(LinearExpr::Sum(x));
    LpData lp = m.ToLpData();
    nnz = lp.num_nonzeros();
    benchmark::DoNotOptimize(lp.a_matrix.valuePtr());
  }
  state.counters["rows"] = rows;
  state.counters["cols"] = cols;
  state.counters["nnz"] = static_cast<double>(nnz);
}

void BM_BuildAndFreezeBulk(benchmark::State& state) {
  const int cols = static_cast<int>(state.range(0));
  const bool named = state.range(1) != 0;
  const int rows = cols;
  std::vector<RowTriplet> triplets;  // input data, made once
  triplets.reserve(static_cast<size_t>(rows) * kTermsPerRow);
  for (int i = 0; i < rows; ++i) {
    for (int k = 0; k < kTermsPerRow; ++k) triplets.push_back({i, Column(i, k, cols), Value(i, k)});
  }
  const Eigen::VectorXd lower = Eigen::VectorXd::Constant(rows, -kInfinity);
  const Eigen::VectorXd upper = Eigen::VectorXd::Constant(rows, 5.0);
  long long nnz = 0;
  for (auto _ : state) {
    Model m("bench");
    VarBlock x = m.AddVariables(cols, 0, 1, VarType::kBinary, named ? "x" : "");
    m.AddRows(triplets, lower, upper, named ? "row" : "");
    m.Minimize(LinearExpr::Sum(x));
    LpData lp = m.ToLpData();
    nnz = lp.num_nonzeros();
    benchmark::DoNotOptimize(lp.a_matrix.valuePtr());
  }
  state.counters["rows"] = rows;
  state.counters["cols"] = cols;
  state.counters["nnz"] = static_cast<double>(nnz);
}

// Writing free MPS of the same model to a discarding stream.
void BM_WriteMps(benchmark::State& state) {
  const int cols = static_cast<int>(state.range(0));
  std::vector<RowTriplet> triplets;
  for (int i = 0; i < cols; ++i) {
    for (int k = 0; k < kTermsPerRow; ++k) triplets.push_back({i, Column(i, k, cols), Value(i, k)});
  }
  Model m("bench");
  VarBlock x = m.AddVariables(cols, 0, 1, VarType::kBinary, "x");
  m.AddRows(triplets, Eigen::VectorXd::Constant(cols, -kInfinity),
            Eigen::VectorXd::Constant(cols, 5.0), "row");
  m.Minimize(LinearExpr::Sum(x));
  const LpData lp = m.ToLpData();
  struct NullBuf : std::streambuf {
    std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
    int overflow(int c) override { return c; }
  } null_buf;
  std::ostream os(&null_buf);
  for (auto _ : state) WriteMps(os, lp);
  state.counters["nnz"] = static_cast<double>(lp.num_nonzeros());
}

BENCHMARK(BM_BuildAndFreezeExpressions)
    ->ArgsProduct({{10000, 100000}, {0, 1}})
    ->ArgNames({"cols", "named"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuildAndFreezeBulk)
    ->ArgsProduct({{10000, 100000}, {0, 1}})
    ->ArgNames({"cols", "named"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WriteMps)->Arg(100000)->ArgName("cols")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace thrustsched::milp

BENCHMARK_MAIN();
