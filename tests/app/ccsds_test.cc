// CCSDS OEM and OPM readers and writers (app/ccsds_oem.h, app/ccsds_opm.h):
// round trips, files written the way other tools write them, and the
// errors for what the program does not support (naming keyword and value).
#include <cmath>
#include <cstdlib>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "app/ccsds_kvn.h"
#include "app/ccsds_oem.h"
#include "app/ccsds_opm.h"

namespace thrustsched::app {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

dynamics::Epoch At(const char* text) { return dynamics::Epoch::Parse(text); }

// Replaces `from` by `to` in the good text and expects `parse` to throw a
// ScenarioError containing `message`.
template <typename Parse>
void ExpectEditFails(Parse parse, const std::string& good, const std::string& from,
                     const std::string& to, const std::string& message) {
  std::string text = good;
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  EXPECT_THAT([&] { parse(text); }, ThrowsMessage<ScenarioError>(HasSubstr(message))) << to;
}

// A GEO ephemeris written the way operations centres write them (two
// segments split at a manoeuvre, units, comments, a covariance block, a
// day-of-year epoch).
const char* kOem = R"(CCSDS_OEM_VERS = 2.0
COMMENT written by hand for the test
CREATION_DATE = 2033-12-31T12:00:00
ORIGINATOR = OPS CENTRE

META_START
OBJECT_NAME          = GEO-TEST
OBJECT_ID            = 2033-999A
CENTER_NAME          = EARTH
REF_FRAME            = EME2000
TIME_SYSTEM          = UTC
START_TIME           = 2034-01-01T00:00:00.000
STOP_TIME            = 2034-001T00:10:00
INTERPOLATION        = HERMITE
INTERPOLATION_DEGREE = 1
META_STOP
COMMENT coast
2034-01-01T00:00:00.000 -32906.123456 -26357.654321 12.500000 1.921234567 -2.399876543 0.000700000
2034-001T00:10:00Z -31697.000001 -27783.000002 12.900000 2.076000001 -2.266000002 0.000600000

META_START
OBJECT_NAME          = GEO-TEST
OBJECT_ID            = 2033-999A
CENTER_NAME          = EARTH
REF_FRAME            = GCRF
TIME_SYSTEM          = TAI
START_TIME           = 2034-01-01T00:10:37.000
STOP_TIME            = 2034-01-01T00:20:37.000
META_STOP
2034-01-01T00:10:37.000 -31697.000001 -27783.000002 12.900000 2.076000001 -2.266000002 0.000600000 1e-6 2e-6 3e-6
2034-01-01T00:20:37.000 -30400.0 -29150.0 13.2 2.22 -2.12 0.0005 1e-6 2e-6 3e-6
COVARIANCE_START
EPOCH = 2034-01-01T00:10:37.000
COV_REF_FRAME = RTN
1.0e-4
COVARIANCE_STOP
)";

TEST(CcsdsOem, ReadsAFileWrittenByAnotherTool) {
  const OemFile f = ParseOem(kOem, "test.oem");
  EXPECT_EQ(f.version, "2.0");
  EXPECT_EQ(f.originator, "OPS CENTRE");
  ASSERT_EQ(f.segments.size(), 2u);
  const OemSegment& a = f.segments[0];
  EXPECT_EQ(a.object_id, "2033-999A");
  EXPECT_EQ(a.frame, dynamics::InertialFrame::kEme2000);
  EXPECT_EQ(a.interpolation, "HERMITE");
  EXPECT_EQ(a.interpolation_degree, 1);
  EXPECT_EQ(a.comments, std::vector<std::string>{"coast"});
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.points[1].epoch, At("2034-01-01T00:10:00Z"));  // day-of-year form
  EXPECT_NEAR(a.points[0].rv[0], -32906123.456, 1e-6);
  EXPECT_NEAR(a.points[0].rv[4], -2399.876543, 1e-9);
  // TAI epochs are held in UTC (TAI - UTC = 37 s); accelerations and covariance are read over.
  const OemSegment& b = f.segments[1];
  EXPECT_EQ(b.frame, dynamics::InertialFrame::kGcrf);
  EXPECT_EQ(b.points[0].epoch, At("2034-01-01T00:10:00Z"));
  EXPECT_EQ(b.stop_time, At("2034-01-01T00:20:00Z"));
  EXPECT_EQ(b.interpolation_degree, -1);
}

