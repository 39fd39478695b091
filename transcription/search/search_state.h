// The state of one search (transcription/search.h): the relaxation, the
// incumbent, the bound, the clock and the step log, shared by every phase
// of the plan (transcription/search/plan.h).
//
//   SearchState state(milp, solver, options, search, &report);
//   state.Offer(x, "the given start");           // verified in the full MILP first
//   state.RaiseBound(dual_bound);                // rounded up to the objective step
//   if (state.Done() || state.Stopped()) ...
//   milp::SolveResult r = state.Result();
//
// Contract: the incumbent changes only through Offer, which completes the
// point's states from its on-off pattern and re-checks every row of the
// full MILP (a restricted solve's verdict is never trusted); the bound only
// rises, through RaiseBound (a safe bound, rounded to the step) and
// RaiseBoundTo (a proven one), and never passes the incumbent.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_SEARCH_STATE_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_SEARCH_STATE_H_

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/timing.h"
#include "milp/lp_bound.h"
#include "milp/solver.h"
#include "transcription/dormant.h"
#include "transcription/schedule_milp.h"
#include "transcription/search/search_options.h"

namespace thrustsched::transcription {

struct SearchReport;

class SearchState {
 public:
  SearchState(const ScheduleMilp& milp, const milp::Solver& solver,
              const milp::SolveOptions& options, const SearchOptions& search, SearchReport* report);

  const ScheduleMilp& milp() const { return milp_; }
  const milp::LpData& lp() const { return lp_; }
  const milp::Solver& solver() const { return solver_; }
  const milp::SolveOptions& options() const { return options_; }
  const SearchOptions& search() const { return search_; }
  SearchReport* report() const { return report_; }
  double step() const { return step_; }

  // -------------------------------------------------------------- clock
  double Elapsed() const { return clock_.Elapsed(); }
  double Remaining() const { return clock_.Remaining(); }
  bool Interrupted() const { return clock_.Interrupted(); }
  bool Stopped() const { return Interrupted() || Remaining() <= 0.0; }

  // --------------------------------------------------------- relaxation
  /// The relaxation's point and the safe bound of its duals (set by the
  /// phase "relaxation"); the thrusters it found dormant.
  void SetRelaxation(milp::LpRelaxationResult relaxation, milp::DualBound dual);
  bool has_relaxation() const { return relaxation_.x.size() > 0; }
  const milp::LpRelaxationResult& relaxation() const { return relaxation_; }
  const milp::DualBound& dual() const { return dual_; }
  DormantThrusters& dormant() { return dormant_; }
  bool Dormant(int thruster) const;

  // ------------------------------------------------ incumbent and bound
  bool has_incumbent() const { return x_.size() > 0; }
  const Eigen::VectorXd& incumbent() const { return x_; }
  double objective() const { return objective_; }
  double bound() const { return bound_; }
  /// A point of the full MILP: completed, verified, then the incumbent if
  /// better. `source` names it in the step log.
  bool Offer(Eigen::VectorXd x, const std::string& source);
  /// A safe bound (an LP's duals, a tree's leaves), rounded up to the step.
  void RaiseBound(double bound);
  /// A proven bound (an exact restricted solve), not rounded.
  void RaiseBoundTo(double bound);
  /// The gap requested by the options is closed.
  bool Done() const;
  /// The incumbent at most one objective step above the bound.
  bool OneStepAboveBound() const;
  /// Only schedules better than the incumbent by a step count.
  double Cutoff() const;
  /// Whether the phase `phase` has offered an incumbent that was taken.
  bool ImprovedBy(const std::string& phase) const;

  // ------------------------------------------------------------- nets
  /// The widening levels of the nets (phases "nets" and "improvement"): the
  /// level whose net held the nets' incumbent, the next improvement level
  /// (-1: not started) and the last improvement net (not solved twice).
  struct NetLadder {
    int incumbent_level = 0;
    int next_improvement_level = -1;
    Eigen::MatrixXi last_improvement_mask;
  };
  NetLadder& ladder() { return ladder_; }
  void set_incumbent_net_level(int level) { ladder_.incumbent_level = level; }

  /// The incumbent when the phase "windows" last ran (+inf: never).
  double windows_at() const { return windows_at_; }
  void set_windows_at(double objective) { windows_at_ = objective; }

  // ------------------------------------------------------------- facts
  /// A tree (the phase "tree" or "windows") has solved its root.
  bool tree_ran() const { return tree_ran_; }
  void set_tree_ran() { tree_ran_ = true; }
  /// The problem is proven infeasible, or the solver failed (no schedule).
  void SetFailed(milp::SolveStatus status) { status_ = status; }
  bool proven_infeasible() const { return status_ == milp::SolveStatus::kInfeasible; }
  void AddNodes(long long nodes) { nodes_ += nodes; }
  void SetSolverDetail(const std::string& detail) { solver_detail_ = detail; }

  // ------------------------------------------------ restricted MILPs
  /// The largest restricted MILP built so far and its condensing time
  /// (restricted_milp.h, TimeToBuild).
  void NoteBuilt(int slots, double seconds);
  int largest_built_slots() const { return largest_built_slots_; }
  double largest_built_seconds() const { return largest_built_seconds_; }
  /// The rows the last restricted solve used, for the step log.
  void set_lazy_note(const std::string& note) { lazy_note_ = note; }
  const std::string& lazy_note() const { return lazy_note_; }

  // ---------------------------------------------------------- the log
  /// The phase now running: its name prefixes the step lines.
  /// The phase now running (empty: none), named in the step log and in
  /// progress reports; a non-empty name is announced by one progress report.
  void BeginPhase(const std::string& name);
  const std::string& phase() const { return phase_; }
  void Step(const std::string& line);
  /// A progress report on the search's clock with its incumbent and bound.
  void Report(milp::SolvePhase phase, bool new_incumbent) const;

  // ------------------------------------------------------- sub-solves
  /// Options of a sub-solve: the time left, the caller's interrupt,
  /// progress on this clock (`global_bound`: the sub-solve's bound is the
  /// whole MILP's).
  milp::SolveOptions SubOptions(bool global_bound) const;
  /// A restricted MILP's: the dual simplex (its condensed rows are dense).
  milp::SolveOptions RestrictedOptions() const;
  /// An incumbent-only restricted MILP's: within the node limit and
  /// `time_share` of the time left.
  milp::SolveOptions HeuristicOptions(double time_share) const;

  milp::SolveResult Result() const;

 private:
  milp::SolveProgress Progress(milp::SolvePhase phase, bool new_incumbent) const;

  const ScheduleMilp& milp_;
  const milp::LpData& lp_;
  const milp::Solver& solver_;
  const milp::SolveOptions& options_;
  const SearchOptions& search_;
  SearchReport* report_;
  common::SolveClock clock_;
  double step_ = 0.0;

  milp::LpRelaxationResult relaxation_;
  milp::DualBound dual_;
  DormantThrusters dormant_;
  double bound_;
  Eigen::VectorXd x_;
  double objective_;
  std::vector<milp::Incumbent> incumbents_;
  std::vector<std::string> improved_by_;  // phases whose offers were taken
  bool tree_ran_ = false;
  NetLadder ladder_;
  double windows_at_ = std::numeric_limits<double>::infinity();
  long long nodes_ = 0;
  milp::SolveStatus status_ = milp::SolveStatus::kNoSolutionFound;
  int largest_built_slots_ = 0;
  double largest_built_seconds_ = 0.0;
  std::string lazy_note_;
  std::string phase_;
  std::string detail_;
  std::string solver_detail_;
};

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_SEARCH_STATE_H_
