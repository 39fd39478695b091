#include "app/html_report.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/format_units.h"
#include "app/outputs.h"
#include "app/plots.h"
#include "dynamics/time.h"

namespace thrustsched::app {
namespace {

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Numbers in the page: `digits` significant digits ("n/a" for NaN).
std::string Sig(double v, int digits = 6) { return FormatSignificant(v, digits); }

double NumberOr(const nlohmann::json& j, const char* key, double fallback = std::nan("")) {
  if (!j.is_object() || !j.contains(key) || !j.at(key).is_number()) return fallback;
  return j.at(key).get<double>();
}

std::string StringOr(const nlohmann::json& j, const char* key, const std::string& fallback = "") {
  if (!j.is_object() || !j.contains(key) || !j.at(key).is_string()) return fallback;
  return j.at(key).get<std::string>();
}

// One CSV line split into cells ("..." quoting with doubled quotes, as
// the writers in outputs.cc and simulate.cc produce).
std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cell += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.push_back(cell);
      cell.clear();
    } else if (c != '\r') {
      cell += c;
    }
  }
  cells.push_back(cell);
  return cells;
}

std::vector<std::vector<std::string>> ReadCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(ReadText(path));
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty()) rows.push_back(SplitCsvLine(line));
  }
  return rows;
}

std::string ModelInWords(const Scenario& s) {
  switch (s.model_type) {
    case ModelType::kHcw:
      return "HCW (Hill-Clohessy-Wiltshire) relative motion about a circular orbit";
    case ModelType::kGeo:
      return "geostationary station keeping, linearised GEO model (thesis ch. 3) with the "
             "nonlinear simulation model for the replay";
    case ModelType::kDoubleIntegrator:
      return "double integrator";
    case ModelType::kYamanakaAnkersen:
      return "Yamanaka-Ankersen relative motion about an elliptic orbit";
    case ModelType::kSchweighartSedwick:
      return "Schweighart-Sedwick relative motion with J2 about a circular orbit";
  }
  return std::string(ToString(s.model_type));
}

std::string TerminalInWords(const Scenario& s) {
  switch (s.problem.terminal.kind) {
    case transcription::TerminalKind::kFree:
      return "free";
    case transcription::TerminalKind::kFixedState:
      return "a prescribed state (rendezvous)";
    case transcription::TerminalKind::kStateBox:
      return "a box around a prescribed state";
    case transcription::TerminalKind::kStationKeepingSets:
      return "end-of-horizon station-keeping sets (thesis ch. 5)";
  }
  return "?";
}

std::string Utc(const Scenario& s, double t) {
  if (!s.geo) return "";
  return dynamics::Epoch::Parse(s.geo->epoch).PlusSeconds(t).ToIso8601();
}

}  // namespace

std::string Row(const std::string& key, const std::string& value_html) {
  return "<tr><th>" + HtmlEscape(key) + "</th><td>" + value_html + "</td></tr>\n";
}

