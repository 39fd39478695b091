#include "app/conjunction_report.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "app/outputs.h"
#include "common/format.h"

namespace thrustsched::app {

using common::FormatG;

namespace {

std::string G(double v, int digits = 4) {
  if (std::isnan(v)) return "n/a";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return FormatG(v, digits);
}

}  // namespace

std::optional<transcription::ConjunctionCheckReport> VerifyConjunction(
    const Scenario& s, const std::vector<transcription::Burn>& burns,
    const std::vector<transcription::Impulse>& impulses) {
  if (!s.problem.conjunction) return std::nullopt;
  const transcription::ConjunctionCheckOptions o =
      s.conjunction_check.value_or(transcription::ConjunctionCheckOptions{});
  return transcription::CheckConjunction(s.problem, burns, impulses, o);
}

void PrintKeepOut(std::ostream& os, const transcription::KeepOutStats& k) {
  os << "keep-out      " << k.num_checks << " checks (" << k.checks_clear
     << " clear whatever the plan, " << k.checks_single_face << " with one possible face, "
     << k.checks_with_binaries << " with binaries): " << k.num_binaries << " binaries, "
     << k.num_rows << " rows; big-M " << G(k.big_m_min_m) << " to " << G(k.big_m_max_m)
     << " m (median " << G(k.big_m_median_m) << "), from the cost budget " << G(k.cost_budget)
     << "; eps' " << G(k.threshold) << ", margin up to " << G(k.margin_max_m) << " m";
  if (k.covariance_repaired) {
    os << "; covariance repaired (smallest eigenvalue " << G(k.covariance_min_eigenvalue)
       << " clipped to 0)";
  }
  os << "\n";
}

void PrintConjunctionCheck(std::ostream& os, const transcription::ConjunctionCheckReport& r) {
  os << "conjunction   " << (r.passed() ? "PASSED" : "FAILED") << ": max instantaneous risk "
     << G(r.max_risk) << " at t = " << G(r.max_risk_time_s, 8) << " s (threshold " << G(r.threshold)
     << "; without manoeuvre " << G(r.max_risk_unmanoeuvred)
     << " at t = " << G(r.max_risk_unmanoeuvred_time_s, 8) << " s); closest mean approach "
     << G(r.min_mean_distance_m) << " m (without manoeuvre "
     << G(r.min_mean_distance_unmanoeuvred_m) << " m)\n";
  if (r.samples > 0) {
    os << "monte carlo   " << r.samples << " samples, step " << G(r.step_s) << " s: linear "
       << r.collisions_linear << " collisions (closest " << G(r.min_distance_linear_m) << " m; "
       << r.collisions_unmanoeuvred_linear << " without manoeuvre)";
    if (r.nonlinear_checked) {
      os << ", nonlinear two-body " << r.collisions_nonlinear << " collisions (closest "
         << G(r.min_distance_nonlinear_m) << " m)";
    } else if (!r.nonlinear_note.empty()) {
      os << "; " << r.nonlinear_note;
    }
    os << "; " << G(r.seconds, 3) << " s\n";
  }
}

void PrintConjunctionSolve(std::ostream& os, const transcription::ConjunctionSolve& cs) {
  if (!std::isnan(cs.without_objective)) {
    const double extra = cs.extra_cost();
    os << "without       " << G(cs.without_objective, 8)
       << " (the plan without the conjunction, bound " << G(cs.lower_bound, 8) << ")";
    if (!std::isnan(extra)) {
      os << "; extra cost of the avoidance " << G(extra, 4);
      if (cs.without_objective > 0.0)
        os << " (" << G(100.0 * extra / cs.without_objective, 3) << " %)";
    }
    os << "\n";
  }
  if (!std::isnan(cs.start_objective)) {
    os << "start         " << G(cs.start_objective, 6) << " (fixed faces: " << cs.start_label
       << "), " << G(cs.start_seconds, 3) << " s\n";
  }
  for (size_t i = 0; i < cs.rounds.size(); ++i) {
    const transcription::BudgetRound& b = cs.rounds[i];
    os << "round " << i + 1 << "       budget " << G(b.budget, 6) << ": " << b.binaries
       << " keep-out binaries, " << StatusName(b.status) << ", objective " << G(b.objective, 6)
       << ", bound " << G(b.best_bound, 6) << ", " << G(b.seconds, 3) << " s"
       << (b.restarted ? " (cheaper plan found: rebuilt with its cost)" : "") << "\n";
  }
}

nlohmann::json ConjunctionJson(const std::optional<transcription::KeepOutStats>& keep_out,
                               const transcription::ConjunctionSolve* cs,
                               const transcription::ConjunctionCheckReport* v) {
  nlohmann::json j;
  if (cs != nullptr) {
    nlohmann::json rounds = nlohmann::json::array();
    for (const transcription::BudgetRound& b : cs->rounds) {
      rounds.push_back({{"budget", b.budget},
                        {"keep_out_binaries", b.binaries},
                        {"status", StatusName(b.status)},
                        {"objective", FiniteOrNull(b.objective)},
                        {"best_bound", FiniteOrNull(b.best_bound)},
                        {"seconds", b.seconds},
                        {"restarted", b.restarted}});
    }
    j["solve"] = {{"start_objective", FiniteOrNull(cs->start_objective)},
                  {"start_label", cs->start_label},
                  {"start_seconds", cs->start_seconds},
                  {"rounds", rounds},
                  {"without_conjunction_objective", FiniteOrNull(cs->without_objective)},
                  {"lower_bound", FiniteOrNull(cs->lower_bound)},
                  {"extra_cost", FiniteOrNull(cs->extra_cost())}};
  } else {
    j["solve"] = nullptr;
  }
  if (keep_out) {
    const transcription::KeepOutStats& k = *keep_out;
    j["keep_out"] = {{"num_checks", k.num_checks},
                     {"checks_clear", k.checks_clear},
                     {"checks_single_face", k.checks_single_face},
                     {"checks_with_binaries", k.checks_with_binaries},
                     {"faces_impossible", k.faces_impossible},
                     {"num_binaries", k.num_binaries},
                     {"num_rows", k.num_rows},
                     {"big_m_min_m", FiniteOrNull(k.big_m_min_m)},
                     {"big_m_median_m", FiniteOrNull(k.big_m_median_m)},
                     {"big_m_max_m", FiniteOrNull(k.big_m_max_m)},
                     {"cost_budget", FiniteOrNull(k.cost_budget)},
                     {"instantaneous_threshold", k.threshold},
                     {"quantile", k.quantile},
                     {"margin_max_m", k.margin_max_m},
                     {"covariance_min_eigenvalue", k.covariance_min_eigenvalue},
                     {"covariance_repaired", k.covariance_repaired},
                     {"infeasibility_reasons", k.infeasibility_reasons}};
  } else {
    j["keep_out"] = nullptr;
  }
  if (v == nullptr) {
    j["verification"] = nullptr;
    return j;
  }
  j["verification"] = {
      {"passed", v->passed()},
      {"threshold", v->threshold},
      {"max_risk", v->max_risk},
      {"max_risk_time_s", FiniteOrNull(v->max_risk_time_s)},
      {"max_risk_unmanoeuvred", v->max_risk_unmanoeuvred},
      {"max_risk_unmanoeuvred_time_s", FiniteOrNull(v->max_risk_unmanoeuvred_time_s)},
      {"min_mean_distance_m", FiniteOrNull(v->min_mean_distance_m)},
      {"min_mean_distance_time_s", FiniteOrNull(v->min_mean_distance_time_s)},
      {"min_mean_distance_unmanoeuvred_m", FiniteOrNull(v->min_mean_distance_unmanoeuvred_m)},
      {"monte_carlo_samples", v->samples},
      {"monte_carlo_step_s", v->step_s},
      {"collisions_linear", v->collisions_linear},
      {"collisions_unmanoeuvred_linear", v->collisions_unmanoeuvred_linear},
      {"min_distance_linear_m", FiniteOrNull(v->min_distance_linear_m)},
      {"nonlinear_checked", v->nonlinear_checked},
      {"nonlinear_note", v->nonlinear_note},
      {"collisions_nonlinear", v->collisions_nonlinear},
      {"min_distance_nonlinear_m", FiniteOrNull(v->min_distance_nonlinear_m)},
      {"seconds", v->seconds}};
  return j;
}

}  // namespace thrustsched::app
