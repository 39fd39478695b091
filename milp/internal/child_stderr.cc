#include "milp/internal/child_stderr.h"

#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>

namespace thrustsched::milp::internal {

ChildStderr::ChildStderr() : fd_(memfd_create("thrustsched-child-stderr", MFD_CLOEXEC)) {}

ChildStderr::~ChildStderr() {
  if (fd_ >= 0) close(fd_);
}

void ChildStderr::AttachInChild() const {
  if (fd_ >= 0) dup2(fd_, STDERR_FILENO);  // the copy does not close on exec
}

std::string ChildStderr::AfterExit(bool died) const {
  constexpr size_t kMaxBytesInAReason = 2000;
  const std::string said = Tail(kMaxBytesInAReason);
  if (said.empty()) return {};
  if (died) return "; it wrote: " + said;
  std::fprintf(stderr, "%s\n", said.c_str());
  return {};
}

std::string ChildStderr::Tail(size_t max_bytes) const {
  if (fd_ < 0) return {};
  struct stat st {};
  if (fstat(fd_, &st) != 0 || st.st_size <= 0) return {};
  const auto size = static_cast<size_t>(st.st_size);
  const size_t length = std::min(size, max_bytes);
  std::string text(length, '\0');
  size_t done = 0;
  while (done < length) {
    const ssize_t n =
        pread(fd_, &text[done], length - done, static_cast<off_t>(size - length + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<size_t>(n);
  }
  text.resize(done);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ' || text.back() == '\r')) {
    text.pop_back();
  }
  return text;
}

}  // namespace thrustsched::milp::internal
