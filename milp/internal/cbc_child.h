// CBC's driver in a child process (internal to the CBC backend).
//
//   DriverOutcome out = RunDriverInChild(request, &recorder, /*stop_grace_s=*/1.0);
//
// Why: the driver cannot be stopped inside some of its phases (an LP in
// CglPreProcess, a round of cuts, a heuristic's sub-search), keeps its state
// in process-wide globals (two concurrent driver calls corrupt each other in
// the Debian build: coin-or/Cbc#332) and has been seen to crash on
// ill-conditioned models. In a child process (fork) it can be stopped at any
// moment, it cannot take the caller down, and solves from several threads
// run in parallel.
//
// How: the child runs RunDriverHere and streams every progress report and
// every incumbent (original column space) to this process through a pipe,
// then its outcome. This process hands them to the listener as they arrive
// (from the calling thread), and reports a heartbeat when the child is
// silent for the progress interval. When listener->StopRequested() or the
// deadline passes, the child is asked to stop (SIGUSR1: it stops at its next
// check and sends its outcome); if it has not ended stop_grace_s later, it
// is killed, and the outcome is made of what it had reported
// (DriverOutcome::completed false). The child's stderr goes to a file of
// this process (child_stderr.h): when the child dies (an assertion of CBC or
// CLP aborts it), what it wrote ends the outcome's detail; otherwise it is
// passed on to this process's stderr. The child ignores the terminal's SIGINT,
// SIGTERM and SIGHUP (the caller decides what they mean) and dies with the
// calling thread (PR_SET_PDEATHSIG).
#ifndef THRUSTSCHED_MILP_INTERNAL_CBC_CHILD_H_
#define THRUSTSCHED_MILP_INTERNAL_CBC_CHILD_H_

#include "milp/internal/cbc_driver.h"

namespace thrustsched::milp::internal {

DriverOutcome RunDriverInChild(const DriverRequest& request, DriverListener* listener,
                               double stop_grace_s);

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_CBC_CHILD_H_