namespace {

// An output's name without its unit suffix ("lat_rad" -> "lat").
std::string Bare(const std::string& name) {
  for (const char* unit : {"_rad", "_m", "_deg"}) {
    const std::string u(unit);
    if (name.size() > u.size() && name.compare(name.size() - u.size(), u.size(), u) == 0) {
      return name.substr(0, name.size() - u.size());
    }
  }
  return name;
}

std::string ScenarioTable(const Scenario& s) {
  std::ostringstream os;
  os << "<table class=\"facts\">\n";
  os << Row("model", HtmlEscape(ModelInWords(s)));
  const double t0 = s.problem.grid.front(), tf = s.problem.grid.back();
  std::string horizon = FormatDuration(tf - t0) + ": " + std::to_string(s.problem.num_intervals()) +
                        " intervals of " + FormatDuration(s.step_s);
  if (s.geo) {
    horizon += ", " + Utc(s, t0) + " to " + Utc(s, tf) + " (UTC)";
  } else {
    horizon += ", t = " + Sig(t0) + " s to " + Sig(tf) + " s";
  }
  os << Row("horizon", HtmlEscape(horizon));
  const dynamics::ThrusterSet& thr = s.problem.thrusters;
  std::string names, disabled;
  for (const auto& t : thr.thrusters()) {
    names += (names.empty() ? "" : ", ") + t.name;
    if (!t.enabled) disabled += (disabled.empty() ? "" : ", ") + t.name;
  }
  std::string thrusters = std::to_string(thr.size()) + " (" + names + "), " +
                          Sig(thr.thrust_n(), 4) + " N each; spacecraft " + Sig(thr.mass_kg(), 6) +
                          " kg, Isp " + Sig(thr.isp_s(), 5) + " s";
  if (!disabled.empty()) thrusters += "; disabled: " + disabled;
  if (s.impulsive()) thrusters += "; impulsive (delta-v at the grid nodes)";
  os << Row("thrusters", HtmlEscape(thrusters));
  if (!s.impulsive()) {
    const transcription::OperationalRules& r = s.problem.rules;
    os << Row("rules",
              HtmlEscape("each burn at least " + FormatDuration(r.min_burn_s) +
                         ", the same thruster off at least " + FormatDuration(r.min_off_same_s) +
                         " between its burns, at least " + FormatDuration(r.min_gap_other_s) +
                         " between burns of different thrusters, at most " +
                         std::to_string(r.max_simultaneous) + " thruster(s) at once"));
    if (!s.problem.forced_off.empty()) {
      std::string f;
      for (const transcription::ForcedOff& w : s.problem.forced_off) {
        f += (f.empty() ? "" : "; ") + thr.thruster(w.thruster).name + " " +
             (s.geo ? Utc(s, w.start_s) + " to " + Utc(s, w.end_s)
                    : Sig(w.start_s) + " s to " + Sig(w.end_s) + " s");
      }
      os << Row("forced off", HtmlEscape(f));
    }
  }
  if (s.problem.window.enabled()) {
    std::string w;
    for (size_t k = 0; k < s.window_half_widths.size(); ++k) {
      const int out = s.problem.window.outputs[k];
      const std::vector<std::string> outs = s.problem.model->output_names();
      w += (w.empty() ? "" : ", ") + std::string("|") +
           (out >= 0 && out < static_cast<int>(outs.size()) ? Bare(outs[static_cast<size_t>(out)])
                                                            : "?") +
           "| &le; " + Sig(s.window_half_widths[k], 6) + " " + HtmlEscape(s.window_unit);
    }
    if (s.problem.window.soft) w += " (soft)";
    if (s.problem.window.margin > 0) {
      w += ", planned with a " + HtmlEscape(FormatPercent(s.problem.window.margin)) + " margin";
    }
    os << Row("window", w);
  } else {
    os << Row("window", "none");
  }
  os << Row("end of horizon", HtmlEscape(TerminalInWords(s)));
  os << Row("objective", HtmlEscape(std::string(transcription::ToString(s.problem.objective.kind)) +
                                    (s.problem.objective.kind == transcription::ObjectiveKind::kL1
                                         ? " (thesis consumption metric, m/s)"
                                         : "")));
  os << "</table>\n";
  return os.str();
}

// A CSV file as an HTML table (all columns); "" if it has no rows.
std::string CsvTable(const std::string& path, size_t max_rows = 2000) {
  const std::vector<std::vector<std::string>> rows = ReadCsv(path);
  if (rows.size() < 2) return "";
  std::ostringstream os;
  os << "<table class=\"data\">\n<thead><tr>";
  for (const std::string& h : rows[0]) os << "<th>" << HtmlEscape(h) << "</th>";
  os << "</tr></thead>\n<tbody>\n";
  for (size_t r = 1; r < rows.size() && r <= max_rows; ++r) {
    os << "<tr>";
    for (const std::string& c : rows[r]) os << "<td>" << HtmlEscape(c) << "</td>";
    os << "</tr>\n";
  }
  os << "</tbody></table>\n";
  if (rows.size() - 1 > max_rows) {
    os << "<p class=\"note\">First " << max_rows << " of " << rows.size() - 1
       << " rows; all are in " << HtmlEscape(path.substr(path.find_last_of('/') + 1)) << ".</p>\n";
  }
  return os.str();
}

}  // namespace

