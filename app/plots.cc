#include "app/plots.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/outputs.h"
#include "common/constants.h"
#include "common/error.h"
#include "common/format.h"

namespace thrustsched::app {

using common::FormatG;

namespace {

// Numbers in gnuplot scripts: 10 significant digits.
std::string G(double v) { return FormatG(v, 10); }

// 1-based gnuplot column of `name` in trajectory.csv.
int Col(const std::vector<std::string>& cols, const std::string& name) {
  auto it = std::find(cols.begin(), cols.end(), name);
  if (it == cols.end()) throw std::logic_error("plots: no trajectory column " + name);
  return static_cast<int>(it - cols.begin()) + 1;
}

// Escapes a string for a gnuplot double-quoted literal.
std::string Quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '@' || c == '^' || c == '_' || c == '{' || c == '}' || c == '&') out += "\\\\";
    out += c;
  }
  return out + "\"";
}

struct TimeAxis {
  double divisor;
  std::string label;
};

TimeAxis ChooseTimeAxis(double duration_s) {
  if (duration_s >= 2 * common::kSecondsPerDay)
    return {common::kSecondsPerDay, "time since t_0 (days)"};
  if (duration_s >= 2 * 3600.0) return {3600.0, "time since t_0 (h)"};
  return {1.0, "time since t_0 (s)"};
}

const char* const kColors =
    "#1f77b4 #ff7f0e #2ca02c #d62728 #9467bd #8c564b #e377c2 #7f7f7f #bcbd22 #17becf";

// The thrusters that fire in the result (first column of schedule.csv or
// impulses.csv in `dir`), as indices into the scenario's thrusters, so that
// the legend names only thrusters that fired.
std::vector<int> FiredThrusters(const std::string& dir, const Scenario& s) {
  std::ifstream in(dir + (s.impulsive() ? "/impulses.csv" : "/schedule.csv"));
  const std::vector<std::string> names = s.thruster_names();
  std::vector<bool> fired(names.size(), false);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const std::string name = line.substr(0, line.find(','));
    auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end()) fired[static_cast<size_t>(it - names.begin())] = true;
  }
  std::vector<int> out;
  for (size_t i = 0; i < fired.size(); ++i) {
    if (fired[i]) out.push_back(static_cast<int>(i));
  }
  return out;
}

// Rendezvous problems end at a prescribed relative state: the target
// spacecraft sits at the frame origin and the end state is the aim point.
bool IsRendezvous(const Scenario& s) {
  return s.model_type != ModelType::kGeo &&
         (s.problem.terminal.kind == transcription::TerminalKind::kFixedState ||
          s.problem.terminal.kind == transcription::TerminalKind::kStateBox) &&
         s.problem.terminal.target.size() >= 3;
}

// gnuplot commands (before `plot`) that set n_rows to the number of data rows
// of trajectory.csv, for the end-point marker (`every ::n_rows-1::n_rows-1`).
std::string CountRows() {
  return "stats 'trajectory.csv' skip 1 using 1 nooutput\nn_rows = STATS_records\n";
}

// Plot clauses marking the start (filled circle), the end (filled square)
// and the burns (thick segments in the thruster's colour; impulses as
// triangles) of the curve `xy` ("using" columns) of trajectory.csv.
std::string Markers(const Scenario& s, const std::vector<std::string>& cols,
                    const std::vector<int>& fired, const std::string& x, const std::string& y) {
  std::ostringstream os;
  const std::vector<std::string> names = s.thruster_names();
  for (int i : fired) {
    const std::string on = "$" + std::to_string(Col(cols, "on_" + names[static_cast<size_t>(i)]));
    os << ", \\\n     'trajectory.csv' skip 1 using (" << on << " > 0.5 ? " << x << " : NaN):" << y
       << (s.impulsive() ? " with points pt 8 ps 1.6" : " with linespoints lw 4 pt 7 ps 0.9")
       << " lc rgb word(colors, " << i % 10 + 1 << ") title "
       << Quote((s.impulsive() ? "impulse " : "burn ") + names[static_cast<size_t>(i)]);
  }
  os << ", \\\n     'trajectory.csv' skip 1 every ::0::0 using " << x << ":" << y
     << " with points pt 7 ps 1.5 lc rgb 'black' title 'start'";
  os << ", \\\n     'trajectory.csv' skip 1 every ::n_rows-1::n_rows-1 using " << x << ":" << y
     << " with points pt 5 ps 1.5 lc rgb 'black' title 'end'";
  return os.str();
}

