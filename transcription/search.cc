#include "transcription/search.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/format.h"
#include "common/timing.h"
#include "milp/lazy_rows.h"
#include "milp/lp_bound.h"
#include "transcription/dormant.h"
#include "transcription/internal/build_time.h"
#include "transcription/total_branching.h"

namespace thrustsched::transcription {

using common::FormatG;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Slack on a count of slots from an interior point's on-values.
constexpr double kIntegralSlack = 1e-6;

// The schedule MILP restricted to a set of free slots, condensed over them.
struct Restriction {
  ScheduleMilp milp;
  milp::LpData small;     // without its fixed columns
  std::vector<int> kept;  // column of `milp` of each column of `small`
  bool feasible = true;   // false: the fixed slots alone break a row
};

class Search {
 public:
  Search(const ScheduleMilp& milp, const milp::Solver& solver, const milp::SolveOptions& options,
         const SearchOptions& search, SearchReport* report)
      : milp_(milp),
        lp_(milp.lp()),
        solver_(solver),
        options_(options),
        search_(search),
        report_(report),
        clock_(options.time_limit_s, options.interrupt) {
    step_ = options.objective_step > 0.0 ? options.objective_step : milp.objective_step();
  }

  milp::SolveResult Run(const std::vector<Eigen::VectorXd>& starts) {
    for (const Eigen::VectorXd& x : starts) Offer(x, "the given start");
    if (!SolveRelaxation()) {
      // No bound from the LP (an error or a limit, not infeasibility): the
      // solver on the whole MILP still has its own chance.
      if (status_ != milp::SolveStatus::kInfeasible && !Stopped()) WholeMilp();
      return Result();
    }
    if (!Done()) Heuristic();
    // A first incumbent one step above the bound: the question left is
    // whether a schedule at the bound exists, which step 4's exact MILP
    // asks by search and step 4b's tree with step 4d's windows by proof;
    // the tree first (BranchOnTotals, which also tries the cheap MILP over
    // the lowest leaf's LP slots before the windows and the leaves' MILPs).
    if (search_.tree_first_at_one_step && !Done() && !Stopped() && OneStepAboveBound())
      BranchOnTotals();
    ExactRounds();
    // The first improvement level is cheap and often finds the optimum; the
    // tree is the proof; the exchange along an axis and the wider levels
    // cost more and come after it. Measured on the six-thruster hard weeks
    // of data/scenarios/hard/ with 60 s, both paths in one run: the
    // exchange before the tree took 7-10 s there and left weeks 14 and 47
    // at 4.55 % and 3.57 % (proven optimal and 1.79 % without it), while it
    // proved week 10 optimal (10.5 % without it).
    bool improved = !Done() && !Stopped() && has_incumbent() && Improve(1);
    if (!tree_ran_ && !Done() && !Stopped() && has_incumbent()) BranchOnTotals();
    if (has_incumbent()) ExchangeWhileItImproves();
    if (!Done() && !Stopped() && OneStepAboveBound()) BranchOnWindows(true);
    if (!Done() && !Stopped() && has_incumbent() && Improve(search_.improvement_rounds)) {
      improved = true;
    }
    if (improved) ExactRounds();
    if (!Done() && !Stopped()) WholeMilp();
    return Result();
  }

 private:
  // ---------------------------------------------------------------- clock

  double Elapsed() const { return clock_.Elapsed(); }
  double Remaining() const { return clock_.Remaining(); }
  bool Interrupted() const { return clock_.Interrupted(); }
  bool Stopped() const { return Interrupted() || Remaining() <= 0.0; }
  bool has_incumbent() const { return x_.size() > 0; }

  // Options of a sub-solve: what is left of the time, the caller's interrupt,
  // progress reported on our clock with our incumbent and bound.
  milp::SolveOptions SubOptions(bool global_bound) const {
    milp::SolveOptions o = options_;
    o.time_limit_s = std::max(0.0, Remaining());
    o.initial_solution.reset();
    o.complete_solution = nullptr;
    o.objective_step = step_;
    const double offset = Elapsed();
    o.progress = nullptr;
    if (options_.progress) {
      o.progress = [this, offset, global_bound](const milp::SolveProgress& sub) {
        milp::SolveProgress p = sub;
        p.wall_seconds += offset;
        if (has_incumbent() && !(p.objective < objective_)) p.objective = objective_;
        if (!global_bound || !(p.best_bound > bound_)) p.best_bound = bound_;
        p.gap = std::isfinite(p.objective) ? milp::RelativeGap(p.objective, p.best_bound) : kNaN;
        options_.progress(p);
      };
    }
    return o;
  }

  // A restricted MILP is small and its condensed window rows are dense: the
  // dual simplex, whatever the caller chose for the whole MILP (an interior
  // point factors the dense A D A' of those rows, minutes on a GEO week).
  milp::SolveOptions RestrictedOptions() const {
    milp::SolveOptions o = SubOptions(false);
    o.lp_algorithm = milp::LpAlgorithm::kDual;
    return o;
  }

  // An incumbent-only restricted MILP: RestrictedOptions within the node
  // limit and its share of the time left (SearchOptions::heuristic_time_share).
  milp::SolveOptions HeuristicOptions(double time_share) const {
    milp::SolveOptions o = RestrictedOptions();
    o.max_nodes = NodeLimit();
    if (std::isfinite(o.time_limit_s)) o.time_limit_s *= time_share;
    return o;
  }
  milp::SolveOptions HeuristicOptions() const {
    return HeuristicOptions(search_.heuristic_time_share);
  }

  void Report(milp::SolvePhase phase, bool new_incumbent) const {
    if (!options_.progress) return;
    milp::SolveProgress p;
    p.wall_seconds = Elapsed();
    p.phase = phase;
    p.in_root_lp = phase == milp::SolvePhase::kRootLp;
    p.objective = has_incumbent() ? objective_ : kNaN;
    p.best_bound = bound_;
    p.gap = has_incumbent() ? milp::RelativeGap(objective_, bound_) : kNaN;
    p.new_incumbent = new_incumbent;
    p.nodes = nodes_;
    options_.progress(p);
  }

  void Step(const std::string& line) {
    detail_ += (detail_.empty() ? "" : "; ") + line;
    if (report_ != nullptr) report_->steps.push_back(line);
  }

  // ------------------------------------------------------- bound and gap

  void RaiseBound(double bound) {
    const double rounded = milp::RoundBoundToStep(lp_, bound, step_);
    if (rounded > bound_) bound_ = rounded;
    if (has_incumbent() && bound_ > objective_) bound_ = objective_;
  }

  bool Done() const { return has_incumbent() && milp::GapClosed(objective_, bound_, options_); }