TEST(CcsdsOem, WritesWhatItReads) {
  OemFile f;
  f.comments = {"round trip"};
  f.creation_date = At("2030-06-01T00:00:00Z");
  f.originator = "THRUSTSCHED";
  OemSegment s;
  s.object_name = "GEO 118E";
  s.object_id = "UNKNOWN";
  s.start_time = At("2034-01-01T00:00:00Z");
  s.stop_time = At("2034-01-01T00:00:20.5Z");
  dynamics::Vector6d rv;
  rv << -32906123.4564, -26357654.3213, 12500.0004, 1921.2345674, -2399.8765436, 0.7000004;
  s.points = {{s.start_time, rv},
              {At("2034-01-01T00:00:10.000002Z"), rv * 1.001},
              {s.stop_time, rv * 1.002}};
  f.segments = {s, s};
  const std::string text = FormatOem(f);
  EXPECT_THAT(text, HasSubstr("CCSDS_OEM_VERS       = 2.0\n"));
  EXPECT_THAT(text, HasSubstr("REF_FRAME            = EME2000\n"));
  EXPECT_THAT(text, HasSubstr("TIME_SYSTEM          = UTC\n"));
  EXPECT_THAT(text, HasSubstr("INTERPOLATION_DEGREE = 5\n"));
  EXPECT_THAT(text, HasSubstr("2034-01-01T00:00:20.500 "));
  EXPECT_THAT(text,
              HasSubstr("2034-01-01T00:00:10.000002 "));  // sub-millisecond epochs get 6 decimals
  EXPECT_THAT(
      text,
      HasSubstr(" -32906.123456 -26357.654321 12.500000 1.921234567 -2.399876544 0.000700000\n"));
  const OemFile g = ParseOem(text, "written.oem");
  ASSERT_EQ(g.segments.size(), 2u);
  EXPECT_EQ(g.creation_date, f.creation_date);
  EXPECT_EQ(g.comments, f.comments);
  for (size_t k = 0; k < 3; ++k) {
    const OemPoint& p = g.segments[1].points[k];
    EXPECT_NEAR(p.epoch.SecondsSince(s.points[k].epoch), 0.0, 1e-6);
    EXPECT_LT((p.rv - s.points[k].rv).head<3>().cwiseAbs().maxCoeff(),
              0.5e-3 + 1e-9);  // 1 mm steps
    EXPECT_LT((p.rv - s.points[k].rv).tail<3>().cwiseAbs().maxCoeff(),
              0.5e-6 + 1e-12);  // 1 um/s steps
  }
}

TEST(CcsdsOem, RejectsWhatItDoesNotSupportNamingKeywordAndValue) {
  auto fails = [](const std::string& from, const std::string& to, const std::string& message) {
    ExpectEditFails([](const std::string& t) { ParseOem(t, "bad.oem"); }, kOem, from, to, message);
  };
  fails("REF_FRAME            = EME2000", "REF_FRAME = ITRF2014",
        "bad.oem:10: REF_FRAME = ITRF2014: unsupported reference frame");
  fails("REF_FRAME            = EME2000", "REF_FRAME = TOD",
        "REF_FRAME = TOD: unsupported reference frame");
  fails("TIME_SYSTEM          = UTC", "TIME_SYSTEM = TDB",
        "TIME_SYSTEM = TDB: unsupported time system");
  fails("CENTER_NAME          = EARTH", "CENTER_NAME = MARS BARYCENTER",
        "CENTER_NAME = MARS BARYCENTER: unsupported centre");
  fails("CCSDS_OEM_VERS = 2.0", "CCSDS_OEM_VERS = 4.0",
        "CCSDS_OEM_VERS = 4.0: unsupported version");
  fails("OBJECT_ID            = 2033-999A\n", "",
        "META block lacks the mandatory keyword OBJECT_ID");
  fails("2034-001T00:10:00Z -31697.000001", "2033-12-31T23:59:00 -31697.000001",
        "epoch outside the segment's [START_TIME, STOP_TIME]");
  fails("-26357.654321 12.500000", "-26357.654321 nan", "\"nan\" is not a finite number");
  fails(" 0.000700000\n", "\n", "a data line holds an epoch and 6 numbers");
  fails("STOP_TIME            = 2034-001T00:10:00", "STOP_TIME = 2034-400T00:10:00",
        "day of year 400 not in 1..365");
  fails("ORIGINATOR = OPS CENTRE\n", "", "the OEM header lacks ORIGINATOR");
  fails("META_STOP\nCOMMENT coast", "COMMENT coast", "META block");
  EXPECT_THAT([] { ParseOem("CCSDS_OPM_VERS = 2.0\n", "x.oem"); },
              ThrowsMessage<ScenarioError>(HasSubstr("x.oem: not a CCSDS OEM")));
}

