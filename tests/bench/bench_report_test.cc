// Tests of report.md's shape: no line longer than kReportMaxLineChars (in the
// committed docs/bench/report.md and in the report regenerated from the
// committed results.csv), the Summary with one row per performance target
// and the right verdicts (synthetic rows with known medians), the provenance
// in meta.json and not in the report, the table splitting and the prose
// wrapping that keep lines short.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/report.h"
#include "benchmarks/bench/report_format.h"
#include "benchmarks/bench/report_random_weeks.h"
#include "benchmarks/bench/report_transfer.h"
#include "benchmarks/bench/results.h"

namespace thrustsched::bench {
namespace {

namespace fs = std::filesystem;

const std::string kSource = THRUSTSCHED_SOURCE_DIR;

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// The report's prose with the wrapping undone: a line that continues a
// paragraph or a list item is joined to the one before by a space.
std::string Flow(const std::string& md) {
  std::string out, prev;
  for (const std::string& l : Lines(md)) {
    const size_t first = l.find_first_not_of(' ');
    const bool block = first == std::string::npos || l[first] == '|' || l[first] == '#' ||
                       l.compare(first, 2, "- ") == 0 || l.compare(first, 3, "```") == 0;
    const bool prev_prose = !prev.empty() && prev[0] != '|' && prev[0] != '#';
    if (!block && prev_prose) {
      out += " " + l.substr(first);
    } else {
      out += (out.empty() ? "" : "\n") + l;
    }
    prev = l;
  }
  return out + "\n";
}

// Code points, counted here independently of report_format's CharCount.
size_t Utf8Length(const std::string& s) {
  size_t n = 0;
  for (size_t i = 0; i < s.size(); ++n) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    i += c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
  }
  return n;
}

void ExpectNoLongLine(const std::string& text, const std::string& what) {
  int n = 0;
  for (const std::string& l : Lines(text)) {
    ++n;
    EXPECT_LE(Utf8Length(l), kReportMaxLineChars) << what << " line " << n << ": " << l;
  }
}

// The body rows of the Markdown table under "## Summary".
std::vector<std::string> SummaryRows(const std::string& report) {
  std::vector<std::string> rows;
  bool in = false;
  int table_line = 0;
  for (const std::string& l : Lines(report)) {
    if (l.rfind("## ", 0) == 0) in = l == "## Summary";
    if (!in) continue;
    if (l.rfind("|", 0) != 0) {
      if (table_line > 0) break;
      continue;
    }
    if (++table_line > 2) rows.push_back(l);  // after the header and its rule
  }
  return rows;
}

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("bench_report_test_" + std::to_string(getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

TEST(BenchReport, CommittedReportHasNoLineLongerThanTheLimit) {
  const std::string report = ReadAll(kSource + "/docs/bench/report.md");
  ASSERT_FALSE(report.empty());
  ExpectNoLongLine(report, "docs/bench/report.md");
}

// The committed results.csv and meta.json through the report generator:
// every line short, one Summary row per target, provenance in meta.json only.
TEST(BenchReport, RegeneratedFromTheCommittedResultsFitsAndSummarisesEveryTarget) {
  const TempDir tmp;
  const std::vector<Row> rows = ReadResultsCsv(kSource + "/docs/bench/results.csv");
  ReportMeta meta = ReadMetaJson(kSource + "/docs/bench/meta.json");
  meta.year_results_dir = kSource + "/docs/year";
  meta.year_reference_path = kSource + "/data/reference/thesis_chapter5.json";
  WriteReport(tmp.path().string(), rows, meta);
  const std::string report = ReadAll(tmp.path() / "report.md");
  ExpectNoLongLine(report, "regenerated report.md");

  // The Summary comes first, before the sections.
  EXPECT_LT(report.find("## Summary"), report.find("## Targets"));
  // Targets, counted from the rows: the discretise and build targets, the two
  // CBC-alone solve targets, each timed target of a solver-speed case (its
  // target_1pct_s / target_opt_s), one row for all the gap targets (the hard
  // weeks), the year.
  std::set<std::string> seen;
  int timed = 0, gap_cases = 0;
  std::map<std::string, std::vector<const Row*>> hard;
  for (const Row& r : rows) {
    if (r.Get("section") != kSectionSolverSpeed || r.Get("solver_path") != "search") continue;
    if (r.Has("target_gap")) hard[r.Get("case_id")].push_back(&r);
    if (!seen.insert(r.Get("case_id")).second) continue;
    timed += r.Has("target_1pct_s") + r.Has("target_opt_s");
    gap_cases += r.Has("target_gap");
  }
  ASSERT_GT(timed, 0);
  ASSERT_GT(gap_cases, 0);
  const std::vector<std::string> summary = SummaryRows(report);
  EXPECT_EQ(summary.size(), 4u + timed + 1u + 1u) << report.substr(0, 4000);
  // The hard weeks' row: how many met, computed here from the rows (a run
  // meets the target if it ends within the gap; the median over repeats,
  // not reached = infinite, below the limit).
  int met = 0;
  for (const auto& [id, runs] : hard) {
    std::vector<double> t;
    for (const Row* r : runs) {
      t.push_back(r->Num("gap") <= r->Num("target_gap") + 1e-12
                      ? r->Num("solve_s")
                      : std::numeric_limits<double>::infinity());
    }
    std::sort(t.begin(), t.end());
    const double median =
        t.size() % 2 ? t[t.size() / 2] : 0.5 * (t[t.size() / 2 - 1] + t[t.size() / 2]);
    met += median < runs.front()->Num("target_gap_s");
  }
  const std::string hard_row = "| search, hard weeks (" + std::to_string(gap_cases) + "): each ";
  bool found = false;
  for (const std::string& l : summary) {
    if (l.rfind(hard_row, 0) != 0) continue;
    found = true;
    EXPECT_NE(l.find(std::to_string(met) + " of " + std::to_string(gap_cases) + " met"),
              std::string::npos)
        << l;
  }
  EXPECT_TRUE(found) << hard_row;

  // Provenance: one line linking meta.json, naming how many runs; none of the
  // earlier runs' commands or machines in the report.
  ASSERT_FALSE(meta.earlier.empty());
  EXPECT_NE(report.find("Provenance: " + std::to_string(meta.earlier.size() + 1) + " runs merged"),
            std::string::npos);
  EXPECT_NE(report.find("[meta.json](meta.json)"), std::string::npos);
  for (const EarlierRun& e : meta.earlier) {
    EXPECT_EQ(report.find(e.command), std::string::npos) << e.command;
    EXPECT_EQ(report.find(e.date_utc), std::string::npos) << e.date_utc;
  }
  EXPECT_EQ(report.find(meta.machine), std::string::npos);

  // The steps of each solver-speed case's search arm are in its log, linked.
  for (const std::string& id : seen) {
    const std::string log = "logs/" + id + ".log";
    EXPECT_NE(report.find("(" + log + ")"), std::string::npos) << log;
    const std::string text = ReadAll(tmp.path() / log);
    EXPECT_NE(text.find("## " + id + ", repeat 0"), std::string::npos) << log;
  }
}

TEST(BenchReport, CommittedMetaJsonHoldsTheProvenanceOfEveryRun) {
  const ReportMeta meta = ReadMetaJson(kSource + "/docs/bench/meta.json");
  EXPECT_FALSE(meta.command.empty());
  EXPECT_FALSE(meta.git_revision.empty());
  EXPECT_FALSE(meta.machine.empty());
  for (const EarlierRun& e : meta.earlier) {
    EXPECT_FALSE(e.command.empty());
    EXPECT_EQ(e.date_utc.size(), 20u) << e.date_utc;  // 2026-11-22T06:43:50Z
    EXPECT_FALSE(e.git_revision.empty()) << e.date_utc;
    EXPECT_FALSE(e.machine.empty()) << e.date_utc;
    EXPECT_FALSE(e.cases_glob.empty()) << e.date_utc;
  }
}

Row Make(const std::map<std::string, std::string>& cells) {
  Row r;
  for (const auto& [k, v] : cells) r.Set(k, v);
  return r;
}

// Synthetic rows with known medians: each Summary row says met or missed and
// by how much; a merged run's meta.json keeps the earlier runs, the report
// only counts them.
TEST(BenchReport, SummaryVerdictsAndProvenanceOnSyntheticRows) {
  const TempDir tmp;
  std::vector<Row> rows;
  // The 7-day GEO grid's discretise and build cases of one scheme.
  auto cost = [&rows](const std::string& scheme, const char* discretise_s, const char* build_s) {
    rows.push_back(Make({{"section", kSectionCost},
                         {"case_id", "cost-geo-" + scheme},
                         {"scheme", scheme},
                         {"horizon_s", "604800"},
                         {"step_s", "300"},
                         {"discretise_s", discretise_s},
                         {"build_s", build_s}}));
  };
  for (const char* d : {"0.05", "0.25", "0.3"}) cost("exact_zoh", d, "0.5");  // 0.25 > 0.2
  cost("euler", "0.01", "0.6");
  for (const char* t : {"3", "6", "9"}) {  // median 6 of a 30-s target: 20 %
    rows.push_back(Make({{"section", kSectionTargets},
                         {"case_id", "targets-t42"},
                         {"scenario", "hcw_table42_t1_2d"},
                         {"time_within_1pct_of_opt_s", t}}));
  }
  // Solver speed: a timed target met (median 1.5 of 2 s) and two gap targets,
  // one met (ends within 2 % in 30 s), one never within it (missed).
  auto search = [&rows](const std::string& id, std::map<std::string, std::string> cells) {
    cells.insert({{"section", kSectionSolverSpeed},
                  {"case_id", "solver_speed-" + id + "-search"},
                  {"solver_path", "search"},
                  {"time_limit_s", "60"}});
    rows.push_back(Make(cells));
  };
  for (const char* t : {"1", "1.5", "4"}) {
    search("hcw-1thread", {{"target_1pct_s", "2"}, {"time_to_1pct_s", t}});
  }
  for (const auto& [id, gap, solve_s] :
       {std::tuple{"hard_a", "0.01", "30"}, std::tuple{"hard_b", "0.05", "60"}}) {
    search(id,
           {{"target_gap", "0.02"}, {"target_gap_s", "60"}, {"gap", gap}, {"solve_s", solve_s}});
  }
  ReportMeta meta;
  meta.command = "thrustsched-bench --cases x --out d --merge";
  meta.date_utc = "2026-12-02T10:00:00Z";
  meta.git_revision = "abc1234";
  meta.machine = "Test CPU, 2 cores";
  meta.earlier.push_back({"thrustsched-bench --out d", "2026-11-20T08:00:00Z", "0123abc",
                          "1.00 1.00 1.00", "Older CPU, 2 cores", "*", 3600.0});
  meta.year_results_dir = (tmp.path() / "no_years").string();
  meta.year_reference_path = kSource + "/data/reference/thesis_chapter5.json";
  WriteMetaJson((tmp.path() / "meta.json").string(), meta);
  WriteReport(tmp.path().string(), rows, meta);
  const std::string report = ReadAll(tmp.path() / "report.md");
  ExpectNoLongLine(report, "synthetic report.md");

  const std::vector<std::string> s = SummaryRows(report);
  ASSERT_EQ(s.size(), 7u) << report;  // 4 fixed, 1 timed, 1 for both gap targets, the year
  EXPECT_EQ(s[0],
            "| Discretise the 7-day GEO grid (5 min) | < 0.2 s | 0.25 s (exact_zoh, slowest of 2 "
            "schemes; n=3) | **missed** by 0.05 s (1.25x the limit) |");
  EXPECT_EQ(s[1],
            "| Build its MILP (sparse, tight) | < 1 s | 0.6 s (euler, slowest of 2 schemes; n=1) | "
            "met (60 % of the limit) |");
  EXPECT_NE(s[2].find("| < 30 s | 6.00 s (n=3) | met (20 % of the limit) |"), std::string::npos)
      << s[2];
  EXPECT_NE(s[3].find("| < 120 s | not run | - |"), std::string::npos) << s[3];
  EXPECT_EQ(s[4],
            "| search, hcw-1thread: time to a proven 1 % gap | < 2 s | 1.50 s | met (75 % of the "
            "limit) |");
  EXPECT_EQ(
      s[5],
      "| search, hard weeks (2): each within 2.00 % of its bound in 60 s | each < 60 s | 1 of "
      "2 met; slowest not reached | **missed** in 1: hard_b |");
  EXPECT_NE(s[6].find("| < 30 min | not run | - |"), std::string::npos) << s[6];

  // Provenance: the report counts the runs and links meta.json; meta.json
  // keeps every one of them (command, date, revision, machine).
  EXPECT_NE(
      Flow(report).find("Provenance: 2 runs merged (2026-11-20 to 2026-12-02); commands, dates, "
                        "revisions, machines and loads in [meta.json](meta.json)."),
      std::string::npos)
      << report.substr(0, 600);
  EXPECT_EQ(report.find("0123abc"), std::string::npos);
  EXPECT_EQ(report.find("Older CPU"), std::string::npos);
  const ReportMeta back = ReadMetaJson((tmp.path() / "meta.json").string());
  ASSERT_EQ(back.earlier.size(), 1u);
  EXPECT_EQ(back.earlier[0].git_revision, "0123abc");
  EXPECT_EQ(back.earlier[0].machine, "Older CPU, 2 cores");
  EXPECT_EQ(back.earlier[0].command, "thrustsched-bench --out d");
  EXPECT_EQ(back.git_revision, "abc1234");
}

// Section 10 from synthetic rows: the figure with its unit next to the
// published one, the ratio and its deviation, the feedback phase and the
// propellant with their published values, the tool's time; rows of other
// sections are left out, and no row gives "Not run.".
TEST(BenchReport, TransferSectionComparesEachFigureWithThePublishedOne) {
  Row fb;
  fb.Set("section", kSectionTransfer);
  fb.Set("scenario", "transfer/gto_geo_bombrun_case1");
  fb.Set("variant", "feedback, end at saturation");
  fb.Set("status", "converged");
  fb.Set("transfer_figure", 138.129);
  fb.Set("transfer_unit", "d");
  fb.Set("published", 136.45);
  fb.Set("ratio", 138.129 / 136.45);
  fb.Set("feedback_phase", 137.855);
  fb.Set("published_feedback_phase", 134.0);
  fb.Set("propellant_kg", 212.97);
  fb.Set("propellant_limit_kg", 211.8);
  fb.Set("revolutions", 197.3);
  fb.Set("solve_s", 0.42);
  Row dv = fb;
  dv.Set("scenario", "transfer/map434_hohmann");
  dv.Set("transfer_unit", "km_s");
  dv.Set("transfer_figure", 3.907087);
  dv.Set("published", 3.9071);
  dv.Set("ratio", 3.907087 / 3.9071);
  Row other = fb;
  other.Set("section", kSectionCost);
  other.Set("scenario", "not_a_transfer");
  std::ostringstream md;
  WriteTransfers(md, {fb, dv, other});
  const std::string s = md.str();
  EXPECT_NE(s.find("## 10. Orbit transfers"), std::string::npos);
  EXPECT_NE(s.find("| 138.129 d | 136.45 d | 1.0123 (1.23 %) | 137.85 (134) | 212.97 (211.8) |"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("3.907087 km/s | 3.9071 km/s"), std::string::npos) << s;
  EXPECT_EQ(s.find("not_a_transfer"), std::string::npos);
  std::ostringstream none;
  WriteTransfers(none, {other});
  EXPECT_NE(none.str().find("Not run."), std::string::npos);
}

// Section 11 from synthetic rows of three weeks: the distribution per arm
// (a week without a schedule or above 1 % counts as not reached), the
// per-preset targets, the ratio where both arms reached 1 %, and a bound of
// one arm above the other arm's schedule named as inconsistent.
TEST(BenchReport, RandomWeeksSectionGivesTheDistributionAndCrossChecksTheBounds) {
  auto row = [](const std::string& week, bool previous) {
    Row r;
    r.Set("section", kSectionRandomWeeks);
    r.Set("scenario", week);
    r.Set("solver_path", previous ? kSearchPreviousPath.column : kSearchPath.column);
    r.Set("status", "feasible");
    return r;
  };
  auto solved = [](Row r, double t1, double objective, double bound) {
    if (t1 > 0) r.Set("time_to_1pct_s", t1);
    r.Set("objective", objective);
    r.Set("consumption_l1_m_s", objective);
    r.Set("best_bound", bound);
    r.Set("gap", (objective - bound) / objective);
    return r;
  };
  std::vector<Row> rows = {
      solved(row("rw_9_000_anzel4", false), 2.0, 0.1, 0.0995),
      solved(row("rw_9_000_anzel4", true), 6.0, 0.1002, 0.101),  // bound above 0.1
      solved(row("rw_9_001_ideal6_failed", false), 40.0, 0.3, 0.2976),
      solved(row("rw_9_001_ideal6_failed", true), -1, 0.31, 0.2945),  // 5 % at the limit
      row("rw_9_002_anzel4", false),                                  // no schedule
      solved(row("rw_9_002_anzel4", true), 12.0, 0.2, 0.199),
  };
  rows[4].Set("status", "no_solution_found");
  Row other = rows[0];
  other.Set("section", kSectionSolverSpeed);
  other.Set("scenario", "not_a_random_week");
  rows.push_back(other);
  std::ostringstream md;
  WriteRandomWeeks(md, rows);
  const std::string s = md.str();
  EXPECT_NE(s.find("## 11. Random weeks"), std::string::npos);
  EXPECT_NE(s.find("| this release | 3 | 40.0 | not reached | not reached | 1 | 1 |"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("| previous release | 3 | 12.0 | not reached | not reached | 0 | 1 |"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("| 1 of 2 | 0 of 1 |"), std::string::npos) << s;
  EXPECT_NE(s.find("on the 1 weeks both reached: median 3, geometric mean 3, range 3 to 3"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("**inconsistent** on 1 of 2: rw_9_000_anzel4."), std::string::npos) << s;
  EXPECT_NE(s.find("| rw_9_001_ideal6_failed | feasible | 40.0 | 0.3 | 0.80 % | not reached | "
                   "5.00 % | - |"),
            std::string::npos)
      << s;
  EXPECT_EQ(s.find("not_a_random_week"), std::string::npos);
  std::ostringstream none;
  WriteRandomWeeks(none, {other});
  EXPECT_NE(none.str().find("Not run."), std::string::npos);
}

TEST(NearestRankQuantile, SmallestValueWithAtLeastQAtOrBelow) {
  const std::vector<double> ten = {10, 9, 8, 7, 6, 5, 4, 3, 2, 1};
  EXPECT_EQ(NearestRankQuantile(ten, 0.9), 9);
  EXPECT_EQ(NearestRankQuantile(ten, 0.5), 5);
  EXPECT_EQ(NearestRankQuantile(ten, 1.0), 10);
  EXPECT_EQ(NearestRankQuantile(ten, 0.0), 1);
  EXPECT_EQ(NearestRankQuantile({1, std::nan(""), INFINITY}, 0.9), INFINITY);
  EXPECT_TRUE(std::isnan(NearestRankQuantile({}, 0.5)));
}

TEST(MdTable, SplitsWideTablesRepeatingTheKeyColumns) {
  MdTable t({"case", "measure", "a", "b", "c"}, 2);
  const std::string wide(95, 'x');
  t.Add({"w02", "gap", wide, wide, wide});
  t.Add({"w10", "gap", "1", "2", "3"});
  const std::string out = t.Str();
  ExpectNoLongLine(out, "table");
  // Three parts (95-character cells: one per part), each with both keys.
  EXPECT_EQ(out, "| case | measure | a |\n|---|---|---|\n| w02 | gap | " + wide +
                     " |\n| w10 | gap | 1 |\n\n"
                     "| case | measure | b |\n|---|---|---|\n| w02 | gap | " +
                     wide +
                     " |\n| w10 | gap | 2 |\n\n"
                     "| case | measure | c |\n|---|---|---|\n| w02 | gap | " +
                     wide + " |\n| w10 | gap | 3 |\n");
  // A narrow table stays one table; '|' in a cell is escaped, empty cells "-".
  MdTable n({"x", "y"});
  n.Add({"a|b", ""});
  EXPECT_EQ(n.Str(), "| x | y |\n|---|---|\n| a\\|b | - |\n");
}

TEST(WrapMarkdown, WrapsProseAndListsButNotTablesHeadingsOrCode) {
  std::string words;
  for (int i = 0; i < 40; ++i) words += (i ? " " : "") + std::string("word") + std::to_string(i);
  const std::string table = "| " + words + " |";
  const std::string md = "# " + words + "\n\n" + words + "\n\n- " + words + "\n\n" + table +
                         "\n\n```\n" + words + "\n```\n";
  const std::string out = WrapMarkdown(md, 60);
  const std::vector<std::string> lines = Lines(out);
  ASSERT_GT(lines.size(), 10u);
  EXPECT_EQ(lines[0], "# " + words);  // headings are left alone
  bool in_list = false, fenced = false;
  std::string flowed_prose, flowed_item;
  for (size_t i = 2; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l == "```") fenced = !fenced;
    if (fenced || l == "```" || l.empty() || l[0] == '|') {
      in_list = false;
      continue;
    }
    if (l.rfind("- ", 0) == 0) in_list = true;
    EXPECT_LE(Utf8Length(l), 60u) << l;
    if (in_list) {
      EXPECT_TRUE(l.rfind("- ", 0) == 0 || l.rfind("  ", 0) == 0) << l;  // continues the item
      flowed_item += (flowed_item.empty() ? "" : " ") + l.substr(2);
    } else {
      flowed_prose += (flowed_prose.empty() ? "" : " ") + l;
    }
  }
  EXPECT_EQ(flowed_prose, words);  // nothing lost or reordered
  EXPECT_EQ(flowed_item, words);
  EXPECT_NE(out.find("\n" + table + "\n"), std::string::npos);          // tables intact
  EXPECT_NE(out.find("```\n" + words + "\n```\n"), std::string::npos);  // code intact
  // Never a break before a word that would open a block: "- 3" stays inline.
  const std::string risky = std::string(55, 'a') + " - 3. # x";
  for (const std::string& l : Lines(WrapMarkdown(risky, 56))) {
    EXPECT_NE(l.rfind("- ", 0), 0u) << l;
    EXPECT_NE(l.rfind("3. ", 0), 0u) << l;
    EXPECT_NE(l.rfind("# ", 0), 0u) << l;
  }
}

}  // namespace
}  // namespace thrustsched::bench
