// Benchmarks for dynamics/discretisation.h: one week of 5-minute intervals
// (2016), every scheme.
//
//   BM_DiscretiseHcw/<scheme>           HCW (LTI), 6 inputs, uniform grid: the
//                                       step map is computed once and reused.
//   BM_DiscretiseHcwIrregular/<scheme>  same, grid jittered by up to +-1 s so
//                                       every interval is computed (LTI per-step cost).
//   BM_DiscretiseSynthetic/<scheme>     6-state time-varying model, 4 inputs
//                                       (Anzel), A/B/d built from a few trig
//                                       terms: the per-interval cost profile
//                                       of the GEO model (benchmarks/geo_benchmark.cc).
//
//   ./build/benchmarks/dynamics_benchmark --benchmark_filter=Synthetic
#include <cmath>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "dynamics/discretisation.h"
#include "dynamics/models.h"
#include "dynamics/thrusters.h"

namespace thrustsched::dynamics {
namespace {

constexpr double kN = 7.2921159e-5;  // GEO mean motion, rad/s

// HCW plus slowly varying periodic couplings, input rotation and drift.
class SyntheticLtv final : public LinearModel {
 public:
  std::string_view name() const override { return "synthetic_ltv"; }
  int num_states() const override { return 6; }
  int num_inputs() const override { return 3; }
  int num_outputs() const override { return 3; }
  bool is_time_invariant() const override { return false; }
  ModelMatrices Evaluate(double t) const override {
    const double s1 = std::sin(kN * t), c1 = std::cos(kN * t);
    const double s2 = std::sin(2 * kN * t), c2 = std::cos(2 * kN * t);
    ModelMatrices m = hcw_.Evaluate(t);
    const double e = 1e-3 * kN * kN;
    m.a(3, 0) += e * c1;
    m.a(3, 1) += e * s2;
    m.a(4, 0) += e * s1;
    m.a(4, 1) += e * c2;
    m.a(5, 2) += e * c1 * s1;
    m.b(3, 1) = 1e-3 * s1;
    m.b(4, 0) = -1e-3 * s1;
    m.b(5, 0) = 1e-4 * c2;
    m.d << 0, 0, 0, 1e-7 * c1, 2e-7 * s1 + 1e-8, 5e-8 * s2;
    return m;
  }
  OutputMatrices EvaluateOutput(double t) const override { return hcw_.EvaluateOutput(t); }
  std::vector<std::string> state_names() const override { return hcw_.state_names(); }
  std::vector<std::string> output_names() const override { return hcw_.output_names(); }
  Eigen::VectorXd state_scale() const override { return hcw_.state_scale(); }
  double time_scale() const override { return hcw_.time_scale(); }

 private:
  HcwModel hcw_{kN};
};

std::vector<double> WeekGrid(bool jitter) {
  std::vector<double> grid = UniformGrid(0.0, 604800.0, 2016);
  if (jitter) {
    for (size_t j = 1; j + 1 < grid.size(); ++j) grid[j] += std::sin(12.9898 * j);  // +-1 s
  }
  return grid;
}

void RunDiscretise(benchmark::State& state, const LinearModel& model, const Eigen::MatrixXd& u,
                   const std::vector<double>& grid) {
  DiscretizationOptions opt;
  opt.scheme = AllSchemes().at(state.range(0));
  state.SetLabel(std::string(ToString(opt.scheme)));
  for (auto _ : state) {
    DiscreteModel dm = Discretize(model, u, grid, opt);
    benchmark::DoNotOptimize(dm.phi.back().data());
  }
  state.counters["intervals"] = static_cast<double>(grid.size() - 1);
}

void BM_DiscretiseHcw(benchmark::State& state) {
  const HcwModel hcw(kN);
  RunDiscretise(state, hcw, ThrusterSet::Ideal6(0.265, 4850.0, 2005.0).AccelerationMatrix(),
                WeekGrid(false));
}

void BM_DiscretiseHcwIrregular(benchmark::State& state) {
  const HcwModel hcw(kN);
  RunDiscretise(state, hcw, ThrusterSet::Ideal6(0.265, 4850.0, 2005.0).AccelerationMatrix(),
                WeekGrid(true));
}

void BM_DiscretiseSynthetic(benchmark::State& state) {
  const SyntheticLtv model;
  RunDiscretise(state, model, ThrusterSet::Anzel4(0.265, 4850.0, 2005.0).AccelerationMatrix(),
                WeekGrid(false));
}

// One argument per scheme, in AllSchemes() order (0 = exact_zoh ... 7 = reference).
BENCHMARK(BM_DiscretiseHcw)->DenseRange(0, 7)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DiscretiseHcwIrregular)->DenseRange(0, 7)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DiscretiseSynthetic)->DenseRange(0, 7)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace thrustsched::dynamics

BENCHMARK_MAIN();
