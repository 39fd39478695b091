// libFuzzer harness: scenario files as raw bytes (invalid JSON, duplicate
// keys, wrong content) through the path of `thrustsched validate`: parse,
// validate, and for grids small enough to build in well under the 1-s
// budget, the MILP build. Contract: fuzz_common.h.
#include <cstddef>
#include <cstdint>

#include "app/scenario.h"
#include "tests/fuzz/fuzz_common.h"
#include "tests/fuzz/scenario_build.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace thrustsched;
  fuzz::ExpectContract([&] {
    const app::Scenario s = app::ParseScenarioText(fuzz::Text(data, size));
    fuzz::BuildIfSmall(s);
  });
  return 0;
}
