#include "dynamics/time.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace thrustsched::dynamics {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

TEST(EpochTest, JulianDatesOfKnownInstants) {
  // Published: J2000.0 = JD 2451545.0; 1987-04-10 0h = JD 2446895.5 (Meeus,
  // example 12.a). Derived here: 2034-01-01 0h = J2000.0 + 12418.5 d = JD 2463963.5.
  EXPECT_DOUBLE_EQ(Epoch::Parse("2000-01-01T12:00:00Z").JulianDateUtc(), 2451545.0);
  EXPECT_DOUBLE_EQ(Epoch::Parse("2034-01-01T00:00:00Z").JulianDateUtc(), 2463963.5);
  EXPECT_DOUBLE_EQ(Epoch::Parse("1987-04-10").JulianDateUtc(), 2446895.5);
  EXPECT_EQ(Epoch::Parse("1972-01-01").modified_julian_day(), 41317);
  // Leap-year day and fractional seconds.
  const Epoch e = Epoch::Parse("2024-02-29T18:30:15.25Z");
  EXPECT_NEAR(e.JulianDateUtc(), 2460369.5 + (18.5 * 3600 + 15.25) / 86400.0, 1e-9);
  EXPECT_DOUBLE_EQ(e.seconds_of_day(), 18.5 * 3600 + 15.25);
}

TEST(EpochTest, TerrestrialTimeUsesTheLeapSecondTable) {
  EXPECT_EQ(Epoch::Parse("1972-01-01").TaiMinusUtc(), 10.0);
  EXPECT_EQ(Epoch::Parse("2016-12-31T23:59:59Z").TaiMinusUtc(), 36.0);
  EXPECT_EQ(Epoch::Parse("2017-01-01").TaiMinusUtc(), 37.0);
  EXPECT_EQ(Epoch::Parse("2034-01-01").TaiMinusUtc(), 37.0);
  const Epoch e = Epoch::Parse("2034-01-01T00:00:00Z");
  EXPECT_NEAR((e.JulianDateTt() - e.JulianDateUtc()) * 86400.0, 69.184, 1e-4);
}

TEST(EpochTest, AcceptedSpellings) {
  const Epoch ref = Epoch::Parse("2034-01-01T06:07:00Z");
  EXPECT_EQ(Epoch::Parse("2034-01-01 06:07:00Z"), ref);
  EXPECT_EQ(Epoch::Parse("2034-01-01T06:07Z"), ref);
  EXPECT_EQ(Epoch::Parse("2034-01-01T06:07:00"), ref);
  EXPECT_EQ(Epoch::Parse("2034-01-01T06:07:00+00:00"), ref);
  EXPECT_EQ(Epoch::Parse("2034-01-01T06:07:00.000Z"), ref);
}

TEST(EpochTest, IsoRoundTripAndArithmetic) {
  for (const char* text :
       {"2034-01-01T00:00:00Z", "2024-02-29T23:59:59.5Z", "1999-12-31T12:34:56.123456Z"}) {
    EXPECT_EQ(Epoch::Parse(text).ToIso8601(), text);
  }
  const Epoch e = Epoch::Parse("2034-01-01T00:00:00Z");
  EXPECT_EQ(e.PlusSeconds(3600.0).ToIso8601(), "2034-01-01T01:00:00Z");
  EXPECT_EQ(e.PlusSeconds(-1.0).ToIso8601(), "2033-12-31T23:59:59Z");
  EXPECT_EQ(e.PlusSeconds(365.0 * 86400.0).ToIso8601(), "2035-01-01T00:00:00Z");
  EXPECT_EQ(e.PlusSeconds(59.0 * 86400.0).ToIso8601(), "2034-03-01T00:00:00Z");  // 2034 not leap
  EXPECT_NEAR(e.PlusSeconds(1234567.875).SecondsSince(e), 1234567.875, 1e-6);
  EXPECT_NEAR(e.PlusSeconds(86400.0).JulianDateTt() - e.JulianDateTt(), 1.0, 1e-9);
}

TEST(EpochTest, FixedDecimalsRoundAndCarry) {
  const Epoch e = Epoch::Parse("2034-01-01T00:00:00Z");
  EXPECT_EQ(e.FormatUtc(3, true), "2034-01-01T00:00:00.000Z");
  EXPECT_EQ(e.PlusSeconds(3723.4567).FormatUtc(3, false), "2034-01-01T01:02:03.457");
  EXPECT_EQ(e.PlusSeconds(3723.4567).FormatUtc(0, true), "2034-01-01T01:02:03Z");
  // Rounding up to midnight carries into the next day (and year).
  EXPECT_EQ(e.PlusSeconds(-0.0004).FormatUtc(3, true), "2034-01-01T00:00:00.000Z");
  EXPECT_EQ(e.PlusSeconds(-0.0006).FormatUtc(3, true), "2033-12-31T23:59:59.999Z");
  EXPECT_EQ(e.PlusSeconds(0.5).FormatUtc(6, false), "2034-01-01T00:00:00.500000");
  EXPECT_THROW(e.FormatUtc(10, true), std::invalid_argument);
}

