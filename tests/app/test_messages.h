// Assertions on the text of error messages, shared by the app tests.
//
//   EXPECT_HAS(ScenarioErrorOf([&] { app::ParseScenario(j); }), "scenario.horizon.step_s");
#ifndef THRUSTSCHED_TESTS_APP_TEST_MESSAGES_H_
#define THRUSTSCHED_TESTS_APP_TEST_MESSAGES_H_

#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "app/json_reader.h"

/// `haystack` (anything convertible to std::string) contains `needle`.
#define EXPECT_HAS(haystack, needle) \
  EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << "in: " << (haystack)

namespace thrustsched::testing {

/// The ScenarioError message `parse` throws, or "(accepted)" if it throws none.
inline std::string ScenarioErrorOf(const std::function<void()>& parse) {
  try {
    parse();
  } catch (const app::ScenarioError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace thrustsched::testing

#endif  // THRUSTSCHED_TESTS_APP_TEST_MESSAGES_H_
