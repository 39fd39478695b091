#include "milp/linear_expr.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace thrustsched::milp {

LinearExpr::LinearExpr(double constant) : constant_(constant) {}

LinearExpr::LinearExpr(Variable v) {
  // An invalid (default-constructed) handle is kept as index -1 so that Model
  // can reject it with a message naming the row.
  terms_.push_back({v.index(), 1.0});
  MergeModel(v.model_id());
}

void LinearExpr::MergeModel(std::uint32_t id) {
  if (id == 0 || id == model_id_) return;
  model_id_ = (model_id_ == 0) ? id : kMixedModels;
}

LinearExpr& LinearExpr::AddTerm(Variable v, double coefficient) {
  terms_.push_back({v.index(), coefficient});
  MergeModel(v.model_id());
  return *this;
}

LinearExpr& LinearExpr::AddConstant(double value) {
  constant_ += value;
  return *this;
}

LinearExpr& LinearExpr::operator+=(const LinearExpr& other) {
  if (&other == this) {
    *this *= 2.0;
    return *this;
  }
  terms_.insert(terms_.end(), other.terms_.begin(), other.terms_.end());
  constant_ += other.constant_;
  if (other.model_id_ == kMixedModels) {
    model_id_ = kMixedModels;
  } else {
    MergeModel(other.model_id_);
  }
  return *this;
}

LinearExpr& LinearExpr::operator-=(const LinearExpr& other) {
  if (&other == this) {
    terms_.clear();
    constant_ = 0.0;
    return *this;
  }
  terms_.reserve(terms_.size() + other.terms_.size());
  for (const Term& t : other.terms_) terms_.push_back({t.index, -t.coefficient});
  constant_ -= other.constant_;
  if (other.model_id_ == kMixedModels) {
    model_id_ = kMixedModels;
  } else {
    MergeModel(other.model_id_);
  }
  return *this;
}

LinearExpr& LinearExpr::operator*=(double scale) {
  for (Term& t : terms_) t.coefficient *= scale;
  constant_ *= scale;
  return *this;
}

LinearExpr LinearExpr::Sum(const VarBlock& vars) {
  LinearExpr e;
  e.terms_.reserve(static_cast<size_t>(vars.size()));
  for (int i = 0; i < vars.size(); ++i) e.terms_.push_back({vars.start() + i, 1.0});
  if (vars.size() > 0) e.MergeModel(vars.model_id());
  return e;
}

LinearExpr LinearExpr::Sum(const std::vector<Variable>& vars) {
  LinearExpr e;
  e.terms_.reserve(vars.size());
  for (const Variable& v : vars) e.AddTerm(v, 1.0);
  return e;
}

LinearExpr LinearExpr::InnerProduct(const Eigen::Ref<const Eigen::VectorXd>& coefficients,
                                    const std::vector<Variable>& vars) {
  if (coefficients.size() != static_cast<Eigen::Index>(vars.size())) {
    throw std::invalid_argument("LinearExpr::InnerProduct: " + std::to_string(coefficients.size()) +
                                " coefficients for " + std::to_string(vars.size()) + " variables");
  }
  LinearExpr e;
  e.terms_.reserve(vars.size());
  for (size_t i = 0; i < vars.size(); ++i) {
    e.AddTerm(vars[i], coefficients[static_cast<Eigen::Index>(i)]);
  }
  return e;
}

LinearExpr LinearExpr::InnerProduct(const Eigen::Ref<const Eigen::VectorXd>& coefficients,
                                    const VarBlock& vars) {
  if (coefficients.size() != vars.size()) {
    throw std::invalid_argument("LinearExpr::InnerProduct: " + std::to_string(coefficients.size()) +
                                " coefficients for a block of " + std::to_string(vars.size()) +
                                " variables");
  }
  LinearExpr e;
  e.terms_.reserve(static_cast<size_t>(vars.size()));
  for (int i = 0; i < vars.size(); ++i) e.terms_.push_back({vars.start() + i, coefficients[i]});
  if (vars.size() > 0) e.MergeModel(vars.model_id());
  return e;
}

