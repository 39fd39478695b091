// The plots as a reader sees them: each plot is rendered by gnuplot and its
// SVG is read back (plot frames, legend positions, the curves by their
// legend titles) to check what the reader must be able to see: window lines
// inside the frame, legends clear of the box and the window lines, start,
// end and burn markers, disabled thrusters and forced-off windows on the
// timeline, the rendezvous view with the target.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/format_units.h"
#include "app/html_report.h"
#include "app/outputs.h"
#include "app/plots.h"
#include "app/scenario.h"
#include "tests/app/cli_runner.h"
#include "tests/app/test_messages.h"

namespace thrustsched::app {
namespace {

using testing::ReadFile;
using testing::TempDir;

struct Rect {
  double left, top, right, bottom;  // SVG pixels, y downwards
};

// Points of an SVG path's data ("M x,y L x,y ..."), each with its command
// letter ('M' or 'L'); parsed by hand (std::regex recurses per character and
// overflows the stack on a week's path).
struct PathPoint {
  char command;
  double x, y;
};
std::vector<PathPoint> PathPoints(const std::string& data) {
  std::vector<PathPoint> out;
  std::istringstream in(data);
  std::string token;
  while (in >> token) {
    if (token.size() < 4 || (token[0] != 'M' && token[0] != 'L')) continue;
    double x = 0, y = 0;
    if (std::sscanf(token.c_str() + 1, "%lf,%lf", &x, &y) == 2) out.push_back({token[0], x, y});
  }
  return out;
}

// The plot frames (gnuplot's border: a closed axis-aligned rectangle path
// drawn in black), one per panel, in drawing order.
std::vector<Rect> Frames(const std::string& svg) {
  std::vector<Rect> out;
  const std::string open = "<path stroke='black'  d='";
  for (size_t at = svg.find(open); at != std::string::npos; at = svg.find(open, at + 1)) {
    const size_t start = at + open.size();
    const size_t end = svg.find('\'', start);
    const std::string data = svg.substr(start, end - start);
    if (data.find('Z') == std::string::npos) continue;
    const std::vector<PathPoint> p = PathPoints(data);
    if (p.size() != 5 || p[0].command != 'M') continue;
    const bool rect = p[0].x == p[1].x && p[1].y == p[2].y && p[2].x == p[3].x &&
                      p[3].y == p[0].y && p[4].x == p[0].x && p[4].y == p[0].y;
    if (!rect) continue;
    const Rect r{std::min(p[0].x, p[2].x), std::min(p[0].y, p[1].y), std::max(p[0].x, p[2].x),
                 std::max(p[0].y, p[1].y)};
    const bool seen = std::any_of(out.begin(), out.end(), [&](const Rect& o) {
      return std::abs(o.left - r.left) < 0.01 && std::abs(o.top - r.top) < 0.01 &&
             std::abs(o.bottom - r.bottom) < 0.01 && std::abs(o.right - r.right) < 0.01;
    });
    if (!seen) out.push_back(r);
  }
  return out;
}

// The SVG groups of the curves titled `title` (gnuplot: <g id="gnuplot_plot_N"><title>...).
std::vector<std::string> Curves(const std::string& svg, const std::string& title) {
  std::vector<std::string> out;
  const std::string open = "<title>" + title + "</title>";
  for (size_t at = svg.find(open); at != std::string::npos; at = svg.find(open, at + 1)) {
    const size_t end = svg.find("<g id=\"gnuplot_plot_", at + open.size());
    out.push_back(svg.substr(at, end == std::string::npos ? std::string::npos : end - at));
  }
  return out;
}

// The first translate(x,y) in `text` at or after `from`.
std::pair<double, double> Translate(const std::string& text, size_t from = 0) {
  const size_t at = text.find("translate(", from);
  double x = -1, y = -1;
  if (at != std::string::npos) std::sscanf(text.c_str() + at + 10, "%lf,%lf", &x, &y);
  return {x, y};
}

// The position of a curve's legend text.
std::pair<double, double> KeyPosition(const std::string& curve) { return Translate(curve); }

// The y pixels of a dashed curve's data (after its legend sample, the first M-segment).
std::vector<double> DashedYs(const std::string& curve) {
  std::vector<double> ys;
  const size_t d = curve.find("stroke-dasharray");
  if (d == std::string::npos) return ys;
  const size_t path = curve.find("d='", d);
  const std::string data = curve.substr(path + 3, curve.find('\'', path + 3) - path - 3);
  int moves = 0;
  for (const PathPoint& p : PathPoints(data)) {
    if (p.command == 'M') ++moves;
    if (moves >= 2) ys.push_back(p.y);
  }
  return ys;
}

bool Inside(const Rect& r, double x, double y) {
  return x > r.left && x < r.right && y > r.top && y < r.bottom;
}

Scenario Hcw(const std::string& extra, double half_width_m = 10000) {
  return ParseScenarioText(R"({
    "name": "hcw_plots",
    "model": {"type": "hcw", "mean_motion_rad_s": 7.2921159e-5},
    "spacecraft": {"mass_kg": 4850, "isp_s": 2005, "thrust_n": 0.265, "thrusters": {"preset": "ideal6"})" +
                           extra + R"(},
    "initial_state": {"hcw_position_m": [1000, 0, 0]},
    "horizon": {"duration_s": 7200, "step_s": 300},
    "window": {"half_width_m": )" +
                           std::to_string(half_width_m) + R"(},
    "operations": {"min_burn_s": 300, "min_off_same_s": 1200, "min_gap_other_s": 300}
  })");
}

// Writes the CSV files of `burns` on `s` into a fresh folder and the plots.
std::string Render(const Scenario& s, const std::vector<transcription::Burn>& burns,
                   const std::string& name) {
  const std::string dir = TempDir(name);
  const transcription::CheckReport r = transcription::CheckSchedule(s.problem, burns, s.check);
  WriteTrajectoryCsv(dir + "/trajectory.csv", s, r, burns);
  WriteScheduleCsv(dir + "/schedule.csv", s, burns);
  const PlotResult p = WritePlots(dir, s, r.nonlinear_checked);
  EXPECT_TRUE(p.ok) << p.message << ReadFile(dir + "/gnuplot.log");
  return dir;
}

class PlotsRendered : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!GnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed (Debian gnuplot-nox)";
  }
};

