// Stop signals reach every phase of the problem-aware search: on a
// six-thruster week that takes tens of seconds to prove (data/scenarios/hard/),
// SIGINT or SIGTERM sent from inside the relaxation, the nets' restricted
// MILPs, the tree on thruster totals and CBC on the whole MILP stops the solve
// within 2 s, and the best schedule found is checked and written with its gap
// (or, before the first one, the run ends with no schedule and exit 4).
//
// A time limit that falls inside each of those phases keeps the incumbent
// the same way: the hook holds the solving thread at the phase's report
// until the limit has passed, so the limit falls in that phase.
//
// The signal is sent by the CLI's own progress hook (app/run_hooks.h) at the
// first progress report from inside the named phase, so it always lands in
// that phase whatever the machine's load: the real signal path in a child
// process, not a timer. The only clock in the test is the stop's latency.
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/cli.h"
#include "app/run_hooks.h"
#include "tests/app/cli_runner.h"
#include "transcription/search/search_options.h"

namespace thrustsched::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kWeek = THRUSTSCHED_DATA_DIR "/scenarios/hard/year_ideal6_fixed_w10.json";

// Which progress report of the phase sends the signal.
enum class Trigger {
  kAnnouncement,  // the phase's announcement (the tree's LPs report nothing)
  kFirstReport,   // its first report after the announcement (a MILP's)
  kLpIterations,  // its first report of LP iterations (from inside CLP)
};

struct PhaseCase {
  std::string phase;
  int signal;
  Trigger trigger;
  /// Phases left out so that `phase` comes sooner.
  std::vector<std::string> disabled;
};

// gtest names a case by its phase (ctest shows it beside the test's name).
void PrintTo(const PhaseCase& c, std::ostream* os) { *os << c.phase; }

// The hard week with progress every 0.5 s and the given phases left out.
std::string PatchedWeek(const std::string& dir, const PhaseCase& c) {
  json j = json::parse(ReadFile(kWeek));
  j["solver"]["progress_interval_s"] = 0.5;
  j["solver"]["threads"] = 1;
  if (!c.disabled.empty()) j["solver"]["search"] = {{"disabled_phases", c.disabled}};
  const std::string path = dir + "/week.json";
  std::ofstream(path) << j.dump(1);
  return path;
}

// The first progress report from inside the case's phase.
bool IsTrigger(const PhaseCase& c, const milp::SolveProgress& p) {
  if (p.stage() != c.phase) return false;
  if (p.stage_begins != (c.trigger == Trigger::kAnnouncement)) return false;
  return c.trigger != Trigger::kLpIterations || p.lp_iterations >= 0;
}

// Runs `solve` on the scenario in a child with the given hooks and extra
// arguments.
RunResult SolveInChild(const std::string& scenario, const std::string& out,
                       const app::RunHooks& hooks, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"thrustsched", "solve",      scenario,      "--out",
                                   out,           "--no-plots", "--no-report", "--no-diagnose"};
  args.insert(args.end(), extra.begin(), extra.end());
  return RunInChild([&] { return app::RunCli(args, hooks); }, 600.0);
}

// Runs the CLI in a child; its progress hook sends the case's signal at the
// first report from inside the phase and writes the search clock's time of
// it to stderr ("test hook: signal at S s").
RunResult SolveAndSignalInPhase(const PhaseCase& c, const std::string& scenario,
                                const std::string& out) {
  app::RunHooks hooks;
  bool sent = false;
  hooks.on_progress = [&](const milp::SolveProgress& p) {
    if (sent || !IsTrigger(c, p)) return;
    sent = true;
    std::fprintf(stderr, "test hook: signal at %.3f s\n", p.wall_seconds);
    std::fflush(stderr);
    kill(getpid(), c.signal);
  };
  return SolveInChild(scenario, out, hooks);
}

double SignalTime(const std::string& err) {
  const size_t at = err.find("test hook: signal at ");
  if (at == std::string::npos) return -1.0;
  return std::stod(err.substr(at + std::string("test hook: signal at ").size()));
}

// The phase of the last step a phase logged in a solver_detail
// "search: PHASE: step; PHASE: step; ...; notes".
std::string LastPhase(const std::string& detail) {
  std::string last;
  size_t last_at = 0;
  for (const std::string& phase : transcription::SearchPhaseNames()) {
    for (const std::string& head : {std::string("search: "), std::string("; ")}) {
      const size_t at = detail.rfind(head + phase + ": ");
      if (at != std::string::npos && (last.empty() || at > last_at)) {
        last = phase;
        last_at = at;
      }
    }
  }
  return last;
}

// A stopped solve: no schedule yet (exit 4, no incumbent), or the best
// incumbent reported written with its open gap and checked (exit 0).
void ExpectTheBestScheduleKept(const RunResult& r, const json& summary, const std::string& out) {
  if (summary["status"] == "no_solution") {
    EXPECT_EQ(r.exit_code, 4) << r.Describe();
    EXPECT_TRUE(summary["incumbents"].empty()) << summary.dump();
    return;
  }
  EXPECT_EQ(r.exit_code, 0) << r.Describe();
  EXPECT_EQ(summary["status"], "feasible") << summary.dump();
  ASSERT_FALSE(summary["incumbents"].empty()) << summary.dump();
  EXPECT_DOUBLE_EQ(summary["objective"].get<double>(),
                   summary["incumbents"].back()["objective"].get<double>());
  EXPECT_GT(summary["gap"].get<double>(), 0.0);
  EXPECT_TRUE(summary["check"]["operational_ok"].get<bool>()) << summary.dump();
  EXPECT_TRUE(fs::exists(out + "/schedule.csv"));
}

