// Tests of transcription::CheckOperationalRules (checker.h): hand-built cases
// for each rule of operations.h at exact boundary values, and a randomized
// cross-check against a second, deliberately different implementation (a
// per-interval pattern evaluator on a uniform 1-minute grid, written below
// from the rule statements in edge/run form).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "transcription/checker.h"
#include "transcription/operations.h"

namespace thrustsched::transcription {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<RuleViolation> Check(const OperationalRules& rules, const std::vector<Burn>& burns,
                                 int num_thrusters = 2, double t0 = 0.0, double tf = 86400.0,
                                 const BoundaryHistory& history = {},
                                 const std::vector<ForcedOff>& forced_off = {}) {
  return CheckOperationalRules(rules, history, forced_off, num_thrusters, t0, tf, burns);
}

std::multiset<std::string> Rules(const std::vector<RuleViolation>& v) {
  std::multiset<std::string> out;
  for (const RuleViolation& x : v) out.insert(x.rule);
  return out;
}

std::string Dump(const std::vector<RuleViolation>& v) {
  std::string s;
  for (const RuleViolation& x : v) s += "[" + x.rule + "] " + x.message + "\n";
  return s;
}

using Set = std::multiset<std::string>;

OperationalRules Thesis() {
  OperationalRules r;
  r.max_simultaneous = 1;
  r.min_burn_s = 300;
  r.min_off_same_s = 1200;
  r.min_gap_other_s = 300;
  return r;
}

BoundaryHistory History(std::vector<double> on, std::vector<double> off) {
  BoundaryHistory h;
  h.on_for_s = std::move(on);
  h.off_for_s = std::move(off);
  return h;
}

// ---------------------------------------------------------------- min_burn

TEST(RuleChecker, EmptyScheduleIsOk) { EXPECT_TRUE(Check(Thesis(), {}).empty()); }

TEST(RuleChecker, MinBurnExactPassesAndOneMillisecondShorterFails) {
  const OperationalRules r = Thesis();
  EXPECT_TRUE(Check(r, {{0, 1000.123, 1300.123}}).empty());
  // Within the 1e-6 s tolerance: still a pass.
  EXPECT_TRUE(Check(r, {{0, 1000.123, 1300.123 - 5e-7}}).empty());
  auto v = Check(r, {{0, 1000.123, 1300.122}});
  ASSERT_EQ(Rules(v), Set({"min_burn"})) << Dump(v);
  EXPECT_EQ(v[0].thruster, 0);
  EXPECT_DOUBLE_EQ(v[0].time_s, 1000.123);
  EXPECT_NE(v[0].message.find("lasts 299.999 s < min_burn 300 s"), std::string::npos)
      << v[0].message;
  EXPECT_NE(v[0].message.find("1000.123"), std::string::npos) << v[0].message;
}

TEST(RuleChecker, ZeroMinBurnAcceptsShortBurns) {
  OperationalRules r;
  EXPECT_TRUE(Check(r, {{0, 10.0, 10.5}}).empty());
}

// ---------------------------------------------------------------- max_burn

TEST(RuleChecker, MaxBurnExactPassesLongerFails) {
  OperationalRules r = Thesis();
  r.max_burn_s = 900;
  EXPECT_TRUE(Check(r, {{1, 3600, 4500}}).empty());
  auto v = Check(r, {{1, 3600, 4500.001}});
  ASSERT_EQ(Rules(v), Set({"max_burn"})) << Dump(v);
  EXPECT_NE(v[0].message.find("burn at 3600 s"), std::string::npos) << v[0].message;
  EXPECT_NE(v[0].message.find("900.001 s > max_burn 900 s"), std::string::npos) << v[0].message;
}

TEST(RuleChecker, MaxBurnCountsTimeBeforeT0) {
  OperationalRules r = Thesis();
  r.max_burn_s = 300;
  const BoundaryHistory h100 = History({100, 0}, {});
  EXPECT_TRUE(Check(r, {{0, 0, 200}}, 2, 0, 86400, h100).empty());
  auto v = Check(r, {{0, 0, 250}}, 2, 0, 86400, h100);
  ASSERT_EQ(Rules(v), Set({"max_burn"})) << Dump(v);
  EXPECT_NE(v[0].message.find("lasts 350 s"), std::string::npos) << v[0].message;
}

TEST(RuleChecker, HistoryBurnSwitchedOffAtT0IsNotJudgedByMaxBurn) {
  // The burn [t0 - 500, t0) is history (data); the schedule ended it at t0.
  OperationalRules r = Thesis();
  r.max_burn_s = 400;
  EXPECT_TRUE(Check(r, {}, 2, 0, 86400, History({500, 0}, {})).empty());
}

// ------------------------------------------------------------ min_off_same

TEST(RuleChecker, SameThrusterGapExactPassesShorterFails) {
  const OperationalRules r = Thesis();
  EXPECT_TRUE(Check(r, {{0, 0, 300}, {0, 1500, 1800}}).empty());
  auto v = Check(r, {{0, 0, 300}, {0, 1499.999, 1800}});
  ASSERT_EQ(Rules(v), Set({"min_off_same"})) << Dump(v);
  EXPECT_DOUBLE_EQ(v[0].time_s, 1499.999);
  EXPECT_NE(v[0].message.find("1199.999 s after its switch-off at 300 s < min_off_same 1200 s"),
            std::string::npos)
      << v[0].message;
  // The same timing on another thruster is governed by min_gap_other (300 s) only.
  EXPECT_TRUE(Check(r, {{0, 0, 300}, {1, 1499.999, 1800}}).empty());
}

// ----------------------------------------------------------- min_gap_other

TEST(RuleChecker, OtherThrusterGapExactPassesShorterFails) {
  const OperationalRules r = Thesis();
  EXPECT_TRUE(Check(r, {{0, 0, 300}, {1, 600, 900}}).empty());
  auto v = Check(r, {{0, 0, 300}, {1, 599.999, 900}});
  ASSERT_EQ(Rules(v), Set({"min_gap_other"})) << Dump(v);
  EXPECT_EQ(v[0].thruster, 1);
  EXPECT_NE(v[0].message.find("299.999 s after thruster 0 switched off at 300 s"),
            std::string::npos)
      << v[0].message;
  // Start exactly at the other's switch-off: gap 0 < 300.
  EXPECT_EQ(Rules(Check(r, {{0, 0, 300}, {1, 300, 600}})), Set({"min_gap_other"}));
  // ... allowed when min_gap_other_s = 0.
  OperationalRules r0 = r;
  r0.min_gap_other_s = 0;
  EXPECT_TRUE(Check(r0, {{0, 0, 300}, {1, 300, 600}}).empty());
}

TEST(RuleChecker, StartWhileOtherIsOnIsOnlyASimultaneityMatter) {
  OperationalRules r = Thesis();
  r.max_simultaneous = 2;
  // Thruster 1 starts at 300 while 0 is on until 600: rule (5) does not apply.
  EXPECT_TRUE(Check(r, {{0, 0, 600}, {1, 300, 900}}).empty());
  r.max_simultaneous = 1;
  EXPECT_EQ(Rules(Check(r, {{0, 0, 600}, {1, 300, 900}})), Set({"max_simultaneous"}));
}

// ------------------------------------------------------- max_simultaneous

TEST(RuleChecker, MaxSimultaneousOne) {
  OperationalRules r;
  r.max_simultaneous = 1;
  // Touching burns of different thrusters are not simultaneous.
  EXPECT_TRUE(Check(r, {{0, 0, 300}, {1, 300, 600}}).empty());
  // Overlap within the tolerance is ignored.
  EXPECT_TRUE(Check(r, {{0, 0, 300}, {1, 300 - 5e-7, 600}}).empty());
  auto v = Check(r, {{0, 0, 300}, {1, 299, 600}});
  ASSERT_EQ(Rules(v), Set({"max_simultaneous"})) << Dump(v);
  EXPECT_DOUBLE_EQ(v[0].time_s, 299);
  EXPECT_NE(v[0].message.find("2 thrusters on at once on [299, 300) > max_simultaneous 1"),
            std::string::npos)
      << v[0].message;
}

TEST(RuleChecker, MaxSimultaneousTwo) {
  OperationalRules r;
  r.max_simultaneous = 2;
  EXPECT_TRUE(Check(r, {{0, 0, 600}, {1, 100, 700}, {2, 600, 800}}, 3).empty());
  auto v = Check(r, {{0, 0, 600}, {1, 100, 700}, {2, 500, 800}}, 3);
  ASSERT_EQ(Rules(v), Set({"max_simultaneous"})) << Dump(v);
  EXPECT_NE(v[0].message.find("3 thrusters on at once on [500, 600)"), std::string::npos)
      << v[0].message;
  // Two separate excursions are two findings.
  v = Check(r, {{0, 0, 1000}, {1, 0, 1000}, {2, 100, 200}, {2, 500, 600}}, 3);
  EXPECT_EQ(Rules(v), Set({"max_simultaneous", "max_simultaneous"})) << Dump(v);
}

// ------------------------------------------------------------------ history

TEST(RuleChecker, HistoryOnShorterThanMinBurnMustContinue) {
  const OperationalRules r = Thesis();
  const BoundaryHistory h = History({120, 0}, {kInf, kInf});
  // Off at t0: the burn [t0 - 120, t0) lasted 120 s < 300 s.
  auto v = Check(r, {}, 2, 0, 86400, h);
  ASSERT_EQ(Rules(v), Set({"min_burn"})) << Dump(v);
  EXPECT_DOUBLE_EQ(v[0].time_s, 0.0);
  EXPECT_NE(v[0].message.find("lasts 120 s < min_burn 300 s"), std::string::npos) << v[0].message;
  // Continuing exactly 180 s more completes 300 s.
  EXPECT_TRUE(Check(r, {{0, 0, 180}}, 2, 0, 86400, h).empty());
  EXPECT_EQ(Rules(Check(r, {{0, 0, 179.999}}, 2, 0, 86400, h)), Set({"min_burn"}));
  // Long enough already: switching off at t0 is legal.
  EXPECT_TRUE(Check(r, {}, 2, 0, 86400, History({300, 0}, {})).empty());
}

TEST(RuleChecker, HistoryOnSwitchedOffAtT0StartsTheGapClocks) {
  const OperationalRules r = Thesis();
  const BoundaryHistory h = History({400, 0}, {});
  // Same thruster again after 1199 s < 1200 s.
  EXPECT_EQ(Rules(Check(r, {{0, 1199, 1500}}, 2, 0, 86400, h)), Set({"min_off_same"}));
  EXPECT_TRUE(Check(r, {{0, 1200, 1500}}, 2, 0, 86400, h).empty());
  // Another thruster after 299 s < 300 s.
  EXPECT_EQ(Rules(Check(r, {{1, 299, 600}}, 2, 0, 86400, h)), Set({"min_gap_other"}));
  EXPECT_TRUE(Check(r, {{1, 300, 600}}, 2, 0, 86400, h).empty());
}

TEST(RuleChecker, HistoryContinuationIsNotAStart) {
  const OperationalRules r = Thesis();
  // Thruster 1 switched off 10 s before t0; thruster 0 has been on for 400 s
  // and continues: no gap rule applies to the continuation.
  const BoundaryHistory h = History({400, 0}, {kInf, 10});
  EXPECT_TRUE(Check(r, {{0, 0, 100}}, 2, 0, 86400, h).empty());
}

TEST(RuleChecker, OffForBlocksEarlyRestarts) {
  const OperationalRules r = Thesis();
  const BoundaryHistory h = History({0, 0}, {600, kInf});
  // Same thruster: 600 + 599.999 < 1200.
  auto v = Check(r, {{0, 599.999, 1000}}, 2, 0, 86400, h);
  ASSERT_EQ(Rules(v), Set({"min_off_same"})) << Dump(v);
  EXPECT_NE(v[0].message.find("switch-off at -600 s"), std::string::npos) << v[0].message;
  EXPECT_TRUE(Check(r, {{0, 600, 1000}}, 2, 0, 86400, h).empty());
  // Other thruster after thruster 0 switched off 100 s before t0.
  const BoundaryHistory h2 = History({}, {100, kInf});
  EXPECT_EQ(Rules(Check(r, {{1, 199.999, 600}}, 2, 0, 86400, h2)), Set({"min_gap_other"}));
  EXPECT_TRUE(Check(r, {{1, 200, 600}}, 2, 0, 86400, h2).empty());
  // Never fired: a start at t0 is fine.
  EXPECT_TRUE(Check(r, {{0, 0, 300}}, 2, 0, 86400, History({}, {kInf, kInf})).empty());
}

TEST(RuleChecker, HistoryWithNonZeroT0) {
  const OperationalRules r = Thesis();
  const double t0 = 86400;
  const BoundaryHistory h = History({0, 200}, {50, 0});
  // Thruster 1 continues 100 s (200 + 100 = 300); thruster 0 switched off at
  // t0 - 50, so it may restart at t0 + 1150.
  EXPECT_TRUE(Check(r, {{1, t0, t0 + 100}, {0, t0 + 1150, t0 + 1450}}, 2, t0, 2 * t0, h).empty());
  EXPECT_EQ(Rules(Check(r, {{1, t0, t0 + 99}, {0, t0 + 1150, t0 + 1450}}, 2, t0, 2 * t0, h)),
            Set({"min_burn"}));
  EXPECT_EQ(Rules(Check(r, {{1, t0, t0 + 100}, {0, t0 + 1149, t0 + 1450}}, 2, t0, 2 * t0, h)),
            Set({"min_off_same"}));
}

// ---------------------------------------------------- allow_burn_across_end

TEST(RuleChecker, BurnAcrossEnd) {
  OperationalRules r = Thesis();
  const double tf = 7200;
  r.allow_burn_across_end = false;
  EXPECT_EQ(Rules(Check(r, {{0, tf - 100, tf}}, 2, 0, tf)), Set({"min_burn"}));
  r.allow_burn_across_end = true;
  EXPECT_TRUE(Check(r, {{0, tf - 100, tf}}, 2, 0, tf).empty());
  // A short burn that stops before tf is still too short.
  EXPECT_EQ(Rules(Check(r, {{0, tf - 100, tf - 1}}, 2, 0, tf)), Set({"min_burn"}));
  // max_burn still applies to the part inside the horizon.
  r.max_burn_s = 600;
  EXPECT_EQ(Rules(Check(r, {{0, tf - 700, tf}}, 2, 0, tf)), Set({"max_burn"}));
}

// --------------------------------------------------------------- forced_off

TEST(RuleChecker, ForcedOffWindows) {
  const OperationalRules r = Thesis();
  const std::vector<ForcedOff> w = {{0, 1000, 2000}};
  const BoundaryHistory none;
  EXPECT_TRUE(Check(r, {{0, 2000, 2300}}, 2, 0, 86400, none, w).empty());
  EXPECT_TRUE(Check(r, {{0, 700, 1000}}, 2, 0, 86400, none, w).empty());
  EXPECT_TRUE(Check(r, {{0, 1999.9999995, 2300}}, 2, 0, 86400, none, w).empty());
  auto v = Check(r, {{0, 1999, 2300}}, 2, 0, 86400, none, w);
  ASSERT_EQ(Rules(v), Set({"forced_off"})) << Dump(v);
  EXPECT_DOUBLE_EQ(v[0].time_s, 1999);
  EXPECT_NE(v[0].message.find("by 1 s"), std::string::npos) << v[0].message;
  // A burn covering the whole window.
  EXPECT_EQ(Rules(Check(r, {{0, 900, 2100}}, 2, 0, 86400, none, w)), Set({"forced_off"}));
  // Another thruster is not affected.
  EXPECT_TRUE(Check(r, {{1, 1200, 1500}}, 2, 0, 86400, none, w).empty());
  // An unbounded window (failed thruster).
  EXPECT_EQ(Rules(Check(r, {{1, 5000, 5300}}, 2, 0, 86400, none, {{1, 4000, kInf}})),
            Set({"forced_off"}));
}

// ---------------------------------------------------------------- max_burns

TEST(RuleChecker, MaxBurnsPerThruster) {
  OperationalRules r = Thesis();
  r.max_burns_per_thruster = 2;
  const std::vector<Burn> two = {{0, 0, 300}, {0, 2000, 2300}, {1, 5000, 5300}};
  EXPECT_TRUE(Check(r, two).empty());
  std::vector<Burn> three = two;
  three.push_back({0, 4000, 4300});
  auto v = Check(r, three);
  ASSERT_EQ(Rules(v), Set({"max_burns"})) << Dump(v);
  EXPECT_DOUBLE_EQ(v[0].time_s, 4000);
  EXPECT_NE(v[0].message.find("starts 3 burns in the horizon > max_burns_per_thruster 2"),
            std::string::npos)
      << v[0].message;
  // The continuation of a history burn is not counted.
  std::vector<Burn> cont = {{0, 0, 300}, {0, 2000, 2300}, {0, 4000, 4300}};
  EXPECT_TRUE(Check(r, cont, 2, 0, 86400, History({400, 0}, {})).empty());
  r.max_burns_per_thruster = 0;
  EXPECT_EQ(Rules(Check(r, {{1, 0, 300}})), Set({"max_burns"}));
  r.max_burns_per_thruster = -1;
  std::vector<Burn> many;
  for (int k = 0; k < 20; ++k) many.push_back({0, 2000.0 * k, 2000.0 * k + 300});
  EXPECT_TRUE(Check(r, many).empty());
}

// ----------------------------------------------------------- merge/overlap

TEST(RuleChecker, TouchingBurnsAreMerged) {
  OperationalRules r = Thesis();
  r.max_burns_per_thruster = 1;
  // 200 + 200 s pieces form one 400 s burn, given in any order.
  EXPECT_TRUE(Check(r, {{0, 200, 400}, {0, 0, 200}}).empty());
  EXPECT_TRUE(Check(r, {{0, 0, 100}, {0, 100, 200}, {0, 200 + 5e-7, 300}}).empty());
  // Not touching: two 200 s burns, each too short, too close, and one too many.
  EXPECT_EQ(Rules(Check(r, {{0, 0, 200}, {0, 201, 401}})),
            Set({"max_burns", "min_burn", "min_burn", "min_off_same"}));
}

TEST(RuleChecker, OverlappingBurnsOfOneThrusterAreReportedAndUnited) {
  const OperationalRules r = Thesis();
  auto v = Check(r, {{0, 0, 400}, {0, 300, 600}});
  ASSERT_EQ(Rules(v), Set({"overlap"})) << Dump(v);
  EXPECT_DOUBLE_EQ(v[0].time_s, 300);
  // The union [0, 600) is judged: a 700 s max_burn holds, 500 s does not.
  OperationalRules r2 = r;
  r2.max_burn_s = 500;
  EXPECT_EQ(Rules(Check(r2, {{0, 0, 400}, {0, 300, 600}})), Set({"overlap", "max_burn"}));
}

// ------------------------------------------------------------ malformed

TEST(RuleChecker, MalformedAndOutsideBurns) {
  const OperationalRules r = Thesis();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Rules(Check(r, {{2, 0, 300}})), Set({"malformed"}));
  EXPECT_EQ(Rules(Check(r, {{-1, 0, 300}})), Set({"malformed"}));
  EXPECT_EQ(Rules(Check(r, {{0, 300, 300}})), Set({"malformed"}));
  EXPECT_EQ(Rules(Check(r, {{0, 400, 300}})), Set({"malformed"}));
  EXPECT_EQ(Rules(Check(r, {{0, nan, 300}})), Set({"malformed"}));
  EXPECT_EQ(Rules(Check(r, {{0, 0, kInf}})), Set({"malformed"}));
  auto v = Check(r, {{0, -1, 300}}, 2, 0, 3600);
  ASSERT_EQ(Rules(v), Set({"horizon"})) << Dump(v);
  EXPECT_NE(v[0].message.find("[-1, 300)"), std::string::npos) << v[0].message;
  EXPECT_EQ(Rules(Check(r, {{0, 3400, 3600.01}}, 2, 0, 3600)), Set({"horizon"}));
  // Within tolerance of the horizon ends: fine.
  EXPECT_TRUE(Check(r, {{0, -5e-7, 300}, {0, 3300, 3600 + 5e-7}}, 2, 0, 3600).empty());
  // A malformed burn takes no further part (it would break min_burn and the gaps).
  EXPECT_EQ(Rules(Check(r, {{0, 0, 300}, {0, 500, 400}})), Set({"malformed"}));
}

