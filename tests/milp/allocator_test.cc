// milp::TuneAllocatorForLargeModels: after it, a block of a few MiB comes
// from malloc's heap (no new mmap'd chunk), one above the threshold still
// from mmap; KeepDefaultAllocator, called first, leaves glibc's settings.
#include "milp/allocator.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>

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

#if defined(__GLIBC__)
// mmap'd chunks in use after allocating (and touching) `bytes`, minus before.
long NewMappedChunks(std::size_t bytes) {
  const long before = static_cast<long>(mallinfo2().hblks);
  void* p = std::malloc(bytes);
  EXPECT_NE(p, nullptr);
  std::memset(p, 1, bytes);
  const long after = static_cast<long>(mallinfo2().hblks);
  std::free(p);
  return after - before;
}

// Runs `body` in a child process (a fresh allocator state for this
// executable's other tests); its exit status.
template <typename Body>
int InChild(Body body) {
  const pid_t pid = fork();
  if (pid == 0) _exit(body());
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 99;
}
#endif

bool ThresholdsFromEnvironment() {
  const char* t = std::getenv("GLIBC_TUNABLES");
  return (t != nullptr && std::strstr(t, "threshold") != nullptr) ||
         std::getenv("MALLOC_MMAP_THRESHOLD_") != nullptr ||
         std::getenv("MALLOC_TRIM_THRESHOLD_") != nullptr;
}

TEST(TuneAllocatorForLargeModels, LargeBlocksComeFromTheHeapBelowTheThreshold) {
#if !defined(__GLIBC__)
  GTEST_SKIP() << "glibc only";
#else
  if (kSanitizerAllocator) GTEST_SKIP() << "the sanitizer's allocator ignores mallopt";
  if (ThresholdsFromEnvironment()) GTEST_SKIP() << "thresholds set by the environment";
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
#endif
}

TEST(KeepDefaultAllocator, LeavesGlibcsThresholds) {
#if !defined(__GLIBC__)
  GTEST_SKIP() << "glibc only";
#else
  if (kSanitizerAllocator) GTEST_SKIP() << "the sanitizer's allocator ignores mallopt";
  if (ThresholdsFromEnvironment()) GTEST_SKIP() << "thresholds set by the environment";
  const int status = InChild([] {
    if (!KeepDefaultAllocator()) return 1;
    if (TuneAllocatorForLargeModels()) return 2;
    if (NewMappedChunks(std::size_t{4} << 20) != 1) return 3;
    return 0;
  });
  EXPECT_EQ(status, 0);
#endif
}

}  // namespace
}  // namespace thrustsched::milp
