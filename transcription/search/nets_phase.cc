#include "transcription/search/nets_phase.h"

#include <string>

#include "common/format.h"
#include "transcription/search/restricted_milp.h"
#include "transcription/search/search_report.h"
#include "transcription/search/slot_nets.h"

namespace thrustsched::transcription {

namespace {

using common::FormatG;

class NetsPhase : public SearchPhase {
 public:
  std::string name() const override { return "nets"; }
  PhaseYield yields() const override { return PhaseYield::kIncumbents; }

  void Run(SearchState& state) override {
    const NetOptions& nets = state.search().nets;
    Eigen::MatrixXi previous;  // the last widening's net
    for (int widening = 0; widening <= nets.max_widenings && !state.Stopped(); ++widening) {
      if (widening == nets.fired_thrusters_net_after + 1 &&
          FiredThrustersNet(state, previous, widening - 1)) {
        return;
      }
      const Eigen::MatrixXi mask = WideningMask(state, state.relaxation().x, widening);
      const int slots = CountSlots(mask);
      // From level 1 on every thruster is free near the candidates, so a net
      // that did not grow already frees every slot: nothing new to try.
      if (widening > 0 && slots == CountSlots(previous)) return;
      if (widening > 0 && slots > nets.max_widened_slots) {
        state.Step("the next net has " + std::to_string(slots) + " slots (more than " +
                   std::to_string(nets.max_widened_slots) + "): not widened further");
        return;
      }
      if (!TimeToBuild(state, mask) || Net(state, mask, " candidate slots", widening)) return;
      previous = mask;
    }
  }

 private:
  // The MILP restricted to `mask`; true if it held a schedule, which is
  // offered; `level` is the widening level the improvement nets continue from.
  static bool Net(SearchState& state, const Eigen::MatrixXi& mask, const std::string& slots,
                  int level) {
    if (state.report() != nullptr) state.report()->candidate_slots = CountSlots(mask);
    const RestrictedSolve rs = SolveOver(
        state, mask, {}, [&] { return state.HeuristicOptions(state.search().nets.time_share); });
    const Restriction& r = rs.restriction;
    const milp::SolveResult& s = rs.solve;
    const std::string what = "MILP restricted to " + std::to_string(CountSlots(mask)) + slots +
                             " (" + std::to_string(r.small.num_cols()) + " columns, " +
                             std::to_string(r.small.num_rows()) + " rows)";
    if (s.has_solution()) {
      state.Step(what + ": " + StatusText(s) + " in " + FormatG(rs.seconds, 3) + " s, " +
                 std::to_string(s.nodes) + " nodes" + state.lazy_note());
      state.Offer(Lift(state, r, s.x), "the restricted MILP");
      state.set_incumbent_net_level(level);
      return true;
    }
    state.Step(what + ": " + (r.feasible ? StatusText(s) : "infeasible") + ", widened after " +
               FormatG(rs.seconds, 3) + " s" + (r.feasible ? state.lazy_note() : ""));
    return false;
  }

  // Every slot of the thrusters the relaxation fires (not dormant) that the
  // MILP leaves free, when that net has at most max_widened_slots slots and
  // is not within `previous`, the net of the widening `level`.
  static bool FiredThrustersNet(SearchState& state, const Eigen::MatrixXi& previous, int level) {
    Eigen::MatrixXi mask = FiredThrusterSlots(state, state.relaxation().x);
    const OperationalEncoding& enc = state.milp().encoding();
    for (int i = 0; i < enc.num_thrusters; ++i) {
      for (int j = 0; j < enc.num_intervals; ++j) {
        if (state.Dormant(i) || state.lp().col_upper[enc.on[i][j].index()] < 0.5) mask(i, j) = 0;
      }
    }
    const int slots = CountSlots(mask);
    if (slots == 0 || slots > state.search().nets.max_widened_slots) return false;
    if ((mask.array() <= previous.array()).all()) return false;
    if (!TimeToBuild(state, mask)) return true;  // the nets after it are no smaller
    return Net(state, mask, " slots of the thrusters the relaxation fires", level);
  }
};

}  // namespace

std::shared_ptr<SearchPhase> MakeNetsPhase() { return std::make_shared<NetsPhase>(); }

}  // namespace thrustsched::transcription
