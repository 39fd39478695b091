// Observers of a `solve` or `simulate` run, injected by tests (and programs
// that embed the CLI) instead of being read from the environment.
//
//   app::RunHooks hooks;
//   hooks.on_progress = app::InterruptSelfAtFirstIncumbent;   // a Ctrl-C mid-search
//   hooks.in_cycle = [](int cycle) { if (cycle == 2) std::abort(); };  // a crash in cycle 2
//   int code = app::RunCli({"thrustsched", "simulate", "year.json", "--out", "out/y"}, hooks);
#ifndef THRUSTSCHED_APP_RUN_HOOKS_H_
#define THRUSTSCHED_APP_RUN_HOOKS_H_

#include <functional>

#include "milp/solver.h"

namespace thrustsched::app {

struct RunHooks {
  /// Called with every progress report of the solver, before the CLI's own
  /// progress line (from the solving thread).
  std::function<void(const milp::SolveProgress&)> on_progress;
  /// `simulate`: called as each cycle's solve starts, with its 1-based number,
  /// inside the crash guard (a process that dies here leaves in_progress.json).
  std::function<void(int cycle)> in_cycle;
};

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_RUN_HOOKS_H_
