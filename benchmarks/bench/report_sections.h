// The sections of report.md that read results.csv's rows (report.cc puts
// them in order; report_solver.h and report_conjunction.h write sections 7-8).
//
//   const report_internal::Index idx(rows);
//   report_internal::Plotter plot{dir, app::GnuplotAvailable()};
//   report_internal::WriteAccuracy(md, idx, &plot);
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_SECTIONS_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_SECTIONS_H_

#include <ostream>
#include <vector>

#include "benchmarks/bench/reference_figures.h"
#include "benchmarks/bench/report.h"
#include "benchmarks/bench/report_index.h"
#include "benchmarks/bench/report_plotter.h"

namespace thrustsched::bench::report_internal {

/// Title, one line of provenance (the rest is in meta.json) and contents (report_meta.cc).
void WriteHeader(std::ostream& md, const ReportMeta& m);
/// "## Summary": one row per performance target (report_summary.cc).
void WriteSummary(std::ostream& md, const Index& idx, const std::vector<Row>& rows,
                  const ReportMeta& m, const BenchReference& ref);
/// The discretise/build cases of the 7-day GEO grid at 5 min, one per scheme.
std::vector<const Group*> WeekGridCostGroups(const Index& idx);
/// Wall seconds of the complete nominal year (year_anzel4_fixed) among the
/// runs of m.year_results_dir; NaN when there is none.
double NominalYearWallS(const ReportMeta& m);
/// "## Targets": discretise/build and solve targets, medians with spread.
void WriteTargets(std::ostream& md, const Index& idx, const ReportMeta& m,
                  const BenchReference& ref, Plotter* plot);
/// "## 1. Accuracy".
void WriteAccuracy(std::ostream& md, const Index& idx, Plotter* plot);
/// "## 2. Cost per scheme", with the thesis's Table 4.3 comparison.
void WriteCost(std::ostream& md, const Index& idx, const BenchReference& ref, Plotter* plot);
/// "## 3. Formulations and encodings".
void WriteFormulations(std::ostream& md, const Index& idx);
/// "## 4. Scaling".
void WriteScaling(std::ostream& md, const Index& idx, Plotter* plot);
/// "## 5. Operational constraints" (thesis Tables 4.3, 4.4).
void WriteOperations(std::ostream& md, const Index& idx, const BenchReference& ref);
/// "## 6. One year of station keeping" from the year.json files of meta.year_results_dir.
void WriteYear(std::ostream& md, const ReportMeta& m, const BenchReference& ref);
/// "## Method and definitions".
void WriteMethod(std::ostream& md);
/// "## Not run or skipped".
void WriteSkipped(std::ostream& md, const Index& idx, const ReportMeta& m);
/// "## Columns of results.csv".
void WriteColumns(std::ostream& md);

}  // namespace thrustsched::bench::report_internal

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_SECTIONS_H_
