// Members re-planned in turn by the search against the fixed plans of those
// before them (transcription/fleet_in_turn.h).
#include "transcription/fleet_in_turn.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "transcription/fleet_start.h"
#include "transcription/internal/fleet_reach.h"

namespace thrustsched::transcription {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxSearches = 20;     // per member (row generation)
constexpr int kCheckNeighbours = 2;  // checks added on each side of a broken one
constexpr int kFaceRanks = 3;        // face choices tried when the chosen faces are infeasible
// Added to each face's right-hand side (metres): the member's MILP and the
// fleet MILP write the same positions through maps computed apart, equal to
// rounding; a millimetre keeps a plan that holds in one holding in the other.
constexpr double kFaceAllowanceM = 1e-3;

double Seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Slack of face f of the check between members l < k: s (r_l - r_k)[f / 2] - rhs[f].
double FaceSlack(const Eigen::Vector3d& r_l, const Eigen::Vector3d& r_k,
                 const Eigen::Matrix<double, 6, 1>& rhs, int f) {
  const double s = f % 2 == 0 ? 1.0 : -1.0;
  return s * (r_l - r_k)[f / 2] - rhs[f];
}

// The positions of every member at the checks, as the fleet MILP writes them.
class Positions {
 public:
  Positions(const FleetMilp& milp, const std::vector<double>& times) : milp_(milp) {
    for (int k = 0; k < milp.num_members(); ++k)
      reach_.emplace_back(milp.member(k), FleetPositionMaps(milp.fleet(), k, times), times,
                          milp.member(k).options());
    at_.resize(milp.num_members());
  }
  void Update(int k, const Eigen::VectorXd& x) {
    at_[k].clear();
    for (size_t q = 0; q < milp_.fleet().keep_out->check_times_s.size(); ++q)
      at_[k].push_back(reach_[k].Position(static_cast<int>(q), milp_.column_offset(k), x));
  }
  const Eigen::Vector3d& at(int k, int q) const { return at_[k][q]; }