// An OPM the way operations centres send one (after CCSDS 502.0-B-3 Annex G
// examples): a GEO satellite, Keplerian elements, spacecraft parameters, a
// maneuver, covariance.
const char* kOpm = R"(CCSDS_OPM_VERS = 3.0
COMMENT Generated for the test
CREATION_DATE = 2033-12-31T18:00:00.000
ORIGINATOR = OPS CENTRE
MESSAGE_ID = TEST-0001

OBJECT_NAME = GEO-TEST
OBJECT_ID = 2033-999A
CENTER_NAME = EARTH
REF_FRAME = EME2000
TIME_SYSTEM = UTC

COMMENT State Vector
EPOCH = 2033-365T22:00:00.000
X = -32906.123456 [km]
Y = -26357.654321 [km]
Z = 12.5 [km]
X_DOT = 1.921234567 [km/s]
Y_DOT = -2.399876543 [km/s]
Z_DOT = 0.0007 [km/s]

SEMI_MAJOR_AXIS = 42165.9 [km]
ECCENTRICITY = 0.0002
INCLINATION = 0.03 [deg]
RA_OF_ASC_NODE = 80.0 [deg]
ARG_OF_PERICENTER = 200.0 [deg]
MEAN_ANOMALY = 38.5 [deg]
GM = 398600.4418 [km**3/s**2]

MASS = 4850.0 [kg]
SOLAR_RAD_AREA = 110.1 [m**2]
SOLAR_RAD_COEFF = 1.0
DRAG_AREA = 0.0 [m**2]
DRAG_COEFF = 0.0

CX_X = 1.0e-6
CY_X = 0.0
CY_Y = 1.0e-6

COMMENT east-west burn
MAN_EPOCH_IGNITION = 2034-01-01T05:00:00.000
MAN_DURATION = 600.0 [s]
MAN_DELTA_MASS = -0.0081 [kg]
MAN_REF_FRAME = RTN
MAN_DV_1 = 0.0 [km/s]
MAN_DV_2 = 0.0000327835 [km/s]
MAN_DV_3 = 0.0 [km/s]
USER_DEFINED_MISSION = TEST
)";

TEST(CcsdsOpm, ReadsAFileWrittenByAnotherTool) {
  const Opm o = ParseOpm(kOpm, "test.opm");
  EXPECT_EQ(o.version, "3.0");
  EXPECT_EQ(o.object_name, "GEO-TEST");
  EXPECT_EQ(o.frame, dynamics::InertialFrame::kEme2000);
  EXPECT_EQ(o.epoch, At("2033-12-31T22:00:00Z"));
  EXPECT_NEAR(o.rv[1], -26357654.321, 1e-6);
  EXPECT_NEAR(o.rv[5], 0.7, 1e-12);
  EXPECT_EQ(o.state_comments, std::vector<std::string>{"State Vector"});
  ASSERT_TRUE(o.keplerian.has_value());
  EXPECT_NEAR(o.keplerian->elements.a_m, 42165.9e3, 1e-6);
  EXPECT_NEAR(o.keplerian->elements.i_rad, 0.03 * kDeg, 1e-15);
  EXPECT_EQ(o.keplerian->elements.anomaly, dynamics::AnomalyKind::kMean);
  EXPECT_NEAR(o.keplerian->gm_m3_s2, 3.986004418e14, 1e3);
  ASSERT_TRUE(o.spacecraft.has_value());
  EXPECT_EQ(o.spacecraft->mass_kg, 4850.0);
  ASSERT_EQ(o.maneuvers.size(), 1u);
  EXPECT_EQ(o.maneuvers[0].comments, std::vector<std::string>{"east-west burn"});
  EXPECT_EQ(o.maneuvers[0].ignition, At("2034-01-01T05:00:00Z"));
  EXPECT_EQ(o.maneuvers[0].ref_frame, "RTN");
  EXPECT_NEAR(o.maneuvers[0].dv_m_s[1], 0.0327835, 1e-12);
}

