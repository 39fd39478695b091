#include "milp/lp_data.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <unordered_set>
#include <utility>

#include "common/error.h"
#include "common/format.h"
#include "milp/internal/column_writer.h"

namespace thrustsched::milp {

using common::FormatG;

namespace {

std::string ColLabel(const LpData& lp, int j) {
  std::string label = "column " + std::to_string(j);
  if (static_cast<int>(lp.col_names.size()) == lp.num_cols()) {
    label += " '" + lp.col_names[static_cast<size_t>(j)] + "'";
  }
  return label;
}

std::string RowLabel(const LpData& lp, int i) {
  std::string label = "row " + std::to_string(i);
  if (static_cast<int>(lp.row_names.size()) == lp.num_rows()) {
    label += " '" + lp.row_names[static_cast<size_t>(i)] + "'";
  }
  return label;
}

// common::Fail with this struct's name in front of the message.
bool Fail(std::string* error, const std::string& message) {
  return common::Fail(error, "LpData '" + message);
}

void CheckSize(const LpData& lp, Eigen::Index size, const char* what) {
  if (size != lp.num_cols()) {
    throw std::invalid_argument(std::string("LpData::") + what + ": x has size " +
                                std::to_string(size) + ", expected " +
                                std::to_string(lp.num_cols()));
  }
}

}  // namespace

double IntegerLowerBound(double lower) {
  if (!std::isfinite(lower)) return lower;
  return std::ceil(lower - 1e-9 * std::max(1.0, std::abs(lower))) + 0.0;  // + 0.0: no -0
}

double IntegerUpperBound(double upper) {
  if (!std::isfinite(upper)) return upper;
  return std::floor(upper + 1e-9 * std::max(1.0, std::abs(upper))) + 0.0;
}

int LpData::num_integer_cols() const {
  return static_cast<int>(std::count_if(col_type.begin(), col_type.end(),
                                        [](VarType t) { return t != VarType::kContinuous; }));
}

double LpData::Objective(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  CheckSize(*this, x.size(), "Objective");
  if (col_cost.size() != x.size()) {
    throw std::invalid_argument("LpData::Objective: col_cost has size " +
                                std::to_string(col_cost.size()) + ", expected " +
                                std::to_string(x.size()));
  }
  return col_cost.dot(x) + objective_offset;
}

double LpData::MaxViolation(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  CheckSize(*this, x.size(), "MaxViolation");
  const int n = num_cols();
  double worst = 0.0;
  auto note = [&worst](double v) {
    if (std::isnan(v)) {
      worst = std::numeric_limits<double>::infinity();
    } else if (v > worst) {
      worst = v;
    }
  };
  for (int j = 0; j < n; ++j) {
    const double v = x[j];
    if (!std::isfinite(v)) {
      note(std::numeric_limits<double>::infinity());
      continue;
    }
    if (j < col_lower.size()) note(col_lower[j] - v);
    if (j < col_upper.size()) note(v - col_upper[j]);
    if (static_cast<size_t>(j) < col_type.size() &&
        col_type[static_cast<size_t>(j)] != VarType::kContinuous) {
      note(std::abs(v - std::round(v)));
    }
  }
  if (num_rows() > 0) {
    const Eigen::VectorXd activity = a_matrix * x;
    for (int i = 0; i < num_rows(); ++i) {
      if (i < row_lower.size()) note(row_lower[i] - activity[i]);
      if (i < row_upper.size()) note(activity[i] - row_upper[i]);
    }
  }
  return worst;
}

bool LpData::IsValid(std::string* error) const {
  const int n = num_cols();
  const int m = num_rows();
  auto size_error = [&](const char* field, Eigen::Index got, int want) {
    return Fail(error, name + "': " + field + " has size " + std::to_string(got) + ", expected " +
                           std::to_string(want));
  };
  if (col_cost.size() != n) return size_error("col_cost", col_cost.size(), n);
  if (col_lower.size() != n) return size_error("col_lower", col_lower.size(), n);
  if (col_upper.size() != n) return size_error("col_upper", col_upper.size(), n);
  if (static_cast<int>(col_type.size()) != n) {
    return size_error("col_type", static_cast<Eigen::Index>(col_type.size()), n);
  }
  if (row_lower.size() != m) return size_error("row_lower", row_lower.size(), m);
  if (row_upper.size() != m) return size_error("row_upper", row_upper.size(), m);
  if (!col_names.empty() && static_cast<int>(col_names.size()) != n) {
    return size_error("col_names", static_cast<Eigen::Index>(col_names.size()), n);
  }
  if (!row_names.empty() && static_cast<int>(row_names.size()) != m) {
    return size_error("row_names", static_cast<Eigen::Index>(row_names.size()), m);
  }
  if (!std::isfinite(objective_offset)) {
    return Fail(error,
                name + "': objective_offset must be finite, got " + FormatG(objective_offset, 17));
  }
  for (int j = 0; j < n; ++j) {
    const double lo = col_lower[j], up = col_upper[j];
    if (!std::isfinite(col_cost[j])) {
      return Fail(error, name + "': " + ColLabel(*this, j) + " cost must be finite, got " +
                             FormatG(col_cost[j], 17));
    }
    if (std::isnan(lo) || std::isnan(up) || lo > up || lo == kInfinity || up == -kInfinity) {
      return Fail(error, name + "': " + ColLabel(*this, j) + " has invalid bounds [" +
                             FormatG(lo, 17) + ", " + FormatG(up, 17) + "]");
    }
    if (col_type[static_cast<size_t>(j)] == VarType::kBinary && (lo < 0.0 || up > 1.0)) {
      return Fail(error, name + "': binary " + ColLabel(*this, j) + " has bounds [" +
                             FormatG(lo, 17) + ", " + FormatG(up, 17) + "] outside [0, 1]");
    }
  }
  for (int i = 0; i < m; ++i) {
    const double lo = row_lower[i], up = row_upper[i];
    if (std::isnan(lo) || std::isnan(up) || lo > up || lo == kInfinity || up == -kInfinity) {
      return Fail(error, name + "': " + RowLabel(*this, i) + " has invalid bounds [" +
                             FormatG(lo, 17) + ", " + FormatG(up, 17) + "]");
    }
  }
  for (int j = 0; j < n; ++j) {
    int previous_row = -1;
    for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(a_matrix, j); it;
         ++it) {
      const int i = static_cast<int>(it.row());
      if (!std::isfinite(it.value())) {
        return Fail(error, name + "': coefficient of " + ColLabel(*this, j) + " in " +
                               RowLabel(*this, i) + " must be finite, got " +
                               FormatG(it.value(), 17));
      }
      if (i <= previous_row) {
        return Fail(error, name + "': a_matrix " + ColLabel(*this, j) +
                               " has unsorted or duplicate row index " + std::to_string(i));
      }
      previous_row = i;
    }
  }
  auto unique_names = [&](const std::vector<std::string>& names, const char* what) {
    std::unordered_set<std::string_view> seen;
    seen.reserve(names.size());
    for (size_t k = 0; k < names.size(); ++k) {
      if (names[k].empty()) {
        return Fail(error, name + "': " + what + " name " + std::to_string(k) + " is empty");
      }
      if (!seen.insert(names[k]).second) {
        return Fail(error, name + "': duplicate " + what + " name '" + names[k] + "'");
      }
    }
    return true;
  };
  if (!unique_names(col_names, "column")) return false;
  if (!unique_names(row_names, "row")) return false;
  return true;
}

