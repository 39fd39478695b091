// The scheduling MILP of a ScheduleProblem. One file on purpose, ~700 lines:
// the columns, the dynamics rows (sparse or condensed, Gazzino 2018 (4.50)),
// the window, the terminal set and the objective share one index layout
// (ScheduleMilp's column maps), which splitting would spread over files.
#include "transcription/schedule_milp.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/constants.h"
#include "common/error.h"
#include "transcription/internal/row_buffer.h"
#include "transcription/partial_maps.h"
#include "transcription/terminal_sets.h"

namespace thrustsched::transcription {
namespace {

using internal::RowBuffer;

constexpr double kInf = std::numeric_limits<double>::infinity();

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

std::string Tag(const char* what, int a, int b) {
  return std::string(what) + "_" + std::to_string(a) + "_" + std::to_string(b);
}

// See ScheduleMilp::objective_step().
double ObjectiveStep(const milp::LpData& lp) {
  double smallest = 0.0;
  for (int j = 0; j < lp.num_cols(); ++j) {
    const double c = std::abs(lp.col_cost[j]);
    if (c == 0.0) continue;
    if (lp.col_type[j] == milp::VarType::kContinuous) return 0.0;
    if (smallest == 0.0 || c < smallest) smallest = c;
  }
  if (smallest == 0.0) return 0.0;
  for (int j = 0; j < lp.num_cols(); ++j) {
    const double ratio = std::abs(lp.col_cost[j]) / smallest;
    if (std::abs(ratio - std::round(ratio)) > 1e-9 * std::max(1.0, ratio)) return 0.0;
  }
  return smallest;
}

// See ScheduleMilp::least_firing_objective() and dearest_schedule_objective():
// {-inf, +inf} where the slots do not carry the whole objective at costs >= 0.
std::pair<double, double> FiringObjectiveRange(const milp::LpData& lp,
                                               const OperationalEncoding& enc,
                                               const OperationalRules& rules) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::pair<double, double> none{-kInf, kInf};
  if (lp.sense != milp::ObjectiveSense::kMinimize || enc.on.empty()) return none;
  std::vector<char> is_on(static_cast<size_t>(lp.num_cols()), 0);
  for (const auto& thruster : enc.on)
    for (const milp::Variable& v : thruster) is_on[static_cast<size_t>(v.index())] = 1;
  double cheapest = kInf;
  bool free_slot = false;  // a slot that can fire at no cost
  for (int j = 0; j < lp.num_cols(); ++j) {
    const double c = lp.col_cost[j];
    if (is_on[static_cast<size_t>(j)]) {
      if (c < 0.0) return none;
      if (lp.col_upper[j] < 0.5) continue;
      free_slot = free_slot || c == 0.0;
      cheapest = std::min(cheapest, c);
    } else if (c != 0.0) {
      return none;  // a cost that is not the slots' (a slack, an arrival time)
    }
  }
  // The dearest: in each interval the max_simultaneous dearest free slots.
  double dearest = lp.objective_offset;
  std::vector<double> costs;
  for (int j = 0; j < enc.num_intervals; ++j) {
    costs.clear();
    for (int i = 0; i < enc.num_thrusters; ++i) {
      const int c = enc.on[static_cast<size_t>(i)][static_cast<size_t>(j)].index();
      if (lp.col_upper[c] >= 0.5) costs.push_back(lp.col_cost[c]);
    }
    std::sort(costs.begin(), costs.end(), std::greater<double>());
    for (size_t k = 0; k < costs.size() && k < static_cast<size_t>(rules.max_simultaneous); ++k)
      dearest += costs[k];
  }
  if (!std::isfinite(cheapest) || free_slot) return {-kInf, dearest};
  // A burn from the history or one continuing past the end may be shorter.
  const bool shorter =
      rules.allow_burn_across_end ||
      std::any_of(enc.prev_on.begin(), enc.prev_on.end(), [](int on) { return on; });
  const int slots = shorter ? 1 : std::max(1, enc.min_burn_intervals_min);
  return {lp.objective_offset + slots * cheapest, dearest};
}

}  // namespace

std::string_view ToString(Formulation formulation) {
  return formulation == Formulation::kSparse ? "sparse" : "condensed";
}

Formulation ParseFormulation(std::string_view name) {
  if (name == "sparse") return Formulation::kSparse;
  if (name == "condensed") return Formulation::kCondensed;
  throw std::invalid_argument("formulation: unknown name \"" + std::string(name) +
                              "\" (expected sparse or condensed)");
}

void ComputeTotals(const dynamics::ThrusterSet& thrusters, Schedule* s) {
  const int m = thrusters.size();
  s->on_time_s.assign(m, 0.0);
  s->consumption_l1_m_s = s->delta_v_m_s = s->propellant_kg = 0.0;
  const double accel = thrusters.acceleration();
  for (const Burn& b : s->burns) {
    const double dt = b.duration_s();
    s->on_time_s[b.thruster] += dt;
    s->consumption_l1_m_s += thrusters.L1Factor(b.thruster) * dt;
    s->delta_v_m_s += accel * dt;
    s->propellant_kg += thrusters.MassFlow() * dt;
  }
  for (const Impulse& im : s->impulses) {
    s->consumption_l1_m_s += thrusters.L1Factor(im.thruster) / accel * im.delta_v_m_s;
    s->delta_v_m_s += im.delta_v_m_s;
    s->propellant_kg +=
        thrusters.mass_kg() * im.delta_v_m_s / (common::kStandardGravity_m_s2 * thrusters.isp_s());
  }
}

