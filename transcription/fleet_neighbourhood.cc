// Member-by-member repair near the members' own plans (transcription/fleet_neighbourhood.h).
#include "transcription/fleet_neighbourhood.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace thrustsched::transcription {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxRounds = 20;  // of row generation per member

// Intervals within `radius` of an interval where member k fires any thruster.
std::vector<bool> NearBurns(const FleetMilp& milp, const Eigen::VectorXd& plans, int k,
                            int radius) {
  const ScheduleMilp& m = milp.member(k);
  const int intervals = m.problem().num_intervals();
  const int thrusters = m.problem().thrusters.size();
  std::vector<bool> near(intervals, false);
  for (int j = 0; j < intervals; ++j) {
    bool fires = false;
    for (int i = 0; i < thrusters && !fires; ++i)
      fires = plans[milp.column_offset(k) + m.on(i, j).index()] > 0.5;
    if (!fires) continue;
    for (int q = std::max(0, j - radius); q <= std::min(intervals - 1, j + radius); ++q)
      near[q] = true;
  }
  return near;
}

// Largest violation of `rows` at the row activities.
double RowsViolation(const milp::LpData& lp, const std::vector<int>& rows,
                     const Eigen::VectorXd& activity) {
  double worst = 0.0;
  for (int r : rows) {
    worst = std::max(worst, lp.row_lower[r] - activity[r]);
    worst = std::max(worst, activity[r] - lp.row_upper[r]);
  }
  return worst;
}

// Keep-out rows per check: [check q][row].
using CheckRows = std::vector<std::vector<int>>;
// Every pair's, [a][b] for a < b, read once from the fleet MILP.
using PairRows = std::vector<std::vector<CheckRows>>;

PairRows AllKeepOutRows(const FleetMilp& milp) {
  const int count = milp.num_members();
  PairRows out(count, std::vector<CheckRows>(count));
  for (int a = 0; a < count; ++a)
    for (int b = a + 1; b < count; ++b) out[a][b] = milp.KeepOutRows(a, b);
  return out;
}

// Adds to `active` every check (l, q) whose rows x breaks, with its
// neighbours within kCheckNeighbours (the violation moves as the plan does);
// returns how many were added.
constexpr int kCheckNeighbours = 2;
// rows[l][k] for l < k: member k's checks against its predecessors.
int ActivateBroken(const milp::LpData& lp, const PairRows& rows, int k, const Eigen::VectorXd& x,
                   std::vector<std::vector<bool>>* active) {
  const Eigen::VectorXd activity = lp.a_matrix * x;
  int added = 0;
  for (int l = 0; l < k; ++l) {
    const int checks = static_cast<int>(rows[l][k].size());
    for (int q = 0; q < checks; ++q) {
      if (RowsViolation(lp, rows[l][k][q], activity) <= kStartFeasibility) continue;
      for (int p = std::max(0, q - kCheckNeighbours);
           p <= std::min(checks - 1, q + kCheckNeighbours); ++p) {
        if (!(*active)[l][p]) (*active)[l][p] = true, ++added;
      }
    }
  }
  return added;
}

