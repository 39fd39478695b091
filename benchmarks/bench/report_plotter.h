// The report's plots: each is a gnuplot script (and its data) written under
// DIR/plots/ and drawn into DIR/NAME.svg when gnuplot is installed, so the
// scripts stay for a reader who wants to redraw them.
//
//   report_internal::Plotter plot{"out", app::GnuplotAvailable()};
//   plot.Run("scaling_step", "plot 'scaling.dat' using 1:2 with lines\n");
//   md << plot.Link("scaling_step", "time against step");
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_PLOTTER_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_PLOTTER_H_

#include <string>
#include <vector>

namespace thrustsched::bench::report_internal {

struct Plotter {
  std::string dir;
  bool gnuplot = false;
  std::vector<std::string> made, failed;

  /// Writes DIR/plots/NAME.gp (SVG terminal prepended) and runs it.
  void Run(const std::string& name, const std::string& script);
  /// Writes DIR/plots/NAME (a data file the scripts read); returns NAME.
  std::string Data(const std::string& name, const std::string& text);
  /// The markdown image link of DIR/NAME.svg.
  std::string Link(const std::string& name, const std::string& alt) const;
};

}  // namespace thrustsched::bench::report_internal

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_PLOTTER_H_