// The target spacecraft (origin) and the aim point (the prescribed end
// position) of a rendezvous, in the plane of position components (a, b)
// (0 = x, 1 = y, 2 = z), km: `data` gets the datablock to define before
// `plot`, the result the plot clauses.
std::string TargetMarkers(const Scenario& s, int a, int b, std::string* data) {
  if (!IsRendezvous(s)) return "";
  const Eigen::VectorXd& t = s.problem.terminal.target;
  *data = "$target << EOD\n0,0\nEOD\n";
  std::ostringstream os;
  os << ", \\\n     $target using 1:2 with points pt 3 ps 3 lw 2 lc rgb '#d62728' title 'target'";
  if (std::abs(t(a)) + std::abs(t(b)) > 0) {
    *data += "$aim << EOD\n" + G(t(a) / 1000.0) + "," + G(t(b) / 1000.0) + "\nEOD\n";
    os << ", \\\n     $aim using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb '#2ca02c' title 'aim "
          "point'";
  }
  return os.str();
}

std::string Header(const std::string& image, int width, int height, const Scenario& s) {
  std::ostringstream os;
  os << "# Generated by thrustsched for scenario " << s.name << ".\n"
     << "# Restyle freely, then run: gnuplot " << image.substr(0, image.size() - 4) << ".gp\n"
     << "# (in this directory; the data are the CSV files next to it).\n"
     << "set terminal svg size " << width << "," << height
     << " dynamic enhanced font 'sans,12' background rgb 'white'\n"
     << "set output '" << image << "'\n"
     << "set datafile separator ','\n"
     << "set grid\n";
  return os.str();
}

std::string WindowScript(const Scenario& s, bool nl, const std::vector<int>& fired) {
  const std::vector<std::string> cols = TrajectoryColumns(s, nl);
  std::ostringstream os;
  os << Header("window.svg", 800, 860, s);
  os << "set title " << Quote(s.name + ": trajectory in the window plane") << "\n";
  // Below the plot: inside it, the legend covered a corner of the box.
  // (Three columns at most, with room for them under the x label.)
  os << "set key below horizontal box samplen 2 maxcols 3\nset bmargin 8\n";
  os << "set size ratio -1\n";
  os << "colors = \"" << kColors << "\"\n";
  os << CountRows();
  const double w = s.window_half_widths.empty()
                       ? 0.0
                       : s.window_half_widths[0] / (s.model_type == ModelType::kGeo ? 1.0 : 1000.0);
  std::string x, y;
  if (s.model_type == ModelType::kGeo) {
    os << "set xlabel 'longitude - station longitude (deg)'\n"
       << "set ylabel 'latitude (deg)'\n";
    x = "($" + std::to_string(Col(cols, "lin_dlon_deg")) + ")";
    y = "($" + std::to_string(Col(cols, "lin_lat_deg")) + ")";
  } else {
    os << "set xlabel 'y, along-track (km)'\n"
       << "set ylabel 'z, normal (km)'\n";
    x = "($" + std::to_string(Col(cols, "y_m")) + "/1000)";
    y = "($" + std::to_string(Col(cols, "z_m")) + "/1000)";
  }
  if (w > 0) {
    os << "w = " << G(w) << "\n"
       << "set object 1 rect from -w,-w to w,w fillstyle empty border lc rgb 'red' lw 2\n"
       << "# show at least the box (plus 15 %), more if the trajectory leaves it\n"
       << "set xrange [*<-1.15*w:1.15*w<*]\nset yrange [*<-1.15*w:1.15*w<*]\n";
  }
  std::string target_data;
  const std::string target =
      s.model_type != ModelType::kGeo ? TargetMarkers(s, 1, 2, &target_data) : "";
  os << target_data;
  os << "plot 'trajectory.csv' skip 1 using " << x << ":" << y
     << " with lines lw 1.5 lc rgb '#1f77b4' title "
     << (s.model_type == ModelType::kGeo ? "'linear model'" : "'trajectory'");
  if (nl) {
    os << ", \\\n     'trajectory.csv' skip 1 using " << Col(cols, "dlon_deg") << ":"
       << Col(cols, "lat_deg") << " with lines lw 1 lc rgb '#ff7f0e' title 'nonlinear replay'";
  }
  os << target << Markers(s, cols, fired, x, y);
  if (w > 0) os << ", \\\n     NaN with lines lc rgb 'red' lw 2 title 'window'";
  os << "\n";
  return os.str();
}

