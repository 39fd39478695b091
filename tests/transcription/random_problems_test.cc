// The search (transcription/search.h) and the checker on a few hundred small
// random problems (tests/transcription/random_problems.h) against their exact
// optima: exhaustive enumeration of the on-off patterns where the pattern
// space is small, plain CBC on the whole MILP (search off) on the larger
// ones. Seeded: the same cases on every run. For long runs:
// scripts/soak_random_problems.sh --soak N.
#include <map>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "milp/cbc_solver.h"
#include "tests/transcription/random_problems.h"

namespace thrustsched::transcription::soak {
namespace {

constexpr int kCases = 300;  // seeds 1..kCases
// Horizons up to 24 slots here (the cases up to 40 take seconds each with
// 2-3 thrusters; they are the soak's: scripts/soak_random_problems.sh).
constexpr int kTestMaxSlots = 24;

// Every case agrees with its reference: status, objective, a reason for an
// infeasible one, and the checker passes every schedule returned.
TEST(RandomProblems, SearchAgreesWithTheExactOptimum) {
  const auto solver = milp::MakeCbcSolver();
  std::map<std::string, int> counts;
  for (int seed = 1; seed <= kCases; ++seed) {
    const RandomCase c = GenerateCase(seed, kTestMaxSlots);
    const CaseOutcome out = RunCase(c, *solver);
    EXPECT_TRUE(out.agree) << c.description << "\n  " << out.disagreement;
    EXPECT_FALSE(out.undecided) << c.description << "\n  reference: " << out.reference.detail;
    ++counts[std::string(ToString(out.reference.kind)) +
             (out.reference.feasible ? (out.reference.objective > 0 ? " firing" : " zero")
                                     : " infeasible")];
  }
  // The mix is not trivial: each reference sees problems that need firing
  // and infeasible ones, and some are solved without firing at all.
  for (const auto& [what, n] : counts) std::cout << "  " << what << ": " << n << " cases\n";
  EXPECT_GE(counts["enumeration firing"], kCases / 10);
  EXPECT_GE(counts["enumeration infeasible"], kCases / 30);
  EXPECT_GE(counts["plain CBC firing"], kCases / 10);
  EXPECT_GE(counts["plain CBC infeasible"], kCases / 30);
}

// The two references agree where both apply: the enumeration and plain CBC
// on the first enumerable cases (so neither is taken on trust).
TEST(RandomProblems, EnumerationAgreesWithPlainCbc) {
  const auto solver = milp::MakeCbcSolver();
  int compared = 0;
  for (int seed = 1; compared < 40; ++seed) {
    const RandomCase c = GenerateCase(seed, kTestMaxSlots);
    if (!c.enumerable) continue;
    ++compared;
    const Reference e = EnumerateOptimum(c.problem);
    const Reference cbc = PlainCbcOptimum(c.problem, *solver);
    ASSERT_TRUE(cbc.decided) << c.description << ": " << cbc.detail;
    ASSERT_EQ(e.feasible, cbc.feasible) << c.description << ": " << cbc.detail;
    if (e.feasible) {
      EXPECT_NEAR(e.objective, cbc.objective, 1e-7 + 1e-6 * e.objective) << c.description;
      EXPECT_GT(e.leaves, 0);  // a pattern reached the end and passed the rules
    }
  }
}

// Seed 63483 of the soak: one -Y thruster of 0.7 N on 100 kg, 26 slots of
// 30 s, a burn may cross the horizon's end. Unthrusted, y leaves the window
// (32.5 m + 0.2531 m/s x 780 s = 229.9 m > 229.1 m) only at the last node,
// and one last slot (braking 0.5 x 0.007 x 30^2 = 3.15 m) keeps it in: the
// optimum is one slot, 0.007 m/s^2 x 30 s = 0.21 m/s. Plain CBC 2.10.8 with
// its preprocessing off called 0.42 (two slots) optimal at its root; the
// soak then checks the search's point in the same MILP and reports CBC's
// claim as refuted, not as a disagreement.
TEST(RandomProblems, APlainCbcOptimumAboveAFeasiblePointIsRefuted) {
  const RandomCase c = GenerateCase(63483);
  const CaseOutcome out = RunCase(c, *milp::MakeCbcSolver());
  EXPECT_TRUE(out.agree) << out.disagreement;
  EXPECT_EQ(out.status, milp::SolveStatus::kOptimal);
  EXPECT_NEAR(out.objective, 0.7 / 100.0 * 30.0, 1e-4);  // the L1 metric of one slot
  if (out.reference_refuted) {
    EXPECT_GT(out.reference.objective, out.objective);
    EXPECT_NE(out.refutation.find("keeps every row"), std::string::npos);
  }
}

// Same seed, same case; different seeds, different cases.
TEST(RandomProblems, GeneratorIsDeterministic) {
  EXPECT_EQ(GenerateCase(7).description, GenerateCase(7).description);
  EXPECT_NE(GenerateCase(7).description, GenerateCase(8).description);
  const RandomCase c = GenerateCase(7);
  std::string error;
  EXPECT_TRUE(c.problem.IsValid(&error)) << error;
  EXPECT_GE(c.problem.num_intervals(), 6);
  EXPECT_LE(c.problem.num_intervals(), 40);
}

}  // namespace
}  // namespace thrustsched::transcription::soak
