#include "milp/model.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unordered_set>
#include <utility>

#include "common/format.h"

namespace thrustsched::milp {

using common::FormatG;

namespace {

std::uint32_t NextModelId() {
  static std::atomic<std::uint32_t> counter{1};
  for (;;) {
    const std::uint32_t id = counter.fetch_add(1, std::memory_order_relaxed);
    if (id != 0 && id != LinearExpr::kMixedModels) return id;
  }
}

void AppendInt(std::string* s, long long v) {
  char buf[24];
  const auto res = std::to_chars(buf, buf + sizeof(buf), v);
  s->append(buf, res.ptr);
}

// Splits "p[k]" (k canonical decimal: no sign, no leading zero) into p and k.
bool SplitBracketed(const std::string& name, std::string* prefix, long long* k) {
  if (name.size() < 4 || name.back() != ']') return false;
  const size_t open = name.rfind('[');
  if (open == std::string::npos || open == 0) return false;
  const size_t first = open + 1, last = name.size() - 1;  // digits in [first, last)
  if (first >= last) return false;
  if (name[first] == '0' && last - first > 1) return false;
  long long value = 0;
  for (size_t i = first; i < last; ++i) {
    if (name[i] < '0' || name[i] > '9') return false;
    if (value > (std::numeric_limits<long long>::max() - 9) / 10) return false;
    value = value * 10 + (name[i] - '0');
  }
  *prefix = name.substr(0, open);
  *k = value;
  return true;
}

}  // namespace

// ---------------------------------------------------------------- NameTable

void Model::NameTable::CheckNew(const std::string& name, const char* what) const {
  if (name.empty()) return;
  if (explicit_index_.count(name) != 0) {
    throw std::invalid_argument(std::string("duplicate ") + what + " name '" + name + "'");
  }
  std::string prefix;
  long long k = 0;
  if (!blocks_.empty() && SplitBracketed(name, &prefix, &k)) {
    const auto it = block_index_.find(prefix);
    if (it != block_index_.end() && k < blocks_[static_cast<size_t>(it->second)].count) {
      throw std::invalid_argument(std::string("duplicate ") + what + " name '" + name +
                                  "' (already given by block '" + prefix + "')");
    }
  }
}

void Model::NameTable::CheckNewBlock(std::string_view prefix, int count, const char* what) const {
  if (prefix.empty()) return;
  const std::string p(prefix);
  if (block_index_.count(p) != 0) {
    throw std::invalid_argument(std::string("duplicate ") + what + " block prefix '" + p +
                                "' (its names " + p + "[i] would repeat)");
  }
  const auto it = bracketed_.find(p);
  if (it != bracketed_.end()) {
    for (long long k : it->second) {
      if (k < count) {
        throw std::invalid_argument(std::string("duplicate ") + what + " name '" + p + "[" +
                                    std::to_string(k) + "]' (block '" + p +
                                    "' would repeat an explicit name)");
      }
    }
  }
}

void Model::NameTable::AddUnnamed(int count) {
  slot_.insert(slot_.end(), static_cast<size_t>(count), -1);
}

void Model::NameTable::AddNamed(std::string name) {
  if (name.empty()) {
    slot_.push_back(-1);
    return;
  }
  std::string prefix;
  long long k = 0;
  if (SplitBracketed(name, &prefix, &k)) bracketed_[prefix].push_back(k);
  explicit_index_.emplace(name, size());
  slot_.push_back(static_cast<int>(explicit_.size()));
  explicit_.push_back(std::move(name));
}

void Model::NameTable::AddBlock(std::string_view prefix, int count) {
  if (prefix.empty()) {
    AddUnnamed(count);
    return;
  }
  const int block = static_cast<int>(blocks_.size());
  blocks_.push_back(Block{std::string(prefix), size(), count});
  block_index_.emplace(std::string(prefix), block);
  slot_.insert(slot_.end(), static_cast<size_t>(count), -2 - block);
}

std::string Model::NameTable::Generated(int index) const {
  std::string base(1, generated_prefix_);
  AppendInt(&base, index);
  if (explicit_index_.empty() || explicit_index_.count(base) == 0) return base;
  // Someone named another entry exactly like our generated name: add a suffix
  // (generated bases never contain '_', block names always contain '[').
  for (long long suffix = 1;; ++suffix) {
    std::string candidate = base + "_";
    AppendInt(&candidate, suffix);
    if (explicit_index_.count(candidate) == 0) return candidate;
  }
}

std::string Model::NameTable::Name(int index) const {
  const int slot = slot_[static_cast<size_t>(index)];
  if (slot >= 0) return explicit_[static_cast<size_t>(slot)];
  if (slot == -1) return Generated(index);
  const Block& b = blocks_[static_cast<size_t>(-2 - slot)];
  std::string name;
  name.reserve(b.prefix.size() + 12);
  name += b.prefix;
  name += '[';
  AppendInt(&name, index - b.start);
  name += ']';
  return name;
}

void Model::NameTable::AppendAll(std::vector<std::string>* out) const {
  out->reserve(out->size() + slot_.size());
  for (int i = 0; i < size(); ++i) out->push_back(Name(i));
}

// -------------------------------------------------------------------- Model

Model::Model(std::string name) : name_(std::move(name)), id_(NextModelId()) {}

void Model::CheckOwned(Variable v, std::string_view what) const {
  if (!v.is_valid()) {
    throw std::invalid_argument("Model '" + name_ + "': " + std::string(what) +
                                ": invalid (default-constructed) Variable");
  }
  if (v.model_id() != id_) {
    throw std::invalid_argument("Model '" + name_ + "': " + std::string(what) +
                                ": variable with index " + std::to_string(v.index()) +
                                " belongs to model #" + std::to_string(v.model_id()) +
                                ", not to this model #" + std::to_string(id_));
  }
  if (v.index() >= num_variables()) {
    throw std::invalid_argument("Model '" + name_ + "': " + std::string(what) +
                                ": variable index " + std::to_string(v.index()) +
                                " out of range (model has " + std::to_string(num_variables()) +
                                " variables)");
  }
}

std::string Model::ColumnLabel(int index) const {
  return "variable '" + col_names_.Name(index) + "'";
}

void Model::CheckColumnBounds(double lower, double upper, VarType type,
                              const std::string& label) const {
  const std::string where = "Model '" + name_ + "': " + label;
  if (std::isnan(lower) || std::isnan(upper)) {
    throw std::invalid_argument(where + ": bounds must not be NaN, got [" + FormatG(lower, 17) +
                                ", " + FormatG(upper, 17) + "]");
  }
  if (lower > upper) {
    throw std::invalid_argument(where + ": lower bound " + FormatG(lower, 17) + " > upper bound " +
                                FormatG(upper, 17));
  }
  if (lower == kInfinity || upper == -kInfinity) {
    throw std::invalid_argument(where + ": bounds [" + FormatG(lower, 17) + ", " +
                                FormatG(upper, 17) + "] leave no finite value");
  }
  if (type == VarType::kBinary && (lower < 0.0 || upper > 1.0)) {
    throw std::invalid_argument(where + ": binary bounds [" + FormatG(lower, 17) + ", " +
                                FormatG(upper, 17) + "] outside [0, 1]");
  }
}

void Model::CheckRowBounds(double lower, double upper, const std::string& label) const {
  const std::string where = "Model '" + name_ + "': " + label;
  if (std::isnan(lower) || std::isnan(upper)) {
    throw std::invalid_argument(where + ": bounds must not be NaN, got [" + FormatG(lower, 17) +
                                ", " + FormatG(upper, 17) +
                                "] (or the expression constant is not finite)");
  }
  if (lower > upper) {
    throw std::invalid_argument(where + ": lower bound " + FormatG(lower, 17) + " > upper bound " +
                                FormatG(upper, 17));
  }
  if (lower == kInfinity || upper == -kInfinity) {
    throw std::invalid_argument(where + ": bounds [" + FormatG(lower, 17) + ", " +
                                FormatG(upper, 17) + "] can never hold");
  }
}

Variable Model::AddVariable(double lower, double upper, VarType type, std::string name) {
  const int index = num_variables();
  std::string label =
      name.empty() ? "variable 'c" + std::to_string(index) + "'" : "variable '" + name + "'";
  CheckColumnBounds(lower, upper, type, label);
  try {
    col_names_.CheckNew(name, "variable");
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("Model '" + name_ + "': " + e.what());
  }
  col_lower_.push_back(lower);
  col_upper_.push_back(upper);
  col_cost_.push_back(0.0);
  col_type_.push_back(type);
  col_names_.AddNamed(std::move(name));
  return Variable(index, id_);
}

Variable Model::AddContinuous(double lower, double upper, std::string name) {
  return AddVariable(lower, upper, VarType::kContinuous, std::move(name));
}

Variable Model::AddInteger(double lower, double upper, std::string name) {
  return AddVariable(lower, upper, VarType::kInteger, std::move(name));
}

Variable Model::AddBinary(std::string name) {
  return AddVariable(0.0, 1.0, VarType::kBinary, std::move(name));
}

VarBlock Model::AddVariables(int count, double lower, double upper, VarType type,
                             std::string_view name_prefix) {
  if (count < 0) {
    throw std::invalid_argument("Model '" + name_ + "': AddVariables: count must be >= 0, got " +
                                std::to_string(count));
  }
  CheckColumnBounds(lower, upper, type, "variable block '" + std::string(name_prefix) + "'");
  try {
    col_names_.CheckNewBlock(name_prefix, count, "variable");
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("Model '" + name_ + "': " + e.what());
  }
  const int start = num_variables();
  const size_t n = static_cast<size_t>(count);
  col_lower_.insert(col_lower_.end(), n, lower);
  col_upper_.insert(col_upper_.end(), n, upper);
  col_cost_.insert(col_cost_.end(), n, 0.0);
  col_type_.insert(col_type_.end(), n, type);
  col_names_.AddBlock(name_prefix, count);
  return VarBlock(start, count, id_);
}

void Model::SetBounds(Variable v, double lower, double upper) {
  CheckOwned(v, "SetBounds");
  CheckColumnBounds(lower, upper, col_type_[static_cast<size_t>(v.index())],
                    ColumnLabel(v.index()));
  col_lower_[static_cast<size_t>(v.index())] = lower;
  col_upper_[static_cast<size_t>(v.index())] = upper;
}

void Model::SetType(Variable v, VarType type) {
  CheckOwned(v, "SetType");
  const size_t j = static_cast<size_t>(v.index());
  CheckColumnBounds(col_lower_[j], col_upper_[j], type, ColumnLabel(v.index()));
  col_type_[j] = type;
}

Constraint Model::AddConstraint(const LinearExpr& expr, double lower, double upper,
                                std::string name) {
  const int row = num_constraints();
  const std::string label =
      name.empty() ? "row 'r" + std::to_string(row) + "'" : "row '" + name + "'";
  const std::string where = "Model '" + name_ + "': " + label;
  if (expr.model_id() == LinearExpr::kMixedModels) {
    throw std::invalid_argument(where + ": expression mixes variables of several models");
  }
  if (expr.model_id() != 0 && expr.model_id() != id_) {
    throw std::invalid_argument(where + ": expression uses variables of model #" +
                                std::to_string(expr.model_id()) + ", not of this model #" +
                                std::to_string(id_));
  }
  LinearExpr e = expr;
  e.Canonicalize();
  for (const LinearExpr::Term& t : e.terms()) {
    if (t.index < 0 || t.index >= num_variables()) {
      throw std::invalid_argument(where + ": invalid variable handle (index " +
                                  std::to_string(t.index) + ")");
    }
    if (!std::isfinite(t.coefficient)) {
      throw std::invalid_argument(where + ": coefficient of " + ColumnLabel(t.index) +
                                  " must be finite, got " + FormatG(t.coefficient, 17));
    }
  }
  const double c = expr.constant();
  if (!std::isfinite(c)) {
    throw std::invalid_argument(where + ": expression constant must be finite, got " +
                                FormatG(c, 17));
  }
  if (std::isnan(lower) || std::isnan(upper)) CheckRowBounds(lower, upper, label);
  const double lo = std::isfinite(lower) ? lower - c : lower;
  const double up = std::isfinite(upper) ? upper - c : upper;
  CheckRowBounds(lo, up, label);
  try {
    row_names_.CheckNew(name, "row");
  } catch (const std::invalid_argument& ex) {
    throw std::invalid_argument("Model '" + name_ + "': " + ex.what());
  }
  // (No reserve here: an exact reserve per row would reallocate every time.)
  for (const LinearExpr::Term& t : e.terms()) entries_.push_back({row, t.index, t.coefficient});
  row_lower_.push_back(lo);
  row_upper_.push_back(up);
  row_names_.AddNamed(std::move(name));
  return Constraint{row};
}

Constraint Model::AddConstraint(const BoundedLinearExpr& c, std::string name) {
  return AddConstraint(c.expr, c.lower, c.upper, std::move(name));
}

ConstraintBlock Model::AddRows(const std::vector<RowTriplet>& triplets,
                               const Eigen::Ref<const Eigen::VectorXd>& lower,
                               const Eigen::Ref<const Eigen::VectorXd>& upper,
                               std::string_view name_prefix, std::vector<std::string> names) {
  const std::string where = "Model '" + name_ + "': AddRows";
  const Eigen::Index m64 = lower.size();
  if (upper.size() != m64) {
    throw std::invalid_argument(where + ": lower has size " + std::to_string(lower.size()) +
                                " but upper has size " + std::to_string(upper.size()));
  }
  if (!names.empty() && static_cast<Eigen::Index>(names.size()) != m64) {
    throw std::invalid_argument(where + ": " + std::to_string(names.size()) + " names for " +
                                std::to_string(m64) + " rows");
  }
  if (m64 > std::numeric_limits<int>::max() - num_constraints()) {
    throw std::invalid_argument(where + ": too many rows");
  }
  const int m = static_cast<int>(m64);
  const int base = num_constraints();
  auto row_label = [&](int i) {
    if (!names.empty() && !names[static_cast<size_t>(i)].empty()) {
      return "row '" + names[static_cast<size_t>(i)] + "'";
    }
    if (names.empty() && !name_prefix.empty()) {
      return "row '" + std::string(name_prefix) + "[" + std::to_string(i) + "]'";
    }
    return "row 'r" + std::to_string(base + i) + "'";
  };
  // Validate bounds.
  for (int i = 0; i < m; ++i) CheckRowBounds(lower[i], upper[i], row_label(i));
  // Validate triplets and bucket them by row (counting sort, O(nnz + m)).
  const int n = num_variables();
  std::vector<int> start(static_cast<size_t>(m) + 1, 0);
  for (const RowTriplet& t : triplets) {
    if (t.row < 0 || t.row >= m) {
      throw std::invalid_argument(where + ": triplet row " + std::to_string(t.row) +
                                  " outside [0, " + std::to_string(m) + ")");
    }
    if (t.column < 0 || t.column >= n) {
      throw std::invalid_argument(where + ": " + row_label(t.row) + ": column " +
                                  std::to_string(t.column) + " outside [0, " + std::to_string(n) +
                                  ")");
    }
    if (!std::isfinite(t.value)) {
      throw std::invalid_argument("Model '" + name_ + "': " + row_label(t.row) +
                                  ": coefficient of " + ColumnLabel(t.column) +
                                  " must be finite, got " + FormatG(t.value, 17));
    }
    ++start[static_cast<size_t>(t.row) + 1];
  }
  for (int i = 0; i < m; ++i) start[static_cast<size_t>(i) + 1] += start[static_cast<size_t>(i)];
  std::vector<std::pair<int, double>> bucket(triplets.size());
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (const RowTriplet& t : triplets) {
      bucket[static_cast<size_t>(next[static_cast<size_t>(t.row)]++)] = {t.column, t.value};
    }
  }
  std::vector<Entry> block;
  block.reserve(triplets.size());
  for (int i = 0; i < m; ++i) {
    auto first = bucket.begin() + start[static_cast<size_t>(i)];
    auto last = bucket.begin() + start[static_cast<size_t>(i) + 1];
    if (!std::is_sorted(first, last,
                        [](const auto& a, const auto& b) { return a.first < b.first; })) {
      std::stable_sort(first, last, [](const auto& a, const auto& b) { return a.first < b.first; });
    }
    for (auto it = first; it != last;) {
      const int col = it->first;
      double sum = 0.0;
      for (; it != last && it->first == col; ++it) sum += it->second;
      if (!std::isfinite(sum)) {
        throw std::invalid_argument("Model '" + name_ + "': " + row_label(i) +
                                    ": summed coefficient of " + ColumnLabel(col) +
                                    " overflows to " + FormatG(sum, 17));
      }
      if (sum != 0.0) block.push_back({base + i, col, sum});
    }
  }
  // Validate names.
  try {
    if (!names.empty()) {
      std::unordered_set<std::string_view> seen;
      seen.reserve(names.size());
      for (const std::string& s : names) {
        if (s.empty()) continue;
        if (!seen.insert(s).second) {
          throw std::invalid_argument("duplicate row name '" + s + "'");
        }
        row_names_.CheckNew(s, "row");
      }
    } else {
      row_names_.CheckNewBlock(name_prefix, m, "row");
    }
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("Model '" + name_ + "': AddRows: " + e.what());
  }
  // Commit.
  entries_.insert(entries_.end(), block.begin(), block.end());
  row_lower_.insert(row_lower_.end(), lower.data(), lower.data() + m);
  row_upper_.insert(row_upper_.end(), upper.data(), upper.data() + m);
  if (!names.empty()) {
    for (std::string& s : names) row_names_.AddNamed(std::move(s));
  } else {
    row_names_.AddBlock(name_prefix, m);
  }
  return ConstraintBlock{base, m};
}

