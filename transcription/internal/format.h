// Number formatting for error messages of the transcription module: the
// value with `precision` significant digits, no trailing noise.
//
//   throw std::invalid_argument("radius must be > 0, got " + internal::FormatNumber(r));
#ifndef THRUSTSCHED_TRANSCRIPTION_INTERNAL_FORMAT_H_
#define THRUSTSCHED_TRANSCRIPTION_INTERNAL_FORMAT_H_

#include <sstream>
#include <string>

namespace thrustsched::transcription::internal {

inline std::string FormatNumber(double value, int precision = 10) {
  std::ostringstream os;
  os.precision(precision);
  os << value;
  return os.str();
}

}  // namespace thrustsched::transcription::internal

#endif  // THRUSTSCHED_TRANSCRIPTION_INTERNAL_FORMAT_H_
