// Unit tests of the thrustsched-bench helpers: error metrics against closed
// forms, log-log fits on exact power laws, the CSV round trip, the JSON merge
// patch, medians and the benchmark matrix.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "benchmarks/bench/accuracy.h"
#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/report.h"
#include "benchmarks/bench/results.h"
#include "dynamics/discretisation.h"
#include "dynamics/models.h"
#include "dynamics/thrusters.h"

namespace thrustsched::bench {
namespace {

constexpr double kN = 7.2921159e-5;

TEST(FitLogLogSlope, RecoversExactPowerLaws) {
  const std::vector<double> h = {60, 150, 300, 600, 1800};
  for (double p : {1.0, 2.0, 4.0, 5.0}) {
    std::vector<double> e;
    for (double x : h) e.push_back(3e-7 * std::pow(x, p));
    EXPECT_NEAR(FitLogLogSlope(h, e), p, 1e-12) << p;
  }
}

TEST(FitLogLogSlope, IgnoresPointsAtTheFloorAndNeedsTwoPoints) {
  // Below the floor (and zeros) are dropped: only 600 and 1800 remain, slope 2.
  EXPECT_NEAR(FitLogLogSlope({60, 150, 600, 1800}, {1e-14, 0.0, 600.0 * 600, 1800.0 * 1800}, 1e-10),
              2.0, 1e-12);
  EXPECT_TRUE(std::isnan(FitLogLogSlope({60, 600}, {1e-14, 1.0}, 1e-10)));
  EXPECT_TRUE(std::isnan(FitLogLogSlope({}, {})));
  EXPECT_THROW(FitLogLogSlope({1, 2}, {1}), std::invalid_argument);
}

dynamics::DiscreteModel HcwDiscrete(dynamics::Scheme scheme, double step, int n) {
  const dynamics::HcwModel hcw(kN);
  dynamics::DiscretizationOptions o;
  o.scheme = scheme;
  return dynamics::Discretize(hcw,
                              dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005).AccelerationMatrix(),
                              dynamics::UniformGrid(0, step * n, n), o);
}

TEST(CompareDiscretisations, EulerErrorMatchesItsClosedForm) {
  // HCW, one interval of h: Euler gives Phi = I + A h; the reference is exp(A h).
  // Independent closed form: ||S^-1 (I + A h - exp(A h)) S||_F / ||S^-1 exp(A h) S||_F
  // with exp(A h) from HcwModel::TransitionMatrix (thesis (I.4), tested in dynamics).
  const double h = 600;
  const dynamics::HcwModel hcw(kN);
  const dynamics::DiscreteModel euler = HcwDiscrete(dynamics::Scheme::kEuler, h, 3);
  const dynamics::DiscreteModel exact = HcwDiscrete(dynamics::Scheme::kExactZoh, h, 3);
  const Eigen::VectorXd s = hcw.state_scale();
  const DiscretizationError e = CompareDiscretizations(euler, exact, s);
  const Eigen::MatrixXd a = hcw.Evaluate(0).a;
  const Eigen::MatrixXd phi = hcw.TransitionMatrix(h);
  const Eigen::MatrixXd si = s.cwiseInverse().asDiagonal();
  const Eigen::MatrixXd sd = s.asDiagonal();
  const Eigen::MatrixXd i6 = Eigen::MatrixXd::Identity(6, 6);
  const double expected = (si * (i6 + a * h - phi) * sd).norm() / (si * phi * sd).norm();
  EXPECT_NEAR(e.max_rel_err_phi, expected, 1e-9 * expected);
  // Euler's Gamma is h B U against the closed-form ZOH integral.
  const Eigen::MatrixXd u = dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005).AccelerationMatrix();
  const Eigen::MatrixXd g_exact = hcw.ZohInputMatrix(h) * u;
  const Eigen::MatrixXd g_euler = h * hcw.Evaluate(0).b * u;
  const double expected_g = (si * (g_euler - g_exact)).norm() / (si * g_exact).norm();
  EXPECT_NEAR(e.max_rel_err_gamma, expected_g, 1e-9 * expected_g);
  // Same model: zero error.
  const DiscretizationError z = CompareDiscretizations(exact, exact, s);
  EXPECT_EQ(z.max_rel_err_phi, 0.0);
  EXPECT_EQ(z.max_rel_err_gamma, 0.0);
}