ConstraintBlock Model::AddRows(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                               const std::vector<Variable>& vars,
                               const Eigen::Ref<const Eigen::VectorXd>& lower,
                               const Eigen::Ref<const Eigen::VectorXd>& upper,
                               std::string_view name_prefix) {
  const std::string where = "Model '" + name_ + "': AddRows";
  if (static_cast<Eigen::Index>(vars.size()) != a.cols()) {
    throw std::invalid_argument(where + ": matrix has " + std::to_string(a.cols()) +
                                " columns but " + std::to_string(vars.size()) +
                                " variables were given");
  }
  if (a.rows() != lower.size()) {
    throw std::invalid_argument(where + ": matrix has " + std::to_string(a.rows()) +
                                " rows but lower has size " + std::to_string(lower.size()));
  }
  for (size_t k = 0; k < vars.size(); ++k) {
    CheckOwned(vars[k], "AddRows: vars[" + std::to_string(k) + "]");
  }
  std::vector<RowTriplet> triplets;
  triplets.reserve(static_cast<size_t>(a.nonZeros()));
  for (Eigen::Index r = 0; r < a.outerSize(); ++r) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(a, r); it; ++it) {
      triplets.push_back(
          {static_cast<int>(r), vars[static_cast<size_t>(it.col())].index(), it.value()});
    }
  }
  return AddRows(triplets, lower, upper, name_prefix);
}

