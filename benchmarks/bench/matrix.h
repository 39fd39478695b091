// The benchmark matrix of thrustsched-bench: which scenario is run with which
// scheme, formulation, encoding, horizon, step, rules and solver settings,
// grouped by the sections of the report (accuracy, cost, formulations and
// encodings, scaling, operational constraints, ...).
//
//   bench::MatrixOptions o;
//   o.quick = false;
//   o.scenario_dirs = {"data/scenarios", "benchmarks/bench/scenarios"};
//   std::vector<bench::CaseSpec> cases = bench::BuildMatrix(o);   // filtered by o.scenario_glob
//
// Every case names a scenario file (parsed by app::LoadScenario's parser)
// and a JSON merge patch (RFC 7386) applied to it before parsing, so that
// horizon, step, scheme, formulation, encoding and rules changes go through
// the same validation as a user's scenario file.
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_MATRIX_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_MATRIX_H_

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "milp/solver.h"

namespace thrustsched::bench {

/// Report sections (also the `section` column of results.csv).
inline constexpr const char* kSectionTargets = "targets";
inline constexpr const char* kSectionAccuracy = "accuracy";
inline constexpr const char* kSectionCost = "cost";
inline constexpr const char* kSectionSchemeSolve = "scheme_solve";
inline constexpr const char* kSectionFormulation = "formulation";
inline constexpr const char* kSectionAblation = "ablation";
inline constexpr const char* kSectionScalingHorizon = "scaling_horizon";
inline constexpr const char* kSectionScalingStep = "scaling_step";
inline constexpr const char* kSectionOperations = "operations";
inline constexpr const char* kSectionSolverSpeed = "solver_speed";
inline constexpr const char* kSectionCollisionAvoidance = "collision_avoidance";
inline constexpr const char* kSectionTransfer = "transfer";
inline constexpr const char* kSectionRandomWeeks = "random_weeks";

/// The random weeks' draw (scripts/random_weeks.py): a seed fixed here and
/// never used while developing the search (develop on others), and how many.
inline constexpr int kRandomWeeksSeed = 8123;
inline constexpr int kRandomWeeksCount = 50;
/// Each random week, on each arm: to a 1 % gap, stopped at this limit.
inline constexpr double kRandomWeeksTimeLimitS = 60.0;

enum class CaseKind {
  kAccuracy,     // every scheme vs the reference on each step of `accuracy_steps_s`
  kDiscretise,   // discretise only (and the error vs the reference)
  kBuild,        // discretise + build (sizes, build time, memory)
  kSolve,        // + LP relaxation + MILP solve + independent check
  kConjunction,  // collision avoidance: SolveConjunction + verification (conjunction_case.h)
  kTransfer,     // an orbit transfer scenario, `thrustsched transfer`'s run (transfer_case.h)
};

/// The search a solve case with `search` runs: the bench's arms of the
/// solver-speed section.
enum class SearchArm {
  kThisRelease,  // SearchOptions' defaults: what `thrustsched solve` does
  /// The search as the previous release ran it, its LP relaxation by CLP's
  /// barrier (RelaxationOptions::LpMethod::kClpBarrier), for the
  /// side-by-side ratio.
  kPreviousRelease,
  /// The lazy rows' first LP without presolve
  /// (LazyRowOptions::presolve_lp_relaxation false), the ablation arm of
  /// section 8.1.
  kLazyLpUnpresolved,
};

struct CaseSpec {
  std::string id;  // unique; also the file stem under DIR/runs/
  std::string section;
  std::string scenario;  // scenario name (file stem), matched by --scenarios
  std::string scenario_path;
  nlohmann::json patch = nlohmann::json::object();  // merge patch for the scenario JSON
  std::string variant;  // short human label ("rules off", "dual LP", ...)
  CaseKind kind = CaseKind::kSolve;
  int repeats = 1;

