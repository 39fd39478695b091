// SVG plots of a result directory, drawn by gnuplot from the CSV files
// (trajectory.csv, schedule.csv or impulses.csv). The generated .gp scripts
// stay in the directory so users can restyle and re-run them
// (`cd DIR && gnuplot window.gp`); the CSV files remain the primary data.
// Without gnuplot the scripts are still written and the plots are skipped.
//
//   app::PlotResult p = app::WritePlots("out/demo", scenario, /*has_nonlinear=*/true);
//   if (!p.ok) std::cerr << p.message << "\n";
//
// Plots: window.svg (trajectory in the window plane with the box: y-z in km
// for Cartesian models, longitude offset-latitude in deg for GEO),
// timeline.svg (per-thruster firing timeline; impulses for impulsive
// problems; forced-off windows and disabled thrusters shaded), outputs.svg
// (window outputs against time, with the box limits), and for Cartesian
// models xy.svg (radial against along-track). The trajectory plots mark the
// start, the end and the burns, and for a rendezvous the target and the aim
// point.
#ifndef THRUSTSCHED_APP_PLOTS_H_
#define THRUSTSCHED_APP_PLOTS_H_

#include <string>
#include <vector>

#include "app/scenario.h"

namespace thrustsched::app {

struct PlotOptions {
  bool run_gnuplot = true;          // false: write the scripts only
  std::string gnuplot = "gnuplot";  // program looked up in PATH

  /// gnuplot not empty when run_gnuplot. On failure `*error` (if given)
  /// names the field and the value.
  bool IsValid(std::string* error) const;
};

struct PlotResult {
  std::vector<std::string> scripts;  // file names written (in the directory)
  std::vector<std::string> images;   // SVG files produced
  bool gnuplot_found = false;
  bool ok = false;      // every image produced
  std::string message;  // why plots were skipped or failed
};

/// Writes window.gp, timeline.gp, outputs.gp (and xy.gp) into `dir` (which must already
/// hold trajectory.csv and schedule.csv or impulses.csv) and runs gnuplot on
/// them (its messages go to dir/gnuplot.log). Never throws for a missing or
/// failing gnuplot (see PlotResult); @throws std::runtime_error if a script
/// cannot be written, std::invalid_argument if !options.IsValid().
PlotResult WritePlots(const std::string& dir, const Scenario& scenario, bool has_nonlinear,
                      const PlotOptions& options = {});

/// True if WritePlots also draws xy.svg (radial against along-track, the
/// rendezvous view): Cartesian models with x and y positions.
bool HasXyView(const Scenario& scenario);

/// True if `program` can be executed (it is run with --version).
bool GnuplotAvailable(const std::string& program = "gnuplot");

/// Runs gnuplot on `<base>.gp` in `dir` for each base (scripts already
/// written). Returns the images produced (`<base>.svg`); *message says which
/// scripts failed ("" if none).
std::vector<std::string> RunGnuplotScripts(const std::string& dir,
                                           const std::vector<std::string>& bases,
                                           std::string* message,
                                           const std::string& program = "gnuplot");

/// Runs `program script` with `dir` as the working directory, its output
/// appended to dir/gnuplot.log. True if it exited with status 0.
bool RunGnuplot(const std::string& dir, const std::string& script,
                const std::string& program = "gnuplot");

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_PLOTS_H_
