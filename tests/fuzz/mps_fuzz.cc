// libFuzzer harness: MPS text (free and fixed) through milp::ReadMpsFile.
// Its documented error for a file it cannot read is std::runtime_error
// (milp/mps_reader.h); std::invalid_argument is accepted too (fuzz_common.h).
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "tests/fuzz/fuzz_common.h"
#include "tests/fuzz/mps_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace thrustsched;
  try {
    fuzz::ExpectContract([&] { (void)fuzz::ReadMpsText(fuzz::Text(data, size)); });
  } catch (const std::runtime_error&) {
  }
  return 0;
}