std::string Figures(const std::string& dir, const std::vector<Figure>& figures) {
  std::ostringstream os;
  int shown = 0;
  for (const Figure& f : figures) {
    const std::string svg = InlineSvg(ReadText(dir + "/" + f.file));
    if (svg.empty()) continue;
    // Element ids are unique per page: prefix each plot's own (one pass,
    // the plots of a long run are megabytes).
    const std::string prefix = "p" + std::to_string(++shown) + "_";
    std::string text;
    text.reserve(svg.size() + svg.size() / 50);
    static const std::vector<std::string> refs = {"id='", "id=\"", "href='#", "href=\"#", "url(#"};
    for (size_t i = 0; i < svg.size();) {
      bool hit = false;
      if (svg[i] == 'i' || svg[i] == 'h' || svg[i] == 'u') {
        for (const std::string& r : refs) {
          if (svg.compare(i, r.size(), r) == 0) {
            text.append(r).append(prefix);
            i += r.size();
            hit = true;
            break;
          }
        }
      }
      if (!hit) text += svg[i++];
    }
    os << "<figure>\n"
       << text << "\n<figcaption>" << HtmlEscape(f.caption) << " (" << HtmlEscape(f.file)
       << ")</figcaption>\n</figure>\n";
  }
  if (shown == 0) os << "<p class=\"note\">No plots (gnuplot missing or --no-plots).</p>\n";
  return os.str();
}

const char* const kStyle = R"(
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif;
       max-width: 1100px; margin: 1.5em auto; padding: 0 1em; color: #1b1b1b; line-height: 1.4; }