TEST(CcsdsOpm, WritesWhatItReads) {
  Opm o = ParseOpm(kOpm, "test.opm");
  o.version = "2.0";
  const Opm back = ParseOpm(FormatOpm(o), "written.opm");
  EXPECT_EQ(back.epoch, o.epoch);
  EXPECT_LT((back.rv - o.rv).head<3>().cwiseAbs().maxCoeff(), 0.5e-3);
  EXPECT_LT((back.rv - o.rv).tail<3>().cwiseAbs().maxCoeff(), 0.5e-6);
  EXPECT_NEAR(back.keplerian->elements.anomaly_rad, o.keplerian->elements.anomaly_rad, 1e-12);
  EXPECT_NEAR(back.keplerian->elements.e, o.keplerian->elements.e, 1e-12);
  ASSERT_EQ(back.maneuvers.size(), 1u);
  EXPECT_NEAR(back.maneuvers[0].duration_s, 600.0, 1e-9);
  EXPECT_NEAR(back.maneuvers[0].delta_mass_kg, -0.0081, 1e-9);
  EXPECT_NEAR(back.maneuvers[0].dv_m_s[1], 0.0327835, 1e-9);
  EXPECT_EQ(back.maneuvers[0].comments, o.maneuvers[0].comments);
}

TEST(CcsdsOpm, RejectsWhatItDoesNotSupportNamingKeywordAndValue) {
  auto fails = [](const std::string& from, const std::string& to, const std::string& message) {
    ExpectEditFails([](const std::string& t) { ParseOpm(t, "bad.opm"); }, kOpm, from, to, message);
  };
  fails("REF_FRAME = EME2000", "REF_FRAME = TOD",
        "bad.opm:10: REF_FRAME = TOD: unsupported reference frame");
  fails("REF_FRAME = EME2000", "REF_FRAME = ITRF-93",
        "REF_FRAME = ITRF-93: unsupported reference frame");
  fails("TIME_SYSTEM = UTC", "TIME_SYSTEM = UT1",
        "TIME_SYSTEM = UT1: unsupported time system (supported: UTC, TAI, TT, GPS)");
  fails("CENTER_NAME = EARTH", "CENTER_NAME = MOON", "CENTER_NAME = MOON: unsupported centre");
  fails("X = -32906.123456 [km]", "X = -32906123.456 [m]",
        "X = -32906123.456: units [m] where [km] are expected");
  fails("Z_DOT = 0.0007 [km/s]\n", "", "the state vector lacks the mandatory keyword Z_DOT");
  fails("GM = 398600.4418 [km**3/s**2]\n", "",
        "the Keplerian elements block lacks the mandatory keyword GM");
  fails("ECCENTRICITY = 0.0002", "ECCENTRICITY = 1.2", "invalid Keplerian elements");
  fails("MAN_DELTA_MASS = -0.0081", "MAN_DELTA_MASS = 0.0081",
        "MAN_DELTA_MASS = 0.0081: must be <= 0");
  fails("MAN_DV_3 = 0.0 [km/s]\n", "", "the maneuver block lacks MAN_DV_3");
  fails("EPOCH = 2033-365T22:00:00.000", "EPOCH = 2033-12-31T23:59:60",
        "a leap second (ss = 60) cannot be represented");
  fails("MASS = 4850.0 [kg]", "MASS = 4850.0 [kg]\nX = 1 [km]", "X = 1: out of order");
  fails("OBJECT_ID = 2033-999A", "OBJECT_ID = 2033-999A\nOBJECT_ID = 2", "OBJECT_ID = 2: repeated");
  fails("MESSAGE_ID = TEST-0001", "MESSAGE_IDENT = TEST-0001",
        "MESSAGE_IDENT = TEST-0001: unknown OPM keyword");
}

TEST(CcsdsKvn, CreationDateFollowsSourceDateEpoch) {
  setenv("SOURCE_DATE_EPOCH", "2000000000", 1);  // 2033-05-18T03:33:20Z
  EXPECT_EQ(CreationDate(), At("2033-05-18T03:33:20Z"));
  setenv("SOURCE_DATE_EPOCH", "soon", 1);
  EXPECT_THAT([] { CreationDate(); }, ThrowsMessage<ScenarioError>(HasSubstr("SOURCE_DATE_EPOCH")));
  unsetenv("SOURCE_DATE_EPOCH");
  EXPECT_GT(CreationDate().SecondsSince(At("2024-01-01T00:00:00Z")), 0.0);
}

}  // namespace
}  // namespace thrustsched::app
