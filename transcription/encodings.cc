#include "transcription/encodings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "common/format.h"

namespace thrustsched::transcription {

using common::FormatG;

namespace {

using milp::LinearExpr;
using milp::Variable;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Builds the rows of one encoding. Interval j is [t_j, t_{j+1}); node a is
// t_a. "Start at node a": on in interval a, off in a-1 (or before t0). "Stop
// at node a": on in a-1 (or at t0 per history), off in a.
class Builder {
 public:
  Builder(milp::Model* model, const EncodingInput& in, Encoding encoding, std::string_view prefix)
      : model_(*model), in_(in), t_(in.grid), prefix_(prefix) {
    enc_.encoding = encoding;
    enc_.num_thrusters = in.num_thrusters;
    enc_.num_intervals = static_cast<int>(t_.size()) - 1;
    m_ = in.num_thrusters;
    n_ = enc_.num_intervals;
    const OperationalRules& r = in.rules;
    single_ = r.max_simultaneous == 1;
    gap_other_ = r.min_gap_other_s > kTimeTolerance;
  }

  OperationalEncoding Build() {
    Validate();
    ComputeEffectiveDurations();
    CreateVariables();
    ApplyHistoryAndForcedOff();
    if (enc_.encoding == Encoding::kTight) {
      BuildTight();
    } else {
      BuildThesis();
    }
    AddMaxBurnRows();
    ApplyNoStarts();
    ApplyBounds();
    return std::move(enc_);
  }

 private:
  // ---- helpers -----------------------------------------------------------
  double prev_on(int i) const { return in_.history.is_on(i) ? 1.0 : 0.0; }

  // True if interval b (>= a) starts before t_a + T (T applied at node a).
  bool Within(int a, int b, double duration) const {
    return t_[b] < t_[a] + duration - kTimeTolerance;
  }

  // on[i][j] as an expression, with j = -1 meaning the state before t0.
  LinearExpr On(int i, int j) const {
    if (j < 0) return LinearExpr(prev_on(i));
    return LinearExpr(enc_.on[i][j]);
  }

  // Sum of all thrusters on in interval j (gamma_j in the thesis encoding),
  // j = -1 -> number on at t0.
  LinearExpr Gamma(int j) const {
    if (j < 0) {
      double s = 0;
      for (int i = 0; i < m_; ++i) s += prev_on(i);
      return LinearExpr(s);
    }
    return LinearExpr(enc_.gamma[j]);
  }

  std::string Name(const std::string& what, int i, int j) const {
    std::string s = prefix_ + what + "_" + std::to_string(i) + "_" + std::to_string(j);
    return s;
  }

  void Add(const LinearExpr& e, double lo, double hi, const std::string& name) {
    model_.AddConstraint(e, lo, hi, name);
  }

  // ---- validation and sizes ----------------------------------------------
  void Validate() {
    std::string err;
    if (m_ < 1) throw std::invalid_argument("encoding: num_thrusters must be >= 1");
    if (t_.size() < 2) throw std::invalid_argument("encoding: grid needs at least 2 points");
    for (size_t j = 0; j < t_.size(); ++j) {
      if (!std::isfinite(t_[j]) || (j > 0 && !(t_[j] > t_[j - 1]))) {
        throw std::invalid_argument(
            "encoding: grid must be finite and strictly increasing (index " + std::to_string(j) +
            ")");
      }
    }
    if (!in_.rules.IsValid(&err)) throw std::invalid_argument(err);
    if (!in_.history.IsValid(m_, &err)) throw std::invalid_argument(err);
    if (!in_.enabled.empty() && static_cast<int>(in_.enabled.size()) != m_) {
      throw std::invalid_argument("encoding: enabled has " + std::to_string(in_.enabled.size()) +
                                  " entries for " + std::to_string(m_) + " thrusters");
    }
    for (const ForcedOff& f : in_.forced_off) {
      if (f.thruster < 0 || f.thruster >= m_) {
        throw std::invalid_argument("encoding: forced_off thruster index " +
                                    std::to_string(f.thruster) + " out of range");
      }
    }
    for (int i = 0; i < m_; ++i) {
      if (in_.history.on_for(i) > in_.rules.max_burn_s + kTimeTolerance) {
        throw std::invalid_argument(
            "history.on_for_s[" + std::to_string(i) + "] = " + FormatG(in_.history.on_for(i), 10) +
            " s already exceeds operations.max_burn_s = " + FormatG(in_.rules.max_burn_s, 10));
      }
    }
  }

