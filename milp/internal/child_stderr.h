// What a child process writes to its standard error, kept for its parent
// (internal to the CBC backend).
//
//   ChildStderr err;                   // before fork()
//   if (fork() == 0) { err.AttachInChild(); ... }
//   ... waitpid ...
//   detail += err.AfterExit(/*died=*/true);  // "; it wrote: ..." or ""
//
// Why: CBC and CLP report broken internal invariants by assert(), which
// prints to stderr and aborts. In the child that runs CBC's driver (see
// cbc_child.h) that abort is survived, and its message belongs in the
// solve's detail, next to "the CBC process died", not scattered through the
// caller's terminal or progress display. An anonymous in-memory file
// (memfd) rather than a pipe: the child never blocks on it, whatever it
// writes and whenever the parent reads.
#ifndef THRUSTSCHED_MILP_INTERNAL_CHILD_STDERR_H_
#define THRUSTSCHED_MILP_INTERNAL_CHILD_STDERR_H_

#include <cstddef>
#include <string>

namespace thrustsched::milp::internal {

class ChildStderr {
 public:
  /// Creates the file; without one (an old kernel), nothing is captured and
  /// the child writes to the parent's stderr as before.
  ChildStderr();
  ~ChildStderr();
  ChildStderr(const ChildStderr&) = delete;
  ChildStderr& operator=(const ChildStderr&) = delete;

  /// In the child after fork(): its stderr becomes the file.
  void AttachInChild() const;
  /// After the child has ended. If it died: its last words (at most 2000
  /// bytes) as "; it wrote: ...", to end the reason it died; "" if it wrote
  /// nothing. Otherwise what it wrote is passed on to this process's stderr
  /// and "" returned.
  std::string AfterExit(bool died) const;
  /// The last `max_bytes` the child wrote (all, if fewer), then without
  /// trailing white space.
  std::string Tail(size_t max_bytes) const;

 private:
  int fd_ = -1;
};

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_CHILD_STDERR_H_