// HCW and Yamanaka-Ankersen outputs.svg: the window +-w was the axis range,
// so its dashed lines were drawn on the frame (a 10 km window with a
// trajectory well inside it autoscaled to exactly +-10 km).
TEST_F(PlotsRendered, OutputsWindowLinesLieInsideThePanels) {
  const std::string dir = Render(Hcw(""), {{1, 300, 600}}, "plots_outputs");
  const std::string svg = ReadFile(dir + "/outputs.svg");
  const std::vector<Rect> frames = Frames(svg);
  ASSERT_EQ(frames.size(), 3u) << svg.substr(0, 2000);
  const std::vector<std::string> windows = Curves(svg, "window");
  ASSERT_EQ(windows.size(), 2u);  // y and z panels (x has no window)
  for (size_t k = 0; k < windows.size(); ++k) {
    const Rect& f = frames[k + 1];
    const std::vector<double> ys = DashedYs(windows[k]);
    ASSERT_FALSE(ys.empty());
    for (double y : ys) {
      EXPECT_GT(y, f.top + 3) << "panel " << k + 1 << ": window line on the top frame";
      EXPECT_LT(y, f.bottom - 3) << "panel " << k + 1 << ": window line on the bottom frame";
    }
    // The legend is outside the panel (right of it), clear of the lines.
    const auto [kx, ky] = KeyPosition(windows[k]);
    EXPECT_FALSE(Inside(f, kx, ky)) << "legend inside panel " << k + 1;
  }
  std::filesystem::remove_all(dir);
}

