#include "milp/allocator.h"

#include <cstdlib>
#include <cstring>
#include <mutex>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace thrustsched::milp {

bool AllocatorThresholdsSetByEnvironment() {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables != nullptr && (std::strstr(tunables, "mmap_threshold") != nullptr ||
                              std::strstr(tunables, "trim_threshold") != nullptr)) {
    return true;
  }
  return std::getenv("MALLOC_MMAP_THRESHOLD_") != nullptr ||
         std::getenv("MALLOC_TRIM_THRESHOLD_") != nullptr;
}

namespace {

bool Tune() {
#if defined(__GLIBC__)
  if (AllocatorThresholdsSetByEnvironment()) return false;
  const bool mmap_set = mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMmapThresholdBytes)) == 1;
  const bool trim_set = mallopt(M_TRIM_THRESHOLD, static_cast<int>(kTrimThresholdBytes)) == 1;
  return mmap_set && trim_set;
#else
  return false;
#endif
}

enum class AllocatorState { kUndecided, kTuned, kNotTuned, kKeptDefault };

std::mutex allocator_mutex;
AllocatorState allocator_state = AllocatorState::kUndecided;

}  // namespace

bool TuneAllocatorForLargeModels() {
  const std::lock_guard<std::mutex> lock(allocator_mutex);
  if (allocator_state == AllocatorState::kUndecided)
    allocator_state = Tune() ? AllocatorState::kTuned : AllocatorState::kNotTuned;
  return allocator_state == AllocatorState::kTuned;
}

bool KeepDefaultAllocator() {
  const std::lock_guard<std::mutex> lock(allocator_mutex);
  if (allocator_state == AllocatorState::kUndecided) allocator_state = AllocatorState::kKeptDefault;
  return allocator_state == AllocatorState::kKeptDefault;
}

}  // namespace thrustsched::milp
