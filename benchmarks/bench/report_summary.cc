// Report section "Summary": every performance target on one screen (goal,
// median, met or missed and by how much), computed from the same rows (and
// year.json files) as the sections that give the details.
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "benchmarks/bench/report_format.h"
#include "benchmarks/bench/report_sections.h"
#include "benchmarks/bench/report_solver.h"

namespace thrustsched::bench::report_internal {
namespace {

// "3.56 s", or "not reached" (no unit).
std::string Seconds(double v) { return std::isfinite(v) ? Sec(v) + " s" : Sec(v); }

std::string Repeats(const Group& g) { return "n=" + std::to_string(g.rows.size()); }

// The slowest scheme's median of `col` over the 7-day GEO grid's cost cases.
void AddSlowestScheme(MdTable* t, const std::vector<const Group*>& cost, const std::string& what,
                      const std::string& col, double limit_s) {
  const Group* slowest = nullptr;
  double worst = -kInf;
  for (const Group* g : cost) {
    const double v = MedianOf(g->Values(col), true);
    if (v > worst) worst = v, slowest = g;
  }
  if (slowest == nullptr) {
    t->Add({what, "< " + G(limit_s) + " s", "not run", "-"});
    return;
  }
  t->Add({what, "< " + G(limit_s) + " s",
          Seconds(worst) + " (" + slowest->Get("scheme") + ", slowest of " +
              std::to_string(cost.size()) + " schemes; " + Repeats(*slowest) + ")",
          Verdict(worst, limit_s)});
}

// The CBC-alone solve target of `scenario` in section "targets".
void AddSolveTarget(MdTable* t, const Index& idx, const std::string& scenario,
                    const std::string& what, const std::string& col, double limit_s) {
  for (const Group* g : idx.Section(kSectionTargets)) {
    if (g->Get("scenario") != scenario) continue;
    const double v = MedianOf(g->Values(col), true);
    t->Add({what, "< " + G(limit_s) + " s", Seconds(v) + " (" + Repeats(*g) + ")",
            Verdict(v, limit_s)});
    return;
  }
  t->Add({what, "< " + G(limit_s) + " s", "not run", "-"});
}

// The solver-speed targets: one row per time target, one per group of gap
// targets (the hard weeks: how many met, the slowest, the misses).
void AddSolverTargets(MdTable* t, const std::vector<Row>& rows) {
  std::map<std::pair<std::string, double>, std::vector<SolverTarget>> gap_groups;
  std::vector<std::pair<std::string, double>> gap_order;
  for (const SolverTarget& s : SolverSpeedTargets(rows)) {
    if (!s.gap_target) {
      t->Add({"search, " + SolverCaseShortId(s.case_id) + ": " + s.measure,
              "< " + G(s.limit_s) + " s", Seconds(s.median_s), Verdict(s.median_s, s.limit_s)});
      continue;
    }
    const auto key = std::make_pair(s.measure, s.limit_s);
    if (!gap_groups.count(key)) gap_order.push_back(key);
    gap_groups[key].push_back(s);
  }
  for (const auto& key : gap_order) {
    const std::vector<SolverTarget>& g = gap_groups[key];
    const SolverTarget* slowest = &g.front();
    std::string missed;
    int n_missed = 0;
    for (const SolverTarget& s : g) {
      if (!(s.median_s <= slowest->median_s)) slowest = &s;
      if (!(s.median_s < s.limit_s)) {
        ++n_missed;
        missed += (missed.empty() ? "" : ", ") + SolverCaseShortId(s.case_id);
      }
    }
    const std::string what = "search, hard weeks (" + std::to_string(g.size()) + "): each " +
                             key.first + " in " + G(key.second) + " s";
    const std::string measured = std::to_string(g.size() - n_missed) + " of " +
                                 std::to_string(g.size()) + " met; slowest " +
                                 Seconds(slowest->median_s);
    t->Add({what, "each < " + G(key.second) + " s", measured,
            n_missed == 0 ? "met (slowest at " + G(100.0 * slowest->median_s / key.second, 3) +
                                " % of the limit)"
                          : "**missed** in " + std::to_string(n_missed) + ": " + missed});
  }
}

}  // namespace

void WriteSummary(std::ostream& md, const Index& idx, const std::vector<Row>& rows,
                  const ReportMeta& m, const BenchReference& ref) {
  md << "## Summary\n\n";
  md << "Every performance target, on this 2-core machine: the median over the repeats of "
        "one run (n = repeats; \"not reached\" counts as infinite), met or missed and by how "
        "much. The sections below give the spread and the details.\n\n";
  MdTable t({"target", "goal", "measured (median)", "verdict"});
  const std::vector<const Group*> cost = WeekGridCostGroups(idx);
  AddSlowestScheme(&t, cost, "Discretise the 7-day GEO grid (5 min)", "discretise_s",
                   ref.target_discretise_week_s);
  AddSlowestScheme(&t, cost, "Build its MILP (sparse, tight)", "build_s", ref.target_build_week_s);
  AddSolveTarget(&t, idx, "hcw_table42_t1_2d",
                 "CBC alone, Table 4.2 t1 = 2 d, 1 thread: incumbent within 1 % of the optimum",
                 "time_within_1pct_of_opt_s", ref.target_table_4_2_within_1pct_s);
  AddSolveTarget(&t, idx, "geo_week_anzel4",
                 "CBC alone, GEO week, 4 thrusters, 2 threads: proven 1 % gap", "time_to_1pct_s",
                 ref.target_geo_week_1pct_gap_s);
  AddSolverTargets(&t, rows);
  const double year_s = NominalYearWallS(m);
  t.Add({"The nominal year (year_anzel4_fixed), wall time of `thrustsched simulate`",
         "< " + G(ref.target_year_wall_s / 60.0) + " min",
         std::isnan(year_s) ? "not run" : G(year_s / 60.0, 3) + " min (one run)",
         std::isnan(year_s) ? "-" : Verdict(year_s, ref.target_year_wall_s)});
  md << t.Str() << "\n";
  md << "Rows 1-4: section Targets (CBC alone: `--no-search`); `search` rows: section 8 (the "
        "default path); the year: section 6 (from its year.json). The campaign engine's targets "
        "are in section 9 (measured by benchmarks/campaign_scaling.py).\n\n";
}

}  // namespace thrustsched::bench::report_internal
