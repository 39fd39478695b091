// libFuzzer harness: the solution importers of `thrustsched import-solution`
// (CBC, glpsol -o, glpsol -w) and what the command does with what they read:
// the values mapped onto the columns of a shipped scenario's model, decoded
// into a schedule, its objective and violation recomputed. The first byte
// picks the format and the scenario (on-off or impulsive); the rest is the
// file. Contract: fuzz_common.h.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/scenario.h"
#include "app/solution_import.h"
#include "milp/model_io.h"
#include "tests/fuzz/fuzz_common.h"
#include "transcription/schedule_milp.h"

namespace {

using namespace thrustsched;

struct Model {
  app::Scenario scenario;
  transcription::ScheduleMilp milp;
  std::vector<std::string> names;
  explicit Model(const std::string& file)
      : scenario(app::ParseScenarioText(fuzz::DataFile(file))),
        milp(scenario.problem, scenario.build),
        names(milp::ExportedColumnNames(milp.lp(), false)) {}
};

const Model& Pick(int k) {
  static const Model on_off("scenarios/hcw_table41_1d.json");
  static const Model impulsive("scenarios/serra_double_integrator_impulsive.json");
  return k == 0 ? on_off : impulsive;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::ByteReader bytes(data, size);
  const uint8_t choice = bytes.Byte();
  const app::SolutionFormat format = choice % 3 == 0   ? app::SolutionFormat::kCbc
                                     : choice % 3 == 1 ? app::SolutionFormat::kGlpsol
                                                       : app::SolutionFormat::kGlpkRaw;
  const Model& m = Pick((choice / 3) % 2);
  const std::string text = bytes.Rest();
  fuzz::ExpectContract([&] {
    const app::ImportedSolution sol = app::ParseSolutionText(text, format, "fuzz.sol");
    if (!sol.has_solution) return;
    const Eigen::VectorXd x = app::ToColumnVector(sol, m.names);
    const transcription::Schedule schedule = m.milp.Decode(x);
    (void)schedule;
    (void)m.milp.lp().Objective(x);
    (void)m.milp.lp().MaxViolation(x);
  });
  return 0;
}
