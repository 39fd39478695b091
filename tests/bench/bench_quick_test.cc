// Runs `thrustsched-bench --quick` into a temporary directory and checks
// that results.csv has every contract column, that report.md has every
// section, and that the numbers in it are right where an independent value is
// known: the thesis Table 4.1 one-day optimum (one 5-min slot, 0.016392 m/s),
// the textbook orders of the schemes on HCW, the external solvers' objective
// and the independent checker's verdict; that report.md fits in 200-character
// lines, opens with the Summary and links meta.json and the step logs. One test (one run of the
// binary): ctest runs each TEST in its own process.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "benchmarks/bench/external_solvers.h"
#include "benchmarks/bench/report.h"
#include "benchmarks/bench/results.h"

namespace thrustsched::bench {
namespace {

namespace fs = std::filesystem;

std::string ReadAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int RunCommand(const std::string& cmd) {
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

const Row* Find(const std::vector<Row>& rows, const std::map<std::string, std::string>& match) {
  for (const Row& r : rows) {
    bool ok = true;
    for (const auto& [k, v] : match) ok = ok && r.Get(k) == v;
    if (ok) return &r;
  }
  return nullptr;
}

TEST(BenchQuick, WritesResultsAndReportWithCorrectNumbers) {
  const fs::path dir =
      fs::temp_directory_path() / ("thrustsched_bench_quick_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string log = (dir.string() + ".log");
  ASSERT_EQ(RunCommand(std::string("'") + THRUSTSCHED_BENCH + "' --quick --out '" + dir.string() +
                       "' > '" + log + "' 2>&1"),
            0)
      << ReadAll(log);

  // results.csv: the header has every contract column.
  std::ifstream csv(dir / "results.csv");
  std::string header;
  ASSERT_TRUE(std::getline(csv, header));
  const std::vector<std::string> cols = SplitCsvLine(header);
  const std::set<std::string> col_set(cols.begin(), cols.end());
  for (const std::string& c : ContractColumns()) EXPECT_TRUE(col_set.count(c)) << "column " << c;
  const std::vector<Row> rows = ReadResultsCsv((dir / "results.csv").string());
  ASSERT_GT(rows.size(), 20u);
  for (const Row& r : rows) {
    EXPECT_NE(r.Get("status"), "error") << r.Get("case_id") << ": " << r.Get("note");
    EXPECT_NE(r.Get("status"), "crashed") << r.Get("case_id");
    EXPECT_NE(r.Get("status"), "killed") << r.Get("case_id");
  }

  // Every scheme appears in the accuracy study, on both models.
  for (const char* model : {"hcw", "geo"}) {
    for (const char* scheme : {"exact_zoh", "frozen_start", "frozen_mid", "hermite_simpson", "rk4",
                               "trapezoid", "euler"}) {
      EXPECT_NE(Find(rows, {{"section", "accuracy"}, {"model", model}, {"scheme", scheme}}),
                nullptr)
          << model << " " << scheme;
    }
  }
  // Observed one-step orders on HCW (time-invariant, exact reference):
  // RK4 / Hermite-Simpson Phi p+1 = 5, Gamma p = 4; trapezoid 3 / 2; Euler 2 / 1.
  const std::map<std::string, std::pair<double, double>> orders = {
      {"rk4", {5, 4}}, {"hermite_simpson", {5, 4}}, {"trapezoid", {3, 2}}, {"euler", {2, 1}}};
  for (const auto& [scheme, o] : orders) {
    const Row* r = Find(rows, {{"section", "accuracy"}, {"model", "hcw"}, {"scheme", scheme}});
    ASSERT_NE(r, nullptr) << scheme;
    EXPECT_NEAR(r->Num("observed_order_phi"), o.first, 0.15) << scheme;
    EXPECT_NEAR(r->Num("observed_order_gamma"), o.second, 0.15) << scheme;
  }
  // exact_zoh on HCW is the exact exponential: at the reference's floor.
  const Row* ez = Find(rows, {{"section", "accuracy"}, {"model", "hcw"}, {"scheme", "exact_zoh"}});
  ASSERT_NE(ez, nullptr);
  EXPECT_LT(ez->Num("max_rel_err_phi"), 1e-11);

  // Table 4.1, one day: optimum = one 5-min slot of an ideal thruster (thesis 0.0164),
  // in all four formulation x encoding combinations.
  const double slot = 0.265 / 4850 * 300;
  for (const char* f : {"sparse", "condensed"}) {
    for (const char* e : {"tight", "thesis"}) {
      const Row* r = Find(rows, {{"section", "formulation"},
                                 {"scenario", "hcw_table41_1d"},
                                 {"formulation", f},
                                 {"encoding", e}});
      ASSERT_NE(r, nullptr) << f << " " << e;
      EXPECT_EQ(r->Get("status"), "optimal") << f << " " << e;
      EXPECT_NEAR(r->Num("objective"), slot, 1e-9) << f << " " << e;
      EXPECT_NEAR(r->Num("consumption_l1_m_s"), slot, 1e-9);
      EXPECT_NEAR(r->Num("ratio"), slot / 0.0164, 1e-6);
      EXPECT_LE(r->Num("lp_bound"), r->Num("objective") + 1e-9);
      EXPECT_EQ(r->Get("operational_ok"), "1");
      EXPECT_LE(r->Num("max_window_violation_nodes"), 1e-3 * 36800);
      EXPECT_GT(r->Num("n_binaries"), 0);
      EXPECT_GT(r->Num("peak_rss_mb"), 1.0);
    }
  }
  // The condensed formulation has more nonzeros than the sparse one (O(N^2)).
  EXPECT_GT(
      Find(rows, {{"section", "formulation"}, {"formulation", "condensed"}})->Num("n_nonzeros"),
      Find(rows, {{"section", "formulation"}, {"formulation", "sparse"}})->Num("n_nonzeros"));
  // The external cross-check, where the programs are installed, finds the same optimum.
  const Row* x = Find(rows, {{"section", "formulation"},
                             {"scenario", "hcw_table41_1d"},
                             {"formulation", "sparse"},
                             {"encoding", "tight"}});
  ASSERT_NE(x, nullptr);
  // HiGHS (npm highs, installed by scripts/install-highs.sh) is skipped with
  // its reason where node or the package is missing.
  for (const std::string& p : ExternalSolverNames()) {
    const std::string st = x->Get("ext_" + p + "_status");
    EXPECT_FALSE(st.empty()) << p;
    if (st == "not installed" || st.rfind("skipped: ", 0) == 0) {
      std::cout << "note: " << p << " " << st << "\n";
      continue;
    }
    EXPECT_NEAR(x->Num("ext_" + p + "_objective"), slot, 1e-6) << p << " " << st;
    EXPECT_GT(x->Num("ext_" + p + "_s"), 0.0) << p;
  }
  if (x->Get("ext_highs_status") == "optimal") {
    EXPECT_NEAR(x->Num("ext_highs_bound"), slot, 1e-6);
    EXPECT_NEAR(x->Num("ext_highs_gap"), 0.0, 1e-6);
  }
  // No external solver beats our proven optimum (or a published one) on our model.
  for (const Row& r : rows) {
    for (const std::string& p : ExternalSolverNames()) {
      EXPECT_EQ(ExternalBeatsOptimum(r, p), "") << r.Get("case_id");
    }
  }
  // Operational rules off cannot cost more; a 10-min minimum burn is two slots here.
  const Row* off = Find(rows, {{"section", "operations"}, {"variant", "rules_off"}});
  ASSERT_NE(off, nullptr);
  EXPECT_LE(off->Num("objective"), slot + 1e-9);
  // GEO solves are replayed through the nonlinear simulator.
  const Row* geo = Find(rows, {{"section", "scheme_solve"}, {"scheme", "hermite_simpson"}});
  ASSERT_NE(geo, nullptr);
  EXPECT_TRUE(geo->Has("max_window_violation_nonlinear_deg"));
  EXPECT_EQ(geo->Get("window_unit"), "deg");
  // The solver-speed arms on Table 4.2, t1 = 2 d: the search and its ablation
  // with the lazy rows' first LP unpresolved both reach the published optimum
  // (1.721 m/s, to the thesis's four digits).
  for (const char* path : {"search", "search_lazy_lp_unpresolved"}) {
    const Row* s = Find(rows, {{"section", "solver_speed"}, {"solver_path", path}});
    ASSERT_NE(s, nullptr) << path;
    EXPECT_EQ(s->Get("scenario"), "hcw_table42_t1_2d") << path;
    EXPECT_EQ(s->Get("status"), "optimal") << path;
    EXPECT_NEAR(s->Num("objective"), 1.721, 5e-4) << path;
    EXPECT_EQ(s->Get("operational_ok"), "1") << path;
  }
  EXPECT_NEAR(
      Find(rows, {{"section", "solver_speed"}, {"solver_path", "search"}})->Num("objective"),
      Find(rows, {{"section", "solver_speed"}, {"solver_path", "search_lazy_lp_unpresolved"}})
          ->Num("objective"),
      1e-9);

  // report.md: every section, and the quick-mode banner.
  const std::string report = ReadAll((dir / "report.md").string());
  for (const char* h :
       {"# thrustsched-bench report", "## Targets", "## 1. Accuracy", "## 2. Cost per scheme",
        "## 3. Formulations and encodings", "### 3.1 Design choices",
        "### 3.2 Cross-check with other solvers", "## 4. Scaling", "## 5. Operational constraints",
        "## Method and definitions", "## Not run or skipped", "## Columns of results.csv",
        "Quick mode"}) {
    EXPECT_NE(report.find(h), std::string::npos) << "missing: " << h;
  }
  EXPECT_NE(report.find("| hcw_table41_1d | sparse | tight |"), std::string::npos);
  EXPECT_NE(report.find("### 8.1 Ablation: the lazy rows' first LP without presolve\n\n`LazyRow"
                        "Options::presolve_lp_relaxation`"),
            std::string::npos);
  EXPECT_NE(report.find("| hcw_table42_t1_2d-1thread | time to a proven 1 % gap | "),
            std::string::npos);
  // No line longer than the limit; the Summary first, with the solver-speed
  // target of the quick run; the search's steps in their log, linked.
  {
    std::istringstream lines(report);
    int n = 0;
    for (std::string l; std::getline(lines, l);) {
      ++n;
      size_t chars = 0;
      for (unsigned char c : l) chars += (c & 0xC0) != 0x80;
      EXPECT_LE(chars, kReportMaxLineChars) << "report.md line " << n << ": " << l;
    }
  }
  EXPECT_LT(report.find("## Summary\n"), report.find("## Targets\n"));
  EXPECT_NE(report.find("| search, hcw_table42_t1_2d-1thread: time to a proven 1 % gap | < 2 s | "),
            std::string::npos);
  const std::string steps_log = "logs/solver_speed-hcw_table42_t1_2d-1thread-search.log";
  EXPECT_NE(report.find("(" + steps_log + ")"), std::string::npos);
  EXPECT_NE(ReadAll((dir / steps_log).string()).find("\nrelaxation: LP bound "), std::string::npos);
  // Provenance: meta.json holds it; the report links it in one line.
  const ReportMeta meta = ReadMetaJson((dir / "meta.json").string());
  EXPECT_NE(meta.command.find("--quick"), std::string::npos);
  EXPECT_FALSE(meta.date_utc.empty());
  EXPECT_FALSE(meta.git_revision.empty());
  EXPECT_FALSE(meta.machine.empty());
  EXPECT_NE(report.find("Provenance: one run, " + meta.date_utc.substr(0, 10)), std::string::npos);
  EXPECT_NE(report.find("[meta.json](meta.json)"), std::string::npos);
  EXPECT_EQ(report.find(meta.machine), std::string::npos);
  // Section 9 comes from campaigns.md (benchmarks/campaign_scaling.py): absent here.
  EXPECT_NE(report.find("## 9. Campaigns (`thrustsched-sweep` on Dask)\n\nNot measured in this "
                        "folder: `PYTHONPATH=build/python"),
            std::string::npos);
  // The cross-check table (split into parts when its cells are wide, e.g. a
  // long "HiGHS skipped: <reason>"; each part repeats the scenario).
  EXPECT_NE(report.find("| scenario | ours | cbc program | glpsol |"), std::string::npos);
  EXPECT_NE(report.find(" | HiGHS |"), std::string::npos);
  EXPECT_NE(report.find(" | agreement |\n|---"), std::string::npos);
  // The report can be regenerated from the CSV alone.
  fs::remove(dir / "report.md");
  ASSERT_EQ(RunCommand(std::string("'") + THRUSTSCHED_BENCH + "' --report-only --out '" +
                       dir.string() + "' > '" + log + "' 2>&1"),
            0)
      << ReadAll(log);
  EXPECT_EQ(ReadAll((dir / "report.md").string()), report);
  // With a campaigns.md beside it, section 9 carries it over, headings one level down.
  std::ofstream(dir / "campaigns.md") << "# Campaign engine scaling\n\nMeasured x.\n\n"
                                         "## On paper\n\n| cores | wall (h) |\n";
  ASSERT_EQ(RunCommand(std::string("'") + THRUSTSCHED_BENCH + "' --report-only --out '" +
                       dir.string() + "' > '" + log + "' 2>&1"),
            0)
      << ReadAll(log);
  EXPECT_NE(ReadAll((dir / "report.md").string())
                .find("## 9. Campaigns (`thrustsched-sweep` on Dask)\n\nMeasured x.\n\n"
                      "### On paper\n\n| cores | wall (h) |\n"),
            std::string::npos);
  fs::remove(dir / "campaigns.md");
  // Section 6 reads year.json files: a whole nominal year gets a ratio to the
  // published 129.2 m/s and the 30-min verdict; a partial run gets no ratio.
  const fs::path years = dir / "years";
  fs::create_directories(years / "year_anzel4_fixed");
  fs::create_directories(years / "year_anzel4_failed_ne");
  auto write_year = [](const fs::path& file, const std::string& name, bool complete, double l1,
                       double wall_s) {
    std::ofstream(file) << R"({"scenario": ")" << name << R"(", "complete": )"
                        << (complete ? "true" : "false") << R"(, "cycles": )"
                        << (complete ? 53 : 18) << R"(, "cycles_total": 53,
      "consumption_l1_m_s": )"
                        << l1 << R"(, "normal_delta_v_m_s": 40.0,
      "thrust_days": {"total": 19.2, "north": 9.6, "south": 9.6, "east": 11.5, "west": 7.7},
      "time_outside_window_s": 0, "max_window_violation_deg": 0, "max_abs_lat_deg": 0.0497,
      "max_abs_lon_deg": 0.0497, "fallbacks": {"total": 0},
      "solve_seconds": {"median": 20, "p90": 40, "max": 100},
      "gap": {"median": 0.004, "max": 0.02}, "wall_seconds": )"
                        << wall_s << R"(, "cpu_seconds": 900})";
  };
  write_year(years / "year_anzel4_fixed" / "year.json", "year_anzel4_fixed", true, 129.2 * 1.01,
             1500.0);
  write_year(years / "year_anzel4_failed_ne" / "year.json", "year_anzel4_failed_ne", false, 44.0,
             1400.0);
  ASSERT_EQ(
      RunCommand(std::string("'") + THRUSTSCHED_BENCH + "' --report-only --out '" + dir.string() +
                 "' --year-results '" + years.string() + "' > '" + log + "' 2>&1"),
      0)
      << ReadAll(log);
  const std::string with_years = ReadAll((dir / "report.md").string());
  EXPECT_NE(with_years.find("| year_anzel4_fixed | 53/53 | 130.49 | 129.2 (L5127) | 1.01 | 40 | "
                            "19.2 (9.6 / 9.6 / 11.5 / 7.7) | 0 s (box held) |"),
            std::string::npos)
      << with_years;
  EXPECT_NE(with_years.find("| year_anzel4_failed_ne | 18/53 (incomplete) | 44 | 176 (Table 5.7, "
                            "L5289-L5311) | - | 40 |"),
            std::string::npos);
  std::string flat = with_years;  // prose is wrapped: compare it as one line
  std::replace(flat.begin(), flat.end(), '\n', ' ');
  EXPECT_NE(flat.find("Measured: 25 min, met (83.3 % of the limit)"), std::string::npos);
  // Bad input: exit code 2.
  EXPECT_EQ(
      RunCommand(std::string("'") + THRUSTSCHED_BENCH + "' --quick --threads 0 > /dev/null 2>&1"),
      2);
  EXPECT_EQ(RunCommand(std::string("'") + THRUSTSCHED_BENCH +
                       "' --quick --scenarios no_such_scenario --out '" + dir.string() +
                       "/x' > /dev/null 2>&1"),
            2);
  fs::remove_all(dir);
  fs::remove(log);
}

}  // namespace
}  // namespace thrustsched::bench
