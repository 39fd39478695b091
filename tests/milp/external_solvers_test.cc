// Every catalogue model is exported (free MPS, fixed MPS with obfuscated
// names, CPLEX LP) and solved by the external programs `cbc` and `glpsol`;
// their optimum must equal the hand-derived one. The exported objective of a
// maximisation model is the negated one (minimisation only). Skips when a
// program is not installed.
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "milp/model_io.h"
#include "tests/milp/problem_catalog.h"

namespace thrustsched::milp {
namespace {

using testing::Catalog;
using testing::CatalogProblem;

bool HaveProgram(const std::string& name) {
  return std::system(("command -v " + name + " > /dev/null 2>&1").c_str()) == 0;
}

// Runs a shell command, returns its stdout and stderr.
std::string Run(const std::string& command) {
  std::string output;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return "popen failed";
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    output.append(buffer.data(), n);
  ::pclose(pipe);
  return output;
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct ExternalResult {
  SolveStatus status = SolveStatus::kError;
  double objective = std::nan("");
  std::string raw;
};

// `cbc <file> -solve -solu <sol>`: the first line of the solution file is
// e.g. "Optimal - objective value 2.80000000" (8 significant digits).
ExternalResult RunCbc(const std::string& model_path, const std::string& dir) {
  ExternalResult r;
  const std::string sol = dir + "/cbc.sol";
  std::remove(sol.c_str());
  r.raw = Run("cbc " + model_path + " -solve -solu " + sol);
  const std::string text = ReadText(sol);
  r.raw += "\n--- solution file:\n" + text.substr(0, 300);
  std::smatch m;
  if (std::regex_search(text, m, std::regex("^Optimal - objective value (\\S+)"))) {
    r.status = SolveStatus::kOptimal;
    r.objective = std::strtod(m[1].str().c_str(), nullptr);
  } else if (std::regex_search(text, std::regex("^(Infeasible|Integer infeasible)"))) {
    r.status = SolveStatus::kInfeasible;
  } else if (std::regex_search(text, std::regex("^Unbounded"))) {
    r.status = SolveStatus::kUnbounded;
  } else if (text.empty() &&
             std::regex_search(
                 r.raw, std::regex("Problem is infeasible|Problem proven infeasible|infeasible"))) {
    r.status = SolveStatus::kInfeasible;
  } else if (text.empty() && std::regex_search(r.raw, std::regex("[Uu]nbounded"))) {
    r.status = SolveStatus::kUnbounded;
  }
  return r;
}

// `glpsol --freemps|--mps|--lp <file> -o <out>`: the output file has
// "Status: INTEGER OPTIMAL" / "OPTIMAL" and "Objective: OBJ = v (MINimum)".
ExternalResult RunGlpsol(const std::string& flag, const std::string& model_path,
                         const std::string& dir) {
  ExternalResult r;
  const std::string out = dir + "/glpsol.out";
  std::remove(out.c_str());
  r.raw = Run("glpsol " + flag + " " + model_path + " -o " + out);
  const std::string text = ReadText(out);
  r.raw += "\n--- output file:\n" + text.substr(0, 400);
  std::smatch m;
  const bool optimal = std::regex_search(text, std::regex("Status:\\s+(INTEGER )?OPTIMAL"));
  if (optimal && std::regex_search(text, m, std::regex("Objective:\\s+\\S+ = (\\S+)"))) {
    r.status = SolveStatus::kOptimal;
    r.objective = std::strtod(m[1].str().c_str(), nullptr);
  } else if (std::regex_search(r.raw, std::regex("UNBOUNDED|unbounded"))) {
    r.status = SolveStatus::kUnbounded;
  } else if (std::regex_search(r.raw, std::regex("NO PRIMAL FEASIBLE|NO INTEGER FEASIBLE|INTEGER "
                                                 "EMPTY|INFEASIBLE \\(FINAL\\)|EMPTY"))) {
    r.status = SolveStatus::kInfeasible;
  }
  return r;
}

class ExternalSolversTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "/milp_ext_" + std::to_string(::getpid()) + "_" + GetParam();
    std::system(("mkdir -p " + dir_).c_str());
    for (const CatalogProblem& p : Catalog()) {
      if (p.name == GetParam()) problem_ = p;
    }
    lp_ = problem_.build();
    sign_ = lp_.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
  }
  void TearDown() override { std::system(("rm -rf " + dir_).c_str()); }

  void Check(const ExternalResult& r, const std::string& who) {
    SCOPED_TRACE(who);
    if (problem_.status == SolveStatus::kOptimal) {
      ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.raw;
      const double expected = sign_ * problem_.objective;  // exported: minimisation
      EXPECT_NEAR(r.objective, expected, 1e-6 * std::max(1.0, std::abs(expected))) << r.raw;
    } else {
      EXPECT_EQ(r.status, problem_.status) << r.raw;
    }
  }

  std::string dir_;
  CatalogProblem problem_;
  LpData lp_;
  double sign_ = 1.0;
};

TEST_P(ExternalSolversTest, CbcReadsFreeMps) {
  if (!HaveProgram("cbc")) GTEST_SKIP() << "cbc not installed";
  const std::string path = dir_ + "/model.mps";
  WriteMpsFile(path, lp_);
  Check(RunCbc(path, dir_), "cbc free MPS");
}

TEST_P(ExternalSolversTest, GlpsolReadsFreeMps) {
  if (!HaveProgram("glpsol")) GTEST_SKIP() << "glpsol not installed";
  const std::string path = dir_ + "/model.mps";
  WriteMpsFile(path, lp_);
  Check(RunGlpsol("--freemps", path, dir_), "glpsol --freemps");
}

TEST_P(ExternalSolversTest, GlpsolReadsFixedMpsWithObfuscatedNames) {
  if (!HaveProgram("glpsol")) GTEST_SKIP() << "glpsol not installed";
  const std::string path = dir_ + "/model_fixed.mps";
  MpsOptions o;
  o.free_format = false;
  o.obfuscate_names = true;
  WriteMpsFile(path, lp_, o);
  Check(RunGlpsol("--mps", path, dir_), "glpsol --mps");
}

TEST_P(ExternalSolversTest, GlpsolReadsLp) {
  if (!HaveProgram("glpsol")) GTEST_SKIP() << "glpsol not installed";
  const std::string path = dir_ + "/model.lp";
  WriteLpFile(path, lp_);
  Check(RunGlpsol("--lp", path, dir_), "glpsol --lp");
}

TEST_P(ExternalSolversTest, CbcReadsLp) {
  if (!HaveProgram("cbc")) GTEST_SKIP() << "cbc not installed";
  const std::string path = dir_ + "/model.lp";
  WriteLpFile(path, lp_);
  Check(RunCbc(path, dir_), "cbc LP");
}

INSTANTIATE_TEST_SUITE_P(Catalog, ExternalSolversTest, ::testing::ValuesIn([] {
                           std::vector<std::string> names;
                           for (const CatalogProblem& p : Catalog()) names.push_back(p.name);
                           return names;
                         }()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace thrustsched::milp
