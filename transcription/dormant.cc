#include "transcription/dormant.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "milp/lp_blocks.h"

namespace thrustsched::transcription {

namespace {

constexpr int kNotEncoding = -1;
constexpr int kShared = -2;  // an encoding column of no single thruster (thesis gamma)

// Thruster owning each column of the operational encoding, kShared for the
// encoding's shared columns, kNotEncoding for every other column.
std::vector<int> EncodingOwners(const OperationalEncoding& enc, int num_cols) {
  std::vector<int> owner(static_cast<size_t>(num_cols), kNotEncoding);
  auto mark = [&owner](const std::vector<std::vector<milp::Variable>>& vars) {
    for (size_t i = 0; i < vars.size(); ++i) {
      for (const milp::Variable& v : vars[i])
        owner[static_cast<size_t>(v.index())] = static_cast<int>(i);
    }
  };
  mark(enc.on);
  mark(enc.start);
  mark(enc.stop);
  for (const milp::Variable& v : enc.gamma) owner[static_cast<size_t>(v.index())] = kShared;
  return owner;
}

// Rows holding only encoding columns, of two or more owners: the rows by
// which the rules tie thrusters together.
std::vector<bool> CouplingRows(const milp::LpData& lp, const std::vector<int>& owner) {
  const int m = lp.num_rows();
  std::vector<bool> other_column(static_cast<size_t>(m), false),
      several(static_cast<size_t>(m), false);
  std::vector<int> first_owner(static_cast<size_t>(m), kNotEncoding);
  for (int j = 0; j < lp.num_cols(); ++j) {
    const int o = owner[static_cast<size_t>(j)];
    for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(lp.a_matrix, j); it;
         ++it) {
      const auto r = static_cast<size_t>(it.row());
      if (o == kNotEncoding) {
        other_column[r] = true;
      } else if (first_owner[r] == kNotEncoding) {
        first_owner[r] = o;
      } else if (first_owner[r] != o) {
        several[r] = true;
      }
    }
  }
  std::vector<bool> coupling(static_cast<size_t>(m), false);
  for (size_t r = 0; r < coupling.size(); ++r) coupling[r] = several[r] && !other_column[r];
  return coupling;
}

}  // namespace

bool DormantThrusters::any() const {
  return std::any_of(thruster.begin(), thruster.end(), [](bool b) { return b; });
}

std::string DormantThrusters::Names(const ScheduleMilp& milp) const {
  std::string out;
  for (size_t i = 0; i < thruster.size(); ++i) {
    if (!thruster[i]) continue;
    out += (out.empty() ? "" : ", ") + milp.problem().thrusters.thruster(static_cast<int>(i)).name;
  }
  return out;
}

DormantThrusters FindDormantThrusters(const ScheduleMilp& milp) {
  const milp::LpData& lp = milp.lp();
  const OperationalEncoding& enc = milp.encoding();
  DormantThrusters d;
  d.thruster.assign(static_cast<size_t>(enc.num_thrusters), false);
  d.column.assign(static_cast<size_t>(lp.num_cols()), false);
  if (milp.problem().input_mode != InputMode::kOnOff || enc.num_intervals == 0 ||
      lp.sense != milp::ObjectiveSense::kMinimize || (lp.col_cost.array() < 0.0).any()) {
    return d;
  }
  const std::vector<int> owner = EncodingOwners(enc, lp.num_cols());
  const std::vector<bool> coupling = CouplingRows(lp, owner);
  const std::vector<int> block = milp::ColumnBlocks(lp, coupling, &d.num_blocks);
  if (d.num_blocks < 2) return d;

  d.all_off = milp.StartFromPattern(Eigen::MatrixXi::Zero(enc.num_thrusters, enc.num_intervals));
  // A block is broken by the all-off point if one of its own rows or columns is.
  std::vector<bool> broken(static_cast<size_t>(d.num_blocks), false);
  constexpr double kTolerance = ScheduleMilp::kPatternFeasibilityTolerance;
  for (int j = 0; j < lp.num_cols(); ++j) {
    const double v = d.all_off[j];
    if (!std::isfinite(v) || v < lp.col_lower[j] - kTolerance || v > lp.col_upper[j] + kTolerance) {
      broken[static_cast<size_t>(block[static_cast<size_t>(j)])] = true;
    }
  }
  const Eigen::VectorXd activity = lp.a_matrix * d.all_off;
  std::vector<int> row_block(static_cast<size_t>(lp.num_rows()), -1);
  for (int j = 0; j < lp.num_cols(); ++j) {
    for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(lp.a_matrix, j); it;
         ++it) {
      row_block[static_cast<size_t>(it.row())] = block[static_cast<size_t>(j)];
    }
  }
  for (int r = 0; r < lp.num_rows(); ++r) {
    if (coupling[static_cast<size_t>(r)] || row_block[static_cast<size_t>(r)] < 0) continue;
    if (activity[r] < lp.row_lower[r] - kTolerance || activity[r] > lp.row_upper[r] + kTolerance) {
      broken[static_cast<size_t>(row_block[static_cast<size_t>(r)])] = true;
    }
  }
  std::vector<bool> dormant_block(static_cast<size_t>(d.num_blocks), false);
  for (int i = 0; i < enc.num_thrusters; ++i) {
    bool off = true;
    for (const milp::Variable& v : enc.on[static_cast<size_t>(i)]) {
      off = off && !broken[static_cast<size_t>(block[static_cast<size_t>(v.index())])];
    }
    d.thruster[static_cast<size_t>(i)] = off;
    if (!off) continue;
    for (const milp::Variable& v : enc.on[static_cast<size_t>(i)]) {
      dormant_block[static_cast<size_t>(block[static_cast<size_t>(v.index())])] = true;
    }
  }
  for (int j = 0; j < lp.num_cols(); ++j) {
    d.column[static_cast<size_t>(j)] =
        dormant_block[static_cast<size_t>(block[static_cast<size_t>(j)])];
  }
  return d;
}

}  // namespace thrustsched::transcription