TEST(CompareDiscretisations, Rk4OneStepOrderIsFiveForPhiAndFourForGamma) {
  std::vector<double> steps = {300, 600, 1200}, ep, eg;
  for (double h : steps) {
    const DiscretizationError e = CompareDiscretizations(
        HcwDiscrete(dynamics::Scheme::kRk4, h, 2), HcwDiscrete(dynamics::Scheme::kExactZoh, h, 2),
        dynamics::HcwModel(kN).state_scale());
    ep.push_back(e.max_rel_err_phi);
    eg.push_back(e.max_rel_err_gamma);
  }
  EXPECT_NEAR(FitLogLogSlope(steps, ep), 5.0, 0.05);
  EXPECT_NEAR(FitLogLogSlope(steps, eg), 4.0, 0.05);
}

TEST(CompareDiscretisations, RejectsMismatchedShapesAndScales) {
  const auto a = HcwDiscrete(dynamics::Scheme::kEuler, 300, 2);
  const auto b = HcwDiscrete(dynamics::Scheme::kEuler, 300, 3);
  const Eigen::VectorXd s = Eigen::VectorXd::Ones(6);
  EXPECT_THROW(CompareDiscretizations(a, b, s), std::invalid_argument);
  EXPECT_THROW(CompareDiscretizations(a, a, Eigen::VectorXd::Ones(5)), std::invalid_argument);
  Eigen::VectorXd bad = s;
  bad[2] = -1;
  EXPECT_THROW(CompareDiscretizations(a, a, bad), std::invalid_argument);
  EXPECT_THROW(
      GlobalPropagationError(a, a, Eigen::VectorXd::Zero(6), Eigen::MatrixXi::Zero(6, 3), s),
      std::invalid_argument);
}

TEST(GlobalPropagationError, FreeDriftOfEulerAgainstClosedForm) {
  // No thrust: x_N = Phi^N x0. Euler: (I + A h)^N x0, reference exp(A N h) x0.
  const double h = 600;
  const int n = 4;
  const dynamics::HcwModel hcw(kN);
  const Eigen::VectorXd x0 = (Eigen::VectorXd(6) << 1000, 0, 0, 0, 0, 0).finished();
  const Eigen::VectorXd s = hcw.state_scale();
  const double err = GlobalPropagationError(HcwDiscrete(dynamics::Scheme::kEuler, h, n),
                                            HcwDiscrete(dynamics::Scheme::kExactZoh, h, n), x0,
                                            Eigen::MatrixXi::Zero(6, n), s);
  const Eigen::MatrixXd step = Eigen::MatrixXd::Identity(6, 6) + hcw.Evaluate(0).a * h;
  double max_diff = 0, max_ref = (x0.cwiseQuotient(s)).lpNorm<Eigen::Infinity>();
  Eigen::VectorXd xe = x0;
  for (int j = 1; j <= n; ++j) {
    xe = step * xe;
    const Eigen::VectorXd xr = hcw.TransitionMatrix(j * h) * x0;
    max_diff = std::max(max_diff, (xe - xr).cwiseQuotient(s).lpNorm<Eigen::Infinity>());
    max_ref = std::max(max_ref, xr.cwiseQuotient(s).lpNorm<Eigen::Infinity>());
  }
  EXPECT_NEAR(err, max_diff / max_ref, 1e-9 * err);
  EXPECT_GT(err, 0.0);
}

