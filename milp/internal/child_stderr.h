// What a child process writes to its standard error, kept for its parent
// (internal to the CBC backend).
//
//   ChildStderr err;                   // before fork()
//   if (fork() == 0) { err.AttachInChild(); ... }
//   ... waitpid ...
//   std::string said = err.Tail(kChildStderrTailBytes);  // its last words, if any
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

/// At most this much of a dead child's stderr goes into a solve's detail.
inline constexpr size_t kChildStderrTailBytes = 2000;

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
  /// The last `max_bytes` the child wrote (all, if fewer), then without
  /// trailing white space.
  std::string Tail(size_t max_bytes) const;

 private:
  int fd_ = -1;
};

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_CHILD_STDERR_H_
