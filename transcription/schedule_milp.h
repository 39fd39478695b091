// ScheduleMilp: transcribes a ScheduleProblem into a MILP (milp::Model),
// and decodes solutions into schedules.
//
//   transcription::BuildOptions opt;
//   opt.discretisation.scheme = dynamics::Scheme::kExactZoh;
//   opt.formulation = transcription::Formulation::kSparse;
//   opt.encoding = transcription::Encoding::kTight;
//   transcription::ScheduleMilp milp(problem, opt);           // discretise + build + freeze
//   milp::SolveResult r = milp::MakeCbcSolver()->Solve(milp.lp());
//   transcription::Schedule s = milp.Decode(r.x);             // burns, totals, states
//
// Formulations:
//  kSparse     states are columns, scaled by the model's state scale S
//              (x = S x~), one block of equality rows per interval
//              x~_{j+1} - S^-1 Phi_j S x~_j - S^-1 Gamma_j u_j = S^-1 d_j:
//              O(N) nonzeros.
//  kCondensed  states eliminated (thesis (4.50)): every window row is a dense
//              row in all earlier binaries: O(N^2) nonzeros.
// Window rows are divided by the window half width, so a row reads
// -1 <= y / w <= 1; with `scale` every row is then divided by its largest
// coefficient. Binary columns are never scaled. The objective is in physical
// units (m/s or kg), so the value another solver reports on the exported MPS
// file compares directly with ours.
#ifndef THRUSTSCHED_TRANSCRIPTION_SCHEDULE_MILP_H_
#define THRUSTSCHED_TRANSCRIPTION_SCHEDULE_MILP_H_

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "dynamics/discretisation.h"
#include "milp/chain_bounds.h"
#include "milp/model.h"
#include "milp/solver.h"
#include "transcription/encodings.h"
#include "transcription/keep_out.h"
#include "transcription/problem.h"

namespace thrustsched::transcription {

enum class Formulation { kSparse, kCondensed };
std::string_view ToString(Formulation formulation);
/// "sparse" | "condensed". @throws std::invalid_argument listing the names.
Formulation ParseFormulation(std::string_view name);

struct BuildOptions {
  dynamics::DiscretizationOptions discretisation;
  Formulation formulation = Formulation::kSparse;
  Encoding encoding = Encoding::kTight;
  /// Scale state columns and rows so coefficients are near 1 (recommended;
  /// off only to demonstrate what goes wrong without it).
  bool scale = true;
  /// On-off mode, optional: thrusters x intervals, 1 where the thruster may
  /// fire; the other on-columns are fixed at 0 (the MILP of the problem with
  /// those firings forbidden, used by the search heuristics on a few hundred
  /// candidate slots). With the condensed formulation they are also left out
  /// of the dynamics rows, which then stay as small as the free set (after
  /// milp::RemoveFixedColumns, a MILP of a few thousand nonzeros per free
  /// slot instead of a week's). Empty: every slot free.
  Eigen::MatrixXi free_slots;
  /// Conjunctions only: if set, the keep-out big-M and pruning also use
  /// small LPs with the terminal constraint (transcription/keep_out.h),
  /// solved with this solver during the build. Not owned.
  const milp::Solver* keep_out_bound_solver = nullptr;

  /// The discretisation options are valid (dynamics::DiscretizationOptions).
  /// free_slots' shape depends on the problem and is checked by ScheduleMilp.
  /// On failure `*error` (if given) names the field and the value.
  bool IsValid(std::string* error) const;
};

struct BuildStats {
  double discretise_seconds = 0.0;
  double build_seconds = 0.0;  // rows + columns + freeze into LpData
  int num_binaries = 0;
  int num_columns = 0;
  int num_rows = 0;
  long long num_nonzeros = 0;
};

struct Impulse {
  int thruster;
  int node;
  double time_s;
  double delta_v_m_s;
};

struct Schedule {
  std::vector<Burn> burns;               // on-off mode, sorted by start then thruster
  std::vector<Impulse> impulses;         // impulsive mode
  Eigen::MatrixXi pattern;               // thrusters x intervals, 0/1 (on-off mode)
  std::vector<Eigen::VectorXd> states;   // x at grid nodes (discrete model)
  std::vector<Eigen::VectorXd> outputs;  // y = C x at grid nodes
  double consumption_l1_m_s = 0.0;       // thesis metric
  double delta_v_m_s = 0.0;              // Euclidean
  double propellant_kg = 0.0;            // F / (g0 Isp) * on-time (constant mass)
  std::vector<double> on_time_s;         // per thruster
  int num_burns() const { return static_cast<int>(burns.size()); }
};

/// Totals of a burn list (consumption, delta-v, propellant, on-time).
void ComputeTotals(const dynamics::ThrusterSet& thrusters, Schedule* schedule);
/// Burns of a 0/1 pattern on a grid (consecutive on intervals merged).
std::vector<Burn> BurnsFromPattern(const Eigen::MatrixXi& pattern, const std::vector<double>& grid);
/// Pattern of burns on a grid: interval j is on if its midpoint lies in a burn.
Eigen::MatrixXi PatternFromBurns(const std::vector<Burn>& burns, int num_thrusters,
                                 const std::vector<double>& grid);

class ScheduleMilp {
 public:
  /// Discretises the model on problem.grid, then builds.
  /// @throws std::invalid_argument if !problem.IsValid() (message names the field).
  ScheduleMilp(const ScheduleProblem& problem, const BuildOptions& options);
  /// Builds from an existing discretisation of problem.model on problem.grid
  /// (shared between formulations and encodings).
  ScheduleMilp(const ScheduleProblem& problem, dynamics::DiscreteModel discrete,
               const BuildOptions& options);

