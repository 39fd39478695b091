// Options of the problem-aware search (transcription/search.h), one struct
// per phase of its plan (transcription/search/plan.h).
//
//   SearchOptions search;                      // the defaults: what SolveBuilt uses
//   search.disabled_phases = {"exchange"};     // an ablation, by phase name
//   search.nets.max_widenings = 4;
//   std::string error;
//   if (!search.IsValid(&error)) ...           // "search.nets.max_widenings must be >= 0, got -1"
//
// Contract: every struct's IsValid names the field by its path below
// `search.` (as a scenario file's `solver.search` spells it) and its value.
// The phases and what each option does: docs/search.md.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_SEARCH_OPTIONS_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_SEARCH_OPTIONS_H_

#include <string>
#include <vector>

#include "milp/lazy_rows.h"
#include "transcription/schedule_milp.h"
#include "transcription/total_branching.h"

namespace thrustsched::transcription {

/// The phase "relaxation": the LP relaxation's bound.
struct RelaxationOptions {
  /// Solve it without the blocks of the thrusters an optimal schedule can
  /// leave off (transcription/dormant.h), and keep those thrusters out of
  /// the nets.
  bool drop_dormant_blocks = true;
  /// Which interior point solves it: CLP's barrier (without crossover), or
  /// the project's own (milp/interior_point.h: one ordering of the KKT
  /// staircase, then a factorisation per iteration), with CLP's barrier after
  /// it where it ends without an optimum. Either way the bound is the safe one
  /// of its duals (milp/lp_bound.h).
  enum class LpMethod { kClpBarrier, kInteriorPoint };
  LpMethod lp_method = LpMethod::kInteriorPoint;
  bool IsValid(std::string* error) const;
};

/// "clp_barrier" | "interior_point" (the scenario's search.relaxation.lp_method).
const char* ToString(RelaxationOptions::LpMethod method);
/// @returns false for any other name.
bool ParseLpMethod(const std::string& name, RelaxationOptions::LpMethod* method);

/// The nets around the relaxation's slots: the phase "nets" (widened until
/// one holds a schedule) and the phase "improvement" (the next, wider nets
/// with a cutoff below the incumbent).
struct NetOptions {
  /// A slot is a candidate when its LP on-value exceeds this.
  double candidate_threshold = 0.01;
  /// Intervals on each side of a candidate slot (every thruster) also free.
  int neighbourhood = 2;
  /// Times a net without a schedule is widened (neighbourhood doubled,
  /// threshold divided by 10, every thruster from the first widening on);
  /// the widening also ends at a net that frees every slot or would exceed
  /// max_widened_slots.
  int max_widenings = 10;
  /// Widenings before the net of every slot of the thrusters the relaxation
  /// fires, tried before the further widenings.
  int fired_thrusters_net_after = 2;
  /// Largest net of a widening (the condensed window rows are dense in every
  /// earlier free slot: a bigger net is a MILP as large as the whole one).
  int max_widened_slots = 6000;
  /// Under a time limit, the largest share of the time left that one
  /// incumbent-only MILP of the nets (and of the leaves' nets) may use.
  double time_share = 0.25;
  /// Widening levels the phase "improvement" tries after the nets' incumbent,
  /// each a net of at most max_improvement_slots slots.
  int improvement_rounds = 2;
  int max_improvement_slots = 3000;
  /// time_share for the improvement MILPs.
  double improvement_time_share = 0.1;
  bool IsValid(std::string* error) const;
};

/// Every restricted MILP (one path: transcription/search/restricted_milp.h).
struct RestrictedMilpOptions {
  /// Condensed (only the free slots' columns, dense window rows) or sparse.
  Formulation formulation = Formulation::kCondensed;
  /// Node limit of each restricted MILP solve.
  long long max_nodes = 20000;
  /// Solved by row generation over their dense rows (milp::SolveWithLazyRows).
  bool lazy_rows = true;
  milp::LazyRowOptions lazy_row_options;
  bool IsValid(std::string* error) const;
};

/// The phase "exact": reduced-cost fixing with the bound's duals, and the
/// MILP over the slots it leaves free (exact for any improvement).
struct ExactOptions {
  /// Largest number of free slots for that MILP.
  int max_slots = 3000;
  /// Under a time limit, the largest share of the time left that the exact
  /// MILP may use before the tree has run; after it, all of it.
  double time_share_before_tree = 0.3;
  bool IsValid(std::string* error) const;
};

/// The phases "tree" (branching on thruster totals), "windows" (the same
/// tree on the totals of windows of the horizon) and the leaves' MILPs that
/// follow a tree.
struct TreePhaseOptions {
  /// LPs of the tree on the totals (warm: dual simplex from the parent's
  /// basis); fewer than 2 leave the tree (and the windows) out.
  int max_lps = 200;
  /// Levels of windows of the phase "windows"; 0 leaves it out.
  int window_levels = 5;
  /// The tree's shape (its window_levels is set per phase).
  TreeOptions shape;
  /// The root basis by the crossover from the relaxation's interior point
  /// (off: a second interior point with its crossover).
  bool root_from_relaxation = true;
  /// Largest number of slots reduced-cost fixing with a leaf's duals may
  /// leave free for the leaf's exact MILP.
  int max_exact_leaf_slots = 6000;
  /// Largest net of a leaf's incumbent-only MILPs (over the slots of the
  /// thrusters its LP fires, or over its LP's candidate slots).
  int max_leaf_net_slots = 3000;
  /// At one step above the bound, the MILPs of up to this many other open
  /// leaves at the bound, each over its LP's slots widened once.
  int other_leaf_nets = 2;
  bool IsValid(std::string* error) const;
};

/// The phase "exchange": the MILP over every slot of one axis' thrusters
/// and the incumbent's slots of the others.
struct ExchangeOptions {
  /// Largest net (an axis' slots and the incumbent's).
  int max_slots = 6000;
  /// Under a time limit, the largest share of the time left per MILP.
  double time_share = 0.5;
  bool IsValid(std::string* error) const;
};

struct SearchOptions {
  /// Off: SolveBuilt hands the whole MILP to the solver, without the search.
  bool enabled = true;
  /// The plan by name (SearchPlanNames(): "default", "exact_first").
  std::string plan = "default";
  /// Phases of the plan left out, by name (SearchPhaseNames()).
  std::vector<std::string> disabled_phases;
  RelaxationOptions relaxation;
  NetOptions nets;
  RestrictedMilpOptions restricted;
  ExactOptions exact;
  TreePhaseOptions tree;
  ExchangeOptions exchange;

  bool PhaseEnabled(const std::string& name) const;
  /// False with a message naming the field (search.nets.neighbourhood, say)
  /// and its value if out of range or an unknown phase or plan.
  bool IsValid(std::string* error) const;
};

/// Names of the phases, in the default plan's order, and of the plans.
const std::vector<std::string>& SearchPhaseNames();
const std::vector<std::string>& SearchPlanNames();

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_SEARCH_OPTIONS_H_
