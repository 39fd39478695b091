// The long-run mode of the random-problem soak (random_problems.h):
//   random_soak --soak N [--first-seed S] [--max-slots M] [--verbose]
// solves seeds S .. S+N-1 (default S = 1; horizons up to M slots, default 40,
// the cap of the plain-CBC cases: random_problems.h) with the search, compares each with
// its exact reference, prints each disagreement (seed and case) as it is
// found and a summary at the end (also after SIGINT or SIGTERM, which stop
// it between two cases: the summary counts the cases run). Exit 0 when every case agrees, 1
// otherwise, 2 on a bad argument. Run through scripts/soak_random_problems.sh.
#include <chrono>
#include <climits>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "milp/cbc_solver.h"
#include "tests/transcription/random_problems.h"

namespace soak = thrustsched::transcription::soak;

namespace {
volatile std::sig_atomic_t g_stop = 0;
void OnStop(int) { g_stop = 1; }
}  // namespace

int main(int argc, char** argv) {
  long long count = -1;
  std::uint64_t first = 1;
  int max_slots = soak::kMaxSlots;
  bool verbose = false;  // each case's description before it is solved
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--verbose") {
      verbose = true;
    } else if ((a == "--soak" || a == "--first-seed" || a == "--max-slots") && i + 1 < argc) {
      char* end = nullptr;
      const long long v = std::strtoll(argv[++i], &end, 10);
      const long long lo = a == "--soak" ? 1 : a == "--max-slots" ? soak::kMinSlots : 0;
      const long long hi = a == "--max-slots" ? soak::kMaxSlots : LLONG_MAX;
      if (*end != '\0' || v < lo || v > hi) {
        std::cerr << "random_soak: " << a << ": expected an integer in [" << lo << ", " << hi
                  << "], got '" << argv[i] << "'\n";
        return 2;
      }
      if (a == "--soak") {
        count = v;
      } else if (a == "--max-slots") {
        max_slots = static_cast<int>(v);
      } else {
        first = static_cast<std::uint64_t>(v);
      }
    } else {
      std::cerr << "usage: random_soak --soak N [--first-seed S] [--max-slots M] [--verbose]\n";
      return 2;
    }
  }
  if (count < 1) {
    std::cerr << "usage: random_soak --soak N [--first-seed S] [--max-slots M] [--verbose]\n";
    return 2;
  }
  const auto solver = thrustsched::milp::MakeCbcSolver();
  const auto t0 = std::chrono::steady_clock::now();
  std::map<std::string, long long> counts;
  long long disagreements = 0, undecided = 0, refuted = 0, run = 0;
  std::signal(SIGINT, OnStop);
  std::signal(SIGTERM, OnStop);
  for (long long k = 0; k < count && !g_stop; ++k, ++run) {
    const soak::RandomCase c = soak::GenerateCase(first + k, max_slots);
    if (verbose) std::cout << c.description << std::endl;
    const auto tc = std::chrono::steady_clock::now();
    const soak::CaseOutcome out = soak::RunCase(c, *solver);
    if (verbose) {
      std::cout << "  " << soak::ToString(out.reference.kind) << ": "
                << (out.reference.decided
                        ? (out.reference.feasible ? std::to_string(out.reference.objective)
                                                  : std::string("infeasible"))
                        : std::string("undecided (") + out.reference.detail + ")")
                << "; search: " << thrustsched::milp::ToString(out.status) << "; "
                << std::chrono::duration<double>(std::chrono::steady_clock::now() - tc).count()
                << " s" << std::endl;
    }
    ++counts[soak::ToString(out.reference.kind)];
    if (out.undecided) ++undecided;
    if (out.reference_refuted) {
      ++refuted;
      std::cout << "REFERENCE REFUTED " << c.description << "\n  " << out.refutation << std::endl;
    }
    if (!out.reference.feasible && out.reference.decided) ++counts["infeasible"];
    if (!out.agree) {
      ++disagreements;
      std::cout << "DISAGREEMENT " << c.description << "\n  " << out.disagreement << std::endl;
    }
    if ((k + 1) % 500 == 0) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::cout << "progress: " << (k + 1) << " cases, " << disagreements << " disagreements, " << s
                << " s" << std::endl;
    }
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "soak: " << run << " cases (seeds " << first << ".." << first + run - 1
            << ", horizons up to " << max_slots << " slots): " << counts["enumeration"]
            << " against enumeration, " << counts["plain CBC"] << " against plain CBC ("
            << undecided << " undecided, not compared; " << refuted
            << " of its optima refuted by the search's feasible point), " << counts["infeasible"]
            << " infeasible; " << disagreements << " disagreements; " << s << " s" << std::endl;
  return disagreements == 0 ? 0 : 1;
}
