#include "transfer/second_order.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "common/constants.h"

namespace thrustsched::transfer {
namespace {

constexpr double kHour = 3600.0;

// MAP434's planar bounded-thrust minimum time (session 8): 60 N on 1500 kg,
// constant mass (Isp 1e9 s), the low circular orbit q_b = 0.1575 x_f to GEO.
MinTimeProblem Map434Problem() {
  MinTimeProblem p;
  p.initial = Equinoctial{0.1575 * 42165e3, 0, 0, 0, 0, 0};
  p.target = TargetElements::Circular(42165e3);
  p.mass_kg = 1500, p.thrust_n = 60, p.isp_s = 1e9;
  return p;
}

// Caillau, Gergaud & Noailles 2003 at 60 N: the switching function never
// vanishes (strengthened Legendre: min |F^T p| is 9 % of its max, measured
// 0.0897) and the endpoint map keeps its rank to t_f (the determinant stays
// of one sign once resolved, from 0.6 h, >= 0.085 over the second half);
// steps 100 times larger give the same determinant there to 0.1 %.
TEST(SecondOrderTest, Caillau60NewtonExtremalHasNoConjugatePoint) {
  const MinTimeProblem p = CaillauGtoProblem(60.0);
  const MinTimeSolution s = SolveMinTime(p, InitialGuess(p));
  ASSERT_TRUE(s.converged);
  const SecondOrderCheck c = CheckSecondOrder(p, s);
  EXPECT_TRUE(c.legendre_holds);
  EXPECT_GT(c.min_switching_norm, 0.05);
  EXPECT_EQ(c.verdict, "no_conjugate_point");
  EXPECT_TRUE(c.no_conjugate_point);
  EXPECT_TRUE(c.conjugate_times_s.empty());
  EXPECT_GT(c.min_abs_determinant, 0.05);
  EXPECT_GE(c.resolved_fraction_second_half, 0.99);
  EXPECT_LT(c.resolved_from_s, s.duration_s / 2);
  SecondOrderOptions o;
  o.costate_step = 1e-5, o.check_step = 1e-4;
  const SecondOrderCheck coarse = CheckSecondOrder(p, s, o);
  ASSERT_EQ(coarse.determinant.size(), c.determinant.size());
  for (std::size_t i = 0; i < c.t_s.size(); ++i) {
    if (c.t_s[i] < s.duration_s / 2) continue;
    EXPECT_NEAR(coarse.determinant[i], c.determinant[i], 1e-3 * std::abs(c.determinant[i])) << i;
  }
  EXPECT_EQ(coarse.verdict, "no_conjugate_point");
}

// MAP434 at 60 N: the shooting converges (35.18 h, 8.95 revolutions: above
// the 27.13 h lower bound of the Hohmann delta-v over the acceleration), H is
// constant, and the second-order checks pass (min |F^T p| / max = 0.0296,
// the determinant of one sign from 0.3 h to t_f, 7.9e-4 at its smallest).
TEST(SecondOrderTest, Map434MinimumTimeAt60NewtonsPassesTheChecks) {
  const MinTimeProblem p = Map434Problem();
  const MinTimeSolution s = SolveMinTime(p, InitialGuess(p));
  ASSERT_TRUE(s.converged);
  EXPECT_GT(s.duration_s / kHour, 27.13);
  EXPECT_NEAR(s.duration_s / kHour, 35.18, 0.05);
  EXPECT_LT(s.hamiltonian_drift, 1e-10);
  EXPECT_LT(std::abs(Eccentricity(s.final_elements)), 1e-8);
  EXPECT_NEAR(s.final_mass_kg, p.mass_kg, 1e-3);  // constant mass to 1 g
  const SecondOrderCheck c = CheckSecondOrder(p, s);
  EXPECT_TRUE(c.legendre_holds);
  EXPECT_GT(c.min_switching_norm, 0.01);
  EXPECT_EQ(c.verdict, "no_conjugate_point");
  EXPECT_TRUE(c.conjugate_times_s.empty());
  EXPECT_GT(c.min_abs_determinant, 1e-4);
  EXPECT_GE(c.resolved_fraction_second_half, 0.99);
}

TEST(SecondOrderTest, NeedsAnExtremal) {
  EXPECT_THROW(CheckSecondOrder(CaillauGtoProblem(60.0), MinTimeSolution{}), std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::transfer