// The fleet LP for re-planning member k: every other member fixed at x, k's
// on-off binaries fixed to 0 away from its burns, and only the active
// keep-out checks against its predecessors kept (every other keep-out row
// relaxed: row generation, the checks found broken added round by round).
milp::LpData StepLp(const FleetMilp& milp, const Eigen::VectorXd& x, int k,
                    const std::vector<bool>& near, const PairRows& rows,
                    const std::vector<std::vector<bool>>& active, FleetNeighbourhood* out) {
  milp::LpData lp = milp.lp();
  const int count = milp.num_members();
  for (int l = 0; l < count; ++l) {
    if (l == k) continue;
    const int first = milp.column_offset(l);
    for (int c = first; c < first + milp.member(l).lp().num_cols(); ++c)
      lp.col_lower[c] = lp.col_upper[c] = x[c];
  }
  const ScheduleMilp& m = milp.member(k);
  for (int i = 0; i < m.problem().thrusters.size(); ++i) {
    for (int j = 0; j < m.problem().num_intervals(); ++j) {
      const int c = milp.column_offset(k) + m.on(i, j).index();
      if (near[j]) {
        ++out->free_binaries;
      } else {
        lp.col_upper[c] = std::min(lp.col_upper[c], 0.0);
        ++out->fixed_binaries;
      }
    }
  }
  const auto relax = [&](const std::vector<int>& r) {
    for (int row : r) lp.row_lower[row] = -kInf, lp.row_upper[row] = kInf;
  };
  for (int a = 0; a < count; ++a) {
    for (int b = a + 1; b < count; ++b) {
      if (b == k) continue;
      for (const std::vector<int>& r : rows[a][b]) relax(r);
    }
  }
  for (int l = 0; l < k; ++l) {
    for (size_t q = 0; q < rows[l][k].size(); ++q)
      if (!active[l][q]) relax(rows[l][k][q]);
  }
  return lp;
}

double Seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

FleetNeighbourhood RepairMemberByMember(const FleetMilp& milp, const Eigen::VectorXd& plans,
                                        const milp::Solver& solver,
                                        const milp::SolveOptions& options, int radius_intervals) {
  const milp::LpData& whole = milp.lp();
  if (plans.size() != whole.num_cols()) {
    throw std::invalid_argument("RepairMemberByMember: plans has " + std::to_string(plans.size()) +
                                " entries for " + std::to_string(whole.num_cols()) + " columns");
  }
  if (radius_intervals < 0) {
    throw std::invalid_argument("RepairMemberByMember: radius_intervals " +
                                std::to_string(radius_intervals) + " < 0");
  }
  const auto start = std::chrono::steady_clock::now();
  FleetNeighbourhood out;
  out.radius_intervals = radius_intervals;
  Eigen::VectorXd x = plans;
  const PairRows rows = AllKeepOutRows(milp);
  for (int k = 1; k < milp.num_members(); ++k) {
    std::vector<std::vector<bool>> active;
    for (int l = 0; l < k; ++l) active.emplace_back(rows[l][k].size(), false);
    if (ActivateBroken(whole, rows, k, x, &active) == 0) continue;
    ++out.members_replanned;
    const std::vector<bool> near = NearBurns(milp, x, k, radius_intervals);
    const double step_limit =
        std::isfinite(options.time_limit_s)
            ? std::max(options.time_limit_s - Seconds(start), 1e-3) / (milp.num_members() - k)
            : kInf;
    const auto step_start = std::chrono::steady_clock::now();
    bool kept = false;
    for (int round = 0; round < kMaxRounds && !kept; ++round) {
      milp::SolveOptions step = options;
      step.initial_solution.reset();
      step.time_limit_s = std::max(step_limit - Seconds(step_start), 1e-3);
      const milp::SolveResult r = solver.Solve(StepLp(milp, x, k, near, rows, active, &out), step);
      out.status = r.status;
      ++out.rounds;
      if (!r.has_solution()) {
        out.note = "member '" + milp.fleet().members[k].name +
                   "' has no plan near its own burns (" + std::string(milp::ToString(r.status)) +
                   ")";
        out.seconds = Seconds(start);
        return out;
      }
      kept = ActivateBroken(whole, rows, k, r.x, &active) == 0;
      if (kept) x = r.x;
    }
    if (!kept) {
      out.note = "member '" + milp.fleet().members[k].name +
                 "' still breaks a keep-out check after " + std::to_string(kMaxRounds) + " rounds";
      out.seconds = Seconds(start);
      return out;
    }
  }
  out.seconds = Seconds(start);
  out.found = KeepsFleetRows(milp, x, &out.objective);
  if (out.found) {
    out.x = x;
  } else {
    out.note = "the repaired plan breaks a fleet row (the balance)";
  }
  return out;
}

}  // namespace thrustsched::transcription