  void ComputeEffectiveDurations() {
    const OperationalRules& r = in_.rules;
    auto span = [&](double duration, int* lo, int* hi, double* eff) {
      *lo = std::numeric_limits<int>::max();
      *hi = 0;
      double eff_s = 0;
      for (int a = 0; a < n_; ++a) {
        const int k = IntervalsSpanning(t_, a, duration);
        if (a + k > n_) continue;  // not fully inside the horizon
        *lo = std::min(*lo, k);
        *hi = std::max(*hi, k);
        eff_s = std::max(eff_s, t_[a + k] - t_[a]);
      }
      if (*lo == std::numeric_limits<int>::max()) *lo = *hi;
      *eff = eff_s;
    };
    span(r.min_burn_s, &enc_.min_burn_intervals_min, &enc_.min_burn_intervals_max,
         &enc_.effective_min_burn_s);
    span(r.min_off_same_s, &enc_.min_off_same_intervals_min, &enc_.min_off_same_intervals_max,
         &enc_.effective_min_off_same_s);
    span(r.min_gap_other_s, &enc_.min_gap_other_intervals_min, &enc_.min_gap_other_intervals_max,
         &enc_.effective_min_gap_other_s);
  }

  void CreateVariables() {
    const bool tight = enc_.encoding == Encoding::kTight;
    const bool starts = tight || in_.rules.max_burns_per_thruster >= 0 || in_.need_starts;
    enc_.on.assign(m_, {});
    lower_.assign(m_, std::vector<double>(n_, 0.0));
    upper_.assign(m_, std::vector<double>(n_, 1.0));
    no_start_.assign(m_, std::vector<bool>(n_, false));
    for (int i = 0; i < m_; ++i) {
      enc_.on[i].reserve(n_);
      for (int j = 0; j < n_; ++j) {
        enc_.on[i].push_back(
            model_.AddVariable(0.0, 1.0, milp::VarType::kBinary, Name("on", i, j)));
      }
    }
    if (starts) {
      enc_.start.assign(m_, {});
      for (int i = 0; i < m_; ++i) {
        for (int j = 0; j < n_; ++j) {
          enc_.start[i].push_back(model_.AddContinuous(0.0, 1.0, Name("start", i, j)));
        }
      }
    }
    if (tight) {
      enc_.stop.assign(m_, {});
      for (int i = 0; i < m_; ++i) {
        for (int j = 0; j < n_; ++j) {
          enc_.stop[i].push_back(model_.AddContinuous(0.0, 1.0, Name("stop", i, j)));
        }
      }
    } else {
      for (int j = 0; j < n_; ++j) {
        enc_.gamma.push_back(model_.AddContinuous(0.0,
                                                  std::min<double>(in_.rules.max_simultaneous, m_),
                                                  prefix_ + "gamma_" + std::to_string(j)));
      }
    }
  }

