// IsValid of the options structs of dynamics/ and transcription/: a bad value
// is refused with a message naming the field and the value, and the function
// that consumes the options throws std::invalid_argument with that message.
#include <limits>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dynamics/discretisation.h"
#include "milp/cbc_solver.h"
#include "tests/transcription/thesis_cases.h"
#include "transcription/checker.h"
#include "transcription/conjunction_check.h"
#include "transcription/conjunction_solve.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"
#include "transcription/terminal_sets.h"

namespace thrustsched::transcription {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(OptionsIsValid, DiscretizationOptions) {
  dynamics::DiscretizationOptions o;
  std::string e;
  EXPECT_TRUE(o.IsValid(&e));
  EXPECT_TRUE(o.IsValid(nullptr));
  o.rk4_substeps = 0;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "rk4_substeps must be >= 1, got 0");
  EXPECT_FALSE(o.IsValid(nullptr));
  o = {};
  o.reference_tolerance = 0.01;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "reference_tolerance must be in (0, 1e-3], got 0.01");
  o.reference_tolerance = kNaN;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_THAT(e, HasSubstr("reference_tolerance"));
}

TEST(OptionsIsValid, BuildOptionsNamesTheDiscretisationField) {
  BuildOptions o;
  std::string e;
  EXPECT_TRUE(o.IsValid(&e));
  o.discretisation.rk4_substeps = -2;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "discretisation.rk4_substeps must be >= 1, got -2");
  EXPECT_THAT([&] { ScheduleMilp m(ThesisTable41(1), o); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("options.discretisation.rk4_substeps must be >= 1, got -2")));
}

TEST(OptionsIsValid, CheckOptions) {
  CheckOptions o;
  std::string e;
  EXPECT_TRUE(o.IsValid(&e));
  o.samples_per_interval = -1;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "samples_per_interval must be >= 0, got -1");
  EXPECT_THAT([&] { CheckSchedule(ThesisTable41(1), {}, o); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("CheckSchedule: options.samples_per_interval must be >= 0, got -1")));
  o = {};
  o.propagation_tolerance = 0.0;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "propagation_tolerance must be finite and > 0, got 0");
}

TEST(OptionsIsValid, SolveScheduleOptionsNamesTheSubStruct) {
  SolveScheduleOptions o;
  std::string e;
  EXPECT_TRUE(o.IsValid(&e));

  o.milp.relative_gap = -0.5;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_THAT(e, HasSubstr("milp"));
  EXPECT_THAT(e, HasSubstr("relative_gap must be finite and >= 0, got -0.5"));
  auto solver = milp::MakeCbcSolver();
  EXPECT_THAT([&] { SolveSchedule(ThesisTable41(1), *solver, o); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("relative_gap must be finite and >= 0, got -0.5")));

  o = {};
  o.build.discretisation.reference_tolerance = 1.0;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "build.discretisation.reference_tolerance must be in (0, 1e-3], got 1");

  o = {};
  o.check.samples_per_interval = -3;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "check.samples_per_interval must be >= 0, got -3");
  o.check_schedule = false;  // the check options are not read
  EXPECT_TRUE(o.IsValid(&e));

  o = {};
  o.search.nets.max_widenings = -1;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_THAT(e, HasSubstr("max_widenings must be >= 0, got -1"));
  o.search.enabled = false;  // the search options are not read
  EXPECT_TRUE(o.IsValid(&e));
}

TEST(OptionsIsValid, SkSetOptions) {
  SkSetOptions o;
  o.mean_motion = 7.2921159e-5;
  o.eps_y = o.eps_z = 36800.0;
  std::string e;
  EXPECT_TRUE(o.IsValid(&e));
  SkSetOptions bad = o;
  bad.mean_motion = -1.0;
  EXPECT_FALSE(bad.IsValid(&e));
  EXPECT_THAT(e, HasSubstr("mean_motion must be finite and > 0, got -1"));
  EXPECT_THAT(
      [&] { StationKeepingSet(bad); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("terminal set: mean_motion must be finite")));
  bad = o;
  bad.facets_cone_plus = 2;
  EXPECT_FALSE(bad.IsValid(&e));
  EXPECT_THAT(e, HasSubstr("facets"));
  bad = o;
  bad.lookahead_s = {0.0, -60.0};
  EXPECT_FALSE(bad.IsValid(&e));
  EXPECT_THAT(e, HasSubstr("lookahead_s"));
}

TEST(OptionsIsValid, ConjunctionCheckOptions) {
  ConjunctionCheckOptions o;
  std::string e;
  EXPECT_TRUE(o.IsValid(&e));
  o.monte_carlo_samples = -1;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "monte_carlo_samples must be >= 0, got -1");
  o = {};
  o.sample_step_s = -2.5;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "sample_step_s must be finite and >= 0, got -2.5");
  o.sample_step_s = kNaN;
  EXPECT_FALSE(o.IsValid(nullptr));
  o = {};
  o.propagation_tolerance = 0.0;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "propagation_tolerance must be finite and > 0, got 0");
}

TEST(OptionsIsValid, ConjunctionSolveOptions) {
  ConjunctionSolveOptions o;
  std::string e;
  EXPECT_TRUE(o.IsValid(&e));
  o.restart_ratio = 1.5;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "restart_ratio must be in (0, 1], got 1.5");
  o.restart_ratio = 0.0;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "restart_ratio must be in (0, 1], got 0");
  o = {};
  o.max_rounds = 0;
  EXPECT_FALSE(o.IsValid(&e));
  EXPECT_EQ(e, "max_rounds must be >= 1, got 0");
}

}  // namespace
}  // namespace thrustsched::transcription