// GEO window.svg: the legend covered a corner of the box; outputs.svg: its
// text crossed the 0.05 deg line. Both legends now sit outside the frames.
TEST_F(PlotsRendered, GeoLegendsStayClearOfTheBoxAndTheWindowLines) {
  const Scenario s = LoadScenario(std::string(THRUSTSCHED_APP_TEST_DATA) + "/geo_day_small.json");
  const std::string dir = Render(s, {{0, 3000, 3600}}, "plots_geo");
  const std::string window = ReadFile(dir + "/window.svg");
  // The plot's frame is the largest rectangle (the legend's box is another).
  std::vector<Rect> wf = Frames(window);
  ASSERT_FALSE(wf.empty());
  const Rect frame = *std::max_element(wf.begin(), wf.end(), [](const Rect& a, const Rect& b) {
    return (a.right - a.left) * (a.bottom - a.top) < (b.right - b.left) * (b.bottom - b.top);
  });
  for (const char* title :
       {"linear model", "nonlinear replay", "start", "end", "burn NE", "window"}) {
    const std::vector<std::string> c = Curves(window, title);
    ASSERT_FALSE(c.empty()) << title;
    const auto [x, y] = KeyPosition(c[0]);
    EXPECT_GT(y, frame.bottom) << title << ": legend not below the plot";
  }
  const std::string outputs = ReadFile(dir + "/outputs.svg");
  const std::vector<Rect> of = Frames(outputs);
  ASSERT_EQ(of.size(), 3u);
  const std::vector<std::string> lines = Curves(outputs, "window");
  ASSERT_EQ(lines.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    const auto [x, y] = KeyPosition(lines[k]);
    EXPECT_GT(x, of[k].right) << "legend of panel " << k + 1 << " inside it";
    for (double py : DashedYs(lines[k])) {
      EXPECT_GT(py, of[k].top + 3);
      EXPECT_LT(py, of[k].bottom - 3);
    }
  }
  std::filesystem::remove_all(dir);
}

// The trajectory shows where it starts and ends and where the thrusters fired.
TEST_F(PlotsRendered, TrajectoryMarksStartEndAndBurns) {
  const std::string dir = Render(Hcw(""), {{1, 300, 900}, {4, 3600, 3900}}, "plots_markers");
  const std::string svg = ReadFile(dir + "/window.svg");
  for (const char* title : {"start", "end", "burn +T", "burn -T"}) {
    const std::vector<std::string> c = Curves(svg, title);
    ASSERT_EQ(c.size(), 1u) << title;
    EXPECT_HAS(c[0], "<use") << title << ": no marker drawn";
  }
  EXPECT_TRUE(Curves(svg, "burn +R").empty()) << "thrusters that never fired are not listed";
  // The start and end markers are at different places (end = last sample):
  // the last marker of each curve is its data point (the first, its legend).
  const std::string start = Curves(svg, "start")[0], end = Curves(svg, "end")[0];
  const auto ps = Translate(start, start.rfind("<use"));
  const auto pe = Translate(end, end.rfind("<use"));
  EXPECT_TRUE(ps.first != pe.first || ps.second != pe.second);
  std::filesystem::remove_all(dir);
}

// The timeline shows where a thruster could not fire.
TEST_F(PlotsRendered, TimelineShowsDisabledThrustersAndForcedOffWindows) {
  Scenario s = ParseScenarioText(R"({
    "name": "hcw_timeline",
    "model": {"type": "hcw", "mean_motion_rad_s": 7.2921159e-5},
    "spacecraft": {"mass_kg": 4850, "isp_s": 2005, "thrust_n": 0.265,
                   "thrusters": {"preset": "ideal6"}, "disabled": ["-N"]},
    "initial_state": {"hcw_position_m": [1000, 0, 0]},
    "horizon": {"duration_s": 7200, "step_s": 300},
    "window": {"half_width_m": 36800},
    "operations": {"min_burn_s": 300, "min_off_same_s": 1200, "min_gap_other_s": 300},
    "forced_off": [{"thruster": "+T", "start_s": 1800, "end_s": 3600}]
  })");
  const std::string dir = Render(s, {{1, 300, 600}}, "plots_timeline");
  const std::string gp = ReadFile(dir + "/timeline.gp");
  EXPECT_HAS(gp, "\"-N (disabled)\" 6");
  EXPECT_HAS(gp, "rect from 0.5,2-0.4 to 1,2+0.4");  // +T, 1800-3600 s in hours
  const std::string svg = ReadFile(dir + "/timeline.svg");
  EXPECT_HAS(svg, "-N (disabled)");
  EXPECT_EQ(Curves(svg, "forced off").size(), 1u);
  EXPECT_EQ(Curves(svg, "disabled").size(), 1u);
  EXPECT_HAS(svg, "rgb(204, 204, 204)");  // the forced-off band
  std::filesystem::remove_all(dir);
}