  // A point of the full MILP: verified, then the incumbent if better.
  bool Offer(Eigen::VectorXd x, const std::string& source) {
    if (x.size() != lp_.num_cols()) return false;
    if (!milp_.CompleteFromPattern(&x) ||
        lp_.MaxViolation(x) > ScheduleMilp::kPatternFeasibilityTolerance)
      return false;
    const double obj = lp_.Objective(x);
    if (has_incumbent() && !(obj < objective_ - 1e-12 * std::max(1.0, std::abs(obj)))) return false;
    x_ = std::move(x);
    objective_ = obj;
    incumbents_.push_back({Elapsed(), objective_, bound_});
    if (bound_ > objective_) bound_ = objective_;
    Step("incumbent " + FormatG(objective_, 6) + " from " + source);
    Report(milp::SolvePhase::kPresolve, true);
    return true;
  }

  // ---------------------------------------------------------- 1. the LP

  bool SolveRelaxation() {
    milp::SolveOptions o = SubOptions(true);
    o.lp_algorithm = milp::LpAlgorithm::kBarrierNoCrossover;
    const double t0 = Elapsed();
    Report(milp::SolvePhase::kRootLp, false);
    relaxation_ = SolveRelaxationWithoutDormantBlocks(o);
    if (report_ != nullptr) report_->lp_seconds = Elapsed() - t0;
    if (relaxation_.status == milp::SolveStatus::kInfeasible) {
      status_ = milp::SolveStatus::kInfeasible;
      Step("the LP relaxation is infeasible (" + relaxation_.detail + ")");
      return false;
    }
    if (relaxation_.status != milp::SolveStatus::kOptimal) {
      Step("LP relaxation: " + std::string(milp::ToString(relaxation_.status)) + " (" +
           relaxation_.detail + ")");
      return false;
    }
    dual_ = milp::SafeDualBound(lp_, relaxation_.row_duals);
    if (report_ != nullptr) report_->lp_bound = dual_.bound;
    RaiseBound(dual_.bound);
    Step("LP bound " + FormatG(dual_.bound, 8) +
         (bound_ > dual_.bound ? " (" + FormatG(bound_, 8) + " on the objective step)"
                               : std::string()) +
         " by interior point in " + FormatG(Elapsed() - t0, 3) + " s" + dormant_note_);
    Report(milp::SolvePhase::kPresolve, false);
    return true;
  }

  // The LP relaxation with the blocks of dormant thrusters fixed at their
  // coasting values and removed (transcription/dormant.h): same bound
  // validity (the duals are the whole MILP's, zero on the removed rows, and
  // SafeDualBound checks them on the whole MILP). An infeasible verdict is
  // confirmed on the whole relaxation, so the reduction never declares a
  // problem infeasible on its own.
  milp::LpRelaxationResult SolveRelaxationWithoutDormantBlocks(const milp::SolveOptions& o) {
    if (search_.drop_dormant_blocks) dormant_ = FindDormantThrusters(milp_);
    if (!dormant_.any()) return solver_.SolveLpRelaxation(lp_, o);
    milp::LpData fixed = lp_;
    for (int j = 0; j < lp_.num_cols(); ++j) {
      if (!dormant_.column[static_cast<size_t>(j)]) continue;
      fixed.col_lower[j] = fixed.col_upper[j] = dormant_.all_off[j];
    }
    std::vector<int> kept, kept_rows;
    bool feasible = true;
    const milp::LpData small = milp::RemoveFixedColumns(fixed, &kept, &feasible, &kept_rows);
    if (!feasible) return solver_.SolveLpRelaxation(lp_, o);
    milp::LpRelaxationResult r = solver_.SolveLpRelaxation(small, o);
    if (r.status == milp::SolveStatus::kInfeasible) {
      milp::SolveOptions rest = o;
      rest.time_limit_s = std::max(0.0, Remaining());
      return solver_.SolveLpRelaxation(lp_, rest);
    }
    dormant_note_ = " (thrusters " + dormant_.Names(milp_) +
                    " left off, their block staying within its constraints without them: LP over " +
                    std::to_string(small.num_cols()) + " of " + std::to_string(lp_.num_cols()) +
                    " columns)";
    if (r.status != milp::SolveStatus::kOptimal) return r;
    Eigen::VectorXd x = fixed.col_lower;  // the removed columns' values
    for (size_t k = 0; k < kept.size(); ++k) x[kept[k]] = r.x[static_cast<Eigen::Index>(k)];
    Eigen::VectorXd duals = Eigen::VectorXd::Zero(lp_.num_rows());
    for (size_t k = 0; k < kept_rows.size(); ++k) {
      duals[kept_rows[k]] = r.row_duals[static_cast<Eigen::Index>(k)];
    }
    r.x = std::move(x);
    r.row_duals = std::move(duals);
    r.objective = lp_.Objective(r.x);
    r.dual_bound = kNaN;  // SafeDualBound below, on the whole MILP
    return r;
  }

  bool Dormant(int thruster) const {
    return !dormant_.thruster.empty() && dormant_.thruster[static_cast<size_t>(thruster)];
  }

  // ------------------------------------------------- 2. restricted MILPs