std::vector<Burn> BurnsFromPattern(const Eigen::MatrixXi& pattern,
                                   const std::vector<double>& grid) {
  std::vector<Burn> burns;
  for (int i = 0; i < pattern.rows(); ++i) {
    int j = 0;
    while (j < pattern.cols()) {
      if (pattern(i, j) == 0) {
        ++j;
        continue;
      }
      int k = j;
      while (k < pattern.cols() && pattern(i, k) != 0) ++k;
      burns.push_back({i, grid[j], grid[k]});
      j = k;
    }
  }
  std::sort(burns.begin(), burns.end(), [](const Burn& a, const Burn& b) {
    return a.start_s != b.start_s ? a.start_s < b.start_s : a.thruster < b.thruster;
  });
  return burns;
}

Eigen::MatrixXi PatternFromBurns(const std::vector<Burn>& burns, int num_thrusters,
                                 const std::vector<double>& grid) {
  const int n = static_cast<int>(grid.size()) - 1;
  Eigen::MatrixXi p = Eigen::MatrixXi::Zero(num_thrusters, n);
  for (const Burn& b : burns) {
    if (b.thruster < 0 || b.thruster >= num_thrusters) {
      throw std::invalid_argument("PatternFromBurns: thruster index " + std::to_string(b.thruster) +
                                  " out of range");
    }
    for (int j = 0; j < n; ++j) {
      const double mid = 0.5 * (grid[j] + grid[j + 1]);
      if (mid >= b.start_s && mid < b.end_s) p(b.thruster, j) = 1;
    }
  }
  return p;
}

bool BuildOptions::IsValid(std::string* error) const {
  std::string e;
  if (!discretisation.IsValid(&e)) return common::Fail(error, "discretisation." + e);
  return true;
}

ScheduleMilp::ScheduleMilp(const ScheduleProblem& problem, const BuildOptions& options)
    : problem_(problem), options_(options) {
  std::string err;
  if (!problem_.IsValid(&err)) throw std::invalid_argument(err);
  if (!options_.IsValid(&err)) throw std::invalid_argument("ScheduleMilp: options." + err);
  const auto t0 = std::chrono::steady_clock::now();
  discrete_ = dynamics::Discretize(*problem_.model, problem_.thrusters.AccelerationMatrix(),
                                   problem_.grid, options_.discretisation);
  stats_.discretise_seconds = Seconds(t0);
  Build();
}

ScheduleMilp::ScheduleMilp(const ScheduleProblem& problem, dynamics::DiscreteModel discrete,
                           const BuildOptions& options)
    : problem_(problem), options_(options), discrete_(std::move(discrete)) {
  std::string err;
  if (!problem_.IsValid(&err)) throw std::invalid_argument(err);
  if (discrete_.num_intervals() != problem_.num_intervals() ||
      discrete_.num_states() != problem_.model->num_states() ||
      discrete_.num_inputs() != problem_.thrusters.size()) {
    throw std::invalid_argument("ScheduleMilp: the discretisation does not match the problem (" +
                                std::to_string(discrete_.num_intervals()) + " intervals, " +
                                std::to_string(discrete_.num_inputs()) + " inputs)");
  }
  Build();
}

