// FleetMilp: the members' blocks and the coupling rows (transcription/fleet.h).
#include "transcription/fleet.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "common/format.h"
#include "transcription/collision_probability.h"
#include "transcription/internal/fleet_reach.h"
#include "transcription/internal/row_buffer.h"

namespace thrustsched::transcription {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Big-M with the same allowance as the Serra keep-out (transcription/keep_out.cc):
// never too small after rounding.
double BigM(double gap, double rhs) { return gap * (1.0 + 1e-9) + 1e-9 * std::abs(rhs); }

}  // namespace

FleetMilp::FleetMilp(const FleetProblem& fleet, const BuildOptions& options)
    : fleet_(fleet), options_(options), model_("fleet") {
  std::string error;
  if (!fleet_.IsValid(&error)) throw std::invalid_argument("fleet: " + error);
  if (options_.formulation != Formulation::kSparse) {
    throw std::invalid_argument(
        "fleet: the coupling rows need the sparse formulation (formulation = sparse)");
  }
  Compose();
  AddObjectiveAndBalance();
  AddCouplings();
  if (fleet_.keep_out) AddKeepOut();
  if (fleet_.assignment) AddAssignment();
  lp_ = model_.ToLpData();
  IndexKeepOutGroups();
  stats_.num_columns = lp_.num_cols();
  stats_.num_rows = lp_.num_rows();
  stats_.num_nonzeros = lp_.num_nonzeros();
  stats_.num_binaries = lp_.num_integer_cols();
}

// One block per member: its columns and rows copied from its own frozen
// model, names prefixed by the member's name.
void FleetMilp::Compose() {
  for (const FleetMember& m : fleet_.members) {
    members_.push_back(std::make_unique<ScheduleMilp>(m.problem, options_));
    const ScheduleMilp& milp = *members_.back();
    const milp::LpData& lp = milp.lp();
    if (lp.sense != milp::ObjectiveSense::kMinimize) {
      throw std::logic_error("fleet: member '" + m.name + "' is not a minimisation");
    }
    for (const std::string& why : milp.infeasibility_reasons())
      stats_.infeasibility_reasons.push_back(m.name + ": " + why);
    const int offset = model_.num_variables();
    offsets_.push_back(offset);
    for (int c = 0; c < lp.num_cols(); ++c) {
      model_.AddVariable(lp.col_lower[c], lp.col_upper[c], lp.col_type[c],
                         m.name + "." + lp.col_names[c]);
    }
    std::vector<milp::RowTriplet> triplets;
    triplets.reserve(lp.num_nonzeros());
    for (int c = 0; c < lp.num_cols(); ++c) {
      for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(lp.a_matrix, c); it;
           ++it)
        triplets.push_back({static_cast<int>(it.row()), offset + c, it.value()});
    }
    std::vector<std::string> names;
    names.reserve(lp.num_rows());
    for (const std::string& r : lp.row_names) names.push_back(m.name + "." + r);
    model_.AddRows(triplets, lp.row_lower, lp.row_upper, "", std::move(names));
  }
}

milp::LinearExpr FleetMilp::ConsumptionOf(int k) const {
  const milp::LpData& lp = members_[k]->lp();
  milp::LinearExpr e;
  for (int c = 0; c < lp.num_cols(); ++c) {
    if (lp.col_cost[c] != 0.0) e.AddTerm(model_.variable(offsets_[k] + c), lp.col_cost[c]);
  }
  e.AddConstant(lp.objective_offset);
  return e;
}

void FleetMilp::AddObjectiveAndBalance() {
  const int count = num_members();
  milp::LinearExpr total;
  for (int k = 0; k < count; ++k) total += ConsumptionOf(k);
  const FuelBalance& b = fleet_.balance;
  if (b.kind == FuelBalanceKind::kMinMax) {
    // Epigraph: t >= J_k for every member; min t + w sum_k J_k.
    const milp::Variable t = model_.AddContinuous(-kInf, kInf, "fleet_max_consumption");
    balance_column_ = t.index();
    for (int k = 0; k < count; ++k) {
      milp::LinearExpr e = ConsumptionOf(k);
      e.AddTerm(t, -1.0);
      model_.AddConstraint(e, -kInf, 0.0, "fleet_max_" + fleet_.members[k].name);
    }
    milp::LinearExpr objective = total;
    objective *= b.sum_weight;
    objective.AddTerm(t, 1.0);
    model_.Minimize(objective);
    return;
  }
  model_.Minimize(total);
  if (b.kind == FuelBalanceKind::kMaxExcessOverMean) {
    // K J_k - (1 + f) sum_l J_l <= 0.
    for (int k = 0; k < count; ++k) {
      milp::LinearExpr e = ConsumptionOf(k);
      e *= static_cast<double>(count);
      milp::LinearExpr mean = total;
      mean *= 1.0 + b.max_excess_fraction;
      e -= mean;
      model_.AddConstraint(e, -kInf, 0.0, "fleet_balance_" + fleet_.members[k].name);
    }
  }
}