void LinearExpr::Canonicalize() {
  if (terms_.empty()) return;
  const bool sorted = std::is_sorted(
      terms_.begin(), terms_.end(), [](const Term& a, const Term& b) { return a.index < b.index; });
  if (!sorted) {
    std::stable_sort(terms_.begin(), terms_.end(),
                     [](const Term& a, const Term& b) { return a.index < b.index; });
  }
  size_t out = 0;
  for (size_t i = 0; i < terms_.size();) {
    Term merged = terms_[i];
    size_t j = i + 1;
    while (j < terms_.size() && terms_[j].index == merged.index) {
      merged.coefficient += terms_[j].coefficient;
      ++j;
    }
    // NaN coefficients are kept (not equal to 0) so that Model can report them.
    if (merged.coefficient != 0.0) terms_[out++] = merged;
    i = j;
  }
  terms_.resize(out);
}

double LinearExpr::Evaluate(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  double value = constant_;
  for (const Term& t : terms_) {
    if (t.index < 0 || t.index >= x.size()) {
      throw std::invalid_argument("LinearExpr::Evaluate: column " + std::to_string(t.index) +
                                  " outside a vector of size " + std::to_string(x.size()));
    }
    value += t.coefficient * x[t.index];
  }
  return value;
}

LinearExpr operator+(LinearExpr a, const LinearExpr& b) {
  a += b;
  return a;
}
LinearExpr operator-(LinearExpr a, const LinearExpr& b) {
  a -= b;
  return a;
}
LinearExpr operator-(LinearExpr a) {
  a *= -1.0;
  return a;
}
LinearExpr operator*(double c, LinearExpr e) {
  e *= c;
  return e;
}
LinearExpr operator*(LinearExpr e, double c) {
  e *= c;
  return e;
}

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

BoundedLinearExpr MakeBounded(LinearExpr e, double lower, double upper) {
  // Fold the constant into the bounds (infinite bounds stay infinite; a NaN
  // constant turns a finite bound into NaN, which Model rejects).
  const double c = e.constant();
  e.AddConstant(-c);
  if (std::isfinite(lower) || std::isnan(lower)) lower -= c;
  if (std::isfinite(upper) || std::isnan(upper)) upper -= c;
  if (!std::isfinite(c)) {
    // Make sure the row is rejected instead of silently losing the constant.
    lower = std::numeric_limits<double>::quiet_NaN();
  }
  return BoundedLinearExpr{std::move(e), lower, upper};
}
}  // namespace

BoundedLinearExpr operator<=(LinearExpr e, double upper) {
  return MakeBounded(std::move(e), -kInf, upper);
}
BoundedLinearExpr operator>=(LinearExpr e, double lower) {
  return MakeBounded(std::move(e), lower, kInf);
}
BoundedLinearExpr operator==(LinearExpr e, double value) {
  return MakeBounded(std::move(e), value, value);
}
BoundedLinearExpr operator<=(double lower, LinearExpr e) {
  return MakeBounded(std::move(e), lower, kInf);
}
BoundedLinearExpr operator>=(double upper, LinearExpr e) {
  return MakeBounded(std::move(e), -kInf, upper);
}
BoundedLinearExpr operator<=(LinearExpr a, const LinearExpr& b) {
  a -= b;
  return MakeBounded(std::move(a), -kInf, 0.0);
}
BoundedLinearExpr operator>=(LinearExpr a, const LinearExpr& b) {
  a -= b;
  return MakeBounded(std::move(a), 0.0, kInf);
}
BoundedLinearExpr operator==(LinearExpr a, const LinearExpr& b) {
  a -= b;
  return MakeBounded(std::move(a), 0.0, 0.0);
}

}  // namespace thrustsched::milp