LpData RemoveFixedColumns(const LpData& lp, std::vector<int>* kept, bool* feasible,
                          std::vector<int>* kept_rows) {
  const int n = lp.num_cols(), m = lp.num_rows();
  std::vector<int> keep, new_index(static_cast<size_t>(n), -1);
  Eigen::VectorXd fixed_value = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < n; ++j) {
    if (lp.col_lower[j] == lp.col_upper[j]) {
      fixed_value[j] = lp.col_lower[j];
    } else {
      new_index[static_cast<size_t>(j)] = static_cast<int>(keep.size());
      keep.push_back(j);
    }
  }
  const Eigen::VectorXd constant = lp.a_matrix * fixed_value;  // per row
  std::vector<int> row_count(static_cast<size_t>(m), 0);
  for (int j : keep) {
    for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(lp.a_matrix, j); it;
         ++it) {
      ++row_count[static_cast<size_t>(it.row())];
    }
  }
  std::vector<int> new_row(static_cast<size_t>(m), -1);
  std::vector<int> rows;
  bool ok = true;
  for (int i = 0; i < m; ++i) {
    if (row_count[static_cast<size_t>(i)] > 0) {
      new_row[static_cast<size_t>(i)] = static_cast<int>(rows.size());
      rows.push_back(i);
      continue;
    }
    const double tol = 1e-9 * std::max(1.0, std::abs(constant[i]));
    if (constant[i] < lp.row_lower[i] - tol || constant[i] > lp.row_upper[i] + tol) ok = false;
  }
  LpData out;
  out.name = lp.name;
  out.sense = lp.sense;
  out.objective_offset = lp.objective_offset + lp.col_cost.dot(fixed_value);
  const int nk = static_cast<int>(keep.size()), mk = static_cast<int>(rows.size());
  out.col_cost.resize(nk);
  out.col_lower.resize(nk);
  out.col_upper.resize(nk);
  out.col_type.resize(static_cast<size_t>(nk));
  // new_row is increasing, so each kept column's rows stay sorted.
  long long kept_nonzeros = 0;
  for (int j : keep) kept_nonzeros += lp.a_matrix.col(j).nonZeros();
  internal::ColumnWriter matrix(&out.a_matrix, mk, nk, kept_nonzeros);
  for (int k = 0; k < nk; ++k) {
    const int j = keep[static_cast<size_t>(k)];
    out.col_cost[k] = lp.col_cost[j];
    out.col_lower[k] = lp.col_lower[j];
    out.col_upper[k] = lp.col_upper[j];
    out.col_type[static_cast<size_t>(k)] = lp.col_type[static_cast<size_t>(j)];
    for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(lp.a_matrix, j); it;
         ++it) {
      matrix.Push(new_row[static_cast<size_t>(it.row())], it.value());
    }
    matrix.EndColumn();
  }
  matrix.Finish();
  out.row_lower.resize(mk);
  out.row_upper.resize(mk);
  for (int r = 0; r < mk; ++r) {
    const int i = rows[static_cast<size_t>(r)];
    out.row_lower[r] = lp.row_lower[i] - constant[i];  // +-inf stay infinite
    out.row_upper[r] = lp.row_upper[i] - constant[i];
  }
  if (static_cast<int>(lp.col_names.size()) == n) {
    for (int j : keep) out.col_names.push_back(lp.col_names[static_cast<size_t>(j)]);
  }
  if (static_cast<int>(lp.row_names.size()) == m) {
    for (int i : rows) out.row_names.push_back(lp.row_names[static_cast<size_t>(i)]);
  }
  if (kept != nullptr) *kept = keep;
  if (kept_rows != nullptr) *kept_rows = rows;
  if (feasible != nullptr) *feasible = ok;
  return out;
}