milp::Variable FleetMilp::StateColumn(int k, int node, int component) const {
  return model_.variable(offsets_[k] + members_[k]->state(node, component).index());
}

void FleetMilp::AddCouplings() {
  internal::RowBuffer rows(/*scale=*/true);
  const int nn = members_[0]->problem().num_intervals();
  for (size_t c = 0; c < fleet_.couplings.size(); ++c) {
    const TerminalCoupling& t = fleet_.couplings[c];
    for (int r = 0; r < t.map.rows(); ++r) {
      rows.Begin();
      for (int side = 0; side < 2; ++side) {
        const int k = side == 0 ? t.member : t.reference;
        if (k < 0) continue;
        const Eigen::VectorXd s = internal::StateScale(*members_[k]);
        for (int i = 0; i < t.map.cols(); ++i) {
          rows.Coef(StateColumn(k, nn, i).index(), (side == 0 ? 1.0 : -1.0) * t.map(r, i) * s[i]);
        }
      }
      const double tol = t.tolerance.size() == 0 ? 0.0 : t.tolerance[r];
      rows.End(t.offset[r] - tol, t.offset[r] + tol,
               "fleet_coupling_" + std::to_string(c) + "_" + std::to_string(r));
    }
  }
  rows.Flush(&model_);
}

// Pairwise keep-out: outside the cube of half-size R around the other member.
namespace {

// The chance-constraint margin of each face of one pair at one check (zero
// without a risk threshold or covariances), Serra 2015 (4.19).
Eigen::Matrix<double, 6, 1> FaceMargins(const FleetProblem& fleet,
                                        const std::vector<internal::MemberReach>& reach,
                                        double quantile, int k, int l, int q) {
  Eigen::Matrix<double, 6, 1> margins = Eigen::Matrix<double, 6, 1>::Zero();
  if (quantile <= 0.0) return margins;
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
  for (int m : {k, l}) {
    const Eigen::MatrixXd& sigma = fleet.members[m].initial_covariance;
    if (sigma.size() != 0) c += reach[m].MapCovariance(q, sigma);
  }
  for (int f = 0; f < 6; ++f) margins[f] = quantile * std::sqrt(std::max(c(f / 2, f / 2), 0.0));
  return margins;
}

struct KeepOutFace {
  Eigen::Vector3d a;
  double big_m = 0.0;
  double rhs = 0.0;  // R plus the face's margin (m)
};

// The faces of one pair's check that the MILP must choose from: a face every
// pair of plans satisfies clears the check, a face none can satisfy is
// dropped (the one missed by least is kept for the infeasibility reason).
struct FaceChoice {
  bool clear = false;
  std::vector<KeepOutFace> faces;
  int impossible = 0;
  double closest_miss = kInf;
  KeepOutFace closest;
};

FaceChoice ChooseFaces(const internal::MemberReach& reach_k, const internal::MemberReach& reach_l,
                       int q, double radius, const Eigen::Matrix<double, 6, 1>& margins) {
  FaceChoice out;
  out.closest = {Eigen::Vector3d::Zero(), 0.0, radius};
  for (int f = 0; f < 6; ++f) {
    Eigen::Vector3d a = Eigen::Vector3d::Zero();
    a[f / 2] = f % 2 == 0 ? 1.0 : -1.0;
    const double rhs = radius + margins[f];
    const auto [lo_k, hi_k] = reach_k.Range(q, a);
    const auto [lo_l, hi_l] = reach_l.Range(q, a);
    const double low = lo_k - hi_l, high = hi_k - lo_l;
    if (low >= rhs) {
      out.clear = true;
      return out;
    }
    if (high < rhs) {
      ++out.impossible;
      if (rhs - high < out.closest_miss) out.closest_miss = rhs - high, out.closest = {a, 0.0, rhs};
    } else {
      out.faces.push_back({a, BigM(rhs - low, rhs), rhs});
    }
  }
  return out;
}

}  // namespace