 private:
  const FleetMilp& milp_;
  std::vector<internal::MemberReach> reach_;
  std::vector<std::vector<Eigen::Vector3d>> at_;
};

// A check of member k against member l < k at check q, and the face it keeps.
using Check = std::pair<int, int>;  // (l, q)

// Adds to `faces` every check of member k against those before it that its
// current positions break, with `pad` checks on each side; returns how many
// were added. Broken checks come in runs (one encounter: consecutive checks,
// gaps of at most 2 kCheckNeighbours), and a run keeps one face throughout:
// the face already chosen for a check near it in an earlier round, else the
// face whose least slack over the run is the largest (the rank-th best for
// rank > 0). One face per check, chosen check by check, would flip as the
// separation passes through zero along one axis (north at a node crossing)
// and ask for 10 km in 10 minutes. The plan alone's broken checks get no
// padding (a restriction beyond them costs fuel: the plan would have to
// clear the cube earlier and longer than it needs); those a new plan breaks
// get kCheckNeighbours (the encounter moved with the plan).
int AddBroken(const FleetMilp& milp, const Positions& pos, int k, int rank, int pad,
              std::map<Check, int>* faces) {
  const int checks = static_cast<int>(milp.fleet().keep_out->check_times_s.size());
  const auto slack = [&](int l, int q, int f) {
    return FaceSlack(pos.at(l, q), pos.at(k, q), milp.KeepOutFaceRhs(l, k, q), f);
  };
  int added = 0;
  for (int l = 0; l < k; ++l) {
    std::vector<int> broken;
    for (int q = 0; q < checks; ++q) {
      double best = -kInf;
      for (int f = 0; f < 6; ++f) best = std::max(best, slack(l, q, f));
      if (best < 0.0) broken.push_back(q);
    }
    for (size_t b = 0; b < broken.size();) {
      size_t e = b;
      while (e + 1 < broken.size() && broken[e + 1] - broken[e] <= 2 * kCheckNeighbours) ++e;
      const int first = std::max(0, broken[b] - kCheckNeighbours);
      const int last = std::min(checks - 1, broken[e] + kCheckNeighbours);
      int face = -1;  // a face chosen before, within the neighbours of the run
      for (int q = first; q <= last && face < 0; ++q) {
        const auto it = faces->find(Check{l, q});
        if (it != faces->end()) face = it->second;
      }
      if (face < 0) {
        std::vector<std::pair<double, int>> least;  // (least slack over the run, face)
        for (int f = 0; f < 6; ++f) {
          double v = kInf;
          for (size_t i = b; i <= e; ++i) v = std::min(v, slack(l, broken[i], f));
          least.emplace_back(v, f);
        }
        std::sort(least.rbegin(), least.rend());
        face = least[std::min<size_t>(static_cast<size_t>(rank), least.size() - 1)].second;
      }
      for (int q = std::max(0, broken[b] - pad); q <= std::min(checks - 1, broken[e] + pad); ++q)
        if (faces->emplace(Check{l, q}, face).second) ++added;
      b = e + 1;
    }
  }
  return added;
}

// Member k's problem with one path constraint per chosen face:
// s (P_k x_k(t))[f / 2] <= s r_l[f / 2] - rhs[f] (- the allowance).
ScheduleProblem ProblemAgainstFixed(const FleetMilp& milp, const ScheduleProblem& alone,
                                    const Positions& pos, int k,
                                    const std::map<Check, int>& faces) {
  ScheduleProblem p = alone;
  const std::vector<double>& times = milp.fleet().keep_out->check_times_s;
  for (const auto& [check, f] : faces) {
    const auto [l, q] = check;
    const double s = f % 2 == 0 ? 1.0 : -1.0;
    const Eigen::MatrixXd map = FleetPositionMap(milp.fleet(), k, times[q]);
    StateConstraint c;
    c.t_s = times[q];
    c.a = s * map.row(f / 2).transpose();
    c.upper = s * pos.at(l, q)[f / 2] - milp.KeepOutFaceRhs(l, k, q)[f] - kFaceAllowanceM;
    c.name = "keep_out_" + milp.fleet().members[l].name + "_" + std::to_string(q) + "_" +
             std::to_string(f);
    p.state_constraints.push_back(std::move(c));
  }
  return p;
}

Eigen::MatrixXi PatternOf(const FleetMilp& milp, const Eigen::VectorXd& x, int k) {
  return milp.member(k).encoding().OnPattern(milp.MemberColumns(x, k));
}

// Member k re-planned against the fixed positions of those before it, each
// run of broken checks on its rank-th face, by row generation (at most
// kMaxSearches searches); the plan's pattern, or none with the reason.
struct Replan {
  bool found = false;
  Eigen::MatrixXi pattern;
  double objective = kInf;
  int searches = 0;
  int faces = 0;
  std::string note;
};

Replan ReplanAgainstFixed(const FleetMilp& milp, const ScheduleProblem& alone, Positions* pos,
                          int k, int rank, Eigen::VectorXd* x, const milp::Solver& solver,
                          const SolveScheduleOptions& options) {
  Replan out;
  std::map<Check, int> faces;
  AddBroken(milp, *pos, k, rank, 0, &faces);
  for (; out.searches < kMaxSearches;) {
    const ScheduleMilp m(ProblemAgainstFixed(milp, alone, *pos, k, faces),
                         milp.member(k).discrete(), milp.member(k).options());
    const ScheduleResult r = SolveBuilt(m, solver, options);
    ++out.searches;
    out.faces = static_cast<int>(faces.size());
    if (!r.solve.has_solution()) {
      out.note = "no plan keeping the chosen faces of " + std::to_string(faces.size()) +
                 " checks (" + std::string(milp::ToString(r.solve.status)) + ")";
      return out;
    }
    out.pattern = m.encoding().OnPattern(r.solve.x);
    out.objective = r.solve.objective;
    x->segment(milp.column_offset(k), milp.member(k).lp().num_cols()) =
        milp.member(k).StartFromPattern(out.pattern);
    pos->Update(k, *x);
    if (AddBroken(milp, *pos, k, rank, kCheckNeighbours, &faces) == 0) {
      out.found = true;
      return out;
    }
  }
  out.note = "still breaks a keep-out check after " + std::to_string(kMaxSearches) + " searches";
  return out;
}

}  // namespace

