#include "transcription/search/relaxation_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "common/format.h"
#include "milp/interior_point.h"
#include "milp/lp_bound.h"
#include "transcription/dormant.h"
#include "transcription/search/search_report.h"

namespace thrustsched::transcription {

namespace {

using common::FormatG;

class RelaxationPhase : public SearchPhase {
 public:
  std::string name() const override { return "relaxation"; }
  PhaseYield yields() const override { return PhaseYield::kBound; }

  void Run(SearchState& state) override {
    milp::SolveOptions o = state.SubOptions(true);
    o.lp_algorithm = milp::LpAlgorithm::kBarrierNoCrossover;
    const double t0 = state.Elapsed();
    state.Report(milp::SolvePhase::kRootLp, false);
    std::string dormant_note, method_note;
    milp::LpRelaxationResult r = SolveWithoutDormantBlocks(state, o, &dormant_note, &method_note);
    if (state.report() != nullptr) state.report()->lp_seconds = state.Elapsed() - t0;
    if (r.status == milp::SolveStatus::kInfeasible) {
      state.SetFailed(milp::SolveStatus::kInfeasible);
      state.Step("the LP relaxation is infeasible (" + r.detail + ")");
      return;
    }
    if (r.status != milp::SolveStatus::kOptimal) {
      state.Step("LP relaxation: " + std::string(milp::ToString(r.status)) + " (" + r.detail + ")");
      return;
    }
    const milp::DualBound dual = milp::SafeDualBound(state.lp(), r.row_duals);
    if (state.report() != nullptr) state.report()->lp_bound = dual.bound;
    const double dearest = state.milp().dearest_schedule_objective();
    if (dual.bound > dearest + 1e-6 * std::max(1.0, std::abs(dearest))) {
      // Weak duality: no schedule costs that much, so there is none.
      state.SetFailed(milp::SolveStatus::kInfeasible);
      state.Step("LP bound " + FormatG(dual.bound, 8) + " by " + method_note +
                 " above the dearest schedule the rules allow (" + FormatG(dearest, 8) +
                 "): infeasible");
      return;
    }
    state.SetRelaxation(std::move(r), dual);
    state.RaiseBound(dual.bound);
    const double bound = state.bound();
    const bool firing = bound == state.milp().least_firing_objective() &&
                        bound > milp::RoundBoundToStep(state.lp(), dual.bound, state.step());
    state.Step(
        "LP bound " + FormatG(dual.bound, 8) +
        (firing
             ? " (" + FormatG(bound, 8) + ": every schedule fires, its burns at least the minimum)"
         : bound > dual.bound ? " (" + FormatG(bound, 8) + " on the objective step)"
                              : std::string()) +
        " by " + method_note + " in " + FormatG(state.Elapsed() - t0, 3) + " s" + dormant_note);
    state.Report(milp::SolvePhase::kPresolve, false);
  }

