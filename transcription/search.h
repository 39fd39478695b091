// The problem-aware solve of an on-off schedule MILP (SolveBuilt's default):
// a bound from the LP relaxation, schedules from MILPs restricted to the
// slots that matter, and CBC only where it is needed.
//
//   SearchOptions search;                       // defaults: what SolveBuilt uses
//   search.disabled_phases = {"exchange"};      // an ablation, by phase name
//   SearchReport report;
//   milp::SolveResult r = SearchSchedule(milp, *solver, options, search, {start}, &report);
//   // report.steps: one line per step, "<phase>: <what it did>"
//
// The search is a plan of named phases (transcription/search/plan.h, one
// file per phase in transcription/search/): the relaxation's bound, the
// nets around its slots, the tree on thruster totals and its windows, the
// exact MILP over the slots reduced-cost fixing leaves free, local
// improvement, the exchange along an axis, and the whole MILP last. The
// plan, each phase's exactness argument and the measurements behind its
// place: docs/search.md.
//
// Contract: every incumbent is verified in the full MILP before it counts;
// bounds come only from safe sources (an LP's duals through
// milp/lp_bound.h, exact restricted solves, the tree's leaves, the whole
// MILP's solver); heuristic phases give incumbents only. Deterministic for
// the same input and options (node limits, no wall-clock decision) unless a
// time limit or an interrupt cuts a step.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_H_

#include <vector>

#include <Eigen/Core>

#include "milp/solver.h"
#include "transcription/schedule_milp.h"
#include "transcription/search/exchange_phase.h"
#include "transcription/search/plan.h"
#include "transcription/search/search_options.h"
#include "transcription/search/search_report.h"

namespace thrustsched::transcription {

/// Solves `milp` (on-off mode) by the plan SearchOptions::plan names.
/// options.time_limit_s and options.interrupt cover all phases;
/// options.max_nodes (>= 0) caps each CBC solve. `starts` are full column
/// vectors (e.g. StartFromBurns of a warm start), verified before use.
/// @throws std::invalid_argument for an impulsive problem or invalid options.
milp::SolveResult SearchSchedule(const ScheduleMilp& milp, const milp::Solver& solver,
                                 const milp::SolveOptions& options, const SearchOptions& search,
                                 const std::vector<Eigen::VectorXd>& starts,
                                 SearchReport* report = nullptr);

/// The same by `plan` (a plan of one's own: DefaultSearchPlan() reordered,
/// say); SearchOptions::plan is not read.
milp::SolveResult SearchScheduleWithPlan(const SearchPlan& plan, const ScheduleMilp& milp,
                                         const milp::Solver& solver,
                                         const milp::SolveOptions& options,
                                         const SearchOptions& search,
                                         const std::vector<Eigen::VectorXd>& starts,
                                         SearchReport* report = nullptr);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_H_
