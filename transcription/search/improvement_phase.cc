#include "transcription/search/improvement_phase.h"

#include <string>

#include "transcription/search/restricted_milp.h"
#include "transcription/search/slot_nets.h"

namespace thrustsched::transcription {

namespace {

class ImprovementPhase : public SearchPhase {
 public:
  explicit ImprovementPhase(int max_nets) : max_nets_(max_nets) {}
  std::string name() const override { return "improvement"; }
  PhaseYield yields() const override { return PhaseYield::kIncumbents; }

  void Run(SearchState& state) override {
    const NetOptions& nets = state.search().nets;
    const int rounds = max_nets_ >= 0 ? max_nets_ : nets.improvement_rounds;
    SearchState::NetLadder& ladder = state.ladder();
    const int end = ladder.incumbent_level + 1 + nets.improvement_rounds;
    if (ladder.next_improvement_level < 0)
      ladder.next_improvement_level = ladder.incumbent_level + 1;
    for (int solved = 0; solved < rounds && ladder.next_improvement_level < end;
         ++ladder.next_improvement_level) {
      if (state.Done() || state.Stopped()) break;
      const Eigen::MatrixXi mask =
          WideningMask(state, state.relaxation().x, ladder.next_improvement_level);
      if (CountSlots(mask) > nets.max_improvement_slots) {
        ladder.next_improvement_level = end;
        break;
      }
      if (ladder.last_improvement_mask.size() == mask.size() &&
          ladder.last_improvement_mask == mask)
        continue;
      ladder.last_improvement_mask = mask;
      if (ImproveWithin(state, mask, "improvement over ", "the improvement MILP",
                        nets.improvement_time_share))
        ++solved;
    }
  }

 private:
  int max_nets_;
};

}  // namespace

std::shared_ptr<SearchPhase> MakeImprovementPhase(int max_nets) {
  return std::make_shared<ImprovementPhase>(max_nets);
}

}  // namespace thrustsched::transcription