// Radial against along-track (the rendezvous view: y to the right, x up,
// the target at the origin), Cartesian models with x and y positions.
std::string XyScript(const Scenario& s, const std::vector<int>& fired) {
  const std::vector<std::string> cols = TrajectoryColumns(s, false);
  std::ostringstream os;
  os << Header("xy.svg", 800, 860, s);
  os << "set title " << Quote(s.name + ": radial against along-track") << "\n";
  // Below the plot, with room for the x label (without a fixed aspect ratio
  // gnuplot lets the two overlap).
  os << "set key below horizontal box samplen 2 maxcols 3\nset bmargin 8\n";
  os << "colors = \"" << kColors << "\"\n";
  os << CountRows();
  os << "set xlabel 'y, along-track (km)'\nset ylabel 'x, radial (km)'\n";
  const std::string x = "($" + std::to_string(Col(cols, "y_m")) + "/1000)";
  const std::string y = "($" + std::to_string(Col(cols, "x_m")) + "/1000)";
  // 5 % margins so that markers on the extremes are not cut by the frame.
  os << "set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n";
  const bool window_on_y =
      s.problem.window.enabled() && !s.window_half_widths.empty() &&
      std::find(s.problem.window.outputs.begin(), s.problem.window.outputs.end(), 1) !=
          s.problem.window.outputs.end();
  if (window_on_y) {
    const auto& outs = s.problem.window.outputs;
    const size_t k = static_cast<size_t>(std::find(outs.begin(), outs.end(), 1) - outs.begin());
    os << "w = " << G(s.window_half_widths[k] / 1000.0) << "\n"
       << "set arrow 1 from -w, graph 0 to -w, graph 1 nohead dt 2 lc rgb 'red'\n"
       << "set arrow 2 from w, graph 0 to w, graph 1 nohead dt 2 lc rgb 'red'\n"
       << "set xrange [*<-1.15*w:1.15*w<*]\n";
  }
  std::string target_data;
  const std::string target = TargetMarkers(s, 1, 0, &target_data);
  os << target_data;
  os << "plot 'trajectory.csv' skip 1 using " << x << ":" << y
     << " with lines lw 1.5 lc rgb '#1f77b4' title 'trajectory'";
  os << target << Markers(s, cols, fired, x, y);
  if (window_on_y) os << ", \\\n     NaN with lines lc rgb 'red' dt 2 title 'window (y)'";
  os << "\n";
  return os.str();
}

