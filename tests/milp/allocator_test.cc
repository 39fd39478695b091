// milp::TuneAllocatorForLargeModels: after it, a block of a few MiB comes
// from malloc's heap (no new mmap'd chunk), one above the threshold still
// from mmap; KeepDefaultAllocator, called first, leaves glibc's settings.
// Each case runs in a child process: a fresh allocator state.
#include "milp/allocator.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace thrustsched::milp {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitizerAllocator = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitizerAllocator = true;
#else
constexpr bool kSanitizerAllocator = false;
#endif
#else
constexpr bool kSanitizerAllocator = false;
#endif

// Why a case cannot run here ("" if it can).
std::string SkipReason() {
#if !defined(__GLIBC__)
  return "glibc only";
#else
  if (kSanitizerAllocator) return "the sanitizer's allocator ignores mallopt";
  if (AllocatorThresholdsSetByEnvironment()) return "thresholds set by the environment";
  return "";
#endif
}

// mmap'd chunks in use after allocating (and touching) `bytes`, minus before.
long NewMappedChunks(std::size_t bytes) {
#if defined(__GLIBC__)
  const long before = static_cast<long>(mallinfo2().hblks);
  void* p = std::malloc(bytes);
  if (p == nullptr) return -1;
  std::memset(p, 1, bytes);
  const long after = static_cast<long>(mallinfo2().hblks);
  std::free(p);
  return after - before;
#else
  (void)bytes;
  return -1;
#endif
}

// `body` in a child process; its exit status (0: every check held).
int InChild(const std::function<int()>& body) {
  const pid_t pid = fork();
  if (pid == 0) _exit(body());
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 99;
}

TEST(TuneAllocatorForLargeModels, LargeBlocksComeFromTheHeapBelowTheThreshold) {
  if (const std::string why = SkipReason(); !why.empty()) GTEST_SKIP() << why;
  const int status = InChild([] {
    // glibc's default at start: a 4 MiB block is mmap'd.
    if (NewMappedChunks(std::size_t{4} << 20) != 1) return 1;
    if (!TuneAllocatorForLargeModels()) return 2;
    if (!TuneAllocatorForLargeModels()) return 3;  // idempotent
    if (NewMappedChunks(std::size_t{4} << 20) != 0) return 4;
    if (NewMappedChunks(kMmapThresholdBytes / 2) != 0) return 5;
    if (NewMappedChunks(kMmapThresholdBytes * 2) != 1) return 6;
    if (KeepDefaultAllocator()) return 7;  // too late
    return 0;
  });
  EXPECT_EQ(status, 0);
}

TEST(KeepDefaultAllocator, LeavesGlibcsThresholds) {
  if (const std::string why = SkipReason(); !why.empty()) GTEST_SKIP() << why;
  const int status = InChild([] {
    if (!KeepDefaultAllocator()) return 1;
    if (TuneAllocatorForLargeModels()) return 2;
    if (NewMappedChunks(std::size_t{4} << 20) != 1) return 3;
    return 0;
  });
  EXPECT_EQ(status, 0);
}

}  // namespace
}  // namespace thrustsched::milp
