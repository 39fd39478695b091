// The HiGHS runner of the bench's cross-check (benchmarks/external/
// highs_solve.mjs through bench::RunExternalSolver): on a small MILP written
// by our own free-MPS writer, with an optimum found here by enumeration, it
// reports "optimal" and that objective; without the npm package it reports
// "skipped: <reason>" instead of failing. Also the parsing of its JSON line
// and the rule that no external objective beats our proven optimum.
// Skipped (GTEST_SKIP, shown by ctest as skipped) where node or the package
// (scripts/install-highs.sh) is missing. No assertion on times.
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "benchmarks/bench/external_solvers.h"
#include "benchmarks/bench/runner.h"
#include "milp/model.h"
#include "milp/model_io.h"

namespace thrustsched::bench {
namespace {

namespace fs = std::filesystem;

// A covering knapsack with a ranged row (exercises the MPS RANGES section):
//   min c'x  s.t.  w'x >= 40,  2 <= x0 + x2 + ... + x10 <= 4,  x binary (12).
struct Knapsack {
  Eigen::VectorXd c{12}, w{12}, even{12};
  Knapsack() {
    c << 7.5, 3.25, 9, 4.75, 6, 2.5, 8.25, 5.5, 3, 6.75, 4, 7;
    w << 11, 4, 13, 6, 9, 3, 12, 7, 4, 10, 5, 8;
    for (int i = 0; i < 12; ++i) even[i] = i % 2 == 0 ? 1.0 : 0.0;
  }
  double EnumeratedOptimum() const {
    double best = std::numeric_limits<double>::infinity();
    for (int mask = 0; mask < (1 << 12); ++mask) {
      double cost = 0, weight = 0, evens = 0;
      for (int i = 0; i < 12; ++i) {
        if (mask & (1 << i)) {
          cost += c[i];
          weight += w[i];
          evens += even[i];
        }
      }
      if (weight >= 40 && evens >= 2 && evens <= 4) best = std::min(best, cost);
    }
    return best;
  }
  void WriteMps(const std::string& path) const {
    milp::Model m("knapsack");
    const milp::VarBlock x = m.AddVariables(12, 0, 1, milp::VarType::kBinary, "x");
    m.AddConstraint(milp::LinearExpr::InnerProduct(w, x) >= 40, "cover");
    m.AddConstraint(milp::LinearExpr::InnerProduct(even, x), 2, 4, "evens");
    m.Minimize(milp::LinearExpr::InnerProduct(c, x));
    milp::WriteMpsFile(path, m.ToLpData());
  }
};

class HighsRunner : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("thrustsched_highs_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(HighsRunner, SolvesKnapsackToEnumeratedOptimum) {
  const Knapsack k;
  const std::string mps = (dir_ / "knapsack.mps").string();
  k.WriteMps(mps);
  const ExternalResult r = RunExternalSolver("highs", mps, (dir_ / "knapsack").string(), 60.0);
  if (r.status.rfind("skipped", 0) == 0) GTEST_SKIP() << "HiGHS " << r.status;
  const double opt = k.EnumeratedOptimum();
  ASSERT_TRUE(std::isfinite(opt));
  EXPECT_EQ(r.status, "optimal");
  EXPECT_NEAR(r.objective, opt, 1e-9);
  EXPECT_NEAR(r.bound, opt, 1e-6);
  EXPECT_NEAR(r.gap, 0.0, 1e-6);
  EXPECT_GT(r.seconds, 0.0);
  // The raw output files are the ones the bench removes.
  for (const std::string& f : ExternalOutputFiles((dir_ / "knapsack").string())) {
    if (f.find(".highs.") != std::string::npos) {
      EXPECT_TRUE(fs::exists(f)) << f;
    }
  }
}

TEST_F(HighsRunner, MissingPackageIsSkippedWithReason) {
  if (!ProgramAvailable("node")) GTEST_SKIP() << "node not installed";
  const Knapsack k;
  const std::string mps = (dir_ / "knapsack.mps").string();
  k.WriteMps(mps);
  const char* before = std::getenv("THRUSTSCHED_HIGHS_DIR");
  const std::string saved = before ? before : "";
  ::setenv("THRUSTSCHED_HIGHS_DIR", (dir_ / "empty").c_str(), 1);
  const ExternalResult r = RunExternalSolver("highs", mps, (dir_ / "knapsack").string(), 10.0);
  if (before) {
    ::setenv("THRUSTSCHED_HIGHS_DIR", saved.c_str(), 1);
  } else {
    ::unsetenv("THRUSTSCHED_HIGHS_DIR");
  }
  EXPECT_EQ(r.status.rfind("skipped: npm package highs not found", 0), 0u) << r.status;
  EXPECT_TRUE(std::isnan(r.objective));
}

TEST(HighsOutput, ParsesResultSkipAndError) {
  ExternalResult r = ParseHighsOutput(
      "some warning\n{\"solver\":\"highs\",\"status\":\"timeLimit\",\"has_solution\":true,"
      "\"objective\":1.75,\"bound\":1.70,\"gap\":0.0286,\"solve_s\":30.1,\"read_s\":0.5}\n");
  EXPECT_EQ(r.status, "timeLimit");
  EXPECT_DOUBLE_EQ(r.objective, 1.75);
  EXPECT_DOUBLE_EQ(r.bound, 1.70);
  EXPECT_DOUBLE_EQ(r.gap, 0.0286);
  EXPECT_TRUE(std::isnan(r.seconds));  // the caller times the process
  // No solution: the bound stays, the objective does not.
  r = ParseHighsOutput(
      "{\"status\":\"timeLimit\",\"has_solution\":false,\"objective\":null,"
      "\"bound\":0.08,\"gap\":null}");
  EXPECT_TRUE(std::isnan(r.objective));
  EXPECT_DOUBLE_EQ(r.bound, 0.08);
  r = ParseHighsOutput("{\"solver\":\"highs\",\"status\":\"skipped\",\"reason\":\"no package\"}");
  EXPECT_EQ(r.status, "skipped: no package");
  r = ParseHighsOutput(
      "{\"status\":\"error\",\"reason\":\"out of memory\",\"has_solution\":false}");
  EXPECT_EQ(r.status, "error: out of memory");
  EXPECT_THROW(ParseHighsOutput(""), std::runtime_error);
}

TEST(ExternalBeatsOptimum, FlagsObjectivesBelowOurOptimumOrThePublishedOne) {
  Row r;
  r.Set("status", "optimal");
  r.Set("objective", 1.72113);
  r.Set("published", 1.721);
  r.Set("ext_highs_status", "optimal");
  r.Set("ext_highs_objective", 1.72113 + 1e-9);
  EXPECT_EQ(ExternalBeatsOptimum(r, "highs"), "");
  r.Set("ext_highs_objective", 1.70474);
  EXPECT_NE(ExternalBeatsOptimum(r, "highs").find("below our proven optimum"), std::string::npos);
  // Our solve not proven optimal: the published optimum is the reference,
  // with the 0.5 % its 4 significant digits need.
  r.Set("status", "time_limit");
  r.Set("ext_highs_objective", 1.7160);
  EXPECT_EQ(ExternalBeatsOptimum(r, "highs"), "");
  r.Set("ext_highs_objective", 1.70);
  EXPECT_NE(ExternalBeatsOptimum(r, "highs").find("below the published"), std::string::npos);
  // A CBC LP value in place of a solution is not a schedule.
  r.Set("ext_cbc_status", "Stopped on time (no integer solution - continuous used)");
  r.Set("ext_cbc_objective", 1.2);
  EXPECT_EQ(ExternalBeatsOptimum(r, "cbc"), "");
  EXPECT_EQ(ExternalBeatsOptimum(r, "glpsol"), "");  // no objective
}

}  // namespace
}  // namespace thrustsched::bench
