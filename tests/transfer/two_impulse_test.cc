#include "transfer/two_impulse.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "transfer/equinoctial.h"

namespace thrustsched::transfer {
namespace {

constexpr double kHour = 3600.0;

// Vallado 2013, Example 6-1: LEO (191.34411 km altitude) to GEO, mu = 398600.4418.
TEST(TwoImpulseTest, HohmannMatchesValladoExample6_1) {
  const HohmannTransfer h = Hohmann(6569.48071e3, 42159.48517e3, 3.986004418e14);
  EXPECT_NEAR(h.dv1_m_s, 2457.038, 1e-3);
  EXPECT_NEAR(h.dv2_m_s, 1478.187, 1e-3);
  EXPECT_NEAR(h.total_m_s, 3935.224, 1e-3);
  EXPECT_NEAR(h.time_of_flight_s / kHour, 5.256713, 1e-6);
  EXPECT_THROW(Hohmann(-1, 2, 3), std::invalid_argument);
}

// MAP434 (session 8): circular start q_b = 0.1575 x_f, x_f = 42165 km,
// mu = 398600.47 km^3/s^2; its criterion in x_f / h units. The minimum is
// the Hohmann transfer: J = 0.0295189, dV0 = 0.208017, dVf = 0.125566,
// t_f = 5.2692 h (3.9071 km/s).
TEST(TwoImpulseTest, Map434OptimumIsTheHohmannTransfer) {
  const double xf = 42165e3, unit = xf / kHour;  // m/s per x_f/h
  const TwoImpulseProblem p{kMuEarth, 0.1575 * xf, xf};
  const TwoImpulseResult r = MinimiseTwoImpulse(p);
  EXPECT_NEAR(r.cost_m2_s2 / (unit * unit), 0.0295189, 5e-7);
  EXPECT_NEAR(r.dv0_m_s / unit, 0.208017, 5e-7);
  EXPECT_NEAR(r.dvf_m_s / unit, 0.125566, 5e-7);
  EXPECT_NEAR(r.time_of_flight_s / kHour, 5.2692, 5e-5);
  EXPECT_NEAR(r.dv0_m_s + r.dvf_m_s, 3907.1, 0.05);
  const HohmannTransfer h = Hohmann(p.r0_m, p.target_m, p.mu);
  EXPECT_NEAR(r.dv0_m_s, h.dv1_m_s, 1e-4);
  EXPECT_NEAR(r.dvf_m_s, h.dv2_m_s, 1e-4);
  EXPECT_NEAR(r.time_of_flight_s, h.time_of_flight_s, 1e-2);
  EXPECT_NEAR(r.dv0_radial_m_s, 0.0, 1e-4);
}

// Independent of the nested golden sections: no transfer on a grid of
// post-burn velocities (every reachable ellipse) does better.
TEST(TwoImpulseTest, NoTransferOnAGridBeatsTheOptimum) {
  const double xf = 42165e3;
  const TwoImpulseProblem p{kMuEarth, 0.1575 * xf, xf};
  const TwoImpulseResult best = MinimiseTwoImpulse(p);
  const double vc = std::sqrt(p.mu / p.r0_m);
  int feasible = 0;
  for (int i = -100; i <= 100; ++i) {
    for (int j = 0; j <= 400; ++j) {
      TwoImpulseResult r;
      const double vr = 0.01 * vc * i, vt = vc * (1 + 0.001 * j);
      if (!EvaluateTwoImpulse(p, vr, vt, &r)) continue;
      ++feasible;
      EXPECT_GE(r.cost_m2_s2, best.cost_m2_s2 * (1 - 1e-12)) << vr << " " << vt;
    }
  }
  EXPECT_GT(feasible, 10000);
}

TEST(TwoImpulseTest, BadProblemIsRefusedNamingTheField) {
  std::string error;
  EXPECT_FALSE((TwoImpulseProblem{kMuEarth, 7e6, 6e6}.IsValid(&error)));
  EXPECT_NE(error.find("target_m"), std::string::npos);
  EXPECT_THROW(MinimiseTwoImpulse({kMuEarth, -1, 6e6}), std::invalid_argument);
}

}  // namespace
}  // namespace thrustsched::transfer
