// Keyword-value notation (KVN) of the CCSDS Orbit Data Messages, CCSDS
// 502.0-B-3 §7: the lexical layer shared by the OEM and OPM readers and
// writers (app/ccsds_oem.h, app/ccsds_opm.h), and the typed values they
// share (epochs, time systems, frames, centres, numbers with units).
//
//   for (const app::KvnLine& l : app::ReadKvn(text)) {
//     if (l.kind == app::KvnLine::kKeyValue && l.keyword == "X") x_km = app::KvnNumber("orbit.opm",
//     l, "km");
//   }
//   std::string row = app::KvnKeyValue("MAN_DURATION", "600.000", "s");  // "MAN_DURATION  ... =
//   600.000 [s]"
//
// Every reading error is a ScenarioError (bad input, exit 2) whose message
// names the file, the line, the keyword and its value.
#ifndef THRUSTSCHED_APP_CCSDS_KVN_H_
#define THRUSTSCHED_APP_CCSDS_KVN_H_

#include <string>
#include <string_view>
#include <vector>

#include "app/json_reader.h"
#include "dynamics/frames.h"
#include "dynamics/time.h"

namespace thrustsched::app {

/// One non-blank line of a KVN file.
struct KvnLine {
  enum Kind {
    kKeyValue,  // KEYWORD = value [units]
    kComment,   // COMMENT text
    kMarker,    // a block keyword alone: META_START, META_STOP, COVARIANCE_START, ...
    kData,      // anything else: an ephemeris data line
  };
  Kind kind = kData;
  int number = 0;       // 1-based line number
  std::string keyword;  // kKeyValue, kComment ("COMMENT"), kMarker
  std::string value;    // kKeyValue: the value without units; kComment: the text
  std::string units;    // kKeyValue: the text inside [ ] if given
  std::string text;     // the whole line, trimmed
};

/// Splits text into lines (blank lines dropped, surrounding blanks trimmed).
/// Keywords are upper case per §7.4.5; the values keep their case.
std::vector<KvnLine> ReadKvn(std::string_view text);

/// Error at a line: "<source>:<line>: <KEYWORD> = <value>: <why>" (or the
/// line's text for data lines).
[[noreturn]] void KvnFail(const std::string& source, const KvnLine& line, const std::string& why);

/// A finite number; if the line gives units they must be `units` (case
/// insensitive; "" = dimensionless, any units then rejected).
double KvnNumber(const std::string& source, const KvnLine& line, std::string_view units);
/// TIME_SYSTEM value: UTC, TAI, TT or GPS (others rejected, naming them).
dynamics::TimeScale KvnTimeSystem(const std::string& source, const KvnLine& line);
/// REF_FRAME value: EME2000 (or J2000) or GCRF.
dynamics::InertialFrame KvnFrame(const std::string& source, const KvnLine& line);
/// CENTER_NAME value: must be EARTH.
void KvnCheckCenter(const std::string& source, const KvnLine& line);
/// An epoch "YYYY-MM-DDThh:mm:ss[.d..d][Z]" or "YYYY-DDDThh:mm:ss[.d..d][Z]"
/// (§7.5.10) in time system `scale`, returned as the UTC instant.
dynamics::Epoch KvnEpoch(const std::string& source, const KvnLine& line, dynamics::TimeScale scale);
/// Parses the epoch text itself (data lines). @throws std::invalid_argument.
dynamics::Epoch ParseCcsdsEpoch(std::string_view text, dynamics::TimeScale scale);

/// "YYYY-MM-DDThh:mm:ss.fff" (UTC, no 'Z'), with 6 decimals when the instant
/// is not a whole millisecond.
std::string CcsdsEpochText(const dynamics::Epoch& epoch);
/// "KEYWORD = value" or "KEYWORD = value [units]", keyword padded so that the
/// '=' signs of a block line up.
std::string KvnKeyValue(std::string_view keyword, std::string_view value,
                        std::string_view units = "");
/// The header lines of a message: "<version_keyword> = <version>", the
/// comments, CREATION_DATE and ORIGINATOR (CCSDS 502.0-B-3 §3.2.2, §5.2.2).
std::string KvnHeader(std::string_view version_keyword, std::string_view version,
                      const std::vector<std::string>& comments,
                      const dynamics::Epoch& creation_date, std::string_view originator);
/// Fixed-point text of a number with `decimals` decimals.
std::string KvnFixed(double value, int decimals);

/// CREATION_DATE of written files: the time SOURCE_DATE_EPOCH names (seconds
/// since 1970-01-01T00:00:00Z, the reproducible-builds convention), else the
/// current time. @throws ScenarioError if SOURCE_DATE_EPOCH is set but not an
/// integer number of seconds.
dynamics::Epoch CreationDate();

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_CCSDS_KVN_H_
