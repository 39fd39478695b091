// Exhaustive proof that both MILP encodings of the operational rules accept
// exactly the binary patterns the independent continuous-time checker
// (transcription/checker.h, CheckOperationalRules) accepts.
//
// For every configuration (grid, rules, history, forced-off windows, end
// policy) and every on/off pattern of 2-3 thrusters over 6-8 intervals:
//   encoding verdict  = the canonical completion of the auxiliary columns
//                       (OperationalEncoding::Complete) satisfies every row
//                       and bound of the frozen LpData;
//   reference verdict = CheckOperationalRules on the burns of the pattern.
// The completion is the unique feasible one (start/stop/gamma are determined
// by the pattern; thesis start indicators at their smallest value), and a
// sample of rejected patterns is re-checked with an LP solve (CLP) with the
// pattern fixed, which must be infeasible: so "rejected" really means no
// auxiliary values exist.
#include <cmath>
#include <memory>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "milp/cbc_solver.h"
#include "milp/model.h"
#include "transcription/checker.h"
#include "transcription/encodings.h"

namespace thrustsched::transcription {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Config {
  std::string name;
  int thrusters;
  std::vector<double> grid;
  OperationalRules rules;
  BoundaryHistory history;
  std::vector<ForcedOff> forced_off;
  std::vector<bool> enabled;
  bool infeasible = false;  // history and forced-off windows conflict: nothing is accepted
};

// gtest prints a failing case's parameter: its name and size, not raw bytes.
void PrintTo(const Config& c, std::ostream* os) {
  *os << c.name << " (" << c.thrusters << " thrusters, " << (c.grid.empty() ? 0 : c.grid.size() - 1)
      << " intervals)";
}

std::vector<double> Uniform(int n, double dt) {
  std::vector<double> g;
  for (int j = 0; j <= n; ++j) g.push_back(j * dt);
  return g;
}

OperationalRules Rules(int k, double tl, double td, double ts) {
  OperationalRules r;
  r.max_simultaneous = k;
  r.min_burn_s = tl;
  r.min_off_same_s = td;
  r.min_gap_other_s = ts;
  return r;
}

BoundaryHistory History(int m, std::vector<std::pair<int, double>> on,
                        std::vector<std::pair<int, double>> off) {
  BoundaryHistory h = BoundaryHistory::AllOff(m);
  for (auto [i, v] : on) h.on_for_s[i] = v;
  for (auto [i, v] : off) h.off_for_s[i] = v;
  return h;
}

std::vector<Config> Configs() {
  std::vector<Config> c;
  const auto u8 = Uniform(8, 300);
  const auto u6 = Uniform(6, 300);
  const auto u5 = Uniform(5, 300);
  const std::vector<double> nonuniform = {0, 300, 500, 900, 1000, 1500, 1800, 2000};
  auto add = [&](std::string name, int m, std::vector<double> grid, OperationalRules r,
                 BoundaryHistory h = {}, std::vector<ForcedOff> f = {},
                 std::vector<bool> enabled = {}) {
    c.push_back({std::move(name), m, std::move(grid), r, std::move(h), std::move(f),
                 std::move(enabled), false});
  };
  // Thesis rules (p = 1, m = 4, q = 1).
  add("thesis_2x8", 2, u8, Rules(1, 300, 1200, 300));
  add("thesis_3x6", 3, u6, Rules(1, 300, 1200, 300));
  // Table 4.4: 10-minute minimum burn (p = 2).
  add("p2_2x8", 2, u8, Rules(1, 600, 1200, 300));
  // Other-thruster gap longer than the same-thruster gap (self_off false).
  add("gap_gt_off_2x8", 2, u8, Rules(1, 600, 600, 900));
  // Gap longer than min_off + min_burn: pairwise rows in the tight encoding.
  add("gap_long_2x8", 2, u8, Rules(1, 300, 300, 900));
  add("gap_long_3x5", 3, u5, Rules(1, 300, 300, 1000));
  // Two thrusters may fire together.
  add("k2_3x5", 3, u5, Rules(2, 600, 600, 300));
  add("k2_nogap_3x5", 3, u5, Rules(2, 300, 600, 0));
  // No gap between different thrusters: direct switches allowed.
  add("nogap_2x8", 2, u8, Rules(1, 600, 900, 0));
  // Maximum burn and maximum number of burns.
  {
    OperationalRules r = Rules(1, 300, 600, 300);
    r.max_burn_s = 900;
    r.max_burns_per_thruster = 2;
    add("maxburn_2x8", 2, u8, r);
    add("maxburn_hist_2x8", 2, u8, r, History(2, {{0, 400}}, {}));
  }
  // Burns across the horizon end allowed.
  {
    OperationalRules r = Rules(1, 900, 1200, 300);
    r.allow_burn_across_end = true;
    add("across_end_2x8", 2, u8, r);
    add("across_end_hist_2x8", 2, u8, r, History(2, {{1, 300}}, {{0, 200}}));
  }
  add("no_across_end_2x8", 2, u8, Rules(1, 900, 1200, 300));
  // Boundary history.
  add("hist_on_short_2x8", 2, u8, Rules(1, 900, 1200, 300), History(2, {{0, 300}}, {}));
  add("hist_on_long_2x8", 2, u8, Rules(1, 900, 1200, 300), History(2, {{1, 1500}}, {}));
  add("hist_off_recent_3x5", 3, u5, Rules(1, 300, 1200, 600), History(3, {}, {{0, 100}, {2, 900}}));
  add("hist_on_and_off_3x6", 3, u6, Rules(1, 600, 900, 300),
      History(3, {{2, 200}}, {{0, 250}, {1, 2000}}));
  add("hist_k2_3x5", 3, u5, Rules(2, 600, 600, 300), History(3, {{0, 300}}, {{1, 100}}));
  // Forced-off windows and disabled thrusters.
  add("forced_off_2x8", 2, u8, Rules(1, 600, 1200, 300), {}, {{1, 600, 1200}, {0, 2000, 2100}});
  add("disabled_3x5", 3, Uniform(5, 300), Rules(1, 300, 1200, 300), {}, {}, {true, false, true});
  add("conflict_2x8", 2, u8, Rules(1, 900, 1200, 300), History(2, {{0, 100}}, {}), {{0, 300, 600}});
  c.back().infeasible = true;
  // Non-uniform grid.
  add("nonuniform_2x7", 2, nonuniform, Rules(1, 400, 700, 250));
  add("nonuniform_k2_3x5", 3, {0, 300, 500, 900, 1000, 1500}, Rules(2, 450, 500, 300),
      History(3, {{0, 100}}, {}));
  return c;
}

std::vector<Burn> BurnsOf(const Eigen::MatrixXi& p, const std::vector<double>& grid) {
  std::vector<Burn> burns;
  for (int i = 0; i < p.rows(); ++i) {
    int j = 0;
    while (j < p.cols()) {
      if (p(i, j) == 0) {
        ++j;
        continue;
      }
      int k = j;
      while (k < p.cols() && p(i, k) == 1) ++k;
      burns.push_back({i, grid[j], grid[k]});
      j = k;
    }
  }
  return burns;
}

// Row-major copy of an LpData for a fast feasibility test with early exit
// (the same semantics as LpData::MaxViolation <= tol, checked below on a sample).
struct FastLp {
  explicit FastLp(const milp::LpData& lp)
      : a(lp.a_matrix),
        row_lower(lp.row_lower),
        row_upper(lp.row_upper),
        col_lower(lp.col_lower),
        col_upper(lp.col_upper) {}
  bool Feasible(const Eigen::VectorXd& x, double tol) const {
    for (int j = 0; j < x.size(); ++j) {
      if (x[j] < col_lower[j] - tol || x[j] > col_upper[j] + tol) return false;
    }
    for (int r = 0; r < a.outerSize(); ++r) {
      double act = 0.0;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(a, r); it; ++it) {
        act += it.value() * x[it.col()];
      }
      if (act < row_lower[r] - tol || act > row_upper[r] + tol) return false;
    }
    return true;
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> a;
  Eigen::VectorXd row_lower, row_upper, col_lower, col_upper;
};

class EncodingsExhaustiveTest : public ::testing::TestWithParam<Config> {};

TEST_P(EncodingsExhaustiveTest, SameAcceptedPatternsAsChecker) {
  const Config& c = GetParam();
  const int m = c.thrusters;
  const int n = static_cast<int>(c.grid.size()) - 1;
  EncodingInput in;
  in.grid = c.grid;
  in.rules = c.rules;
  in.history = c.history;
  in.forced_off = c.forced_off;
  in.enabled = c.enabled;
  in.num_thrusters = m;

  std::vector<ForcedOff> checker_forced = c.forced_off;
  for (int i = 0; i < static_cast<int>(c.enabled.size()); ++i) {
    if (!c.enabled[i]) checker_forced.push_back({i, c.grid.front() - 1.0, c.grid.back() + 1.0});
  }

  struct Built {
    Encoding encoding;
    milp::Model model;
    OperationalEncoding enc;
    milp::LpData lp;
    std::unique_ptr<FastLp> fast;
  };
  std::vector<Built> built;
  for (Encoding e : {Encoding::kThesis, Encoding::kTight}) {
    Built b{e, milp::Model(std::string(ToString(e))), {}, {}, nullptr};
    b.enc = AddOperationalConstraints(&b.model, in, e);
    b.lp = b.model.ToLpData();
    b.fast = std::make_unique<FastLp>(b.lp);
    built.push_back(std::move(b));
  }

  const long long total = 1LL << (m * n);
  long long accepted = 0;
  std::mt19937 rng(12345);
  std::vector<Eigen::MatrixXi> rejected_sample;
  Eigen::MatrixXi pattern(m, n);
  for (long long bits = 0; bits < total; ++bits) {
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < n; ++j) pattern(i, j) = (bits >> (i * n + j)) & 1;
    }
    const std::vector<Burn> burns = BurnsOf(pattern, c.grid);
    const bool ref_ok = CheckOperationalRules(c.rules, c.history, checker_forced, m, c.grid.front(),
                                              c.grid.back(), burns)
                            .empty();
    accepted += ref_ok;
    for (Built& b : built) {
      Eigen::VectorXd x = Eigen::VectorXd::Zero(b.lp.num_cols());
      b.enc.Complete(pattern, &x);
      const bool enc_ok = b.fast->Feasible(x, 1e-9);
      if ((bits & 1023) == 0) {  // the fast test agrees with the library's own measure
        ASSERT_EQ(enc_ok, b.lp.MaxViolation(x) <= 1e-9);
      }
      if (enc_ok != ref_ok) {
        std::string msg;
        for (int i = 0; i < m; ++i) {
          for (int j = 0; j < n; ++j) msg += pattern(i, j) ? '1' : '0';
          msg += ' ';
        }
        ADD_FAILURE() << c.name << " encoding " << ToString(b.encoding) << " pattern " << msg
                      << " encoding says " << enc_ok << ", checker says " << ref_ok;
        return;
      }
    }
    if (!ref_ok && rejected_sample.size() < 40 &&
        std::uniform_int_distribution<int>(0, 200)(rng) == 0) {
      rejected_sample.push_back(pattern);
    }
  }
  // Sanity: the configuration is neither trivial nor empty (or, for a
  // conflicting history, empty with a stated reason).
  if (c.infeasible) {
    EXPECT_EQ(accepted, 0) << c.name;
    for (Built& b : built) EXPECT_FALSE(b.enc.infeasibility_reasons.empty()) << c.name;
  } else {
    EXPECT_GT(accepted, 0) << c.name;
    EXPECT_LT(accepted, total) << c.name;
  }
  RecordProperty("accepted_patterns", std::to_string(accepted));

  // Rejected means: no auxiliary values exist (LP with the pattern fixed).
  auto solver = milp::MakeCbcSolver();
  for (Built& b : built) {
    for (const Eigen::MatrixXi& p : rejected_sample) {
      milp::LpData lp = b.lp;
      bool outside_bounds = false;  // the pattern breaks a fixing: rejected by bounds alone
      for (int i = 0; i < m; ++i) {
        for (int j = 0; j < n; ++j) {
          const int col = b.enc.on[i][j].index();
          if (p(i, j) < lp.col_lower[col] || p(i, j) > lp.col_upper[col]) outside_bounds = true;
          lp.col_lower[col] = lp.col_upper[col] = p(i, j);
        }
      }
      if (outside_bounds) continue;
      const milp::LpRelaxationResult r = solver->SolveLpRelaxation(lp);
      EXPECT_EQ(r.status, milp::SolveStatus::kInfeasible)
          << c.name << " " << ToString(b.encoding) << ": a rejected pattern admits auxiliaries";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllConfigs, EncodingsExhaustiveTest, ::testing::ValuesIn(Configs()),
                         [](const ::testing::TestParamInfo<Config>& info) {
                           return info.param.name;
                         });

TEST(EncodingsTest, IntervalsSpanningRoundsUp) {
  const auto g = Uniform(10, 300);
  EXPECT_EQ(IntervalsSpanning(g, 0, 300), 1);
  EXPECT_EQ(IntervalsSpanning(g, 0, 301), 2);
  EXPECT_EQ(IntervalsSpanning(g, 0, 1200), 4);
  EXPECT_EQ(IntervalsSpanning(g, 0, 0), 0);
  EXPECT_EQ(IntervalsSpanning(g, 8, 900), 3);  // beyond the horizon: N - a + 1
  const std::vector<double> nu = {0, 100, 400, 450, 1000};
  EXPECT_EQ(IntervalsSpanning(nu, 0, 400), 2);
  EXPECT_EQ(IntervalsSpanning(nu, 1, 400), 3);
}

TEST(EncodingsTest, EffectiveDurationsOfThesisRules) {
  milp::Model model;
  EncodingInput in;
  in.grid = Uniform(20, 300);
  in.rules = Rules(1, 300, 1200, 300);
  in.num_thrusters = 4;
  const OperationalEncoding enc = AddOperationalConstraints(&model, in, Encoding::kThesis);
  EXPECT_EQ(enc.min_burn_intervals_max, 1);       // p
  EXPECT_EQ(enc.min_off_same_intervals_max, 4);   // m
  EXPECT_EQ(enc.min_gap_other_intervals_max, 1);  // q
  EXPECT_DOUBLE_EQ(enc.effective_min_off_same_s, 1200);
  // 4N binaries, N gamma columns.
  EXPECT_EQ(model.num_integer_variables(), 80);
}

TEST(EncodingsTest, ConflictIsReportedNotThrown) {
  milp::Model model;
  EncodingInput in;
  in.grid = Uniform(4, 300);
  in.rules = Rules(1, 900, 0, 0);
  in.num_thrusters = 1;
  in.history = History(1, {{0, 100}}, {});
  in.forced_off = {{0, 0, 300}};
  const OperationalEncoding enc = AddOperationalConstraints(&model, in, Encoding::kTight);
  ASSERT_FALSE(enc.infeasibility_reasons.empty());
  EXPECT_NE(enc.infeasibility_reasons[0].find("forced off"), std::string::npos);
}

TEST(EncodingsTest, BadInputThrows) {
  milp::Model model;
  EncodingInput in;
  in.grid = {0, 300, 300};
  in.num_thrusters = 1;
  EXPECT_THROW(AddOperationalConstraints(&model, in, Encoding::kTight), std::invalid_argument);
  in.grid = Uniform(3, 300);
  in.forced_off = {{5, 0, 10}};
  EXPECT_THROW(AddOperationalConstraints(&model, in, Encoding::kTight), std::invalid_argument);
  in.forced_off.clear();
  in.rules.min_burn_s = -1;
  EXPECT_THROW(AddOperationalConstraints(&model, in, Encoding::kThesis), std::invalid_argument);
  in.rules.min_burn_s = 0;
  in.rules.max_burn_s = 600;
  in.history = History(1, {{0, 900}}, {});
  EXPECT_THROW(AddOperationalConstraints(&model, in, Encoding::kThesis), std::invalid_argument);
  EXPECT_THROW(ParseEncoding("fancy"), std::invalid_argument);
  EXPECT_EQ(ParseEncoding("thesis"), Encoding::kThesis);
}

}  // namespace
}  // namespace thrustsched::transcription