  // Fixings shared by both encodings.
  void ApplyHistoryAndForcedOff() {
    const OperationalRules& r = in_.rules;
    const double t0 = t_[0];
    for (int i = 0; i < m_; ++i) {
      if (!in_.enabled.empty() && !in_.enabled[i]) {
        for (int j = 0; j < n_; ++j) upper_[i][j] = 0.0;
      }
    }
    for (const ForcedOff& f : in_.forced_off) {
      for (int j = 0; j < n_; ++j) {
        if (std::max(t_[j], f.start_s) < std::min(t_[j + 1], f.end_s) - kTimeTolerance) {
          upper_[f.thruster][j] = 0.0;
        }
      }
    }
    for (int i = 0; i < m_; ++i) {
      if (in_.history.is_on(i)) {
        // The burn began at t0 - h and must last min_burn_s.
        const double began = t0 - in_.history.on_for(i);
        for (int j = 0; j < n_; ++j) {
          if (t_[j] < began + r.min_burn_s - kTimeTolerance) lower_[i][j] = 1.0;
        }
        if (!r.allow_burn_across_end && t_[n_] < began + r.min_burn_s - kTimeTolerance) {
          enc_.infeasibility_reasons.push_back(
              "thruster " + std::to_string(i) + " is on at t0 for " +
              FormatG(in_.history.on_for(i), 10) + " s and cannot reach the minimum burn of " +
              FormatG(r.min_burn_s, 10) +
              " s before the horizon ends, and burns across the end are not allowed");
          upper_[i][n_ - 1] = 0.0;
        }
      } else {
        const double g = in_.history.off_for(i);
        if (!std::isfinite(g)) continue;
        const double ended = t0 - g;
        // Same thruster: off until ended + min_off_same_s.
        for (int j = 0; j < n_; ++j) {
          if (t_[j] < ended + r.min_off_same_s - kTimeTolerance) upper_[i][j] = 0.0;
        }
        // Other thrusters: no start before ended + min_gap_other_s.
        if (gap_other_) {
          for (int l = 0; l < m_; ++l) {
            if (l == i) continue;
            for (int j = 0; j < n_; ++j) {
              if (t_[j] < ended + r.min_gap_other_s - kTimeTolerance) {
                if (in_.history.is_on(l)) {
                  if (j > 0) no_start_[l][j] = true;  // a restart would be a start
                } else {
                  upper_[l][j] = 0.0;  // off at t0 and may not start: off
                }
              }
            }
          }
        }
      }
    }
    // Burns that cannot complete before the horizon end.
    if (!r.allow_burn_across_end) {
      for (int i = 0; i < m_; ++i) {
        for (int a = 0; a < n_; ++a) {
          if (t_[n_] < t_[a] + r.min_burn_s - kTimeTolerance) no_start_[i][a] = true;
        }
      }
    }
  }

  // ---- tight encoding ----------------------------------------------------
  void BuildTight() {
    const OperationalRules& r = in_.rules;
    for (int i = 0; i < m_; ++i) {
      for (int j = 0; j < n_; ++j) {
        // on[j] - on[j-1] = v[j] - w[j]
        LinearExpr e = On(i, j) - On(i, j - 1);
        e.AddTerm(enc_.start[i][j], -1.0);
        e.AddTerm(enc_.stop[i][j], 1.0);
        Add(e, 0.0, 0.0, Name("link", i, j));
      }
    }
    AddMaxSimultaneous();
    for (int i = 0; i < m_; ++i) {
      for (int b = 0; b < n_; ++b) {
        // Minimum up: a start at a in up(b) forces on at b.
        LinearExpr up;
        for (int a = b; a >= 0; --a) {
          if (a != b && !Within(a, b, r.min_burn_s)) break;
          up.AddTerm(enc_.start[i][a], 1.0);
        }
        up.AddTerm(enc_.on[i][b], -1.0);
        Add(up, -kInf, 0.0, Name("minup", i, b));
        // Minimum down (same thruster): a stop at a in down(b) forces off at b.
        LinearExpr down;
        for (int a = b; a >= 0; --a) {
          if (a != b && !Within(a, b, r.min_off_same_s)) break;
          down.AddTerm(enc_.stop[i][a], 1.0);
        }
        down.AddTerm(enc_.on[i][b], 1.0);
        Add(down, -kInf, 1.0, Name("mindown", i, b));
      }
    }
    if (gap_other_ && m_ > 1) {
      // At most one stop of i can fall in a gap window when two stops are
      // separated by at least min_off_same + min_burn >= min_gap_other.
      const bool aggregate =
          single_ && r.min_gap_other_s <= r.min_off_same_s + r.min_burn_s + kTimeTolerance;
      for (int i = 0; i < m_; ++i) {
        for (int b = 0; b < n_; ++b) {
          std::vector<int> stops;
          for (int a = b; a >= 0 && Within(a, b, r.min_gap_other_s); --a) stops.push_back(a);
          if (aggregate) {
            LinearExpr e;
            for (int a : stops) e.AddTerm(enc_.stop[i][a], 1.0);
            for (int l = 0; l < m_; ++l) {
              if (l != i) e.AddTerm(enc_.start[l][b], 1.0);
            }
            Add(e, -kInf, 1.0, Name("gap", i, b));
          } else {
            for (int a : stops) {
              for (int l = 0; l < m_; ++l) {
                if (l == i) continue;
                LinearExpr e;
                e.AddTerm(enc_.stop[i][a], 1.0);
                e.AddTerm(enc_.start[l][b], 1.0);
                Add(e, -kInf, 1.0,
                    prefix_ + "gap_" + std::to_string(i) + "_" + std::to_string(a) + "_" +
                        std::to_string(l) + "_" + std::to_string(b));
              }
            }
          }
        }
      }
    }
    AddMaxBurnsCount();
  }

