#include "transcription/search/exchange_phase.h"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "transcription/search/exact_phase.h"
#include "transcription/search/restricted_milp.h"
#include "transcription/total_branching.h"

namespace thrustsched::transcription {

namespace {

// Slack on a count of slots from an interior point's on-values.
constexpr double kIntegralSlack = 1e-6;

class ExchangePhase : public SearchPhase {
 public:
  std::string name() const override { return "exchange"; }
  PhaseYield yields() const override { return PhaseYield::kIncumbents; }

  void Run(SearchState& state) override {
    while (!state.Done() && !state.Stopped() && AlongAxes(state)) ExactRounds(state);
  }

 private:
  // Returns at the first improvement (for the exact rounds to try their
  // proof); called again, it solves the axes not yet solved against the
  // new incumbent; false once every axis has been.
  bool AlongAxes(SearchState& state) {
    if (!started_) {
      axes_ = RankedAxes(state);
      exchanged_at_.assign(axes_.size(), std::numeric_limits<double>::infinity());
      started_ = true;
    }
    const ExchangeOptions& options = state.search().exchange;
    for (size_t a = 0; a < axes_.size(); ++a) {
      if (state.Done() || state.Stopped()) return false;
      if (exchanged_at_[a] == state.objective()) continue;
      const double before = state.objective();
      const Eigen::MatrixXi mask = AxisMask(state, axes_[a]);
      if (CountSlots(mask) <= options.max_slots) {
        ImproveWithin(state, mask, "exchange along " + axes_[a].name + " over ",
                      "the exchange along an axis", options.time_share);
      }
      exchanged_at_[a] = state.objective();
      if (state.objective() < before) return true;
    }
    return false;
  }

  // Axes the incumbent fires at least one slot more than the relaxation
  // does, most first: an axis where the relaxation matches the incumbent
  // within a slot has little to give.
  static std::vector<ThrusterGroup> RankedAxes(const SearchState& state) {
    const dynamics::ThrusterSet& thrusters = state.milp().problem().thrusters;
    if (!AxisExchangeApplies(thrusters)) return {};
    const OperationalEncoding& enc = state.milp().encoding();
    const Eigen::VectorXd& x = state.incumbent();
    const Eigen::VectorXd& relaxed_x = state.relaxation().x;
    std::vector<std::pair<double, ThrusterGroup>> ranked;
    for (ThrusterGroup& axis : ThrusterAxes(thrusters)) {
      double incumbent = 0.0, relaxed = 0.0;
      for (int i : axis.thrusters) {
        for (int j = 0; j < enc.num_intervals; ++j) {
          const int c = enc.on[i][j].index();
          incumbent += x[c] > 0.5 ? 1.0 : 0.0;
          relaxed += relaxed_x[c];
        }
      }
      if (incumbent - relaxed >= 1.0 - kIntegralSlack)
        ranked.emplace_back(incumbent - relaxed, std::move(axis));
    }
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<ThrusterGroup> axes;
    for (auto& r : ranked) axes.push_back(std::move(r.second));
    return axes;
  }

  // Every slot of the axis' thrusters and the incumbent's of the others.
  static Eigen::MatrixXi AxisMask(const SearchState& state, const ThrusterGroup& axis) {
    const OperationalEncoding& enc = state.milp().encoding();
    Eigen::MatrixXi mask = enc.OnPattern(state.incumbent());
    for (int i : axis.thrusters) {
      if (state.Dormant(i)) continue;
      for (int j = 0; j < enc.num_intervals; ++j) {
        if (state.lp().col_upper[enc.on[i][j].index()] > 0.5) mask(i, j) = 1;
      }
    }
    return mask;
  }

  bool started_ = false;
  std::vector<ThrusterGroup> axes_;   // RankedAxes, against the first incumbent
  std::vector<double> exchanged_at_;  // incumbent of each axis' last exchange
};

}  // namespace

bool AxisExchangeApplies(const dynamics::ThrusterSet& thrusters) {
  const std::vector<ThrusterGroup> axes = ThrusterAxes(thrusters);
  return axes.size() >= 2 && std::any_of(axes.begin(), axes.end(), [](const ThrusterGroup& a) {
           return a.thrusters.size() >= 2;
         });
}

std::shared_ptr<SearchPhase> MakeExchangePhase() { return std::make_shared<ExchangePhase>(); }

}  // namespace thrustsched::transcription
