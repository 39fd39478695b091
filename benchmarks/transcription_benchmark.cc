// MILP build benchmarks (transcription layer).
//
//   build/benchmarks/transcription_benchmark --benchmark_filter=BM_Build
//
// BM_BuildGeoWeek/<formulation>_<encoding>  ScheduleMilp from an existing
//     discretisation of the 7-day GEO grid (5 min, 2016 intervals, 4 Anzel
//     thrusters, thesis rules, +-0.05 deg window, end-of-week station-keeping
//     sets): rows, columns and freezing into LpData. Target < 1 s.
// BM_BuildHcwWeek/<encoding>  the same for the thesis Table 4.2 week (HCW,
//     6 ideal thrusters, 12 096 binaries).
// BM_BuildGeoWeekCondensed/<days>  the condensed formulation on 1-3 days of
//     the GEO grid, to show its O(N^2) growth.
// BM_BuildGeoWeekRestricted/<thrusters>  what the search builds for a
//     restricted MILP (transcription/search.cc): the condensed six-thruster
//     GEO week with every slot of the first 1-3 thrusters free (2016-6048
//     slots), then milp::RemoveFixedColumns.
// BM_GeoWeekRelaxation/<method>/<thrusters>  the LP relaxation of the GEO
//     week (4 or 6 thrusters) as the search's phase "relaxation" solves it:
//     by the project's interior point (milp/interior_point.h, method 0) or
//     by CLP's barrier without crossover (method 1, the previous release),
//     with the safe bound of its duals (milp/lp_bound.h). Target 0.2 s.
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "common/constants.h"
#include "dynamics/discretisation.h"
#include "dynamics/geo_model.h"
#include "dynamics/models.h"
#include "dynamics/thrusters.h"
#include "milp/cbc_solver.h"
#include "milp/interior_point.h"
#include "milp/lp_bound.h"
#include "milp/lp_data.h"
#include "transcription/schedule_milp.h"

namespace thrustsched::transcription {
namespace {

constexpr double kDay = common::kSecondsPerDay;

ScheduleProblem GeoProblem(double days, bool six_thrusters = false) {
  ScheduleProblem p;
  p.model = std::make_shared<dynamics::GeoLinearModel>(dynamics::GeoModelOptions{});
  p.thrusters = six_thrusters ? dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005)
                              : dynamics::ThrusterSet::Anzel4(0.265, 4850, 2005);
  p.grid = dynamics::UniformGrid(0.0, days * kDay, static_cast<int>(days * 288));
  p.initial_state = Eigen::VectorXd::Zero(6);
  p.rules.min_burn_s = 300;
  p.rules.min_off_same_s = 1200;
  p.rules.min_gap_other_s = 300;
  p.window.outputs = {1, 2};
  p.window.half_widths = {dynamics::geo::kWindowHalfWidthRad, dynamics::geo::kWindowHalfWidthRad};
  p.terminal.kind = TerminalKind::kStationKeepingSets;
  return p;
}

ScheduleProblem HcwWeek() {
  ScheduleProblem p;
  p.model = std::make_shared<dynamics::HcwModel>(7.2921159e-5);
  p.thrusters = dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005);
  p.grid = dynamics::UniformGrid(0.0, 7 * kDay, 2016);
  p.initial_state = (Eigen::VectorXd(6) << 0, 0, 60000, 0, 0, 0).finished();
  p.rules.min_burn_s = 300;
  p.rules.min_off_same_s = 1200;
  p.rules.min_gap_other_s = 300;
  p.window.outputs = {1, 2};
  p.window.half_widths = {36800, 36800};
  p.window.enforce_from_s = 2 * kDay;
  return p;
}

void RunBuild(benchmark::State& state, const ScheduleProblem& p, const BuildOptions& opt) {
  const dynamics::DiscreteModel dm =
      dynamics::Discretize(*p.model, p.thrusters.AccelerationMatrix(), p.grid, opt.discretisation);
  long long nonzeros = 0;
  for (auto _ : state) {
    ScheduleMilp milp(p, dm, opt);
    nonzeros = milp.stats().num_nonzeros;
    benchmark::DoNotOptimize(milp);
  }
  state.counters["nonzeros"] = static_cast<double>(nonzeros);
}