// Rendezvous: the radial/along-track view exists and both views draw the
// target (origin) and the aim point (the prescribed end position).
TEST_F(PlotsRendered, RendezvousHasTheXyViewWithTheTarget) {
  Scenario s = ParseScenarioText(R"({
    "name": "hcw_rendezvous",
    "model": {"type": "hcw", "mean_motion_rad_s": 7.2921159e-5},
    "spacecraft": {"mass_kg": 4850, "isp_s": 2005, "thrust_n": 0.265, "thrusters": {"preset": "ideal6"}},
    "initial_state": {"hcw_position_m": [500, -3000, 0]},
    "horizon": {"duration_s": 7200, "step_s": 300},
    "terminal": {"type": "fixed_state", "hcw_position_m": [0, -100, 0]},
    "operations": {"min_burn_s": 300, "min_off_same_s": 1200, "min_gap_other_s": 300}
  })");
  ASSERT_TRUE(HasXyView(s));
  const std::string dir = Render(s, {{1, 300, 900}}, "plots_rendezvous");
  const std::string xy = ReadFile(dir + "/xy.svg");
  for (const char* title : {"trajectory", "target", "aim point", "start", "end", "burn +T"}) {
    EXPECT_EQ(Curves(xy, title).size(), 1u) << title;
  }
  EXPECT_HAS(xy, "x, radial (km)");
  EXPECT_EQ(Curves(ReadFile(dir + "/window.svg"), "target").size(), 1u);
  // Station keeping has the x-y view too, without a target.
  const std::string sk = Render(Hcw(""), {}, "plots_xy_sk");
  EXPECT_TRUE(std::filesystem::exists(sk + "/xy.svg"));
  EXPECT_TRUE(Curves(ReadFile(sk + "/xy.svg"), "target").empty());
  std::filesystem::remove_all(dir);
  std::filesystem::remove_all(sk);
}

TEST(FormatUnits, GapsAndDurationsInHumanUnits) {
  EXPECT_EQ(FormatPercent(1.5e-16), "0 %");
  EXPECT_EQ(FormatPercent(-3e-12), "0 %");
  EXPECT_EQ(FormatPercent(0.0123), "1.23 %");
  EXPECT_EQ(FormatPercent(std::nan("")), "n/a");
  EXPECT_EQ(FormatDuration(3.743e5), "104 h");
  EXPECT_EQ(FormatDuration(0), "0 s");
  EXPECT_EQ(FormatDuration(42), "42 s");
  EXPECT_EQ(FormatDuration(1500), "25 min");
  EXPECT_EQ(FormatDuration(86400 * 53.0), "53 d");
}

TEST(HtmlReport, InlinedSvgHasNoPrologAndAScalableSize) {
  const std::string svg = InlineSvg(
      "<?xml version=\"1.0\" encoding=\"utf-8\"  standalone=\"no\"?>\n<svg \n viewBox=\"0 0 800 "
      "600\"\n xmlns=\"http://www.w3.org/2000/svg\"><script>alert(1)</script><g/></svg>\n");
  EXPECT_EQ(svg.find("<?xml"), std::string::npos);
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_EQ(svg.rfind("<svg width=\"800\" height=\"600\"", 0), 0u) << svg;
  EXPECT_EQ(HtmlEscape("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
}

TEST(PlotOptionsIsValid, RunningGnuplotNeedsAProgramName) {
  PlotOptions o;
  std::string e;
  EXPECT_TRUE(o.IsValid(&e));
  o.gnuplot.clear();
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "gnuplot must name a program when run_gnuplot is set, got \"\"");
  o.run_gnuplot = false;  // the scripts only: no program needed
  EXPECT_TRUE(o.IsValid(&e));
}

}  // namespace
}  // namespace thrustsched::app