TEST(Results, CsvRoundTripKeepsValuesQuotesAndEmptyCells) {
  Row r;
  r.Set("scenario", "hcw_table41_1d");
  r.Set("objective", 0.016391752577319587);
  r.Set("n_binaries", 1728);
  r.Set("note", "a, \"quoted\" note");
  r.Set("gap", std::numeric_limits<double>::quiet_NaN());
  Row r2;
  r2.Set("status", "optimal");
  const std::string path =
      (std::filesystem::temp_directory_path() / "bench_helpers_results.csv").string();
  WriteResultsCsv(path, {r, r2});
  const std::vector<Row> back = ReadResultsCsv(path);
  std::remove(path.c_str());
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].Get("scenario"), "hcw_table41_1d");
  EXPECT_NEAR(back[0].Num("objective"), 0.016391752577319587, 1e-11);
  EXPECT_EQ(back[0].Num("n_binaries"), 1728);
  EXPECT_EQ(back[0].Get("note"), "a, \"quoted\" note");
  EXPECT_FALSE(back[0].Has("gap"));
  EXPECT_TRUE(std::isnan(back[0].Num("gap")));
  EXPECT_EQ(back[1].Get("status"), "optimal");
  EXPECT_THROW(r.Set("no_such_column", 1.0), std::invalid_argument);
  EXPECT_THROW(ReadResultsCsv("/nonexistent/results.csv"), std::runtime_error);
}

TEST(Meta, RoundTripKeepsTheEarlierRunsOfAPartialRerun) {
  ReportMeta m;
  m.command = "thrustsched-bench --cases 'formulation-*' --merge";
  m.git_revision = "abc1234";
  m.cases_glob = "formulation-*";
  m.total_wall_s = 12.5;
  m.earlier.push_back({"thrustsched-bench --out x", "2026-11-22T06:43:50Z", "db60e22",
                       "5.30 6.33 6.02", "Intel(R) Xeon(R) Processor, 2 cores", "*", 4530.8});
  const std::string path =
      (std::filesystem::temp_directory_path() / "bench_helpers_meta.json").string();
  WriteMetaJson(path, m);
  const ReportMeta back = ReadMetaJson(path);
  std::remove(path.c_str());
  EXPECT_EQ(back.command, m.command);
  EXPECT_EQ(back.cases_glob, "formulation-*");
  ASSERT_EQ(back.earlier.size(), 1u);
  EXPECT_EQ(back.earlier[0].git_revision, "db60e22");
  EXPECT_EQ(back.earlier[0].cases_glob, "*");
  EXPECT_DOUBLE_EQ(back.earlier[0].total_wall_s, 4530.8);
  EXPECT_EQ(back.earlier[0].load_average, "5.30 6.33 6.02");
  EXPECT_EQ(back.earlier[0].machine, "Intel(R) Xeon(R) Processor, 2 cores");
}

TEST(Results, EveryContractColumnIsAResultColumn) {
  const auto& all = ResultColumns();
  const std::set<std::string> set(all.begin(), all.end());
  EXPECT_EQ(set.size(), all.size()) << "duplicate column";
  for (const std::string& c : ContractColumns()) EXPECT_TRUE(set.count(c)) << c;
  EXPECT_EQ(ContractColumns().size(), 29u);
  EXPECT_EQ(SplitCsvLine("a,\"b,c\",,d"), (std::vector<std::string>{"a", "b,c", "", "d"}));
  EXPECT_THROW(SplitCsvLine("a,\"b"), std::runtime_error);
}

TEST(MergePatch, FollowsRfc7386) {
  const nlohmann::json target = {{"a", "b"}, {"c", {{"d", "e"}, {"f", "g"}}}};
  const nlohmann::json patch = {{"a", "z"}, {"c", {{"f", nullptr}}}};
  EXPECT_EQ(MergePatch(target, patch), (nlohmann::json{{"a", "z"}, {"c", {{"d", "e"}}}}));
  EXPECT_EQ(MergePatch({{"a", {{"b", "c"}}}}, {{"a", {{"b", "d"}, {"c", nullptr}}}}),
            (nlohmann::json{{"a", {{"b", "d"}}}}));
  EXPECT_EQ(MergePatch({{"a", 1}}, nlohmann::json::array({1, 2})), nlohmann::json::array({1, 2}));
}