void AppendRows(LpData* lp, const std::vector<SparseRow>& rows) {
  const int m = lp->num_rows(), n = lp->num_cols();
  const int added = static_cast<int>(rows.size());
  std::vector<std::vector<std::pair<int, double>>> by_column(static_cast<size_t>(n));
  for (int r = 0; r < added; ++r) {
    const SparseRow& row = rows[static_cast<size_t>(r)];
    const std::string label = "AppendRows: row " + std::to_string(m + r) +
                              (row.name.empty() ? std::string() : " '" + row.name + "'");
    if (row.columns.size() != row.coefficients.size()) {
      throw std::invalid_argument(label + ": " + std::to_string(row.columns.size()) +
                                  " columns but " + std::to_string(row.coefficients.size()) +
                                  " coefficients");
    }
    for (size_t k = 0; k < row.columns.size(); ++k) {
      const int j = row.columns[k];
      if (j < 0 || j >= n) {
        throw std::invalid_argument(label + ": column " + std::to_string(j) + " out of range [0, " +
                                    std::to_string(n) + ")");
      }
      auto& entries = by_column[static_cast<size_t>(j)];
      if (!entries.empty() && entries.back().first == m + r) {
        throw std::invalid_argument(label + ": column " + std::to_string(j) + " repeated");
      }
      if (row.coefficients[k] != 0.0) entries.emplace_back(m + r, row.coefficients[k]);
    }
  }
  // Each column: its old rows (below m, sorted), then the new ones in order.
  Eigen::Index nonzeros = lp->a_matrix.nonZeros();
  for (const auto& entries : by_column) nonzeros += static_cast<Eigen::Index>(entries.size());
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> old;
  old.swap(lp->a_matrix);
  internal::ColumnWriter matrix(&lp->a_matrix, m + added, n, nonzeros);
  for (int j = 0; j < n; ++j) {
    for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(old, j); it; ++it) {
      matrix.Push(static_cast<int>(it.row()), it.value());
    }
    for (const auto& [i, v] : by_column[static_cast<size_t>(j)]) matrix.Push(i, v);
    matrix.EndColumn();
  }
  matrix.Finish();
  // Rows named when the model's rows are (or, with none yet, its columns).
  const bool named = m > 0 ? static_cast<int>(lp->row_names.size()) == m : !lp->col_names.empty();
  lp->row_lower.conservativeResize(m + added);
  lp->row_upper.conservativeResize(m + added);
  for (int r = 0; r < added; ++r) {
    const SparseRow& row = rows[static_cast<size_t>(r)];
    lp->row_lower[m + r] = row.lower;
    lp->row_upper[m + r] = row.upper;
    if (named) lp->row_names.push_back(row.name.empty() ? "R" + std::to_string(m + r) : row.name);
  }
}

