#include "benchmarks/bench/report_solver.h"

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/report_format.h"

namespace thrustsched::bench {
namespace {

// The arms of one case: rows of "<id>-search", "<id>-previous" (the
// previous release's search), "<id>-lazy-lp-unpresolved" (the search with
// the lazy rows' first LP unpresolved) and "<id>-cbc" (the first release's
// path).
struct Pair {
  std::string id;
  std::vector<const Row*> search, previous, unpresolved, cbc;
};

std::vector<Pair> Pairs(const std::vector<Row>& rows) {
  std::vector<Pair> out;
  std::map<std::string, size_t> at;
  for (const Row& r : rows) {
    if (r.Get("section") != kSectionSolverSpeed) continue;
    const std::string id = r.Get("case_id");
    const std::string path = r.Get("solver_path");
    const std::string suffix = SolverPathIdSuffix(path);
    const bool tagged = id.size() > suffix.size() &&
                        id.compare(id.size() - suffix.size(), suffix.size(), suffix) == 0;
    const std::string base = tagged ? id.substr(0, id.size() - suffix.size()) : id;
    auto [it, fresh] = at.emplace(base, out.size());
    if (fresh) out.push_back({base, {}, {}, {}, {}});
    Pair& pair = out[it->second];
    std::vector<const Row*>& arm = path == kSearchPath.column                    ? pair.search
                                   : path == kSearchPreviousPath.column          ? pair.previous
                                   : path == kSearchLazyLpUnpresolvedPath.column ? pair.unpresolved
                                                                                 : pair.cbc;
    arm.push_back(&r);
  }
  return out;
}

double MedianCol(const std::vector<const Row*>& rows, const std::string& col, bool missing_is_inf) {
  std::vector<double> v;
  for (const Row* r : rows) v.push_back(r->Num(col));
  return MedianOf(v, missing_is_inf);
}

// A target's value in one run: time to a 1 % proof, to optimality, or (for
// a gap target) the run's time if it ended within the gap, else +inf.
double TimeToGap(const Row& r, double gap) {
  const double g = r.Num("gap");
  return std::isfinite(g) && g <= gap + 1e-12 ? r.Num("solve_s") : INFINITY;
}

// The timed measures of a case: its targets' columns.
struct Measure {
  std::string name;
  std::string column;  // empty: gap target
  std::string target_column;
};

std::vector<Measure> MeasuresOf(const Row& spec) {
  std::vector<Measure> measures;
  if (spec.Has("target_1pct_s")) {
    measures.push_back({"time to a proven 1 % gap", "time_to_1pct_s", "target_1pct_s"});
  }
  if (spec.Has("target_opt_s")) {
    measures.push_back({"time to proven optimality", "time_to_opt_s", "target_opt_s"});
  }
  if (spec.Has("target_gap")) {
    measures.push_back(
        {"within " + Pct(spec.Num("target_gap")) + " of its bound", "", "target_gap_s"});
  }
  return measures;
}

// The median of one arm's runs on a measure (NaN: the arm was not run;
// +inf: not reached in most runs).
double ArmValue(const std::vector<const Row*>& arm, const Measure& m, const Row& spec) {
  if (arm.empty()) return NAN;
  if (!m.column.empty()) return MedianCol(arm, m.column, true);
  std::vector<double> v;
  for (const Row* r : arm) v.push_back(TimeToGap(*r, spec.Num("target_gap")));
  return MedianOf(v, true);
}

// The medians of `col` over the given arms, " / "-separated.
std::string PerArm(const std::vector<const std::vector<const Row*>*>& arms, const std::string& col,
                   bool pct) {
  std::string out;
  for (const auto* arm : arms) {
    const double v = arm->empty() ? NAN : MedianCol(*arm, col, false);
    out += (out.empty() ? "" : " / ") + (pct ? Pct(v) : G(v, 8));
  }
  return out;
}

// Section 8.1: the search with SearchOptions::lazy_rows_presolve_lp off
// against the default, measure by measure, and their geometric mean.
void WriteLazyLpAblation(std::ostream& md, const std::vector<Pair>& pairs) {
  md << "### 8.1 Ablation: the lazy rows' first LP without presolve\n\n";
  MdTable t({"case", "measure", "default (s)", "unpresolved (s)", "default / unpresolved",
             "objective (default / unpresolved)", "final gap (default / unpresolved)"});
  double log_sum = 0.0;
  int finite_pairs = 0;
  for (const Pair& p : pairs) {
    if (p.search.empty() || p.unpresolved.empty()) continue;
    const Row& spec = *p.search.front();
    for (const Measure& m : MeasuresOf(spec)) {
      const double on = ArmValue(p.search, m, spec), off = ArmValue(p.unpresolved, m, spec);
      const double limit = spec.Num("time_limit_s");
      std::string ratio = "-";  // neither reached
      if (std::isfinite(on) && std::isfinite(off) && on > 0.0 && off > 0.0) {
        ratio = G(on / off, 3) + "x";
        log_sum += std::log(on / off);
        ++finite_pairs;
      } else if (std::isfinite(off) && off > 0.0) {
        ratio = "> " + G(limit / off, 3) + "x";
      } else if (std::isfinite(on) && on > 0.0) {
        ratio = "< " + G(on / limit, 3) + "x";
      }
      t.Add({p.id, m.name, Sec(on), Sec(off), ratio,
             PerArm({&p.search, &p.unpresolved}, "objective", false),
             PerArm({&p.search, &p.unpresolved}, "gap", true)});
    }
  }
  if (t.empty()) {
    md << "Not run (the `-lazy-lp-unpresolved` cases).\n\n";
    return;
  }
  md << "`SearchOptions::lazy_rows_presolve_lp` (default on) lets CLP presolve the LP "
        "relaxation whose binding rows start each row generation over a restricted MILP's "
        "dense window rows (`milp/lazy_rows.h`); the `lazy-lp-unpresolved` arm runs the same "
        "search with it off, in the same run as the default (`search`) arm. Medians over the "
        "repeats; a ratio above 1 means the unpresolved first LP was faster; \"not reached\" "
        "counts as the time limit in the bounds on a ratio.\n\n";
  md << t.Str() << "\n";
  if (finite_pairs > 0) {
    md << "Geometric mean of the ratios where both arms reached the measure (" << finite_pairs
       << "): " << G(std::exp(log_sum / finite_pairs), 3) << "x.\n\n";
  }
}

}  // namespace

void WriteSolverSpeed(std::ostream& md, const std::vector<Row>& rows) {
  md << "## 8. Solver speed: the search against the previous release and CBC alone\n\n";
  const std::vector<Pair> pairs = Pairs(rows);
  if (pairs.empty()) {
    md << "Not run.\n\n";
    return;
  }
  md << "Each case is solved by every path in the same run, one after the other, so machine "
        "load acts on all: `search` is what `thrustsched solve` does (interior-point LP bound "
        "from safe duals, MILPs restricted to the slots the relaxation uses and solved by row "
        "generation over their dense window rows, local improvement over wider nets, "
        "reduced-cost fixing, CBC on the whole MILP only when needed; "
        "`transcription/search.h`), `previous` is this search as the previous release ran "
        "it: the first LP of each restricted MILP's row generation with the dense rows its "
        "column bounds imply, which CLP's presolve then removes "
        "(`SearchOptions::lazy_rows_skip_implied` off; rows of the weeks not re-run since come "
        "from earlier runs, whose `previous` was an earlier release (the `variant` column says "
        "which): where the incumbent is one step above the bound after the lowest leaf's "
        "restricted MILP, no restricted MILP of the tree's other leaves at the bound "
        "(`SearchOptions::other_leaf_nets` 0); before it, step 4's exact MILP and "
        "step 4a's first improvement MILP before step 4b's tree also where step 2's incumbent "
        "is already one step above the bound (`SearchOptions::tree_first_at_one_step`), with "
        "glibc's malloc thresholds (`milp/allocator.h`); before it, step 4d (the tree again "
        "where the incumbent is one step above the bound, splitting the number of slots of "
        "each fired thruster in a half, quarter, ... of the horizon) only after step 4c's "
        "exchange, not also between step 4b's tree and its leaves' MILPs "
        "(`SearchOptions::windows_before_leaves`); before it, without step "
        "4d (`SearchOptions::total_branching_window_levels` 0), its `search` arm then "
        "splitting no window on those weeks; before it, step "
        "2's restricted MILP widened at most twice, not until a net holds a schedule, "
        "frees every slot or exceeds 6000 slots (`SearchOptions::max_widenings`), and without "
        "the MILP restricted to every slot of the thrusters the relaxation fires after the "
        "first two widenings (`SearchOptions::fired_thrusters_net`); before it, step "
        "4's exact MILP before the tree with all the time left, not 30 % "
        "(`SearchOptions::exact_time_share`), and the tree's leaves without a pivot limit "
        "(`SearchOptions::total_branching_leaf_pivot_limit`); before it, step 4a's improvement "
        "MILPs with a quarter of the time left, not a tenth; before it, the root basis of its "
        "branching on "
        "thruster "
        "totals by a second interior point and its crossover, not by the crossover from the "
        "relaxation's interior point in its LP session, and the exchange's MILPs with a quarter "
        "of the time left, not half; before it, without the exchange along axes (the MILP over "
        "every slot of one "
        "axis' thrusters and the incumbent's slots of the others); before it, each leaf LP of its "
        "branching on "
        "thruster totals (`transcription/total_branching.h`) an interior point from scratch, "
        "two side by side, not a dual simplex from its parent's basis in one LP session, and "
        "its MILPs that only look for schedules free to use all the time left, not a quarter "
        "of it; before it, the "
        "tree's budget a count of LPs whatever their size, not a budget of LP work; before it, "
        "the tree with hard bounds on the totals in its leaves' LPs, not elastic ones; before "
        "it, "
        "the tree on single thrusters only, not first the summed total of +N and -N; before "
        "it, the search without that branching; before it, for the Hill-Clohessy-Wiltshire rows "
        "the LP on the whole MILP without leaving out "
        "the blocks of thrusters an optimal schedule can leave off, `transcription/dormant.h`, "
        "for the GEO weeks the search before row generation), `cbc` is the first release's "
        "path (`--no-search`). Medians over the repeats; \"not reached\" counts as infinite; "
        "the ratios are the other path's time / this release's (> 1: faster now).\n\n";
  MdTable t({"case", "measure", "target (s)", "this release", "previous release", "ratio",
             "first release", "ratio", "verdict (this release)",
             "objective (this / previous / first)", "final gap (this / previous / first)"});
  for (const Pair& p : pairs) {
    if (p.search.empty()) continue;
    const Row& spec = *p.search.front();
    for (const Measure& m : MeasuresOf(spec)) {
      auto value = [&](const std::vector<const Row*>& arm) { return ArmValue(arm, m, spec); };
      const double now = value(p.search);
      const double limit = spec.Num(m.target_column);
      auto ratio = [&](double before) {
        if (!(now > 0.0) || !std::isfinite(now) || std::isnan(before)) return std::string("-");
        return std::isinf(before) ? "> " + G(spec.Num("time_limit_s") / now, 3) + "x"
                                  : G(before / now, 3) + "x";
      };
      const double previous = value(p.previous), first = value(p.cbc);
      t.Add({p.id, m.name, G(limit, 3), Sec(now), Sec(previous), ratio(previous), Sec(first),
             ratio(first), Verdict(now, limit),
             PerArm({&p.search, &p.previous, &p.cbc}, "objective", false),
             PerArm({&p.search, &p.previous, &p.cbc}, "gap", true)});
    }
  }
  md << t.Str() << "\n";
  md << "What the search did (first repeat of each case):\n\n";
  for (const Pair& p : pairs) {
    if (p.search.empty()) continue;
    md << "- `" << p.id << "`: " << p.search.front()->Get("search_steps") << "\n";
  }
  md << "\n";
  WriteLazyLpAblation(md, pairs);
}

}  // namespace thrustsched::bench
