#include "benchmarks/bench/report_solver.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/report.h"
#include "benchmarks/bench/report_format.h"

namespace thrustsched::bench {
namespace {

// The arms of one case: rows of "<id>-search" (this release), "<id>-previous"
// (the search with one switch off, named by the `variant` column),
// "<id>-lazy-lp-unpresolved" (the search with the lazy rows' first LP
// unpresolved) and "<id>-cbc" (CBC alone on the whole MILP).
struct Pair {
  std::string id;
  std::vector<const Row*> search, previous, unpresolved, cbc;
};

std::vector<Pair> Pairs(const std::vector<Row>& rows) {
  std::vector<Pair> out;
  std::map<std::string, size_t> at;
  for (const Row& r : rows) {
    if (r.Get("section") != kSectionSolverSpeed) continue;
    const std::string id = r.Get("case_id");
    const std::string path = r.Get("solver_path");
    const std::string suffix = SolverPathIdSuffix(path);
    const bool tagged = id.size() > suffix.size() &&
                        id.compare(id.size() - suffix.size(), suffix.size(), suffix) == 0;
    const std::string base = tagged ? id.substr(0, id.size() - suffix.size()) : id;
    auto [it, fresh] = at.emplace(base, out.size());
    if (fresh) out.push_back({base, {}, {}, {}, {}});
    Pair& pair = out[it->second];
    std::vector<const Row*>& arm = path == kSearchPath.column                    ? pair.search
                                   : path == kSearchPreviousPath.column          ? pair.previous
                                   : path == kSearchLazyLpUnpresolvedPath.column ? pair.unpresolved
                                                                                 : pair.cbc;
    arm.push_back(&r);
  }
  return out;
}

double MedianCol(const std::vector<const Row*>& rows, const std::string& col, bool missing_is_inf) {
  std::vector<double> v;
  for (const Row* r : rows) v.push_back(r->Num(col));
  return MedianOf(v, missing_is_inf);
}

// A target's value in one run: time to a 1 % proof, to optimality, or (for
// a gap target) the run's time if it ended within the gap, else +inf.
double TimeToGap(const Row& r, double gap) {
  const double g = r.Num("gap");
  return std::isfinite(g) && g <= gap + 1e-12 ? r.Num("solve_s") : INFINITY;
}

// The timed measures of a case: its targets' columns.
struct Measure {
  std::string name;
  std::string column;  // empty: gap target
  std::string target_column;
};

std::vector<Measure> MeasuresOf(const Row& spec) {
  std::vector<Measure> measures;
  if (spec.Has("target_1pct_s")) {
    measures.push_back({"time to a proven 1 % gap", "time_to_1pct_s", "target_1pct_s"});
  }
  if (spec.Has("target_opt_s")) {
    measures.push_back({"time to proven optimality", "time_to_opt_s", "target_opt_s"});
  }
  if (spec.Has("target_gap")) {
    measures.push_back(
        {"within " + Pct(spec.Num("target_gap")) + " of its bound", "", "target_gap_s"});
  }
  return measures;
}

// The median of one arm's runs on a measure (NaN: the arm was not run;
// +inf: not reached in most runs).
double ArmValue(const std::vector<const Row*>& arm, const Measure& m, const Row& spec) {
  if (arm.empty()) return NAN;
  if (!m.column.empty()) return MedianCol(arm, m.column, true);
  std::vector<double> v;
  for (const Row* r : arm) v.push_back(TimeToGap(*r, spec.Num("target_gap")));
  return MedianOf(v, true);
}

// The medians of `col` over the given arms, " / "-separated.
std::string PerArm(const std::vector<const std::vector<const Row*>*>& arms, const std::string& col,
                   bool pct) {
  std::string out;
  for (const auto* arm : arms) {
    const double v = arm->empty() ? NAN : MedianCol(*arm, col, false);
    out += (out.empty() ? "" : " / ") + (pct ? Pct(v) : G(v, 8));
  }
  return out;
}

// Section 8.1: the search with LazyRowOptions::presolve_lp_relaxation off
// against the default, measure by measure, and their geometric mean.
void WriteLazyLpAblation(std::ostream& md, const std::vector<Pair>& pairs) {
  md << "### 8.1 Ablation: the lazy rows' first LP without presolve\n\n";
  MdTable t({"case", "measure", "default (s)", "unpresolved (s)", "default / unpresolved",
             "objective (default / unpresolved)", "final gap (default / unpresolved)"},
            2);
  double log_sum = 0.0;
  int finite_pairs = 0;
  for (const Pair& p : pairs) {
    if (p.search.empty() || p.unpresolved.empty()) continue;
    const Row& spec = *p.search.front();
    for (const Measure& m : MeasuresOf(spec)) {
      const double on = ArmValue(p.search, m, spec), off = ArmValue(p.unpresolved, m, spec);
      const double limit = spec.Num("time_limit_s");
      std::string ratio = "-";  // neither reached
      if (std::isfinite(on) && std::isfinite(off) && on > 0.0 && off > 0.0) {
        ratio = G(on / off, 3) + "x";
        log_sum += std::log(on / off);
        ++finite_pairs;
      } else if (std::isfinite(off) && off > 0.0) {
        ratio = "> " + G(limit / off, 3) + "x";
      } else if (std::isfinite(on) && on > 0.0) {
        ratio = "< " + G(on / limit, 3) + "x";
      }
      t.Add({SolverCaseShortId(p.id), m.name, Sec(on), Sec(off), ratio,
             PerArm({&p.search, &p.unpresolved}, "objective", false),
             PerArm({&p.search, &p.unpresolved}, "gap", true)});
    }
  }
  if (t.empty()) {
    md << "Not run (the `-lazy-lp-unpresolved` cases).\n\n";
    return;
  }
  md << "`LazyRowOptions::presolve_lp_relaxation` (default on) lets CLP presolve the LP "
        "relaxation whose binding rows start each row generation over a restricted MILP's "
        "dense window rows (`milp/lazy_rows.h`); the `lazy-lp-unpresolved` arm runs the same "
        "search with it off, in the same run as the default (`search`) arm. Medians over the "
        "repeats; a ratio above 1 means the unpresolved first LP was faster; \"not reached\" "
        "counts as the time limit in the bounds on a ratio.\n\n";
  md << t.Str() << "\n";
  if (finite_pairs > 0) {
    md << "Geometric mean of the ratios where both arms reached the measure (" << finite_pairs
       << "): " << G(std::exp(log_sum / finite_pairs), 3) << "x.\n\n";
  }
}

// The search's steps (column search_steps, " | "-separated), one per line.
std::string StepLines(const std::string& steps) {
  std::string out;
  size_t pos = 0;
  while (pos <= steps.size()) {
    size_t end = steps.find(" | ", pos);
    if (end == std::string::npos) end = steps.size();
    std::string step = steps.substr(pos, end - pos);
    if (step.size() > kReportMaxLineChars) {  // a tree's LPs: one per line
      for (size_t at = step.find("; "); at != std::string::npos; at = step.find("; ", at + 4)) {
        step.replace(at, 2, ";\n  ");
      }
    }
    out += step + "\n";
    pos = end + 3;
  }
  return out;
}

// DIR/logs/<case id>.log for each arm with steps: every repeat, one step per
// line. Returns the search arm's log name per case ("" when it has no steps).
std::map<std::string, std::string> WriteStepLogs(const std::vector<Pair>& pairs,
                                                 const std::string& dir) {
  namespace fs = std::filesystem;
  const fs::path logs = fs::path(dir) / "logs";
  if (fs::is_directory(logs)) {
    for (const auto& e : fs::directory_iterator(logs)) {
      if (e.is_regular_file() && e.path().extension() == ".log") fs::remove(e.path());
    }
  }
  std::map<std::string, std::string> search_logs;
  for (const Pair& p : pairs) {
    for (const std::vector<const Row*>* arm : {&p.search, &p.previous, &p.unpresolved, &p.cbc}) {
      std::string text;
      for (const Row* r : *arm) {
        if (r->Get("search_steps").empty()) continue;
        text += "## " + r->Get("case_id") + ", repeat " + r->Get("repeat") + " (" +
                r->Get("variant") + "): " + r->Get("status") + ", objective " +
                r->Get("objective") + ", gap " + Pct(r->Num("gap")) + ", " +
                Sec(r->Num("solve_s")) + " s\n" + StepLines(r->Get("search_steps")) + "\n";
      }
      if (text.empty()) continue;
      const std::string id = arm->front()->Get("case_id");
      fs::create_directories(logs);
      const fs::path file = logs / (id + ".log");
      std::ofstream out(file);
      out << "# The steps of the schedule search on " << id
          << ", one per line (results.csv, column search_steps)\n\n"
          << text;
      if (!out) throw std::runtime_error("cannot write " + file.string());
      if (arm == &p.search) search_logs[p.id] = "logs/" + id + ".log";
    }
  }
  return search_logs;
}

}  // namespace

std::string SolverCaseShortId(const std::string& case_id) {
  const std::string prefix = std::string(kSectionSolverSpeed) + "-";
  return case_id.rfind(prefix, 0) == 0 ? case_id.substr(prefix.size()) : case_id;
}

std::vector<SolverTarget> SolverSpeedTargets(const std::vector<Row>& rows) {
  std::vector<SolverTarget> out;
  for (const Pair& p : Pairs(rows)) {
    if (p.search.empty()) continue;
    const Row& spec = *p.search.front();
    for (const Measure& m : MeasuresOf(spec)) {
      out.push_back(
          {p.id, m.name, m.column.empty(), spec.Num(m.target_column), ArmValue(p.search, m, spec)});
    }
  }
  return out;
}

void WriteSolverSpeed(std::ostream& md, const std::vector<Row>& rows, const std::string& dir) {
  md << "## 8. Solver speed: the search against the previous release and CBC alone\n\n";
  const std::vector<Pair> pairs = Pairs(rows);
  const std::map<std::string, std::string> logs = WriteStepLogs(pairs, dir);
  if (pairs.empty()) {
    md << "Not run.\n\n";
    return;
  }
  md << "Each case is solved by every arm in the same run, one after the other, so machine "
        "load acts on all. `search` is this release, what `thrustsched solve` does "
        "(`transcription/search.h`); `previous` is the same search with one named switch off "
        "(below, from the `variant` column of its rows); `cbc` is CBC alone on the whole MILP "
        "(`--no-search`). Medians over the repeats; \"not reached\" counts as infinite; a ratio "
        "is the other arm's time / the search's (> 1: the search is faster).\n\n";
  // What `previous` is, from its rows (a merged file can hold several).
  std::vector<std::pair<std::string, int>> previous_variants;
  for (const Pair& p : pairs) {
    for (const Row* r : p.previous) {
      auto it = std::find_if(previous_variants.begin(), previous_variants.end(),
                             [&](const auto& v) { return v.first == r->Get("variant"); });
      if (it == previous_variants.end()) {
        previous_variants.push_back({r->Get("variant"), 1});
      } else {
        ++it->second;
      }
    }
  }
  for (const auto& [variant, n] : previous_variants) {
    md << "- `previous` in " << n << " rows: " << variant << "\n";
  }
  if (!previous_variants.empty()) md << "\n";
  MdTable t({"case", "measure", "target (s)", "search", "previous", "ratio", "CBC alone", "ratio",
             "verdict (search)", "objective (search / previous / CBC)",
             "final gap (search / previous / CBC)"},
            2);
  for (const Pair& p : pairs) {
    if (p.search.empty()) continue;
    const Row& spec = *p.search.front();
    for (const Measure& m : MeasuresOf(spec)) {
      auto value = [&](const std::vector<const Row*>& arm) { return ArmValue(arm, m, spec); };
      const double now = value(p.search);
      const double limit = spec.Num(m.target_column);
      auto ratio = [&](double before) {
        if (!(now > 0.0) || !std::isfinite(now) || std::isnan(before)) return std::string("-");
        return std::isinf(before) ? "> " + G(spec.Num("time_limit_s") / now, 3) + "x"
                                  : G(before / now, 3) + "x";
      };
      const double previous = value(p.previous), first = value(p.cbc);
      t.Add({SolverCaseShortId(p.id), m.name, G(limit, 3), Sec(now), Sec(previous), ratio(previous),
             Sec(first), ratio(first), Verdict(now, limit),
             PerArm({&p.search, &p.previous, &p.cbc}, "objective", false),
             PerArm({&p.search, &p.previous, &p.cbc}, "gap", true)});
    }
  }
  md << "Case ids without their `solver_speed-` prefix.\n\n" << t.Str() << "\n";
  if (!logs.empty()) {
    md << "What the search did, step by step, every repeat (one log per case, from the "
          "`search_steps` column of results.csv):\n\n";
    for (const Pair& p : pairs) {
      const auto it = logs.find(p.id);
      if (it == logs.end()) continue;
      md << "- [" << SolverCaseShortId(p.id) << "](" << it->second << ")\n";
    }
    md << "\n";
  }
  WriteLazyLpAblation(md, pairs);
}

}  // namespace thrustsched::bench
