// The C library's allocator set up for solver sessions on large models: one
// call per process, made by every Solver entry point (Solve,
// SolveLpRelaxation(s), OpenLpSession), so a program need not call it.
//
//   milp::TuneAllocatorForLargeModels();  // idempotent; false: left as it was
//
// Why: glibc's malloc serves every block above its mmap threshold (128 KiB
// at start, raised only when such a block is freed) by a fresh mmap, and
// returns it by munmap on free; a block of its heap above the trim threshold
// goes back to the kernel as well. An LP session that re-solves a GEO week's
// LP (26,000 columns, 66,000 rows) hundreds of times allocates CLP's work
// arrays of a few MiB anew for each solve, and each one is then paged in
// again by the kernel: the window LPs of the search spent two thirds of the
// process' time in the kernel before the thresholds below, and ran twice as
// fast with them (docs/results.md); how fast depended on which steps had
// run before (the threshold is raised by the first large free).
//
// What it sets (glibc only; elsewhere nothing): M_MMAP_THRESHOLD to 32 MiB
// (glibc's largest on 64-bit systems) and M_TRIM_THRESHOLD to 512 MiB, unless
// the environment already sets either (GLIBC_TUNABLES, MALLOC_MMAP_THRESHOLD_,
// MALLOC_TRIM_THRESHOLD_): the user's choice is kept. The cost is memory a
// process keeps after freeing it (at most the trim threshold above its peak
// in use), not a larger peak.
#ifndef THRUSTSCHED_MILP_ALLOCATOR_H_
#define THRUSTSCHED_MILP_ALLOCATOR_H_

#include <cstddef>

namespace thrustsched::milp {

inline constexpr std::size_t kMmapThresholdBytes = std::size_t{32} << 20;
inline constexpr std::size_t kTrimThresholdBytes = std::size_t{512} << 20;

/// Sets the thresholds once per process (later calls return the first
/// call's answer). True if they were set by this call or an earlier one.
bool TuneAllocatorForLargeModels();

/// True when the environment sets either threshold (GLIBC_TUNABLES'
/// mmap_threshold or trim_threshold, MALLOC_MMAP_THRESHOLD_,
/// MALLOC_TRIM_THRESHOLD_): TuneAllocatorForLargeModels then keeps them.
bool AllocatorThresholdsSetByEnvironment();

/// For comparisons with the releases before this setting (the bench's
/// `previous` arm, in its own process): later TuneAllocatorForLargeModels
/// calls leave the allocator as glibc set it. True if no call had tuned it
/// before (otherwise it is too late and nothing changes).
bool KeepDefaultAllocator();

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_ALLOCATOR_H_
