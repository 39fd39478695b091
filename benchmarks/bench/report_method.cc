// Report closing sections: method and definitions, cases not run, column glossary.
#include "benchmarks/bench/report_sections.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "benchmarks/bench/report_format.h"
#include "benchmarks/bench/report_index.h"
#include "benchmarks/bench/report_plotter.h"

namespace thrustsched::bench::report_internal {

void WriteMethod(std::ostream& md) {
  md << "## Method and definitions\n\n"
     << "- **Runs**: each configuration (and each repeat) runs in a forked child process; the "
        "parent waits with a deadline (300 s + 2x the time limit, plus the external "
        "cross-check) and records a crash, a kill or an exception as a row with that status. "
        "Runs are sequential, so that timings do not compete with each other and the peak "
        "memory is per configuration. The machine is shared with other jobs: wall-clock times "
        "vary by up to 2-3x between runs, which is why the timing targets are medians of "
        "repeated runs with their spread.\n"
     << "- **peak_rss_mb**: the child's `getrusage(RUSAGE_SELF).ru_maxrss` taken after the "
        "solve and the check (before any external solver runs), i.e. the peak of this "
        "configuration alone plus the few MB the parent had mapped at fork time.\n"
     << "- **discretise_s**: `dynamics::Discretise` on the scenario's grid (wall clock). "
        "**build_s**: `ScheduleMilp` rows, columns and freezing into `LpData` from that "
        "discretisation (`BuildStats::build_seconds`).\n"
     << "- **lp_bound, lp_s**: the continuous relaxation solved separately by CLP with "
        "presolve and the algorithm in `lp_relaxation_algorithm` (dual simplex in section 3, "
        "the case's root-LP algorithm elsewhere), not CBC's root node, which adds cuts.\n"
     << "- **time_to_first_s**: first incumbent. **time_to_1pct_s**: first moment the proven "
        "gap (incumbent vs CBC's bound at that moment) is <= 1 %. **time_to_opt_s**: the "
        "solve time when CBC proved optimality to the 1e-4 relative gap (empty otherwise, and "
        "for solves run to a 1 % gap). **time_within_1pct_of_opt_s**: first incumbent within "
        "1 % of the published optimum (or of the run's final bound).\n"
     << "- **max_window_violation**: the independent checker (transcription/checker.h) "
        "re-propagates the continuous-time linear model with adaptive integration through "
        "the decoded burns (grid nodes plus 4 samples inside each interval): max over samples "
        "of |y| - half width, in the window's unit (m for HCW, deg for GEO; 0 = inside). "
        "The MILP constrains nodes only, so the inter-sample part can be positive for a valid "
        "schedule; `max_window_violation_nodes` is the node-only value. "
        "**max_window_violation_nonlinear_deg**: the same through the nonlinear GEO "
        "simulator (dynamics/geo_simulator.h). **terminal_error**: box/fixed terminal "
        "constraint error of the re-propagated final state, in state-scale units.\n"
     << "- **Consumption**: `consumption_l1_m_s` is the thesis's L1 metric (sum over thrusters "
        "of ||Gamma_i||_1 x on-time); `delta_v_m_s` is F/m x on-time. The objective is the L1 "
        "metric in every scenario here.\n"
     << "- **cpu_s, load_1min**: user + system CPU seconds of the child (all its threads; "
        "taken before the external cross-check) and the 1-minute load average of the machine "
        "when the run started. On a shared 2-core machine, CPU / wall well below the thread "
        "count means the run waited for a core: its wall times are inflated by other jobs.\n"
     << "- **Medians**: over the repeats of one configuration; a repeat that never reached a "
        "milestone counts as \"not reached\" (+inf) in the median.\n"
     << "- **Threads**: CBC with more than one thread is not deterministic; objectives of "
        "time-limited runs can differ between repeats.\n"
     << "- **Time limits**: CBC checks its time limit only after the root LP relaxation "
        "(coin-or/Cbc#231), so a solve can overrun its limit by the root LP time.\n"
     << "- **Solver settings** not set by the benchmark (presolve, random seed) come from each "
        "scenario file, with one exception: the Table 4.2 files set `\"presolve\": false`, and "
        "the benchmark runs them with presolve on (the library default). Measured while "
        "building this benchmark (t1 = 2 d, 1 thread, load ~5 on 2 cores): presolve off spent "
        "1128 s in CBC's root LP (the 600 s limit cannot interrupt it) and then reported the "
        "feasible model *infeasible* (cbc status 0, secondary 1); presolve on reached the "
        "optimum 1.72113 in 68 s. The `note` column marks these rows.\n\n";
}

void WriteSkipped(std::ostream& md, const Index& idx, const ReportMeta& m) {
  md << "## Not run or skipped\n\n";
  if (m.quick) {
    md << "- Quick mode: the timing targets, Table 4.1 beyond 1 day, Table 4.2, the 7-day "
          "GEO solves and the constrained-final-state week are not run; horizons are 1-2 "
          "days.\n";
  }
  md << "- Condensed formulation not solved for Table 4.1 beyond 2 days, Table 4.2 (7 days) "
        "and the GEO week: its window rows are dense in all earlier binaries, so the matrix "
        "has ~ (outputs x thrusters) N^2 / 2 nonzeros (GEO week: 2 x 4 x 2016^2 / 2 = 1.6e7; "
        "Table 4.2 week: 2 x 6 x 2016^2 / 2 = 2.4e7). Its build size and time are measured "
        "up to 7 days in section 4 instead.\n"
     << "- Thesis encoding: run on Table 4.1, Table 4.2 t1 = 2 d and the GEO week, not on "
        "the other Table 4.2 cases (tight only, with the external cross-check).\n"
     << "- One-year runs are not run by this tool (hours each): section 6 reads the results of "
        "`thrustsched simulate` (scripts/run_year_validation.sh).\n";
  for (const Group& g : idx.groups()) {
    for (const Row* r : g.rows) {
      const std::string st = r->Get("status");
      if (st == "error" || st == "killed" || st == "crashed") {
        md << "- **Failed run** " << r->Get("case_id") << " (repeat " << r->Get("repeat")
           << "): " << st << ": " << r->Get("note") << "\n";
      }
    }
  }
  if (m.scenario_glob != "*") {
    md << "- Only scenarios matching `" << m.scenario_glob << "` were run.\n";
  }
  md << "\n";
}

void WriteColumns(std::ostream& md) {
  md << "## Columns of results.csv\n\n"
     << "One row per run (accuracy: per scheme and step). Contract columns (fixed names): `" <<
      [] {
        std::string s;
        for (const std::string& c : ContractColumns()) s += (s.empty() ? "" : "`, `") + c;
        return s;
      }()
     << "`. Extensions: `section`, `case_id`, `repeat`, `variant` (what was changed), "
        "`model`, `n_thrusters`, `threads`, `time_limit_s`, `relative_gap`, `lp_algorithm`, "
        "`lp_relaxation_algorithm`, "
        "`objective_step` (0 = off), `global_rel_err`, `observed_order_phi/gamma` (accuracy "
        "rows), `nodes`, `time_to_opt_s`, `time_within_1pct_of_opt_s`, `operational_ok`, "
        "`max_window_violation_nodes`, `window_unit`, `terminal_ok`, `terminal_error`, "
        "`published`, `published_source`, `ratio` (objective / published), `ext_cbc_*`, "
        "`ext_glpsol_*` and `ext_highs_*` (status, objective, seconds of the external "
        "cross-check; HiGHS also `ext_highs_bound` and `ext_highs_gap`, its mip_dual_bound and "
        "mip_gap), collision avoidance (section 7): `start_objective`, `budget_rounds`, "
        "`keep_out_binaries`, `max_risk`, `max_risk_unmanoeuvred` (thrust-free path), "
        "`published_risk_unmanoeuvred`, `mc_samples`, `mc_collisions_linear`, "
        "`mc_collisions_nonlinear`, `mc_min_distance_m`, `verify_s`, and for on-off cases "
        "`without_conjunction` (cost of the plan without the conjunction), `extra_cost`, "
        "`without_max_risk`, `without_mc_collisions_linear`, `without_mc_collisions_nonlinear` "
        "(that plan verified against the conjunction), `allocator_tuned` (MILP rows: 1 "
        "when the child ran with milp/allocator.h's malloc thresholds, 0 with glibc's, as "
        "the releases before ff7ffbf), orbit transfers (section 10): `transfer_method`, "
        "`transfer_figure` in `transfer_unit` (h, d or km_s), `feedback_phase` and "
        "`published_feedback_phase` (d), `switch_rule`, `propellant_kg`, `propellant_limit_kg` "
        "(T t_f / (g0 Isp) of the published minimum time), `revolutions`, `wall_s` "
        "(whole child run), `exit` (child exit code), `note`. Times are wall-clock seconds; "
        "empty cells = not applicable or not reached.\n";
}

}  // namespace thrustsched::bench::report_internal
