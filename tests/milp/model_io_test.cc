// Tests of the MPS / LP writers (model_io.h) and the CoinMpsIO reader
// (mps_reader.h): round trips through files, exact numbers, the MPS pitfalls
// other readers hit (model_io.h), golden files and every @throws.
//
// Golden files live in data/golden/ and are regenerated only with
// THRUSTSCHED_UPDATE_GOLDEN=1 in the environment.
#include "milp/model_io.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "milp/cbc_solver.h"
#include "milp/mps_reader.h"
#include "tests/milp/problem_catalog.h"

namespace thrustsched::milp {
namespace {

using testing::Catalog;
using testing::CatalogProblem;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::ThrowsMessage;

constexpr double kTol = 1e-6;

std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "/milp_io_" + std::to_string(::getpid()) + "_" + name;
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const CatalogProblem& Find(const std::string& name) {
  static const std::vector<CatalogProblem> catalog = Catalog();
  for (const CatalogProblem& p : catalog) {
    if (p.name == name) return p;
  }
  throw std::logic_error("no catalogue problem " + name);
}

// Lines of the file section `section` (between its header and the next).
std::vector<std::string> Section(const std::string& text, const std::string& section) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != ' ' && line[0] != '*') {
      inside = line.rfind(section, 0) == 0;
      continue;
    }
    if (inside) lines.push_back(line);
  }
  return lines;
}

std::string Squash(const std::string& line) {
  std::istringstream in(line);
  std::string word, out;
  while (in >> word) out += (out.empty() ? "" : " ") + word;
  return out;
}

std::vector<std::string> Squashed(const std::vector<std::string>& lines) {
  std::vector<std::string> out;
  for (const std::string& l : lines) out.push_back(Squash(l));
  return out;
}

// ---- round trips

class RoundTripTest : public ::testing::TestWithParam<std::string> {};

