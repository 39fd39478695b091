#include "app/simulate.h"

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>

#include "app/commands.h"
#include "app/interrupt.h"
#include "app/outputs.h"
#include "app/plots.h"
#include "app/format_units.h"
#include "app/html_report.h"
#include "app/run_folder.h"
#include "dynamics/time.h"
#include "milp/cbc_solver.h"

namespace thrustsched::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using transcription::CycleRecord;
using transcription::Fallback;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;
constexpr const char* kCheckpointFormat = "thrustsched-year-checkpoint-1";

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string G(double v, int digits = 12) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[48];
  std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
  return buf;
}

nlohmann::json Num(double v) {
  if (!std::isfinite(v)) return nullptr;
  return v;
}

std::string Hms(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--:--";
  const long s = std::lround(seconds);
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}

std::string CycleTag(int index) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "cycle_%03d", index + 1);
  return buf;
}

std::string Utc(const std::string& epoch, double t) {
  try {
    return dynamics::Epoch::Parse(epoch).PlusSeconds(t).ToIso8601();
  } catch (const std::exception&) {
    return "";
  }
}

// 64-bit FNV-1a of a text, as 16 hex digits (stable across builds).
std::string Fingerprint(const std::string& text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  char buf[24];
  std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::string CsvQuote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}


void MakeDirectory(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw ScenarioError(dir + ": cannot create the output directory (" + ec.message() + ")");
  }
}

// Writes through a temporary file and a rename, so a reader (or a resume
// after a crash) never sees half a file.
void WriteAtomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  WriteTextFile(tmp, text);
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw std::runtime_error(path + ": cannot replace the file (" + ec.message() + ")");
}

// ---- Crash guard.
// A cycle's solve runs inside CBC; a defect there can kill the process
// (CoinUtils 2.11 was seen to SIGSEGV in the postsolve of CBC's preprocessing
// on a six-thruster week), which no exception handler can catch. Before each
// cycle, `in_progress.json` names it; a normal end of the cycle (recorded,
// interrupted or failed with an exception) removes the file. A file that
// survives means the process died inside that cycle: `--resume` then solves
// the cycle with CBC's preprocessing and presolve off (the configuration that
// avoided the crash), and the cycle's note says so. A second death in the same
// cycle stops with an error instead of looping.
constexpr const char* kInProgressFile = "in_progress.json";

struct InProgress {
  int cycle = 0;          // 1-based
  bool safe = false;      // that attempt already ran without preprocessing
};

std::optional<InProgress> ReadInProgress(const std::string& path, const std::string& fingerprint) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object() || j.value("fingerprint", "") != fingerprint ||
      !j.contains("cycle") || !j.at("cycle").is_number_integer()) {
    return std::nullopt;  // not ours or unreadable: ignore, it is rewritten below
  }
  InProgress p;
  p.cycle = j.at("cycle").get<int>();
  p.safe = j.value("solver_preprocessing_off", false);
  return p;
}

// Removes the in-progress file when the cycle ends in any way the process
// survives (the destructor does not run when the process is killed).
class InProgressGuard {
 public:
  InProgressGuard(std::string path, const std::string& fingerprint, int cycle, bool safe)
      : path_(std::move(path)) {
    nlohmann::json j;
    j["cycle"] = cycle;
    j["fingerprint"] = fingerprint;
    j["solver_preprocessing_off"] = safe;
    j["meaning"] = "this cycle was running; if the process is gone it died inside the cycle";
    WriteAtomically(path_, j.dump(1) + "\n");
  }
  ~InProgressGuard() {
    std::error_code ec;
    fs::remove(path_, ec);
  }
  InProgressGuard(const InProgressGuard&) = delete;
  InProgressGuard& operator=(const InProgressGuard&) = delete;

 private:
  std::string path_;
};

milp::SolveStatus ParseStatus(const std::string& name, const std::string& path) {
  for (milp::SolveStatus s :
       {milp::SolveStatus::kOptimal, milp::SolveStatus::kFeasible, milp::SolveStatus::kInfeasible,
        milp::SolveStatus::kUnbounded, milp::SolveStatus::kNoSolutionFound,
        milp::SolveStatus::kError}) {
    if (name == milp::ToString(s)) return s;
  }
  throw ScenarioError(path + ": unknown solver status \"" + name + "\"");
}

// ---------------------------------------------------------------------------
// JSON helpers for the checkpoint (numbers round-trip exactly: nlohmann
// writes the shortest representation that reads back to the same double).

double GetNumber(const nlohmann::json& j, const char* key, const std::string& path) {
  if (!j.contains(key)) throw ScenarioError(path + "." + key + ": missing");
  const nlohmann::json& v = j.at(key);
  if (v.is_null()) return kNaN;
  if (!v.is_number()) throw ScenarioError(path + "." + key + ": expected a number, got " + DescribeJson(v));
  return v.get<double>();
}

std::vector<double> GetNumbers(const nlohmann::json& j, const char* key, const std::string& path,
                               double null_value = kNaN) {
  if (!j.contains(key) || !j.at(key).is_array()) {
    throw ScenarioError(path + "." + key + ": expected an array");
  }
  std::vector<double> out;
  for (const nlohmann::json& v : j.at(key)) {
    if (v.is_null()) {
      out.push_back(null_value);
    } else if (v.is_number()) {
      out.push_back(v.get<double>());
    } else {
      throw ScenarioError(path + "." + key + ": expected numbers, got " + DescribeJson(v));
    }
  }
  return out;
}

nlohmann::json VectorJson(const Eigen::VectorXd& v) {
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < v.size(); ++i) a.push_back(Num(v(i)));
  return a;
}

Eigen::VectorXd ToVector(const std::vector<double>& v) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(v.size()));
  for (size_t i = 0; i < v.size(); ++i) x(static_cast<Eigen::Index>(i)) = v[i];
  return x;
}

dynamics::Vector6d ToVector6(const std::vector<double>& v, const std::string& path) {
  if (v.size() != 6) throw ScenarioError(path + ": expected 6 numbers, got " + std::to_string(v.size()));
  dynamics::Vector6d x;
  for (int i = 0; i < 6; ++i) {
    if (!std::isfinite(v[i])) throw ScenarioError(path + ": non-finite component " + std::to_string(i));
    x(i) = v[i];
  }
  return x;
}

// ---------------------------------------------------------------------------
// Parsing of the long_horizon section.