 private:
  // One LP by the method the options name; the project's interior point
  // hands over to CLP's barrier where it ends without an optimum (it gives
  // no infeasibility verdict), unless a stop or the limit ended it.
  static milp::LpRelaxationResult SolveLp(const SearchState& state, const milp::LpData& lp,
                                          const milp::SolveOptions& o, std::string* method_note) {
    *method_note = "interior point";
    if (state.search().relaxation.lp_method != RelaxationOptions::LpMethod::kInteriorPoint) {
      return state.solver().SolveLpRelaxation(lp, o);
    }
    milp::InteriorPointOptions ipm;
    ipm.should_stop = [&state] { return state.Stopped(); };
    // Progress as CLP's root LP reports it: on the first iteration, then
    // every progress interval.
    const double t0 = state.Elapsed();
    double last_report = -std::numeric_limits<double>::infinity();
    if (o.progress) {
      ipm.on_iteration = [&](int iteration, double objective, double primal_residual) {
        const double now = state.Elapsed() - t0;
        if (iteration > 1 && now - last_report < o.progress_interval_s) return;
        last_report = now;
        milp::SolveProgress p;
        p.wall_seconds = now;
        p.phase = milp::SolvePhase::kRootLp;
        p.in_root_lp = true;
        p.lp_iterations = iteration;
        p.lp_objective = objective;
        p.lp_primal_infeasibility = primal_residual;
        o.progress(p);
      };
    }
    milp::InteriorPointResult own = milp::SolveLpByInteriorPoint(lp, ipm);
    if (own.status == milp::SolveStatus::kOptimal) {
      *method_note =
          "the project's interior point (" + std::to_string(own.iterations) + " iterations)";
      return milp::ToLpRelaxationResult(lp, std::move(own));
    }
    if (state.Stopped()) {  // a stop or the limit: nothing left for CLP either
      *method_note = "the project's interior point, " + own.detail;
      return milp::ToLpRelaxationResult(lp, std::move(own));
    }
    *method_note = "CLP's interior point (the project's: " + own.detail + ")";
    milp::SolveOptions rest = o;
    rest.time_limit_s = std::max(0.0, state.Remaining());
    return state.solver().SolveLpRelaxation(lp, rest);
  }

  // The LP relaxation with the blocks of dormant thrusters fixed at their
  // coasting values and removed: same bound validity (the duals are the
  // whole MILP's, zero on the removed rows). An infeasible verdict is
  // confirmed on the whole relaxation, so the reduction never declares a
  // problem infeasible on its own.
  static milp::LpRelaxationResult SolveWithoutDormantBlocks(SearchState& state,
                                                            const milp::SolveOptions& o,
                                                            std::string* note,
                                                            std::string* method_note) {
    const milp::LpData& lp = state.lp();
    DormantThrusters& dormant = state.dormant();
    if (state.search().relaxation.drop_dormant_blocks) dormant = FindDormantThrusters(state.milp());
    if (!dormant.any()) return SolveLp(state, lp, o, method_note);
    milp::LpData fixed = lp;
    for (int j = 0; j < lp.num_cols(); ++j) {
      if (!dormant.column[static_cast<size_t>(j)]) continue;
      fixed.col_lower[j] = fixed.col_upper[j] = dormant.all_off[j];
    }
    std::vector<int> kept, kept_rows;
    bool feasible = true;
    const milp::LpData small = milp::RemoveFixedColumns(fixed, &kept, &feasible, &kept_rows);
    if (!feasible) return SolveLp(state, lp, o, method_note);
    milp::LpRelaxationResult r = SolveLp(state, small, o, method_note);
    if (r.status == milp::SolveStatus::kInfeasible) {
      milp::SolveOptions rest = o;
      rest.time_limit_s = std::max(0.0, state.Remaining());
      return state.solver().SolveLpRelaxation(lp, rest);
    }
    *note = " (thrusters " + dormant.Names(state.milp()) +
            " left off, their block staying within its constraints without them: LP over " +
            std::to_string(small.num_cols()) + " of " + std::to_string(lp.num_cols()) + " columns)";
    if (r.status != milp::SolveStatus::kOptimal) return r;
    Eigen::VectorXd x = fixed.col_lower;  // the removed columns' values
    for (size_t k = 0; k < kept.size(); ++k) x[kept[k]] = r.x[static_cast<Eigen::Index>(k)];
    Eigen::VectorXd duals = Eigen::VectorXd::Zero(lp.num_rows());
    for (size_t k = 0; k < kept_rows.size(); ++k) {
      duals[kept_rows[k]] = r.row_duals[static_cast<Eigen::Index>(k)];
    }
    r.x = std::move(x);
    r.row_duals = std::move(duals);
    r.objective = lp.Objective(r.x);
    r.dual_bound = std::numeric_limits<double>::quiet_NaN();  // SafeDualBound, on the whole MILP
    return r;
  }
};

}  // namespace

std::shared_ptr<SearchPhase> MakeRelaxationPhase() { return std::make_shared<RelaxationPhase>(); }

}  // namespace thrustsched::transcription
