// The time to condense a restricted MILP over `slots` free slots, estimated
// from the largest one built so far in the same search (its free slots and
// seconds): the condensed window rows are dense in every earlier free slot,
// and on a GEO week the build time grows about linearly with the free slots
// (docs/results.md, the restricted MILPs' build times).
//
//   double s = internal::RestrictionBuildSeconds(4043, 546, 0.71);  // 5.26
//   internal::RestrictionBuildSeconds(4043, 0, 0.0);                // 0: none built yet
#ifndef THRUSTSCHED_TRANSCRIPTION_INTERNAL_BUILD_TIME_H_
#define THRUSTSCHED_TRANSCRIPTION_INTERNAL_BUILD_TIME_H_

namespace thrustsched::transcription::internal {

inline double RestrictionBuildSeconds(int slots, int built_slots, double built_seconds) {
  if (slots <= 0 || built_slots <= 0 || !(built_seconds > 0.0)) return 0.0;
  return built_seconds * static_cast<double>(slots) / static_cast<double>(built_slots);
}

}  // namespace thrustsched::transcription::internal

#endif  // THRUSTSCHED_TRANSCRIPTION_INTERNAL_BUILD_TIME_H_
