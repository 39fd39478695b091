// The run's metadata: collected from the machine, kept in meta.json beside
// results.csv (so --report-only can regenerate the report), and written as the
// report's header.
#include <sys/utsname.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "benchmarks/bench/external_solvers.h"
#include "benchmarks/bench/report.h"
#include "benchmarks/bench/report_format.h"
#include "benchmarks/bench/report_sections.h"
#include "milp/cbc_solver.h"

namespace thrustsched::bench {
namespace {

std::string Capture(const std::string& cmd) {
  std::string out;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[512];
    while (fgets(buf, sizeof(buf), p)) out += buf;
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

}  // namespace

namespace report_internal {

void WriteHeader(std::ostream& md, const ReportMeta& m) {
  md << "# thrustsched-bench report\n\n";
  md << (m.quick ? "**Quick mode** (`--quick`): a miniature of every section to keep the tool "
                   "working; the numbers below are not the benchmark. The full report is "
                   "docs/bench/report.md.\n\n"
                 : "");
  // One line: which runs made the rows lives in meta.json (command, date,
  // revision, machine and load of each), not here.
  std::string first = m.date_utc;
  for (const EarlierRun& e : m.earlier) first = std::min(first, e.date_utc);
  md << "Provenance: ";
  if (m.earlier.empty()) {
    md << "one run, " << m.date_utc.substr(0, 10) << ", revision " << m.git_revision;
  } else {
    md << m.earlier.size() + 1 << " runs merged (" << first.substr(0, 10) << " to "
       << m.date_utc.substr(0, 10) << ")";
  }
  md << "; commands, dates, revisions, machines and loads in [meta.json](meta.json).\n\n";
  md << "Contents: [Summary](#summary) · [Targets](#targets) · [1. Accuracy](#1-accuracy) · "
        "[2. Cost per scheme](#2-cost-per-scheme) · "
        "[3. Formulations and encodings](#3-formulations-and-encodings) · "
        "[4. Scaling](#4-scaling) · [5. Operational constraints](#5-operational-constraints) · "
        "[6. One year](#6-one-year-of-station-keeping-thrustsched-simulate) · "
        "[7. Collision avoidance](#7-collision-avoidance-serra-2015-ch-4) · "
        "[8. Solver speed](#8-solver-speed-the-search-against-the-previous-release-and-cbc-alone) "
        "· [9. Campaigns](#9-campaigns-thrustsched-sweep-on-dask) · "
        "[10. Orbit transfers](#10-orbit-transfers-transfer) · "
        "[11. Random weeks](#11-random-weeks-the-search-on-weeks-nobody-chose) · "
        "[Method and definitions](#method-and-definitions) · "
        "[Not run or skipped](#not-run-or-skipped) · [Columns](#columns-of-resultscsv)\n\n";
}

}  // namespace report_internal

ReportMeta CollectMeta(int argc, char** argv, bool quick) {
  ReportMeta m;
  m.quick = quick;
  for (int i = 0; i < argc; ++i) {
    m.command += (i ? " " : "") + std::string(i == 0 ? "thrustsched-bench" : argv[i]);
  }
  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  m.date_utc = date;
  std::string cpu = Capture("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'");
  const std::string cores = Capture("nproc");
  const std::string mem =
      Capture("awk '/MemTotal/ {printf \"%.1f GB\", $2/1048576}' /proc/meminfo");
  utsname u{};
  uname(&u);
  m.machine = (cpu.empty() ? "unknown CPU" : cpu) + ", " + cores + " cores (nproc), " + mem +
              " RAM, " + u.sysname + " " + u.release;
  m.load_average = Capture("cut -d' ' -f1-3 /proc/loadavg");
  m.git_revision =
      Capture("git -C '" THRUSTSCHED_SOURCE_DIR "' rev-parse --short HEAD 2>/dev/null");
  if (m.git_revision.empty())
    m.git_revision = "unknown";
  else if (!Capture("git -C '" THRUSTSCHED_SOURCE_DIR "' status --porcelain 2>/dev/null").empty())
    m.git_revision += " (with uncommitted changes)";
  m.solver = milp::CbcVersion();
  std::string ext;
  const std::string cbc =
      Capture("command -v cbc >/dev/null 2>&1 && echo quit | cbc 2>/dev/null | grep -m1 Version");
  const std::string glp = Capture("glpsol --version 2>/dev/null | head -1");
  ext += cbc.empty() ? "cbc program not found" : "cbc program (" + cbc + ")";
  ext += ", ";
  ext += glp.empty() ? "glpsol not found" : glp;
  ext += ", " + HighsVersionNote();
  m.external = ext;
  m.build_type = THRUSTSCHED_BUILD_TYPE;
  return m;
}

void WriteMetaJson(const std::string& path, const ReportMeta& m) {
  const nlohmann::json j = {{"command", m.command},
                            {"date_utc", m.date_utc},
                            {"machine", m.machine},
                            {"load_average", m.load_average},
                            {"git_revision", m.git_revision},
                            {"solver", m.solver},
                            {"external", m.external},
                            {"build_type", m.build_type},
                            {"quick", m.quick},
                            {"threads", m.threads},
                            {"time_limit_s", m.time_limit_s},
                            {"scenario_glob", m.scenario_glob},
                            {"total_wall_s", m.total_wall_s}};
  nlohmann::json j2 = j;
  j2["cases_glob"] = m.cases_glob;
  nlohmann::json earlier = nlohmann::json::array();
  for (const EarlierRun& e : m.earlier) {
    earlier.push_back({{"command", e.command},
                       {"date_utc", e.date_utc},
                       {"git_revision", e.git_revision},
                       {"load_average", e.load_average},
                       {"machine", e.machine},
                       {"cases_glob", e.cases_glob},
                       {"total_wall_s", e.total_wall_s}});
  }
  if (!earlier.empty()) j2["earlier_runs"] = earlier;
  std::ofstream out(path);
  out << j2.dump(2) << "\n";
  if (!out) throw std::runtime_error("cannot write " + path);
}

ReportMeta ReadMetaJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  const nlohmann::json j = nlohmann::json::parse(in);
  ReportMeta m;
  m.command = j.value("command", "");
  m.date_utc = j.value("date_utc", "");
  m.machine = j.value("machine", "");
  m.load_average = j.value("load_average", "");
  m.git_revision = j.value("git_revision", "");
  m.solver = j.value("solver", "");
  m.external = j.value("external", "");
  m.build_type = j.value("build_type", "");
  m.quick = j.value("quick", false);
  m.threads = j.value("threads", 0);
  m.time_limit_s = j.value("time_limit_s", 0.0);
  m.scenario_glob = j.value("scenario_glob", "*");
  m.total_wall_s = j.value("total_wall_s", 0.0);
  m.cases_glob = j.value("cases_glob", "*");
  if (j.contains("earlier_runs")) {
    for (const auto& e : j.at("earlier_runs")) {
      EarlierRun r;
      r.command = e.value("command", "");
      r.date_utc = e.value("date_utc", "");
      r.git_revision = e.value("git_revision", "");
      r.load_average = e.value("load_average", "");
      r.machine = e.value("machine", "");
      r.cases_glob = e.value("cases_glob", "*");
      r.total_wall_s = e.value("total_wall_s", 0.0);
      m.earlier.push_back(std::move(r));
    }
  }
  return m;
}

}  // namespace thrustsched::bench