  const ScheduleProblem& problem() const { return problem_; }
  const BuildOptions& options() const { return options_; }
  const milp::Model& model() const { return model_; }
  const milp::LpData& lp() const { return lp_; }
  const dynamics::DiscreteModel& discrete() const { return discrete_; }
  const OperationalEncoding& encoding() const { return encoding_; }
  const BuildStats& stats() const { return stats_; }
  /// Reasons the problem is infeasible whatever the solver does (conflicting
  /// history and forced-off windows, ...); empty in general.
  const std::vector<std::string>& infeasibility_reasons() const { return reasons_; }
  /// If every costed column is integer and every cost an integer multiple of
  /// the smallest (equal thruster costs on a uniform grid), that smallest cost:
  /// feasible objective values then differ by whole steps, which lets the
  /// solver prove optimality (milp::SolveOptions::objective_step). Else 0.
  double objective_step() const { return objective_step_; }
  /// The least objective of a schedule that fires at all, where the slots
  /// carry the whole objective at positive costs: every burn lasts at least
  /// the minimum burn's number of intervals (one where a burn from the
  /// history or across the end may be shorter), each at least the cheapest
  /// free slot's cost. A bound above the zero schedule's objective
  /// (objective_offset) proves that every schedule fires, and so raises to
  /// this: a week that needs a fraction of a slot of thrust, by the LP, and
  /// burns of at least 3 slots, is bounded by 3 slots. -inf where the costs
  /// are not of that form (a slack, an arrival time, a free slot).
  double least_firing_objective() const { return least_firing_objective_; }
  /// The objective of the dearest schedule the rules allow, where the slots
  /// carry the whole objective at costs >= 0: in every interval the
  /// max_simultaneous dearest free slots. A bound above it proves the MILP
  /// infeasible. +inf where the costs are not of that form.
  double dearest_schedule_objective() const { return dearest_schedule_objective_; }
  /// The keep-out rows of problem().conjunction (sizes, big-M range, budget);
  /// empty without a conjunction.
  const std::optional<KeepOutStats>& keep_out() const { return keep_out_; }

  /// Adds rows/columns through `edit`, then refreezes lp().
  template <typename Edit>
  void Modify(Edit&& edit) {
    edit(model_);
    lp_ = model_.ToLpData();
  }

  /// @throws std::invalid_argument if x has the wrong size.
  Schedule Decode(const Eigen::VectorXd& x) const;
  /// Full column vector (MIP start) for a burn list: binaries from the
  /// pattern on the grid, auxiliaries completed, states propagated.
  Eigen::VectorXd StartFromBurns(const std::vector<Burn>& burns) const;
  /// Same from a 0/1 pattern (thrusters x intervals).
  Eigen::VectorXd StartFromPattern(const Eigen::MatrixXi& pattern) const;
  /// Largest violation (bounds and rows, model units) at which a point built
  /// by StartFromPattern or CompleteFromPattern is taken as a schedule of
  /// the MILP (the search's incumbents; dormant.h's all-off blocks).
  static constexpr double kPatternFeasibilityTolerance = 1e-6;
  /// Completes a column vector from its on-off columns (the rest, which may
  /// be NaN, recomputed as StartFromPattern does). False, x unchanged, if an
  /// on-off entry is NaN or not 0/1, or in impulsive mode. (The solver's
  /// milp::SolveOptions::complete_solution.)
  bool CompleteFromPattern(Eigen::VectorXd* x) const;

  /// Column of "thruster i on in interval j" (on-off mode).
  milp::Variable on(int thruster, int interval) const { return encoding_.on[thruster][interval]; }
  /// Column of state component c at node j, in scaled units (x = S x~);
  /// sparse formulation only. @throws std::out_of_range otherwise.
  milp::Variable state(int node, int component) const { return state_.at(node).at(component); }
  /// Sparse formulation: the state columns by node (impulsive: then the
  /// final state after the last impulse) and the dynamics rows that define
  /// each node's from the previous one; empty for the condensed formulation.
  const milp::EqualityChain& state_chain() const { return state_chain_; }

 private:
  void Build();
  void BuildSparse();
  void BuildCondensed();
  void AddObjective();
  void AddConjunction();
  std::vector<Eigen::VectorXd> PropagateDiscrete(const Eigen::MatrixXi& pattern,
                                                 const Eigen::MatrixXd& impulses) const;

  ScheduleProblem problem_;
  BuildOptions options_;
  dynamics::DiscreteModel discrete_;
  milp::Model model_;
  milp::LpData lp_;
  OperationalEncoding encoding_;
  BuildStats stats_;
  std::vector<std::string> reasons_;
  double objective_step_ = 0.0;
  double least_firing_objective_ = -std::numeric_limits<double>::infinity();
  double dearest_schedule_objective_ = std::numeric_limits<double>::infinity();
  std::optional<KeepOutStats> keep_out_;
  Eigen::VectorXd scale_;                           // state scale S (ones if !scale)
  std::vector<std::vector<milp::Variable>> state_;  // sparse: [node][component], scaled
  std::vector<std::vector<milp::Variable>> dv_;     // impulsive: [thruster][node]
  std::vector<milp::Variable> final_state_;         // impulsive sparse: after the last impulse
  milp::EqualityChain state_chain_;                 // sparse: state_ (+ final_state_), dyn rows
  struct SoftSlack {
    milp::Variable var;
    int node;
    int window_index;
    int sub;  // 0 = node, p > 0 = intersample point
  };
  std::vector<SoftSlack> slacks_;
};

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SCHEDULE_MILP_H_