TEST_P(RoundTripTest, WriteReadSolveGivesTheSameOptimum) {
  const CatalogProblem& p = Find(GetParam());
  const LpData lp = p.build();
  for (bool free_format : {true, false}) {
    SCOPED_TRACE(free_format ? "free" : "fixed (obfuscated)");
    MpsOptions options;
    options.free_format = free_format;
    options.obfuscate_names = !free_format;
    const std::string path = TempPath(p.name + (free_format ? ".mps" : "_fixed.mps"));
    WriteMpsFile(path, lp, options);
    const LpData back = ReadMpsFile(path);
    std::remove(path.c_str());
    EXPECT_EQ(back.sense, ObjectiveSense::kMinimize);
    const double sign = lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
    const SolveResult r = MakeCbcSolver()->Solve(back);
    ASSERT_EQ(r.status, p.status) << r.detail;
    if (p.status == SolveStatus::kOptimal) {
      EXPECT_NEAR(r.objective, sign * p.objective, kTol);
    }
    // Same columns (plus OBJ_CONST when there is an offset).
    const int extra = lp.objective_offset != 0.0 ? 1 : 0;
    EXPECT_EQ(back.num_cols(), lp.num_cols() + extra);
    EXPECT_EQ(back.num_integer_cols(), lp.num_integer_cols());
    if (free_format) {
      std::vector<std::string> names = ExportedColumnNames(lp, false);
      names.resize(static_cast<size_t>(back.num_cols()), "OBJ_CONST");
      EXPECT_EQ(back.col_names, names);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Catalog, RoundTripTest, ::testing::ValuesIn([] {
                           std::vector<std::string> names;
                           for (const CatalogProblem& p : Catalog()) names.push_back(p.name);
                           return names;
                         }()),
                         [](const auto& info) { return info.param; });

// Builds a model whose bounds, costs, coefficients and (ranged) rows use the
// given numbers.
LpData AwkwardModel(const std::vector<double>& awkward) {
  Model m("exact");
  std::vector<Variable> v;
  for (size_t k = 0; k < awkward.size(); ++k) {
    v.push_back(
        m.AddContinuous(-std::abs(awkward[k]), std::abs(awkward[k]) * 2, "v" + std::to_string(k)));
  }
  Variable k = m.AddInteger(-7, 9, "k");
  LinearExpr objective;
  for (size_t i = 0; i < awkward.size(); ++i) {
    LinearExpr row;
    for (size_t j = 0; j < awkward.size(); ++j)
      row.AddTerm(v[j], awkward[(i + j) % awkward.size()]);
    row.AddTerm(k, awkward[i]);
    const double lo = awkward[i];
    const double up = awkward[i] + std::abs(awkward[(i + 1) % awkward.size()]) * 3;  // ranged
    m.AddConstraint(row, lo, up, "r" + std::to_string(i));
    objective.AddTerm(v[i], awkward[(i + 3) % awkward.size()]);
  }
  m.AddConstraint(LinearExpr(v[0]) == 1.0 / 3.0, "eq");
  m.Minimize(objective + 0.1);
  return m.ToLpData();
}

void ExpectSameNumbers(const LpData& lp, const LpData& back) {
  ASSERT_EQ(back.num_cols(), lp.num_cols() + 1);  // OBJ_CONST
  ASSERT_EQ(back.num_rows(), lp.num_rows());
  for (int j = 0; j < lp.num_cols(); ++j) {
    EXPECT_EQ(back.col_lower[j], lp.col_lower[j]) << j;
    EXPECT_EQ(back.col_upper[j], lp.col_upper[j]) << j;
    EXPECT_EQ(back.col_cost[j], lp.col_cost[j]) << j;
  }
  EXPECT_EQ(back.col_cost[lp.num_cols()], 0.1);  // the offset
  for (int i = 0; i < lp.num_rows(); ++i) {
    EXPECT_EQ(back.row_lower[i], lp.row_lower[i]) << i;
    EXPECT_EQ(back.row_upper[i], lp.row_upper[i]) << i;
  }
  const Eigen::MatrixXd a = lp.a_matrix;
  const Eigen::MatrixXd b = Eigen::MatrixXd(back.a_matrix).leftCols(lp.num_cols());
  EXPECT_EQ(a, b);
}

// A minimal free-MPS reader with correctly rounded std::strtod, for the
// subset the writer emits: the independent check of "%.17g is exact".
LpData ParseWithStrtod(const std::string& text, const LpData& shape) {
  LpData lp;
  const int n = shape.num_cols() + 1, m = shape.num_rows();
  std::vector<std::string> cols = ExportedColumnNames(shape, false);
  cols.push_back("OBJ_CONST");
  const std::vector<std::string> rows = ExportedRowNames(shape, false);
  auto index = [](const std::vector<std::string>& names, const std::string& name) {
    for (size_t k = 0; k < names.size(); ++k) {
      if (names[k] == name) return static_cast<int>(k);
    }
    return -1;
  };
  lp.col_cost = Eigen::VectorXd::Zero(n);
  lp.col_lower = Eigen::VectorXd::Zero(n);
  lp.col_upper = Eigen::VectorXd::Constant(n, kInfinity);
  lp.row_lower = Eigen::VectorXd::Constant(m, -kInfinity);
  lp.row_upper = Eigen::VectorXd::Constant(m, kInfinity);
  lp.col_type.assign(static_cast<size_t>(n), VarType::kContinuous);
  std::vector<char> type(static_cast<size_t>(m), 'N');
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m), range = Eigen::VectorXd::Zero(m);
  std::vector<Eigen::Triplet<double>> entries;
  std::istringstream in(text);
  std::string line, section;
  auto num = [](const std::string& s) { return std::strtod(s.c_str(), nullptr); };
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '*') continue;
    if (line[0] != ' ') {
      section = line.substr(0, line.find(' '));
      continue;
    }
    std::istringstream f(line);
    std::vector<std::string> t;
    for (std::string w; f >> w;) t.push_back(w);
    if (section == "ROWS" && t[1] != "OBJ") {
      type[static_cast<size_t>(index(rows, t[1]))] = t[0][0];
    } else if (section == "COLUMNS" && t[1] != "'MARKER'") {
      const int j = index(cols, t[0]);
      if (t[1] == "OBJ") {
        lp.col_cost[j] = num(t[2]);
      } else {
        entries.emplace_back(index(rows, t[1]), j, num(t[2]));
      }
    } else if (section == "RHS") {
      rhs[index(rows, t[1])] = num(t[2]);
    } else if (section == "RANGES") {
      range[index(rows, t[1])] = num(t[2]);
    } else if (section == "BOUNDS") {
      const int j = index(cols, t[2]);
      if (t[0] == "LO") lp.col_lower[j] = num(t[3]);
      if (t[0] == "UP") lp.col_upper[j] = num(t[3]);
      if (t[0] == "FX") lp.col_lower[j] = lp.col_upper[j] = num(t[3]);
      if (t[0] == "MI") lp.col_lower[j] = -kInfinity;
    }
  }
  for (int i = 0; i < m; ++i) {
    const double r = std::abs(range[i]);
    switch (type[static_cast<size_t>(i)]) {
      case 'E':
        lp.row_lower[i] = lp.row_upper[i] = rhs[i];
        break;
      case 'G':
        lp.row_lower[i] = rhs[i];
        if (r != 0.0) lp.row_upper[i] = rhs[i] + r;
        break;
      case 'L':
        lp.row_upper[i] = rhs[i];
        if (r != 0.0) lp.row_lower[i] = rhs[i] - r;
        break;
      default:
        break;
    }
  }
  lp.a_matrix.resize(m, n);
  lp.a_matrix.setFromTriplets(entries.begin(), entries.end());
  return lp;
}

