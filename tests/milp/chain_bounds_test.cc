// ChainImpliedBounds against enumeration: on a chain x_{j+1} = P_j x_j +
// G_j u_j + d_j with bounded inputs, the range of each state over the box of
// the inputs is attained at the box's vertices, so the bounds must equal the
// extremes over every vertex (within the padding); and the structure errors.
#include "milp/chain_bounds.h"

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "milp/model.h"

namespace thrustsched::milp {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// A chain of `steps` steps, n = 2 states, two inputs per step with the given
// bounds; x_0 fixed at (0.3, -0.2). Rows are scaled by an arbitrary factor
// (as a scaled export's are) and the inputs listed before the states.
struct TestChain {
  LpData lp;
  EqualityChain chain;
  std::vector<Eigen::Matrix2d> p;
  std::vector<Eigen::Matrix2d> g;
  std::vector<Eigen::Vector2d> d;
  std::vector<int> inputs;  // [2 j + i]
};

TestChain MakeChain(int steps, double input_lo, double input_hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  TestChain t;
  Model m("chain");
  std::vector<Variable> us;
  for (int j = 0; j < steps; ++j) {
    for (int i = 0; i < 2; ++i) {
      const Variable u = input_lo == 0.0 && input_hi == 1.0
                             ? m.AddBinary("u_" + std::to_string(i) + "_" + std::to_string(j))
                             : m.AddContinuous(input_lo, input_hi,
                                               "u_" + std::to_string(i) + "_" + std::to_string(j));
      t.inputs.push_back(u.index());
      us.push_back(u);
    }
  }
  std::vector<std::vector<Variable>> x(steps + 1);
  for (int j = 0; j <= steps; ++j) {
    for (int k = 0; k < 2; ++k) {
      x[j].push_back(m.AddContinuous(-kInfinity, kInfinity,
                                     "x_" + std::to_string(k) + "_" + std::to_string(j)));
    }
    t.chain.blocks.push_back({x[j][0].index(), x[j][1].index()});
  }
  m.SetBounds(x[0][0], 0.3, 0.3);
  m.SetBounds(x[0][1], -0.2, -0.2);
  for (int j = 0; j < steps; ++j) {
    Eigen::Matrix2d p, g;
    // Near a rotation with growth, as a transition matrix over a step.
    p << 1.0 + 0.1 * uni(rng), 0.3 + 0.1 * uni(rng), -0.3 + 0.1 * uni(rng), 1.0 + 0.1 * uni(rng);
    g << uni(rng), uni(rng), uni(rng), uni(rng);
    const Eigen::Vector2d d(0.05 * uni(rng), 0.05 * uni(rng));
    t.p.push_back(p);
    t.g.push_back(g);
    t.d.push_back(d);
    t.chain.rows.emplace_back();
    for (int k = 0; k < 2; ++k) {
      const double scale = 0.5 + 3.0 * (uni(rng) + 1.0);
      LinearExpr e = scale * LinearExpr(x[j + 1][k]);
      for (int c = 0; c < 2; ++c) e -= scale * p(k, c) * LinearExpr(x[j][c]);
      for (int i = 0; i < 2; ++i) e -= scale * g(k, i) * LinearExpr(us[2 * j + i]);
      t.chain.rows.back().push_back(m.num_constraints());
      m.AddConstraint(e == scale * d[k], "dyn_" + std::to_string(k) + "_" + std::to_string(j));
    }
  }
  t.lp = m.ToLpData();
  return t;
}

TEST(ChainBoundsTest, EqualTheExtremesOverEveryVertexOfTheInputBox) {
  const int steps = 5;  // 10 inputs: 1024 vertices
  for (unsigned seed : {1u, 2u, 3u}) {
    const TestChain t = MakeChain(steps, 0.0, 1.0, seed);
    const ChainBounds b = ChainImpliedBounds(t.lp, t.chain);
    std::vector<Eigen::Vector2d> lo(steps + 1, Eigen::Vector2d::Constant(kInfinity)),
        hi(steps + 1, Eigen::Vector2d::Constant(-kInfinity));
    for (int mask = 0; mask < (1 << (2 * steps)); ++mask) {
      Eigen::Vector2d x(0.3, -0.2);
      for (int j = 0; j <= steps; ++j) {
        lo[j] = lo[j].cwiseMin(x);
        hi[j] = hi[j].cwiseMax(x);
        if (j == steps) break;
        const Eigen::Vector2d u((mask >> (2 * j)) & 1, (mask >> (2 * j + 1)) & 1);
        x = t.p[j] * x + t.g[j] * u + t.d[j];
      }
    }
    for (int j = 0; j <= steps; ++j) {
      for (int k = 0; k < 2; ++k) {
        const double pad = 1e-6 * (1.0 + std::abs(lo[j][k]) + std::abs(hi[j][k]));
        EXPECT_LE(b.lower[j][k], lo[j][k]) << "seed " << seed << " node " << j << " state " << k;
        EXPECT_GE(b.upper[j][k], hi[j][k]) << "seed " << seed << " node " << j << " state " << k;
        EXPECT_NEAR(b.lower[j][k], lo[j][k], pad);
        EXPECT_NEAR(b.upper[j][k], hi[j][k], pad);
      }
    }
  }
}

TEST(ChainBoundsTest, TighteningKeepsTheLpAndFixedColumns) {
  TestChain t = MakeChain(4, 0.0, 1.0, 7);
  LpData tight = t.lp;
  TightenToChainBounds(&tight, t.chain);
  EXPECT_EQ(tight.col_lower[t.chain.blocks[0][0]], 0.3);  // fixed start untouched
  EXPECT_EQ(tight.col_upper[t.chain.blocks[0][0]], 0.3);
  const ChainBounds b = ChainImpliedBounds(t.lp, t.chain);
  for (int j = 1; j <= 4; ++j) {
    for (int k = 0; k < 2; ++k) {
      const int c = t.chain.blocks[j][k];
      EXPECT_FALSE(std::isfinite(t.lp.col_lower[c]));
      const double lo = b.lower[j][k], hi = b.upper[j][k];
      const double margin = 0.5 * (hi - lo) + 1e-3 * (1.0 + std::max(std::abs(lo), std::abs(hi)));
      EXPECT_DOUBLE_EQ(tight.col_lower[c], lo - margin);
      EXPECT_DOUBLE_EQ(tight.col_upper[c], hi + margin);
    }
  }
  LpData exact = t.lp;
  TightenToChainBounds(&exact, t.chain, 0.0);
  EXPECT_DOUBLE_EQ(
      exact.col_upper[t.chain.blocks[2][1]],
      b.upper[2][1] + 1e-3 * (1.0 + std::max(std::abs(b.lower[2][1]), std::abs(b.upper[2][1]))));
  EXPECT_THAT([&] { TightenToChainBounds(&exact, t.chain, -1.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("widen_fraction")));
  for (int c : t.inputs) {
    EXPECT_EQ(tight.col_lower[c], t.lp.col_lower[c]);
    EXPECT_EQ(tight.col_upper[c], t.lp.col_upper[c]);
  }
  EXPECT_EQ((tight.a_matrix - t.lp.a_matrix).norm(), 0.0);
  EXPECT_EQ(tight.row_lower, t.lp.row_lower);
  EXPECT_EQ(tight.col_names, t.lp.col_names);
  // A fixed terminal state the inputs cannot reach keeps its own bounds (the
  // model is infeasible; the solver says so, not the writer).
  const int last = t.chain.blocks[4][0];
  LpData unreachable = t.lp;
  unreachable.col_lower[last] = unreachable.col_upper[last] = 1e6;
  TightenToChainBounds(&unreachable, t.chain);
  EXPECT_EQ(unreachable.col_lower[last], 1e6);
  EXPECT_EQ(unreachable.col_upper[last], 1e6);
}

TEST(ChainBoundsTest, AnInputUnboundedAboveOpensOnlyTheSidesItReaches) {
  const TestChain t = MakeChain(3, 0.0, kInfinity, 11);
  const ChainBounds b = ChainImpliedBounds(t.lp, t.chain);
  // Node 1: x_1 = P x_0 + G u + d with u >= 0: a state whose G row is all
  // positive is bounded below by P x_0 + d and unbounded above.
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector2d free = t.p[0] * Eigen::Vector2d(0.3, -0.2) + t.d[0];
    const bool up = t.g[0](k, 0) > 0 || t.g[0](k, 1) > 0;
    const bool down = t.g[0](k, 0) < 0 || t.g[0](k, 1) < 0;
    EXPECT_EQ(std::isinf(b.upper[1][k]), up) << k;
    EXPECT_EQ(std::isinf(b.lower[1][k]), down) << k;
    if (!down) {
      EXPECT_NEAR(b.lower[1][k], free[k], 1e-6);
    }
    if (!up) {
      EXPECT_NEAR(b.upper[1][k], free[k], 1e-6);
    }
  }
}

TEST(ChainBoundsTest, StructureErrorsNameTheRow) {
  TestChain t = MakeChain(2, 0.0, 1.0, 5);
  EqualityChain wrong = t.chain;
  wrong.rows.pop_back();
  EXPECT_THAT([&] { ChainImpliedBounds(t.lp, wrong); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("3 blocks need 2 row blocks")));
  LpData ranged = t.lp;
  ranged.row_upper[t.chain.rows[1][0]] += 1.0;
  EXPECT_THAT([&] { ChainImpliedBounds(ranged, t.chain); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("row dyn_0_1 is not an equality")));
  wrong = t.chain;
  std::swap(wrong.rows[0], wrong.rows[1]);  // step 1's rows hold blocks 1 and 2
  EXPECT_THAT(
      [&] { ChainImpliedBounds(t.lp, wrong); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("row dyn_0_1 holds a column of block 1")));
  wrong = t.chain;
  std::swap(wrong.blocks[1][0], wrong.blocks[1][1]);  // dyn_0_0 defines x_0_1, not x_1_1
  EXPECT_THAT([&] { ChainImpliedBounds(t.lp, wrong); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("row dyn_0_0 does not hold the column it defines")));
}

}  // namespace
}  // namespace thrustsched::milp
