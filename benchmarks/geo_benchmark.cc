// GEO station-keeping dynamics benchmarks.
//
//   build/benchmarks/geo_benchmark --benchmark_filter=BM_Geo
//
// BM_GeoEvaluate          one GeoLinearModel::Evaluate (A, B, d at one t; target < 20 us)
// BM_GeoEvaluateOutput    one C, C' evaluation
// BM_DiscretiseGeoWeek/S  Discretize on the 7-day, 5-min grid (2016 intervals) with the
//                         4 Anzel thrusters, for every scheme except "reference"
//                         (target < 0.2 s per scheme)
// BM_GeoSimulateWeek      nonlinear propagation of 7 days, samples every 5 min, one burn a day
// BM_GeoSimulateYear      nonlinear free drift for 365 days, daily samples
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "common/constants.h"
#include "dynamics/discretisation.h"
#include "dynamics/geo_model.h"
#include "dynamics/geo_simulator.h"
#include "dynamics/thrusters.h"

namespace thrustsched::dynamics {
namespace {

constexpr double kDay = common::kSecondsPerDay;

void BM_GeoEvaluate(benchmark::State& state) {
  const GeoLinearModel model{GeoModelOptions{}};
  double t = 0.0;
  for (auto _ : state) {
    ModelMatrices m = model.Evaluate(t);
    benchmark::DoNotOptimize(m);
    t += 150.0;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GeoEvaluate)->Unit(benchmark::kMicrosecond);

void BM_GeoEvaluateOutput(benchmark::State& state) {
  const GeoLinearModel model{GeoModelOptions{}};
  double t = 0.0;
  for (auto _ : state) {
    OutputMatrices m = model.EvaluateOutput(t);
    benchmark::DoNotOptimize(m);
    t += 150.0;
  }
}
BENCHMARK(BM_GeoEvaluateOutput)->Unit(benchmark::kMicrosecond);

void BM_DiscretiseGeoWeek(benchmark::State& state, Scheme scheme) {
  const GeoLinearModel model{GeoModelOptions{}};
  const Eigen::MatrixXd u = ThrusterSet::Anzel4(0.265, 4850, 2005).AccelerationMatrix();
  const std::vector<double> grid = UniformGrid(0.0, 7 * kDay, 2016);
  DiscretizationOptions options;
  options.scheme = scheme;
  for (auto _ : state) {
    DiscreteModel dm = Discretize(model, u, grid, options);
    benchmark::DoNotOptimize(dm);
  }
  state.counters["intervals"] = 2016;
}

const bool kRegistered = [] {
  for (Scheme scheme : AllSchemes()) {
    if (scheme == Scheme::kReference) continue;
    benchmark::RegisterBenchmark(("BM_DiscretiseGeoWeek/" + std::string(ToString(scheme))).c_str(),
                                 BM_DiscretiseGeoWeek, scheme)
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

void BM_GeoSimulateWeek(benchmark::State& state) {
  const GeoSimulator sim{GeoModelOptions{}};
  const Eigen::MatrixXd u = ThrusterSet::Anzel4(0.265, 4850, 2005).AccelerationMatrix();
  const Vector6d x0 = sim.EciFromRelative(Eigen::VectorXd::Zero(6), 0.0);
  std::vector<InputPulse> pulses;
  for (int d = 0; d < 7; ++d) pulses.push_back({d % 4, d * kDay + 20000.0, d * kDay + 21800.0});
  std::vector<double> samples;
  for (int k = 0; k <= 2016; ++k) samples.push_back(300.0 * k);
  for (auto _ : state) {
    std::vector<Vector6d> xs = sim.Propagate(x0, 0.0, u, pulses, samples);
    benchmark::DoNotOptimize(xs);
  }
  state.counters["simulated_days"] = 7;
}
BENCHMARK(BM_GeoSimulateWeek)->Unit(benchmark::kMillisecond);

void BM_GeoSimulateYear(benchmark::State& state) {
  const GeoSimulator sim{GeoModelOptions{}};
  const Vector6d x0 = sim.EciFromRelative(Eigen::VectorXd::Zero(6), 0.0);
  std::vector<double> samples;
  for (int d = 0; d <= 365; ++d) samples.push_back(d * kDay);
  for (auto _ : state) {
    std::vector<Vector6d> xs = sim.Propagate(x0, 0.0, Eigen::MatrixXd::Zero(3, 1), {}, samples);
    benchmark::DoNotOptimize(xs);
  }
  state.counters["simulated_days"] = 365;
}
BENCHMARK(BM_GeoSimulateYear)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace thrustsched::dynamics

BENCHMARK_MAIN();