TEST(MpsWriterTest, FreeMpsRoundTripsDoublesExactly) {
  const double pi = 3.14159265358979323846;
  const std::vector<double> awkward = {0.1,       1.0 / 3.0, 1e-300, 123456789.123456789,
                                       pi * 1e-7, -2.0 / 3.0};
  const LpData lp = AwkwardModel(awkward);
  const std::string text = ToMpsString(lp);
  EXPECT_THAT(text, HasSubstr("0.10000000000000001"));  // %.17g
  ExpectSameNumbers(lp, ParseWithStrtod(text, lp));
}

TEST(MpsWriterTest, CoinMpsIoRoundTripIsExactForOrdinaryNumbers) {
  // CoinMpsIO parses numbers with its own (not correctly rounded) routine:
  // 1e-300 reads as 0 and 1e-20 as 9.9999999999999995e-21, so the exact
  // check through it leaves such numbers out (see the strtod test above).
  const double pi = 3.14159265358979323846;
  const LpData lp =
      AwkwardModel({0.1, 1.0 / 3.0, 123456789.123456789, pi * 1e-7, -2.0 / 3.0, 2.5e-7});
  const std::string path = TempPath("exact.mps");
  WriteMpsFile(path, lp);
  const LpData back = ReadMpsFile(path);
  std::remove(path.c_str());
  ExpectSameNumbers(lp, back);
}

// ---- MPS pitfalls other readers hit (model_io.h), one test each

TEST(MpsPitfallsTest, IntegerColumnGetsQuotedMarkersAndExplicitBounds) {
  const LpData lp = Find("integer_fractional_bound").build();
  const std::string text = ToMpsString(lp);
  EXPECT_THAT(text, HasSubstr("'MARKER'  'INTORG'"));
  EXPECT_THAT(text, HasSubstr("'MARKER'  'INTEND'"));
  const std::vector<std::string> bounds = Squashed(Section(text, "BOUNDS"));
  EXPECT_THAT(bounds, ::testing::Contains("LO BND x 0"));
  EXPECT_THAT(bounds, ::testing::Contains("UP BND x 3"));  // 3.5 rounded inward, not binary
  const std::string path = TempPath("intbound.mps");
  WriteMpsFile(path, lp);
  const LpData back = ReadMpsFile(path);
  std::remove(path.c_str());
  EXPECT_EQ(back.col_type[0], VarType::kInteger);
  EXPECT_EQ(back.col_upper[0], 3.0);
  // Binaries also get both bounds.
  const std::string knap = ToMpsString(Find("integer_gap_knapsack").build());
  EXPECT_THAT(Squashed(Section(knap, "BOUNDS")), ::testing::Contains("UP BND v(2) 1"));
  EXPECT_THAT(Squashed(Section(knap, "BOUNDS")), ::testing::Contains("LO BND v(2) 0"));
}

TEST(MpsPitfallsTest, MaximisationIsWrittenNegatedWithoutObjsense) {
  const LpData lp = Find("max_knapsack_offset").build();
  const std::string text = ToMpsString(lp);
  EXPECT_THAT(text, Not(HasSubstr("OBJSENSE")));
  EXPECT_THAT(text, Not(HasSubstr("MAX\n")));
  EXPECT_THAT(text, HasSubstr("* The model MAXIMISES"));
  const std::vector<std::string> columns = Squashed(Section(text, "COLUMNS"));
  EXPECT_THAT(columns, ::testing::Contains("a OBJ -5"));
  EXPECT_THAT(columns, ::testing::Contains("OBJ_CONST OBJ 2.5"));  // offset -2.5 negated
  EXPECT_THAT(Squashed(Section(text, "BOUNDS")), ::testing::Contains("FX BND OBJ_CONST 1"));
}