void BM_BuildGeoWeek(benchmark::State& state, Formulation f, Encoding e) {
  BuildOptions opt;
  opt.discretisation.scheme = dynamics::Scheme::kHermiteSimpson;
  opt.formulation = f;
  opt.encoding = e;
  RunBuild(state, GeoProblem(7), opt);
}
BENCHMARK_CAPTURE(BM_BuildGeoWeek, sparse_tight, Formulation::kSparse, Encoding::kTight)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BuildGeoWeek, sparse_thesis, Formulation::kSparse, Encoding::kThesis)
    ->Unit(benchmark::kMillisecond);

void BM_BuildHcwWeek(benchmark::State& state, Encoding e) {
  BuildOptions opt;
  opt.encoding = e;
  RunBuild(state, HcwWeek(), opt);
}
BENCHMARK_CAPTURE(BM_BuildHcwWeek, tight, Encoding::kTight)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BuildHcwWeek, thesis, Encoding::kThesis)->Unit(benchmark::kMillisecond);

void BM_BuildGeoWeekCondensed(benchmark::State& state) {
  BuildOptions opt;
  opt.discretisation.scheme = dynamics::Scheme::kHermiteSimpson;
  opt.formulation = Formulation::kCondensed;
  RunBuild(state, GeoProblem(static_cast<double>(state.range(0))), opt);
}
BENCHMARK(BM_BuildGeoWeekCondensed)->DenseRange(1, 3)->Unit(benchmark::kMillisecond);

void BM_BuildGeoWeekRestricted(benchmark::State& state) {
  const ScheduleProblem p = GeoProblem(7, /*six_thrusters=*/true);
  BuildOptions opt;
  opt.discretisation.scheme = dynamics::Scheme::kHermiteSimpson;
  opt.formulation = Formulation::kCondensed;
  opt.free_slots = Eigen::MatrixXi::Zero(p.thrusters.size(), p.num_intervals());
  opt.free_slots.topRows(state.range(0)).setOnes();
  const dynamics::DiscreteModel dm =
      dynamics::Discretize(*p.model, p.thrusters.AccelerationMatrix(), p.grid, opt.discretisation);
  long long nonzeros = 0;
  for (auto _ : state) {
    ScheduleMilp milp(p, dm, opt);
    std::vector<int> kept;
    bool feasible = true;
    const milp::LpData small = milp::RemoveFixedColumns(milp.lp(), &kept, &feasible);
    nonzeros = small.num_nonzeros();
    benchmark::DoNotOptimize(small);
  }
  state.counters["nonzeros"] = static_cast<double>(nonzeros);
}
BENCHMARK(BM_BuildGeoWeekRestricted)->DenseRange(1, 3)->Unit(benchmark::kMillisecond);

void BM_GeoWeekRelaxation(benchmark::State& state) {
  const bool own = state.range(0) == 0;
  const ScheduleProblem p = GeoProblem(7, /*six_thrusters=*/state.range(1) == 6);
  BuildOptions opt;
  const dynamics::DiscreteModel dm =
      dynamics::Discretize(*p.model, p.thrusters.AccelerationMatrix(), p.grid, opt.discretisation);
  const ScheduleMilp milp(p, dm, opt);
  const std::unique_ptr<milp::Solver> solver = milp::MakeCbcSolver();
  milp::SolveOptions clp;
  clp.lp_algorithm = milp::LpAlgorithm::kBarrierNoCrossover;
  clp.log_level = 0;
  milp::LpRelaxationResult r;
  for (auto _ : state) {
    r = own ? milp::ToLpRelaxationResult(milp.lp(), milp::SolveLpByInteriorPoint(milp.lp(), {}))
            : solver->SolveLpRelaxation(milp.lp(), clp);
    benchmark::DoNotOptimize(r.x.data());
  }
  state.counters["optimal"] = r.status == milp::SolveStatus::kOptimal ? 1 : 0;
  state.counters["objective"] = r.objective;
  state.counters["safe_bound"] = milp::SafeDualBound(milp.lp(), r.row_duals).bound;
  state.counters["iterations"] = static_cast<double>(r.iterations);
}
BENCHMARK(BM_GeoWeekRelaxation)
    ->ArgsProduct({{0, 1}, {4, 6}})
    ->ArgNames({"method", "thrusters"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace thrustsched::transcription

BENCHMARK_MAIN();