  // Slots the relaxation uses (with forced-on slots and the incumbent's),
  // and the same thruster's within k intervals of them; `all_thrusters`
  // frees every thruster there (a wider net when that is infeasible).
  Eigen::MatrixXi CandidateSlots(double threshold, int k, bool all_thrusters) const {
    return CandidateSlots(relaxation_.x, threshold, k, all_thrusters);
  }
  // The same around the slots a relaxation point `x` uses.
  Eigen::MatrixXi CandidateSlots(const Eigen::VectorXd& x, double threshold, int k,
                                 bool all_thrusters) const {
    const OperationalEncoding& enc = milp_.encoding();
    const int m = enc.num_thrusters, n = enc.num_intervals;
    Eigen::MatrixXi used = Eigen::MatrixXi::Zero(m, n);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < n; ++j) {
        const int c = enc.on[i][j].index();
        if (x[c] > threshold || lp_.col_lower[c] > 0.5 || (has_incumbent() && x_[c] > 0.5)) {
          used(i, j) = 1;
        }
      }
    }
    Eigen::MatrixXi mask = Eigen::MatrixXi::Zero(m, n);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < n; ++j) {
        // Dormant thrusters stay off in the heuristic nets (it only needs
        // a schedule; the exact step 4 does not use these nets).
        if (lp_.col_upper[enc.on[i][j].index()] < 0.5 || Dormant(i)) continue;
        bool near = false;
        for (int d = -k; d <= k && !near; ++d) {
          const int jj = j + d;
          near = jj >= 0 && jj < n && (all_thrusters ? used.col(jj).any() : used(i, jj) != 0);
        }
        if (near) mask(i, j) = 1;
      }
    }
    return mask;
  }

  Restriction Restrict(const Eigen::MatrixXi& mask) {
    const double t0 = Elapsed();
    BuildOptions bo = milp_.options();
    bo.formulation = search_.restricted_formulation;
    bo.free_slots = mask;
    Restriction r{ScheduleMilp(milp_.problem(), milp_.discrete(), bo), {}, {}, true};
    r.small = milp::RemoveFixedColumns(r.milp.lp(), &r.kept, &r.feasible);
    r.feasible = r.feasible && r.milp.infeasibility_reasons().empty();
    if (Count(mask) >= largest_built_slots_) {
      largest_built_slots_ = Count(mask);
      largest_built_seconds_ = Elapsed() - t0;
    }
    return r;
  }

  // Condensing a restriction cannot be interrupted and takes seconds on a
  // large net (2.9 s for 4032 slots of a six-thruster GEO week), so under a
  // time limit a net is not built when it would not be ready before the
  // limit: its time is estimated from the largest net built so far (the
  // time grows about linearly with the free slots). Without that, the
  // widening of week c41 of data/scenarios/hard/ built a 3474-slot net
  // with less than a second left and ended 9.4 s after its 60-s limit.
  bool TimeToBuild(const Eigen::MatrixXi& mask) {
    const double needed = internal::RestrictionBuildSeconds(Count(mask), largest_built_slots_,
                                                            largest_built_seconds_);
    if (needed < Remaining()) return true;
    Step("the MILP over " + std::to_string(Count(mask)) + " slots not built: about " +
         FormatG(needed, 2) + " s to condense, " + FormatG(std::max(0.0, Remaining()), 2) +
         " s left");
    return false;
  }

  // The full MILP's point of a restricted solution (its on-off pattern).
  Eigen::VectorXd Lift(const Restriction& r, const Eigen::VectorXd& small_x) const {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(r.milp.lp().num_cols());
    for (size_t k = 0; k < r.kept.size(); ++k) x[r.kept[k]] = small_x[static_cast<Eigen::Index>(k)];
    return milp_.StartFromPattern(r.milp.encoding().OnPattern(x));
  }

  static int Count(const Eigen::MatrixXi& mask) { return mask.sum(); }

  // A sub-solve's status for the step log; an error with its reason (the
  // solver process died, say, with what it wrote).
  static std::string StatusText(const milp::SolveResult& s) {
    std::string text(milp::ToString(s.status));
    if (s.status == milp::SolveStatus::kError && !s.detail.empty()) text += " (" + s.detail + ")";
    return text;
  }

  // Step 2: the MILP restricted to the candidate slots, widened while it
  // holds no schedule, until a net frees every slot or would exceed
  // max_widened_slots (step 5's whole MILP is then the next try). After
  // the first two widenings, the net of every slot of the thrusters the
  // relaxation fires (SearchOptions::fired_thrusters_net).
  void Heuristic() {
    Eigen::MatrixXi previous;  // the last widening's net
    for (int widening = 0; widening <= search_.max_widenings && !Stopped(); ++widening) {
      if (widening == kFiredThrustersNetAfter + 1 && search_.fired_thrusters_net &&
          FiredThrustersNet(previous, widening - 1)) {
        return;
      }
      const Eigen::MatrixXi mask = WideningMask(widening);
      const int slots = Count(mask);
      // From level 1 on every thruster is free near the candidates, so a net
      // that did not grow already frees every slot: nothing new to try.
      if (widening > 0 && slots == Count(previous)) return;
      if (widening > 0 && slots > search_.max_widened_slots) {
        Step("the next net has " + std::to_string(slots) + " slots (more than " +
             std::to_string(search_.max_widened_slots) + "): not widened further");
        return;
      }
      if (!TimeToBuild(mask) || HeuristicNet(mask, " candidate slots", widening)) return;
      previous = mask;
    }
  }

  // The MILP restricted to `mask` (incumbents only); true if it held a
  // schedule, which is offered; `level` is the widening level step 4a's
  // improvement nets continue from.
  bool HeuristicNet(const Eigen::MatrixXi& mask, const std::string& slots, int level) {
    const double t0 = Elapsed();  // the step's time counts its MILP's condensing
    const Restriction r = Restrict(mask);
    if (report_ != nullptr) report_->candidate_slots = Count(mask);
    milp::SolveResult s;
    if (r.feasible) s = SolveRestricted(r.small, HeuristicOptions());
    nodes_ += s.nodes;
    const std::string what = "MILP restricted to " + std::to_string(Count(mask)) + slots + " (" +
                             std::to_string(r.small.num_cols()) + " columns, " +
                             std::to_string(r.small.num_rows()) + " rows)";
    if (s.has_solution()) {
      Step(what + ": " + StatusText(s) + " in " + FormatG(Elapsed() - t0, 3) + " s, " +
           std::to_string(s.nodes) + " nodes" + lazy_note_);
      Offer(Lift(r, s.x), "the restricted MILP");
      heuristic_level_ = level;
      return true;
    }
    Step(what + ": " + (r.feasible ? StatusText(s) : "infeasible") + ", widened after " +
         FormatG(Elapsed() - t0, 3) + " s" + (r.feasible ? lazy_note_ : ""));
    return false;
  }

  // Every slot of the thrusters the relaxation fires (not dormant) that the
  // MILP leaves free, when that net has at most max_widened_slots slots and
  // is not within `previous`, the net of the widening `level`. The nets
  // widen in time around the relaxation's slots; on a week that needs a few
  // slots of one thruster, its firings may have to move anywhere in the
  // week (as for the lowest leaf's MILP of step 4b).
  bool FiredThrustersNet(const Eigen::MatrixXi& previous, int level) {
    Eigen::MatrixXi mask = FiredThrusterSlots(relaxation_.x);
    const OperationalEncoding& enc = milp_.encoding();
    for (int i = 0; i < enc.num_thrusters; ++i) {
      for (int j = 0; j < enc.num_intervals; ++j) {
        if (Dormant(i) || lp_.col_upper[enc.on[i][j].index()] < 0.5) mask(i, j) = 0;
      }
    }
    if (Count(mask) == 0 || Count(mask) > search_.max_widened_slots) return false;
    if ((mask.array() <= previous.array()).all()) return false;
    if (!TimeToBuild(mask)) return true;  // the nets after it are no smaller
    return HeuristicNet(mask, " slots of the thrusters the relaxation fires", level);
  }

  // Every slot of the thrusters a point `x` fires: their total on-value is
  // at least candidate_threshold.
  Eigen::MatrixXi FiredThrusterSlots(const Eigen::VectorXd& x) const {
    const OperationalEncoding& enc = milp_.encoding();
    const std::vector<double> totals = ThrusterTotals(enc, x);
    Eigen::MatrixXi mask = Eigen::MatrixXi::Zero(enc.num_thrusters, enc.num_intervals);
    for (int i = 0; i < enc.num_thrusters; ++i) {
      if (totals[static_cast<size_t>(i)] >= search_.candidate_threshold) mask.row(i).setOnes();
    }
    return mask;
  }

  // The candidate slots of widening level w: the relaxation's slots with
  // threshold t/10^w, k doubled w times, every thruster from level 1 on.
  Eigen::MatrixXi WideningMask(int level) const { return WideningMask(relaxation_.x, level); }
  // The same around the slots a relaxation point `x` uses.
  Eigen::MatrixXi WideningMask(const Eigen::VectorXd& x, int level) const {
    double threshold = search_.candidate_threshold;
    int k = search_.neighbourhood;
    for (int w = 0; w < level; ++w) {
      k = std::max(2 * k, k + 1);
      threshold /= 10.0;
    }
    return CandidateSlots(x, threshold, k, level > 0);
  }

  // Step 4a, local improvement (when reduced-cost fixing leaves too many
  // slots): the MILP restricted to the next, wider nets around the
  // relaxation's and the incumbent's slots, each asked for a schedule better
  // than the incumbent by a step (a cutoff row): the next `rounds` of the
  // improvement_rounds levels, nets of at most max_exact_slots slots.
  // Incumbents only: a restriction's verdict says nothing of the slots it
  // leaves out. True if it improved.
  bool Improve(int rounds) {
    const double before = objective_;
    const int end = heuristic_level_ + 1 + search_.improvement_rounds;
    if (improvement_level_ < 0) improvement_level_ = heuristic_level_ + 1;
    for (int solved = 0; solved < rounds && improvement_level_ < end; ++improvement_level_) {
      if (Done() || Stopped()) break;
      const Eigen::MatrixXi mask = WideningMask(improvement_level_);
      if (Count(mask) > search_.max_exact_slots) {
        improvement_level_ = end;
        break;
      }
      if (last_improvement_mask_.size() == mask.size() && last_improvement_mask_ == mask) continue;
      last_improvement_mask_ = mask;
      if (ImproveWithin(mask, "improvement over ", "the improvement MILP", {},
                        search_.improvement_time_share))
        ++solved;
    }
    return objective_ < before;
  }

  // The MILP restricted to `mask` with the cutoff one step below the
  // incumbent (and `extra_rows`, if given); its schedule (if any) offered.
  // False if the restriction is infeasible by its fixed slots alone (nothing
  // solved).
  bool ImproveWithin(
      const Eigen::MatrixXi& mask, const std::string& what, const std::string& source,
      const std::function<std::vector<milp::SparseRow>(const Restriction&)>& extra_rows = {},
      double time_share = 0.0) {  // 0: heuristic_time_share
    if (!TimeToBuild(mask)) return false;
    const double t0 = Elapsed();
    Restriction r = Restrict(mask);
    if (!r.feasible) return false;
    AddObjectiveCutoff(&r.small, Cutoff());
    if (extra_rows) milp::AppendRows(&r.small, extra_rows(r));
    const milp::SolveResult s = SolveRestricted(
        r.small, HeuristicOptions(time_share > 0.0 ? time_share : search_.heuristic_time_share));
    nodes_ += s.nodes;
    Step(what + std::to_string(Count(mask)) + " slots: " + StatusText(s) + " in " +
         FormatG(Elapsed() - t0, 3) + " s" + lazy_note_);
    if (s.has_solution()) Offer(Lift(r, s.x), source);
    return true;
  }

  // Step 4c, exchange along an axis: the MILP restricted to every slot of
  // the thrusters on one axis (directions parallel or opposite) and to the
  // incumbent's slots of the others, with the cutoff. The nets above grow
  // around the relaxation's slots in time; here an axis' firings can move
  // anywhere in the week. Only for thrusters along the orbital frame's
  // axes in opposite pairs (AxisExchangeApplies: the ideal six): each
  // firing then moves its own axis' components of the state, and a pair
  // can trade its firings over the week (+T early, -T later) while the
  // other axes keep theirs. With thrusters that push both ways (the
  // thesis' four Anzel thrusters, each alone on its axis) every firing
  // moves the whole state; on week 35 of the NE-failure hard weeks the
  // exchanges took 17 s and found nothing.
  // The axes of ExchangeAxes, those where rounding lost most first. Returns
  // at the first improvement (for step 4 to try its proof); called again,
  // it solves the axes not yet solved against the new incumbent (block
  // coordinate descent), false once every axis has been. Incumbents only.
  // Step 4c, after each schedule of the exchange step 4's proof.
  void ExchangeWhileItImproves() {
    while (!Done() && !Stopped() && search_.axis_exchange && ExchangeAlongAxes()) ExactRounds();
  }

  bool ExchangeAlongAxes() {
    if (!exchange_started_) {
      exchange_axes_ = ExchangeAxes();
      exchanged_at_.assign(exchange_axes_.size(), kInf);
      exchange_started_ = true;
    }
    for (size_t a = 0; a < exchange_axes_.size(); ++a) {
      if (Done() || Stopped()) return false;
      if (exchanged_at_[a] == objective_) continue;
      const double before = objective_;
      const Eigen::MatrixXi mask = AxisMask(exchange_axes_[a]);
      if (Count(mask) <= search_.max_exchange_slots) {
        ImproveWithin(mask, "exchange along " + exchange_axes_[a].name + " over ",
                      "the exchange along an axis", {}, search_.exchange_time_share);
      }
      exchanged_at_[a] = objective_;
      if (objective_ < before) return true;
    }
    return false;
  }

  // Axes (ThrusterAxes) the incumbent fires at least one slot more than the
  // relaxation does, most first; none unless AxisExchangeApplies. An axis
  // where the relaxation matches the incumbent within a slot has little to
  // give: on the six-thruster hard weeks (02-52 of data/scenarios/hard/)
  // the incumbent fires +N and -N 0.06-0.66 slots more than the relaxation
  // and their exchange never improved (4-8 s each), +T and -T 2.1-5.5 more
  // and theirs improved in 5 of the 7 weeks where it ran (run before the
  // tree).
  std::vector<ThrusterGroup> ExchangeAxes() const {
    if (!AxisExchangeApplies(milp_.problem().thrusters)) return {};
    const OperationalEncoding& enc = milp_.encoding();
    std::vector<std::pair<double, ThrusterGroup>> ranked;
    for (ThrusterGroup& axis : ThrusterAxes(milp_.problem().thrusters)) {
      double incumbent = 0.0, relaxed = 0.0;
      for (int i : axis.thrusters) {
        for (int j = 0; j < enc.num_intervals; ++j) {
          const int c = enc.on[i][j].index();
          incumbent += x_[c] > 0.5 ? 1.0 : 0.0;
          relaxed += relaxation_.x[c];
        }
      }
      if (incumbent - relaxed >= 1.0 - kIntegralSlack)
        ranked.emplace_back(incumbent - relaxed, std::move(axis));
    }
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<ThrusterGroup> axes;
    for (auto& r : ranked) axes.push_back(std::move(r.second));
    return axes;
  }

  // Every slot of the axis' thrusters and the incumbent's of the others.
  Eigen::MatrixXi AxisMask(const ThrusterGroup& axis) const {
    const OperationalEncoding& enc = milp_.encoding();
    Eigen::MatrixXi mask = enc.OnPattern(x_);
    for (int i : axis.thrusters) {
      if (Dormant(i)) continue;
      for (int j = 0; j < enc.num_intervals; ++j) {
        if (lp_.col_upper[enc.on[i][j].index()] > 0.5) mask(i, j) = 1;
      }
    }
    return mask;
  }

  void ExactRounds() {
    for (int round = 0; round < 3 && !Done() && !Stopped() && has_incumbent(); ++round) {
      if (!ExactRestricted()) break;
    }
  }

  // Only schedules better than the incumbent by a step count.
  double Cutoff() const {
    return objective_ - std::max(step_, 0.0) + 1e-7 * std::max(1.0, std::abs(objective_));
  }

  // A restricted MILP: by row generation over its dense (condensed window)
  // rows unless disabled (milp/lazy_rows.h; exact, so proofs carry over).
  milp::SolveResult SolveRestricted(const milp::LpData& small, const milp::SolveOptions& o) {
    if (!search_.lazy_rows) return solver_.Solve(small, o);
    milp::LazyRowOptions rows;
    rows.keep_model_incumbents = search_.lazy_rows_keep_incumbents;
    rows.presolve_lp_relaxation = search_.lazy_rows_presolve_lp;
    rows.skip_implied_rows_in_lp = search_.lazy_rows_skip_implied;
    milp::LazyRowReport lazy;
    milp::SolveResult s = milp::SolveWithLazyRows(solver_, small, o, rows, &lazy);
    lazy_note_ = "";
    if (lazy.used) {
      lazy_note_ = " (" + std::to_string(lazy.final_rows) + " of " +
                   std::to_string(small.num_rows()) + " rows in " + std::to_string(lazy.rounds) +
                   " round" + (lazy.rounds == 1 ? "" : "s") +
                   (lazy.kept_incumbent ? "; the best schedule of their searches kept" : "") + ")";
    }
    return s;
  }

  long long NodeLimit() const {
    return options_.max_nodes >= 0 ? std::min(options_.max_nodes, search_.restricted_max_nodes)
                                   : search_.restricted_max_nodes;
  }

  // ------------------------------------- 4. reduced-cost fixing, exactly

  // Slots that may be on in a schedule better than the incumbent (by a step).
  Eigen::MatrixXi FreeByReducedCost() const {
    return SlotsFreeByReducedCost(milp_.encoding(), lp_, dual_, objective_, step_);
  }

  // Step 4. Returns false when it cannot help (too many free slots).
  bool ExactRestricted() {
    if (!dual_.finite()) return false;
    const Eigen::MatrixXi mask = FreeByReducedCost();
    if (report_ != nullptr) report_->exact_slots = Count(mask);
    if (Count(mask) > search_.max_exact_slots) {
      Step(std::to_string(Count(mask)) + " slots can still improve on the incumbent (more than " +
           std::to_string(search_.max_exact_slots) + "): the whole MILP instead");
      return false;
    }
    if (!TimeToBuild(mask)) return false;
    const double t0 = Elapsed();
    Restriction r = Restrict(mask);
    const double before = objective_;
    AddObjectiveCutoff(&r.small, Cutoff());
    milp::SolveResult s;
    milp::SolveOptions o = RestrictedOptions();
    if (!tree_ran_ && search_.total_branching_lps >= 2 && std::isfinite(o.time_limit_s))
      o.time_limit_s *= search_.exact_time_share;
    if (r.feasible) s = SolveRestricted(r.small, o);
    nodes_ += s.nodes;
    const std::string what = "exact MILP over the " + std::to_string(Count(mask)) +
                             " slots reduced-cost fixing leaves free";
    if (!r.feasible || s.status == milp::SolveStatus::kInfeasible) {
      // No schedule better than the incumbent: it is optimal.
      bound_ = objective_;
      Step(what + ": no better schedule (" + FormatG(Elapsed() - t0, 3) +
           " s): the incumbent is "
           "optimal");
      return true;
    }
    if (s.has_solution()) Offer(Lift(r, s.x), "the exact restricted MILP");
    // Every better schedule lies in the restriction: the bound is the
    // smaller of the old incumbent and the restricted solve's bound.
    const double restricted_bound =
        s.has_solution() || std::isfinite(s.best_bound) ? s.best_bound : -kInf;
    if (s.status == milp::SolveStatus::kOptimal) {
      bound_ = std::max(bound_, std::min(before, objective_));
    } else if (std::isfinite(restricted_bound)) {
      bound_ = std::max(bound_, std::min(before, restricted_bound));
    }
    if (bound_ > objective_) bound_ = objective_;
    Step(what + ": " + StatusText(s) + " in " + FormatG(Elapsed() - t0, 3) + " s, bound " +
         FormatG(bound_, 8) + lazy_note_);
    return s.status != milp::SolveStatus::kOptimal && objective_ < before;
  }

  // Appends the row  cost' x <= cutoff - offset.
  static void AddObjectiveCutoff(milp::LpData* lp, double cutoff) {
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

  // ------------------------------------- 4b. branching on thruster totals

  // Step 4b: a better bound from a small tree over each thruster's number
  // of on slots (transcription/total_branching.h), then its leaves' MILPs.
  // When the tree leaves the incumbent one step above the bound, step 4d's
  // windows come between the two: at one step they either prove the
  // incumbent optimal or change nothing, and the leaves' MILPs, which find
  // the schedules at the bound where there are some, still follow. Before
  // the windows, the MILP over the lowest leaf's LP slots: a look for a
  // schedule at the bound that costs a fraction of a second. Week 39 of
  // the four-thruster year: it finds the optimum in 0.24 s, where the
  // windows first took 54 LPs and 15 s without closing the leaves.
  void BranchOnTotals() {
    TotalBranching t;
    if (!Tree(0, &t)) return;
    bool candidates_tried = false;
    if (search_.windows_before_leaves && search_.total_branching_window_levels > 0 && !Done() &&
        !Stopped() && OneStepAboveBound()) {
      candidates_tried = t.lowest_leaf_x.size() > 0;
      if (candidates_tried) LeafCandidates(t);
      if (!Done() && !Stopped() && OneStepAboveBound()) BranchOnWindows(false);
    }
    CloseOrSearchLeaves(t, candidates_tried);
  }

  // The tree with `window_levels` levels of windows: raises the bound;
  // false when the tree is off.
  bool Tree(int window_levels, TotalBranching* t) {
    if (search_.total_branching_lps < 2 || !relaxation_.x.size()) return false;
    tree_ran_ = true;
    milp::SolveOptions o = SubOptions(true);
    o.lp_algorithm = milp::LpAlgorithm::kBarrierNoCrossover;
    const double t0 = Elapsed();
    TreeOptions tree;
    tree.axis_groups = search_.total_branching_axis_groups;
    tree.elastic = search_.total_branching_elastic;
    tree.warm = search_.total_branching_warm;
    tree.leaf_pivot_limit = search_.total_branching_leaf_pivot_limit;
    tree.window_levels = window_levels;
    *t = BranchOnThrusterTotals(
        milp_, solver_, o, relaxation_.x, bound_, objective_, step_, TreeLpBudget(), tree,
        search_.tree_root_from_relaxation ? relaxation_.row_duals : Eigen::VectorXd());
    RaiseBound(t->bound);
    Step((window_levels > 0 ? "the tree again, with windows: " : "") + t->detail + " (" +
         FormatG(Elapsed() - t0, 3) + " s)");
    Report(milp::SolvePhase::kSearch, false);
    return true;
  }

  // The open leaves' exact MILPs (CloseLeaves), else the lowest leaf's
  // restricted MILP (LeafHeuristic).
  void CloseOrSearchLeaves(const TotalBranching& t, bool candidates_tried) {
    const bool lowest_solved = !Done() && !Stopped() && CloseLeaves(t);
    if (!Done() && !Stopped() && t.lowest_leaf_x.size() > 0 && !lowest_solved)
      LeafHeuristic(t, candidates_tried);
  }

  // Step 4d: the tree again, now with windows, when the incumbent is one
  // step above the bound: after step 4b's tree (before its leaves' MILPs)
  // and again after the exchange if that lowered the incumbent to one step
  // (then with its own leaves' MILPs). Not inside the first tree's
  // splitting: there the windowed leaves replace the first tree's, and the
  // four-thruster year's week 42 ended a step above the optimum that the
  // lowest leaf's MILP of the first tree finds (f701f9a); and the first
  // tree alone never splits a window where the exchange is what brings the
  // incumbent to one step (year_ideal6_fixed_windowed_c41: 17 steps after
  // the tree, 15 after the exchange, proven by the windows). Measured on
  // the 75 deg E week of data/scenarios/hard/ (one step, +T alone): 274
  // window LPs in 23 s prove it, where the leaf's MILP and the exchange
  // before them ran 61 s without a schedule.
  void BranchOnWindows(bool with_leaves) {
    if (search_.total_branching_window_levels <= 0 || !(objective_ < windows_at_)) return;
    windows_at_ = objective_;
    TotalBranching t;
    if (Tree(search_.total_branching_window_levels, &t) && with_leaves)
      CloseOrSearchLeaves(t, false);
  }

  bool OneStepAboveBound() const {
    return has_incumbent() && OneStepAbove(objective_, bound_, step_);
  }

  // The open leaves, lowest first, each solved exactly while reduced-cost
  // fixing with its LP's duals leaves at most max_exact_leaf_slots slots
  // free (OpenLeaf::free_slots): the MILP with the leaf's totals restricted
  // to them, with the cutoff, as step 4 does for the whole MILP. A leaf that
  // holds no better schedule is closed at the incumbent; the bound is the
  // lowest of the leaves' bounds after their solves (those not solved keep
  // their LP's). Stops at the first leaf with too many free slots (the bound
  // cannot pass it). True if the lowest leaf was solved.
  bool CloseLeaves(const TotalBranching& t) {
    double lowest = kInf;
    size_t k = 0;  // leaves solved
    for (; k < t.open.size() && !Stopped(); ++k) {
      const OpenLeaf& leaf = t.open[k];
      if (leaf.free_slots.size() == 0) {
        Step("the leaf " + LeafText(t, leaf) +
             ": no reduced-cost fixing (its LP gave no point within its totals)");
        break;
      }
      if (Count(leaf.free_slots) > search_.max_exact_leaf_slots) {
        Step("the leaf " + LeafText(t, leaf) + ": " + std::to_string(Count(leaf.free_slots)) +
             " slots can still improve on the incumbent (more than " +
             std::to_string(search_.max_exact_leaf_slots) + ")");
        break;
      }
      if (!TimeToBuild(leaf.free_slots)) break;
      lowest = std::min(lowest, std::max(leaf.bound, SolveLeaf(t, leaf)));
      if (Done()) {
        ++k;
        break;
      }
    }
    for (size_t rest = k; rest < t.open.size(); ++rest)
      lowest = std::min(lowest, t.open[rest].bound);
    if (k > 0) RaiseBound(lowest);
    return k > 0;
  }

  // One leaf's exact MILP; returns a bound for the leaf.
  double SolveLeaf(const TotalBranching& t, const OpenLeaf& leaf) {
    const double before = objective_;
    const double t0 = Elapsed();
    Restriction r = Restrict(leaf.free_slots);
    milp::SolveResult s;
    if (r.feasible) {
      AddObjectiveCutoff(&r.small, Cutoff());
      milp::AppendRows(&r.small, TotalRows(r, t.groups, leaf.lower, leaf.upper));
      s = SolveRestricted(r.small, RestrictedOptions());
      nodes_ += s.nodes;
    }
    const std::string what = "exact MILP of the leaf " + LeafText(t, leaf) + " over the " +
                             std::to_string(Count(leaf.free_slots)) +
                             " slots reduced-cost fixing with its LP leaves free: ";
    if (!r.feasible || s.status == milp::SolveStatus::kInfeasible) {
      Step(what + "no better schedule (" + FormatG(Elapsed() - t0, 3) + " s)" + lazy_note_);
      return before;
    }
    Step(what + StatusText(s) + " in " + FormatG(Elapsed() - t0, 3) + " s" + lazy_note_);
    if (s.has_solution()) Offer(Lift(r, s.x), "an exact leaf MILP");
    if (s.status == milp::SolveStatus::kOptimal) return std::min(before, s.objective);
    return std::isfinite(s.best_bound) ? std::min(before, s.best_bound) : -kInf;
  }

  // "+N and -N <= 9, -T >= 2": the leaf's bounds on the totals it bounds.
  std::string LeafText(const TotalBranching& t, const OpenLeaf& leaf) const {
    std::string text;
    const int n = milp_.encoding().num_intervals;
    for (size_t g = 0; g < t.groups.size(); ++g) {
      if (!TotalIsBounded(leaf.lower[g], leaf.upper[g], t.groups[g], n)) continue;
      std::string range = leaf.lower[g] > 0.0 ? FormatG(leaf.lower[g], 6) + " <= " : "";
      range += t.groups[g].name;
      if (leaf.upper[g] < t.groups[g].MaxTotal(n)) range += " <= " + FormatG(leaf.upper[g], 6);
      text += (text.empty() ? "" : ", ") + range;
    }
    return text;
  }

  // SearchOptions::total_branching_lp_nonzeros: the tree's LPs are the
  // whole MILP's with a few rows, so their size is the MILP's.
  int TreeLpBudget() const {
    if (search_.total_branching_warm) return search_.total_branching_warm_lps;
    const int lps = search_.total_branching_lps;
    const double size = std::max(1, lp_.num_nonzeros());
    if (search_.total_branching_lp_nonzeros <= 0 || size >= search_.total_branching_lp_nonzeros)
      return lps;
    const double scale = std::min<double>(SearchOptions::kTreeLpScaleMax,
                                          search_.total_branching_lp_nonzeros / size);
    return static_cast<int>(std::floor(lps * scale));
  }

  // The lowest leaf is where a better schedule would be: the MILP with the
  // leaf's bounds on the thrusters' totals, restricted to every slot of the
  // thrusters its LP fires when they are few enough (`max_exact_slots`),
  // else to the slots its LP uses; with the cutoff. Measured on week 2 of
  // data/scenarios/hard/: the leaf fires -T alone, for 7 slots, spread thin
  // over the week; its slots and their neighbours (179) hold no 7-slot
  // schedule, all 2016 slots of -T hold the optimum.
  // `candidates_tried`: LeafCandidates ran, not worth solving again.
  void LeafHeuristic(const TotalBranching& t, bool candidates_tried) {
    Eigen::MatrixXi mask = FiredThrusterSlots(t.lowest_leaf_x);
    if (Count(mask) > search_.max_exact_slots) {
      if (candidates_tried) return;
      mask = LeafCandidateSlots(t);
    }
    if (Count(mask) <= search_.max_exact_slots) LeafRestricted(t, mask);
    // After LeafCandidates the other leaves' MILPs ran against this same
    // incumbent (one step above the bound; a better one would be at it).
    if (!candidates_tried) OtherLeafNets(t);
  }

  // The lowest leaf's MILP restricted to its LP's candidate slots, then the
  // other leaves' (OtherLeafNets).
  void LeafCandidates(const TotalBranching& t) {
    const Eigen::MatrixXi mask = LeafCandidateSlots(t);
    if (Count(mask) <= search_.max_exact_slots) LeafRestricted(t, mask);
    OtherLeafNets(t);
  }

  // At one step above the bound, a better schedule is one at the bound:
  // it lies in a leaf at the bound, not necessarily the lowest one (ties
  // are kept in creation order). The MILP of each other leaf at the bound
  // (its totals, the cutoff; at most `other_leaf_nets`), restricted to its
  // LP's candidate slots widened once as step 2 widens (WideningMask: every
  // thruster, neighbourhood doubled, threshold / 10): a leaf's LP point is the
  // relaxation's with its totals whole, so its net is the first net that
  // held a schedule, with fewer schedules to search. Incumbents only.
  // Week 33 of data/scenarios/hard/ (six thrusters, 60 s): the tree splits
  // +N at 14.27 slots; the lowest leaf (+N <= 14) holds no schedule at the
  // bound (34 slots), the other one (+N >= 15) the optimum (+N and -N 15
  // slots each), found by its 1266-slot net in 4 s.
  void OtherLeafNets(const TotalBranching& t) {
    int solved = 0;
    for (const OpenLeaf& leaf : t.open) {
      if (solved >= search_.other_leaf_nets || Done() || Stopped() || !OneStepAboveBound()) return;
      const bool at_bound = leaf.bound <= bound_ + 1e-9 * std::max(1.0, std::abs(bound_));
      if (leaf.x.size() == 0 || !at_bound ||
          (leaf.lower == t.lowest_leaf_lower && leaf.upper == t.lowest_leaf_upper))
        continue;
      const Eigen::MatrixXi mask = WideningMask(leaf.x, 1);
      if (Count(mask) > search_.max_exact_slots) continue;
      ++solved;
      ImproveWithin(mask, "MILP restricted to the leaf " + LeafText(t, leaf) + "'s widened ",
                    "another leaf's restricted MILP", [&](const Restriction& r) {
                      return TotalRows(r, t.groups, leaf.lower, leaf.upper);
                    });
    }
  }

  Eigen::MatrixXi LeafCandidateSlots(const TotalBranching& t) const {
    return CandidateSlots(t.lowest_leaf_x, search_.candidate_threshold, search_.neighbourhood,
                          false);
  }

  // Incumbents only: the MILP with the lowest leaf's bounds on the totals,
  // restricted to `mask`, with the cutoff.
  void LeafRestricted(const TotalBranching& t, const Eigen::MatrixXi& mask) {
    ImproveWithin(mask, "MILP restricted to the lowest leaf's ",
                  "the lowest leaf's restricted MILP", [&](const Restriction& r) {
                    return TotalRows(r, t.groups, t.lowest_leaf_lower, t.lowest_leaf_upper);
                  });
  }

  // Rows lower[g] <= (group g's number of on slots) <= upper[g] on a
  // restriction's model, for the groups whose total is bounded.
  static std::vector<milp::SparseRow> TotalRows(const Restriction& r,
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

  // --------------------------------------------------- 5. the whole MILP

  void WholeMilp() {
    milp::SolveOptions o = SubOptions(true);
    o.complete_solution = [this](Eigen::VectorXd* x) { return milp_.CompleteFromPattern(x); };
    if (has_incumbent() && search_.whole_milp_from_incumbent) o.initial_solution = x_;
    const double t0 = Elapsed();
    const milp::SolveResult s = solver_.Solve(lp_, o);
    nodes_ += s.nodes;
    if (report_ != nullptr) report_->whole_milp = true;
    if ((s.status == milp::SolveStatus::kInfeasible || s.status == milp::SolveStatus::kError) &&
        !has_incumbent()) {
      status_ = s.status;
    }
    if (s.has_solution()) {
      Offer(s.x, std::string(solver_.name()) + " on the whole MILP");
      if (std::isfinite(s.best_bound)) RaiseBound(s.best_bound);
    }
    solver_detail_ = s.detail;
    Step("whole MILP (" + std::string(solver_.name()) +
         (o.initial_solution ? ", from the incumbent" : "") + "): " + StatusText(s) + " in " +
         FormatG(Elapsed() - t0, 3) + " s");
  }

  // -------------------------------------------------------------- result

  milp::SolveResult Result() {
    milp::SolveResult r;
    r.solver_version = solver_.version();
    r.nodes = nodes_;
    r.incumbents = incumbents_;
    if (has_incumbent()) {
      r.status = Done() ? milp::SolveStatus::kOptimal : milp::SolveStatus::kFeasible;
      r.x = x_;
      r.objective = objective_;
      r.best_bound = bound_;
      r.gap = milp::RelativeGap(objective_, bound_);
    } else if (status_ == milp::SolveStatus::kInfeasible || status_ == milp::SolveStatus::kError) {
      r.status = status_;
    } else {
      r.status = milp::SolveStatus::kNoSolutionFound;
    }
    std::string why;
    if (!Done()) {
      if (Interrupted()) {
        why = "; interrupted";
      } else if (Remaining() <= 0.0) {
        why = "; time limit";
      }
    }
    r.detail =
        "search: " + detail_ + why +
        (solver_detail_.empty() ? std::string()
                                : "; " + std::string(solver_.name()) + ": " + solver_detail_);
    r.wall_seconds = Elapsed();
    return r;
  }

  const ScheduleMilp& milp_;
  const milp::LpData& lp_;
  const milp::Solver& solver_;
  const milp::SolveOptions& options_;
  const SearchOptions& search_;
  SearchReport* report_;
  common::SolveClock clock_;
  double step_ = 0.0;
  // The fired thrusters' net comes after this many widenings: the first
  // nets are small and cheap (infeasible in 0.4-0.9 s on a GEO week).
  static constexpr int kFiredThrustersNetAfter = 2;
  int heuristic_level_ = 0;                   // widening level of the heuristic's incumbent
  int improvement_level_ = -1;                // next widening level of step 4a (-1: not started)
  Eigen::MatrixXi last_improvement_mask_;     // its last net, not solved twice
  int largest_built_slots_ = 0;               // the largest restriction built (TimeToBuild)
  double largest_built_seconds_ = 0.0;        // and its condensing time
  bool tree_ran_ = false;                     // step 4b started (exact_time_share)
  double windows_at_ = kInf;                  // incumbent when step 4d last ran
  bool exchange_started_ = false;             // step 4c's axes chosen
  std::vector<ThrusterGroup> exchange_axes_;  // those axes (ExchangeAxes)
  std::vector<double> exchanged_at_;          // incumbent of each one's last exchange
  std::string lazy_note_;                     // rows the last restricted solve used

  milp::LpRelaxationResult relaxation_;
  DormantThrusters dormant_;
  std::string dormant_note_;
  milp::DualBound dual_;
  double bound_ = -kInf;
  Eigen::VectorXd x_;
  double objective_ = kInf;
  std::vector<milp::Incumbent> incumbents_;
  long long nodes_ = 0;
  milp::SolveStatus status_ = milp::SolveStatus::kNoSolutionFound;
  std::string detail_;
  std::string solver_detail_;
};

}  // namespace