std::string TimelineScript(const Scenario& s) {
  const std::vector<std::string> names = s.thruster_names();
  const int m = static_cast<int>(names.size());
  const double t0 = s.problem.grid.front();
  const double tf = s.problem.grid.back();
  const TimeAxis ax = ChooseTimeAxis(tf - t0);
  std::ostringstream os;
  os << Header("timeline.svg", 1000, 180 + 45 * m, s);
  os << "t0 = " << G(t0) << "\nunit = " << G(ax.divisor) << "\n";
  os << "colors = \"" << kColors << "\"\n";
  os << "color(i) = word(colors, (i - 1) % 10 + 1)\n";
  os << "names = \"";
  for (int i = 0; i < m; ++i) os << (i ? " " : "") << names[i];
  os << "\"\n";
  os << "set xlabel " << Quote(ax.label) << "\n";
  os << "set xrange [0:" << FormatG((tf - t0) / ax.divisor, 10) << "]\n";
  os << "set key off\n";
  if (s.impulsive()) {
    os << "set title " << Quote(s.name + ": impulses (delta-v per thruster)") << "\n"
       << "set ylabel 'delta-v (m/s)'\n"
       << "set key top right\n"
       << "set yrange [0:*]\n"
       << "plot for [i=1:" << m << "] 'impulses.csv' skip 1 using (($3-t0)/unit):"
       << "(strcol(1) eq word(names,i) ? $4 : NaN) with impulses lw 3 lc rgb color(i) title "
          "word(names,i), \\\n"
       << "     NaN notitle\n";
  } else {
    os << "set title " << Quote(s.name + ": firing timeline") << "\n"
       << "set yrange [0.4:" << m << ".6]\n"
       << "set ytics (";
    const auto& thr = s.problem.thrusters.thrusters();
    bool any_disabled = false;
    for (int i = 0; i < m; ++i) {
      const bool off = !thr[static_cast<size_t>(i)].enabled;
      any_disabled = any_disabled || off;
      os << (i ? ", " : "") << Quote(names[i] + (off ? " (disabled)" : "")) << " " << i + 1;
    }
    os << ")\n"
       << "set grid noytics\n";
    // Where a thruster may not fire: hatched rows for disabled thrusters,
    // grey bands for the forced-off windows (clipped to the horizon).
    int object = 10;
    for (int i = 0; i < m; ++i) {
      if (thr[static_cast<size_t>(i)].enabled) continue;
      os << "set object " << object++ << " rect from 0," << i + 1 << "-0.4 to "
         << G((tf - t0) / ax.divisor) << "," << i + 1
         << "+0.4 behind fillcolor rgb '#7f7f7f' fillstyle pattern 4 noborder\n";
    }
    bool any_forced = false;
    for (const transcription::ForcedOff& f : s.problem.forced_off) {
      const double a = std::max(f.start_s, t0), b = std::min(f.end_s, tf);
      if (!(b > a) || f.thruster < 0 || f.thruster >= m) continue;
      any_forced = true;
      os << "set object " << object++ << " rect from " << G((a - t0) / ax.divisor) << ","
         << f.thruster + 1 << "-0.4 to " << G((b - t0) / ax.divisor) << "," << f.thruster + 1
         << "+0.4 behind fillcolor rgb '#cccccc' fillstyle solid 1.0 noborder\n";
    }
    if (any_disabled || any_forced) os << "set key below horizontal\n";
    os << "# one thick horizontal bar per burn: start -> end, at the thruster's row\n"
       << "plot for [i=1:" << m << "] 'schedule.csv' skip 1 using (($2-t0)/unit):"
       << "(strcol(1) eq word(names,i) ? i : NaN):($4/unit):(0) "
       << "with vectors nohead lw 12 lc rgb color(i) notitle";
    if (any_forced) {
      os << ", \\\n     NaN with boxes fillstyle solid 1.0 noborder fillcolor rgb '#cccccc' "
            "title 'forced off'";
    }
    if (any_disabled) {
      os << ", \\\n     NaN with boxes fillstyle pattern 4 noborder fillcolor rgb '#7f7f7f' "
            "title 'disabled'";
    }
    os << ", \\\n     NaN notitle\n";
  }
  return os.str();
}

