// report.md, the SVG plots and the search's step logs (DIR/logs/) of
// thrustsched-bench, generated from the rows of results.csv alone (plus the
// solve targets' progress traces, DIR/runs/targets-*.trace.csv, when
// present), so `thrustsched-bench --report-only DIR` regenerates them after a
// run. Which runs made the rows (command, date, revision, machine) is in
// DIR/meta.json; the report links it in one line. No line of report.md is
// longer than kReportMaxLineChars.
//
//   bench::ReportMeta meta = bench::CollectMeta(argc, argv, /*quick=*/false);
//   bench::WriteMetaJson("out/meta.json", meta);
//   bench::WriteReport("out", bench::ReadResultsCsv("out/results.csv"), meta);
//
// Sections (headings the test suite checks): "## Summary" (one row per
// performance target), "## Targets",
// "## 1. Accuracy", "## 2. Cost per scheme", "## 3. Formulations and encodings",
// "## 4. Scaling", "## 5. Operational constraints", "## Method and definitions",
// "## Not run or skipped".
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_H_

#include <cstddef>
#include <string>
#include <vector>

#include "benchmarks/bench/results.h"

namespace thrustsched::bench {

/// No line of report.md is longer than this (characters): tables wider than it
/// are split (report_format.h), prose is wrapped, long logs go to logs/.
constexpr size_t kReportMaxLineChars = 200;
/// Prose lines of report.md are wrapped at this width (characters).
constexpr size_t kReportWrapChars = 100;

/// A run whose rows a partial re-run (`--merge`) kept.
struct EarlierRun {
  std::string command;
  std::string date_utc;
  std::string git_revision;
  std::string load_average;
  std::string machine;
  std::string cases_glob;  // the cases that run (re)ran
  double total_wall_s = 0.0;
};

struct ReportMeta {
  std::string command;       // command line as run
  std::string date_utc;      // ISO 8601
  std::string machine;       // CPU model, cores, memory, kernel
  std::string load_average;  // /proc/loadavg at start
  std::string git_revision;  // short hash (+ "-dirty"), or "unknown"
  std::string solver;        // CBC/CLP versions linked
  std::string external;      // versions of the cbc and glpsol programs found
  std::string build_type;    // CMAKE_BUILD_TYPE of the tool
  bool quick = false;
  int threads = 0;
  double time_limit_s = 0.0;
  std::string scenario_glob;
  std::string cases_glob = "*";  // --cases of this run
  double total_wall_s = 0.0;
  /// Runs whose rows this one kept (--merge), oldest first: the report names
  /// them so that no row is credited to the wrong revision or date.
  std::vector<EarlierRun> earlier;
  /// Section 6: one subdirectory per `thrustsched simulate` run, each with its
  /// year.json (e.g. docs/year); empty or missing: the section says so.
  std::string year_results_dir;
  /// data/reference/thesis_chapter5.json (the published yearly figures).
  std::string year_reference_path;
};

/// Machine, date, versions, command line.
ReportMeta CollectMeta(int argc, char** argv, bool quick);
/// @throws std::runtime_error naming the path on I/O failure.
void WriteMetaJson(const std::string& path, const ReportMeta& meta);
ReportMeta ReadMetaJson(const std::string& path);

/// Writes dir/report.md, dir/logs/*.log (the search's steps per solver-speed
/// case) and the plots (dir/*.svg via gnuplot, scripts and data
/// dir/plots/*.gp, *.dat; skipped with a note if gnuplot is missing).
/// @throws std::runtime_error if report.md cannot be written.
void WriteReport(const std::string& dir, const std::vector<Row>& rows, const ReportMeta& meta);

/// Median of the finite values (NaN if none).
double Median(std::vector<double> values);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_H_
