// Writing to the pipe from a child process to its parent (internal to the
// CBC backend's child processes, cbc_child.cc and lp_child.cc).
//
//   WriteAllOrExit(fd, &header, sizeof(header));   // _exit(3) if the parent is gone
#ifndef THRUSTSCHED_MILP_INTERNAL_PIPE_IO_H_
#define THRUSTSCHED_MILP_INTERNAL_PIPE_IO_H_

#include <unistd.h>

#include <cerrno>
#include <cstddef>

namespace thrustsched::milp::internal {

/// Writes all `size` bytes (retrying after signals); a child whose parent
/// has gone has nobody to report to and ends (exit status 3).
inline void WriteAllOrExit(int fd, const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(3);
    p += n;
    size -= static_cast<size_t>(n);
  }
}

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_PIPE_IO_H_
