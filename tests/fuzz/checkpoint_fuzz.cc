// libFuzzer harness: checkpoint.json of `thrustsched simulate --resume`
// (simulate_detail::ParseCheckpoint) against the shipped ideal-six year
// scenario, whose fingerprint the seed checkpoints carry. Contract:
// fuzz_common.h.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/simulate.h"
#include "app/simulate_internal.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace thrustsched;
  static const app::SimulationSetup setup = app::ParseSimulationText(
      fuzz::DataFile("scenarios/year/year_ideal6_fixed.json"), "year_ideal6_fixed.json");
  planning::LongHorizonState state;
  std::vector<planning::CycleRecord> cycles;
  fuzz::ExpectContract([&] {
    app::simulate_detail::ParseCheckpoint(
        std::string(fuzz::Text(data, size)), "checkpoint.json", setup,
        static_cast<int>(setup.scenario.problem.thrusters.size()), &state, &cycles);
  });
  return 0;
}
