#include "benchmarks/bench/report_random_weeks.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/report_format.h"

namespace thrustsched::bench {
namespace {

// One week's two arms (nullptr: that arm was not run).
struct Week {
  std::string name;
  const Row* now = nullptr;
  const Row* previous = nullptr;
};

std::vector<Week> Weeks(const std::vector<Row>& rows) {
  std::vector<Week> out;
  std::map<std::string, size_t> at;
  for (const Row& r : rows) {
    if (r.Get("section") != kSectionRandomWeeks) continue;
    auto [it, fresh] = at.emplace(r.Get("scenario"), out.size());
    if (fresh) out.push_back({r.Get("scenario")});
    Week& w = out[it->second];
    (r.Get("solver_path") == kSearchPreviousPath.column ? w.previous : w.now) = &r;
  }
  return out;
}

bool HasSchedule(const Row* r) { return r != nullptr && r->Has("objective"); }

// Seconds to a proven 1 % gap; +inf where the run did not get there (no
// schedule, or a larger gap at the limit); NaN where the arm was not run.
double TimeTo1Pct(const Row* r) {
  if (r == nullptr) return NAN;
  const double t = r->Num("time_to_1pct_s");
  return HasSchedule(r) && std::isfinite(t) ? t : INFINITY;
}

// The week's preset, from the name scripts/random_weeks.py gives it.
std::string PresetOf(const std::string& name) {
  for (const char* p : {"anzel4", "ideal6"}) {
    if (name.find(std::string("_") + p) != std::string::npos) return p;
  }
  return "?";
}

// Issue-level targets of the time to 1 % by preset: four thrusters 10 s,
// six 30 s.
double PresetTargetS(const std::string& preset) {
  return preset == "anzel4" ? 10.0 : preset == "ideal6" ? 30.0 : NAN;
}

// A safe bound of one arm never exceeds the other arm's schedule.
bool BoundsConsistent(const Row& a, const Row& b) {
  auto below = [](const Row& bound_of, const Row& schedule_of) {
    const double bound = bound_of.Num("best_bound"), obj = schedule_of.Num("objective");
    return !(bound > obj + 1e-6 * std::abs(obj) + 1e-9);
  };
  return below(a, b) && below(b, a);
}

void WriteDistribution(std::ostream& md, const std::vector<Week>& weeks) {
  MdTable t({"arm", "weeks", "median (s)", "p90 (s)", "max (s)", "without a schedule",
             "not within 1 % in " + G(kRandomWeeksTimeLimitS) + " s", "four thrusters within 10 s",
             "six thrusters within 30 s"});
  for (const bool now : {true, false}) {
    std::vector<double> times;
    int without = 0, not_within = 0;
    std::map<std::string, std::pair<int, int>> per_preset;  // met, of
    for (const Week& w : weeks) {
      const Row* r = now ? w.now : w.previous;
      if (r == nullptr) continue;
      const double t = TimeTo1Pct(r);
      times.push_back(t);
      without += !HasSchedule(r);
      not_within += std::isinf(t);
      const std::string preset = PresetOf(w.name);
      per_preset[preset].first += t <= PresetTargetS(preset);
      ++per_preset[preset].second;
    }
    if (times.empty()) continue;
    auto met = [&per_preset](const char* preset) {
      const auto& [m, n] = per_preset[preset];
      return n == 0 ? std::string("-") : std::to_string(m) + " of " + std::to_string(n);
    };
    t.Add({now ? "this release" : "previous release", std::to_string(times.size()),
           Sec(NearestRankQuantile(times, 0.5)), Sec(NearestRankQuantile(times, 0.9)),
           Sec(NearestRankQuantile(times, 1.0)), std::to_string(without),
           std::to_string(not_within), met("anzel4"), met("ideal6")});
  }
  md << t.Str() << "\n";
}

void WriteRatioAndBounds(std::ostream& md, const std::vector<Week>& weeks) {
  std::vector<double> ratios;
  double log_sum = 0.0;
  int both = 0, inconsistent = 0;
  std::string inconsistent_names;
  for (const Week& w : weeks) {
    if (w.now == nullptr || w.previous == nullptr) continue;
    const double a = TimeTo1Pct(w.now), b = TimeTo1Pct(w.previous);
    if (std::isfinite(a) && std::isfinite(b) && a > 0.0) {
      ratios.push_back(b / a);
      log_sum += std::log(b / a);
    }
    if (HasSchedule(w.now) && HasSchedule(w.previous)) {
      ++both;
      if (!BoundsConsistent(*w.now, *w.previous)) {
        ++inconsistent;
        inconsistent_names += " " + w.name;
      }
    }
  }
  if (!ratios.empty()) {
    md << "Previous / this release, time to 1 % on the " << ratios.size()
       << " weeks both reached: median " << G(NearestRankQuantile(ratios, 0.5), 3)
       << ", geometric mean " << G(std::exp(log_sum / ratios.size()), 3) << ", range "
       << G(*std::min_element(ratios.begin(), ratios.end()), 3) << " to "
       << G(*std::max_element(ratios.begin(), ratios.end()), 3) << ".\n\n";
  }
  if (both > 0) {
    md << "Each arm's bound against the other arm's schedule (two LP solvers; a safe bound "
          "is never above a schedule): "
       << (inconsistent == 0 ? "consistent on all " + std::to_string(both) + " weeks"
                             : "**inconsistent** on " + std::to_string(inconsistent) + " of " +
                                   std::to_string(both) + ":" + inconsistent_names)
       << ".\n\n";
  }
}

void WritePerWeek(std::ostream& md, const std::vector<Week>& weeks) {
  MdTable t({"week", "status", "time to 1 % (s)", "consumption (m/s)", "gap",
             "previous: time to 1 % (s)", "previous: gap", "previous / this"},
            1);
  for (const Week& w : weeks) {
    const double a = TimeTo1Pct(w.now), b = TimeTo1Pct(w.previous);
    t.Add({w.name, w.now ? w.now->Get("status") : "-", Sec(a),
           HasSchedule(w.now) ? G(w.now->Num("consumption_l1_m_s"), 6) : "-",
           HasSchedule(w.now) ? Pct(w.now->Num("gap")) : "-", Sec(b),
           HasSchedule(w.previous) ? Pct(w.previous->Num("gap")) : "-",
           std::isfinite(a) && std::isfinite(b) && a > 0.0 ? G(b / a, 3) : "-"});
  }
  md << t.Str() << "\n";
}

}  // namespace

double NearestRankQuantile(std::vector<double> v, double q) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return std::isnan(x); }), v.end());
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const double rank = std::ceil(std::clamp(q, 0.0, 1.0) * static_cast<double>(v.size()));
  return v[static_cast<size_t>(std::max(rank, 1.0)) - 1];
}

void WriteRandomWeeks(std::ostream& md, const std::vector<Row>& rows) {
  md << "## 11. Random weeks: the search on weeks nobody chose\n\n";
  const std::vector<Week> weeks = Weeks(rows);
  if (weeks.empty()) {
    md << "Not run.\n\n";
    return;
  }
  md << weeks.size() << " GEO weeks drawn by `scripts/random_weeks.py --seed " << kRandomWeeksSeed
     << "` (DIR/random_weeks/weeks.csv lists the draws: station longitude, epoch 2025-2045, "
        "preset, a failed thruster or none, window 0.03-0.1 deg, rules, 5- or 10-min grid, "
        "initial state inside the window, end-of-week set or none), a seed not used while "
        "developing the search. Each week on each arm to a proven 1 % gap on 2 threads, "
        "stopped at "
     << G(kRandomWeeksTimeLimitS)
     << " s; this release against the previous one (its LP relaxation by CLP's barrier) in "
        "the same run. Times to 1 % (not reached: +inf, counted in the quantiles as the "
        "largest); p90 and max by nearest rank.\n\n";
  WriteDistribution(md, weeks);
  WriteRatioAndBounds(md, weeks);
  WritePerWeek(md, weeks);
}

}  // namespace thrustsched::bench