TEST(Median, OddEvenNaNAndInfinity) {
  EXPECT_EQ(Median({3, 1, 2}), 2);
  EXPECT_EQ(Median({4, 1, 3, 2}), 2.5);
  EXPECT_EQ(Median({std::nan(""), 5, 1}), 3);
  EXPECT_TRUE(std::isnan(Median({})));
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(Median({1, inf, inf}), inf);  // two of three runs never reached it
  EXPECT_EQ(Median({1, 2, inf}), 2);
}

TEST(Matrix, FullMatrixCoversTheIssueAndFindsEveryScenario) {
  MatrixOptions o;
  o.scenario_dirs = {std::string(THRUSTSCHED_DATA_DIR) + "/scenarios",
                     std::string(THRUSTSCHED_SOURCE_DIR) + "/benchmarks/bench/scenarios"};
  const std::vector<CaseSpec> cases = BuildMatrix(o);
  std::set<std::string> ids, sections, schemes_cost;
  int targets = 0;
  for (const CaseSpec& c : cases) {
    EXPECT_TRUE(ids.insert(c.id).second) << c.id;
    EXPECT_TRUE(std::filesystem::exists(c.scenario_path)) << c.scenario_path;
    sections.insert(c.section);
    if (c.section == kSectionCost) schemes_cost.insert(c.patch["discretisation"]["scheme"]);
    if (c.section == kSectionTargets) {
      ++targets;
      EXPECT_EQ(c.repeats, 3);
      EXPECT_EQ(c.threads, c.scenario == "hcw_table42_t1_2d" ? 1 : 2);
    }
  }
  EXPECT_EQ(targets, 2);
  EXPECT_EQ(schemes_cost.size(), 7u);
  // The orbit transfers: each case names its published figure.
  int transfers = 0;
  for (const CaseSpec& c : cases) {
    if (c.section != kSectionTransfer) continue;
    ++transfers;
    EXPECT_EQ(c.kind, CaseKind::kTransfer) << c.id;
    EXPECT_FALSE(c.reference_id.empty()) << c.id;
    EXPECT_FALSE(c.reference_key.empty()) << c.id;
  }
  EXPECT_EQ(transfers, 11);
  for (const char* s :
       {kSectionTargets, kSectionAccuracy, kSectionCost, kSectionSchemeSolve, kSectionFormulation,
        kSectionAblation, kSectionScalingHorizon, kSectionScalingStep, kSectionOperations}) {
    EXPECT_TRUE(sections.count(s)) << s;
  }
  // The glob filters by scenario name.
  o.scenario_glob = "hcw_table41_*";
  for (const CaseSpec& c : BuildMatrix(o)) EXPECT_EQ(c.scenario.rfind("hcw_table41_", 0), 0u);
  o.threads = 0;
  EXPECT_THROW(BuildMatrix(o), std::invalid_argument);
  o.threads = 1;
  o.scenario_dirs = {"/nonexistent"};
  EXPECT_THROW(BuildMatrix(o), std::invalid_argument);
}

// Every solver-speed case runs each of the four paths once, its id ending
// in its path's suffix, and the suffixes map back to the paths (the report
// groups a case's arms by them); an unknown path reads as the first
// release's.
TEST(Matrix, SolverSpeedArmsAreNamedByTheirPath) {
  MatrixOptions o;
  o.scenario_dirs = {std::string(THRUSTSCHED_DATA_DIR) + "/scenarios",
                     std::string(THRUSTSCHED_SOURCE_DIR) + "/benchmarks/bench/scenarios"};
  std::map<std::string, std::set<std::string>> paths_of_case;
  for (const CaseSpec& c : BuildMatrix(o)) {
    if (c.section != kSectionSolverSpeed) continue;
    const std::string path = SolverPath(c);
    const std::string suffix = SolverPathIdSuffix(path);
    ASSERT_GT(c.id.size(), suffix.size()) << c.id;
    EXPECT_EQ(c.id.substr(c.id.size() - suffix.size()), suffix) << c.id << " on " << path;
    EXPECT_TRUE(paths_of_case[c.id.substr(0, c.id.size() - suffix.size())].insert(path).second)
        << c.id;
    EXPECT_EQ(path == "search_previous", c.search && c.search_arm == SearchArm::kPreviousRelease);
  }
  ASSERT_GE(paths_of_case.size(), 22u);
  const std::set<std::string> all = {"search", "search_previous", "search_lazy_lp_unpresolved",
                                     "cbc"};
  for (const auto& [base, paths] : paths_of_case) EXPECT_EQ(paths, all) << base;
  EXPECT_EQ(SolverPathIdSuffix("search"), "-search");
  EXPECT_EQ(SolverPathIdSuffix("search_previous"), "-previous");
  EXPECT_EQ(SolverPathIdSuffix("search_lazy_lp_unpresolved"), "-lazy-lp-unpresolved");
  EXPECT_EQ(SolverPathIdSuffix("cbc"), "-cbc");
  EXPECT_EQ(SolverPathIdSuffix(""), "-cbc");
}

