// COIN-OR CBC/CLP backend (target thrustsched::milp_cbc). This header includes
// no COIN-OR header; only cbc_solver.cc and mps_reader.cc do.
//
//   auto solver = thrustsched::milp::MakeCbcSolver();
//   thrustsched::milp::SolveResult r = solver->Solve(lp, options);
//
// MILPs are solved by the cbc driver (CbcMain1 "-solve": CglPreProcess, the
// default cut generators and heuristics, branch and cut) on a CbcModel over
// OsiClpSolverInterface, with a wall-clock ("timeMode elapsed") time limit, a
// CbcEventHandler for progress, incumbents and the interrupt flag, and the MIP
// start passed as CBC's mipStart plus a cutoff. Models without integer
// columns and LP relaxations are solved by ClpSimplex (presolve + dual
// simplex), with row duals. Models without rows or columns are solved here.
//
// Threading guarantees:
//  * Solver objects are stateless: one object may be used from several
//    threads, and several objects at once.
//  * MILP solves are serialised by a process-wide mutex: the cbc driver of the
//    Debian build (2.10.8, not compiled with CBC_THREAD_SAFE) parses its
//    arguments through process-wide globals, installs a process-wide SIGINT
//    handler during the search, and CglZeroHalf keeps file-static state;
//    two unlocked concurrent solves were measured to corrupt each other
//    (coin-or/Cbc#332). So several MILP solves in parallel threads are safe
//    but run one after another. The wait for the mutex is not charged to a
//    solve's time limit (its clock starts when it gets the driver, and
//    SolveResult::detail reports the wait), so its result does not depend on
//    the other threads; the interrupt flag is honoured while it waits. For
//    truly parallel MILP solves, use one process per solve (as
//    thrustsched-bench does).
//  * LP solves (no integer columns, SolveLpRelaxation) use only per-call CLP
//    objects and run truly in parallel.
//  * threads > 1 switches on CBC's parallel branch and cut (the Debian build
//    has thread support); results are then not deterministic (SolveResult
//    detail says so). threads == 1 (default) is deterministic for the same
//    input and options when no time limit or interrupt cuts the search.
//  * Nothing is printed at log_level 0 (the default), CLP and CGL included.
//  * The initial LP relaxation inside the driver is not interrupted by the
//    time limit (coin-or/Cbc#231); CBC stops at its first check after it.
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
