// report.md: the sections in order (report_sections.h and the section files
// report_*.cc), then the plots' status.
#include "benchmarks/bench/report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/plots.h"
#include "benchmarks/bench/report_campaigns.h"
#include "benchmarks/bench/report_conjunction.h"
#include "benchmarks/bench/report_format.h"
#include "benchmarks/bench/report_random_weeks.h"
#include "benchmarks/bench/report_sections.h"
#include "benchmarks/bench/report_solver.h"
#include "benchmarks/bench/report_transfer.h"

namespace thrustsched::bench {

double Median(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return std::isnan(v); }),
               values.end());
  if (values.empty()) return report_internal::kNaN;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  if (n % 2 == 1) return values[n / 2];
  if (std::isinf(values[n / 2]) || std::isinf(values[n / 2 - 1])) return values[n / 2];
  return 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

void WriteReport(const std::string& dir, const std::vector<Row>& rows, const ReportMeta& meta) {
  using namespace report_internal;
  // Published figures and targets: beside the year's reference file when the
  // run names one, else in this source tree's data/reference/.
  const std::string reference_dir =
      meta.year_reference_path.empty()
          ? std::string(THRUSTSCHED_SOURCE_DIR) + "/data/reference"
          : std::filesystem::path(meta.year_reference_path).parent_path().string();
  const BenchReference ref = LoadBenchReference(reference_dir);
  const Index idx(rows);
  Plotter plot;
  plot.dir = dir;
  plot.gnuplot = app::GnuplotAvailable();
  std::ostringstream md;
  WriteHeader(md, meta);
  WriteSummary(md, idx, rows, meta, ref);
  WriteTargets(md, idx, meta, ref, &plot);
  WriteAccuracy(md, idx, &plot);
  WriteCost(md, idx, ref, &plot);
  WriteFormulations(md, idx);
  WriteScaling(md, idx, &plot);
  WriteOperations(md, idx, ref);
  WriteYear(md, meta, ref);
  WriteCollisionAvoidance(md, rows);
  WriteSolverSpeed(md, rows, dir);
  WriteCampaigns(md, dir);
  WriteTransfers(md, rows);
  WriteRandomWeeks(md, rows);
  WriteMethod(md);
  WriteSkipped(md, idx, meta);
  WriteColumns(md);
  if (!plot.gnuplot) {
    md << "\nPlots: gnuplot not found; the scripts and data are in plots/.\n";
  } else if (!plot.failed.empty()) {
    md << "\nPlots that gnuplot failed to draw (see plots/*.log):";
    for (const std::string& f : plot.failed) md << " " << f;
    md << "\n";
  }
  std::ofstream out(dir + "/report.md");
  out << WrapMarkdown(md.str(), kReportWrapChars);
  if (!out) throw std::runtime_error("cannot write " + dir + "/report.md");
}

}  // namespace thrustsched::bench