void FleetMilp::AddKeepOut() {
  const FleetKeepOut& ko = *fleet_.keep_out;
  const int count = num_members();
  std::vector<internal::MemberReach> reach;
  for (int k = 0; k < count; ++k)
    reach.emplace_back(*members_[k], FleetPositionMaps(fleet_, k, ko.check_times_s),
                       ko.check_times_s, options_);
  if (ko.instantaneous_threshold > 0.0)
    stats_.keep_out_quantile = NormalQuantile(1.0 - ko.instantaneous_threshold);
  internal::RowBuffer rows(/*scale=*/true);
  std::vector<double> big_ms;
  for (int k = 0; k < count; ++k) {
    for (int l = k + 1; l < count; ++l) {
      const std::string pair = fleet_.members[k].name + "_" + fleet_.members[l].name;
      keep_out_rhs_.emplace_back();
      for (size_t q = 0; q < ko.check_times_s.size(); ++q) {
        ++stats_.keep_out_checks;
        const Eigen::Matrix<double, 6, 1> margins =
            FaceMargins(fleet_, reach, stats_.keep_out_quantile, k, l, static_cast<int>(q));
        keep_out_rhs_.back().push_back(Eigen::Matrix<double, 6, 1>::Constant(ko.half_size_m) +
                                       margins);
        stats_.keep_out_margin_max_m = std::max(stats_.keep_out_margin_max_m, margins.maxCoeff());
        FaceChoice choice =
            ChooseFaces(reach[k], reach[l], static_cast<int>(q), ko.half_size_m, margins);
        stats_.keep_out_faces_impossible += choice.impossible;
        std::vector<KeepOutFace>& faces = choice.faces;
        if (choice.clear) {
          ++stats_.keep_out_checks_clear;
          continue;
        }
        const std::string tag = pair + "_" + std::to_string(q);
        if (faces.empty()) {
          stats_.infeasibility_reasons.push_back(
              "keep-out " + pair + " at t = " + common::FormatG(ko.check_times_s[q], 10) +
              " s: no face of the cube (with its margin) can be left within the thrust bounds "
              "(missed by " +
              common::FormatG(choice.closest_miss, 10) + " m)");
          faces.push_back(choice.closest);
        }
        std::vector<milp::Variable> w;
        if (faces.size() > 1) {
          for (size_t f = 0; f < faces.size(); ++f) {
            w.push_back(model_.AddBinary("fleet_keep_out_w_" + tag + "_" + std::to_string(f)));
            big_ms.push_back(faces[f].big_m);
          }
          stats_.keep_out_binaries += static_cast<int>(faces.size());
        } else {
          ++stats_.keep_out_single_face;
        }
        for (size_t f = 0; f < faces.size(); ++f) {
          rows.Begin();
          double rhs = faces[f].rhs;
          for (int side = 0; side < 2; ++side) {
            const int member = side == 0 ? k : l;
            const double sign = side == 0 ? 1.0 : -1.0;
            rhs -= sign *
                   reach[member].AddPositionTerms(q, faces[f].a, sign, offsets_[member],
                                                  [&](int col, double v) { rows.Coef(col, v); });
          }
          if (!w.empty()) rows.Coef(w[f].index(), faces[f].big_m);
          rows.End(rhs, kInf, "fleet_keep_out_" + tag + "_" + std::to_string(f));
        }
        if (!w.empty()) {
          KeepOutGroup group;  // its rows are indexed once the model is frozen
          for (const milp::Variable& v : w) group.binaries.push_back(v.index());
          keep_out_groups_.groups.push_back(std::move(group));
          keep_out_tags_.push_back(tag);
          model_.AddConstraint(milp::LinearExpr::Sum(w), -kInf, static_cast<double>(w.size()) - 1.0,
                               "fleet_keep_out_pick_" + tag);
        }
      }
    }
  }
  rows.Flush(&model_);
  if (!big_ms.empty()) {
    stats_.big_m_min_m = *std::min_element(big_ms.begin(), big_ms.end());
    stats_.big_m_max_m = *std::max_element(big_ms.begin(), big_ms.end());
  }
}

