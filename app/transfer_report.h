// The plots and report.html of `thrustsched transfer`: elements.svg (a, e, i
// and the mass against time, from trajectory.csv) and orbit.svg (the x-y
// projection of orbit.csv: the Cartesian replay, with the Earth, the start
// and the end), drawn by gnuplot from scripts left in the folder (as the
// other commands' plots, app/plots.h), and one self-contained page in the
// style of the solve report (app/html_report.h): the scenario in words, the
// result, the convergence figures, the state handed over to station
// keeping and the plots.
//
//   app::PlotResult p = app::WriteTransferPlots(folder.path(), scenario, summary, rows,
//                                                  run.orbit.size(), !no_plots);
//   app::WriteTransferReport(folder.path(), scenario, summary);   // after the plots
#ifndef THRUSTSCHED_APP_TRANSFER_REPORT_H_
#define THRUSTSCHED_APP_TRANSFER_REPORT_H_

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "app/plots.h"
#include "app/transfer_scenario.h"

namespace thrustsched::app {

/// Writes elements.gp and orbit.gp into `dir` (which holds trajectory.csv
/// and orbit.csv, of trajectory_rows and orbit_points rows: the scripts draw
/// at most 5000 and 20000 of them) and, with run_gnuplot and gnuplot found,
/// their SVGs.
/// Never throws for a missing or failing gnuplot (PlotResult says why);
/// @throws std::runtime_error if a script cannot be written.
PlotResult WriteTransferPlots(const std::string& dir, const TransferScenario& scenario,
                              const nlohmann::json& summary, std::size_t trajectory_rows,
                              std::size_t orbit_points, bool run_gnuplot);

/// Writes dir/report.html from `summary` (summary.json's content) and the
/// SVG files present in `dir`. @throws std::runtime_error if it cannot write.
void WriteTransferReport(const std::string& dir, const TransferScenario& scenario,
                         const nlohmann::json& summary);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_TRANSFER_REPORT_H_
