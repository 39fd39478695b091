// The problem-aware solve of an on-off schedule MILP (SolveBuilt's default):
// a bound from the LP relaxation, schedules from MILPs restricted to the slots
// that matter, and CBC only where it is needed.
//
//   SearchOptions search;                       // defaults: what SolveBuilt uses
//   milp::SolveResult r = SearchSchedule(milp, *solver, options, search, {start});
//
// Why: a GEO week's MILP has 8,000-12,000 binaries and a relaxation that CBC's
// simplex needs half a minute for, but its optimum fires in ~1 % of the slots
// and the relaxation (tight encoding) is nearly integral there. So:
//  1. The LP relaxation by interior point without crossover (seconds),
//     without the blocks of thrusters that an optimal schedule can leave
//     off (transcription/dormant.h: an in-plane block that coasts inside its
//     box while the transfer is out of plane, say); its
//     row duals give a bound valid whatever its accuracy (milp/lp_bound.h),
//     rounded up to the objective step when every schedule costs a whole
//     number of slots (ScheduleMilp::objective_step).
//  2. Candidate slots: those the relaxation uses (on-value above
//     `candidate_threshold`), every thruster within `neighbourhood` intervals
//     of them, and the slots of the given starts. The MILP with every other
//     slot off, in the condensed formulation over the candidates only
//     (BuildOptions::free_slots, milp::RemoveFixedColumns: hundreds of
//     columns instead of tens of thousands), is solved by the solver with a
//     node limit; its schedule is completed in the full MILP (states
//     propagated) and verified there. A restriction without a schedule is
//     widened, until a net frees every slot or exceeds `max_widened_slots`;
//     after two widenings, every slot of the thrusters the relaxation fires
//     is tried first (`fired_thrusters_net`: a week that needs a few slots
//     of one thruster may have to fire them anywhere in the week).
//  3. When the incumbent is within the requested gap of the bound: done,
//     without a search over the whole MILP (the usual case on GEO weeks,
//     where the rounded bound often proves the incumbent optimal).
//  4. Otherwise reduced-cost fixing (Nemhauser & Wolsey, sec. II.5.2) with the
//     bound's duals: only the slots whose reduced cost is below the gap can be
//     on in a better schedule. If they are few (`max_exact_slots`), the MILP
//     restricted to them is exact for any improvement: its solve proves the
//     incumbent optimal or finds a better one (and then again), and the bound
//     is min(incumbent, that solve's bound) and at least the LP bound.
//     Before the tree (4b) has run, it gets at most `exact_time_share` of
//     the time left: the tree often proves what it cannot.
//     Restricted MILPs are solved by row generation over their dense window
//     rows (milp/lazy_rows.h; exact): a few thousand of them bind.
//  4a. When too many slots stay free for step 4: local improvement, the MILP
//     restricted to wider nets around the relaxation's and the incumbent's
//     slots with a cutoff one step below the incumbent (incumbents only):
//     the first net (under a time limit, each incumbent-only MILP gets a
//     share of the time left: `heuristic_time_share`, the improvement
//     MILPs `improvement_time_share`), then
//  4b. branching on each thruster's number of on slots (an integer in every
//     schedule; first the sum over thrusters that stand in for each other,
//     +N and -N), its leaves dual simplex solves from their parent's basis
//     (the root's by the crossover from step 1's interior point; a leaf
//     stops at as many pivots as the root took and keeps its parent's
//     bound: `total_branching_leaf_pivot_limit`), within a
//     budget of LPs, until the gap closes: a better bound, often the proof
//     (transcription/total_branching.h; each leaf's LP holds its totals
//     elastically, so it is never infeasible); then step 4 for each open
//     leaf, lowest first, while reduced-cost fixing with the leaf's LP duals
//     leaves at most `max_exact_leaf_slots` slots free (the MILP with the leaf's
//     totals restricted to them is exact for the leaf: it closes the leaf or
//     improves the incumbent); otherwise the MILP with the lowest leaf's
//     bounds on the totals, restricted to every slot of the thrusters its LP
//     fires (or, if too many, the slots it uses); when that leaves the
//     incumbent one step above the bound, the MILPs of the other leaves at
//     the bound over their LP's candidate slots widened once
//     (`other_leaf_nets`: the schedule at the bound may lie in any of them);
//  4c. the exchange along an axis: the MILP restricted to every slot of the
//     thrusters on one axis (+T and -T, say) and to the incumbent's slots of
//     the others, with the cutoff, for the axes the incumbent fires a slot
//     or more above the relaxation, again while one improves (step 4 after
//     each better schedule), and only for thrusters in opposite pairs on
//     the frame's axes (AxisExchangeApplies: the ideal six, whatever the
//     encoding; not the four Anzel thrusters); an axis' firings can
//     move anywhere in the week, out of every net around the relaxation's
//     slots (each MILP with up to half the time left: after the tree, the
//     bound's work left is step 4's proof);
//  4d. when the incumbent is one step above the bound: the tree of 4b
//     again, on to the number of slots of each fired thruster in each half,
//     quarter, ... of the horizon once every total is whole, the thruster
//     with the fewest slots first (`total_branching_window_levels`): whether
//     the lowest leaf's whole slots can fall where its LP spreads them. A
//     proof only: at one step it proves the incumbent optimal or changes
//     nothing. Run between 4b's tree and its leaves' MILPs (these still
//     follow: they find the schedules at the bound where there are some;
//     `windows_before_leaves`; first the cheap MILP over the lowest leaf's
//     LP slots), and after 4c if the exchange brought the
//     incumbent to one step (then with its own leaves' MILPs); then the
//     wider nets, and step 4 again if the incumbent improved.
//  Where step 2's incumbent is already one step above the bound, 4b (with
//     4d between its tree and its leaves' MILPs) comes before 4 and 4a
//     (`tree_first_at_one_step`): at one step the question is whether a
//     schedule at the bound exists, and the tree answers it cheaper.
//  5. Otherwise, or with no incumbent: the solver on the whole MILP, on its
//     own (SearchOptions::whole_milp_from_incumbent: not from the incumbent,
//     which is kept if the solver finds nothing better).
// A step's time in the log (SearchReport::steps) counts the building of its
// restricted MILP: condensing a six-thruster GEO week over the free slots of
// one or two whole thrusters (2016 or 4032 slots, about the size of the
// exchange's 4043 on c41 of data/scenarios/hard/) and removing the fixed
// columns takes 1.6 or 2.9 s (build/benchmarks/transcription_benchmark
// --benchmark_filter=BM_BuildGeoWeekRestricted, medians of 3 on the 2-core
// machine; most of it is copying 4.3 or 8.5 M window-row entries).
// Heuristic steps give incumbents only; bounds come from the LP duals and
// from exact (restricted-by-proof) solves. Deterministic for the same input
// and options (node limits, no wall-clock decision) unless a time limit or
// an interrupt cuts a step.
#ifndef THRUSTSCHED_TRANSCRIPTION_SEARCH_H_
#define THRUSTSCHED_TRANSCRIPTION_SEARCH_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "milp/solver.h"
#include "transcription/schedule_milp.h"