void ParseLongHorizon(SimulationSetup* setup) {
  Scenario& s = setup->scenario;
  transcription::LongHorizonOptions& o = setup->options;
  JsonObject lh(s.raw.at("long_horizon"), "scenario.long_horizon");
  o.start_s = s.start_s;
  o.step_s = s.step_s;
  o.duration_s = lh.Number("duration_s", Bound::kPositive);
  o.cycle_s = lh.OptionalNumber("cycle_s", Bound::kPositive).value_or(s.step_s * s.num_intervals);
  o.mode = transcription::ParseHorizonMode(
      lh.Has("mode") ? lh.Choice("mode", {"fixed", "receding"}) : std::string("fixed"));
  if (o.mode == transcription::HorizonMode::kReceding) {
    o.control_s = lh.Number("control_s", Bound::kPositive);
  } else if (lh.Has("control_s")) {
    lh.Fail("control_s", "is only used with \"mode\": \"receding\"");
  }
  // End-of-cycle sets: default K = 16 in fixed mode, none in receding mode (thesis 5.4).
  bool sets = o.mode == transcription::HorizonMode::kFixed;
  int facets = 16;
  if (lh.Has("terminal")) {
    JsonObject t = lh.Object("terminal");
    if (t.Has("type")) sets = t.Choice("type", {"station_keeping", "free"}) == "station_keeping";
    else sets = true;
    if (auto k = t.OptionalInteger("facets", 3, 1000)) {
      if (!sets) t.Fail("facets", "is only used with \"type\": \"station_keeping\"");
      facets = *k;
    }
    if (t.Has("lookahead_s")) {
      if (!sets) t.Fail("lookahead_s", "is only used with \"type\": \"station_keeping\"");
      o.terminal.lookahead_s = t.NumberArray("lookahead_s", -1, Bound::kNonNegative);
    }
    if (auto mg = t.OptionalNumber("margin", Bound::kNonNegative)) {
      if (!sets) t.Fail("margin", "is only used with \"type\": \"station_keeping\"");
      if (*mg >= 1.0) t.Fail("margin", "must be in [0, 1), got " + FormatNumber(*mg));
      o.terminal.margin = *mg;
    }
    t.Finish();
  }
  if (sets) {
    o.terminal.kind = transcription::TerminalKind::kStationKeepingSets;
    o.terminal.facets_out_of_plane = o.terminal.facets_cone_plus = o.terminal.facets_cone_minus =
        facets;
    o.terminal_in_receding = o.mode == transcription::HorizonMode::kReceding;
  } else {
    o.terminal = transcription::TerminalSpec{};
  }

  // Solver settings per cycle: the scenario's solver section, with the cycle
  // limits of this section.
  o.solve.build = s.build;
  o.solve.solve = s.solve;
  o.solve.check = s.check;
  o.solve.check.nonlinear.reset();  // the driver replays from the true state
  o.solve.check_schedule = true;
  o.solve.search.enabled = s.search;
  const nlohmann::json* solver = s.raw.contains("solver") ? &s.raw.at("solver") : nullptr;
  const bool solver_time = solver != nullptr && solver->contains("time_limit_s");
  const bool solver_gap = solver != nullptr && solver->contains("relative_gap");
  o.solve.solve.time_limit_s = lh.OptionalNumber("cycle_time_limit_s", Bound::kPositive)
                                   .value_or(solver_time ? s.solve.time_limit_s : 30.0);
  o.solve.solve.relative_gap = lh.OptionalNumber("cycle_relative_gap", Bound::kNonNegative)
                                   .value_or(solver_gap ? s.solve.relative_gap : 0.02);
  if (auto th = lh.OptionalInteger("cycle_threads", 1, 64)) o.solve.solve.threads = *th;
  if (auto nodes = lh.OptionalInteger("cycle_max_nodes", 0, 2000000000)) {
    o.solve.solve.max_nodes = *nodes;
  }
  const std::string lp =
      lh.Has("cycle_lp_algorithm") ? lh.Choice("cycle_lp_algorithm", {"barrier", "primal", "dual"})
                                   : std::string("barrier");
  o.solve.solve.lp_algorithm = lp == "barrier"  ? milp::LpAlgorithm::kBarrier
                               : lp == "primal" ? milp::LpAlgorithm::kPrimal
                                                : milp::LpAlgorithm::kDual;
  o.soft_penalty = lh.OptionalNumber("soft_penalty", Bound::kPositive).value_or(o.soft_penalty);
  o.improve_above_gap = lh.OptionalNumber("cycle_improve_above_gap", Bound::kNonNegative)
                            .value_or(o.improve_above_gap);
  if (auto nodes = lh.OptionalInteger("cycle_improve_max_nodes", 0, 2000000000)) {
    o.improve_max_nodes = *nodes;
  }
  o.retry_without_preprocessing =
      lh.OptionalBool("cycle_retry_without_preprocessing").value_or(o.retry_without_preprocessing);
  o.replay_samples_per_step =
      lh.OptionalInteger("replay_samples_per_step", 1, 1000).value_or(o.replay_samples_per_step);
  setup->trajectory_sample_s =
      lh.OptionalNumber("trajectory_sample_s", Bound::kPositive).value_or(3600.0);
  setup->timeline_cycle = lh.OptionalInteger("timeline_cycle", 1, 100000).value_or(0) - 1;

  // Failures: thrusters switched off from a date on.
  const dynamics::ThrusterSet& thr = s.problem.thrusters;
  std::vector<JsonObject> failures;
  if (lh.Has("failures")) failures = lh.ObjectArray("failures");
  for (size_t k = 0; k < failures.size(); ++k) {
    JsonObject& f = failures[k];
    FailureSpec spec;
    spec.thrusters = f.StringArray("thrusters");
    if (spec.thrusters.empty()) f.Fail("thrusters", "is empty (name at least one thruster)");
    spec.from_s = f.Number("from_s");
    spec.until_s = f.OptionalNumber("until_s").value_or(kInf);
    if (!(spec.until_s > spec.from_s)) {
      f.Fail("until_s", "must be after from_s (" + FormatNumber(spec.from_s) + " s), got " +
                            FormatNumber(spec.until_s) + " s");
    }
    spec.opposite_also_off = f.OptionalBool("opposite_also_off").value_or(false);
    std::vector<int> off;
    for (size_t i = 0; i < spec.thrusters.size(); ++i) {
      const std::string where = f.FieldPath("thrusters") + "[" + std::to_string(i) + "]";
      const int idx = Wrap(where, [&] { return thr.IndexOf(spec.thrusters[i]); });
      off.push_back(idx);
      if (spec.opposite_also_off) {
        off.push_back(Wrap(where, [&] { return transcription::OppositeThruster(thr, idx); }));
      }
    }
    for (int idx : off) {
      bool dup = false;
      for (const std::string& n : spec.switched_off) dup = dup || n == thr.thruster(idx).name;
      if (dup) continue;
      spec.switched_off.push_back(thr.thruster(idx).name);
      o.outages.push_back({idx, spec.from_s, spec.until_s});
    }
    f.Finish();
    setup->failures.push_back(spec);
  }
  lh.Finish();
  std::string err;
  if (!o.IsValid(&err)) throw ScenarioError("scenario." + err);
}

// ---------------------------------------------------------------------------
// Output files.

std::string TrajectoryHeader() {
  return "t_s,day,lat_deg,lon_deg,dr_km,ex,ey,incl_x_deg,incl_y_deg,dl_deg\n";
}

// Replay samples of a cycle at multiples of `spacing` since the run start
// (the cycle's last sample only for the run's last cycle: it is the next
// cycle's first).
std::string TrajectoryRows(const SimulationSetup& setup, const CycleRecord& c, bool last_cycle) {
  std::ostringstream os;
  const double t0 = setup.options.start_s;
  const double spacing = setup.trajectory_sample_s;
  for (size_t k = 0; k < c.sample_times.size(); ++k) {
    const double t = c.sample_times[k];
    if (k + 1 == c.sample_times.size() && !last_cycle) break;
    const double r = (t - t0) / spacing;
    if (std::abs(r - std::round(r)) > 1e-7 && !(last_cycle && k + 1 == c.sample_times.size())) {
      continue;
    }
    const Eigen::Vector3d& y = c.sample_outputs[k];
    const Eigen::VectorXd& x = c.sample_states[k];
    // Inclination vector i (cos W, sin W) in degrees from the half-angle
    // vector tan(i/2) (cos W, sin W).
    const double q = std::hypot(x(3), x(4));
    const double incl = 2.0 * std::atan(q);
    const double ix = q > 0 ? incl * x(3) / q : 0.0, iy = q > 0 ? incl * x(4) / q : 0.0;
    os << G(t, 15) << "," << G((t - t0) / 86400.0, 10) << "," << G(y(1) * kRadToDeg, 10) << ","
       << G(y(2) * kRadToDeg, 10) << "," << G(y(0) / 1000.0, 10) << "," << G(x(1), 10) << ","
       << G(x(2), 10) << "," << G(ix * kRadToDeg, 10) << "," << G(iy * kRadToDeg, 10) << ","
       << G(x(5) * kRadToDeg, 10) << "\n";
  }
  return os.str();
}