// The random weeks: both arms of every week file of the folder (other files
// ignored), to 1 % in the section's limit on 2 threads; none without the
// folder or in --quick.
TEST(Matrix, RandomWeeksRunBothArmsOfEveryWeekInTheFolder) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("bench_random_weeks_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  for (const char* f : {"rw_5_001_ideal6_failed.json", "rw_5_000_anzel4.json", "weeks.csv"}) {
    std::FILE* out = std::fopen((dir / f).c_str(), "w");
    ASSERT_NE(out, nullptr);
    std::fclose(out);
  }
  MatrixOptions o;
  o.scenario_dirs = {std::string(THRUSTSCHED_DATA_DIR) + "/scenarios",
                     std::string(THRUSTSCHED_SOURCE_DIR) + "/benchmarks/bench/scenarios"};
  auto random_ids = [&o] {
    std::vector<std::string> ids;
    for (const CaseSpec& c : BuildMatrix(o)) {
      if (c.section != kSectionRandomWeeks) continue;
      ids.push_back(c.id);
      EXPECT_TRUE(c.search) << c.id;
      EXPECT_EQ(c.threads, 2) << c.id;
      EXPECT_EQ(c.time_limit_s, kRandomWeeksTimeLimitS) << c.id;
      EXPECT_EQ(c.relative_gap, 0.01) << c.id;
      EXPECT_EQ(c.scenario_path, o.random_weeks_dir + "/" + c.scenario + ".json") << c.id;
    }
    return ids;
  };
  EXPECT_TRUE(random_ids().empty());
  o.random_weeks_dir = dir.string();
  EXPECT_EQ(random_ids(),
            (std::vector<std::string>{"random_weeks-rw_5_000_anzel4-2threads-search",
                                      "random_weeks-rw_5_000_anzel4-2threads-previous",
                                      "random_weeks-rw_5_001_ideal6_failed-2threads-search",
                                      "random_weeks-rw_5_001_ideal6_failed-2threads-previous"}));
  o.quick = true;
  EXPECT_TRUE(random_ids().empty());
  std::filesystem::remove_all(dir);
}

TEST(Published, ThesisTablesAreSlotMultiples) {
  // Independent check of the constants: Table 4.1 and 4.2 are whole numbers of
  // 5-min slots of 0.265 N / 4850 kg (0.016392 m/s): derived here, see
  // data/reference/thesis_tables.json.
  const double slot = 0.265 / 4850 * 300;
  const int t41_slots[] = {1, 5, 6, 7, 8, 8, 8, 8};
  for (int d = 1; d <= 8; ++d) EXPECT_NEAR(Table41(d).value, t41_slots[d - 1] * slot, 6e-4) << d;
  const int t42_slots[] = {110, 105, 104, 104, 104, 104, 103};
  for (int d = 1; d <= 7; ++d) EXPECT_NEAR(Table42(d).value, t42_slots[d - 1] * slot, 2e-3) << d;
  EXPECT_THROW(Table41(0), std::invalid_argument);
  EXPECT_THROW(Table42(8), std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::bench
