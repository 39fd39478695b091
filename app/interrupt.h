// Stop requests for long runs (`solve`, `simulate`): the first SIGINT
// (Ctrl-C), SIGTERM (what `timeout`, systemd and batch schedulers send) or
// SIGHUP (the terminal closed) raises a flag that the solver polls (the solve
// stops as at a time limit and keeps its best schedule, which is checked and
// written); a second one ends the program at once (exit 128 + signal).
//
//   {
//     InterruptWatcher watcher;                  // the signals now go to the flag
//     options.interrupt = watcher.flag();
//     result = solver.Solve(lp, options);
//     if (watcher.interrupted()) ...             // watcher.signal_name(): "SIGTERM"
//   }                                            // signal handling restored
//
// Why not a plain signal handler: CBC's driver installs its own SIGINT handler
// while it runs (and swallows the signal in some phases). Instead the signals
// are blocked in every thread (the solver's threads inherit the mask) and a
// watcher thread takes them with sigtimedwait. A signal still pending when
// the watcher ends is consumed (it counts as a stop request) instead of
// killing the program while it writes its results.
#ifndef THRUSTSCHED_APP_INTERRUPT_H_
#define THRUSTSCHED_APP_INTERRUPT_H_

#include <signal.h>

#include <atomic>
#include <thread>

#include "milp/solver.h"

namespace thrustsched::app {

class InterruptWatcher {
 public:
  /// Clears the flag, blocks SIGINT in the calling thread (threads it starts
  /// later inherit that) and starts the watcher. One watcher at a time.
  InterruptWatcher();
  ~InterruptWatcher();
  InterruptWatcher(const InterruptWatcher&) = delete;
  InterruptWatcher& operator=(const InterruptWatcher&) = delete;

  /// The flag to hand to milp::SolveOptions::interrupt; it outlives the watcher.
  static const std::atomic<bool>* flag();
  /// A stop signal was received since this watcher started.
  static bool interrupted();
  /// "SIGINT", "SIGTERM" or "SIGHUP": the first stop signal received ("" if none).
  static const char* signal_name();

 private:
  void Watch();

  sigset_t set_{};
  sigset_t old_{};
  bool blocked_ = false;
  std::atomic<bool> done_{false};
  std::thread thread_;
};

/// A progress hook (RunHooks::on_progress) for a deterministic Ctrl-C test:
/// the first new incumbent reported sends SIGINT to this process and waits
/// (up to 10 s) until the watcher has raised the flag, so the solve is
/// interrupted right there, mid-search, through the same path as a real
/// Ctrl-C. Later reports do nothing.
void InterruptSelfAtFirstIncumbent(const milp::SolveProgress& p);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_INTERRUPT_H_
