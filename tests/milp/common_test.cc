// The shared helpers of common/: FormatG writes what an ostream with the same
// precision writes (every call site that moved to it kept its digits), and
// Fail follows the IsValid convention.
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/constants.h"
#include "common/error.h"
#include "common/format.h"
#include "milp/solver.h"

namespace thrustsched::common {
namespace {

std::string Stream(double v, int digits) {
  std::ostringstream os;
  os.precision(digits);
  os << v;
  return os.str();
}

TEST(CommonFormat, FormatGIsTheOstreamDefaultFormat) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double v :
       {0.0, -0.0, 1.0, -2.5, 0.1, 1.0 / 3.0, 123456789.0, 1e-7, 6.02214076e23, kPi, inf, -inf}) {
    for (int digits : {4, 6, 10, 12, 15, 17}) {
      EXPECT_EQ(FormatG(v, digits), Stream(v, digits)) << v << " with " << digits << " digits";
    }
  }
  EXPECT_EQ(FormatG(0.1, 17), "0.10000000000000001");
  EXPECT_EQ(FormatG(86400.0, 10), "86400");
  EXPECT_EQ(FormatG(1e-3, 6), "0.001");
}

TEST(CommonError, FailStoresTheMessageWhenAskedAndReturnsFalse) {
  std::string e = "unchanged";
  EXPECT_FALSE(Fail(&e, "x must be > 0, got -1"));
  EXPECT_EQ(e, "x must be > 0, got -1");
  EXPECT_FALSE(Fail(nullptr, "ignored"));
}

TEST(CommonConstants, Values) {
  EXPECT_EQ(kSecondsPerDay, 86400.0);
  EXPECT_DOUBLE_EQ(kDegToRad * 180.0, kPi);
  EXPECT_DOUBLE_EQ(kRadToDeg * kPi, 180.0);
}

TEST(RelativeGap, DenominatorIsTheObjectiveFloor1e10) {
  EXPECT_DOUBLE_EQ(milp::RelativeGap(2.0, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(milp::RelativeGap(-2.0, -3.0), 0.5);
  EXPECT_DOUBLE_EQ(milp::RelativeGap(0.0, 1e-12), 1e-2);  // |0 - 1e-12| / 1e-10
  EXPECT_TRUE(std::isinf(milp::RelativeGap(1.0, -std::numeric_limits<double>::infinity())));
  EXPECT_TRUE(std::isinf(milp::RelativeGap(std::numeric_limits<double>::quiet_NaN(), 1.0)));
}

}  // namespace
}  // namespace thrustsched::common
