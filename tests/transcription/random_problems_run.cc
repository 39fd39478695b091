// One random case solved by the search and compared with its reference
// (random_problems.h: RunCase, PlainCbcOptimum).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "tests/transcription/random_problems.h"
#include "transcription/schedule_milp.h"
#include "transcription/solve.h"

namespace thrustsched::transcription::soak {
namespace {

// Exact answers: gap 0, one thread (deterministic). The time limit is only a
// guard against a hang: wall-clock, so it must be far above what these sizes
// take even at nice 19 on a shared machine, where a case of 6.8 s alone (seed
// 29903) passed 120 s and was reported as a disagreement.
SolveScheduleOptions ExactOptions(bool search) {
  SolveScheduleOptions o;
  o.search.enabled = search;
  o.milp.relative_gap = 0.0;
  o.milp.absolute_gap = 0.0;
  o.milp.threads = 1;
  o.milp.time_limit_s = 1800.0;
  return o;
}

std::string G(double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.10g", v);
  return buf;
}

// The checker's verdict on a returned schedule: empty when it passes.
std::string CheckerFindings(const ScheduleProblem& p, const ScheduleResult& r) {
  if (!r.checked) return "the schedule was not checked";
  std::string out;
  if (!r.check.operational_ok) out += "rules broken: " + r.check.Summary() + "; ";
  if (!r.check.terminal_ok) out += "terminal box missed by " + G(r.check.terminal_error) + "; ";
  if (!p.window.soft) {
    const double width =
        *std::max_element(p.window.half_widths.begin(), p.window.half_widths.end());
    if (r.check.max_window_violation_at_nodes > 1e-6 * width) {
      out += "window left at the nodes by " + G(r.check.max_window_violation_at_nodes) + " m; ";
    }
  }
  return out;
}

// A plain-CBC optimum above the search's objective is refuted when the
// search's point is feasible in the same MILP (rows and bounds to 1e-9,
// integers integral) and its schedule passes the checker.
bool RefutesTheReference(const ScheduleProblem& p, const ScheduleResult& r, const Reference& ref) {
  if (ref.kind != ReferenceKind::kPlainCbc || !ref.decided || !ref.feasible) return false;
  if (r.solve.status != milp::SolveStatus::kOptimal &&
      r.solve.status != milp::SolveStatus::kFeasible)
    return false;
  if (!(r.solve.objective < ref.objective - (1e-7 + 1e-6 * std::abs(ref.objective)))) return false;
  if (!CheckerFindings(p, r).empty()) return false;
  const ScheduleMilp milp(p, ExactOptions(true).build);
  const milp::LpData& lp = milp.lp();
  // Rows, bounds and integrality (MaxViolation covers all three).
  if (r.solve.x.size() != lp.num_cols() || !(lp.MaxViolation(r.solve.x) <= 1e-9)) return false;
  return std::abs(lp.Objective(r.solve.x) - r.solve.objective) <=
         1e-9 + 1e-9 * std::abs(r.solve.objective);
}

}  // namespace

Reference PlainCbcOptimum(const ScheduleProblem& p, const milp::Solver& solver) {
  // CBC's preprocessing off: with it, CBC 2.10 called a schedule of cost
  // 0.04484 optimal at its root where the empty schedule (cost 0) is
  // feasible (seed 1342; docs/results.md, "Random problems").
  SolveScheduleOptions o = ExactOptions(false);
  o.milp.presolve = false;
  const ScheduleResult r = SolveSchedule(p, solver, o);
  Reference ref;
  ref.kind = ReferenceKind::kPlainCbc;
  ref.decided = r.solve.status == milp::SolveStatus::kOptimal ||
                r.solve.status == milp::SolveStatus::kInfeasible;
  ref.feasible = r.solve.status == milp::SolveStatus::kOptimal;
  ref.objective = ref.feasible ? r.solve.objective : std::numeric_limits<double>::infinity();
  ref.detail = std::string(milp::ToString(r.solve.status)) + ": " + r.solve.detail;
  return ref;
}

CaseOutcome RunCase(const RandomCase& c, const milp::Solver& solver) {
  CaseOutcome out;
  const ScheduleProblem& p = c.problem;
  out.reference = c.enumerable ? EnumerateOptimum(p) : PlainCbcOptimum(p, solver);
  const ScheduleResult r = SolveSchedule(p, solver, ExactOptions(true));
  out.status = r.solve.status;
  out.objective = r.solve.objective;
  std::string why;
  if (r.has_schedule()) why += CheckerFindings(p, r);
  const Reference& ref = out.reference;
  out.undecided = !ref.decided;
  if (ref.decided && ref.feasible) {
    const double tol = 1e-7 + 1e-6 * std::abs(ref.objective);
    if (r.solve.status != milp::SolveStatus::kOptimal) {
      why += "the search says " + std::string(milp::ToString(r.solve.status)) + " (" +
             r.solve.detail + "), the " + ToString(ref.kind) + " optimum is " + G(ref.objective) +
             "; ";
    } else if (!(std::abs(r.solve.objective - ref.objective) <= tol)) {
      why += "objective " + G(r.solve.objective) + ", the " + ToString(ref.kind) + " optimum is " +
             G(ref.objective) + "; ";
    }
  } else if (ref.decided) {
    if (r.solve.status != milp::SolveStatus::kInfeasible) {
      why += "the search says " + std::string(milp::ToString(r.solve.status)) +
             (r.has_schedule() ? " with objective " + G(r.solve.objective) : "") + ", the " +
             ToString(ref.kind) + " says infeasible; ";
    } else if (r.solve.detail.empty() && r.infeasibility_reasons.empty()) {
      why += "infeasible without a reason; ";
    }
  }
  out.agree = why.empty();
  if (!out.agree && RefutesTheReference(p, r, ref)) {
    out.reference_refuted = true;
    out.refutation = "the search's " + G(r.solve.objective) +
                     " keeps every row of the MILP "
                     "and passes the checker; plain CBC called " +
                     G(ref.objective) + " optimal";
    out.agree = true;
    return out;
  }
  if (!out.agree && ref.kind == ReferenceKind::kPlainCbc &&
      PatternSpaceSize(p, kMaxThirdOpinionLeaves) <= kMaxThirdOpinionLeaves) {
    const Reference e = EnumerateOptimum(p);
    why += "third opinion, the enumeration (" + std::to_string(e.leaves) +
           " leaves): " + (e.feasible ? G(e.objective) : std::string("infeasible")) + "; ";
  }
  out.disagreement = why;
  return out;
}

}  // namespace thrustsched::transcription::soak