  // ---- thesis encoding ---------------------------------------------------
  void BuildThesis() {
    const OperationalRules& r = in_.rules;
    for (int j = 0; j < n_; ++j) {
      LinearExpr e;
      for (int i = 0; i < m_; ++i) e.AddTerm(enc_.on[i][j], 1.0);
      e.AddTerm(enc_.gamma[j], -1.0);
      Add(e, 0.0, 0.0, prefix_ + "gammadef_" + std::to_string(j));  // Xi_1 F - gamma = 0
    }
    // gamma_j <= K is the column bound of gamma.
    // (4.11) minimum duration. With K = 1 and a positive gap between
    // thrusters, "on at a and gamma_{a-1} = 0" is exactly a start at a.
    const bool gamma_start = single_ && gap_other_;
    for (int l = 0; l < m_; ++l) {
      for (int a = 0; a < n_; ++a) {
        for (int b = a + 1; b < n_ && Within(a, b, r.min_burn_s); ++b) {
          LinearExpr e = On(l, a) - On(l, b);
          e -= gamma_start ? Gamma(a - 1) : On(l, a - 1);
          Add(e, -kInf, 0.0,
              prefix_ + "minburn_" + std::to_string(l) + "_" + std::to_string(a) + "_" +
                  std::to_string(b));
        }
      }
    }
    // (4.16) same-thruster gap: a stop at a keeps l off on down(a).
    for (int l = 0; l < m_; ++l) {
      for (int a = 0; a < n_; ++a) {
        if (a == 0 && prev_on(l) == 0.0) continue;  // no stop possible at node 0
        for (int b = a + 1; b < n_ && Within(a, b, r.min_off_same_s); ++b) {
          LinearExpr e = On(l, a - 1) - On(l, a) + On(l, b);
          Add(e, -kInf, 1.0,
              prefix_ + "offsame_" + std::to_string(l) + "_" + std::to_string(a) + "_" +
                  std::to_string(b));
        }
      }
    }
    // (4.19) corrected: a stop of l at a forbids other thrusters on gap(a).
    if (gap_other_ && m_ > 1) {
      for (int l = 0; l < m_; ++l) {
        for (int a = 0; a < n_; ++a) {
          if (a == 0 && prev_on(l) == 0.0) continue;
          for (int b = a; b < n_ && Within(a, b, r.min_gap_other_s); ++b) {
            const std::string name = prefix_ + "offother_" + std::to_string(l) + "_" +
                                     std::to_string(a) + "_" + std::to_string(b);
            LinearExpr stop = On(l, a - 1) - On(l, a);
            if (single_) {
              // l itself is off at b when b == a or b lies in its own off window.
              const bool self_off = b == a || Within(a, b, r.min_off_same_s);
              LinearExpr e = stop;
              if (self_off) {
                e += Gamma(b);
              } else {
                for (int o = 0; o < m_; ++o) {
                  if (o != l) e.AddTerm(enc_.on[o][b], 1.0);
                }
              }
              Add(e, -kInf, 1.0, name);
            } else {
              for (int o = 0; o < m_; ++o) {
                if (o == l) continue;
                LinearExpr e = stop + On(o, b) - On(o, b - 1);
                Add(e, -kInf, 1.0, name + "_" + std::to_string(o));
              }
            }
          }
        }
      }
    }
    if (!enc_.start.empty()) {
      // start >= on[j] - on[j-1]: the smallest feasible value is the start indicator.
      for (int i = 0; i < m_; ++i) {
        for (int j = 0; j < n_; ++j) {
          LinearExpr e = LinearExpr(enc_.start[i][j]) - On(i, j) + On(i, j - 1);
          Add(e, 0.0, kInf, Name("startdef", i, j));
        }
      }
    }
    AddMaxBurnsCount();
  }