class SearchSignals : public ::testing::TestWithParam<PhaseCase> {};

TEST_P(SearchSignals, StopWithinTwoSecondsAndKeepTheBestSchedule) {
  const PhaseCase& c = GetParam();
  const std::string dir = TempDir("search_signal_" + c.phase);
  const RunResult r = SolveAndSignalInPhase(c, PatchedWeek(dir, c), dir + "/o");
  ASSERT_TRUE(r.exited) << r.Describe();
  const double signalled_at = SignalTime(r.err);
  ASSERT_GE(signalled_at, 0.0) << "the phase never reported: " << r.Describe();
  const json summary = ReadJson(dir + "/o/summary.json");
  // The step log ends in the phase the signal stopped.
  const std::string detail = summary["solver_detail"].get<std::string>();
  EXPECT_EQ(LastPhase(detail), c.phase) << detail;
  EXPECT_TRUE(summary["interrupted"].get<bool>()) << summary.dump();
  // The search's clock and the solve's start within milliseconds of each
  // other: the solve's wall time less the signal's time is the stop's latency.
  EXPECT_LE(summary["solve_seconds"].get<double>() - signalled_at, 2.0) << r.Describe();
  ExpectTheBestScheduleKept(r, summary, dir + "/o");
  fs::remove_all(dir);
}

// The time limit of the time-limit cases: long enough for every case's
// phase to begin under a heavy load (a phase that begins later is skipped,
// not failed); the hook then holds the solve there until it has passed.
constexpr double kTimeLimitS = 45.0;

// Runs the CLI with --time-limit kTimeLimitS in a child; at the first report
// from inside the phase its hook sleeps until the limit has passed and writes
// "test hook: held at S s", or "test hook: late" if the phase began after it.
RunResult SolveWithLimitFallingInPhase(const PhaseCase& c, const std::string& scenario,
                                       const std::string& out) {
  app::RunHooks hooks;
  bool held = false;
  hooks.on_progress = [&](const milp::SolveProgress& p) {
    if (held || !IsTrigger(c, p)) return;
    held = true;
    const double wait_s = kTimeLimitS + 0.3 - p.wall_seconds;
    std::fprintf(stderr, wait_s > 0 ? "test hook: held at %.3f s\n" : "test hook: late\n",
                 p.wall_seconds);
    std::fflush(stderr);
    if (wait_s > 0) usleep(static_cast<useconds_t>(wait_s * 1e6));
  };
  return SolveInChild(scenario, out, hooks, {"--time-limit", std::to_string(kTimeLimitS)});
}

class SearchTimeLimits : public ::testing::TestWithParam<PhaseCase> {};

TEST_P(SearchTimeLimits, ALimitInsideThePhaseStopsThereAndKeepsTheBestSchedule) {
  const PhaseCase& c = GetParam();
  const std::string dir = TempDir("search_limit_" + c.phase);
  const RunResult r = SolveWithLimitFallingInPhase(c, PatchedWeek(dir, c), dir + "/o");
  ASSERT_TRUE(r.exited) << r.Describe();
  if (r.err.find("test hook: late") != std::string::npos) {
    GTEST_SKIP() << "the phase began after the " << kTimeLimitS << " s limit (a loaded machine)";
  }
  const json summary = ReadJson(dir + "/o/summary.json");
  if (r.err.find("test hook: held at ") == std::string::npos &&
      summary["solve_seconds"].get<double>() >= kTimeLimitS) {
    GTEST_SKIP() << "the limit fell before the phase began (a loaded machine)";
  }
  ASSERT_NE(r.err.find("test hook: held at "), std::string::npos)
      << "the phase never reported: " << r.Describe();
  const std::string detail = summary["solver_detail"].get<std::string>();
  EXPECT_EQ(LastPhase(detail), c.phase) << detail;
  EXPECT_FALSE(summary["interrupted"].get<bool>()) << summary.dump();
  // The whole limit went to the solve (no diagnosis), and the solve ended
  // within 2 s of it.
  EXPECT_DOUBLE_EQ(summary["solve_time_limit_s"].get<double>(), kTimeLimitS);
  EXPECT_GE(summary["solve_seconds"].get<double>(), kTimeLimitS);
  EXPECT_LE(summary["solve_seconds"].get<double>(), kTimeLimitS + 2.0) << r.Describe();
  ExpectTheBestScheduleKept(r, summary, dir + "/o");
  fs::remove_all(dir);
}

const std::vector<std::string> kAllButWholeMilp = {"nets", "exact",   "improvement",
                                                   "tree", "windows", "exchange"};

const PhaseCase kRelaxation{"relaxation", SIGINT, Trigger::kLpIterations, {}};
const PhaseCase kNets{"nets", SIGTERM, Trigger::kFirstReport, {}};
const PhaseCase kTree{"tree", SIGINT, Trigger::kAnnouncement, {"exact", "improvement"}};
const PhaseCase kWholeMilp{"whole_milp", SIGTERM, Trigger::kFirstReport, kAllButWholeMilp};

std::string CaseName(const ::testing::TestParamInfo<PhaseCase>& info) { return info.param.phase; }

INSTANTIATE_TEST_SUITE_P(EachPhase, SearchSignals,
                         ::testing::Values(kRelaxation, kNets, kTree, kWholeMilp), CaseName);
INSTANTIATE_TEST_SUITE_P(EachPhase, SearchTimeLimits,
                         ::testing::Values(kRelaxation, kNets, kTree, kWholeMilp), CaseName);

}  // namespace
}  // namespace thrustsched::testing