std::string PlotHeader(const std::string& image, int w, int h, const std::string& name) {
  std::ostringstream os;
  os << "# Generated by thrustsched simulate for scenario " << name << ".\n"
     << "# Restyle freely, then run: gnuplot " << image.substr(0, image.size() - 4)
     << ".gp (in this directory).\n"
     << "set terminal svg size " << w << "," << h
     << " dynamic enhanced font 'sans,12' background rgb 'white'\n"
     << "set output '" << image << "'\n"
     << "set datafile separator ','\n"
     << "set grid\n";
  return os.str();
}

// Text for a single-quoted gnuplot string in enhanced mode: no quote, and
// one backslash before the enhanced-text control characters (single quotes
// keep backslashes as they are, so '\_' prints an underscore).
std::string GnuplotText(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '_' || c == '^' || c == '{' || c == '}' || c == '@' || c == '&') out += '\\';
    if (c == '\'') continue;
    out += c;
  }
  return out;
}

struct PlotFiles {
  std::vector<std::string> images;
  std::string message;
};

PlotFiles WriteYearPlots(const std::string& dir, const SimulationSetup& setup,
                         const std::vector<CycleRecord>& cycles, bool run) {
  const std::string name = GnuplotText(setup.scenario.name);
  const double w = setup.scenario.window_half_widths.empty() ? 0.05 : setup.scenario.window_half_widths[0];
  std::vector<std::pair<std::string, std::string>> scripts;
  {
    std::ostringstream os;
    os << PlotHeader("consumption.svg", 1000, 600, name)
       << "set title '" << name << ": consumption per cycle and cumulative (L1 thesis metric)'\n"
       << "set xlabel 'cycle start (days since t_0)'\n"
       << "set ylabel 'per cycle (m/s)'\nset y2label 'cumulative (m/s)'\n"
       << "set ytics nomirror\nset y2tics\nset key top left\n"
       // Bars from 0: an axis from the smallest cycle exaggerated the differences.
       << "set yrange [0:*]\nset y2range [0:*]\n"
       << "set style fill solid 0.5\n"
       << "cum = 0\n"
       << "t0 = " << G(setup.options.start_s, 15) << "\n"
       << "# cycles.csv: col 3 start_s, col 4 end_s, col 14 consumption_l1_m_s\n"
       << "plot 'cycles.csv' skip 1 using (($3-t0)/86400 + ($4-$3)/172800):14:(($4-$3)/86400*0.8) "
          "with boxes lc rgb '#1f77b4' title 'per cycle', \\\n"
       << "     'cycles.csv' skip 1 using (($4-t0)/86400):(cum = cum + $14) axes x1y2 with "
          "linespoints pt 7 ps 0.5 lw 2 lc rgb '#d62728' title 'cumulative'\n";
    scripts.emplace_back("consumption", os.str());
  }
  {
    std::ostringstream os;
    os << PlotHeader("vectors.svg", 1200, 600, name)
       << "set multiplot layout 1,2 title '" << name
       << ": inclination and eccentricity vectors (nonlinear replay, osculating)'\n"
       << "set size ratio -1\nset key off\n"
       << "set title 'inclination vector i (cos W, sin W)'\n"
       << "set xlabel 'i_x (deg)'\nset ylabel 'i_y (deg)'\n"
       << "plot 'trajectory.csv' skip 1 using 8:9:2 with lines lc palette lw 1.5\n"
       << "set title 'eccentricity vector e (cos(w+W), sin(w+W))'\n"
       << "set xlabel 'e_x (1e-4)'\nset ylabel 'e_y (1e-4)'\n"
       << "set cblabel 'days since t_0'\n"
       << "plot 'trajectory.csv' skip 1 using ($6*1e4):($7*1e4):2 with lines lc palette lw 1.5\n"
       << "unset multiplot\n";
    scripts.emplace_back("vectors", os.str());
  }
  {
    std::ostringstream os;
    os << PlotHeader("latlon.svg", 1200, 800, name)
       << "set multiplot layout 2,1 title '" << name
       << ": latitude and longitude over the run (nonlinear replay)'\n"
       << "w = " << G(w) << "\nset key top right\n"
       << "set ylabel 'latitude (deg)'\nset xlabel ''\n"
       << "plot 'trajectory.csv' skip 1 using 2:3 with lines lc rgb '#1f77b4' title 'latitude', \\\n"
       << "     w with lines dt 2 lc rgb 'red' title 'window', -w with lines dt 2 lc rgb 'red' notitle\n"
       << "set ylabel 'longitude - station (deg)'\nset xlabel 'days since t_0'\n"
       << "plot 'trajectory.csv' skip 1 using 2:4 with lines lc rgb '#ff7f0e' title 'longitude', \\\n"
       << "     w with lines dt 2 lc rgb 'red' title 'window', -w with lines dt 2 lc rgb 'red' notitle\n"
       << "unset multiplot\n";
    scripts.emplace_back("latlon", os.str());
  }
  // Firing timeline of one cycle: the chosen one, else the one with most burns.
  int pick = setup.timeline_cycle;
  if (pick < 0 || pick >= static_cast<int>(cycles.size())) {
    pick = -1;
    size_t most = 0;
    for (size_t k = 0; k < cycles.size(); ++k) {
      if (pick < 0 || cycles[k].burns.size() > most) {
        most = cycles[k].burns.size();
        pick = static_cast<int>(k);
      }
    }
  }
  if (pick >= 0) {
    const CycleRecord& c = cycles[static_cast<size_t>(pick)];
    const std::vector<std::string> names = setup.scenario.thruster_names();
    const int m = static_cast<int>(names.size());
    std::ostringstream os;
    os << PlotHeader("timeline.svg", 1100, 150 + 45 * m, name)
       << "set title '" << name << ": firing timeline of cycle " << pick + 1 << " ("
       << Utc(setup.scenario.geo->epoch, c.start_s) << ")'\n"
       << "t0 = " << G(c.start_s, 15) << "\n"
       << "colors = \"#1f77b4 #ff7f0e #2ca02c #d62728 #9467bd #8c564b\"\n"
       << "color(i) = word(colors, (i - 1) % 6 + 1)\n"
       << "names = \"";
    for (int i = 0; i < m; ++i) os << (i ? " " : "") << names[i];
    os << "\"\nset xlabel 'days since the cycle start'\n"
       << "set xrange [0:" << G((c.applied_end_s - c.start_s) / 86400.0) << "]\n"
       << "set yrange [0.4:" << m << ".6]\nset ytics (";
    for (int i = 0; i < m; ++i) os << (i ? ", " : "") << "'" << names[i] << "' " << i + 1;
    os << ")\nset grid noytics\nset key off\n"
       << "plot for [i=1:" << m << "] 'cycles/" << CycleTag(pick)
       << ".csv' skip 1 using (($2-t0)/86400):(strcol(1) eq word(names,i) ? i : NaN):($4/86400):(0) "
          "with vectors nohead lw 12 lc rgb color(i) notitle, NaN notitle\n";
    scripts.emplace_back("timeline", os.str());
  }
  PlotFiles out;
  for (const auto& [base, text] : scripts) WriteTextFile(dir + "/" + base + ".gp", text);
  if (!run) {
    out.message = "plots skipped (--no-plots); the gnuplot scripts are in " + dir;
    return out;
  }
  if (!GnuplotAvailable()) {
    out.message = "gnuplot not found: plots skipped; run the .gp scripts in " + dir;
    return out;
  }
  std::string failed;
  for (const auto& [base, text] : scripts) {
    if (RunGnuplot(dir, base + ".gp")) {
      out.images.push_back(base + ".svg");
    } else {
      failed += (failed.empty() ? "" : ", ") + base + ".gp";
    }
  }
  if (!failed.empty()) out.message = "gnuplot failed on " + failed + " (see " + dir + "/gnuplot.log)";
  return out;
}

