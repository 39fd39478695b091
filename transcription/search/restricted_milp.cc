#include "transcription/search/restricted_milp.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "common/format.h"
#include "milp/lazy_rows.h"
#include "transcription/internal/build_time.h"
#include "transcription/search/search_report.h"

namespace thrustsched::transcription {

using common::FormatG;

namespace {

Restriction Restrict(SearchState& state, const Eigen::MatrixXi& mask) {
  const double t0 = state.Elapsed();
  BuildOptions bo = state.milp().options();
  bo.formulation = state.search().restricted.formulation;
  bo.free_slots = mask;
  Restriction r{ScheduleMilp(state.milp().problem(), state.milp().discrete(), bo), {}, {}, true};
  r.small = milp::RemoveFixedColumns(r.milp.lp(), &r.kept, &r.feasible);
  r.feasible = r.feasible && r.milp.infeasibility_reasons().empty();
  state.NoteBuilt(CountSlots(mask), state.Elapsed() - t0);
  return r;
}

// Appends the row  cost' x <= cutoff - offset.
void AddObjectiveCutoff(milp::LpData* lp, double cutoff) {
  milp::SparseRow row;
  for (int j = 0; j < lp->num_cols(); ++j) {
    if (lp->col_cost[j] == 0.0) continue;
    row.columns.push_back(j);
    row.coefficients.push_back(lp->col_cost[j]);
  }
  row.upper = cutoff - lp->objective_offset;
  row.name = "objective_cutoff";
  milp::AppendRows(lp, {row});
}

// By row generation over its dense (condensed window) rows unless disabled
// (milp/lazy_rows.h; exact, so proofs carry over).
milp::SolveResult SolveRestricted(SearchState& state, const milp::LpData& small,
                                  const milp::SolveOptions& o) {
  state.set_lazy_note("");
  const RestrictedMilpOptions& options = state.search().restricted;
  if (!options.lazy_rows) return state.solver().Solve(small, o);
  milp::LazyRowReport lazy;
  milp::SolveResult s =
      milp::SolveWithLazyRows(state.solver(), small, o, options.lazy_row_options, &lazy);
  if (lazy.used) {
    state.set_lazy_note(
        " (" + std::to_string(lazy.final_rows) + " of " + std::to_string(small.num_rows()) +
        " rows in " + std::to_string(lazy.rounds) + " round" + (lazy.rounds == 1 ? "" : "s") +
        (lazy.kept_incumbent ? "; the best schedule of their searches kept" : "") + ")");
  }
  return s;
}

}  // namespace

int CountSlots(const Eigen::MatrixXi& mask) { return mask.sum(); }

// Condensing a restriction cannot be interrupted and takes seconds on a
// large net, so under a time limit a net is not built when it would not be
// ready before the limit: its time is estimated from the largest net built
// so far (it grows about linearly with the free slots).
bool TimeToBuild(SearchState& state, const Eigen::MatrixXi& mask) {
  const double needed = internal::RestrictionBuildSeconds(
      CountSlots(mask), state.largest_built_slots(), state.largest_built_seconds());
  if (needed < state.Remaining()) return true;
  state.Step("the MILP over " + std::to_string(CountSlots(mask)) + " slots not built: about " +
             FormatG(needed, 2) + " s to condense, " +
             FormatG(std::max(0.0, state.Remaining()), 2) + " s left");
  return false;
}

RestrictedSolve SolveOver(SearchState& state, const Eigen::MatrixXi& mask,
                          const RestrictionRows& rows,
                          const std::function<milp::SolveOptions()>& options) {
  const double t0 = state.Elapsed();
  RestrictedSolve rs{Restrict(state, mask), {}, 0.0};
  if (rs.restriction.feasible) {
    if (std::isfinite(rows.cutoff)) AddObjectiveCutoff(&rs.restriction.small, rows.cutoff);
    if (rows.extra) milp::AppendRows(&rs.restriction.small, rows.extra(rs.restriction));
    rs.solve = SolveRestricted(state, rs.restriction.small, options());
    state.AddNodes(rs.solve.nodes);
  }
  rs.seconds = state.Elapsed() - t0;
  return rs;
}

Eigen::VectorXd Lift(const SearchState& state, const Restriction& r,
                     const Eigen::VectorXd& small_x) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(r.milp.lp().num_cols());
  for (size_t k = 0; k < r.kept.size(); ++k) x[r.kept[k]] = small_x[static_cast<Eigen::Index>(k)];
  return state.milp().StartFromPattern(r.milp.encoding().OnPattern(x));
}

std::string StatusText(const milp::SolveResult& s) {
  std::string text(milp::ToString(s.status));
  if (s.status == milp::SolveStatus::kError && !s.detail.empty()) text += " (" + s.detail + ")";
  return text;
}

std::vector<milp::SparseRow> TotalRows(const Restriction& r,
                                       const std::vector<ThrusterGroup>& groups,
                                       const std::vector<double>& lower,
                                       const std::vector<double>& upper) {
  const OperationalEncoding& enc = r.milp.encoding();
  std::vector<int> small_column(static_cast<size_t>(r.milp.lp().num_cols()), -1);
  for (size_t k = 0; k < r.kept.size(); ++k)
    small_column[static_cast<size_t>(r.kept[k])] = static_cast<int>(k);
  std::vector<milp::SparseRow> rows;
  for (size_t g = 0; g < groups.size(); ++g) {
    if (!TotalIsBounded(lower[g], upper[g], groups[g], enc.num_intervals)) continue;
    milp::SparseRow row;
    double fixed_on = 0.0;  // slots fixed on (removed with their value)
    for (int i : groups[g].thrusters) {
      for (int j = groups[g].first_interval; j < groups[g].End(enc.num_intervals); ++j) {
        const int column = enc.on[i][j].index();
        const int k = small_column[static_cast<size_t>(column)];
        if (k >= 0) {
          row.columns.push_back(k);
          row.coefficients.push_back(1.0);
        } else {
          fixed_on += r.milp.lp().col_lower[column];
        }
      }
    }
    row.lower = lower[g] > 0.0 ? lower[g] - fixed_on : -milp::kInfinity;
    row.upper = upper[g] - fixed_on;
    row.name = "total_" + std::to_string(g);
    rows.push_back(std::move(row));
  }
  return rows;
}

bool ImproveWithin(SearchState& state, const Eigen::MatrixXi& mask, const std::string& what,
                   const std::string& source, double time_share,
                   const std::function<std::vector<milp::SparseRow>(const Restriction&)>& extra) {
  if (!TimeToBuild(state, mask)) return false;
  const RestrictedSolve rs = SolveOver(state, mask, {state.Cutoff(), extra},
                                       [&] { return state.HeuristicOptions(time_share); });
  if (!rs.restriction.feasible) return false;
  state.Step(what + std::to_string(CountSlots(mask)) + " slots: " + StatusText(rs.solve) + " in " +
             FormatG(rs.seconds, 3) + " s" + state.lazy_note());
  if (rs.solve.has_solution()) state.Offer(Lift(state, rs.restriction, rs.solve.x), source);
  return true;
}

}  // namespace thrustsched::transcription
