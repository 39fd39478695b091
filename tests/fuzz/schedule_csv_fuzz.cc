// libFuzzer harness: schedule.csv as `thrustsched check` reads it
// (app::ParseScheduleCsv) for a shipped GEO scenario (UTC, direction and
// delta-v columns) or an HCW one, picked by the first byte. Contract:
// fuzz_common.h.
#include <cstddef>
#include <cstdint>
#include <string>

#include "app/outputs.h"
#include "app/scenario.h"
#include "tests/fuzz/fuzz_common.h"

namespace {

using namespace thrustsched;

const app::Scenario& Pick(int k) {
  static const app::Scenario geo =
      app::ParseScenarioText(fuzz::DataFile("scenarios/geo_2day_anzel4.json"));
  static const app::Scenario hcw =
      app::ParseScenarioText(fuzz::DataFile("scenarios/hcw_table41_1d.json"));
  return k == 0 ? geo : hcw;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::ByteReader bytes(data, size);
  const app::Scenario& s = Pick(bytes.Byte() % 2);
  const std::string text = bytes.Rest();
  fuzz::ExpectContract([&] { (void)app::ParseScheduleCsv(text, "fuzz.csv", s); });
  return 0;
}
