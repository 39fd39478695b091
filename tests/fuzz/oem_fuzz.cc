// libFuzzer harness: CCSDS OEM text (KVN) through app::ParseOem; a file it
// accepts is written again (app::FormatOem, in UTC: the reader's epochs are
// UTC already) and read back with as many segments and points. Contract:
// fuzz_common.h.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "app/ccsds_oem.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace thrustsched;
  app::OemFile oem;
  if (!fuzz::ExpectContract([&] { oem = app::ParseOem(fuzz::Text(data, size), "fuzz.oem"); })) {
    return 0;
  }
  for (app::OemSegment& s : oem.segments) s.time_system = dynamics::TimeScale::kUtc;
  std::string text;
  if (!fuzz::ExpectContract([&] { text = app::FormatOem(oem); })) return 0;
  const app::OemFile back = app::ParseOem(text, "rewritten.oem");  // must read: no catch
  if (back.segments.size() != oem.segments.size()) {
    throw std::logic_error("OEM round trip changed the number of segments");
  }
  for (size_t k = 0; k < oem.segments.size(); ++k) {
    if (back.segments[k].points.size() != oem.segments[k].points.size()) {
      throw std::logic_error("OEM round trip changed the number of points");
    }
  }
  return 0;
}