TEST(RuleChecker, ViolationsSortedByTimeAndIndependentOfInputOrder) {
  const OperationalRules r = Thesis();
  std::vector<Burn> burns = {{1, 5000, 5100}, {0, 0, 300}, {0, 700, 1000}, {1, 1100, 1400}};
  auto a = Check(r, burns);
  ASSERT_GE(a.size(), 3u) << Dump(a);
  for (std::size_t k = 1; k < a.size(); ++k) EXPECT_LE(a[k - 1].time_s, a[k].time_s);
  std::reverse(burns.begin(), burns.end());
  auto b = Check(r, burns);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k].message, b[k].message);
}

TEST(RuleChecker, InvalidInputsThrow) {
  const OperationalRules r = Thesis();
  EXPECT_THROW(Check(r, {}, 2, 100, 100), std::invalid_argument);
  EXPECT_THROW(Check(r, {}, 2, 0, kInf), std::invalid_argument);
  EXPECT_THROW(Check(r, {}, -1), std::invalid_argument);
  OperationalRules bad = r;
  bad.max_simultaneous = 0;
  try {
    Check(bad, {});
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_simultaneous"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Check(r, {}, 2, 0, 100, History({1, 2, 3}, {})), std::invalid_argument);
  EXPECT_THROW(Check(r, {}, 2, 0, 100, {}, {{2, 0, 10}}), std::invalid_argument);
  EXPECT_THROW(Check(r, {}, 2, 0, 100, {}, {{0, 10, 5}}), std::invalid_argument);
}

// ====================================================================
// Randomized cross-check against a discrete pattern evaluator.
//
// The reference works on an on/off pattern on[i][j] per 1-minute interval and
// re-derives every rule from edges of the pattern: a rising edge of thruster
// i at node j (on at j, off at j-1, where "interval -1" is the history state),
// a falling edge at node j (off at j, on at j-1), plus a virtual falling
// edge at -off_for for a thruster off at t0. It checks gaps over ALL pairs
// of edges (not only consecutive burns), simultaneity per interval and
// forced-off overlap per interval.

struct PatternCase {
  int num_thrusters = 0;
  int num_intervals = 0;
  double dt = 60.0;
  std::vector<std::vector<int>> on;  // [thruster][interval]
  OperationalRules rules;
  BoundaryHistory history;
  std::vector<ForcedOff> forced_off;  // times relative to t0 = 0
};

std::set<std::string> PatternVerdict(const PatternCase& c) {
  const double eps = 1e-9;
  std::set<std::string> bad;
  const OperationalRules& r = c.rules;
  const int n = c.num_thrusters, N = c.num_intervals;
  auto state = [&](int i, int j) -> bool {  // j = -1: the history state
    if (j < 0) return c.history.on_for(i) > 0.0;
    return c.on[i][j] != 0;
  };
  for (int j = 0; j < N; ++j) {
    int count = 0;
    for (int i = 0; i < n; ++i) count += state(i, j);
    if (count > r.max_simultaneous) bad.insert("max_simultaneous");
  }
  std::vector<std::vector<double>> rises(n), falls(n);
  for (int i = 0; i < n; ++i) {
    if (!state(i, -1) && std::isfinite(c.history.off_for(i))) {
      falls[i].push_back(-c.history.off_for(i));
    }
    for (int j = 0; j < N; ++j) {
      if (state(i, j) && !state(i, j - 1)) rises[i].push_back(j * c.dt);
      if (!state(i, j) && state(i, j - 1)) falls[i].push_back(j * c.dt);
    }
    // Runs: from each on-interval that follows an off one (or the history
    // burn) to the next off interval.
    for (int j = 0; j < N; ++j) {
      const bool starts_run = state(i, j) && (j == 0 || !state(i, j - 1));
      if (!starts_run) continue;
      int k = j;
      while (k < N && state(i, k)) ++k;
      double length = (k - j) * c.dt;
      if (j == 0 && state(i, -1)) length += c.history.on_for(i);
      if (length < r.min_burn_s - eps && !(r.allow_burn_across_end && k == N)) {
        bad.insert("min_burn");
      }
      if (length > r.max_burn_s + eps) bad.insert("max_burn");
    }
    if (state(i, -1) && !state(i, 0) && c.history.on_for(i) < r.min_burn_s - eps) {
      bad.insert("min_burn");
    }
    if (r.max_burns_per_thruster >= 0 &&
        static_cast<int>(rises[i].size()) > r.max_burns_per_thruster) {
      bad.insert("max_burns");
    }
    for (const ForcedOff& w : c.forced_off) {
      if (w.thruster != i) continue;
      for (int j = 0; j < N; ++j) {
        if (state(i, j) && std::min((j + 1) * c.dt, w.end_s) - std::max(j * c.dt, w.start_s) > 0) {
          bad.insert("forced_off");
        }
      }
    }
  }
  for (int l = 0; l < n; ++l) {
    for (double rise : rises[l]) {
      for (int i = 0; i < n; ++i) {
        for (double fall : falls[i]) {
          if (fall > rise) continue;
          const double gap = rise - fall;
          if (i == l && gap < r.min_off_same_s - eps) bad.insert("min_off_same");
          if (i != l && gap < r.min_gap_other_s - eps) bad.insert("min_gap_other");
        }
      }
    }
  }
  return bad;
}

double Pick(std::mt19937& rng, const std::vector<double>& values) {
  return values[std::uniform_int_distribution<std::size_t>(0, values.size() - 1)(rng)];
}

PatternCase RandomCase(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto coin = [&](double p) { return u(rng) < p; };
  PatternCase c;
  c.num_thrusters = std::uniform_int_distribution<int>(1, 4)(rng);
  c.num_intervals = std::uniform_int_distribution<int>(8, 40)(rng);
  const double dt = c.dt;
  OperationalRules& r = c.rules;
  r.max_simultaneous = coin(0.7) ? 1 : 2;
  // Durations on the grid, off the grid (half intervals) and zero.
  r.min_burn_s = Pick(rng, {0, dt, 2 * dt, 3 * dt, 2.5 * dt, 4 * dt});
  r.max_burn_s = coin(0.5) ? kInf : r.min_burn_s + Pick(rng, {dt, 2 * dt, 3.5 * dt, 6 * dt});
  if (r.max_burn_s <= 0) r.max_burn_s = dt;
  r.min_off_same_s = Pick(rng, {0, dt, 3 * dt, 4 * dt, 5.5 * dt, 8 * dt});
  r.min_gap_other_s = Pick(rng, {0, dt, 2 * dt, 1.5 * dt});
  r.max_burns_per_thruster = std::uniform_int_distribution<int>(-1, 3)(rng);
  r.allow_burn_across_end = coin(0.5);
  if (coin(0.6)) {
    c.history.on_for_s.assign(c.num_thrusters, 0.0);
    c.history.off_for_s.assign(c.num_thrusters, kInf);
    for (int i = 0; i < c.num_thrusters; ++i) {
      if (coin(0.25)) {
        c.history.on_for_s[i] = Pick(rng, {30, dt, 90, 2 * dt, 150, 3 * dt, 500});
      } else if (coin(0.6)) {
        c.history.off_for_s[i] = Pick(rng, {0, 30, dt, 2 * dt, 150, 4 * dt, 1000});
      }
    }
  }
  const int windows = std::uniform_int_distribution<int>(0, 2)(rng);
  for (int k = 0; k < windows; ++k) {
    const int i = std::uniform_int_distribution<int>(0, c.num_thrusters - 1)(rng);
    // Endpoints on nodes or 0.1 s-rounded off nodes.
    auto t = [&]() {
      const double node = std::uniform_int_distribution<int>(0, c.num_intervals)(rng) * dt;
      return coin(0.5) ? node : node + std::round(u(rng) * 590) / 10.0;
    };
    double a = t(), b = t();
    if (a > b) std::swap(a, b);
    if (b == a) b = a + 0.5;
    c.forced_off.push_back({i, a, b});
  }
  // Pattern: a few burns of random thrusters with lengths and gaps near the
  // rule values, so that both valid and invalid schedules are common.
  c.on.assign(c.num_thrusters, std::vector<int>(c.num_intervals, 0));
  for (int i = 0; i < c.num_thrusters; ++i) {
    if (c.history.on_for(i) > 0 && coin(0.7)) {
      const int len = std::uniform_int_distribution<int>(1, 4)(rng);
      for (int j = 0; j < std::min(len, c.num_intervals); ++j) c.on[i][j] = 1;
    }
  }
  int j = std::uniform_int_distribution<int>(0, 6)(rng);
  while (j < c.num_intervals) {
    const int i = std::uniform_int_distribution<int>(0, c.num_thrusters - 1)(rng);
    const int len = std::uniform_int_distribution<int>(1, 5)(rng);
    for (int k = j; k < std::min(j + len, c.num_intervals); ++k) c.on[i][k] = 1;
    if (coin(0.15) && c.num_thrusters > 1) {  // overlapping second thruster
      const int l = (i + 1) % c.num_thrusters;
      for (int k = j + 1; k < std::min(j + len + 1, c.num_intervals); ++k) c.on[l][k] = 1;
    }
    j += len + std::uniform_int_distribution<int>(0, 9)(rng);
  }
  return c;
}

// Burns of the pattern, with runs randomly cut into touching pieces, times
// shifted by t0 and jittered well inside kTimeTolerance, in random order.
std::vector<Burn> ToBurns(const PatternCase& c, double t0, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-2e-7, 2e-7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Burn> burns;
  for (int i = 0; i < c.num_thrusters; ++i) {
    int j = 0;
    while (j < c.num_intervals) {
      if (!c.on[i][j]) {
        ++j;
        continue;
      }
      int k = j;
      while (k < c.num_intervals && c.on[i][k]) ++k;
      int a = j;
      for (int cut = j + 1; cut < k; ++cut) {
        if (u(rng) < 0.3) {
          burns.push_back({i, t0 + a * c.dt + jitter(rng), t0 + cut * c.dt + jitter(rng)});
          a = cut;
        }
      }
      burns.push_back({i, t0 + a * c.dt + jitter(rng), t0 + k * c.dt + jitter(rng)});
      j = k;
    }
  }
  std::shuffle(burns.begin(), burns.end(), rng);
  return burns;
}

TEST(RuleCheckerCrossCheck, AgreesWithPatternEvaluatorOnRandomSchedules) {
  std::mt19937 rng(20240611);
  const int kCases = 20000;
  int ok = 0;
  std::map<std::string, int> seen;
  for (int n = 0; n < kCases; ++n) {
    const PatternCase c = RandomCase(rng);
    const double t0 = (n % 2 == 0) ? 0.0 : 86400.0 * 3 + 0.25;
    std::vector<ForcedOff> shifted = c.forced_off;
    for (ForcedOff& w : shifted) {
      w.start_s += t0;
      w.end_s += t0;
    }
    const std::vector<Burn> burns = ToBurns(c, t0, rng);
    const std::vector<RuleViolation> v = CheckOperationalRules(
        c.rules, c.history, shifted, c.num_thrusters, t0, t0 + c.num_intervals * c.dt, burns);
    std::set<std::string> got;
    for (const RuleViolation& x : v) got.insert(x.rule);
    const std::set<std::string> want = PatternVerdict(c);
    ASSERT_EQ(got, want) << "case " << n << "\n" << Dump(v);
    if (want.empty()) ++ok;
    for (const std::string& s : want) ++seen[s];
  }
  // Both verdicts must be common, and every rule must have been broken often,
  // or the comparison proves little.
  EXPECT_GT(ok, kCases / 20);
  EXPECT_LT(ok, kCases * 19 / 20);
  for (const char* rule : {"max_simultaneous", "min_burn", "max_burn", "min_off_same",
                           "min_gap_other", "forced_off", "max_burns"}) {
    EXPECT_GT(seen[rule], kCases / 50) << rule;
  }
  std::printf("cross-check: %d cases, %d valid;", kCases, ok);
  for (const auto& [rule, count] : seen) std::printf(" %s %d", rule.c_str(), count);
  std::printf("\n");
}

}  // namespace
}  // namespace thrustsched::transcription