h1 { font-size: 1.6em; margin-bottom: 0.2em; }
h2 { font-size: 1.25em; border-bottom: 1px solid #ccc; padding-bottom: 0.2em; margin-top: 1.6em; }
p.lead { color: #444; margin-top: 0; }
table { border-collapse: collapse; margin: 0.5em 0; }
table.facts th { text-align: left; vertical-align: top; padding: 0.2em 1em 0.2em 0; white-space: nowrap;
                 color: #444; font-weight: 600; }
table.facts td { padding: 0.2em 0; }
table.data { font-size: 0.85em; font-variant-numeric: tabular-nums; }
table.data th, table.data td { border: 1px solid #d0d0d0; padding: 0.15em 0.45em; text-align: right; }
table.data th { background: #f0f0f0; position: sticky; top: 0; }
table.data tbody tr:nth-child(even) { background: #fafafa; }
.verdict { display: inline-block; padding: 0.1em 0.6em; border-radius: 0.3em; font-weight: 700; }
.pass { background: #dff3df; color: #14591a; }
.fail { background: #fbe0e0; color: #8a1111; }
figure { margin: 1em 0; page-break-inside: avoid; break-inside: avoid; }
figure svg { display: block; max-width: 100%; height: auto; border: 1px solid #e3e3e3; }
figcaption { color: #555; font-size: 0.9em; margin-top: 0.3em; }
.note { color: #666; font-size: 0.9em; }
ul.findings li { margin: 0.2em 0; }
.tablewrap { overflow-x: auto; }
@media print {
  body { max-width: none; margin: 0; font-size: 10pt; }
  h2 { page-break-after: avoid; break-after: avoid; }
  figure svg { border: none; }
  table.data th { position: static; }
  .tablewrap { overflow: visible; }
}
)";

std::string PageStart(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta name=\"generator\" content=\"thrustsched\">\n<title>" +
         HtmlEscape(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
}

namespace {

std::string Verdict(bool passed) {
  return passed ? "<span class=\"verdict pass\">PASSED</span>"
                : "<span class=\"verdict fail\">FAILED</span>";
}

void WriteOrThrow(const std::string& path, const std::string& text) { WriteTextFile(path, text); }

std::string CheckSection(const Scenario& s, const nlohmann::json& check) {
  std::ostringstream os;
  if (!check.is_object()) {
    os << "<p>No schedule was checked.</p>\n";
    return os.str();
  }
  const bool passed = check.value("passed", false);
  os << "<p>The independent checker re-propagates the schedule with the continuous-time model"
     << (check.value("nonlinear_checked", false) ? " and replays it through the nonlinear model"
                                                 : "")
     << ": " << Verdict(passed) << "</p>\n<table class=\"facts\">\n";
  os << Row("operational rules", check.value("operational_ok", false) ? "ok" : "<b>violated</b>");
  const std::string unit = StringOr(check, "window_unit");
  if (!unit.empty()) {
    os << Row("window violation",
              HtmlEscape(Sig(NumberOr(check, "max_window_violation_nodes"), 4) + " " + unit +
                         " at the grid nodes, " + Sig(NumberOr(check, "max_window_violation"), 4) +
                         " " + unit + " on all samples (negative: inside by that much)"));
  }
  if (s.problem.terminal.kind == transcription::TerminalKind::kFixedState ||
      s.problem.terminal.kind == transcription::TerminalKind::kStateBox) {
    os << Row("end state", check.value("terminal_ok", false) ? "ok" : "<b>violated</b>");
  }
  if (check.value("nonlinear_checked", false)) {
    os << Row("nonlinear replay",
              HtmlEscape("max |lat| " + Sig(NumberOr(check, "max_abs_lat_deg"), 4) +
                         " deg, max |lon - station| " + Sig(NumberOr(check, "max_abs_lon_deg"), 4) +
                         " deg, about " +
                         FormatDuration(NumberOr(check, "time_outside_window_nonlinear_s", 0.0)) +
                         " outside the window"));
  }
  os << "</table>\n";
  std::vector<std::string> items;
  for (const char* key : {"findings", "rule_violations"}) {
    if (check.contains(key) && check.at(key).is_array()) {
      for (const auto& f : check.at(key)) {
        if (f.is_string()) items.push_back(f.get<std::string>());
      }
    }
  }
  if (check.contains("nonlinear_error") && check.at("nonlinear_error").is_string()) {
    items.push_back("nonlinear replay failed: " + check.at("nonlinear_error").get<std::string>());
  }
  if (!items.empty()) {
    os << "<ul class=\"findings\">\n";
    for (const std::string& f : items) os << "<li>" << HtmlEscape(f) << "</li>\n";
    os << "</ul>\n";
  }
  return os.str();
}

}  // namespace

std::string HtmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string InlineSvg(const std::string& svg_text) {
  const size_t start = svg_text.find("<svg");
  const size_t end = svg_text.rfind("</svg>");
  if (start == std::string::npos || end == std::string::npos || end < start) return "";
  std::string svg = svg_text.substr(start, end + 6 - start);
  // No script inside the page, whatever a restyled .gp asked for.
  for (size_t at; (at = svg.find("<script")) != std::string::npos;) {
    const size_t close = svg.find("</script>", at);
    svg.erase(at, close == std::string::npos ? std::string::npos : close + 9 - at);
  }
  // gnuplot's "dynamic" SVG has a viewBox and no size: give it its natural
  // size (the style sheet scales it down to the page width).
  const size_t tag_end = svg.find('>');
  const std::string tag = svg.substr(0, tag_end);
  const size_t vb = tag.find("viewBox=\"");
  if (vb != std::string::npos && tag.find(" width=") == std::string::npos) {
    double x = 0, y = 0, w = 0, h = 0;
    if (std::sscanf(tag.c_str() + vb + 9, "%lf %lf %lf %lf", &x, &y, &w, &h) == 4 && w > 0 &&
        h > 0) {
      svg.insert(4, " width=\"" + Sig(w, 8) + "\" height=\"" + Sig(h, 8) + "\"");
    }
  }
  return svg;
}

void WriteSolveReport(const std::string& dir, const Scenario& s, const nlohmann::json& summary) {
  std::ostringstream os;
  os << PageStart(s.name + " - thrustsched");
  os << "<h1>" << HtmlEscape(s.name) << "</h1>\n";
  if (s.raw.is_object() && s.raw.contains("description") && s.raw.at("description").is_string()) {
    os << "<p class=\"lead\">" << HtmlEscape(s.raw.at("description").get<std::string>())
       << "</p>\n";
  }
  os << "<p class=\"note\">Scenario file " << HtmlEscape(StringOr(summary, "scenario_file", s.path))
     << "; command <code>" << HtmlEscape(StringOr(summary, "command_line")) << "</code></p>\n";

  os << "<h2>Scenario</h2>\n" << ScenarioTable(s);

  os << "<h2>Result</h2>\n<table class=\"facts\">\n";
  std::string status = StringOr(summary, "status", "?");
  if (summary.value("interrupted", false)) status += " (interrupted: the best schedule found)";
  os << Row("status", HtmlEscape(status));
  const std::string unit =
      s.problem.objective.kind == transcription::ObjectiveKind::kPropellant ? " kg" : " m/s";
  if (summary.contains("objective") && summary.at("objective").is_number()) {
    os << Row("objective", HtmlEscape(Sig(NumberOr(summary, "objective"), 8) + unit + " (" +
                                      StringOr(summary, "objective_kind") + ")"));
    os << Row("best bound", HtmlEscape(Sig(NumberOr(summary, "best_bound"), 8) + unit));
    os << Row("gap", HtmlEscape(FormatPercent(NumberOr(summary, "gap"))));
  }
  if (summary.contains("min_time") && summary.at("min_time").is_object()) {
    const nlohmann::json& m = summary.at("min_time");
    const std::string arrival =
        m.contains("arrival_time_s") && m.at("arrival_time_s").is_number()
            ? Sig(NumberOr(m, "arrival_time_s"), 8) + " s after the start" +
                  (StringOr(m, "time_status") == "optimal"
                       ? std::string(", proven earliest")
                       : ", not before " + Sig(NumberOr(m, "arrival_bound_s"), 8) + " s") +
                  (m.value("verified", false) ? "; verified" : "; NOT verified")
            : "none found";
    os << Row("arrival (minimum time)", HtmlEscape(arrival));
  }
  if (summary.contains("consumption_l1_m_s") && summary.at("consumption_l1_m_s").is_number()) {
    os << Row("consumption", HtmlEscape(Sig(NumberOr(summary, "consumption_l1_m_s")) +
                                        " m/s (L1, thesis metric)"));
    os << Row("delta-v", HtmlEscape(Sig(NumberOr(summary, "delta_v_m_s")) + " m/s"));
    os << Row("propellant", HtmlEscape(Sig(NumberOr(summary, "propellant_kg")) + " kg"));
    if (s.impulsive()) {
      os << Row("impulses", std::to_string(summary.value("n_impulses", 0)));
    } else {
      double on = 0;  // on_time_s: seconds per thruster
      if (summary.contains("on_time_s") && summary.at("on_time_s").is_object()) {
        for (const auto& [name, v] : summary.at("on_time_s").items()) {
          if (v.is_number()) on += v.get<double>();
        }
      }
      os << Row("burns", std::to_string(summary.value("n_burns", 0)) + ", firing for " +
                             HtmlEscape(FormatDuration(on)) + " in total");
    }
  }
  os << Row("solver",
            HtmlEscape(StringOr(summary, "solver_version") + ", " +
                       FormatDuration(NumberOr(summary, "solve_seconds")) + " (total run " +
                       FormatDuration(NumberOr(summary, "total_seconds")) + ")"));
  os << Row("MILP", HtmlEscape(std::to_string(summary.value("n_binaries", 0)) + " binaries, " +
                               std::to_string(summary.value("n_rows", 0)) + " rows"));
  if (summary.contains("infeasibility_reasons") && summary.at("infeasibility_reasons").is_array()) {
    for (const auto& r : summary.at("infeasibility_reasons")) {
      if (r.is_string()) os << Row("reason", HtmlEscape(r.get<std::string>()));
    }
  }
  os << "</table>\n";

  os << "<h2>Checker</h2>\n"
     << CheckSection(s, summary.is_object() && summary.contains("check") ? summary.at("check")
                                                                         : nlohmann::json());

  os << "<h2>Plots</h2>\n"
     << Figures(
            dir,
            {{"window.svg", s.model_type == ModelType::kGeo
                                ? "Where the satellite went: longitude and latitude in the box"
                                : "Trajectory in the window plane (along-track y, normal z)"},
             {"xy.svg", "Radial against along-track (x-y)"},
             {"timeline.svg", s.impulsive() ? "Impulses per thruster" : "When each thruster fired"},
             {"outputs.svg", "The window outputs against time"}});

  const std::string table = CsvTable(dir + (s.impulsive() ? "/impulses.csv" : "/schedule.csv"));
  os << "<h2>Schedule</h2>\n";
  if (table.empty()) {
    os << "<p>No " << (s.impulsive() ? "impulse" : "burn") << ".</p>\n";
  } else {
    os << "<p class=\"note\">Times in seconds since the model epoch" << (s.geo ? " and in UTC" : "")
       << ".</p>\n<div class=\"tablewrap\">" << table << "</div>\n";
  }
  os << "</body>\n</html>\n";
  WriteOrThrow(dir + "/" + kReportName, os.str());
}

std::vector<std::string> YearReportFiles() {
  return {kReportName,       "gap.gp", "gap.svg", "thrust_days.gp",
          "thrust_days.svg", "box.gp", "box.svg"};
}

YearReport WriteYearReport(const std::string& dir, const Scenario& s, const nlohmann::json& year,
                           bool run_gnuplot) {
  YearReport out;
  // The year plots the other simulate plots do not show, by the same route
  // (a script kept beside the data, then gnuplot).
  auto header = [](const std::string& base, int width, int height) {
    return "# Generated by thrustsched simulate (report.html). Restyle, then: gnuplot " + base +
           ".gp\nset terminal svg size " + std::to_string(width) + "," + std::to_string(height) +
           " dynamic enhanced font 'sans,12' background rgb 'white'\nset output '" + base +
           ".svg'\nset datafile separator ','\nset grid\n";
  };
  const double w = s.window_half_widths.empty() ? 0.05 : s.window_half_widths[0];
  std::vector<std::pair<std::string, std::string>> scripts;
  {
    std::ostringstream os;
    os << header("gap", 1000, 450)
       << "set title 'optimality gap per cycle (proven distance to the best bound)'\n"
       << "set xlabel 'cycle'\nset ylabel 'gap (%)'\nset yrange [0:*]\nset key off\n"
       << "set style fill solid 0.6\nset boxwidth 0.8\n"
       << "# cycles.csv: col 1 cycle, col 9 gap (fraction)\n"
       << "plot 'cycles.csv' skip 1 using 1:(100*$9) with boxes lc rgb '#9467bd'\n";
    scripts.emplace_back("gap", os.str());
  }
  {
    std::ostringstream os;
    os << header("thrust_days", 800, 450) << "set title 'thrust-days per thruster'\n"
       << "set ylabel 'days of firing'\nset yrange [0:*]\nset key off\n"
       << "set style fill solid 0.6\nset boxwidth 0.6\n"
       << "$days << EOD\n";
    const nlohmann::json per =
        year.contains("thrust_days") && year.at("thrust_days").is_object()
            ? year.at("thrust_days").value("per_thruster", nlohmann::json::object())
            : nlohmann::json::object();
    for (const auto& t : s.problem.thrusters.thrusters()) {
      const double d =
          per.contains(t.name) && per.at(t.name).is_number() ? per.at(t.name).get<double>() : 0.0;
      os << t.name << "," << Sig(d, 10) << "\n";
    }
    os << "EOD\n"
       << "plot $days using 0:2:xtic(1) with boxes lc rgb '#1f77b4', \\\n"
       << "     $days using 0:2:(sprintf('%.3g', $2)) with labels offset 0,0.8 notitle\n";
    scripts.emplace_back("thrust_days", os.str());
  }
  {
    std::ostringstream os;
    os << header("box", 800, 860)
       << "set title 'the box over the run (nonlinear replay), colour: days since t_0'\n"
       << "set xlabel 'longitude - station (deg)'\nset ylabel 'latitude (deg)'\n"
       << "set size ratio -1\nset key below horizontal box\n"
       << "w = " << Sig(w, 10) << "\n"
       << "set object 1 rect from -w,-w to w,w fillstyle empty border lc rgb 'red' lw 2\n"
       << "set xrange [*<-1.15*w:1.15*w<*]\nset yrange [*<-1.15*w:1.15*w<*]\n"
       << "set cblabel 'days since t_0'\n"
       << "# trajectory.csv: col 2 day, col 3 lat_deg, col 4 lon_deg\n"
       << "plot 'trajectory.csv' skip 1 using 4:3:2 with lines lc palette lw 1 notitle, \\\n"
       << "     'trajectory.csv' skip 1 every ::0::0 using 4:3 with points pt 7 ps 1.5 lc rgb "
          "'black' "
          "title 'start', \\\n"
       << "     NaN with lines lc rgb 'red' lw 2 title 'window'\n";
    scripts.emplace_back("box", os.str());
  }
  std::vector<std::string> bases;
  for (const auto& [base, text] : scripts) {
    WriteTextFile(dir + "/" + base + ".gp", text);
    bases.push_back(base);
  }
  if (run_gnuplot && GnuplotAvailable()) out.images = RunGnuplotScripts(dir, bases, &out.message);

  // The page.
  std::ostringstream os;
  os << PageStart(s.name + " - thrustsched simulate");
  os << "<h1>" << HtmlEscape(s.name) << "</h1>\n";
  if (s.raw.is_object() && s.raw.contains("description") && s.raw.at("description").is_string()) {
    os << "<p class=\"lead\">" << HtmlEscape(s.raw.at("description").get<std::string>())
       << "</p>\n";
  }
  const nlohmann::json settings = year.value("settings", nlohmann::json::object());
  os << "<h2>Scenario</h2>\n" << ScenarioTable(s);
  os << "<table class=\"facts\">\n"
     << Row("cycles",
            HtmlEscape(std::to_string(year.value("cycles", 0)) + " of " +
                       std::to_string(year.value("cycles_total", 0)) + " (" +
                       StringOr(year, "mode") + ", " +
                       FormatDuration(NumberOr(settings, "cycle_s")) + " each, from " +
                       StringOr(year, "start_utc") + " UTC)" +
                       (year.value("complete", false) ? "" : "; the run is not complete")))
     << "</table>\n";

  os << "<h2>Result</h2>\n<table class=\"facts\">\n";
  os << Row("simulated", HtmlEscape(Sig(NumberOr(year, "simulated_days"), 5) + " days"));
  os << Row("consumption",
            HtmlEscape(Sig(NumberOr(year, "consumption_l1_m_s")) + " m/s (L1, thesis metric)"));
  os << Row("delta-v", HtmlEscape(Sig(NumberOr(year, "delta_v_m_s")) + " m/s, of which normal " +
                                  Sig(NumberOr(year, "normal_delta_v_m_s"), 5) + " m/s"));
  os << Row("propellant", HtmlEscape(Sig(NumberOr(year, "propellant_kg")) + " kg"));
  os << Row("burns", HtmlEscape(std::to_string(year.value("burns", 0))));
  const nlohmann::json td = year.value("thrust_days", nlohmann::json::object());
  os << Row(
      "thrust-days",
      HtmlEscape(Sig(NumberOr(td, "total"), 5) + " in total; N " + Sig(NumberOr(td, "north"), 4) +
                 ", S " + Sig(NumberOr(td, "south"), 4) + ", E " + Sig(NumberOr(td, "east"), 4) +
                 ", W " + Sig(NumberOr(td, "west"), 4)));
  const nlohmann::json gap = year.value("gap", nlohmann::json::object());
  const nlohmann::json solve = year.value("solve_seconds", nlohmann::json::object());
  os << Row("gap per cycle", HtmlEscape("median " + FormatPercent(NumberOr(gap, "median")) +
                                        ", max " + FormatPercent(NumberOr(gap, "max"))));
  os << Row("solve time per cycle",
            HtmlEscape("median " + FormatDuration(NumberOr(solve, "median")) + ", max " +
                       FormatDuration(NumberOr(solve, "max")) + "; wall " +
                       FormatDuration(NumberOr(year, "wall_seconds")) + " over all cycles"));
  const nlohmann::json fb = year.value("fallbacks", nlohmann::json::object());
  os << Row("fallbacks", HtmlEscape(Sig(NumberOr(fb, "total", 0), 6) + " cycle(s)"));
  os << "</table>\n";

  os << "<h2>Window (nonlinear replay)</h2>\n";
  const bool inside = !(NumberOr(year, "max_window_violation_deg", 0.0) > 0);
  os << "<p>" << Verdict(inside) << " "
     << HtmlEscape(inside
                       ? std::string("inside the box for the whole run")
                       : "outside by up to " + Sig(NumberOr(year, "max_window_violation_deg"), 3) +
                             " deg for " + FormatDuration(NumberOr(year, "time_outside_window_s")) +
                             " (first worst at " + StringOr(year, "worst_time_utc", "?") + " UTC)")
     << "; max |lat| " << HtmlEscape(Sig(NumberOr(year, "max_abs_lat_deg"), 4))
     << " deg, max |lon| " << HtmlEscape(Sig(NumberOr(year, "max_abs_lon_deg"), 4))
     << " deg.</p>\n";

  os << "<h2>Plots</h2>\n"
     << Figures(dir, {{"consumption.svg", "Consumption per cycle and cumulative"},
                      {"thrust_days.svg", "Thrust-days per thruster"},
                      {"box.svg", "The box over the run"},
                      {"latlon.svg", "Latitude and longitude against time"},
                      {"gap.svg", "Optimality gap per cycle"},
                      {"vectors.svg", "Inclination and eccentricity vectors"},
                      {"timeline.svg", "Firing timeline of one cycle"}});

  // Per-cycle table: the columns a reader scans (every column is in cycles.csv).
  const std::vector<std::vector<std::string>> rows = ReadCsv(dir + "/cycles.csv");
  os << "<h2>Cycles</h2>\n";
  if (rows.size() >= 2) {
    const std::vector<std::string>& head = rows[0];
    auto col = [&head](const std::string& name) {
      for (size_t i = 0; i < head.size(); ++i) {
        if (head[i] == name) return static_cast<int>(i);
      }
      return -1;
    };
    struct Column {
      const char* title;
      int index;
      char kind;  // 't' text, 'n' number, 'p' fraction as percent, 'd' duration (s)
    };
    const std::vector<Column> columns = {{"cycle", col("cycle"), 't'},
                                         {"start (UTC)", col("start_utc"), 't'},
                                         {"status", col("status"), 't'},
                                         {"fallback", col("fallback"), 't'},
                                         {"consumption (m/s)", col("consumption_l1_m_s"), 'n'},
                                         {"gap", col("gap"), 'p'},
                                         {"burns", col("burns"), 't'},
                                         {"max |lat| (deg)", col("max_abs_lat_deg"), 'n'},
                                         {"max |lon| (deg)", col("max_abs_lon_deg"), 'n'},
                                         {"outside", col("time_outside_window_s"), 'd'},
                                         {"solve", col("solve_s"), 'd'},
                                         {"note", col("note"), 't'}};
    os << "<div class=\"tablewrap\"><table class=\"data\">\n<thead><tr>";
    for (const Column& c : columns) os << "<th>" << HtmlEscape(c.title) << "</th>";
    os << "</tr></thead>\n<tbody>\n";
    for (size_t r = 1; r < rows.size(); ++r) {
      os << "<tr>";
      for (const Column& c : columns) {
        std::string v = c.index >= 0 && c.index < static_cast<int>(rows[r].size())
                            ? rows[r][static_cast<size_t>(c.index)]
                            : "";
        if (c.kind != 't' && !v.empty()) {
          char* end = nullptr;
          const double x = std::strtod(v.c_str(), &end);
          if (end != v.c_str()) {
            v = c.kind == 'p' ? FormatPercent(x) : c.kind == 'd' ? FormatDuration(x) : Sig(x, 5);
          }
        }
        os << "<td>" << HtmlEscape(v) << "</td>";
      }
      os << "</tr>\n";
    }
    os << "</tbody></table></div>\n";
  } else {
    os << "<p>No cycle finished.</p>\n";
  }
  os << "</body>\n</html>\n";
  WriteOrThrow(dir + "/" + kReportName, os.str());
  return out;
}

}  // namespace thrustsched::app