ConstraintBlock Model::AddRows(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                               const VarBlock& vars, const Eigen::Ref<const Eigen::VectorXd>& lower,
                               const Eigen::Ref<const Eigen::VectorXd>& upper,
                               std::string_view name_prefix) {
  const std::string where = "Model '" + name_ + "': AddRows";
  if (vars.size() != a.cols()) {
    throw std::invalid_argument(where + ": matrix has " + std::to_string(a.cols()) +
                                " columns but the block has " + std::to_string(vars.size()) +
                                " variables");
  }
  if (a.rows() != lower.size()) {
    throw std::invalid_argument(where + ": matrix has " + std::to_string(a.rows()) +
                                " rows but lower has size " + std::to_string(lower.size()));
  }
  if (vars.size() > 0) {
    if (vars.model_id() != id_) {
      throw std::invalid_argument(where + ": variable block belongs to model #" +
                                  std::to_string(vars.model_id()) + ", not to this model #" +
                                  std::to_string(id_));
    }
    if (vars.start() < 0 || vars.start() + vars.size() > num_variables()) {
      throw std::invalid_argument(where + ": variable block out of range");
    }
  }
  std::vector<RowTriplet> triplets;
  triplets.reserve(static_cast<size_t>(a.nonZeros()));
  for (Eigen::Index r = 0; r < a.outerSize(); ++r) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(a, r); it; ++it) {
      triplets.push_back(
          {static_cast<int>(r), vars.start() + static_cast<int>(it.col()), it.value()});
    }
  }
  return AddRows(triplets, lower, upper, name_prefix);
}

