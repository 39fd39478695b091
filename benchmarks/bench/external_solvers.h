// The external cross-check of thrustsched-bench: other solvers solve the
// exported free-MPS file of a case, each as a child process under `timeout`,
// timed wall-clock from here (start-up and model reading included, as for
// every program): the `cbc` program (COIN-OR CBC, Debian coinor-cbc),
// `glpsol` (GLPK, Debian glpk-utils) and HiGHS (its WebAssembly build, npm
// package `highs`, run by node through benchmarks/external/highs_solve.mjs;
// scripts/install-highs.sh installs it into .deps/highs).
//
//   bench::Row r = ...;                      // the case's row, our solve filled
//   bench::RunExternalSolvers("runs/x.mps", "runs/x", 30.0, &r);
//   // r: ext_cbc_*, ext_glpsol_*, ext_highs_* (status, objective, seconds;
//   //    HiGHS also bound and gap)
//   for (const std::string& f : bench::ExternalOutputFiles("runs/x")) std::remove(f.c_str());
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_EXTERNAL_SOLVERS_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_EXTERNAL_SOLVERS_H_

#include <limits>
#include <string>
#include <vector>

#include "benchmarks/bench/results.h"

namespace thrustsched::bench {

struct ExternalResult {
  std::string status = "not run";
  double objective = std::numeric_limits<double>::quiet_NaN();  // NaN: no solution
  double seconds = std::numeric_limits<double>::quiet_NaN();    // wall clock of the process
  double bound = std::numeric_limits<double>::quiet_NaN();      // HiGHS only (mip_dual_bound)
  double gap = std::numeric_limits<double>::quiet_NaN();        // HiGHS only (mip_gap)
};

/// The solvers of the cross-check, in report order: "cbc", "glpsol", "highs".
/// Their columns are ext_<name>_status, ext_<name>_objective, ext_<name>_s.
const std::vector<std::string>& ExternalSolverNames();

/// Runs `solver` (one of ExternalSolverNames()) on the free-MPS file `mps`
/// with a time limit of `limit_s`; its raw output goes to files named from
/// `stem`. Never throws for a solver failure: the status says what happened
/// ("not installed", "skipped: <reason>" for HiGHS, "killed by `timeout` ...").
ExternalResult RunExternalSolver(const std::string& solver, const std::string& mps,
                                 const std::string& stem, double limit_s);

/// Every solver of ExternalSolverNames() on `mps`, one after the other; the
/// results go into the ext_* columns of `row`.
void RunExternalSolvers(const std::string& mps, const std::string& stem, double limit_s, Row* row);

/// The raw-output files the solvers may have written for `stem` (removed by
/// the bench unless --keep-mps).
std::vector<std::string> ExternalOutputFiles(const std::string& stem);

/// The one JSON line of benchmarks/external/highs_solve.mjs read into a
/// result (seconds left NaN: the caller times the process). A runner that
/// could not load the package gives status "skipped: <its reason>".
/// @throws std::runtime_error if `text` has no JSON object line.
ExternalResult ParseHighsOutput(const std::string& text);

/// "highs-js 1.15.3 (HiGHS 1.15.1)", or "HiGHS skipped: <reason>" (for the
/// report's header).
std::string HighsVersionNote();

/// A verdict the cross-check must never give: `solver`'s objective on our
/// exported model below our proven optimum (a wrong optimum of ours or a
/// wrong model), or, where ours is not proven optimal, below the published
/// optimum by more than 0.5 % (published values have 4 significant digits;
/// a lower value would mean our model is looser than the published one).
/// Returns the explanation, or "" when the objective (if any) is consistent.
std::string ExternalBeatsOptimum(const Row& row, const std::string& solver);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_EXTERNAL_SOLVERS_H_