void ScheduleMilp::Build() {
  const auto t0 = std::chrono::steady_clock::now();
  const int n = problem_.model->num_states();
  scale_ = options_.scale ? problem_.model->state_scale() : Eigen::VectorXd::Ones(n);
  if (scale_.size() != n || !(scale_.array() > 0.0).all() || !scale_.allFinite()) {
    throw std::invalid_argument("ScheduleMilp: model " + std::string(problem_.model->name()) +
                                " returned an invalid state_scale");
  }
  model_ = milp::Model("thrustsched");
  if (problem_.input_mode == InputMode::kOnOff) {
    EncodingInput in;
    in.grid = problem_.grid;
    in.rules = problem_.rules;
    in.history = problem_.history;
    in.forced_off = problem_.forced_off;
    in.num_thrusters = problem_.thrusters.size();
    in.enabled.resize(in.num_thrusters);
    for (int i = 0; i < in.num_thrusters; ++i)
      in.enabled[i] = problem_.thrusters.thruster(i).enabled;
    in.need_starts = problem_.objective.burn_start_penalty > 0.0;
    encoding_ = AddOperationalConstraints(&model_, in, options_.encoding);
    reasons_ = encoding_.infeasibility_reasons;
  } else if (options_.formulation != Formulation::kSparse) {
    throw std::invalid_argument("impulsive input mode supports the sparse formulation only");
  }
  const Eigen::MatrixXi& mask = options_.free_slots;
  if (mask.size() > 0) {
    if (problem_.input_mode != InputMode::kOnOff || mask.rows() != problem_.thrusters.size() ||
        mask.cols() != problem_.num_intervals()) {
      throw std::invalid_argument("ScheduleMilp: free_slots must be thrusters x intervals (" +
                                  std::to_string(problem_.thrusters.size()) + " x " +
                                  std::to_string(problem_.num_intervals()) +
                                  ") in on-off mode, got " + std::to_string(mask.rows()) + " x " +
                                  std::to_string(mask.cols()));
    }
    // An always-off slot, and the start/stop indicators between two
    // always-off slots: any pattern the free slots allow keeps them at 0
    // (they are only bounded above by the rows), so they leave the model
    // with milp::RemoveFixedColumns, and with them the rows of the rules
    // that concern no free slot.
    for (int i = 0; i < mask.rows(); ++i) {
      for (int j = 0; j < mask.cols(); ++j) {
        if (mask(i, j) != 0) continue;
        model_.SetBounds(encoding_.on[i][j], 0.0, 0.0);
        const bool off_before = j > 0 ? mask(i, j - 1) == 0 : encoding_.prev_on[i] == 0;
        if (!off_before) continue;
        for (const auto* v : {&encoding_.start, &encoding_.stop}) {
          if (static_cast<int>(v->size()) > i && static_cast<int>((*v)[i].size()) > j) {
            model_.SetBounds((*v)[i][j], 0.0, 0.0);
          }
        }
      }
    }
  }
  if (options_.formulation == Formulation::kSparse) {
    BuildSparse();
  } else {
    BuildCondensed();
  }
  AddObjective();
  if (problem_.conjunction) AddConjunction();
  lp_ = model_.ToLpData();
  objective_step_ = ObjectiveStep(lp_);
  std::tie(least_firing_objective_, dearest_schedule_objective_) =
      FiringObjectiveRange(lp_, encoding_, problem_.rules);
  stats_.build_seconds = Seconds(t0);
  stats_.num_binaries = lp_.num_integer_cols();
  stats_.num_columns = lp_.num_cols();
  stats_.num_rows = lp_.num_rows();
  stats_.num_nonzeros = lp_.num_nonzeros();
}

namespace {

// Partial maps from each interval start to its inter-sample points (the
// window's intersample_points equally spaced inside each interval).
std::vector<std::vector<PartialMap>> InterSampleMaps(const ScheduleProblem& p,
                                                     const dynamics::DiscretizationOptions& opt) {
  const int r = p.window.intersample_points;
  std::vector<std::vector<PartialMap>> out(p.num_intervals());
  if (r <= 0) return out;
  std::vector<double> times;
  for (int j = 0; j < p.num_intervals(); ++j) {
    const double h = p.grid[j + 1] - p.grid[j];
    for (int k = 1; k <= r; ++k) times.push_back(p.grid[j] + h * k / (r + 1));
  }
  for (PartialMap& q :
       PartialMaps(*p.model, p.thrusters.AccelerationMatrix(), p.grid, times, opt)) {
    out[q.interval].push_back(std::move(q));
  }
  return out;
}

// The end-of-horizon sets of p.terminal (kStationKeepingSets): the window's
// along-track and normal half widths, shrunk by the window's planning margin
// and the terminal margin; look-ahead {0, horizon} unless given.
SkSetOptions SkOptionsOf(const ScheduleProblem& p) {
  const TerminalSpec& term = p.terminal;
  SkSetOptions o;
  o.mean_motion = HcwMeanMotion(*p.model);
  HcwWindowWidths(*p.model, p.window.outputs, p.window.half_widths, &o.eps_y, &o.eps_z);
  o.eps_y *= (1.0 - p.window.margin) * (1.0 - term.margin);
  o.eps_z *= (1.0 - p.window.margin) * (1.0 - term.margin);
  o.facets_out_of_plane = term.facets_out_of_plane;
  o.facets_cone_plus = term.facets_cone_plus;
  o.facets_cone_minus = term.facets_cone_minus;
  o.lookahead_s =
      term.lookahead_s.empty() ? std::vector<double>{0.0, p.horizon_s()} : term.lookahead_s;
  return o;
}

bool WindowActive(const ScheduleProblem& p, int node, double t) {
  return node >= 1 && t >= p.window.enforce_from_s - kTimeTolerance;
}

// The maps from each interval's start to the times of the state constraints
// in it: [interval] = (constraint index, map), in time order. A time within
// the horizon's tolerance outside it is taken at the horizon's end.
using ConstraintMaps = std::vector<std::vector<std::pair<int, PartialMap>>>;
ConstraintMaps StateConstraintMaps(const ScheduleProblem& p,
                                   const dynamics::DiscretizationOptions& opt) {
  ConstraintMaps out(p.num_intervals());
  const std::vector<StateConstraint>& cs = p.state_constraints;
  if (cs.empty()) return out;
  std::vector<int> order(cs.size());
  for (size_t k = 0; k < cs.size(); ++k) order[k] = static_cast<int>(k);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cs[a].t_s < cs[b].t_s; });
  std::vector<double> times;
  for (int k : order) times.push_back(std::clamp(cs[k].t_s, p.grid.front(), p.grid.back()));
  std::vector<PartialMap> maps =
      PartialMaps(*p.model, p.thrusters.AccelerationMatrix(), p.grid, times, opt);
  for (size_t q = 0; q < maps.size(); ++q)
    out[maps[q].interval].emplace_back(order[q], std::move(maps[q]));
  return out;
}