nlohmann::json CheckpointJson(const SimulationSetup& setup, const transcription::LongHorizonState& st,
                              const std::vector<CycleRecord>& cycles) {
  nlohmann::json j;
  j["format"] = kCheckpointFormat;
  j["scenario"] = setup.scenario.path;
  j["fingerprint"] = setup.fingerprint;
  j["next_cycle"] = st.next_cycle;
  j["time_s"] = st.time_s;
  j["eci"] = VectorJson(st.eci);
  nlohmann::json last = nlohmann::json::array();
  for (double e : st.last_burn_end_s) last.push_back(Num(e));  // null = never fired
  j["last_burn_end_s"] = last;
  nlohmann::json c = nlohmann::json::array();
  for (const CycleRecord& r : cycles) c.push_back(CycleRecordJson(r));
  j["cycles"] = c;
  return j;
}

void ReadCheckpoint(const std::string& path, const SimulationSetup& setup, int num_thrusters,
                    transcription::LongHorizonState* st, std::vector<CycleRecord>* cycles) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot open the checkpoint");
  std::ostringstream ss;
  ss << in.rdbuf();
  const nlohmann::json j = ParseJsonText(ss.str(), path);
  if (!j.is_object() || j.value("format", "") != kCheckpointFormat) {
    throw ScenarioError(path + ": not a thrustsched year checkpoint (format " +
                        std::string(kCheckpointFormat) + ")");
  }
  if (j.value("fingerprint", "") != setup.fingerprint) {
    throw ScenarioError(path + ": the checkpoint was written for another scenario or other "
                        "settings (fingerprint " + j.value("fingerprint", "?") + ", this scenario " +
                        setup.fingerprint + "); run without --resume to start again");
  }
  st->next_cycle = static_cast<int>(GetNumber(j, "next_cycle", path));
  st->time_s = GetNumber(j, "time_s", path);
  st->eci = ToVector6(GetNumbers(j, "eci", path), path + ".eci");
  st->last_burn_end_s = GetNumbers(j, "last_burn_end_s", path, -kInf);
  if (static_cast<int>(st->last_burn_end_s.size()) != num_thrusters) {
    throw ScenarioError(path + ".last_burn_end_s: " + std::to_string(st->last_burn_end_s.size()) +
                        " entries for " + std::to_string(num_thrusters) + " thrusters");
  }
  if (!j.contains("cycles") || !j.at("cycles").is_array()) {
    throw ScenarioError(path + ".cycles: expected an array");
  }
  cycles->clear();
  for (size_t k = 0; k < j.at("cycles").size(); ++k) {
    cycles->push_back(
        CycleRecordFromJson(j.at("cycles")[k], path + ".cycles[" + std::to_string(k) + "]"));
  }
  if (static_cast<int>(cycles->size()) != st->next_cycle) {
    throw ScenarioError(path + ": " + std::to_string(cycles->size()) + " cycle records for next_cycle " +
                        std::to_string(st->next_cycle));
  }
}

std::string ProgressLine(const CycleRecord& c, int total, const std::string& epoch, double consumed,
                         double eta) {
  std::ostringstream os;
  os << "cycle " << c.index + 1 << "/" << total << " " << Utc(epoch, c.start_s).substr(0, 10) << ": "
     << StatusName(c.status);
  if (c.fallback != Fallback::kNone) os << " (fallback " << transcription::ToString(c.fallback) << ")";
  os << ", solve " << G(c.solve_seconds, 3) << " s, gap "
     << (std::isfinite(c.gap) ? G(100.0 * c.gap, 3) + "%" : std::string("n/a")) << ", "
     << G(c.consumption_l1_m_s, 4) << " m/s (total " << G(consumed, 5) << " m/s L1), max |lat| "
     << G(c.max_abs_lat_deg, 3) << " |lon| " << G(c.max_abs_lon_deg, 3) << " deg"
     << (c.time_outside_window_s > 0 ? ", " + G(c.time_outside_window_s, 4) + " s OUTSIDE" : "")
     << (c.controllable ? "" : ", UNCONTROLLABLE") << "; ETA " << Hms(eta);
  return os.str();
}

}  // namespace

// ---------------------------------------------------------------------------

SimulationSetup ParseSimulationText(const std::string& text, const std::string& source) {
  SimulationSetup setup;
  ScenarioParseOptions po;
  po.extra_sections = {"long_horizon"};
  po.source = source;
  setup.scenario = ParseScenarioText(text, po);
  Scenario& s = setup.scenario;
  if (s.model_type != ModelType::kGeo) {
    throw ScenarioError("scenario.model.type: simulate needs a \"geo\" model, got \"" +
                        std::string(ToString(s.model_type)) + "\"");
  }
  if (s.impulsive()) {
    throw ScenarioError("scenario.input_mode: simulate needs on-off thrusters, got \"impulsive\"");
  }
  if (!s.raw.contains("long_horizon")) {
    throw ScenarioError("scenario.long_horizon: missing (simulate needs this section)");
  }
  if (s.raw.contains("terminal")) {
    throw ScenarioError(
        "scenario.terminal: not used by simulate; give the end-of-cycle sets in "
        "long_horizon.terminal");
  }
  if (s.raw.contains("conjunction")) {
    throw ScenarioError("scenario.conjunction: not used by simulate (solve the encounter with `solve`)");
  }
  if (!s.problem.window.enabled()) {
    throw ScenarioError("scenario.window: missing (simulate keeps the satellite in a window)");
  }
  if (s.problem.window.soft) {
    throw ScenarioError(
        "scenario.window.soft: not used by simulate (the fallbacks soften the window "
        "themselves; see long_horizon.soft_penalty)");
  }
  for (int i = 0; i < s.problem.thrusters.size(); ++i) {
    if (s.problem.history.is_on(i)) {
      throw ScenarioError("scenario.history." + s.problem.thrusters.thruster(i).name +
                          ".on_for_s: simulate starts with every thruster off (use off_for_s)");
    }
  }
  ParseLongHorizon(&setup);
  setup.fingerprint = Fingerprint(s.raw.dump());
  return setup;
}

SimulationSetup LoadSimulation(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot open the scenario file");
  std::ostringstream ss;
  ss << in.rdbuf();
  SimulationSetup s = ParseSimulationText(ss.str(), path);
  s.scenario.path = path;
  return s;
}

