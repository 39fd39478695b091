// ExportLp against enumeration: on a short Table 4.1 grid the range of each
// state over every 0/1 pattern of the thrusters (whatever the operational
// rules say: the bounds come from the dynamics and the binaries' box only),
// propagated by the builder's own StartFromPattern, widened as
// milp::kChainBoundWidening says, is the exported bound; the rest of the
// model is untouched.
#include "transcription/export_lp.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "tests/transcription/thesis_cases.h"
#include "transcription/schedule_milp.h"

namespace thrustsched::transcription {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ExportLpTest, StateBoundsAreTheWidenedRangeOverEveryOnOffPattern) {
  ScheduleProblem p = ThesisTable41(1.0);
  p.grid = dynamics::UniformGrid(0.0, 900.0, 3);  // 3 slots x 6 thrusters: 2^18 patterns
  BuildOptions o;
  o.discretisation.scheme = dynamics::Scheme::kExactZoh;
  const ScheduleMilp milp(p, o);
  const milp::LpData exported = ExportLp(milp);
  const milp::LpData& lp = milp.lp();
  const int n = 6, nodes = 4;
  std::vector<double> lo(n * nodes, kInf), hi(n * nodes, -kInf);
  Eigen::MatrixXi pattern(6, 3);
  for (int mask = 0; mask < (1 << 18); ++mask) {
    for (int b = 0; b < 18; ++b) pattern(b / 3, b % 3) = (mask >> b) & 1;
    const Eigen::VectorXd x = milp.StartFromPattern(pattern);
    for (int j = 0; j < nodes; ++j) {
      for (int c = 0; c < n; ++c) {
        const double v = x[milp.state(j, c).index()];
        lo[j * n + c] = std::min(lo[j * n + c], v);
        hi[j * n + c] = std::max(hi[j * n + c], v);
      }
    }
  }
  for (int j = 1; j < nodes; ++j) {
    for (int c = 0; c < n; ++c) {
      const int col = milp.state(j, c).index();
      EXPECT_EQ(lp.col_lower[col], -kInf);  // free in the model we solve
      // The reachable range widened by half its width and 1e-3 (1 + |x|).
      const double l = exported.col_lower[col], u = exported.col_upper[col];
      const double a = lo[j * n + c], b = hi[j * n + c];
      const double margin =
          milp::kChainBoundWidening * (b - a) + 1e-3 * (1.0 + std::max(std::abs(a), std::abs(b)));
      const double tol = 1e-6 * (1.0 + std::abs(a) + std::abs(b));
      EXPECT_NEAR(l, a - margin, tol) << lp.col_names[col];
      EXPECT_NEAR(u, b + margin, tol) << lp.col_names[col];
    }
  }
}

TEST(ExportLpTest, OnlyTheStateBoundsChange) {
  const ScheduleMilp milp(ThesisTable41(1.0), BuildOptions{});
  const milp::LpData exported = ExportLp(milp);
  const milp::LpData& lp = milp.lp();
  EXPECT_EQ(exported.col_names, lp.col_names);
  EXPECT_EQ(exported.row_names, lp.row_names);
  EXPECT_EQ(exported.col_cost, lp.col_cost);
  EXPECT_EQ(exported.row_lower, lp.row_lower);
  EXPECT_EQ(exported.row_upper, lp.row_upper);
  EXPECT_EQ((exported.a_matrix - lp.a_matrix).norm(), 0.0);
  std::vector<bool> is_state(lp.num_cols(), false);
  for (const auto& block : milp.state_chain().blocks) {
    for (int c : block) is_state[c] = true;
  }
  int bounded = 0;
  for (int c = 0; c < lp.num_cols(); ++c) {
    if (!is_state[c]) {
      EXPECT_EQ(exported.col_lower[c], lp.col_lower[c]) << lp.col_names[c];
      EXPECT_EQ(exported.col_upper[c], lp.col_upper[c]) << lp.col_names[c];
    } else if (std::isfinite(exported.col_lower[c]) && std::isfinite(exported.col_upper[c])) {
      ++bounded;
    }
  }
  EXPECT_EQ(bounded, 6 * 289);  // every state column (node 0 fixed as before)
}

TEST(ExportLpTest, ImpulsiveFinalStateAndCondensedFormulation) {
  ScheduleProblem p = ThesisTable41(0.25);
  p.input_mode = InputMode::kImpulsive;
  p.max_impulse_m_s = 0.05;
  const ScheduleMilp impulsive(p, BuildOptions{});
  const milp::LpData e = ExportLp(impulsive);
  ASSERT_EQ(impulsive.state_chain().blocks.size(), 72u + 2u);  // nodes 0..72, then x after dv_72
  for (const auto& block : impulsive.state_chain().blocks) {
    for (int c : block) {
      EXPECT_TRUE(std::isfinite(e.col_lower[c]) && std::isfinite(e.col_upper[c])) << e.col_names[c];
    }
  }
  // Unbounded impulses: what they reach stays free (both directions: the
  // six thrusters push both ways on every axis).
  p.max_impulse_m_s = kInf;
  const ScheduleMilp unbounded(p, BuildOptions{});
  const milp::LpData ue = ExportLp(unbounded);
  for (int c : unbounded.state_chain().blocks[1]) {
    EXPECT_EQ(ue.col_lower[c], -kInf) << ue.col_names[c];
    EXPECT_EQ(ue.col_upper[c], kInf) << ue.col_names[c];
  }
  BuildOptions condensed;
  condensed.formulation = Formulation::kCondensed;
  const ScheduleMilp c(ThesisTable41(0.25), condensed);
  EXPECT_TRUE(c.state_chain().blocks.empty());
  const milp::LpData ce = ExportLp(c);
  EXPECT_EQ(ce.col_lower, c.lp().col_lower);
  EXPECT_EQ(ce.col_upper, c.lp().col_upper);
}

}  // namespace
}  // namespace thrustsched::transcription
