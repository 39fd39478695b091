// Report section 6: the year simulations (year.json of each `thrustsched simulate` run).
#include "benchmarks/bench/report_sections.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "benchmarks/bench/reference_figures.h"

#include "benchmarks/bench/report_format.h"
#include "benchmarks/bench/report_index.h"
#include "benchmarks/bench/report_plotter.h"

namespace thrustsched::bench::report_internal {

namespace {

namespace fs = std::filesystem;

// The run directories of m.year_results_dir that hold a year.json, sorted.
std::vector<fs::path> YearRuns(const ReportMeta& m) {
  std::vector<fs::path> runs;
  if (!m.year_results_dir.empty() && fs::is_directory(m.year_results_dir)) {
    for (const auto& e : fs::directory_iterator(m.year_results_dir)) {
      if (fs::exists(e.path() / "year.json")) runs.push_back(e.path());
    }
  }
  std::sort(runs.begin(), runs.end());
  return runs;
}

// The directory as the report names it: relative to the source tree when
// inside it, so the report does not depend on where the tree was checked out.
std::string Shown(const std::string& dir) {
  std::error_code ec;
  const fs::path abs = fs::weakly_canonical(dir, ec);
  const fs::path src = fs::weakly_canonical(THRUSTSCHED_SOURCE_DIR, ec);
  const fs::path rel = abs.lexically_relative(src);
  if (ec || rel.empty() || *rel.begin() == "..") return dir;
  return rel.string();
}

}  // namespace

double NominalYearWallS(const ReportMeta& m) {
  for (const fs::path& dir : YearRuns(m)) {
    try {
      std::ifstream in(dir / "year.json");
      const nlohmann::json y = nlohmann::json::parse(in);
      if (y.value("scenario", "") == "year_anzel4_fixed" && y.value("complete", false) &&
          y.contains("wall_seconds") && y["wall_seconds"].is_number()) {
        return y["wall_seconds"].get<double>();
      }
    } catch (const std::exception&) {
      // WriteYear names the unreadable file in its table.
    }
  }
  return kNaN;
}

void WriteYear(std::ostream& md, const ReportMeta& m, const BenchReference& ref) {
  md << "## 6. One year of station keeping (`thrustsched simulate`)\n\n";
  const std::vector<fs::path> runs = YearRuns(m);
  if (runs.empty()) {
    md << "No year results in `" << Shown(m.year_results_dir)
       << "` (run `scripts/run_year_validation.sh`, then copy the run directories there).\n\n";
    return;
  }
  // Published figures by scenario file (data/reference/thesis_chapter5.json).
  std::map<std::string, std::pair<double, std::string>> published;
  try {
    std::ifstream in(m.year_reference_path);
    const nlohmann::json ref = nlohmann::json::parse(in);
    for (const auto& [key, v] : ref.at("results").items()) {
      if (!v.contains("scenario")) continue;
      const std::string stem = fs::path(v.at("scenario").get<std::string>()).stem().string();
      std::string where = v.contains("table") ? v.at("table").get<std::string>() : "";
      if (v.contains("lines"))
        where += (where.empty() ? "" : ", ") + v.at("lines").get<std::string>();
      published[stem] = {v.at("l1_m_s").get<double>(), where};
    }
  } catch (const std::exception& e) {
    md << "(published figures unavailable: " << e.what() << ")\n\n";
  }
  md << "Each row is one `thrustsched simulate` run of a scenario in data/scenarios/year/ "
        "(weekly MILPs closed through the nonlinear model), read from its `year.json` in `"
     << Shown(m.year_results_dir)
     << "`; docs/year_results.md discusses them. Consumption in the thesis L1 metric; window "
        "figures on the nonlinear replay (±0.05 deg); solve times per cycle (all attempts), "
        "wall and CPU over the whole run.\n\n";
  MdTable t({"scenario", "cycles", "L1 (m/s)", "thesis", "ours/thesis", "normal dv (m/s)",
             "thrust days (N / S / E / W)", "outside window", "max lat / lon (deg)", "fallbacks",
             "solve s median / p90 / max", "gap median / max", "wall (h)", "CPU (h)"});
  for (const fs::path& dir : runs) {
    nlohmann::json y;
    try {
      std::ifstream in(dir / "year.json");
      y = nlohmann::json::parse(in);
    } catch (const std::exception& e) {
      t.Add({dir.filename().string(), std::string("unreadable year.json: ") + e.what()});
      continue;
    }
    auto num = [&y](const nlohmann::json& v) { return v.is_number() ? v.get<double>() : kNaN; };
    const std::string name = y.value("scenario", dir.filename().string());
    const double l1 = num(y["consumption_l1_m_s"]);
    const auto pub = published.find(name);
    const bool complete = y.value("complete", false);
    const nlohmann::json& td = y["thrust_days"];
    const nlohmann::json& sol = y["solve_seconds"];
    const nlohmann::json& gap = y["gap"];
    const double outside = num(y["time_outside_window_s"]);
    t.Add({name,
           std::to_string(y.value("cycles", 0)) + "/" + std::to_string(y.value("cycles_total", 0)) +
               (complete ? "" : " (incomplete)"),
           G(l1, 5),
           pub == published.end() ? std::string("-")
                                  : G(pub->second.first, 4) + " (" + pub->second.second + ")",
           // A ratio only for a whole year: a partial run's consumption is not comparable.
           pub == published.end() || !complete ? std::string("-") : G(l1 / pub->second.first, 4),
           G(num(y["normal_delta_v_m_s"]), 4),
           G(num(td["total"]), 4) + " (" + G(num(td["north"]), 3) + " / " + G(num(td["south"]), 3) +
               " / " + G(num(td["east"]), 3) + " / " + G(num(td["west"]), 3) + ")",
           outside > 0 ? G(outside, 4) + " s, by up to " + Sci(num(y["max_window_violation_deg"])) +
                             " deg (worst " + y.value("worst_time_utc", std::string("?")) + ")"
                       : std::string("0 s (box held)"),
           G(num(y["max_abs_lat_deg"]), 4) + " / " + G(num(y["max_abs_lon_deg"]), 4),
           std::to_string(y["fallbacks"].value("total", 0)),
           G(num(sol["median"]), 3) + " / " + G(num(sol["p90"]), 3) + " / " + G(num(sol["max"]), 3),
           Pct(num(gap["median"])) + " / " + Pct(num(gap["max"])),
           G(num(y["wall_seconds"]) / 3600.0, 3), G(num(y["cpu_seconds"]) / 3600.0, 3)});
  }
  md << t.Str();
  md << "\nTarget: the nominal year (year_anzel4_fixed) in under "
     << G(ref.target_year_wall_s / 60.0) << " minutes of wall time on this 2-core machine; "
     << "the thesis needed about " << std::lround(ref.thesis_seconds_per_cycle)
     << " s per cycle with Gurobi (Table 5.3; about "
     << G(ref.thesis_seconds_per_cycle * 53.0 / 3600.0, 2) << " hours). ";
  const double nominal_wall_s = NominalYearWallS(m);
  if (nominal_wall_s > 0.0) {
    md << "Measured: " << G(nominal_wall_s / 60.0, 3) << " min, "
       << Verdict(nominal_wall_s, ref.target_year_wall_s) << ".\n\n";
  } else {
    md << "The nominal year is not among the runs above.\n\n";
  }
}

}  // namespace thrustsched::bench::report_internal