void Model::SetObjective(const LinearExpr& objective, ObjectiveSense sense) {
  const std::string where = "Model '" + name_ + "': objective";
  if (objective.model_id() == LinearExpr::kMixedModels) {
    throw std::invalid_argument(where + " mixes variables of several models");
  }
  if (objective.model_id() != 0 && objective.model_id() != id_) {
    throw std::invalid_argument(where + " uses variables of model #" +
                                std::to_string(objective.model_id()) + ", not of this model #" +
                                std::to_string(id_));
  }
  LinearExpr e = objective;
  e.Canonicalize();
  for (const LinearExpr::Term& t : e.terms()) {
    if (t.index < 0 || t.index >= num_variables()) {
      throw std::invalid_argument(where + ": invalid variable handle (index " +
                                  std::to_string(t.index) + ")");
    }
    if (!std::isfinite(t.coefficient)) {
      throw std::invalid_argument(where + ": coefficient of " + ColumnLabel(t.index) +
                                  " must be finite, got " + FormatG(t.coefficient, 17));
    }
  }
  if (!std::isfinite(e.constant())) {
    throw std::invalid_argument(where + ": constant must be finite, got " +
                                FormatG(e.constant(), 17));
  }
  std::fill(col_cost_.begin(), col_cost_.end(), 0.0);
  for (const LinearExpr::Term& t : e.terms())
    col_cost_[static_cast<size_t>(t.index)] = t.coefficient;
  objective_offset_ = e.constant();
  sense_ = sense;
}