TEST(EpochTest, OtherTimeScalesConvertToUtc) {
  // 2034: TAI - UTC = 37 s, TT - UTC = 69.184 s, GPS - UTC = 18 s.
  const Epoch utc = Epoch::Parse("2034-01-01T00:00:00Z");
  EXPECT_EQ(UtcFromScale(Epoch::Parse("2034-01-01T00:00:37Z"), TimeScale::kTai), utc);
  EXPECT_NEAR(
      UtcFromScale(Epoch::Parse("2034-01-01T00:01:09.184Z"), TimeScale::kTt).SecondsSince(utc), 0.0,
      1e-9);
  EXPECT_EQ(UtcFromScale(Epoch::Parse("2034-01-01T00:00:18Z"), TimeScale::kGps), utc);
  EXPECT_EQ(UtcFromScale(utc, TimeScale::kUtc), utc);
  // Just after the 2016-12-31 leap second: TAI - UTC = 37 s on the UTC side.
  EXPECT_EQ(UtcFromScale(Epoch::Parse("2017-01-01T00:00:37Z"), TimeScale::kTai),
            Epoch::Parse("2017-01-01T00:00:00Z"));
  // Just before it: 36 s.
  EXPECT_EQ(UtcFromScale(Epoch::Parse("2016-12-31T12:00:36Z"), TimeScale::kTai),
            Epoch::Parse("2016-12-31T12:00:00Z"));
  EXPECT_STREQ(ToString(TimeScale::kTt), "TT");
}

TEST(EpochTest, LeapSecondCrossingsAreDetected) {
  EXPECT_TRUE(CrossesLeapSecond(Epoch::Parse("2016-12-31T12:00:00Z"), 86400.0));
  EXPECT_FALSE(CrossesLeapSecond(Epoch::Parse("2017-01-01T00:00:00Z"), 365 * 86400.0));
  EXPECT_FALSE(CrossesLeapSecond(Epoch::Parse("2034-01-01T00:00:00Z"), 365 * 86400.0));
  // The table's last known date is after its last leap second.
  EXPECT_EQ(Epoch::Parse(kLeapSecondsKnownUntil).TaiMinusUtc(), 37.0);
}

TEST(GmstTest, PublishedValues) {
  // J2000.0: 280.46061837 deg by definition of the series.
  EXPECT_NEAR(GmstRad(2451545.0) / kDeg, 280.46061837, 1e-8);
  // Meeus example 12.a: 1987-04-10 0h UT, GMST = 13h10m46.3668s = 197.693195 deg.
  EXPECT_NEAR(GmstRad(2446895.5) / kDeg, 197.693195, 1e-5);
  // Theta(t0) at 2034-01-01 0h = 100.7225 deg (evaluated independently from the
  // series of Meeus eq. (12.4); not a published value).
  EXPECT_NEAR(GmstRad(Epoch::Parse("2034-01-01T00:00:00Z").JulianDateUtc()) / kDeg, 100.7225, 5e-5);
  // Sidereal rate: one solar day advances GMST by 360.98564736629 deg.
  const double d = GmstRad(2463964.5) - GmstRad(2463963.5);
  EXPECT_NEAR(std::remainder(d / kDeg - 0.98564736629, 360.0), 0.0, 1e-6);
}

TEST(EpochTest, BadTextThrowsNamingIt) {
  for (const char* bad :
       {"", "2034", "2034-1-01", "2034-13-01", "2034-02-29", "2034-01-32", "2034-01-01T24:00:00Z",
        "2034-01-01T12:60:00Z", "2034-01-01T12:00:60Z", "2034-01-01T12:00:00+01:00",
        "2034-01-01T12:00:00.Z", "2034/01/01", "1969-12-31", "2200-01-01", "tomorrow"}) {
    EXPECT_THAT([&] { Epoch::Parse(bad); },
                ThrowsMessage<std::invalid_argument>(HasSubstr(std::string("'") + bad + "'")))
        << bad;
  }
}

TEST(EpochTest, NonFiniteArgumentsThrow) {
  const Epoch e = Epoch::Parse("2034-01-01");
  EXPECT_THAT([&] { e.PlusSeconds(std::numeric_limits<double>::quiet_NaN()); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("seconds must be finite")));
  EXPECT_THAT([&] { e.PlusSeconds(std::numeric_limits<double>::infinity()); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("seconds must be finite")));
  EXPECT_THAT([&] { e.PlusSeconds(200.0 * 365.25 * 86400.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("year")));
  EXPECT_THAT([&] { GmstRad(std::numeric_limits<double>::quiet_NaN()); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("jd_ut1")));
}

}  // namespace
}  // namespace thrustsched::dynamics
