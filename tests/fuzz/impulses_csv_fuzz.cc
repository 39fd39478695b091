// libFuzzer harness: impulses.csv as `thrustsched check` reads it
// (app::ParseImpulsesCsv) for the shipped impulsive double-integrator
// scenario. Contract: fuzz_common.h.
#include <cstddef>
#include <cstdint>

#include "app/outputs.h"
#include "app/scenario.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace thrustsched;
  static const app::Scenario s =
      app::ParseScenarioText(fuzz::DataFile("scenarios/serra_double_integrator_impulsive.json"));
  fuzz::ExpectContract([&] { (void)app::ParseImpulsesCsv(fuzz::Text(data, size), "fuzz.csv", s); });
  return 0;
}
