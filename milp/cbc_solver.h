// COIN-OR CBC/CLP backend (target thrustsched::milp_cbc). This header includes
// no COIN-OR header; only cbc_solver.cc, mps_reader.cc and milp/internal/*.cc do.
//
//   auto solver = thrustsched::milp::MakeCbcSolver();
//   thrustsched::milp::SolveResult r = solver->Solve(lp, options);
//
// MILPs are solved by the cbc driver (CbcMain1 "-solve": CglPreProcess, the
// default cut generators and heuristics, branch and cut) on a CbcModel over
// OsiClpSolverInterface, with a wall-clock ("timeMode elapsed") time limit, a
// CbcEventHandler for progress, incumbents and stop requests, and the MIP
// start passed as CBC's mipStart plus a cutoff. Models without integer
// columns and LP relaxations are solved by ClpSimplex (presolve +
// SolveOptions::lp_algorithm), with row duals. Models without rows or
// columns are solved here.
//
// Guarantees:
//  * A solution found is never lost. By default (SolveOptions::cbc.
//    separate_process) the driver runs in a child process that streams every
//    incumbent of its search to the caller's process, in the original column
//    space, as soon as CBC has it; whatever ends the solve (gap, time or node
//    limit, interrupt, the driver dropping its incumbent before its
//    post-processing, a crash of CBC), the best one is completed
//    (SolveOptions::complete_solution, else an LP over the continuous
//    columns), verified against the model and returned with status kFeasible
//    and its gap.
//  * The time limit and the interrupt flag stop the solve within
//    SolveOptions::cbc.stop_grace_s in every phase, CLP's LPs inside the
//    driver included (the child is asked to stop, then killed): the driver
//    itself ignores its limit in its initial LP (coin-or/Cbc#231).
//  * Progress reaches SolveOptions::progress at least every
//    progress_interval_s (a heartbeat naming the phase when CBC reports
//    nothing), from the calling thread.
//  * Solver objects are stateless: one object may be used from several
//    threads, and several objects at once. In child processes, MILP solves
//    from several threads run truly in parallel; in this process
//    (separate_process off) they are serialised by a process-wide mutex: the
//    cbc driver of the Debian build (2.10.8, not compiled with
//    CBC_THREAD_SAFE) parses its arguments through process-wide globals,
//    installs a SIGINT handler during the search, and CglZeroHalf keeps
//    file-static state (coin-or/Cbc#332). The wait for the mutex is not
//    charged to a solve's time limit (SolveResult::detail reports it).
//  * LP solves (no integer columns, SolveLpRelaxation) use only per-call CLP
//    objects and run in parallel in this process.
//  * threads > 1 switches on CBC's parallel branch and cut (the Debian build
//    has thread support); results are then not deterministic (SolveResult
//    detail says so). threads == 1 (default) is deterministic for the same
//    input and options when no time limit or interrupt cuts the search, in a
//    child process or not.
//  * Nothing is printed at log_level 0 (the default), CLP and CGL included.
#ifndef THRUSTSCHED_MILP_CBC_SOLVER_H_
#define THRUSTSCHED_MILP_CBC_SOLVER_H_

#include <memory>
#include <string>

#include "milp/solver.h"

namespace thrustsched::milp {

/// "CBC <version> / CLP <version>"
std::string CbcVersion();
std::unique_ptr<Solver> MakeCbcSolver();

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_CBC_SOLVER_H_