namespace thrustsched::transcription {

struct SearchOptions {
  /// Off: SolveBuilt hands the whole MILP to the solver (the first release's
  /// behaviour, kept for comparison in the bench).
  bool enabled = true;
  /// A slot is a candidate when its LP on-value exceeds this.
  double candidate_threshold = 0.01;
  /// Intervals on each side of a candidate slot (every thruster) also free.
  int neighbourhood = 2;
  /// Times a restriction without a schedule is widened (neighbourhood
  /// doubled and threshold divided by 10, every thruster from the first
  /// widening on) before giving up on it; the widening also ends at a net
  /// that frees every slot or would exceed max_widened_slots. Weeks that
  /// start at the station point and need a few slots of thrust (six
  /// thrusters, 2026-2035, 60 s, two threads): the relaxation fires 5-6 slots
  /// and nets of up to 72 slots (two widenings, the previous default) held
  /// no schedule, so CBC on the whole MILP found one only at 47 s (98 %
  /// gap); the net of 414 slots (five widenings) held one in 2 s and the
  /// week was proven optimal at 24 s, another one's at 1554 slots (seven).
  /// A widening that proves its net infeasible takes 0.4-2 s there.
  int max_widenings = 10;
  /// After the first two widenings, the MILP restricted to every slot of
  /// the thrusters the relaxation fires (at most max_widened_slots slots),
  /// then the further widenings. Off: the previous release's widening, kept
  /// for comparison in the bench. A six-thruster week from the station
  /// point at 140 deg E on 2035-11-27 (data/scenarios/hard/, 60 s, two
  /// threads): the relaxation fires +T for 2.7 slots; the nets of widenings
  /// 3-6 (114-786 slots) were infeasible or ran out their share (10.6 s and
  /// 8.2 s) with nothing, and a schedule came at the seventh (1554 slots);
  /// every slot of +T (2016) holds the optimum (3 slots), found in 3.1 s
  /// and proven optimal by the rounded bound at 14 s.
  bool fired_thrusters_net = true;
  /// Largest net of a widening: the condensed window rows are dense in every
  /// earlier free slot, so a bigger net is a MILP as large as the whole one
  /// (step 5). The same size as max_exchange_slots.
  int max_widened_slots = 6000;
  /// Formulation of the restricted MILPs: condensed (only the free slots'
  /// columns, dense window rows) or sparse (state columns kept, sparse rows).
  Formulation restricted_formulation = Formulation::kCondensed;
  /// Node limit of each restricted MILP solve.
  long long restricted_max_nodes = 20000;
  /// Under a time limit, the largest share of the time left that one
  /// incumbent-only restricted MILP (steps 2 and 3, the lowest leaf's) may
  /// use; the rest is kept for the bound (the tree, the exact solves). 1: no
  /// cap. Weeks 10, 47 and 52 of data/scenarios/hard/ with 60 s: the first
  /// improvement MILP alone took 47-50 s of its 20,000 nodes (finding
  /// nothing on two of them) and left the tree no time.
  double heuristic_time_share = 0.25;
  /// heuristic_time_share for step 4a's improvement MILPs. On the hard weeks
  /// of data/scenarios/hard/ (bench of 2026-11-28, 22 solves over 9 weeks)
  /// they either found a better schedule within 2.1 s (10) or ran out their
  /// quarter of the time left, 7.9-12 s, with nothing (11; once a better
  /// schedule at 11.4 s): the time goes to the tree and the exchange.
  double improvement_time_share = 0.1;
  /// Under a time limit, the largest share of the time left that step 4's
  /// exact MILP may use before the tree (step 4b) has run; after it, all of
  /// it. Week 13 of the six-thruster year (2034-03-26), 60 s, two threads:
  /// the exact MILP over 2153 slots ran 43 s without a proof and the time
  /// ran out at 2.44 %, where the tree proves the incumbent optimal in two
  /// LPs (6 s in the year run). The exact solves of the hard weeks that
  /// closed took 9.3 s at most.
  double exact_time_share = 0.3;
  /// Restricted MILPs solved by row generation over their dense rows
  /// (milp::SolveWithLazyRows): on GEO weeks ~1/4 of the condensed window
  /// rows bind at the LP optimum, and CBC's node LPs on the rest cost 10x.
  bool lazy_rows = true;
  /// Their subset incumbents that break no left-out row are kept as the
  /// solver reports them (milp::LazyRowOptions::keep_model_incumbents): a
  /// subset search that ends at its share on a solution breaking a row
  /// still hands over the schedule it found before. Off: only a subset's
  /// final solution counts.
  bool lazy_rows_keep_incumbents = true;
  /// Their first LP (which picks the dense rows that start in) with CLP's
  /// presolve (milp::LazyRowOptions::presolve_lp_relaxation). Off saves
  /// most of that LP's time on large nets (4.1 s of presolve against 0.85 s
  /// of dual simplex over 4043 slots of a six-thruster week), but the
  /// optimum it reaches differs where the LP is degenerate, and with it the
  /// rows that start in. Off against on in the same run (the bench's
  /// `lazy-lp-unpresolved` arm: every solver-speed case, 2 threads, 60 s on
  /// the hard weeks, medians of 3, 2026-11-30): geometric mean 1.03x faster
  /// over 22 measures; weeks 16 and 14 of the six-thruster year 1.50x and
  /// 1.31x, but week 2 0.69x (its lowest leaf's 2016-slot MILP started with
  /// 21953 rows, where with presolve it ends its three rounds with 20307,
  /// and found nothing within its share), week 21 0.70x and a six-thruster
  /// week at 40 deg E 0.69x. Still on: a small, mixed gain, and off would
  /// move every year's path.
  bool lazy_rows_presolve_lp = true;
  /// That first LP without the dense rows the column bounds imply
  /// (milp::LazyRowOptions::skip_implied_rows_in_lp): the same LP, without
  /// the seconds CLP's presolve takes to remove them from a large net. Off:
  /// the previous release's first LP, kept for comparison in the bench.
  bool lazy_rows_skip_implied = true;
  /// Widening levels tried after the heuristic's incumbent, each a
  /// restricted MILP with a cutoff one step below the incumbent (step 3).
  int improvement_rounds = 2;
  /// Largest number of slots left free by reduced-cost fixing for the exact
  /// restricted solve (step 4); above it, the whole MILP (step 5).
  int max_exact_slots = 3000;
  /// The same for an open leaf of the tree (step 4b). Its MILP carries the
  /// leaf's bounds on the totals as rows, which tie its slots together, and
  /// a leaf's lower bound on a total weakens its reduced-cost fixing (the
  /// row's dual lowers the reduced cost of every slot of the group). Week 41
  /// of the six-thruster year (2034-10-08): the lowest leaf (+N and -N >= 10,
  /// -T >= 2, -N <= 4) left 3037 slots free; their exact MILP found a
  /// 12-step schedule in 4 s (100 nodes), proving it optimal (13 steps and
  /// 7.69 % with 3000).
  int max_exact_leaf_slots = 6000;
  /// When the incumbent is one step above the bound after the lowest leaf's
  /// restricted MILP (step 4b), the MILPs of up to this many other open
  /// leaves at the bound, each restricted to its LP's candidate slots
  /// widened once (as step 2's first widening) with its totals and the
  /// cutoff. 0: the previous release's search, kept for comparison in the
  /// bench. Week 33 of data/scenarios/hard/ (six thrusters, 60 s, two
  /// threads): where step 2's net stops at its share on 35 or 36 slots
  /// (bound 34), the lowest leaf (+N <= 14) holds only 35; the other leaf
  /// at the bound (+N >= 15) held the optimum in its 1266-slot net (4 s).
  int other_leaf_nets = 2;
  /// Hand the incumbent to the solver of the whole MILP (step 5) as its MIP
  /// start and cutoff. Off: measured on a six-thruster week of the year
  /// (week 2), CBC given the search's 0.1475 m/s plan found nothing better in
  /// 100 nodes (~480 s) while CBC on its own found and proved the 0.1147 m/s
  /// optimum in 150 s; on the hard-weeks suite it changed nothing or helped.
  /// The incumbent is kept either way (a worse CBC result does not replace it).
  bool whole_milp_from_incumbent = false;
  /// LPs of the tree over each thruster's number of on slots that raises the
  /// bound when the incumbent is not proven (transcription/total_branching.h;
  /// step 4b); 0 (or 1) turns it off. On a six-thruster GEO week each LP is
  /// an interior point over the whole MILP (~10-20 s; the two of a split
  /// side by side with two threads): two splits prove week 39 of
  /// data/scenarios/hard/ optimal (0.377 m/s; the rounded relaxation 0.3606).
  int total_branching_lps = 6;
  /// The tree's budget is in LP work: total_branching_lps LPs of this many
  /// nonzeros (an interior-point iteration costs about in proportion; a
  /// six-thruster GEO week at 5 min steps has 289 k). A smaller MILP's LPs
  /// are cheaper, so its tree may solve more of them: total_branching_lps x
  /// (this / the MILP's nonzeros), at most kTreeLpScaleMax times as many.
  /// 0: a count of LPs whatever their size (the previous release's tree,
  /// kept for comparison in the bench). The one-day last cycle of the
  /// six-thruster year (2034-12-31, 41 k nonzeros): 6 LPs (14.5 s) left it
  /// at 11.1 % (8 steps against 9), 10 LPs prove the 9-step schedule
  /// optimal.
  int total_branching_lp_nonzeros = 300000;
  static constexpr int kTreeLpScaleMax = 8;
  /// The tree's leaves as dual simplex solves in one LP session, each from
  /// its parent's basis (a leaf only changes bounds), after one interior
  /// point with crossover for the root's basis; its budget is then
  /// total_branching_warm_lps LPs. Off: each leaf LP an interior point from
  /// scratch, budgeted as above (the previous release's tree, kept for
  /// comparison in the bench). Week 52 of data/scenarios/hard/ (six
  /// thrusters, 60 s, one thread): 8 leaf LPs in 3.5 s after the root's
  /// 11 s raised the bound from 80 to 82 steps and the lowest leaf's MILP
  /// found an 82-step schedule (proven optimal), where the previous tree's
  /// first two leaf LPs ran out of the minute.
  bool total_branching_warm = true;
  int total_branching_warm_lps = 200;
  /// The tree splits the summed total of thrusters that stand in for each
  /// other (+N and -N) before their own (TotalGroups). Off: single thrusters
  /// only, the previous release's tree, kept for comparison in the bench. On
  /// week 52 of data/scenarios/hard/ (six thrusters) one split of +N and -N
  /// together raised the bound from 80 to 81 steps (gap 2.44 % to 1.22 %),
  /// where six LPs on +N and -N alone left it at 80.
  bool total_branching_axis_groups = true;
  /// The tree's leaf LPs hold their bounds on the totals elastically (a
  /// penalty per slot outside them, WithGroupTotals), so they are never
  /// infeasible. Off: hard bounds, the previous release's tree, kept for
  /// comparison in the bench. Week 37 of the six-thruster year (2034-09-10):
  /// with hard bounds a leaf LP CLP took 540-730 s to call infeasible and
  /// another one that was infeasible returned no better than its parent's
  /// bound (the interior point stops at an infeasible point), 5.26 % after
  /// 723 s; elastic, one split proves the 19-step schedule optimal in 96 s.
  bool total_branching_elastic = true;
  /// The warm tree's leaves stop their dual simplex after as many pivots as
  /// the root's basis took (at least 1000) and keep their parent's bound
  /// (TreeOptions::leaf_pivot_limit). Off: the previous release's tree,
  /// kept for comparison in the bench. Week 45 of the six-thruster year
  /// (2034-11-05), 60 s, two threads: three leaves took 10-25 s each and
  /// left it at 2.7 %; with the limit, 4.5-5 s each, and the lowest leaf's
  /// MILP found the optimum, proven at 32 s.
  bool total_branching_leaf_pivot_limit = true;
  /// Step 4d: levels of windows the tree splits once every thruster's total
  /// is whole (TreeOptions::window_levels, transcription/total_branching.h:
  /// the number of slots of a fired thruster in each half, quarter, ... of
  /// the horizon), run where the incumbent is one step above the bound
  /// (windows_before_leaves) or after step 4c. 0: an earlier release's
  /// search (kept for comparison). year_ideal6_fixed_windowed_c41 of
  /// data/scenarios/hard/ (six thrusters; 6.7 % from its bound without it,
  /// in 60 s and with the year's 900 s) is proven optimal in 72 s with the
  /// year's settings (the windows of -T, 23 LPs, 25 s). The three years of
  /// data/scenarios/year/ give the same weeks with and without it.
  int total_branching_window_levels = 5;
  /// Step 4d also between step 4b's tree and its leaves' MILPs when the
  /// tree leaves the incumbent one step above the bound. Off: only after
  /// step 4c, the previous release's search (kept for comparison in the
  /// bench). The station-point weeks 75 deg E and 40 deg E of
  /// data/scenarios/hard/ (60 s, two threads, bench medians of 3): proven
  /// optimal in 57.6 s (once one slot above at the limit) and 44.7 s (274
  /// and 140 window LPs of +T, 24 s and 19 s), where off the lowest leaf's
  /// exact MILP and the exchange use the time left without a schedule and
  /// they end one slot above the bound (20 %, 16.7 %; still so in 120 s).
  /// Where a schedule at the bound exists the windows cost time before the
  /// step that finds it: 38 s (14 LPs of -T) in week 41 of the
  /// six-thruster year, then found by the exchange.
  bool windows_before_leaves = true;
  /// When the first incumbent (step 2's) is one step above the bound, step
  /// 4b's tree (with step 4d's windows and its leaves' MILPs) before step
  /// 4's exact MILP and step 4a's first improvement MILP. Off: the previous
  /// release's order (kept for comparison in the bench). The station-point
  /// week 75 deg E of data/scenarios/hard/ (60 s, two threads): the exact
  /// MILP over 1506 slots and the improvement MILP took 14.7 s and 3.2 s
  /// before the tree without a schedule or a bound; the windows prove the
  /// first incumbent optimal right after the tree (bench medians of 3, same
  /// run: 31.4 s against 60.1 s, 20 % in 2 of 3 runs). 40 deg E: 24.1 s
  /// against 45.3 s. Week 16: the tree proves it in 2 LPs where the exact
  /// MILP took 5 s (17.9 s against 28.5 s).
  bool tree_first_at_one_step = true;
  /// Step 4c's exchange along an axis: the MILP restricted to every slot of
  /// the thrusters on one axis (directions parallel or opposite) and the
  /// incumbent's slots of the others, with the cutoff, axis after axis. Off:
  /// the previous release's search, kept for comparison in the bench. Week
  /// 10 of data/scenarios/hard/ (six thrusters): the nets around the
  /// relaxation's slots held no schedule below 19 steps (bound 17); the
  /// exchange along +T and -T moved their firings (one +T slot to the last
  /// day) for 18 steps in 9 s, which step 4 then proved optimal in 5 s:
  /// proven at 99-120 s with 150 s (10.5 % without it). Within 60 s the tree
  /// leaves it no time; run before the tree it proved week 10 in 37 s but
  /// cost weeks 14 and 47 their minute.
  bool axis_exchange = true;
  /// Largest net of the exchange (an axis' slots and the incumbent's): a
  /// GEO week's two thrusters on one axis have 4032.
  int max_exchange_slots = 6000;
  /// heuristic_time_share for the exchange's MILPs. They run after the tree,
  /// when what is left of the bound's work is step 4's proof after a better
  /// schedule (seconds), so they may take more of the time left than the
  /// MILPs before the tree. Week 10 of data/scenarios/hard/ (six thrusters,
  /// 60 s): the exchange along +T and -T found the 18-step schedule in
  /// 5.2 s once and nothing in its 4.9 s (a quarter of the time left) the
  /// next run.
  double exchange_time_share = 0.5;
  /// The warm tree's root basis by the crossover from step 1's interior
  /// point (milp::LpSession::CrossOverFrom with the relaxation's duals).
  /// Off: by a second interior point with its crossover, the previous
  /// release's search, kept for comparison in the bench. Week 10 of
  /// data/scenarios/hard/ (six thrusters, 60 s): the root basis in 2 s
  /// instead of 13 s, which leaves the exchange along +T and -T its time.
  /// Week 33: 1.8 s, where a second interior point with its crossover
  /// takes 14 s (61-71 s before the crossover put the columns the duals
  /// price out at their bounds first).
  bool tree_root_from_relaxation = true;
  /// Solve the LP relaxation without the blocks of the thrusters an optimal
  /// schedule can leave off (transcription/dormant.h), and keep those
  /// thrusters out of the heuristic nets. On thesis Table 4.2 (t1 = 2 d), an
  /// out-of-plane transfer in the Hill-Clohessy-Wiltshire equations, the LP
  /// drops from 48,390 to 16,128 columns and from 5 s to 0.9 s.
  bool drop_dormant_blocks = true;