std::string StateConstraintName(const ScheduleProblem& p, int k) {
  const std::string& name = p.state_constraints[k].name;
  return "state_" + (name.empty() ? std::to_string(k) : name);
}

double Shifted(double bound, double shift) { return std::isfinite(bound) ? bound - shift : bound; }

}  // namespace

void ScheduleMilp::BuildSparse() {
  const ScheduleProblem& p = problem_;
  const dynamics::LinearModel& model = *p.model;
  const int n = model.num_states();
  const int m = p.thrusters.size();
  const int nn = p.num_intervals();
  const bool impulsive = p.input_mode == InputMode::kImpulsive;
  const Eigen::VectorXd& S = scale_;

  // State columns (scaled), node 0 fixed to the initial state.
  state_.assign(nn + 1, {});
  const std::vector<std::string> names = model.state_names();
  for (int j = 0; j <= nn; ++j) {
    for (int c = 0; c < n; ++c) {
      state_[j].push_back(
          model_.AddContinuous(-kInf, kInf, "x_" + names[c] + "_" + std::to_string(j)));
    }
  }
  for (int c = 0; c < n; ++c) {
    const double v = p.initial_state[c] / S[c];
    model_.SetBounds(state_[0][c], v, v);
  }
  Eigen::MatrixXd directions;  // impulsive: 3 x m unit vectors
  if (impulsive) {
    directions.resize(3, m);
    for (int i = 0; i < m; ++i) directions.col(i) = p.thrusters.thruster(i).direction;
    dv_.assign(m, {});
    for (int i = 0; i < m; ++i) {
      const double hi = p.thrusters.thruster(i).enabled ? p.MaxImpulse(i) : 0.0;
      for (int j = 0; j <= nn; ++j) {
        dv_[i].push_back(model_.AddContinuous(0.0, hi, Tag("dv", i, j)));
      }
    }
    for (int c = 0; c < n; ++c) {
      final_state_.push_back(model_.AddContinuous(-kInf, kInf, "xf_" + names[c]));
    }
  }

  RowBuffer rows(options_.scale);
  // The chain of states and the rows that define them (ExportLp's bounds);
  // the buffer's rows follow the model's in order.
  int next_row = model_.num_constraints();
  state_chain_.blocks.clear();
  for (const auto& node : state_) {
    state_chain_.blocks.emplace_back();
    for (const milp::Variable& v : node) state_chain_.blocks.back().push_back(v.index());
  }
  state_chain_.rows.assign(nn, {});
  // Dynamics: x~_{j+1} - S^-1 Phi S x~_j - S^-1 Gamma u_j = S^-1 d_j.
  for (int j = 0; j < nn; ++j) {
    const Eigen::MatrixXd& phi = discrete_.phi[j];
    Eigen::MatrixXd impulse_map;  // n x m: Phi_j B_j D
    if (impulsive) impulse_map = phi * model.Evaluate(p.grid[j]).b * directions;
    for (int r = 0; r < n; ++r) {
      rows.Begin();
      rows.Coef(state_[j + 1][r].index(), 1.0);
      for (int c = 0; c < n; ++c) rows.Coef(state_[j][c].index(), -phi(r, c) * S[c] / S[r]);
      for (int i = 0; i < m; ++i) {
        if (impulsive) {
          rows.Coef(dv_[i][j].index(), -impulse_map(r, i) / S[r]);
        } else {
          rows.Coef(encoding_.on[i][j].index(), -discrete_.gamma[j](r, i) / S[r]);
        }
      }
      const double rhs = discrete_.drift[j][r] / S[r];
      rows.End(rhs, rhs, Tag("dyn", r, j));
      state_chain_.rows[j].push_back(next_row++);
    }
  }
  if (impulsive) {
    // Final impulse: x_N+ = x_N + B_N D dv_N.
    const Eigen::MatrixXd last = model.Evaluate(p.grid.back()).b * directions;
    state_chain_.blocks.emplace_back();
    for (const milp::Variable& v : final_state_) state_chain_.blocks.back().push_back(v.index());
    state_chain_.rows.emplace_back();
    for (int r = 0; r < n; ++r) {
      rows.Begin();
      rows.Coef(final_state_[r].index(), 1.0);
      rows.Coef(state_[nn][r].index(), -1.0);
      for (int i = 0; i < m; ++i) rows.Coef(dv_[i][nn].index(), -last(r, i) / S[r]);
      rows.End(0.0, 0.0, "dyn_final_" + std::to_string(r));
      state_chain_.rows.back().push_back(next_row++);
    }
  }
  rows.Flush(&model_);

  // Window rows at nodes and inter-sample points.
  if (p.window.enabled()) {
    const auto partials = InterSampleMaps(p, options_.discretisation);
    auto add_window_row = [&](const Eigen::RowVectorXd& cx, int node_for_x,
                              const Eigen::RowVectorXd& cu, int interval_for_u, double shift, int k,
                              int node, int sub) {
      const double w = p.window.half_widths[k] * (1.0 - p.window.margin);  // planned box
      milp::Variable slack;
      if (p.window.soft) {
        slack = model_.AddContinuous(
            0.0, kInf,
            "viol_" + std::to_string(k) + "_" + std::to_string(node) + "_" + std::to_string(sub));
        slacks_.push_back({slack, node, k, sub});
      }
      const std::string tag = "win_" + std::to_string(k) + "_" + std::to_string(node) +
                              (sub > 0 ? "_" + std::to_string(sub) : "");
      for (int side = 0; side < (p.window.soft ? 2 : 1); ++side) {
        rows.Begin();
        for (int c = 0; c < n; ++c) rows.Coef(state_[node_for_x][c].index(), cx[c] * S[c] / w);
        if (interval_for_u >= 0) {
          for (int i = 0; i < m; ++i) rows.Coef(encoding_.on[i][interval_for_u].index(), cu[i] / w);
        }
        const double lo = -1.0 - shift / w, hi = 1.0 - shift / w;
        if (!p.window.soft) {
          rows.End(lo, hi, tag);
        } else if (side == 0) {
          rows.Coef(slack.index(), -1.0);
          rows.End(-kInf, hi, tag + "_hi");
        } else {
          rows.Coef(slack.index(), 1.0);
          rows.End(lo, kInf, tag + "_lo");
        }
      }
    };
    for (int j = 0; j <= nn; ++j) {
      if (WindowActive(p, j, p.grid[j])) {
        const Eigen::MatrixXd c = model.EvaluateOutput(p.grid[j]).c;
        for (size_t k = 0; k < p.window.outputs.size(); ++k) {
          add_window_row(c.row(p.window.outputs[k]), j, Eigen::RowVectorXd(), -1, 0.0,
                         static_cast<int>(k), j, 0);
        }
      }
      if (j == nn || impulsive) continue;
      for (size_t s = 0; s < partials[j].size(); ++s) {
        const PartialMap& q = partials[j][s];
        if (!WindowActive(p, j + 1, q.t)) continue;
        const Eigen::MatrixXd c = model.EvaluateOutput(q.t).c;
        for (size_t k = 0; k < p.window.outputs.size(); ++k) {
          const int o = p.window.outputs[k];
          add_window_row(c.row(o) * q.phi, j, c.row(o) * q.gamma, j, c.row(o).dot(q.drift),
                         static_cast<int>(k), j, static_cast<int>(s) + 1);
        }
      }
    }
  }
  rows.Flush(&model_);

  // Path constraints, on their interval's start node and on-columns.
  const ConstraintMaps constrained = StateConstraintMaps(p, options_.discretisation);
  for (int j = 0; j < nn; ++j) {
    for (const auto& [k, q] : constrained[j]) {
      const StateConstraint& c = p.state_constraints[k];
      const Eigen::RowVectorXd on_state = c.a.transpose() * q.phi;
      const Eigen::RowVectorXd on_thrust = c.a.transpose() * q.gamma;
      rows.Begin();
      for (int i = 0; i < n; ++i) rows.Coef(state_[j][i].index(), on_state[i] * S[i]);
      for (int i = 0; i < m; ++i) rows.Coef(encoding_.on[i][j].index(), on_thrust[i]);
      const double shift = c.a.dot(q.drift);
      rows.End(Shifted(c.lower, shift), Shifted(c.upper, shift), StateConstraintName(p, k));
    }
  }
  rows.Flush(&model_);

  // Terminal constraint on the final state (after the last impulse).
  const std::vector<milp::Variable>& xf = impulsive ? final_state_ : state_[nn];
  const TerminalSpec& term = p.terminal;
  if (term.kind == TerminalKind::kFixedState || term.kind == TerminalKind::kStateBox) {
    for (int c = 0; c < n; ++c) {
      const double tol = term.kind == TerminalKind::kStateBox ? term.tolerance[c] : 0.0;
      model_.SetBounds(xf[c], (term.target[c] - tol) / S[c], (term.target[c] + tol) / S[c]);
    }
  } else if (term.kind == TerminalKind::kStationKeepingSets) {
    const HalfSpaces h = StationKeepingSet(SkOptionsOf(p));
    const AffineMap map = HcwCoordinates(model, p.grid.back());
    const Eigen::MatrixXd coef = h.a * map.map;  // rows x n, in model state units
    const Eigen::VectorXd rhs = h.b - h.a * map.offset;
    for (int r = 0; r < h.rows(); ++r) {
      rows.Begin();
      for (int c = 0; c < n; ++c) rows.Coef(xf[c].index(), coef(r, c) * S[c]);
      rows.End(-kInf, rhs[r], h.names[r]);
    }
    rows.Flush(&model_);
  }
}