std::string OutputsScript(const Scenario& s, bool nl) {
  const std::vector<std::string> cols = TrajectoryColumns(s, nl);
  const double t0 = s.problem.grid.front();
  const TimeAxis ax = ChooseTimeAxis(s.problem.grid.back() - t0);
  std::ostringstream os;
  os << Header("outputs.svg", 1000, 900, s);
  os << "t0 = " << G(t0) << "\nunit = " << G(ax.divisor) << "\n";
  // Outside the panels: inside, the legend text crossed the window lines.
  os << "set key outside right top\n";
  os << "set multiplot layout 3,1 title " << Quote(s.name + ": outputs against time") << "\n";
  const std::string x = "(($1-t0)/unit)";
  struct Panel {
    std::string label;
    std::string lin;   // using expression for the linear value
    std::string nonl;  // nonlinear value ("" if none)
    double bound;      // window half width in the panel unit, 0 if none
  };
  std::vector<Panel> panels;
  const double w = s.window_half_widths.empty() ? 0.0 : s.window_half_widths[0];
  if (s.model_type == ModelType::kGeo) {
    const std::string c_lat = "($" + std::to_string(Col(cols, "lin_lat_deg")) + ")";
    const std::string c_lon = "($" + std::to_string(Col(cols, "lin_dlon_deg")) + ")";
    const std::string c_dr = "($" + std::to_string(Col(cols, "dr_m")) + "/1000)";
    panels.push_back(
        {"latitude (deg)", c_lat, nl ? "($" + std::to_string(Col(cols, "lat_deg")) + ")" : "", w});
    panels.push_back({"longitude - station (deg)", c_lon,
                      nl ? "($" + std::to_string(Col(cols, "dlon_deg")) + ")" : "", w});
    panels.push_back({"r - a_mp (km)", c_dr,
                      nl ? "($" + std::to_string(Col(cols, "dr_nl_m")) + "/1000)" : "", 0.0});
  } else {
    const bool km = s.model_type != ModelType::kDoubleIntegrator;
    const std::string div = km ? "/1000" : "";
    const std::string unit = km ? "km" : "m";
    const double b = km ? w / 1000.0 : w;
    panels.push_back(
        {"x, radial (" + unit + ")", "($" + std::to_string(Col(cols, "x_m")) + div + ")", "", 0.0});
    panels.push_back({"y, along-track (" + unit + ")",
                      "($" + std::to_string(Col(cols, "y_m")) + div + ")", "", b});
    panels.push_back(
        {"z, normal (" + unit + ")", "($" + std::to_string(Col(cols, "z_m")) + div + ")", "", b});
  }
  for (size_t k = 0; k < panels.size(); ++k) {
    const Panel& p = panels[k];
    os << "set ylabel " << Quote(p.label) << "\n";
    const bool bounded = p.bound > 0 && s.problem.window.enabled();
    if (bounded) {
      // 15 % beyond the window, so that its dashed lines are not drawn on the frame.
      os << "b = " << G(p.bound) << "\nset yrange [*<-1.15*b:1.15*b<*]\n";
    } else {
      os << "set autoscale y\n";
    }
    os << "set xlabel " << (k + 1 == panels.size() ? Quote(ax.label) : "''") << "\n";
    os << "plot 'trajectory.csv' skip 1 using " << x << ":" << p.lin
       << " with lines lw 1.5 lc rgb '#1f77b4' title "
       << (s.model_type == ModelType::kGeo ? "'linear model'" : "'trajectory'");
    if (!p.nonl.empty()) {
      os << ", \\\n     'trajectory.csv' skip 1 using " << x << ":" << p.nonl
         << " with lines lw 1 lc rgb '#ff7f0e' title 'nonlinear replay'";
    }
    if (bounded) {
      os << ", \\\n     " << G(p.bound) << " with lines lc rgb 'red' dt 2 title 'window', \\\n     "
         << G(-p.bound) << " with lines lc rgb 'red' dt 2 notitle";
    }
    os << "\n";
  }
  os << "unset multiplot\n";
  return os.str();
}

