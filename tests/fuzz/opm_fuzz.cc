// libFuzzer harness: CCSDS OPM text (KVN) through app::ParseOpm, the reader
// of a scenario's "initial_state": {"opm": ...}. Contract: fuzz_common.h.
#include <cstddef>
#include <cstdint>

#include "app/ccsds_opm.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace thrustsched;
  fuzz::ExpectContract([&] { (void)app::ParseOpm(fuzz::Text(data, size), "fuzz.opm"); });
  return 0;
}