// Richards et al. 2002: z_is = 1 puts member i on slot s.
void FleetMilp::AddAssignment() {
  const SlotAssignment& a = *fleet_.assignment;
  const int count = static_cast<int>(a.members.size());
  const double t_final = members_[0]->problem().grid.back();
  auto reach_of = [&](int k) {
    return internal::MemberReach(*members_[k], {a.map}, {t_final}, options_);
  };
  std::optional<internal::MemberReach> ref;
  if (a.reference >= 0) ref.emplace(reach_of(a.reference));
  slot_binaries_.assign(count, {});
  for (int i = 0; i < count; ++i) {
    for (int s = 0; s < count; ++s) {
      slot_binaries_[i].push_back(model_.AddBinary(
          "fleet_slot_" + fleet_.members[a.members[i]].name + "_" + std::to_string(s)));
    }
  }
  stats_.assignment_binaries = count * count;
  for (int i = 0; i < count; ++i) {
    model_.AddConstraint(milp::LinearExpr::Sum(slot_binaries_[i]), 1.0, 1.0,
                         "fleet_slot_member_" + std::to_string(i));
    std::vector<milp::Variable> col;
    for (int s = 0; s < count; ++s) col.push_back(slot_binaries_[s][i]);
    model_.AddConstraint(milp::LinearExpr::Sum(col), 1.0, 1.0, "fleet_slot_" + std::to_string(i));
  }
  internal::RowBuffer rows(/*scale=*/true);
  double m_max = 0.0;
  for (int i = 0; i < count; ++i) {
    const int k = a.members[i];
    const internal::MemberReach reach = reach_of(k);
    for (int r = 0; r < a.map.rows(); ++r) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(a.map.rows());
      e[r] = 1.0;
      auto [low, high] = reach.Range(0, e);
      if (ref) {
        const auto [lo_ref, hi_ref] = ref->Range(0, e);
        low -= hi_ref;
        high -= lo_ref;
      }
      const double tol = a.tolerance.size() == 0 ? 0.0 : a.tolerance[r];
      for (int s = 0; s < count; ++s) {
        const milp::Variable z = slot_binaries_[i][s];
        const double upper = a.slots[s][r] + tol, lower = a.slots[s][r] - tol;
        if (upper < low || lower > high) {  // no plan reaches this slot
          model_.SetBounds(z, 0.0, 0.0);
          continue;
        }
        const double m_up = BigM(std::max(high - upper, 0.0), upper);
        const double m_down = BigM(std::max(lower - low, 0.0), lower);
        m_max = std::max({m_max, m_up, m_down});
        for (int sense = 0; sense < 2; ++sense) {
          rows.Begin();
          double shift = 0.0;  // the drift terms of the map at t_N
          shift += reach.AddPositionTerms(0, e, 1.0, offsets_[k],
                                          [&](int c, double v) { rows.Coef(c, v); });
          if (ref) {
            shift -= ref->AddPositionTerms(0, e, -1.0, offsets_[a.reference],
                                           [&](int c, double v) { rows.Coef(c, v); });
          }
          const std::string name = "fleet_slot_" + fleet_.members[k].name + "_" +
                                   std::to_string(s) + "_" + std::to_string(r);
          if (sense == 0) {  // v + M_up z <= target + tol + M_up
            rows.Coef(z.index(), m_up);
            rows.End(-kInf, upper + m_up - shift, name + "_up");
          } else {  // v - M_down z >= target - tol - M_down
            rows.Coef(z.index(), -m_down);
            rows.End(lower - m_down - shift, kInf, name + "_down");
          }
        }
      }
    }
  }
  rows.Flush(&model_);
  stats_.assignment_big_m_max = m_max;
}

Eigen::VectorXd FleetMilp::MemberColumns(const Eigen::VectorXd& x, int k) const {
  if (x.size() != lp_.num_cols()) {
    throw std::invalid_argument("FleetMilp: solution has " + std::to_string(x.size()) +
                                " values, the model has " + std::to_string(lp_.num_cols()) +
                                " columns");
  }
  return x.segment(offsets_.at(k), members_.at(k)->lp().num_cols());
}

std::vector<Schedule> FleetMilp::Decode(const Eigen::VectorXd& x) const {
  std::vector<Schedule> out;
  for (int k = 0; k < num_members(); ++k) out.push_back(members_[k]->Decode(MemberColumns(x, k)));
  return out;
}

std::vector<double> FleetMilp::Consumptions(const Eigen::VectorXd& x) const {
  std::vector<double> out;
  for (int k = 0; k < num_members(); ++k)
    out.push_back(members_[k]->lp().Objective(MemberColumns(x, k)));
  return out;
}

std::vector<int> FleetMilp::Slots(const Eigen::VectorXd& x) const {
  std::vector<int> out;
  for (const auto& row : slot_binaries_) {
    int best = 0;
    for (size_t s = 0; s < row.size(); ++s) {
      if (x[row[s].index()] > x[row[best].index()]) best = static_cast<int>(s);
    }
    out.push_back(best);
  }
  return out;
}

