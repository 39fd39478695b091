// thrustsched-bench: integration schemes x formulations x encodings on the
// thesis scenarios, in one run, with one command.
//
//   thrustsched-bench [--quick] [--scenarios GLOB] [--out DIR] [--threads N]
//                     [--time-limit S] [--repeats K] [--cases GLOB] [--merge]
//                     [--report-only] [--list] [--year-results DIR]
//                     [--external-time-limit S] [--keep-mps]
//
// Writes DIR/results.csv, DIR/report.md, DIR/*.svg, DIR/meta.json,
// DIR/runs/ (one JSON result file and one solver trace per run) and
// DIR/random_weeks/ (the weeks of the section "random_weeks", drawn by
// scripts/random_weeks.py from bench::kRandomWeeksSeed). Each run is
// a forked child process (see runner.h). Exit code: 0 when every case
// produced a row (solver limits are results, not failures), 1 if a case
// failed (error, crash or deadline), 2 on bad command-line input.
#include <fnmatch.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/report.h"
#include "benchmarks/bench/results.h"
#include "benchmarks/bench/runner.h"
#include "transcription/search/search_options.h"

namespace {

namespace bench = thrustsched::bench;

const char* KindName(bench::CaseKind k) {
  switch (k) {
    case bench::CaseKind::kAccuracy:
      return "accuracy";
    case bench::CaseKind::kDiscretise:
      return "discretise";
    case bench::CaseKind::kBuild:
      return "build";
    case bench::CaseKind::kSolve:
      return "solve";
    case bench::CaseKind::kConjunction:
      return "conjunction";
    case bench::CaseKind::kTransfer:
      return "transfer";
  }
  return "?";
}

// Draws the random weeks into `dir` (scripts/random_weeks.py, the bench's
// seed and count); false, with a warning, where the script fails (the
// section is then not run).
bool WriteRandomWeeks(const std::string& dir) {
  const std::string cmd = "python3 '" THRUSTSCHED_SOURCE_DIR "/scripts/random_weeks.py' --seed " +
                          std::to_string(bench::kRandomWeeksSeed) + " --count " +
                          std::to_string(bench::kRandomWeeksCount) + " --out '" + dir +
                          "' > /dev/null";
  if (std::system(cmd.c_str()) == 0) return true;
  std::cerr << "thrustsched-bench: warning: scripts/random_weeks.py could not write " << dir
            << ": the section random_weeks is not run\n";
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "thrustsched-bench: compare integration schemes, formulations and encodings "
      "on the thesis scenarios; writes DIR/results.csv, DIR/report.md and SVG plots"};
  bool quick = false, report_only = false, list = false, no_fork = false, keep_mps = false;
  bool merge = false;
  std::string glob = "*", case_glob = "*", out = "bench-out";
  std::string data_dir = THRUSTSCHED_DATA_DIR;
  std::string bench_scenarios = THRUSTSCHED_BENCH_SCENARIO_DIR;
  int threads = 2, repeats = 3;
  double time_limit = 60.0;
  app.add_flag("--quick", quick, "small matrix touching every code path (under 2 minutes)");
  app.add_option("--scenarios", glob, "only scenarios whose name matches this glob (fnmatch)");
  app.add_option("--cases", case_glob, "only cases whose id matches this glob (see --list)");
  app.add_option("--out", out, "output directory (created)");
  app.add_option("--threads", threads,
                 "CBC threads of the matrix solves (the two solve targets keep 1 and 2)")
      ->check(CLI::Range(1, 64));
  app.add_option("--time-limit", time_limit,
                 "time limit (s) of each matrix solve; the target cases keep their own "
                 "(600 s and 120 s); the constrained-final-state week uses max(S, 120)")
      ->check(CLI::PositiveNumber);
  double external_time_limit = 0.0;
  app.add_option("--external-time-limit", external_time_limit,
                 "time limit (s) of each external cross-check solver (cbc, glpsol, HiGHS); "
                 "default min(30, --time-limit), --quick 600 (a guard: quick runs stop at a "
                 "node limit)")
      ->check(CLI::PositiveNumber);
  app.add_option("--repeats", repeats, "repeats of the timing-target cases")
      ->check(CLI::Range(1, 20));
  app.add_option("--data-dir", data_dir, "data directory (scenarios/ inside)");
  std::string year_dir = THRUSTSCHED_SOURCE_DIR "/docs/year";
  app.add_option("--year-results", year_dir,
                 "directory of `thrustsched simulate` runs (one subdirectory with year.json "
                 "each) for the report's section 6");
  app.add_flag("--report-only", report_only,
               "regenerate report.md and plots from DIR/results.csv and DIR/meta.json");
  app.add_flag("--list", list, "print the cases and exit");
  app.add_flag("--no-fork", no_fork, "run cases in-process (debugging; peak RSS not per case)");
  app.add_flag("--keep-mps", keep_mps,
               "keep the MPS files of the external cross-check and the external solvers' raw "
               "output (.sol, .log, .glpsol.txt, .highs.txt; removed otherwise)");
  std::vector<std::string> disabled_phases;
  app.add_option("--disable-phases", disabled_phases,
                 "phases of the search left out in every search case, comma-separated "
                 "(an ablation; docs/search.md names them)")
      ->delimiter(',');
  app.add_flag("--merge", merge,
               "keep the rows of DIR/results.csv whose cases are not run again (partial re-runs)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  try {
    if (report_only) {
      const std::vector<bench::Row> rows = bench::ReadResultsCsv(out + "/results.csv");
      bench::ReportMeta meta = bench::ReadMetaJson(out + "/meta.json");
      meta.year_results_dir = year_dir;
      meta.year_reference_path = data_dir + "/reference/thesis_chapter5.json";
      bench::WriteReport(out, rows, meta);
      std::cout << "wrote " << out << "/report.md from " << rows.size() << " rows\n";
      return 0;
    }
    {
      thrustsched::transcription::SearchOptions search;
      search.disabled_phases = disabled_phases;
      std::string error;
      if (!search.IsValid(&error)) {
        std::cerr << "thrustsched-bench: --disable-phases: " << error << "\n";
        return 2;
      }
    }
    bench::MatrixOptions mo;
    mo.quick = quick;
    mo.scenario_dirs = {data_dir + "/scenarios", bench_scenarios};
    mo.scenario_glob = glob;
    mo.threads = threads;
    mo.time_limit_s = time_limit;
    mo.timing_repeats = repeats;
    mo.external_time_limit_s = external_time_limit;
    // --list writes nothing to DIR: the weeks go to a temporary folder.
    std::string list_dir;
    if (list) {
      std::string pattern =
          (std::filesystem::temp_directory_path() / "thrustsched-bench-XXXXXX").string();
      if (mkdtemp(pattern.data()) != nullptr) list_dir = pattern;
    }
    const std::string weeks_dir = list ? list_dir + "/random_weeks" : out + "/random_weeks";
    if (!quick && (!list || !list_dir.empty()) && WriteRandomWeeks(weeks_dir)) {
      mo.random_weeks_dir = weeks_dir;
    }
    std::vector<bench::CaseSpec> cases;
    for (bench::CaseSpec& c : bench::BuildMatrix(mo)) {
      if (fnmatch(case_glob.c_str(), c.id.c_str(), 0) == 0) cases.push_back(std::move(c));
    }
    if (!list_dir.empty()) {
      std::error_code ec;
      std::filesystem::remove_all(list_dir, ec);
    }
    if (list) {
      for (const bench::CaseSpec& c : cases) {
        std::cout << c.id << "  [" << KindName(c.kind) << ", x" << c.repeats << ", " << c.threads
                  << " thr, " << c.time_limit_s << " s] " << c.variant << "\n";
      }
      std::cout << cases.size() << " cases\n";
      return 0;
    }
    if (cases.empty()) {
      std::cerr << "thrustsched-bench: no case matches --scenarios " << glob << "\n";
      return 2;
    }
    std::filesystem::create_directories(out + "/runs");
    bench::ReportMeta meta = bench::CollectMeta(argc, argv, quick);
    meta.threads = threads;
    meta.time_limit_s = time_limit;
    meta.scenario_glob = glob;
    meta.year_results_dir = year_dir;
    meta.year_reference_path = data_dir + "/reference/thesis_chapter5.json";
    bench::RunContext ctx;
    ctx.runs_dir = out + "/runs";
    ctx.fork = !no_fork;
    ctx.keep_mps = keep_mps;
    ctx.disabled_phases = disabled_phases;

    const auto t0 = std::chrono::steady_clock::now();
    std::vector<bench::Row> rows;
    meta.cases_glob = case_glob;
    if (merge && std::filesystem::exists(out + "/results.csv")) {
      // The kept rows come from the earlier run(s): name them in the report.
      if (std::filesystem::exists(out + "/meta.json")) {
        const bench::ReportMeta before = bench::ReadMetaJson(out + "/meta.json");
        meta.earlier = before.earlier;
        meta.earlier.push_back({before.command, before.date_utc, before.git_revision,
                                before.load_average, before.machine, before.cases_glob,
                                before.total_wall_s});
      }
      std::set<std::string> rerun;
      for (const bench::CaseSpec& c : cases) rerun.insert(c.id);
      for (bench::Row& r : bench::ReadResultsCsv(out + "/results.csv")) {
        if (!rerun.count(r.Get("case_id"))) rows.push_back(std::move(r));
      }
    }
    int failures = 0, done = 0, total = 0;
    for (const bench::CaseSpec& c : cases) total += c.repeats;
    for (const bench::CaseSpec& c : cases) {
      for (int k = 0; k < c.repeats; ++k) {
        ++done;
        std::cerr << "[" << done << "/" << total << "] " << c.id
                  << (c.repeats > 1 ? " (repeat " + std::to_string(k + 1) + ")" : "") << " ... "
                  << std::flush;
        const std::vector<bench::Row> got = bench::RunCase(c, k, ctx);
        for (const bench::Row& r : got) {
          const std::string st = r.Get("status");
          if (st == "error" || st == "killed" || st == "crashed") ++failures;
        }
        const bench::Row& r0 = got.front();
        std::cerr << r0.Get("wall_s").substr(0, 6) << " s";
        if (r0.Has("status")) std::cerr << ", " << r0.Get("status");
        if (r0.Has("objective")) std::cerr << ", objective " << r0.Get("objective");
        if (r0.Has("note") && (r0.Get("status") == "error" || r0.Get("status") == "crashed" ||
                               r0.Get("status") == "killed")) {
          std::cerr << " (" << r0.Get("note") << ")";
        }
        std::cerr << "\n";
        rows.insert(rows.end(), got.begin(), got.end());
        bench::WriteResultsCsv(out + "/results.csv", rows);  // partial results survive
      }
    }
    meta.total_wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    bench::WriteMetaJson(out + "/meta.json", meta);
    bench::WriteReport(out, rows, meta);
    std::cout << "wrote " << out << "/results.csv (" << rows.size() << " rows), " << out
              << "/report.md in " << static_cast<int>(meta.total_wall_s) << " s";
    if (failures > 0) std::cout << "; " << failures << " failed run(s), see the note column";
    std::cout << "\n";
    return failures > 0 ? 1 : 0;
  } catch (const std::invalid_argument& e) {
    std::cerr << "thrustsched-bench: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "thrustsched-bench: " << e.what() << "\n";
    return 1;
  }
}
