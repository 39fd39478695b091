// Solving a problem with a conjunction: the keep-out MILP's LP relaxation is
// weak (a big-M disjunction per check time relaxes to "no manoeuvre"), so
// the cost budget that bounds every big-M is also the lever that makes it
// solvable. Every build of the problem is exact for solutions cheaper than
// its budget (transcription/keep_out.h), and a smaller budget prunes checks
// and faces and shrinks M. Hence:
//
//  1. a start: in impulsive mode, LPs with every disjunction fixed (at each
//     check the face the thrust-free path satisfies best, or one given face
//     for all checks where no face holds freely), one per face; the cheapest
//     feasible plan is a MIP start and an upper bound. In on-off mode, the
//     plan of the problem without its conjunction (by the problem-aware
//     search), then the MILP with every disjunction fixed to the face that
//     plan misses least, first restricted to the slots near its burns and
//     the half orbit before the checks, then over every slot (each solve a
//     quarter of the time limit, 300 s without one); the optimum without the
//     conjunction is then also a lower bound, added as a row to the rounds.
//     A start within the requested gap of that bound ends the solve (an
//     avoidance at no extra cost is common: station-keeping optima are
//     degenerate, and many plans of the same cost pass elsewhere);
//  2. rounds: the problem is rebuilt with the best known cost as its budget
//     (big-M and pruning bounded with the terminal constraint too, by small
//     LPs) and solved from that plan; a round that finds a plan cheaper than
//     `restart_ratio` times its budget is stopped and the next round rebuilt
//     with the new cost. A round proven optimal is optimal for the problem:
//     any cheaper plan would have fit its budget.
//
//   transcription::ConjunctionSolve r = transcription::SolveConjunction(milp, *solver, options);
//   std::cout << r.result.schedule.consumption_l1_m_s << " after " << r.rounds.size() << "
//   rounds\n";
//
// The scenario's own budget is the first round's when no start is found.
#ifndef THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_SOLVE_H_
#define THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_SOLVE_H_

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "milp/solver.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"

namespace thrustsched::transcription {

struct ConjunctionSolveOptions {
  bool fixed_face_start = true;  // step 1 (fixed faces, or the repaired plan in on-off mode)
  bool tighten_budget = true;    // step 2; false: one solve of the model as built
  double restart_ratio = 0.9;    // in (0, 1]
  /// Rebuilt rounds bound their big-M with the terminal constraint too
  /// (BuildOptions::keep_out_bound_solver).
  bool lp_bounds = true;
  int max_rounds = 10;

  /// restart_ratio in (0, 1]; max_rounds >= 1. On failure `*error` (if
  /// given) names the field and the value.
  bool IsValid(std::string* error) const;
};

struct BudgetRound {
  double budget = 0.0;  // objective units
  int binaries = 0;     // keep-out binaries of this build
  milp::SolveStatus status = milp::SolveStatus::kError;
  double objective = std::numeric_limits<double>::quiet_NaN();
  double best_bound = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0.0;    // build + solve
  bool restarted = false;  // stopped for a cheaper plan
};

struct ConjunctionSolve {
  ScheduleResult result;  // of the last round, checked as SolveBuilt does
  /// The last round's model; null if the last round solved `first` itself.
  std::shared_ptr<const ScheduleMilp> milp;
  std::vector<BudgetRound> rounds;
  double start_objective = std::numeric_limits<double>::quiet_NaN();  // step 1, NaN if none
  std::string start_label;  // which fixed-face assignment gave it
  double start_seconds = 0.0;
  /// The start's lower bound, added to every rebuilt round as the row
  /// "objective >= bound" (valid, and it tightens the LP relaxation).
  double lower_bound = -std::numeric_limits<double>::infinity();
  /// On-off mode: the plan of the problem without its conjunction (its cost,
  /// and the plan as a full column vector of the solved model, for
  /// Decode and CheckConjunction); NaN / empty otherwise.
  double without_objective = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd without_x;

  /// The avoidance's extra cost over the plan without the conjunction:
  /// result.solve.objective - without_objective (NaN if either is missing).
  double extra_cost() const {
    return result.has_schedule() ? result.solve.objective - without_objective
                                 : std::numeric_limits<double>::quiet_NaN();
  }
};

/// Step 1 alone, as a full column vector of `milp`: impulsive mode, the
/// cheapest plan over the fixed-face assignments (one LP each); on-off mode,
/// the repaired plan of the problem without its conjunction (two MILPs).
/// Empty `x` if none is found. @throws std::invalid_argument without a conjunction.
struct ConjunctionStart {
  double objective = std::numeric_limits<double>::infinity();
  Eigen::VectorXd x;
  std::string label;
  /// On-off mode: the best bound of the problem without its conjunction,
  /// also a lower bound with it (a constraint can only raise the optimum).
  double lower_bound = -std::numeric_limits<double>::infinity();
  /// On-off mode: that problem's plan (cost, and as a full column vector of
  /// `milp`, keep-out binaries completed); NaN / empty otherwise.
  double without_objective = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd without_x;
};
ConjunctionStart FixedFaceStart(const ScheduleMilp& milp, const milp::Solver& solver,
                                const milp::SolveOptions& options);

/// @throws std::invalid_argument if the problem has no conjunction or the
///         options are invalid (and as SolveBuilt).
ConjunctionSolve SolveConjunction(const ScheduleMilp& first, const milp::Solver& solver,
                                  const SolveScheduleOptions& options,
                                  const ConjunctionSolveOptions& conjunction_options = {});

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_SOLVE_H_
