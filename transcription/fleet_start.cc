// The decoupled first incumbent of a fleet (transcription/fleet_start.h).
#include "transcription/fleet_start.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>

namespace thrustsched::transcription {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr size_t kMaxEnumeratedMembers = 8;  // 8! = 40320 permutations
constexpr size_t kMaxStartTries = 24;        // assignments tried for a start the fleet keeps

// Index of the state component a map row selects (one entry 1, the others 0), or -1.
int SelectedComponent(const Eigen::RowVectorXd& row) {
  int at = -1;
  for (int i = 0; i < row.size(); ++i) {
    if (row[i] == 0.0) continue;
    if (row[i] != 1.0 || at >= 0) return -1;
    at = i;
  }
  return at;
}

// Narrows `box` (a kStateBox or kFixedState terminal, or kFree) by map x = offset +- tol;
// false if the map is not a selection of components or the terminal is the
// station-keeping sets (not a box).
bool Narrow(const Eigen::MatrixXd& map, const Eigen::VectorXd& offset,
            const Eigen::VectorXd& tolerance, TerminalSpec* box) {
  const int n = static_cast<int>(map.cols());
  if (box->kind == TerminalKind::kStationKeepingSets) return false;  // not a box
  if (box->kind == TerminalKind::kFixedState) {                      // a box of zero width
    box->kind = TerminalKind::kStateBox;
    box->tolerance = Eigen::VectorXd::Zero(n);
  }
  if (box->kind == TerminalKind::kFree) {
    box->kind = TerminalKind::kStateBox;
    box->target = Eigen::VectorXd::Zero(n);
    box->tolerance = Eigen::VectorXd::Constant(n, kInf);
  }
  for (int r = 0; r < map.rows(); ++r) {
    const int i = SelectedComponent(map.row(r));
    if (i < 0) return false;
    const double tol = tolerance.size() == 0 ? 0.0 : tolerance[r];
    double lo = offset[r] - tol, hi = offset[r] + tol;
    if (std::isfinite(box->tolerance[i])) {
      lo = std::max(lo, box->target[i] - box->tolerance[i]);
      hi = std::min(hi, box->target[i] + box->tolerance[i]);
    }
    if (lo > hi) hi = lo;  // an empty box: the member alone is infeasible
    box->target[i] = 0.5 * (lo + hi);
    box->tolerance[i] = 0.5 * (hi - lo);
  }
  return true;
}

struct Alone {
  double objective = kInf;
  double bound = -kInf;  // the solve's proven bound (+inf: proven infeasible)
  Eigen::MatrixXi pattern;
};

Alone SolveAlone(const ScheduleProblem& problem, const milp::Solver& solver,
                 const SolveScheduleOptions& options) {
  const ScheduleResult r = SolveSchedule(problem, solver, options);
  Alone a;
  if (r.solve.status == milp::SolveStatus::kInfeasible) a.bound = kInf;
  if (std::isfinite(r.solve.best_bound)) a.bound = r.solve.best_bound;
  if (!r.has_schedule()) return a;
  a.objective = r.solve.objective;
  a.pattern = r.schedule.pattern;
  return a;
}

// The fleet objective of member objectives J_k (FleetMilp's objective with
// its balance: the sum, or max_k J_k + w sum_k J_k).
double FleetObjective(const FuelBalance& balance, const std::vector<double>& j) {
  double sum = 0.0, most = -kInf;
  for (double v : j) sum += v, most = std::max(most, v);
  if (balance.kind == FuelBalanceKind::kMinMax) return most + balance.sum_weight * sum;
  return sum;
}

// Member objectives (or bounds) per fleet member, with the assigned ones
// taken from value[i][slots[i]].
std::vector<double> PerMember(const std::vector<double>& fixed, const SlotAssignment* a,
                              const std::vector<std::vector<double>>& value,
                              const std::vector<int>& slots) {
  std::vector<double> out = fixed;
  if (a != nullptr)
    for (size_t i = 0; i < slots.size(); ++i) out[a->members[i]] = value[i][slots[i]];
  return out;
}

// The assignments in order of fleet objective (all permutations up to
// kMaxEnumeratedMembers; beyond, one: each member its cheapest free slot) and
// the least fleet objective of the bounds over every assignment (beyond the
// enumeration: each member its least bound over all slots, weaker but valid).
struct Choice {
  std::vector<std::vector<int>> ordered;  // cheapest first, infeasible ones left out
  double bound = -kInf;
};

Choice ChooseSlots(const FuelBalance& balance, const std::vector<double>& fixed_cost,
                   const std::vector<double>& fixed_bound, const SlotAssignment& a,
                   const std::vector<std::vector<double>>& cost,
                   const std::vector<std::vector<double>>& bound) {
  const size_t count = cost.size();
  Choice out;
  std::vector<int> perm(count);
  std::iota(perm.begin(), perm.end(), 0);
  if (count <= kMaxEnumeratedMembers) {
    std::vector<std::pair<double, std::vector<int>>> all;
    out.bound = kInf;
    do {
      const double c = FleetObjective(balance, PerMember(fixed_cost, &a, cost, perm));
      if (std::isfinite(c)) all.emplace_back(c, perm);
      out.bound =
          std::min(out.bound, FleetObjective(balance, PerMember(fixed_bound, &a, bound, perm)));
    } while (std::next_permutation(perm.begin(), perm.end()));
    std::stable_sort(all.begin(), all.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    for (auto& [c, p] : all) out.ordered.push_back(std::move(p));
    return out;
  }
  std::vector<bool> used(count, false);
  std::vector<double> least(fixed_bound);
  std::vector<int> greedy;
  for (size_t i = 0; i < count; ++i) {
    int pick = -1;
    for (size_t s = 0; s < count; ++s) {
      if (!used[s] && (pick < 0 || cost[i][s] < cost[i][pick])) pick = static_cast<int>(s);
    }
    used[pick] = true;
    greedy.push_back(pick);
    least[a.members[i]] = *std::min_element(bound[i].begin(), bound[i].end());
  }
  out.ordered.push_back(greedy);
  out.bound = FleetObjective(balance, least);
  return out;
}

// The members' own problems with their absolute couplings as terminal boxes;
// empty with `*why` set if the fleet cannot be decoupled.
std::vector<ScheduleProblem> AloneProblems(const FleetProblem& fleet, std::string* why) {
  std::vector<ScheduleProblem> out;
  for (const FleetMember& m : fleet.members) out.push_back(m.problem);
  for (const TerminalCoupling& c : fleet.couplings) {
    if (c.reference >= 0) {
      *why = "a coupling is relative to another member";
      return {};
    }
    if (!Narrow(c.map, c.offset, c.tolerance, &out[c.member].terminal)) {
      *why =
          "a coupling map is not a selection of state components, or its member's terminal "
          "set is not a box (station-keeping sets)";
      return {};
    }
  }
  if (fleet.assignment && fleet.assignment->reference >= 0) {
    *why = "the assignment is relative to another member";
    return {};
  }
  return out;
}

// Every assigned member for every slot, solved alone.
struct SlotPlans {
  std::vector<std::vector<double>> cost, lower;  // [member i][slot s]
  std::vector<std::vector<Alone>> plans;
};

bool SolveEverySlot(const SlotAssignment& a, const std::vector<ScheduleProblem>& problems,
                    const milp::Solver& solver, const SolveScheduleOptions& options, SlotPlans* out,
                    FleetStart* start) {
  const size_t slots = a.members.size();
  out->cost.assign(slots, std::vector<double>(slots, kInf));
  out->lower.assign(slots, std::vector<double>(slots, -kInf));
  out->plans.assign(slots, std::vector<Alone>(slots));
  for (size_t i = 0; i < slots; ++i) {
    for (size_t s = 0; s < slots; ++s) {
      ScheduleProblem p = problems[a.members[i]];
      if (!Narrow(a.map, a.slots[s], a.tolerance, &p.terminal)) {
        start->note =
            "the assignment map is not a selection of state components, or a member's "
            "terminal set is not a box (station-keeping sets)";
        return false;
      }
      out->plans[i][s] = SolveAlone(p, solver, options);
      ++start->member_solves;
      out->cost[i][s] = out->plans[i][s].objective;
      out->lower[i][s] = out->plans[i][s].bound;
    }
  }
  return true;
}

// The cheapest assignment whose members alone keep the fleet's rows (the
// keep-out above all), or the cheapest one if none of the first
// kMaxStartTries does; *tries: how many were tried until one did (0: none).
std::vector<int> PickAssignment(const FleetMilp& milp, const std::vector<Alone>& alone,
                                const SlotPlans& p, const Choice& choice, int* tries) {
  const SlotAssignment& a = *milp.fleet().assignment;
  std::vector<int> slot_of(alone.size(), -1);  // index in a.members, per member
  for (size_t i = 0; i < a.members.size(); ++i) slot_of[a.members[i]] = static_cast<int>(i);
  for (size_t t = 0; t < choice.ordered.size() && t < kMaxStartTries; ++t) {
    std::vector<Eigen::MatrixXi> patterns;
    bool complete = true;
    for (size_t k = 0; k < alone.size(); ++k) {
      const int i = slot_of[k];
      const Alone& plan = i < 0 ? alone[k] : p.plans[i][choice.ordered[t][i]];
      complete = complete && std::isfinite(plan.objective);
      patterns.push_back(plan.pattern);
    }
    if (complete && milp.lp().MaxViolation(milp.StartFromPatterns(patterns, choice.ordered[t])) <=
                        kStartFeasibility) {
      *tries = static_cast<int>(t) + 1;
      return choice.ordered[t];
    }
  }
  return choice.ordered.empty() ? std::vector<int>() : choice.ordered[0];
}

// The fleet start from every member's plan alone (out->note set if one has none).
void Assemble(const FleetMilp& milp, const std::vector<Alone>& alone, FleetStart* out) {
  const FleetProblem& fleet = milp.fleet();
  std::vector<Eigen::MatrixXi> patterns;
  for (size_t k = 0; k < alone.size(); ++k) {
    if (!std::isfinite(alone[k].objective)) {
      out->note = "member '" + fleet.members[k].name + "' alone has no schedule";
      return;
    }
    patterns.push_back(alone[k].pattern);
    out->member_objectives.push_back(alone[k].objective);
  }
  out->x = milp.StartFromPatterns(patterns, out->slots);
  out->accepted = milp.lp().MaxViolation(out->x) <= kStartFeasibility;
  out->objective = FleetObjective(fleet.balance, out->member_objectives);
  out->built = true;
  out->note = std::to_string(out->member_solves) + " member solves";
}

}  // namespace

std::vector<ScheduleProblem> MemberProblemsAlone(const FleetProblem& fleet,
                                                 const std::vector<int>& slots, std::string* why) {
  std::vector<ScheduleProblem> out = AloneProblems(fleet, why);
  if (out.empty() || !fleet.assignment) return out;
  const SlotAssignment& a = *fleet.assignment;
  if (slots.size() != a.members.size()) {
    *why = "no slot for every assigned member";
    return {};
  }
  for (size_t i = 0; i < slots.size(); ++i) {
    if (!Narrow(a.map, a.slots[slots[i]], a.tolerance, &out[a.members[i]].terminal)) {
      *why = "the assignment map is not a selection of state components";
      return {};
    }
  }
  return out;
}

FleetStart DecoupledStart(const FleetMilp& milp, const milp::Solver& solver,
                          const SolveScheduleOptions& member_options) {
  const auto start = std::chrono::steady_clock::now();
  const FleetProblem& fleet = milp.fleet();
  SolveScheduleOptions options = member_options;
  options.check_schedule = false;
  options.prefix_diagnosis_s = 0.0;
  FleetStart out;
  out.tried = true;
  const std::vector<ScheduleProblem> problems = AloneProblems(fleet, &out.note);
  const int count = static_cast<int>(fleet.members.size());
  std::vector<Alone> alone(count);
  std::vector<bool> assigned(count, false);
  if (fleet.assignment)
    for (int k : fleet.assignment->members) assigned[k] = true;
  for (int k = 0; k < count && !problems.empty(); ++k) {
    if (assigned[k]) continue;
    alone[k] = SolveAlone(problems[k], solver, options);
    ++out.member_solves;
  }
  std::vector<double> fixed_cost(count), fixed_bound(count);
  for (int k = 0; k < count; ++k)
    fixed_cost[k] = alone[k].objective, fixed_bound[k] = alone[k].bound;
  double bound = problems.empty() ? -kInf : FleetObjective(fleet.balance, fixed_bound);
  SlotPlans p;
  if (!problems.empty() && fleet.assignment &&
      SolveEverySlot(*fleet.assignment, problems, solver, options, &p, &out)) {
    const SlotAssignment& a = *fleet.assignment;
    const Choice choice = ChooseSlots(fleet.balance, fixed_cost, fixed_bound, a, p.cost, p.lower);
    bound = choice.bound;
    out.slots = PickAssignment(milp, alone, p, choice, &out.tries);
    for (size_t i = 0; i < out.slots.size(); ++i) alone[a.members[i]] = p.plans[i][out.slots[i]];
  }
  if (!problems.empty() && out.note.empty()) {
    out.bound = bound;
    Assemble(milp, alone, &out);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace thrustsched::transcription
