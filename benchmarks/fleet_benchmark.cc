// The fleet MILP (transcription/fleet.h): how its size and solve time grow
// with the number of members K and with the keep-out check grid, one CBC
// thread, a 60-s limit per solve.
//
//   build/benchmarks/fleet_benchmark
//
// BM_FleetMirror/<K>/<checks per second>: K double integrators (1 m/s^2
// on-off thrust along +-x and +-y, 8 slots of 1 s, one thruster at a time)
// at rest on the x axis 2 m apart, each to rest at its mirror image (x to
// -x): every pair must cross, and the keep-out (cube of half-size 0.5 m,
// checked every 1 s or 0.5 s) makes them step aside along y. The counters
// give the MILP's size, the keep-out binaries, the final gap, whether the
// optimum was proven within the limit, and the smallest max-norm distance of
// any pair on the checker's fine samples (below 0.5 m: a pair crossed the
// cube between two checks).
#include <algorithm>
#include <limits>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "dynamics/discretisation.h"
#include "dynamics/models.h"
#include "milp/cbc_solver.h"
#include "transcription/fleet.h"

namespace {

namespace ts = thrustsched;
using ts::transcription::FleetProblem;

constexpr int kSlots = 8;

ts::transcription::ScheduleProblem MirrorMember(double x0) {
  ts::transcription::ScheduleProblem p;
  p.model = std::make_shared<ts::dynamics::DoubleIntegrator3d>();
  const Eigen::Vector3d ex(1, 0, 0), ey(0, 1, 0);
  p.thrusters = ts::dynamics::ThrusterSet({{"+X", ex}, {"-X", -ex}, {"+Y", ey}, {"-Y", -ey}}, 1.0,
                                          1.0, 300.0);
  p.grid = ts::dynamics::UniformGrid(0.0, kSlots, kSlots);
  p.initial_state = Eigen::VectorXd::Zero(6);
  p.initial_state[0] = x0;
  p.terminal.kind = ts::transcription::TerminalKind::kFixedState;
  p.terminal.target = Eigen::VectorXd::Zero(6);
  p.terminal.target[0] = -x0;
  return p;
}

FleetProblem MirrorFleet(int members, int checks_per_second) {
  FleetProblem f;
  for (int k = 0; k < members; ++k) {
    const double x0 = 2.0 * k - (members - 1.0);  // -1, 1; -2, 0, 2; -3, -1, 1, 3
    f.members.push_back({"m" + std::to_string(k), MirrorMember(x0)});
  }
  // The middle member of an odd fleet (x = 0) stays put and lets the others by.
  ts::transcription::FleetKeepOut ko;
  ko.half_size_m = 0.5;
  for (int q = 1; q <= kSlots * checks_per_second; ++q)
    ko.check_times_s.push_back(static_cast<double>(q) / checks_per_second);
  f.keep_out = ko;
  return f;
}

void BM_FleetMirror(benchmark::State& state) {
  const FleetProblem f =
      MirrorFleet(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  ts::transcription::FleetSolveOptions o;
  o.milp.relative_gap = 0.0;
  o.milp.threads = 1;
  o.milp.time_limit_s = 60.0;
  const auto solver = ts::milp::MakeCbcSolver();
  ts::transcription::FleetResult r;
  for (auto _ : state) {
    r = ts::transcription::SolveFleet(f, *solver, o);
    benchmark::DoNotOptimize(r.stats.num_rows);  // an int (see min_time_benchmark.cc)
  }
  state.counters["binaries"] = r.stats.num_binaries;
  state.counters["keep_out_binaries"] = r.stats.keep_out_binaries;
  state.counters["rows"] = r.stats.num_rows;
  state.counters["objective"] = r.objective;
  state.counters["gap"] = r.gap;
  state.counters["proven"] = r.status == ts::milp::SolveStatus::kOptimal ? 1 : 0;
  // The re-check on the checker's fine samples: below 0.5 m, the members
  // passed through each other's cube between two checks.
  double closest = std::numeric_limits<double>::infinity();
  for (const auto& pair : r.checked_pairs) closest = std::min(closest, pair.min_box_distance_m);
  state.counters["checked_min_box_m"] = closest;
}
BENCHMARK(BM_FleetMirror)
    ->Args({2, 1})
    ->Args({2, 2})
    ->Args({3, 1})
    ->Args({3, 2})
    ->Args({4, 1})
    ->Args({4, 2})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