void ScheduleMilp::BuildCondensed() {
  // Window rows are handed to the model in chunks of about this many entries
  // (16 MB of triplets): a restricted six-thruster week's hold 8.5 M.
  constexpr size_t kFlushEntries = size_t{1} << 20;
  const ScheduleProblem& p = problem_;
  const dynamics::LinearModel& model = *p.model;
  const int n = model.num_states();
  const int m = p.thrusters.size();
  const int nn = p.num_intervals();
  RowBuffer rows(options_.scale);
  const auto partials = InterSampleMaps(p, options_.discretisation);
  const ConstraintMaps constrained = StateConstraintMaps(p, options_.discretisation);

  // x_j = base_j + G_j u over the free on-columns (all of them without a
  // free_slots mask), stacked in time order: G_j has nonzeros in the columns
  // of the intervals before j only. A fixed slot (always off) adds nothing.
  std::vector<milp::Variable> cols;                            // the free on-columns, in time order
  std::vector<int> first_col(static_cast<size_t>(nn) + 1, 0);  // of interval j
  for (int j = 0; j < nn; ++j) {
    first_col[static_cast<size_t>(j)] = static_cast<int>(cols.size());
    for (int i = 0; i < m; ++i) {
      if (options_.free_slots.size() == 0 || options_.free_slots(i, j) != 0) {
        cols.push_back(encoding_.on[i][j]);
      }
    }
  }
  first_col[static_cast<size_t>(nn)] = static_cast<int>(cols.size());
  Eigen::VectorXd base = p.initial_state;
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(cols.size()));
  auto add_row = [&](const Eigen::RowVectorXd& coef, int used_cols, double shift, double lo,
                     double hi, const std::string& name, milp::Variable slack, double slack_coef) {
    rows.Begin();
    for (int col = 0; col < used_cols; ++col)
      rows.Coef(cols[static_cast<size_t>(col)].index(), coef[col]);
    if (slack.is_valid()) rows.Coef(slack.index(), slack_coef);
    rows.End(std::isfinite(lo) ? lo - shift : lo, std::isfinite(hi) ? hi - shift : hi, name);
  };
  auto add_window = [&](const Eigen::RowVectorXd& coef, int used_cols, double shift, int k,
                        int node, int sub) {
    const double w = p.window.half_widths[k] * (1.0 - p.window.margin);  // planned box
    const std::string tag = "win_" + std::to_string(k) + "_" + std::to_string(node) +
                            (sub > 0 ? "_" + std::to_string(sub) : "");
    if (!p.window.soft) {
      add_row(coef / w, used_cols, shift / w, -1.0, 1.0, tag, milp::Variable(), 0.0);
      return;
    }
    milp::Variable slack = model_.AddContinuous(
        0.0, kInf,
        "viol_" + std::to_string(k) + "_" + std::to_string(node) + "_" + std::to_string(sub));
    slacks_.push_back({slack, node, k, sub});
    add_row(coef / w, used_cols, shift / w, -kInf, 1.0, tag + "_hi", slack, -1.0);
    add_row(coef / w, used_cols, shift / w, -1.0, kInf, tag + "_lo", slack, 1.0);
  };

  // Gamma_j's columns of the free slots of interval j.
  auto gamma_free = [&](const Eigen::MatrixXd& gamma, int j) {
    Eigen::MatrixXd out(gamma.rows(),
                        first_col[static_cast<size_t>(j) + 1] - first_col[static_cast<size_t>(j)]);
    int k = 0;
    for (int i = 0; i < m; ++i) {
      if (options_.free_slots.size() == 0 || options_.free_slots(i, j) != 0)
        out.col(k++) = gamma.col(i);
    }
    return out;
  };
  for (int j = 0; j <= nn; ++j) {
    const int used = first_col[static_cast<size_t>(j)];
    if (p.window.enabled() && WindowActive(p, j, p.grid[j])) {
      const Eigen::MatrixXd c = model.EvaluateOutput(p.grid[j]).c;
      for (size_t k = 0; k < p.window.outputs.size(); ++k) {
        const int o = p.window.outputs[k];
        const Eigen::RowVectorXd coef = c.row(o) * g.leftCols(used);
        add_window(coef, used, c.row(o).dot(base), static_cast<int>(k), j, 0);
      }
    }
    if (j == nn) break;
    if (p.window.enabled()) {
      for (size_t s = 0; s < partials[j].size(); ++s) {
        const PartialMap& q = partials[j][s];
        if (!WindowActive(p, j + 1, q.t)) continue;
        const Eigen::MatrixXd c = model.EvaluateOutput(q.t).c;
        const Eigen::MatrixXd qg = gamma_free(q.gamma, j);
        for (size_t k = 0; k < p.window.outputs.size(); ++k) {
          const int o = p.window.outputs[k];
          const int here = static_cast<int>(qg.cols());
          Eigen::RowVectorXd coef = Eigen::RowVectorXd::Zero(used + here);
          const Eigen::RowVectorXd cphi = c.row(o) * q.phi;
          coef.head(used) = cphi * g.leftCols(used);
          coef.tail(here) = c.row(o) * qg;
          add_window(coef, used + here, cphi.dot(base) + c.row(o).dot(q.drift), static_cast<int>(k),
                     j, static_cast<int>(s) + 1);
        }
      }
    }
    for (const auto& [k, q] : constrained[j]) {
      const StateConstraint& c = p.state_constraints[k];
      const Eigen::MatrixXd qg = gamma_free(q.gamma, j);
      const int here = static_cast<int>(qg.cols());
      const Eigen::RowVectorXd aphi = c.a.transpose() * q.phi;
      Eigen::RowVectorXd coef(used + here);
      coef.head(used) = aphi * g.leftCols(used);
      coef.tail(here) = c.a.transpose() * qg;
      add_row(coef, used + here, aphi.dot(base) + c.a.dot(q.drift), c.lower, c.upper,
              StateConstraintName(p, k), milp::Variable(), 0.0);
    }
    if (rows.pending_entries() > kFlushEntries) rows.Flush(&model_);
    // Advance: x_{j+1} = Phi_j x_j + Gamma_j u_j + d_j.
    const Eigen::MatrixXd& phi = discrete_.phi[j];
    g.leftCols(used) = phi * g.leftCols(used);
    const Eigen::MatrixXd gj = gamma_free(discrete_.gamma[j], j);
    g.middleCols(used, gj.cols()) = gj;
    base = phi * base + discrete_.drift[j];
  }
  rows.Flush(&model_);

  // Terminal rows on x_N = base + G u.
  const TerminalSpec& term = p.terminal;
  const int used = static_cast<int>(cols.size());
  if (term.kind == TerminalKind::kFixedState || term.kind == TerminalKind::kStateBox) {
    for (int c = 0; c < n; ++c) {
      const double tol = term.kind == TerminalKind::kStateBox ? term.tolerance[c] : 0.0;
      const double s = scale_[c];
      add_row(g.row(c) / s, used, base[c] / s, (term.target[c] - tol) / s,
              (term.target[c] + tol) / s, "terminal_" + std::to_string(c), milp::Variable(), 0.0);
    }
  } else if (term.kind == TerminalKind::kStationKeepingSets) {
    const HalfSpaces h = StationKeepingSet(SkOptionsOf(p));
    const AffineMap map = HcwCoordinates(model, p.grid.back());
    const Eigen::MatrixXd a = h.a * map.map;
    for (int r = 0; r < h.rows(); ++r) {
      const double shift = a.row(r).dot(base) + h.a.row(r).dot(map.offset);
      add_row(a.row(r) * g, used, shift, -kInf, h.b[r], h.names[r], milp::Variable(), 0.0);
    }
  }
  rows.Flush(&model_);
}