TEST(MpsPitfallsTest, NegativeUpperBoundHasExplicitLowerBound) {
  Model m("neg");
  Variable z = m.AddContinuous(-5, -3, "z");
  Variable w = m.AddContinuous(-kInfinity, -2, "w");
  Variable k = m.AddInteger(-4, -1, "k");
  m.AddConstraint(z + w + k <= 0, "r");
  m.Minimize(z + w + k);
  const std::vector<std::string> bounds = Squashed(Section(ToMpsString(m.ToLpData()), "BOUNDS"));
  const std::vector<std::string> expected = {"LO BND z -5", "UP BND z -3", "MI BND w",
                                             "UP BND w -2", "LO BND k -4", "UP BND k -1"};
  EXPECT_EQ(bounds, expected);
}

TEST(MpsPitfallsTest, NamesWithSpacesAreSanitisedAndKeptUnique) {
  Model m("name test");
  m.AddContinuous(0, 1, "my var");
  m.AddContinuous(0, 1, "a b");
  m.AddContinuous(0, 1, "a_b");
  m.AddContinuous(0, 1, "3x");
  m.AddContinuous(0, 1, "e1");
  m.AddContinuous(0, 1, "free");
  m.AddContinuous(0, 1, "x[2]");
  m.AddContinuous(0, 1, "OBJ_CONST");
  m.AddContinuous(0, 1, "tab\there");
  m.AddConstraint(LinearExpr(m.variable(0)) <= 1, "row 1");
  m.AddConstraint(LinearExpr(m.variable(1)) <= 1, "OBJ");
  const LpData lp = m.ToLpData();
  const std::vector<std::string> cols = ExportedColumnNames(lp, false);
  const std::vector<std::string> expected = {"my_var", "a_b",  "a_b_1",       "_3x",     "_e1",
                                             "_free",  "x(2)", "OBJ_CONST_1", "tab_here"};
  EXPECT_EQ(cols, expected);
  EXPECT_EQ(ExportedRowNames(lp, false), (std::vector<std::string>{"row_1", "OBJ_1"}));
  EXPECT_EQ(ExportedColumnNames(lp, true)[8], "C000009");
  EXPECT_EQ(ExportedRowNames(lp, true)[1], "R000002");
  const std::string text = ToMpsString(lp);
  EXPECT_THAT(text, HasSubstr("NAME          name_test  FREE\n"));
  for (const std::string& c : cols) EXPECT_THAT(text, HasSubstr("    " + c + "  "));
  // Read back: CoinMpsIO sees exactly these names.
  const std::string path = TempPath("names.mps");
  WriteMpsFile(path, lp);
  const LpData back = ReadMpsFile(path);
  std::remove(path.c_str());
  EXPECT_EQ(back.col_names, cols);
  EXPECT_EQ(back.row_names, ExportedRowNames(lp, false));
  // Obfuscation.
  MpsOptions o;
  o.obfuscate_names = true;
  EXPECT_THAT(ToMpsString(lp, o), HasSubstr("C000001"));
  EXPECT_THAT(ToMpsString(lp, o), Not(HasSubstr("my_var")));
}

TEST(MpsPitfallsTest, RangesOnlyForRangedRows) {
  const std::string text = ToMpsString(Find("equality_and_ranged").build());
  EXPECT_EQ(Squashed(Section(text, "RANGES")), (std::vector<std::string>{"RNG rng 1"}));
  EXPECT_THAT(Squashed(Section(text, "ROWS")), ::testing::ElementsAre("N OBJ", "E eq", "G rng"));
  EXPECT_THAT(ToMpsString(Find("lp_min_duals").build()), Not(HasSubstr("RANGES")));
}

