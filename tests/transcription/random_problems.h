// Test support: small random on-off scheduling problems and their exact
// optima, to soak the search (transcription/search.h) and the checker
// against references that share none of their code. Used by
// random_problems_test.cc (a few hundred seeds on every run) and by
// random_soak.cc (scripts/soak_random_problems.sh --soak N, long runs).
//
//   const RandomCase c = GenerateCase(42);           // deterministic in the seed
//   const CaseOutcome out = RunCase(c, *milp::MakeCbcSolver());
//   if (!out.agree) std::cout << c.description << ": " << out.disagreement << "\n";
//
// A case: an HCW (mean motion 2e-4 .. 1.2e-3 rad/s) or 3-D double-integrator
// model, 1-3 thrusters of random directions and thrust, a uniform or
// non-uniform grid of 6-40 slots, random operational rules (simultaneity,
// minimum burn and off times, maximum burn length and count, forced-off
// windows, burns across the end), a hard or soft window on x and y from a
// random node (margin, inter-sample points), an optional terminal box, an
// L1, delta-v or propellant objective with an optional burn-start penalty,
// and a random initial state; some are infeasible.
//
// The reference, named in Reference::kind:
//   kEnumeration  the case's pattern space (per-slot on-off combinations
//                 within max_simultaneous, over every slot) has at most
//                 kMaxEnumeratedLeaves leaves: a depth-first enumeration of
//                 every pattern, pruned only by the hard window at nodes and
//                 by cost (costs are >= 0), each leaf judged by the
//                 continuous-time rule checker (CheckOperationalRules) and
//                 propagated by an exact zero-order hold computed here (the
//                 exponential of the augmented matrix [A B d; 0 0 0], Eigen's
//                 MatrixFunctions; not dynamics::Discretize);
//   kPlainCbc     larger cases (up to 40 slots): CBC on the whole MILP with
//                 the search off (SearchOptions::enabled = false) and its
//                 preprocessing off (which once cut off an optimum), compared
//                 only when it proves optimality or infeasibility; a
//                 disagreement is also enumerated when its pattern space
//                 allows (kMaxThirdOpinionLeaves).
#ifndef THRUSTSCHED_TESTS_TRANSCRIPTION_RANDOM_PROBLEMS_H_
#define THRUSTSCHED_TESTS_TRANSCRIPTION_RANDOM_PROBLEMS_H_

#include <cstdint>
#include <limits>
#include <string>

#include "milp/solver.h"
#include "transcription/problem.h"

namespace thrustsched::transcription::soak {

/// Patterns a case may have to be enumerated (else the plain-CBC reference).
inline constexpr long long kMaxEnumeratedLeaves = 150000;

struct RandomCase {
  std::uint64_t seed = 0;
  std::string description;  // one line: model, thrusters, grid, rules, window, objective
  ScheduleProblem problem;
  bool enumerable = false;  // the reference is the enumeration (see above)
};

/// The longest horizon GenerateCase draws by default, and the shortest.
inline constexpr int kMaxSlots = 40;
inline constexpr int kMinSlots = 6;

/// The case of `seed` (std::mt19937_64; the same seed and max_slots give the
/// same case; max_slots, in [kMinSlots, kMaxSlots], caps the horizon of the
/// cases whose reference is plain CBC, and changes only that draw).
RandomCase GenerateCase(std::uint64_t seed, int max_slots = kMaxSlots);

enum class ReferenceKind { kEnumeration, kPlainCbc };
const char* ToString(ReferenceKind kind);

struct Reference {
  ReferenceKind kind = ReferenceKind::kEnumeration;
  bool decided = false;  // enumeration: always; CBC: proven optimal or infeasible
  bool feasible = false;
  double objective = std::numeric_limits<double>::infinity();  // minimum (model sense)
  long long leaves = 0;  // enumeration: complete patterns judged
  std::string detail;
};

/// A disagreement against plain CBC is also enumerated (a third opinion,
/// in CaseOutcome::disagreement) when its pattern space is at most this.
inline constexpr long long kMaxThirdOpinionLeaves = 5000000;

/// Number of leaves of the unpruned enumeration of `p` (saturates at
/// limit + 1).
long long PatternSpaceSize(const ScheduleProblem& p, long long limit = kMaxEnumeratedLeaves);
/// The exhaustive minimum over all on-off patterns (see the file's text).
Reference EnumerateOptimum(const ScheduleProblem& p);
/// CBC on the whole MILP, the search and CBC's preprocessing off, gap 0.
Reference PlainCbcOptimum(const ScheduleProblem& p, const milp::Solver& solver);

struct CaseOutcome {
  Reference reference;
  milp::SolveStatus status = milp::SolveStatus::kError;  // the search's
  double objective = std::numeric_limits<double>::quiet_NaN();
  bool agree = true;         // false: see disagreement
  std::string disagreement;  // empty when agree
  bool undecided = false;    // the plain-CBC reference did not decide (not compared)
  /// The plain-CBC reference claimed an optimum above the search's, and the
  /// search's point keeps every row of the same MILP (largest violation at
  /// most 1e-9) and passes the checker: CBC's claim is refuted, not counted
  /// as a disagreement (`refutation` says by how much).
  bool reference_refuted = false;
  std::string refutation;
};

/// Solves the case with the search (gap 0) and compares: the status and the
/// objective with the reference; an infeasible case reported infeasible with
/// a reason (the solver's detail or infeasibility_reasons); every returned
/// schedule passes the checker (rules, terminal, hard window at the nodes).
CaseOutcome RunCase(const RandomCase& c, const milp::Solver& solver);

}  // namespace thrustsched::transcription::soak

#endif  // THRUSTSCHED_TESTS_TRANSCRIPTION_RANDOM_PROBLEMS_H_