void ScheduleMilp::AddConjunction() {
  if (options_.formulation != Formulation::kSparse) {
    throw std::invalid_argument("conjunction: the keep-out rows need the sparse formulation");
  }
  KeepOutColumns cols;
  cols.state = state_;
  cols.scale = scale_;
  cols.impulsive = problem_.input_mode == InputMode::kImpulsive;
  cols.thrust = cols.impulsive ? dv_ : encoding_.on;
  keep_out_ = AddKeepOut(problem_, discrete_, options_.discretisation, cols, &model_,
                         options_.keep_out_bound_solver);
  reasons_.insert(reasons_.end(), keep_out_->infeasibility_reasons.begin(),
                  keep_out_->infeasibility_reasons.end());
}

void ScheduleMilp::AddObjective() {
  const ScheduleProblem& p = problem_;
  const int m = p.thrusters.size();
  const double accel = p.thrusters.acceleration();
  // Cost of thruster i per second on (on-off) or per m/s of delta-v (impulsive).
  std::vector<double> rate(m);
  for (int i = 0; i < m; ++i) {
    double per_second = 0.0;
    switch (p.objective.kind) {
      case ObjectiveKind::kL1:
        per_second = p.thrusters.L1Factor(i);
        break;
      case ObjectiveKind::kDeltaV:
        per_second = accel;
        break;
      case ObjectiveKind::kPropellant:
        per_second = p.thrusters.MassFlow();
        break;
    }
    rate[i] = p.input_mode == InputMode::kImpulsive ? per_second / accel : per_second;
  }
  milp::LinearExpr obj;
  if (p.input_mode == InputMode::kOnOff) {
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < p.num_intervals(); ++j) {
        obj.AddTerm(encoding_.on[i][j], rate[i] * (p.grid[j + 1] - p.grid[j]));
      }
    }
    if (p.objective.burn_start_penalty > 0.0) {
      for (int i = 0; i < m; ++i) {
        for (int j = 0; j < p.num_intervals(); ++j) {
          obj.AddTerm(encoding_.start[i][j], p.objective.burn_start_penalty);
        }
      }
    }
  } else {
    for (int i = 0; i < m; ++i) {
      for (const milp::Variable& v : dv_[i]) obj.AddTerm(v, rate[i]);
    }
  }
  for (const SoftSlack& s : slacks_) obj.AddTerm(s.var, p.window.soft_penalty);
  model_.Minimize(obj);
}