  void AddMaxSimultaneous() {
    const int k = in_.rules.max_simultaneous;
    if (k >= m_) return;
    for (int j = 0; j < n_; ++j) {
      LinearExpr e;
      for (int i = 0; i < m_; ++i) e.AddTerm(enc_.on[i][j], 1.0);
      Add(e, -kInf, k, prefix_ + "maxsim_" + std::to_string(j));
    }
  }

  void AddMaxBurnsCount() {
    const int limit = in_.rules.max_burns_per_thruster;
    if (limit < 0) return;
    for (int i = 0; i < m_; ++i) {
      LinearExpr e;
      for (int j = 0; j < n_; ++j) e.AddTerm(enc_.start[i][j], 1.0);
      Add(e, -kInf, limit, prefix_ + "maxburns_" + std::to_string(i));
    }
  }

  // Maximum burn duration: no run of consecutive on intervals spans more
  // than max_burn_s (the same sliding-window rows in both encodings).
  void AddMaxBurnRows() {
    const double tmax = in_.rules.max_burn_s;
    if (!std::isfinite(tmax)) return;
    for (int i = 0; i < m_; ++i) {
      for (int a = 0; a < n_; ++a) {
        int c = a + 1;
        while (c <= n_ && t_[c] - t_[a] <= tmax + kTimeTolerance) ++c;
        if (c > n_) break;  // later windows are longer than the horizon remainder
        LinearExpr e;
        for (int j = a; j < c; ++j) e.AddTerm(enc_.on[i][j], 1.0);
        Add(e, -kInf, c - a - 1, Name("maxburn", i, a));
      }
      if (in_.history.is_on(i)) {
        const double began = t_[0] - in_.history.on_for(i);
        int c = 0;
        while (c <= n_ && t_[c] - began <= tmax + kTimeTolerance) ++c;
        if (c <= n_) {
          LinearExpr e;
          for (int j = 0; j < c; ++j) e.AddTerm(enc_.on[i][j], 1.0);
          Add(e, -kInf, c - 1, Name("maxburnhist", i, 0));
        }
      }
    }
  }

  void ApplyNoStarts() {
    for (int i = 0; i < m_; ++i) {
      for (int j = 0; j < n_; ++j) {
        if (!no_start_[i][j]) continue;
        if (j == 0 && prev_on(i) == 0.0) {
          upper_[i][0] = 0.0;
          continue;
        }
        if (j == 0) continue;  // continuation of a burn on at t0 is not a start
        if (enc_.encoding == Encoding::kTight) {
          model_.SetBounds(enc_.start[i][j], 0.0, 0.0);
        } else {
          LinearExpr e = On(i, j) - On(i, j - 1);
          Add(e, -kInf, 0.0, Name("nostart", i, j));
        }
      }
    }
  }