TEST(MpsPitfallsTest, PrecisionIsSeventeenDigits) {
  Model m;
  Variable x = m.AddContinuous(0, 1.0 / 3.0, "x");
  m.AddConstraint(0.1 * x >= 1e-300, "r");
  m.Minimize(3.14159265358979323846e-7 * x);
  const std::string text = ToMpsString(m.ToLpData());
  auto g17 = [](double v) {
    char buf[40];
    std::snprintf(buf, sizeof(buf), "%.17g", v);
    return std::string(buf);
  };
  EXPECT_THAT(text, HasSubstr("UP BND  x  0.33333333333333331\n"));
  EXPECT_THAT(text, HasSubstr("RHS  r  " + g17(1e-300) + "\n"));
  EXPECT_THAT(text, HasSubstr("x  OBJ  3.1415926535897932e-07\n"));
  EXPECT_EQ(g17(3.14159265358979323846e-7), "3.1415926535897932e-07");
  // Fixed MPS keeps 12-character fields (shortest exact form when it fits).
  MpsOptions fixed;
  fixed.free_format = false;
  const std::string f = ToMpsString(m.ToLpData(), fixed);
  EXPECT_THAT(f, HasSubstr("    x         r         0.1\n"));
}

TEST(MpsWriterTest, FixedMpsNeedsShortNames) {
  Model m;
  m.AddContinuous(0, 1, "a_long_name");
  MpsOptions fixed;
  fixed.free_format = false;
  EXPECT_THAT([&] { ToMpsString(m.ToLpData(), fixed); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("'a_long_name' is longer")));
  fixed.obfuscate_names = true;
  EXPECT_THAT(ToMpsString(m.ToLpData(), fixed), HasSubstr("C000001"));
}

TEST(MpsWriterTest, StreamAndStringAgree) {
  const LpData lp = Find("free_variable_offset").build();
  std::ostringstream os;
  WriteMps(os, lp);
  EXPECT_EQ(os.str(), ToMpsString(lp));
  std::ostringstream ls;
  WriteLp(ls, lp);
  EXPECT_EQ(ls.str(), ToLpString(lp));
}

// Counts what reaches the stream, and the largest single write.
class CountingBuf : public std::streambuf {
 public:
  std::streamsize total = 0, largest = 0;

 protected:
  std::streamsize xsputn(const char*, std::streamsize n) override {
    total += n;
    largest = std::max(largest, n);
    return n;
  }
  int overflow(int c) override {
    ++total;
    return c;
  }
};

TEST(MpsWriterTest, StreamsLargeModelsInChunks) {
  // Building the whole file as one string fails for very large models (as
  // OR-Tools' MPS export did); the writer must hand the stream bounded chunks.
  Model m("large");
  VarBlock x = m.AddVariables(20000, 0, 10, VarType::kInteger, "x");
  std::vector<RowTriplet> t;
  for (int i = 0; i < 20000; ++i) {
    for (int k = 0; k < 5; ++k) t.push_back({i, (i + 7 * k) % 20000, 1.0 / (1 + k)});
  }
  m.AddRows(t, Eigen::VectorXd::Zero(20000), Eigen::VectorXd::Constant(20000, 5.0), "row");
  m.Minimize(LinearExpr::Sum(x));
  CountingBuf buf;
  std::ostream os(&buf);
  WriteMps(os, m.ToLpData());
  EXPECT_GT(buf.total, 4 << 20);
  EXPECT_LT(buf.largest, 1 << 17);
  CountingBuf lp_buf;
  std::ostream lp_os(&lp_buf);
  WriteLp(lp_os, m.ToLpData());
  EXPECT_GT(lp_buf.total, 1 << 20);
  EXPECT_LT(lp_buf.largest, 1 << 17);
}

TEST(LpWriterTest, SectionsRangesAndFreeRows) {
  const std::string text = ToLpString(Find("fixed_and_free_row").build());
  EXPECT_THAT(text, HasSubstr("Minimize\n OBJ: + 1 x + 1 y\n"));
  EXPECT_THAT(text, HasSubstr(" _free: + 1 x - 1 y - 1 ~_free = 0\n"));  // "free" is a keyword
  EXPECT_THAT(text, HasSubstr(" ~_free free\n"));
  EXPECT_THAT(text, HasSubstr(" 0 <= y <= 10\n"));  // never "-0"
  EXPECT_THAT(text, HasSubstr(" x = 2\n"));
  EXPECT_THAT(text, HasSubstr("Generals\n y\n"));
  const std::string ranged = ToLpString(Find("equality_and_ranged").build());
  EXPECT_THAT(ranged, HasSubstr(" rng: + 1 y - 1 z - 1 ~rng = 1\n"));
  EXPECT_THAT(ranged, HasSubstr(" 0 <= ~rng <= 1\n"));
  const std::string knap = ToLpString(Find("max_knapsack_offset").build());
  EXPECT_THAT(knap, HasSubstr("Binaries\n a b c\n"));
  EXPECT_THAT(knap, HasSubstr("+ 2.5 OBJ_CONST"));
  EXPECT_THAT(knap, HasSubstr(" OBJ_CONST = 1\n"));
  EXPECT_THAT(knap, Not(HasSubstr("Maximize")));
}