bool SearchOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& m) {
    if (error != nullptr) *error = "SearchOptions: " + m;
    return false;
  };
  if (!(candidate_threshold > 0.0 && candidate_threshold < 1.0)) {
    return fail("candidate_threshold must be in (0, 1), got " + FormatG(candidate_threshold, 6));
  }
  if (neighbourhood < 0)
    return fail("neighbourhood must be >= 0, got " + std::to_string(neighbourhood));
  if (max_widenings < 0)
    return fail("max_widenings must be >= 0, got " + std::to_string(max_widenings));
  if (restricted_max_nodes < 0) {
    return fail("restricted_max_nodes must be >= 0, got " + std::to_string(restricted_max_nodes));
  }
  if (total_branching_lps < 0) {
    return fail("total_branching_lps must be >= 0, got " + std::to_string(total_branching_lps));
  }
  if (total_branching_warm_lps < 0) {
    return fail("total_branching_warm_lps must be >= 0, got " +
                std::to_string(total_branching_warm_lps));
  }
  if (total_branching_window_levels < 0 || total_branching_window_levels > 16) {
    return fail("total_branching_window_levels must be in [0, 16], got " +
                std::to_string(total_branching_window_levels));
  }
  if (max_exact_leaf_slots < 0) {
    return fail("max_exact_leaf_slots must be >= 0, got " + std::to_string(max_exact_leaf_slots));
  }
  if (other_leaf_nets < 0)
    return fail("other_leaf_nets must be >= 0, got " + std::to_string(other_leaf_nets));
  if (max_widened_slots < 0) {
    return fail("max_widened_slots must be >= 0, got " + std::to_string(max_widened_slots));
  }
  if (max_exchange_slots < 0) {
    return fail("max_exchange_slots must be >= 0, got " + std::to_string(max_exchange_slots));
  }
  if (total_branching_lp_nonzeros < 0) {
    return fail("total_branching_lp_nonzeros must be >= 0, got " +
                std::to_string(total_branching_lp_nonzeros));
  }
  const std::pair<const char*, double> shares[] = {
      {"heuristic_time_share", heuristic_time_share},
      {"improvement_time_share", improvement_time_share},
      {"exact_time_share", exact_time_share},
      {"exchange_time_share", exchange_time_share}};
  for (const auto& [name, share] : shares) {
    if (!(share > 0.0 && share <= 1.0))
      return fail(std::string(name) + " must be in (0, 1], got " + FormatG(share, 6));
  }
  if (improvement_rounds < 0)
    return fail("improvement_rounds must be >= 0, got " + std::to_string(improvement_rounds));
  if (max_exact_slots < 0)
    return fail("max_exact_slots must be >= 0, got " + std::to_string(max_exact_slots));
  return true;
}