std::vector<Eigen::VectorXd> ScheduleMilp::PropagateDiscrete(
    const Eigen::MatrixXi& pattern, const Eigen::MatrixXd& impulses) const {
  const ScheduleProblem& p = problem_;
  const int nn = p.num_intervals();
  std::vector<Eigen::VectorXd> x(nn + 1);
  x[0] = p.initial_state;
  Eigen::MatrixXd directions;
  if (p.input_mode == InputMode::kImpulsive) {
    directions.resize(3, p.thrusters.size());
    for (int i = 0; i < p.thrusters.size(); ++i)
      directions.col(i) = p.thrusters.thruster(i).direction;
  }
  for (int j = 0; j < nn; ++j) {
    if (p.input_mode == InputMode::kOnOff) {
      x[j + 1] = discrete_.phi[j] * x[j] + discrete_.gamma[j] * pattern.col(j).cast<double>() +
                 discrete_.drift[j];
    } else {
      const Eigen::VectorXd kick = p.model->Evaluate(p.grid[j]).b * directions * impulses.col(j);
      x[j + 1] = discrete_.phi[j] * (x[j] + kick) + discrete_.drift[j];
    }
  }
  return x;
}

Schedule ScheduleMilp::Decode(const Eigen::VectorXd& x) const {
  if (x.size() != lp_.num_cols()) {
    throw std::invalid_argument("ScheduleMilp::Decode: solution has " + std::to_string(x.size()) +
                                " values, the model has " + std::to_string(lp_.num_cols()) +
                                " columns");
  }
  const ScheduleProblem& p = problem_;
  const int m = p.thrusters.size();
  const int nn = p.num_intervals();
  Schedule s;
  Eigen::MatrixXd impulses = Eigen::MatrixXd::Zero(m, nn + 1);
  if (p.input_mode == InputMode::kOnOff) {
    s.pattern = encoding_.OnPattern(x);
    s.burns = BurnsFromPattern(s.pattern, p.grid);
  } else {
    for (int j = 0; j <= nn; ++j) {
      for (int i = 0; i < m; ++i) {
        const double v = x[dv_[i][j].index()];
        if (v > 1e-12) {
          impulses(i, j) = v;
          s.impulses.push_back({i, j, p.grid[j], v});
        }
      }
    }
  }
  ComputeTotals(p.thrusters, &s);
  s.states = PropagateDiscrete(s.pattern, impulses);
  for (int j = 0; j <= nn; ++j) {
    s.outputs.push_back(p.model->EvaluateOutput(p.grid[j]).c * s.states[j]);
  }
  return s;
}