nlohmann::json CycleRecordJson(const CycleRecord& r) {
  nlohmann::json j;
  j["index"] = r.index;
  j["start_s"] = r.start_s;
  j["applied_end_s"] = r.applied_end_s;
  j["prediction_end_s"] = r.prediction_end_s;
  j["fallback"] = std::string(transcription::ToString(r.fallback));
  j["status"] = std::string(milp::ToString(r.status));
  nlohmann::json attempts = nlohmann::json::array();
  for (const transcription::CycleAttempt& a : r.attempts) {
    attempts.push_back({{"level", std::string(transcription::ToString(a.level))},
                        {"status", std::string(milp::ToString(a.status))},
                        {"solve_seconds", a.solve_seconds},
                        {"detail", a.detail}});
  }
  j["attempts"] = attempts;
  j["objective"] = Num(r.objective);
  j["best_bound"] = Num(r.best_bound);
  j["gap"] = Num(r.gap);
  j["nodes"] = r.nodes;
  j["solve_seconds"] = r.solve_seconds;
  j["first_solution_seconds"] = Num(r.first_solution_seconds);
  j["build_seconds"] = r.build_seconds;
  j["check_seconds"] = r.check_seconds;
  j["replay_seconds"] = r.replay_seconds;
  j["wall_seconds"] = r.wall_seconds;
  j["cpu_seconds"] = r.cpu_seconds;
  j["controllable"] = r.controllable;
  j["note"] = r.note;
  nlohmann::json burns = nlohmann::json::array();
  for (const transcription::Burn& b : r.burns) burns.push_back({b.thruster, b.start_s, b.end_s});
  j["burns"] = burns;
  j["planned_burns"] = r.planned_burns;
  j["consumption_l1_m_s"] = r.consumption_l1_m_s;
  j["delta_v_m_s"] = r.delta_v_m_s;
  j["propellant_kg"] = r.propellant_kg;
  j["normal_delta_v_m_s"] = r.normal_delta_v_m_s;
  j["on_time_s"] = r.on_time_s;
  j["checked"] = r.checked;
  j["rules_ok"] = r.rules_ok;
  j["linear_window_violation_deg"] = Num(r.linear_window_violation_deg);
  j["soft_violation_deg"] = Num(r.soft_violation_deg);
  j["max_abs_lat_deg"] = r.max_abs_lat_deg;
  j["max_abs_lon_deg"] = r.max_abs_lon_deg;
  j["max_window_violation_deg"] = r.max_window_violation_deg;
  j["worst_time_s"] = Num(r.worst_time_s);
  j["time_outside_window_s"] = r.time_outside_window_s;
  j["prediction_error_deg"] = Num(r.prediction_error_deg);
  j["eci_start"] = VectorJson(r.eci_start);
  j["eci_end"] = VectorJson(r.eci_end);
  j["initial_state"] = VectorJson(r.initial_state);
  j["final_state"] = VectorJson(r.final_state);
  return j;
}

CycleRecord CycleRecordFromJson(const nlohmann::json& j, const std::string& path) {
  if (!j.is_object()) throw ScenarioError(path + ": expected an object");
  auto str = [&](const char* key) {
    if (!j.contains(key) || !j.at(key).is_string()) {
      throw ScenarioError(path + "." + key + ": expected a string");
    }
    return j.at(key).get<std::string>();
  };
  auto boolean = [&](const char* key) {
    if (!j.contains(key) || !j.at(key).is_boolean()) {
      throw ScenarioError(path + "." + key + ": expected a boolean");
    }
    return j.at(key).get<bool>();
  };
  CycleRecord r;
  r.index = static_cast<int>(GetNumber(j, "index", path));
  r.start_s = GetNumber(j, "start_s", path);
  r.applied_end_s = GetNumber(j, "applied_end_s", path);
  r.prediction_end_s = GetNumber(j, "prediction_end_s", path);
  r.fallback = Wrap(path + ".fallback", [&] { return transcription::ParseFallback(str("fallback")); });
  r.status = ParseStatus(str("status"), path + ".status");
  if (!j.contains("attempts") || !j.at("attempts").is_array()) {
    throw ScenarioError(path + ".attempts: expected an array");
  }
  for (size_t k = 0; k < j.at("attempts").size(); ++k) {
    const nlohmann::json& a = j.at("attempts")[k];
    const std::string ap = path + ".attempts[" + std::to_string(k) + "]";
    if (!a.is_object() || !a.contains("level") || !a.contains("status") || !a.contains("detail")) {
      throw ScenarioError(ap + ": expected {level, status, solve_seconds, detail}");
    }
    transcription::CycleAttempt at;
    at.level = Wrap(ap + ".level",
                    [&] { return transcription::ParseFallback(a.at("level").get<std::string>()); });
    at.status = ParseStatus(a.at("status").get<std::string>(), ap + ".status");
    at.solve_seconds = GetNumber(a, "solve_seconds", ap);
    at.detail = a.at("detail").get<std::string>();
    r.attempts.push_back(at);
  }
  r.objective = GetNumber(j, "objective", path);
  r.best_bound = GetNumber(j, "best_bound", path);
  r.gap = GetNumber(j, "gap", path);
  r.nodes = static_cast<long long>(GetNumber(j, "nodes", path));
  r.solve_seconds = GetNumber(j, "solve_seconds", path);
  r.first_solution_seconds = GetNumber(j, "first_solution_seconds", path);
  r.build_seconds = GetNumber(j, "build_seconds", path);
  r.check_seconds = GetNumber(j, "check_seconds", path);
  r.replay_seconds = GetNumber(j, "replay_seconds", path);
  r.wall_seconds = GetNumber(j, "wall_seconds", path);
  r.cpu_seconds = GetNumber(j, "cpu_seconds", path);
  r.controllable = boolean("controllable");
  r.note = str("note");
  if (!j.contains("burns") || !j.at("burns").is_array()) {
    throw ScenarioError(path + ".burns: expected an array");
  }
  for (size_t k = 0; k < j.at("burns").size(); ++k) {
    const nlohmann::json& b = j.at("burns")[k];
    if (!b.is_array() || b.size() != 3 || !b[0].is_number_integer() || !b[1].is_number() ||
        !b[2].is_number()) {
      throw ScenarioError(path + ".burns[" + std::to_string(k) +
                          "]: expected [thruster, start_s, end_s], got " + DescribeJson(b));
    }
    r.burns.push_back({b[0].get<int>(), b[1].get<double>(), b[2].get<double>()});
  }
  r.planned_burns = static_cast<int>(GetNumber(j, "planned_burns", path));
  r.consumption_l1_m_s = GetNumber(j, "consumption_l1_m_s", path);
  r.delta_v_m_s = GetNumber(j, "delta_v_m_s", path);
  r.propellant_kg = GetNumber(j, "propellant_kg", path);
  r.normal_delta_v_m_s = GetNumber(j, "normal_delta_v_m_s", path);
  r.on_time_s = GetNumbers(j, "on_time_s", path);
  r.checked = boolean("checked");
  r.rules_ok = boolean("rules_ok");
  r.linear_window_violation_deg = GetNumber(j, "linear_window_violation_deg", path);
  r.soft_violation_deg = GetNumber(j, "soft_violation_deg", path);
  r.max_abs_lat_deg = GetNumber(j, "max_abs_lat_deg", path);
  r.max_abs_lon_deg = GetNumber(j, "max_abs_lon_deg", path);
  r.max_window_violation_deg = GetNumber(j, "max_window_violation_deg", path);
  r.worst_time_s = GetNumber(j, "worst_time_s", path);
  r.time_outside_window_s = GetNumber(j, "time_outside_window_s", path);
  r.prediction_error_deg = GetNumber(j, "prediction_error_deg", path);
  r.eci_start = ToVector6(GetNumbers(j, "eci_start", path), path + ".eci_start");
  r.eci_end = ToVector6(GetNumbers(j, "eci_end", path), path + ".eci_end");
  r.initial_state = ToVector(GetNumbers(j, "initial_state", path));
  r.final_state = ToVector(GetNumbers(j, "final_state", path));
  return r;
}

std::string CyclesCsvHeader() {
  return "cycle,start_utc,start_s,end_s,status,fallback,objective,best_bound,gap,solve_s,"
         "first_solution_s,wall_s,cpu_s,consumption_l1_m_s,delta_v_m_s,propellant_kg,"
         "normal_delta_v_m_s,burns,max_abs_lat_deg,max_abs_lon_deg,max_window_violation_deg,"
         "time_outside_window_s,prediction_error_deg,rules_ok,controllable,note\n";
}

