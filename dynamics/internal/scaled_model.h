// Private helper (not installed): a validated, nondimensional view of a
// LinearModel with its input columns folded in, shared by Discretize and
// PropagateLinear.
//
// With T = model.time_scale(), S = diag(model.state_scale()), U = input columns:
//   tau = t / T,  xi = S^-1 x,  d xi / d tau = A^ xi + E^ [u; 1],
//   A^ = T S^-1 A S  (n x n),   E^ = T S^-1 [B U, d]  (n x (m + 1)).
//
//   internal::ScaledModel sm(model, thrusters.AccelerationMatrix(), "Discretize");
//   const internal::ScaledModel::Frozen& f = sm.At(t);   // f.a, f.e
//
// At() caches: a time-invariant model is evaluated once; a time-varying one
// keeps the last kCacheSize evaluations keyed by the exact time, so schemes
// that revisit a time (shared interval endpoints, repeated Runge-Kutta stage
// times) do not call Evaluate again. A reference returned by At() stays valid
// for the next kCacheSize - 1 calls.
#ifndef THRUSTSCHED_DYNAMICS_INTERNAL_SCALED_MODEL_H_
#define THRUSTSCHED_DYNAMICS_INTERNAL_SCALED_MODEL_H_

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "dynamics/linear_model.h"

namespace thrustsched::dynamics::internal {

class ScaledModel {
 public:
  struct Frozen {
    Eigen::MatrixXd a;  // n x n, nondimensional
    Eigen::MatrixXd e;  // n x (m + 1): [B U, d], nondimensional
  };
  static constexpr int kCacheSize = 16;

  /// @throws std::invalid_argument (prefixed by `where`) if the model's sizes,
  ///         scales or the input columns are invalid.
  ScaledModel(const LinearModel& model, const Eigen::MatrixXd& input_columns,
              std::string_view where)
      : model_(model), input_columns_(input_columns), where_(where) {
    n_ = model.num_states();
    if (n_ < 1) Fail("model '" + std::string(model.name()) + "' has no states");
    if (input_columns.rows() != model.num_inputs()) {
      std::ostringstream msg;
      msg << "input_columns has " << input_columns.rows() << " rows, model '" << model.name()
          << "' takes " << model.num_inputs() << " inputs";
      Fail(msg.str());
    }
    if (!input_columns.allFinite()) Fail("input_columns holds non-finite values");
    m_ = static_cast<int>(input_columns.cols());
    time_scale_ = model.time_scale();
    if (!std::isfinite(time_scale_) || time_scale_ <= 0.0) {
      std::ostringstream msg;
      msg << "model '" << model.name() << "' time_scale must be finite and > 0, got "
          << time_scale_;
      Fail(msg.str());
    }
    scale_ = model.state_scale();
    if (scale_.size() != n_) {
      std::ostringstream msg;
      msg << "model '" << model.name() << "' state_scale has " << scale_.size()
          << " entries, expected " << n_;
      Fail(msg.str());
    }
    for (int i = 0; i < n_; ++i) {
      if (!std::isfinite(scale_[i]) || scale_[i] <= 0.0) {
        std::ostringstream msg;
        msg << "model '" << model.name() << "' state_scale[" << i
            << "] must be finite and > 0, got " << scale_[i];
        Fail(msg.str());
      }
    }
    inv_scale_ = scale_.cwiseInverse();
    time_invariant_ = model.is_time_invariant();
    for (Entry& entry : cache_) {
      entry.frozen.a.resize(n_, n_);
      entry.frozen.e.resize(n_, m_ + 1);
    }
  }

  int n() const { return n_; }
  int m() const { return m_; }
  double time_scale() const { return time_scale_; }
  const Eigen::VectorXd& scale() const { return scale_; }
  const Eigen::VectorXd& inv_scale() const { return inv_scale_; }
  bool time_invariant() const { return time_invariant_; }
  long evaluations() const { return evaluations_; }

  /// Nondimensional A^, E^ at time t (s).
  const Frozen& At(double t) {
    if (time_invariant_) {
      if (evaluations_ == 0) Fill(t, cache_[0]);
      return cache_[0].frozen;
    }
    for (int k = 0; k < filled_; ++k) {
      const int idx = (next_ - 1 - k + kCacheSize) % kCacheSize;
      if (cache_[idx].t == t) return cache_[idx].frozen;
    }
    Entry& entry = cache_[next_];
    Fill(t, entry);
    next_ = (next_ + 1) % kCacheSize;
    if (filled_ < kCacheSize) ++filled_;
    return entry.frozen;
  }

 private:
  struct Entry {
    double t = 0.0;
    Frozen frozen;
  };

  [[noreturn]] void Fail(const std::string& what) const {
    throw std::invalid_argument(where_ + ": " + what);
  }

  void Fill(double t, Entry& entry) {
    const ModelMatrices mm = model_.Evaluate(t);
    ++evaluations_;
    const int r = model_.num_inputs();
    if (mm.a.rows() != n_ || mm.a.cols() != n_ || mm.b.rows() != n_ || mm.b.cols() != r ||
        mm.d.size() != n_) {
      std::ostringstream msg;
      msg << "model '" << model_.name() << "' returned A " << mm.a.rows() << "x" << mm.a.cols()
          << ", B " << mm.b.rows() << "x" << mm.b.cols() << ", d " << mm.d.size() << " at t = " << t
          << "; expected A " << n_ << "x" << n_ << ", B " << n_ << "x" << r << ", d " << n_;
      Fail(msg.str());
    }
    if (!mm.a.allFinite() || !mm.b.allFinite() || !mm.d.allFinite()) {
      std::ostringstream msg;
      msg << "model '" << model_.name() << "' returned non-finite A, B or d at t = " << t;
      Fail(msg.str());
    }
    entry.t = t;
    // A^ = T S^-1 A S, E^ = T S^-1 [B U, d].
    entry.frozen.a.noalias() = time_scale_ * (inv_scale_.asDiagonal() * mm.a * scale_.asDiagonal());
    entry.frozen.e.leftCols(m_).noalias() =
        time_scale_ * (inv_scale_.asDiagonal() * (mm.b * input_columns_));
    entry.frozen.e.col(m_) = time_scale_ * inv_scale_.cwiseProduct(mm.d);
  }

  const LinearModel& model_;
  const Eigen::MatrixXd& input_columns_;
  std::string where_;
  int n_ = 0, m_ = 0;
  double time_scale_ = 1.0;
  Eigen::VectorXd scale_, inv_scale_;
  bool time_invariant_ = false;
  std::array<Entry, kCacheSize> cache_;
  int next_ = 0, filled_ = 0;
  long evaluations_ = 0;
};

}  // namespace thrustsched::dynamics::internal

#endif  // THRUSTSCHED_DYNAMICS_INTERNAL_SCALED_MODEL_H_