void Model::Minimize(const LinearExpr& objective) {
  SetObjective(objective, ObjectiveSense::kMinimize);
}

void Model::Maximize(const LinearExpr& objective) {
  SetObjective(objective, ObjectiveSense::kMaximize);
}

void Model::AddObjectiveTerm(Variable v, double c) {
  CheckOwned(v, "AddObjectiveTerm");
  const size_t j = static_cast<size_t>(v.index());
  const double sum = col_cost_[j] + c;
  if (!std::isfinite(c) || !std::isfinite(sum)) {
    throw std::invalid_argument("Model '" + name_ + "': objective coefficient of " +
                                ColumnLabel(v.index()) + " must be finite, got " + FormatG(c, 17));
  }
  col_cost_[j] = sum;
}

int Model::num_integer_variables() const {
  return static_cast<int>(std::count_if(col_type_.begin(), col_type_.end(),
                                        [](VarType t) { return t != VarType::kContinuous; }));
}

Variable Model::variable(int index) const {
  if (index < 0 || index >= num_variables()) {
    throw std::out_of_range("Model '" + name_ + "': variable index " + std::to_string(index) +
                            " outside [0, " + std::to_string(num_variables()) + ")");
  }
  return Variable(index, id_);
}

std::string Model::variable_name(Variable v) const {
  CheckOwned(v, "variable_name");
  return col_names_.Name(v.index());
}