// Runs `program script` in `dir`, output appended to dir/gnuplot.log.
// Returns the exit status, 127 if the program could not be started, -1 on a signal.
int Run(const std::string& dir, const std::string& program, const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(126);
    const int fd = open("gnuplot.log", O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
      close(fd);
    }
    const int null_in = open("/dev/null", O_RDONLY);
    if (null_in >= 0) dup2(null_in, 0);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execvp(program.c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return -1;
}

}  // namespace

bool RunGnuplot(const std::string& dir, const std::string& script, const std::string& program) {
  return Run(dir, program, {script}) == 0;
}

std::vector<std::string> RunGnuplotScripts(const std::string& dir,
                                           const std::vector<std::string>& bases,
                                           std::string* message, const std::string& program) {
  std::vector<std::string> images;
  std::string failed;
  for (const std::string& base : bases) {
    if (Run(dir, program, {base + ".gp"}) == 0) {
      images.push_back(base + ".svg");
    } else {
      failed += (failed.empty() ? "" : ", ") + base + ".gp";
    }
  }
  *message = failed.empty() ? "" : "gnuplot failed on " + failed + " (see " + dir + "/gnuplot.log)";
  return images;
}

bool HasXyView(const Scenario& s) {
  if (s.model_type == ModelType::kGeo) return false;
  const std::vector<std::string> names = s.problem.model->state_names();
  return std::find(names.begin(), names.end(), "x_m") != names.end() &&
         std::find(names.begin(), names.end(), "y_m") != names.end();
}

bool GnuplotAvailable(const std::string& program) {
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    const int null_fd = open("/dev/null", O_RDWR);
    if (null_fd >= 0) {
      dup2(null_fd, 0);
      dup2(null_fd, 1);
      dup2(null_fd, 2);
    }
    execlp(program.c_str(), program.c_str(), "--version", static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return false;
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

bool PlotOptions::IsValid(std::string* error) const {
  if (run_gnuplot && gnuplot.empty()) {
    return common::Fail(error, "gnuplot must name a program when run_gnuplot is set, got \"\"");
  }
  return true;
}

PlotResult WritePlots(const std::string& dir, const Scenario& s, bool has_nonlinear,
                      const PlotOptions& options) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument("PlotOptions: " + err);
  PlotResult r;
  const bool nl = has_nonlinear && s.model_type == ModelType::kGeo;
  const std::vector<int> fired = FiredThrusters(dir, s);
  std::vector<std::pair<std::string, std::string>> scripts = {
      {"window", WindowScript(s, nl, fired)},
      {"timeline", TimelineScript(s)},
      {"outputs", OutputsScript(s, nl)},
  };
  if (HasXyView(s)) scripts.emplace_back("xy", XyScript(s, fired));
  for (const auto& [base, text] : scripts) {
    WriteTextFile(dir + "/" + base + ".gp", text);
    r.scripts.push_back(base + ".gp");
  }
  if (!options.run_gnuplot) {
    r.message = "plots skipped (--no-plots); the gnuplot scripts are in " + dir;
    return r;
  }
  r.gnuplot_found = GnuplotAvailable(options.gnuplot);
  if (!r.gnuplot_found) {
    r.message = "gnuplot not found: plots skipped; run the .gp scripts in " + dir +
                " once gnuplot is installed";
    return r;
  }
  std::vector<std::string> bases;
  for (const auto& script : scripts) bases.push_back(script.first);
  r.images = RunGnuplotScripts(dir, bases, &r.message, options.gnuplot);
  r.ok = r.message.empty();
  return r;
}

}  // namespace thrustsched::app
