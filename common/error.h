// The `bool IsValid(std::string* error) const` convention of the options
// structs: a failed check stores its message (naming the field and the value)
// when the caller asked for it, and returns false.
//
//   if (!(step_s > 0)) return common::Fail(error, "step_s must be > 0, got " +
//   common::FormatG(step_s, 10));
#ifndef THRUSTSCHED_COMMON_ERROR_H_
#define THRUSTSCHED_COMMON_ERROR_H_

#include <string>

namespace thrustsched::common {

/// Stores `message` in `*error` when `error` is not null; returns false.
inline bool Fail(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
  return false;
}

}  // namespace thrustsched::common

#endif  // THRUSTSCHED_COMMON_ERROR_H_