double Model::lower_bound(Variable v) const {
  CheckOwned(v, "lower_bound");
  return col_lower_[static_cast<size_t>(v.index())];
}

double Model::upper_bound(Variable v) const {
  CheckOwned(v, "upper_bound");
  return col_upper_[static_cast<size_t>(v.index())];
}

VarType Model::type(Variable v) const {
  CheckOwned(v, "type");
  return col_type_[static_cast<size_t>(v.index())];
}

double Model::objective_coefficient(Variable v) const {
  CheckOwned(v, "objective_coefficient");
  return col_cost_[static_cast<size_t>(v.index())];
}

std::string Model::constraint_name(Constraint c) const {
  if (c.index < 0 || c.index >= num_constraints()) {
    throw std::out_of_range("Model '" + name_ + "': constraint index " + std::to_string(c.index) +
                            " outside [0, " + std::to_string(num_constraints()) + ")");
  }
  return row_names_.Name(c.index);
}

LpData Model::ToLpData() const {
  LpData lp;
  lp.name = name_;
  lp.sense = sense_;
  lp.objective_offset = objective_offset_;
  const int n = num_variables();
  const int m = num_constraints();
  lp.col_cost = Eigen::Map<const Eigen::VectorXd>(col_cost_.data(), n);
  lp.col_lower = Eigen::Map<const Eigen::VectorXd>(col_lower_.data(), n);
  lp.col_upper = Eigen::Map<const Eigen::VectorXd>(col_upper_.data(), n);
  lp.row_lower = Eigen::Map<const Eigen::VectorXd>(row_lower_.data(), m);
  lp.row_upper = Eigen::Map<const Eigen::VectorXd>(row_upper_.data(), m);
  lp.col_type = col_type_;
  // Entries are sorted by row, so a counting sort by column leaves every
  // column's row indices increasing: the result is already compressed CSC.
  const size_t nnz = entries_.size();
  lp.a_matrix.resize(m, n);
  lp.a_matrix.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = lp.a_matrix.outerIndexPtr();
  int* inner = lp.a_matrix.innerIndexPtr();
  double* values = lp.a_matrix.valuePtr();
  std::fill(outer, outer + n + 1, 0);
  for (const Entry& e : entries_) ++outer[e.column + 1];
  for (int j = 0; j < n; ++j) outer[j + 1] += outer[j];
  std::vector<int> next(outer, outer + n);
  for (const Entry& e : entries_) {
    const int p = next[static_cast<size_t>(e.column)]++;
    inner[p] = e.row;
    values[p] = e.value;
  }
  col_names_.AppendAll(&lp.col_names);
  row_names_.AppendAll(&lp.row_names);
  return lp;
}

}  // namespace thrustsched::milp