  void ApplyBounds() {
    for (int i = 0; i < m_; ++i) {
      for (int j = 0; j < n_; ++j) {
        const double lo = lower_[i][j];
        const double hi = upper_[i][j];
        if (lo <= hi) {
          model_.SetBounds(enc_.on[i][j], lo, hi);
        } else {
          // Forced on (history) and forced off (window, disabled) at once.
          model_.SetBounds(enc_.on[i][j], 0.0, 0.0);
          Add(LinearExpr(enc_.on[i][j]), 1.0, kInf, Name("conflict", i, j));
          enc_.infeasibility_reasons.push_back("thruster " + std::to_string(i) +
                                               " must stay on in interval " + std::to_string(j) +
                                               " (burn in progress at t0) but is forced off there");
        }
      }
    }
  }

  milp::Model& model_;
  const EncodingInput& in_;
  const std::vector<double>& t_;
  std::string prefix_;
  OperationalEncoding enc_;
  int m_ = 0, n_ = 0;
  bool single_ = true, gap_other_ = false;
  std::vector<std::vector<double>> lower_, upper_;
  std::vector<std::vector<bool>> no_start_;
};

}  // namespace

std::string_view ToString(Encoding encoding) {
  return encoding == Encoding::kThesis ? "thesis" : "tight";
}

Encoding ParseEncoding(std::string_view name) {
  if (name == "thesis") return Encoding::kThesis;
  if (name == "tight") return Encoding::kTight;
  throw std::invalid_argument("encoding: unknown name \"" + std::string(name) +
                              "\" (expected thesis or tight)");
}

int IntervalsSpanning(const std::vector<double>& grid, int a, double duration_s) {
  const int n = static_cast<int>(grid.size()) - 1;
  if (duration_s <= kTimeTolerance) return 0;
  for (int k = 1; a + k <= n; ++k) {
    if (grid[a + k] - grid[a] >= duration_s - kTimeTolerance) return k;
  }
  return n - a + 1;
}

Eigen::MatrixXi OperationalEncoding::OnPattern(const Eigen::VectorXd& x) const {
  Eigen::MatrixXi pattern(num_thrusters, num_intervals);
  for (int i = 0; i < num_thrusters; ++i) {
    for (int j = 0; j < num_intervals; ++j) pattern(i, j) = x[on[i][j].index()] > 0.5 ? 1 : 0;
  }
  return pattern;
}

void OperationalEncoding::Complete(const Eigen::MatrixXi& pattern, Eigen::VectorXd* x) const {
  if (pattern.rows() != num_thrusters || pattern.cols() != num_intervals) {
    throw std::invalid_argument(
        "OperationalEncoding::Complete: pattern is " + std::to_string(pattern.rows()) + "x" +
        std::to_string(pattern.cols()) + ", expected " + std::to_string(num_thrusters) + "x" +
        std::to_string(num_intervals));
  }
  for (int i = 0; i < num_thrusters; ++i) {
    for (int j = 0; j < num_intervals; ++j) {
      const int now = pattern(i, j);
      const int before =
          j == 0 ? (i < static_cast<int>(prev_on.size()) ? prev_on[i] : 0) : pattern(i, j - 1);
      (*x)[on[i][j].index()] = now;
      if (!start.empty()) (*x)[start[i][j].index()] = std::max(0, now - before);
      if (!stop.empty()) (*x)[stop[i][j].index()] = std::max(0, before - now);
    }
  }
  for (int j = 0; j < static_cast<int>(gamma.size()); ++j) {
    (*x)[gamma[j].index()] = pattern.col(j).sum();
  }
}

OperationalEncoding AddOperationalConstraints(milp::Model* model, const EncodingInput& input,
                                              Encoding encoding, std::string_view prefix) {
  if (model == nullptr) throw std::invalid_argument("AddOperationalConstraints: model is null");
  Builder builder(model, input, encoding, prefix);
  OperationalEncoding enc = builder.Build();
  enc.prev_on.resize(input.num_thrusters);
  for (int i = 0; i < input.num_thrusters; ++i) enc.prev_on[i] = input.history.is_on(i) ? 1 : 0;
  return enc;
}

}  // namespace thrustsched::transcription