// ---- golden files

class GoldenTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GoldenTest, MatchesByteForByte) {
  const LpData lp = Find(GetParam()).build();
  const bool update = std::getenv("THRUSTSCHED_UPDATE_GOLDEN") != nullptr &&
                      std::string(std::getenv("THRUSTSCHED_UPDATE_GOLDEN")) == "1";
  for (const std::string& ext : {std::string(".mps"), std::string(".lp")}) {
    const std::string golden = std::string(THRUSTSCHED_DATA_DIR) + "/golden/" + GetParam() + ext;
    const std::string now = ext == ".mps" ? ToMpsString(lp) : ToLpString(lp);
    if (update) {
      std::ofstream(golden, std::ios::binary) << now;
      continue;
    }
    std::ifstream probe(golden);
    ASSERT_TRUE(probe.good()) << golden << " missing; run with THRUSTSCHED_UPDATE_GOLDEN=1";
    EXPECT_EQ(now, ReadText(golden)) << golden;
  }
}

INSTANTIATE_TEST_SUITE_P(Catalog, GoldenTest,
                         ::testing::Values("equality_and_ranged", "max_knapsack_offset",
                                           "negative_upper_bound"),
                         [](const auto& info) { return info.param; });

// ---- @throws

TEST(ModelIoErrorsTest, IoFailuresNameThePath) {
  const LpData lp = Find("lp_min_duals").build();
  EXPECT_THAT([&] { WriteMpsFile("/nonexistent_dir_xyz/a.mps", lp); },
              ThrowsMessage<std::runtime_error>(HasSubstr("/nonexistent_dir_xyz/a.mps")));
  EXPECT_THAT([&] { WriteLpFile("/nonexistent_dir_xyz/a.lp", lp); },
              ThrowsMessage<std::runtime_error>(HasSubstr("/nonexistent_dir_xyz/a.lp")));
  EXPECT_THAT(
      [&] { ReadMpsFile("/nonexistent_dir_xyz/a.mps"); },
      ThrowsMessage<std::runtime_error>(HasSubstr("cannot open '/nonexistent_dir_xyz/a.mps'")));
  const std::string path = TempPath("broken.mps");
  std::ofstream(path) << "NAME broken\nROWS\n N OBJ\n L r1\nCOLUMNS\n x r2 1\nRHS\nENDATA\n";
  EXPECT_THAT([&] { ReadMpsFile(path); },
              ThrowsMessage<std::runtime_error>(HasSubstr("read error")));
  std::remove(path.c_str());
}

// The layouts CoinMpsIO crashed on (tests/fuzz/corpus/mps/crash_*) are
// rejected before it reads them, naming the file, the line and the keyword.
TEST(ModelIoErrorsTest, BrokenSectionStructureIsRejectedByLineAndKeyword) {
  const std::string path = TempPath("structure.mps");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"NAME a\nROWS\n N OBJ\nROWS\n N OBJ\nCOLUMNS\nENDATA\n",
       "line 4: ROWS: section appears a second time"},
      {"NAME a\nRHS\n RHS r 1\nROWS\n N OBJ\nCOLUMNS\nENDATA\n",
       "line 2: RHS: section before ROWS and COLUMNS"},
      {"NAME a\nROWS\n N OBJ\nCOLUMNS\n x OBJ 1\nEN 1.0\nENDATA\n",
       "line 6: EN: not a section header"},
      {"NAME a\nROWS\n N OBJ\nCOLUMNS\n x OBJ \x99\nENDATA\n",
       "line 5: \" x OBJ ?\": byte 153 is not printable ASCII"},
      {"NAME a\nROWS\n N OBJ\nCOLUMNS\n x OBJ 1\n", "line 5: ENDATA: missing"},
      {"* no NAME\nROWS\n N OBJ\nCOLUMNS\n x OBJ 1\nENDATA\n",
       "line 2: ROWS: the first section must be NAME"},
      {"NAME " + std::string(170, 'n') + "\nROWS\n N OBJ\nCOLUMNS\nENDATA\n",
       "line 1: \"nnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnn...\": field longer than 159 characters"},
      // Fixed format: a name longer than 8 characters that ends the line, in
      // column 15 (a COLUMNS line cut short, a BOUNDS line) or 40.
      {"NAME a\nROWS\n N OBJ\nCOLUMNS\n    X3        COSINTORG'\nENDATA\n",
       "line 5: \"COSINTORG'\": a name of more than 8 characters in column 15 ends the line"},
      {"NAME a\nROWS\n N OBJ\nCOLUMNS\n    X1        OBJ       1.0            \n"
       "BOUNDS\n FR BND       X123456789  \nENDATA\n",
       "line 7: \"X123456789\": a name of more than 8 characters in column 15"},
      {"NAME a\nROWS\n N OBJ\nCOLUMNS\n    X1        OBJ       1.0            R23456789\n"
       "ENDATA\n",
       "line 5: \"R23456789\": a name of more than 8 characters in column 40"},
      // CoinMpsIO aborts on a fixed-format BOUNDS line with tabs of 81+ characters.
      {"NAME a\nROWS\n N OBJ\nCOLUMNS\n    X1        OBJ       1.0\nBOUNDS\n UP BND\tX1\t" +
           std::string(80, ' ') + "3\nENDATA\n",
       "line 7: \" UP BND?X1?"},
  };
  for (const auto& [text, message] : cases) {
    std::ofstream(path, std::ios::binary) << text;
    EXPECT_THAT([&] { ReadMpsFile(path); },
                ThrowsMessage<std::runtime_error>(HasSubstr("'" + path + "' " + message)))
        << text;
  }
  std::remove(path.c_str());
}