  // Solver settings (kSolve).
  double time_limit_s = 60.0;
  long long max_nodes = -1;  // >= 0: branch-and-bound node limit (deterministic)
  double relative_gap = 1e-4;
  int threads = 1;
  milp::LpAlgorithm lp_algorithm = milp::LpAlgorithm::kPrimal;
  bool use_objective_step = true;  // pass ScheduleMilp::objective_step() to the solver
  /// The problem-aware search (transcription::SearchSchedule, what `solve`
  /// does) instead of CBC on the whole MILP (the first release's path).
  bool search = false;
  /// With `search`: which search (SearchArm).
  SearchArm search_arm = SearchArm::kThisRelease;
  /// Targets of the solver-speed section (NaN: none): seconds to a proven
  /// 1 % gap, seconds to proven optimality, and a gap to reach within
  /// target_gap_s seconds.
  double target_1pct_s = std::numeric_limits<double>::quiet_NaN();
  double target_opt_s = std::numeric_limits<double>::quiet_NaN();
  double target_gap = std::numeric_limits<double>::quiet_NaN();
  double target_gap_s = std::numeric_limits<double>::quiet_NaN();
  bool lp_relaxation = true;  // also solve the root LP alone (lp_bound, lp_s)
  /// Algorithm of that separate LP solve if set (else lp_algorithm): the
  /// encoding comparison wants the bound itself, with the fastest algorithm.
  std::optional<milp::LpAlgorithm> lp_relaxation_algorithm;
  double lp_relaxation_time_limit_s = 0.0;  // > 0: its own limit (else time_limit_s)
  bool error_metrics = true;                // max_rel_err_* against the reference discretisation
  bool external = false;                    // cross-check the exported MPS with cbc / glpsol
  double external_time_limit_s = 60.0;

  // kAccuracy: steps to compare (s) and schemes (empty = all but the reference).
  std::vector<double> accuracy_steps_s;

  // Published figure this case reproduces (NaN if none) and its source.
  double published = std::numeric_limits<double>::quiet_NaN();
  std::string published_source;
  std::string note;  // written to the `note` column

  // kTransfer: the published figure, as the case id and the key of
  // data/reference/transfers.json ("bombrun_case1", "minimum_time_d"); the
  // key's unit suffix (_h, _d, _km_s) is the figure's unit.
  std::string reference_id, reference_key;
};

/// A solve case's path: its `solver_path` column and the end of its
/// solver-speed case id (AddSolverSpeed's arms). The one place these names
/// are spelled: the runner, the matrix and the report use these.
struct SolverPathName {
  const char* column;
  const char* id_suffix;
};
inline constexpr SolverPathName kSearchPath{"search", "-search"};
inline constexpr SolverPathName kSearchPreviousPath{"search_previous", "-previous"};
inline constexpr SolverPathName kSearchLazyLpUnpresolvedPath{"search_lazy_lp_unpresolved",
                                                             "-lazy-lp-unpresolved"};
inline constexpr SolverPathName kCbcPath{"cbc", "-cbc"};

/// The `solver_path` column of a solve case (SolverPathName::column).
std::string SolverPath(const CaseSpec& spec);
/// The end of the id of a solver-speed case on that path
/// (SolverPathName::id_suffix; a path not named above: kCbcPath's).
std::string SolverPathIdSuffix(const std::string& solver_path);

/// --quick: node limit of every solve, and the wall-clock guard against a hang.
inline constexpr long long kQuickMaxNodes = 2000;
inline constexpr double kQuickGuardSeconds = 600.0;

struct MatrixOptions {
  bool quick = false;
  std::vector<std::string> scenario_dirs;  // searched in order for <name>.json
  std::string scenario_glob = "*";         // fnmatch on the scenario name
  int threads = 2;                         // CBC threads of matrix solves (targets fixed)
  double time_limit_s = 60.0;              // per matrix solve (targets fixed)
  int timing_repeats = 3;                  // repeats of the timing-target cases
  double external_time_limit_s = 0.0;      // cross-check solvers; 0: min(30 s, time_limit_s)
  /// Folder of the random weeks (scripts/random_weeks.py's files, which the
  /// bench writes there); empty: the section "random_weeks" is not built.
  std::string random_weeks_dir;
};

/// The cases, in run order. Scenario files are located but not parsed.
/// @throws std::invalid_argument if a needed scenario file is missing from
///         every directory (naming it), or an option is out of range.
std::vector<CaseSpec> BuildMatrix(const MatrixOptions& options);

/// The discretisation schemes compared, by scenario-file name, in
/// dynamics::AllSchemes() order: all but the reference (the yardstick, not a
/// contender).
const std::vector<std::string>& ComparedSchemes();

/// Published thesis figures used by the matrix and the report (value, source).
struct Published {
  double value;
  const char* source;
};
/// Table 4.1 (horizon days 1..8) and Table 4.2 (t1 days 1..7), in m/s (L1).
Published Table41(int horizon_days);
Published Table42(int t1_days);

/// RFC 7386 JSON merge patch.
nlohmann::json MergePatch(nlohmann::json target, const nlohmann::json& patch);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_MATRIX_H_