int AppendColumns(LpData* lp, const std::vector<ColumnSpec>& columns) {
  const int n = lp->num_cols();
  const int added = static_cast<int>(columns.size());
  for (int k = 0; k < added; ++k) {
    const ColumnSpec& c = columns[static_cast<size_t>(k)];
    if (std::isnan(c.lower) || std::isnan(c.upper) || std::isnan(c.cost) || c.lower > c.upper) {
      throw std::invalid_argument("AppendColumns: column " + std::to_string(n + k) +
                                  (c.name.empty() ? std::string() : " '" + c.name + "'") +
                                  ": bounds [" + common::FormatG(c.lower, 17) + ", " +
                                  common::FormatG(c.upper, 17) + "], cost " +
                                  common::FormatG(c.cost, 17));
    }
  }
  // Columns named when the model's columns are (or, with none yet, its rows).
  const bool named = n > 0 ? static_cast<int>(lp->col_names.size()) == n : !lp->row_names.empty();
  lp->a_matrix.conservativeResize(lp->num_rows(), n + added);
  lp->a_matrix.makeCompressed();
  lp->col_lower.conservativeResize(n + added);
  lp->col_upper.conservativeResize(n + added);
  lp->col_cost.conservativeResize(n + added);
  for (int k = 0; k < added; ++k) {
    const ColumnSpec& c = columns[static_cast<size_t>(k)];
    lp->col_lower[n + k] = c.lower;
    lp->col_upper[n + k] = c.upper;
    lp->col_cost[n + k] = c.cost;
    lp->col_type.push_back(c.type);
    if (named) lp->col_names.push_back(c.name.empty() ? "C" + std::to_string(n + k) : c.name);
  }
  return n;
}

}  // namespace thrustsched::milp