  /// False with a message naming the field and value if out of range.
  bool IsValid(std::string* error) const;
};

/// What the search did, for reports (SolveResult::detail says it in words).
struct SearchReport {
  double lp_seconds = 0.0;
  double lp_bound = 0.0;           // from the duals, before rounding to the step
  int candidate_slots = 0;         // free slots of the last heuristic restriction
  int exact_slots = -1;            // free slots after reduced-cost fixing (-1: not run)
  bool whole_milp = false;         // step 5 ran
  std::vector<std::string> steps;  // one line per step, in order
};

/// Solves `milp` (on-off mode) as above. options.time_limit_s and
/// options.interrupt cover all steps; options.max_nodes (>= 0) caps each
/// CBC solve. `starts` are full column vectors (e.g. StartFromBurns of a
/// warm start), verified before use. @throws std::invalid_argument for an
/// impulsive problem or invalid options.
milp::SolveResult SearchSchedule(const ScheduleMilp& milp, const milp::Solver& solver,
                                 const milp::SolveOptions& options, const SearchOptions& search,
                                 const std::vector<Eigen::VectorXd>& starts,
                                 SearchReport* report = nullptr);

/// Whether step 4c's exchange along an axis applies to `thrusters`: they lie
/// on two axes or more (ThrusterAxes: an exchange keeps the other axes'
/// firings) and one axis holds two of them or more (the ideal six's +T and
/// -T), not the thesis' four Anzel thrusters (each alone on its axis).
/// Depends on the thrusters only, not on the MILP's encoding.
bool AxisExchangeApplies(const dynamics::ThrusterSet& thrusters);

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_SEARCH_H_
