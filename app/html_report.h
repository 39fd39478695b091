// report.html: one self-contained page per run (solve, simulate) that a
// user opens in a browser or prints: the scenario in words, the result, the
// checker's verdict, the plots (the run's SVG files inlined: no network, no
// script, no external file), and the schedule as a table (UTC columns where
// the model has an epoch). `simulate` adds the per-cycle table and the year
// plots (consumption per cycle, thrust-days per thruster, the box over the
// year, gap per cycle).
//
//   WriteSolveReport(folder.path(), scenario, summary_json);        // after the plots
//   YearReport y = WriteYearReport(dir, scenario, year_json, true);  // simulate
//
// The page is static HTML with a small embedded style sheet (a print style
// included); it is readable without JavaScript.
#ifndef THRUSTSCHED_APP_HTML_REPORT_H_
#define THRUSTSCHED_APP_HTML_REPORT_H_

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/scenario.h"

namespace thrustsched::app {

/// The report's file name.
inline constexpr const char* kReportName = "report.html";

/// Writes dir/report.html for a `solve` (or `check`) run. `summary` is the
/// run's summary.json content; the schedule (schedule.csv or impulses.csv)
/// and the plots (window.svg, xy.svg, timeline.svg, outputs.svg) are read
/// from `dir` where present. @throws std::runtime_error if it cannot write.
void WriteSolveReport(const std::string& dir, const Scenario& scenario,
                      const nlohmann::json& summary);

/// The files WriteYearReport may write (for simulate's manifest).
std::vector<std::string> YearReportFiles();

struct YearReport {
  std::vector<std::string> images;  // SVG files added (gap.svg, thrust_days.svg, box.svg)
  std::string message;              // why plots were skipped or failed, "" if none
};

/// Writes the year plots the report adds to simulate's (gap.gp,
/// thrust_days.gp, box.gp and, with run_gnuplot, their SVGs) and
/// dir/report.html for a `simulate` run from `year` (year.json's content),
/// cycles.csv and the SVG files in `dir`. @throws std::runtime_error if it
/// cannot write.
YearReport WriteYearReport(const std::string& dir, const Scenario& scenario,
                           const nlohmann::json& year, bool run_gnuplot);

// The pieces of a report page, for the commands that write their own
// (the transfer report, app/transfer_report.h).

/// The page's head (title, the style sheet) and the opening <body>.
std::string PageStart(const std::string& title);
/// <tr><th>key</th><td>value</td></tr> (a row of a "facts" table), the value already HTML.
std::string Row(const std::string& key, const std::string& value_html);

struct Figure {
  std::string file;  // an SVG file in the run folder
  std::string caption;
};
/// The figures present in `dir`, inlined with their captions (element ids
/// made unique per page); a note when none is present.
std::string Figures(const std::string& dir, const std::vector<Figure>& figures);

/// `text` with &, <, >, " and ' escaped for HTML.
std::string HtmlEscape(const std::string& text);

/// An SVG file's text ready to inline in HTML: the XML prolog and any
/// DOCTYPE removed, and gnuplot's fixed size replaced by a scalable one
/// (width 100 %, height from the viewBox). "" if the file holds no <svg>.
std::string InlineSvg(const std::string& svg_text);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_HTML_REPORT_H_