FleetInTurn PlanMembersInTurn(const FleetMilp& milp, const Eigen::VectorXd& plans,
                              const std::vector<int>& slots, const milp::Solver& solver,
                              const SolveScheduleOptions& member_options) {
  const milp::LpData& whole = milp.lp();
  if (plans.size() != whole.num_cols()) {
    throw std::invalid_argument("PlanMembersInTurn: plans has " + std::to_string(plans.size()) +
                                " entries for " + std::to_string(whole.num_cols()) + " columns");
  }
  if (!milp.fleet().keep_out) throw std::invalid_argument("PlanMembersInTurn: no keep-out");
  const auto start = std::chrono::steady_clock::now();
  const int count = milp.num_members();
  FleetInTurn out;
  const std::vector<ScheduleProblem> alone = MemberProblemsAlone(milp.fleet(), slots, &out.note);
  if (alone.empty()) {
    out.note = "not decoupled: " + out.note;
    return out;
  }
  Eigen::VectorXd x = plans;
  std::vector<Eigen::MatrixXi> patterns;
  for (int k = 0; k < count; ++k) patterns.push_back(PatternOf(milp, x, k));
  Positions pos(milp, milp.fleet().keep_out->check_times_s);
  for (int k = 0; k < count; ++k) pos.Update(k, x);
  const double limit = member_options.milp.time_limit_s;
  for (int k = 1; k < count; ++k) {
    std::map<Check, int> broken;
    if (AddBroken(milp, pos, k, 0, 0, &broken) == 0) continue;
    ++out.members_replanned;
    const Eigen::VectorXd plan_alone =
        x.segment(milp.column_offset(k), milp.member(k).lp().num_cols());
    // The faces of rank 0 from the plan alone, the next rank where they
    // cannot all be kept: the first rank that can, not the cheapest of all
    // (docs/fleet.md, the co-located week).
    Replan best;
    std::string why;
    for (int rank = 0; rank < kFaceRanks; ++rank) {
      if (member_options.announce) {
        member_options.announce("start: member '" + milp.fleet().members[k].name + "' breaks " +
                                std::to_string(broken.size()) +
                                " keep-out checks: re-planned by the search against the fixed "
                                "plans before it (faces of rank " +
                                std::to_string(rank) + ")");
      }
      SolveScheduleOptions o = member_options;
      o.announce = nullptr;
      o.check_schedule = false;
      o.prefix_diagnosis_s = 0.0;
      o.warm_start.clear();
      if (std::isfinite(limit))
        o.milp.time_limit_s =
            std::max(limit - Seconds(start), 1e-3) / ((count - k) * (kFaceRanks - rank));
      x.segment(milp.column_offset(k), plan_alone.size()) = plan_alone;
      pos.Update(k, x);
      const Replan r = ReplanAgainstFixed(milp, alone[k], &pos, k, rank, &x, solver, o);
      out.searches += r.searches;
      if (r.found) {
        best = r;
        break;
      }
      why += (why.empty() ? "" : "; ") + ("faces of rank " + std::to_string(rank) + ": " + r.note);
      if (member_options.milp.interrupt != nullptr && member_options.milp.interrupt->load()) break;
    }
    if (!best.found) {
      out.note = "member '" + milp.fleet().members[k].name + "': " + why;
      out.seconds = Seconds(start);
      return out;
    }
    out.constraints += best.faces;
    patterns[k] = best.pattern;
    x.segment(milp.column_offset(k), plan_alone.size()) =
        milp.member(k).StartFromPattern(patterns[k]);
    pos.Update(k, x);
  }
  x = milp.StartFromPatterns(patterns, slots);
  out.seconds = Seconds(start);
  out.found = KeepsFleetRows(milp, x, &out.objective);
  if (out.found) {
    out.x = x;
  } else {
    out.note = "the plans in turn break a fleet row (the balance or a coupling)";
  }
  return out;
}

}  // namespace thrustsched::transcription