// Until this release the test was "the MILP's rows fall into two blocks or
// more" (DormantThrusters::num_blocks, meant as the orbit plane and its
// normal). The GEO weeks' linear model ties the plane and its normal into
// one block, and only the thesis encoding's shared columns (gamma, one
// block each) passed that test, the tight encoding's did not: week 10 of
// the six-thruster year (data/scenarios/hard/, tight encoding, 60 s, two
// threads) ended 10.5 % from its bound without the exchange; with it, the
// exchange along +T and -T found the optimum, proven at 59.4 s in one run
// and left 5.6 % from the bound in another (the windows' proof unfinished).
bool AxisExchangeApplies(const dynamics::ThrusterSet& thrusters) {
  const std::vector<ThrusterGroup> axes = ThrusterAxes(thrusters);
  return axes.size() >= 2 && std::any_of(axes.begin(), axes.end(), [](const ThrusterGroup& a) {
           return a.thrusters.size() >= 2;
         });
}

milp::SolveResult SearchSchedule(const ScheduleMilp& milp, const milp::Solver& solver,
                                 const milp::SolveOptions& options, const SearchOptions& search,
                                 const std::vector<Eigen::VectorXd>& starts, SearchReport* report) {
  std::string error;
  if (milp.problem().input_mode != InputMode::kOnOff) {
    throw std::invalid_argument("SearchSchedule: on-off problems only");
  }
  if (!search.IsValid(&error) || !options.IsValid(&error)) throw std::invalid_argument(error);
  if (milp.problem().objective.kind != ObjectiveKind::kL1 &&
      milp.problem().objective.kind != ObjectiveKind::kDeltaV &&
      milp.problem().objective.kind != ObjectiveKind::kPropellant) {
    throw std::invalid_argument("SearchSchedule: unknown objective");
  }
  Search s(milp, solver, options, search, report);
  return s.Run(starts);
}

}  // namespace thrustsched::transcription