Eigen::VectorXd ScheduleMilp::StartFromBurns(const std::vector<Burn>& burns) const {
  const ScheduleProblem& p = problem_;
  if (p.input_mode != InputMode::kOnOff) {
    throw std::invalid_argument("StartFromBurns: only for the on-off input mode");
  }
  return StartFromPattern(PatternFromBurns(burns, p.thrusters.size(), p.grid));
}

bool ScheduleMilp::CompleteFromPattern(Eigen::VectorXd* x) const {
  if (problem_.input_mode != InputMode::kOnOff || x->size() != lp_.num_cols()) return false;
  const int m = static_cast<int>(encoding_.on.size());
  const int n = problem_.num_intervals();
  Eigen::MatrixXi pattern = Eigen::MatrixXi::Zero(m, n);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      const double v = (*x)[encoding_.on[i][j].index()];
      if (!(std::abs(v) <= 1e-6 || std::abs(v - 1.0) <= 1e-6)) return false;  // NaN too
      pattern(i, j) = v > 0.5 ? 1 : 0;
    }
  }
  *x = StartFromPattern(pattern);
  return true;
}

Eigen::VectorXd ScheduleMilp::StartFromPattern(const Eigen::MatrixXi& pattern) const {
  const ScheduleProblem& p = problem_;
  if (p.input_mode != InputMode::kOnOff) {
    throw std::invalid_argument("StartFromPattern: only for the on-off input mode");
  }
  Eigen::VectorXd x = Eigen::VectorXd::Zero(lp_.num_cols());
  encoding_.Complete(pattern, &x);
  const std::vector<Eigen::VectorXd> states = PropagateDiscrete(pattern, Eigen::MatrixXd());
  for (size_t j = 0; j < state_.size(); ++j) {
    for (size_t c = 0; c < state_[j].size(); ++c)
      x[state_[j][c].index()] = states[j][c] / scale_[c];
  }
  // Soft-window slacks: each appears in two rows lo <= a x + coef * slack <=
  // hi (coef > 0 in the lower-bound row, < 0 in the upper-bound row); raise
  // it until both hold.
  if (!slacks_.empty()) {
    const Eigen::VectorXd act = lp_.a_matrix * x;  // slacks are 0 here
    for (const SoftSlack& sl : slacks_) {
      double need = 0.0;
      for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(lp_.a_matrix,
                                                                               sl.var.index());
           it; ++it) {
        const int row = static_cast<int>(it.row());
        const double a = it.value();
        if (a > 0 && act[row] < lp_.row_lower[row]) {
          need = std::max(need, (lp_.row_lower[row] - act[row]) / a);
        }
        if (a < 0 && act[row] > lp_.row_upper[row]) {
          need = std::max(need, (act[row] - lp_.row_upper[row]) / -a);
        }
      }
      x[sl.var.index()] = need;
    }
  }
  if (keep_out_) CompleteKeepOut(lp_, *keep_out_, &x);
  return x;
}

}  // namespace thrustsched::transcription