std::string CyclesCsvRow(const CycleRecord& r, const std::string& epoch) {
  std::ostringstream os;
  os << r.index + 1 << "," << Utc(epoch, r.start_s) << "," << G(r.start_s, 15) << ","
     << G(r.applied_end_s, 15) << "," << StatusName(r.status) << ","
     << transcription::ToString(r.fallback) << "," << G(r.objective) << "," << G(r.best_bound)
     << "," << G(r.gap) << "," << G(r.solve_seconds, 6) << "," << G(r.first_solution_seconds, 6)
     << "," << G(r.wall_seconds, 6) << "," << G(r.cpu_seconds, 6) << "," << G(r.consumption_l1_m_s) << "," << G(r.delta_v_m_s)
     << "," << G(r.propellant_kg) << "," << G(r.normal_delta_v_m_s) << "," << r.burns.size() << ","
     << G(r.max_abs_lat_deg) << "," << G(r.max_abs_lon_deg) << "," << G(r.max_window_violation_deg)
     << "," << G(r.time_outside_window_s) << "," << G(r.prediction_error_deg) << ","
     << (r.rules_ok ? "true" : "false") << "," << (r.controllable ? "true" : "false") << ","
     << CsvQuote(r.note) << "\n";
  return os.str();
}

nlohmann::json YearJson(const SimulationSetup& setup, const std::vector<CycleRecord>& cycles,
                        int cycles_total, double this_run_wall_seconds) {
  const dynamics::ThrusterSet& thr = setup.scenario.problem.thrusters;
  const transcription::LongHorizonSummary s = transcription::Summarise(cycles, thr);
  const transcription::LongHorizonOptions& o = setup.options;
  const std::string epoch = setup.scenario.geo->epoch;
  nlohmann::json j;
  j["scenario"] = setup.scenario.name;
  j["scenario_file"] = setup.scenario.path;
  j["complete"] = s.cycles == cycles_total;
  j["cycles"] = s.cycles;
  j["cycles_total"] = cycles_total;
  j["mode"] = std::string(transcription::ToString(o.mode));
  j["start_utc"] = Utc(epoch, o.start_s);
  j["simulated_days"] = s.simulated_s / 86400.0;
  j["consumption_l1_m_s"] = s.consumption_l1_m_s;
  j["delta_v_m_s"] = s.delta_v_m_s;
  j["propellant_kg"] = s.propellant_kg;
  j["normal_delta_v_m_s"] = s.normal_delta_v_m_s;
  j["burns"] = s.burns;
  nlohmann::json per = nlohmann::json::object();
  double total_days = 0;
  for (int i = 0; i < thr.size(); ++i) {
    per[thr.thruster(i).name] = s.thrust_days[i];
    total_days += s.thrust_days[i];
  }
  j["thrust_days"] = {{"per_thruster", per},   {"total", total_days},
                      {"north", s.north_days}, {"south", s.south_days},
                      {"east", s.east_days},   {"west", s.west_days}};
  j["thrust_days_faces_rule"] =
      "a thruster sits on the face opposite to its push: north = pushes -N, south = pushes +N, "
      "east = pushes -T (westward), west = pushes +T (Anzel: N = NE+NW, S = SE+SW, E = NE+SE, "
      "W = NW+SW, thesis Table 5.7)";
  j["time_outside_window_s"] = s.time_outside_window_s;
  j["max_abs_lat_deg"] = s.max_abs_lat_deg;
  j["max_abs_lon_deg"] = s.max_abs_lon_deg;
  j["max_window_violation_deg"] = s.max_window_violation_deg;
  j["worst_time_s"] = Num(s.worst_time_s);
  j["worst_time_utc"] = std::isfinite(s.worst_time_s) ? nlohmann::json(Utc(epoch, s.worst_time_s))
                                                      : nlohmann::json(nullptr);
  j["box_held"] = s.max_window_violation_deg <= 0.0;
  j["window_half_width_deg"] =
      setup.scenario.window_half_widths.empty() ? 0.0 : setup.scenario.window_half_widths[0];
  j["rules_ok"] = s.rules_ok;
  nlohmann::json fb_cycles = nlohmann::json::array();
  nlohmann::json unctl = nlohmann::json::array();
  std::vector<double> pred;
  for (const CycleRecord& c : cycles) {
    if (c.fallback != Fallback::kNone) {
      fb_cycles.push_back({{"cycle", c.index + 1},
                           {"start_utc", Utc(epoch, c.start_s)},
                           {"fallback", std::string(transcription::ToString(c.fallback))}});
    }
    if (!c.controllable) unctl.push_back({{"cycle", c.index + 1}, {"reason", c.note}});
    pred.push_back(c.prediction_error_deg);
  }
  j["fallbacks"] = {{"soft_window", s.fallback_soft_window},
                    {"soft_window_free_terminal", s.fallback_free_terminal},
                    {"zero_thrust", s.fallback_zero_thrust},
                    {"total", s.fallback_soft_window + s.fallback_free_terminal +
                                  s.fallback_zero_thrust},
                    {"cycles", fb_cycles}};
  j["uncontrollable"] = {{"cycles", s.uncontrollable_cycles}, {"list", unctl}};
  j["time_limited_cycles"] = s.time_limited_cycles;
  auto dist = [](const transcription::Distribution& d) {
    return nlohmann::json{{"median", Num(d.median)}, {"p90", Num(d.p90)},  {"max", Num(d.max)},
                          {"mean", Num(d.mean)},     {"count", d.count}};
  };
  j["solve_seconds"] = dist(s.solve_seconds);
  j["gap"] = dist(s.gap);
  j["cycle_wall_seconds"] = dist(s.wall_seconds);
  j["cycle_cpu_seconds"] = dist(s.cpu_seconds);
  j["cpu_seconds"] = s.cpu_seconds_total;
  j["prediction_error_deg"] = dist(transcription::Distribute(pred));
  j["wall_seconds"] = s.wall_seconds_total;
  j["this_run_wall_seconds"] = this_run_wall_seconds;
  nlohmann::json fails = nlohmann::json::array();
  for (const FailureSpec& f : setup.failures) {
    fails.push_back({{"thrusters", f.thrusters},
                     {"from_s", f.from_s},
                     {"from_utc", Utc(epoch, f.from_s)},
                     {"until_s", Num(f.until_s)},
                     {"opposite_also_off", f.opposite_also_off},
                     {"switched_off", f.switched_off}});
  }
  j["failures"] = fails;
  std::vector<std::string> disabled;
  for (const auto& t : thr.thrusters()) {
    if (!t.enabled) disabled.push_back(t.name);
  }
  j["disabled"] = disabled;
  j["settings"] = {
      {"cycle_s", o.cycle_s},
      {"control_s", o.mode == transcription::HorizonMode::kReceding ? o.control_s : o.cycle_s},
      {"step_s", o.step_s},
      {"duration_s", o.duration_s},
      {"cycle_time_limit_s", Num(o.solve.solve.time_limit_s)},
      {"cycle_relative_gap", o.solve.solve.relative_gap},
      {"threads", o.solve.solve.threads},
      {"cycle_max_nodes", o.solve.solve.max_nodes >= 0 ? nlohmann::json(o.solve.solve.max_nodes)
                                                       : nlohmann::json(nullptr)},
      {"lp_algorithm", std::string(milp::ToString(o.solve.solve.lp_algorithm))},
      {"scheme", std::string(dynamics::ToString(o.solve.build.discretisation.scheme))},
      {"terminal", o.terminal.kind == transcription::TerminalKind::kStationKeepingSets
                       ? nlohmann::json{{"type", "station_keeping"},
                                        {"facets", o.terminal.facets_out_of_plane},
                                        {"lookahead_s", o.terminal.lookahead_s.empty()
                                                            ? std::vector<double>{0.0, o.cycle_s}
                                                            : o.terminal.lookahead_s},
                                        {"margin", o.terminal.margin}}
                       : nlohmann::json{{"type", "free"}}},
      {"soft_penalty", o.soft_penalty},
      {"cycle_improve_above_gap", o.improve_above_gap},
      {"cycle_improve_max_nodes", o.improve_max_nodes >= 0
                                      ? nlohmann::json(o.improve_max_nodes)
                                      : (o.solve.solve.max_nodes >= 0
                                             ? nlohmann::json(5 * std::max(o.solve.solve.max_nodes, 1LL))
                                             : nlohmann::json(nullptr))},
      {"cycle_retry_without_preprocessing", o.retry_without_preprocessing},
      {"replay_samples_per_step", o.replay_samples_per_step}};
  return j;
}

