// RowBuffer: accumulates MILP rows for one bulk milp::Model::AddRows call,
// each row divided by its largest coefficient (scaling) and cleaned of
// negligible coefficients. Shared by the transcription builders.
//
//   internal::RowBuffer rows(/*scale=*/true);
//   rows.Begin();
//   rows.Coef(x.index(), 2.0);
//   rows.Coef(y.index(), -1.0);
//   rows.End(0.0, 4.0, "my_row");       // 0 <= 2 x - y <= 4, stored as 0 <= x - y/2 <= 2
//   rows.Flush(&model);
#ifndef THRUSTSCHED_TRANSCRIPTION_INTERNAL_ROW_BUFFER_H_
#define THRUSTSCHED_TRANSCRIPTION_INTERNAL_ROW_BUFFER_H_

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "milp/model.h"

namespace thrustsched::transcription::internal {

// Accumulates rows for one bulk AddRows call, each row divided by its
// largest coefficient (scaling) and cleaned of negligible coefficients.
class RowBuffer {
 public:
  // Coefficients below this fraction of their row's largest are dropped.
  // They are roundoff or physically negligible couplings (a radial thrust on
  // the inclination, a 1e-9 element of a 5-min transition matrix: over a
  // week of 2016 steps they move the scaled state by < 2016 x 1e-8 = 2e-5),
  // but CBC 2.10 on GEO weeks with coefficients down to 1e-14 "proved"
  // feasible models infeasible (a knapsack column cut, or strong branching on
  // the ill-conditioned root LP); without those below 1e-8 it solves them.
  // The independent checker re-propagates the exact model, so any effect of
  // the dropped terms would show there.
  static constexpr double kDropRelative = 1e-8;

  explicit RowBuffer(bool scale) : scale_(scale) {}

  void Begin() { current_.clear(); }
  void Coef(int column, double value) {
    if (value != 0.0) current_.push_back({0, column, value});
  }
  // Ends the row lo <= sum <= hi; returns the factor the row was multiplied by.
  double End(double lo, double hi, std::string name) {
    double big = 0.0;
    for (const auto& t : current_) big = std::max(big, std::abs(t.value));
    double factor = 1.0;
    if (scale_ && big > 0.0) factor = 1.0 / big;
    const int row = static_cast<int>(lower_.size());
    for (const auto& t : current_) {
      if (std::abs(t.value) <= kDropRelative * big) continue;
      triplets_.push_back({row, t.column, t.value * factor});
    }
    lower_.push_back(std::isfinite(lo) ? lo * factor : lo);
    upper_.push_back(std::isfinite(hi) ? hi * factor : hi);
    names_.push_back(std::move(name));
    return factor;
  }
  // Entries waiting for Flush. A builder with millions of them (the
  // condensed window rows) flushes in chunks: the buffer's memory is then
  // reused instead of growing, and copied, to the size of the whole block.
  size_t pending_entries() const { return triplets_.size(); }
  void Flush(milp::Model* model) {
    if (lower_.empty()) return;
    const Eigen::Map<const Eigen::VectorXd> lo(lower_.data(), lower_.size());
    const Eigen::Map<const Eigen::VectorXd> hi(upper_.data(), upper_.size());
    model->AddRows(triplets_, lo, hi, "", std::move(names_));
    triplets_.clear();
    lower_.clear();
    upper_.clear();
    names_.clear();
  }

 private:
  bool scale_;
  std::vector<milp::RowTriplet> current_, triplets_;
  std::vector<double> lower_, upper_;
  std::vector<std::string> names_;
};

}  // namespace thrustsched::transcription::internal

#endif  // THRUSTSCHED_TRANSCRIPTION_INTERNAL_ROW_BUFFER_H_
