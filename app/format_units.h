// Numbers in human units for the text summaries and report.html: a relative
// gap as a percentage (a gap at rounding level reads "0 %"), a duration in the
// unit a reader thinks in (s, min, h, d).
//
//   FormatPercent(1.5e-16)  -> "0 %"          FormatPercent(0.0123) -> "1.23 %"
//   FormatDuration(374300)  -> "104 h"        FormatDuration(42)    -> "42 s"
#ifndef THRUSTSCHED_APP_FORMAT_UNITS_H_
#define THRUSTSCHED_APP_FORMAT_UNITS_H_

#include <string>

namespace thrustsched::app {

/// Relative gaps below this are rounding noise of the solver's arithmetic
/// (CBC reports 1e-14-level gaps on proven optima) and print as "0 %".
inline constexpr double kZeroGap = 1e-9;

/// `fraction` (0.0123 = 1.23 %) with 3 significant digits and " %";
/// |fraction| < kZeroGap -> "0 %"; NaN -> "n/a"; infinite -> "inf %".
std::string FormatPercent(double fraction);

/// `v` with `digits` significant digits (%g style: "0.0163918", "1.5e-07");
/// NaN -> "n/a", infinities -> "inf" / "-inf".
std::string FormatSignificant(double v, int digits = 6);

/// Seconds in s (< 2 min), min (< 2 h), h (< 10 d) or d, 3 significant
/// digits; 0 -> "0 s"; NaN -> "n/a".
std::string FormatDuration(double seconds);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_FORMAT_UNITS_H_