// A folder holding an earlier run is continued (--resume) or started over
// (--force: the earlier run's files are removed first), never silently
// overwritten: hours of cycles would be lost.
void PrepareFolder(const std::string& dir, const SimulateArgs& a, std::ostream& err) {
  if (a.resume && a.force) {
    throw ScenarioError("--resume and --force: choose one (continue the run in " + dir +
                        ", or start it over)");
  }
  const FolderContents before = InspectFolder(dir);
  if (!before.holds_run() || a.resume) return;
  if (!a.force) {
    throw ScenarioError(dir + " holds an earlier run (" +
                        (fs::exists(dir + "/checkpoint.json") ? std::string("checkpoint.json, ")
                                                              : std::string()) +
                        std::to_string(before.run_files.size()) +
                        " file(s)): use --resume to continue it, or --force to start over");
  }
  RemoveEarlierRun(dir, before);
  if (!a.quiet) {
    err << "note: --force: removed the earlier run's " << before.run_files.size()
        << " file(s) in " << dir << "\n";
  }
}

int RunSimulate(const SimulateArgs& a) {
  const Clock::time_point t_run = Clock::now();
  SimulationSetup setup = a.scenario_text.empty() ? LoadSimulation(a.scenario)
                                                  : ParseSimulationText(a.scenario_text, a.scenario);
  if (!a.scenario_text.empty()) setup.scenario.path = a.scenario;
  const std::string dir =
      a.out_dir.empty() ? "out/" + fs::path(a.scenario).stem().string() : a.out_dir;
  std::ostream& err = std::cerr;
  PrepareFolder(dir, a, err);
  MakeDirectory(dir);
  MakeDirectory(dir + "/cycles");
  std::vector<std::string> manifest = {
      "checkpoint.json", kInProgressFile, "cycles.csv",  "cycles",      "year.json",
      "trajectory.csv",  "gnuplot.log",   "consumption.gp", "consumption.svg", "vectors.gp",
      "vectors.svg",     "latlon.gp",     "latlon.svg",  "timeline.gp", "timeline.svg"};
  for (const std::string& f : YearReportFiles()) manifest.push_back(f);
  WriteManifest(dir, manifest, a.command_line);
  const Scenario& s = setup.scenario;
  const std::string epoch = s.geo->epoch;
  CheckFlightDynamicsFiles(s, a.ccsds, setup.options.start_s,
                           setup.options.start_s + setup.options.duration_s);

  // Ctrl-C stops the running solve; that unfinished cycle is not recorded.
  setup.options.solve.solve.interrupt = a.interrupt != nullptr ? a.interrupt : InterruptWatcher::flag();
  auto stop_requested = [&a] {
    return a.interrupt != nullptr ? a.interrupt->load() : InterruptWatcher::interrupted();
  };
  if (std::getenv("THRUSTSCHED_TEST_INTERRUPT_AT_INCUMBENT") != nullptr) {
    setup.options.solve.solve.progress = InterruptForTestAtIncumbent;
  }
  auto simulator = std::make_shared<const dynamics::GeoSimulator>(*s.geo);
  const std::shared_ptr<const milp::Solver> solver(milp::MakeCbcSolver().release());
  const transcription::LongHorizonSimulation run(s.problem, setup.options, simulator, solver);
  const int total = run.num_cycles();
  const int target = a.cycles > 0 ? std::min(a.cycles, total) : total;

  transcription::LongHorizonState state;
  std::vector<CycleRecord> cycles;
  const std::string checkpoint = dir + "/checkpoint.json";
  if (a.resume && fs::exists(checkpoint)) {
    ReadCheckpoint(checkpoint, setup, s.problem.thrusters.size(), &state, &cycles);
    if (!a.quiet) {
      err << "resuming " << s.name << " after cycle " << state.next_cycle << "/" << total << " ("
          << Utc(epoch, state.time_s) << ")\n";
    }
  } else {
    if (a.resume && !a.quiet) err << "note: no checkpoint in " << dir << ": starting at cycle 1\n";
    state = run.InitialState();
    WriteAtomically(checkpoint, CheckpointJson(setup, state, cycles).dump(1) + "\n");
  }
  // cycles.csv is regenerated from the checkpoint's records (so a row
  // appended by a cycle whose checkpoint was never written disappears).
  {
    std::string text = CyclesCsvHeader();
    for (const CycleRecord& c : cycles) text += CyclesCsvRow(c, epoch);
    WriteAtomically(dir + "/cycles.csv", text);
  }
  if (!a.quiet) {
    err << s.name << ": " << total << " " << transcription::ToString(setup.options.mode)
        << " cycles of " << G(setup.options.cycle_s / 86400.0, 4) << " d"
        << (setup.options.mode == transcription::HorizonMode::kReceding
                ? " (applied " + G(setup.options.control_s / 86400.0, 4) + " d)"
                : std::string())
        << " at " << G(setup.options.step_s) << " s, time limit "
        << G(setup.options.solve.solve.time_limit_s) << " s, gap "
        << G(setup.options.solve.solve.relative_gap) << " per cycle; running cycles "
        << state.next_cycle + 1 << ".." << target << "; Ctrl-C stops (finished cycles are kept, "
        << "continue with --resume)\n";
  }

  // Crash guard: only an earlier process can have left a marker, and only for
  // the first cycle this run solves (each cycle's guard removes its own).
  const std::string in_progress = dir + "/" + kInProgressFile;
  const std::optional<InProgress> died = ReadInProgress(in_progress, setup.fingerprint);
  const int first_cycle = state.next_cycle;

  bool interrupted = false;
  double consumed = 0;
  for (const CycleRecord& c : cycles) consumed += c.consumption_l1_m_s;
  double this_run_cycles_wall = 0;
  int this_run_cycles = 0;
  {
    std::optional<InterruptWatcher> watcher;
    if (a.interrupt == nullptr) watcher.emplace();
    while (state.next_cycle < target) {
      const int k = state.next_cycle;
      if (!a.quiet) {
        err << "cycle " << k + 1 << "/" << total << " " << Utc(epoch, run.Times(k).start_s)
            << ": solving...\n";
      }
      const bool retry = k == first_cycle && died.has_value() && died->cycle == k + 1;
      if (retry && died->safe) {
        throw std::runtime_error(
            "cycle " + std::to_string(k + 1) + " ended the process twice (the second time with "
            "CBC preprocessing off): the solver crashes on this cycle's MILP; " + in_progress +
            " records it (remove that file to try again)");
      }
      if (retry && !a.quiet) {
        err << "note: an earlier run died while solving cycle " << k + 1
            << " (a crash inside the solver); solving it with CBC preprocessing off (if that run "
               "was killed from outside instead, stop, remove "
            << in_progress << " and resume to solve it as configured)\n";
      }
      CycleRecord rec;
      {
        InProgressGuard guard(in_progress, setup.fingerprint, k + 1, retry);
        // Test hook: the process dies inside cycle N, as in a solver crash
        // (tests/app/simulate_test.cc, SimulateCli.SolverCrashIsRetriedOnResume).
        if (const char* die = std::getenv("THRUSTSCHED_TEST_DIE_IN_CYCLE")) {
          if (std::atoi(die) == k + 1) std::abort();
        }
        if (retry) {
          // The same cycle with CBC's preprocessing and presolve off.
          transcription::LongHorizonOptions safe = setup.options;
          safe.solve.solve.presolve = false;
          rec = transcription::LongHorizonSimulation(s.problem, safe, simulator, solver)
                    .RunCycle(&state);
          rec.note += std::string(rec.note.empty() ? "" : "; ") +
                      "an earlier run died inside this cycle's solve (solver crash); solved with "
                      "CBC preprocessing and presolve off";
        } else {
          rec = run.RunCycle(&state);
        }
      }
      // Ctrl-C during the solve: the cycle is incomplete and not recorded.
      // Ctrl-C after it (replay): the cycle is complete and recorded.
      interrupted = rec.interrupted || stop_requested();
      if (rec.interrupted) break;
      // Files of the finished cycle, then the checkpoint.
      const ReplayLeg leg = CycleReplayLeg(rec, setup.options.step_s);
      WriteScheduleCsv(dir + "/cycles/" + CycleTag(k) + ".csv", s, rec.burns, &leg);
      WriteTextFile(dir + "/cycles/" + CycleTag(k) + "_trajectory.csv",
                    TrajectoryHeader() + TrajectoryRows(setup, rec, k + 1 == total));
      {
        std::ofstream out(dir + "/cycles.csv", std::ios::app | std::ios::binary);
        out << CyclesCsvRow(rec, epoch);
        out.flush();
        if (!out) throw std::runtime_error(dir + "/cycles.csv: write failed");
      }
      rec.sample_times.clear();
      rec.sample_outputs.clear();
      rec.sample_states.clear();
      consumed += rec.consumption_l1_m_s;
      this_run_cycles_wall += rec.wall_seconds;
      ++this_run_cycles;
      cycles.push_back(rec);
      WriteAtomically(checkpoint, CheckpointJson(setup, state, cycles).dump(1) + "\n");
      // The totals so far ("complete": false until the last cycle).
      WriteAtomically(dir + "/year.json", YearJson(setup, cycles, total, Since(t_run)).dump(2) + "\n");
      if (a.on_cycle) a.on_cycle(cycles.back(), state.next_cycle, target);
      if (!a.quiet) {
        const double per = this_run_cycles_wall / this_run_cycles;
        err << ProgressLine(cycles.back(), total, epoch, consumed, per * (target - state.next_cycle))
            << "\n";
        for (const transcription::CycleAttempt& at : cycles.back().attempts) {
          if (at.level != Fallback::kNone || at.status != cycles.back().status) {
            err << "  attempt " << transcription::ToString(at.level) << ": "
                << StatusName(at.status) << " after " << G(at.solve_seconds, 3) << " s ("
                << at.detail.substr(0, 160) << ")\n";
          }
        }
      }
      if (interrupted) break;
    }
  }
  if (interrupted && !a.quiet) {
    err << "interrupted: cycles 1.." << state.next_cycle << " are saved in " << dir
        << "; continue with: thrustsched simulate " << a.scenario << " --out " << dir
        << " --resume\n";
  }

  // The run-level files from all finished cycles.
  {
    std::string text = TrajectoryHeader();
    for (const CycleRecord& c : cycles) {
      std::ifstream in(dir + "/cycles/" + CycleTag(c.index) + "_trajectory.csv", std::ios::binary);
      std::string line;
      bool first = true;
      while (std::getline(in, line)) {
        if (first) {
          first = false;
          continue;
        }
        text += line + "\n";
      }
    }
    WriteTextFile(dir + "/trajectory.csv", text);
  }
  const nlohmann::json year = YearJson(setup, cycles, total, Since(t_run));
  WriteJsonFile(dir + "/year.json", year);
  std::vector<std::string> files = {"cycles.csv", "year.json", "trajectory.csv", "checkpoint.json",
                                    "cycles/"};
  if (a.ccsds.any() && !cycles.empty()) {
    std::vector<ReplayLeg> legs;
    for (const CycleRecord& c : cycles) legs.push_back(CycleReplayLeg(c, setup.options.step_s));
    for (const std::string& f : WriteFlightDynamicsFiles(s, a.ccsds, legs)) files.push_back(f);
  }
  if (!cycles.empty()) {
    const PlotFiles p = WriteYearPlots(dir, setup, cycles, !a.no_plots);
    files.insert(files.end(), p.images.begin(), p.images.end());
    if (!p.message.empty()) err << "note: " << p.message << "\n";
    if (!a.no_report) {
      const YearReport rep = WriteYearReport(dir, s, year, !a.no_plots);
      files.insert(files.end(), rep.images.begin(), rep.images.end());
      files.push_back(kReportName);
      if (!rep.message.empty()) err << "note: " << rep.message << "\n";
    }
  }

  if (!a.print_summary) return interrupted ? kExitNoSolution : kExitOk;
  std::ostream& out = std::cout;
  const transcription::LongHorizonSummary sum = transcription::Summarise(cycles, s.problem.thrusters);
  out << "scenario      " << s.name << " (" << a.scenario << ")\n"
      << "cycles        " << sum.cycles << "/" << total << " ("
      << transcription::ToString(setup.options.mode) << ", " << G(sum.simulated_s / 86400.0, 6)
      << " days simulated)" << (interrupted ? ", interrupted" : "") << "\n"
      << "consumption   " << G(sum.consumption_l1_m_s, 6) << " m/s (L1 thesis metric), delta-v "
      << G(sum.delta_v_m_s, 6) << " m/s, normal delta-v " << G(sum.normal_delta_v_m_s, 5)
      << " m/s, propellant " << G(sum.propellant_kg, 5) << " kg, " << sum.burns << " burns\n"
      // The total is over the thrusters (as year.json's thrust_days.total):
      // N + S covers every thruster only in the thesis's four-thruster layout
      // (one per face gives ±R thrusters on neither face).
      << "thrust days   total "
      << G(std::accumulate(sum.thrust_days.begin(), sum.thrust_days.end(), 0.0), 5) << "; N "
      << G(sum.north_days, 4) << ", S " << G(sum.south_days, 4) << ", E " << G(sum.east_days, 4)
      << ", W " << G(sum.west_days, 4) << "\n"
      << "window        max |lat| " << G(sum.max_abs_lat_deg, 4) << " deg, max |lon| "
      << G(sum.max_abs_lon_deg, 4) << " deg; "
      << (sum.max_window_violation_deg > 0
              ? "OUTSIDE by up to " + G(sum.max_window_violation_deg, 3) + " deg for " +
                    FormatDuration(sum.time_outside_window_s) + " (first worst at " +
                    Utc(epoch, sum.worst_time_s) + ")"
              : std::string("inside the box for the whole run (nonlinear replay)"))
      << "\n"
      << "fallbacks     " << sum.fallback_soft_window << " soft window, "
      << sum.fallback_free_terminal << " soft window + free terminal, " << sum.fallback_zero_thrust
      << " zero thrust; " << sum.uncontrollable_cycles << " uncontrollable cycle(s); "
      << sum.time_limited_cycles << " cycle(s) stopped by the time limit\n"
      << "solve time    median " << G(sum.solve_seconds.median, 3) << " s, p90 "
      << G(sum.solve_seconds.p90, 3) << " s, max " << G(sum.solve_seconds.max, 3)
      << " s; gap median " << FormatPercent(sum.gap.median) << ", max "
      << FormatPercent(sum.gap.max) << "; wall " << Hms(sum.wall_seconds_total) << " over all cycles\n"
      << "output        " << dir << " (";
  for (size_t i = 0; i < files.size(); ++i) out << (i ? ", " : "") << files[i];
  out << ")\n";
  out.flush();
  return interrupted ? kExitNoSolution : kExitOk;
}

}  // namespace thrustsched::app