// The fixed-format check leaves free-format files alone: long names that end
// a line are ordinary there.
TEST(ModelIoErrorsTest, LongNamesEndingALineAreReadInFreeFormat) {
  const std::string path = TempPath("free_long_names.mps");
  std::ofstream(path, std::ios::binary)
      << "NAME a  FREE\nROWS\n N OBJ\n L R123456789\nCOLUMNS\n"
      << "    X123456789    OBJ       1.0   R123456789 2.0\nRHS\n    RHS  R123456789 4\n"
      << "BOUNDS\n UP BND       X123456789 3\nENDATA\n";
  const LpData lp = ReadMpsFile(path);
  ASSERT_EQ(lp.num_cols(), 1);
  EXPECT_DOUBLE_EQ(lp.col_upper[0], 3.0);
  EXPECT_DOUBLE_EQ(lp.row_upper[0], 4.0);
  std::remove(path.c_str());
}

TEST(ModelIoErrorsTest, InvalidProblemIsRejected) {
  LpData lp = Find("lp_min_duals").build();
  lp.col_lower[0] = 3;
  lp.col_upper[0] = 1;
  EXPECT_THAT([&] { ToMpsString(lp); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("WriteMps")));
  EXPECT_THAT([&] { ToLpString(lp); }, ThrowsMessage<std::invalid_argument>(HasSubstr("WriteLp")));
  EXPECT_THAT([&] { WriteMpsFile(TempPath("bad.mps"), lp); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("WriteMpsFile")));
  EXPECT_THAT([&] { WriteLpFile(TempPath("bad.lp"), lp); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("WriteLpFile")));
}

// Integer bounds are written rounded inward; bounds that hold no integer
// would give LO 1 / UP 0, which cbc and glpsol reject as a malformed file.
TEST(ModelIoErrorsTest, IntegerColumnWithoutIntegerValueIsRejectedByName) {
  Model m("no_integer");
  const Variable x = m.AddInteger(0.2, 0.8, "x_frac");
  const Variable y = m.AddInteger(-0.5, 0.5, "y_zero");  // holds 0: fine
  m.AddConstraint(LinearExpr(x) + y, 0, 2, "r");
  m.Minimize(LinearExpr(x));
  const LpData lp = m.ToLpData();
  EXPECT_THAT([&] { ToMpsString(lp); },
              ThrowsMessage<std::invalid_argument>(HasSubstr(
                  "integer column 'x_frac' has no integer value within its bounds [0.2")));
  EXPECT_THAT([&] { ToLpString(lp); }, ThrowsMessage<std::invalid_argument>(HasSubstr("x_frac")));
  LpData ok = lp;
  ok.col_upper[0] = 1.0;
  EXPECT_THAT(ToMpsString(ok), HasSubstr("x_frac"));  // [1, 1]: written
}

}  // namespace
}  // namespace thrustsched::milp