// The keep-out rows by name: they were buffered and rescaled, so their
// indices are known once the model is frozen.
void FleetMilp::IndexKeepOutGroups() {
  if (keep_out_tags_.empty()) return;
  std::unordered_map<std::string, int> rows;
  for (int r = 0; r < lp_.num_rows(); ++r) rows.emplace(lp_.row_names[r], r);
  for (size_t g = 0; g < keep_out_tags_.size(); ++g) {
    KeepOutGroup& group = keep_out_groups_.groups[g];
    for (size_t f = 0; f < group.binaries.size(); ++f)
      group.rows.push_back(
          rows.at("fleet_keep_out_" + keep_out_tags_[g] + "_" + std::to_string(f)));
  }
}

bool KeepsFleetRows(const FleetMilp& milp, const Eigen::VectorXd& x, double* objective) {
  if (milp.lp().MaxViolation(x) > kStartFeasibility) return false;
  *objective = milp.lp().Objective(x);
  return true;
}

Eigen::Matrix<double, 6, 1> FleetMilp::KeepOutFaceRhs(int k, int l, int q) const {
  const int count = num_members();
  if (!fleet_.keep_out || k < 0 || k >= l || l >= count)
    throw std::out_of_range("FleetMilp::KeepOutFaceRhs: no keep-out check for members " +
                            std::to_string(k) + ", " + std::to_string(l));
  const int pair = k * count - k * (k + 1) / 2 + (l - k - 1);
  return keep_out_rhs_.at(pair).at(q);
}

std::vector<std::vector<int>> FleetMilp::KeepOutRows(int k, int l) const {
  std::vector<std::vector<int>> out;
  if (!fleet_.keep_out) return out;
  if (k > l) std::swap(k, l);
  const std::string pair = fleet_.members.at(k).name + "_" + fleet_.members.at(l).name;
  std::unordered_map<std::string, int> rows;
  for (int r = 0; r < lp_.num_rows(); ++r) rows.emplace(lp_.row_names[r], r);
  for (size_t q = 0; q < fleet_.keep_out->check_times_s.size(); ++q) {
    const std::string tag = pair + "_" + std::to_string(q);
    out.emplace_back();
    for (int f = 0; f < 6; ++f) {
      const auto it = rows.find("fleet_keep_out_" + tag + "_" + std::to_string(f));
      if (it != rows.end()) out.back().push_back(it->second);
    }
    const auto pick = rows.find("fleet_keep_out_pick_" + tag);
    if (pick != rows.end()) out.back().push_back(pick->second);
  }
  return out;
}

Eigen::VectorXd FleetMilp::StartFromPatterns(const std::vector<Eigen::MatrixXi>& patterns,
                                             const std::vector<int>& slots) const {
  if (static_cast<int>(patterns.size()) != num_members()) {
    throw std::invalid_argument("FleetMilp::StartFromPatterns: " + std::to_string(patterns.size()) +
                                " patterns for " + std::to_string(num_members()) + " members");
  }
  const size_t assigned = fleet_.assignment ? fleet_.assignment->members.size() : 0;
  if (slots.size() != assigned) {
    throw std::invalid_argument("FleetMilp::StartFromPatterns: " + std::to_string(slots.size()) +
                                " slots for " + std::to_string(assigned) + " assigned members");
  }
  Eigen::VectorXd x = Eigen::VectorXd::Zero(lp_.num_cols());
  for (int k = 0; k < num_members(); ++k) {
    const Eigen::VectorXd block = members_[k]->StartFromPattern(patterns[k]);
    x.segment(offsets_[k], block.size()) = block;
  }
  for (size_t i = 0; i < slots.size(); ++i) {
    if (slots[i] < 0 || slots[i] >= static_cast<int>(assigned)) {
      throw std::invalid_argument("FleetMilp::StartFromPatterns: slot " + std::to_string(slots[i]) +
                                  " out of range");
    }
    x[slot_binaries_[i][slots[i]].index()] = 1.0;
  }
  if (balance_column_ >= 0) {  // the epigraph column at the largest member objective
    double most = -kInf;
    for (int k = 0; k < num_members(); ++k) {
      const Eigen::VectorXd block = x.segment(offsets_[k], members_[k]->lp().num_cols());
      most = std::max(most, members_[k]->lp().Objective(block));
    }
    x[balance_column_] = most;
  }
  CompleteKeepOut(lp_, keep_out_groups_, &x);
  return x;
}

}  // namespace thrustsched::transcription
