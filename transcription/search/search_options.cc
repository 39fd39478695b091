#include "transcription/search/search_options.h"

#include <algorithm>
#include <string>

#include "common/format.h"

namespace thrustsched::transcription {

namespace {

using common::FormatG;

// Writes "search.<path> must be <rule>, got <value>" and returns false.
bool Fail(std::string* error, const std::string& path, const std::string& rule,
          const std::string& value) {
  if (error != nullptr) *error = "search." + path + " must be " + rule + ", got " + value;
  return false;
}

bool AtLeast(std::string* error, const std::string& path, long long value, long long least) {
  return value >= least || Fail(error, path, ">= " + std::to_string(least), std::to_string(value));
}

// A share of the time left: (0, 1].
bool Share(std::string* error, const std::string& path, double value) {
  return (value > 0.0 && value <= 1.0) || Fail(error, path, "in (0, 1]", FormatG(value, 6));
}

}  // namespace

bool RelaxationOptions::IsValid(std::string* /*error*/) const { return true; }

const char* ToString(RelaxationOptions::LpMethod method) {
  return method == RelaxationOptions::LpMethod::kInteriorPoint ? "interior_point" : "clp_barrier";
}

bool ParseLpMethod(const std::string& name, RelaxationOptions::LpMethod* method) {
  for (auto m :
       {RelaxationOptions::LpMethod::kClpBarrier, RelaxationOptions::LpMethod::kInteriorPoint}) {
    if (name == ToString(m)) {
      *method = m;
      return true;
    }
  }
  return false;
}

bool NetOptions::IsValid(std::string* error) const {
  if (!(candidate_threshold > 0.0 && candidate_threshold < 1.0)) {
    return Fail(error, "nets.candidate_threshold", "in (0, 1)", FormatG(candidate_threshold, 6));
  }
  return AtLeast(error, "nets.neighbourhood", neighbourhood, 0) &&
         AtLeast(error, "nets.max_widenings", max_widenings, 0) &&
         AtLeast(error, "nets.fired_thrusters_net_after", fired_thrusters_net_after, 0) &&
         AtLeast(error, "nets.max_widened_slots", max_widened_slots, 0) &&
         Share(error, "nets.time_share", time_share) &&
         AtLeast(error, "nets.improvement_rounds", improvement_rounds, 0) &&
         AtLeast(error, "nets.max_improvement_slots", max_improvement_slots, 0) &&
         Share(error, "nets.improvement_time_share", improvement_time_share);
}

bool RestrictedMilpOptions::IsValid(std::string* error) const {
  if (!AtLeast(error, "restricted.max_nodes", max_nodes, 0)) return false;
  std::string lazy;
  if (!lazy_row_options.IsValid(&lazy)) {
    if (error != nullptr) *error = "search.restricted.lazy_row_options: " + lazy;
    return false;
  }
  return true;
}

bool ExactOptions::IsValid(std::string* error) const {
  return AtLeast(error, "exact.max_slots", max_slots, 0) &&
         Share(error, "exact.time_share_before_tree", time_share_before_tree);
}

bool TreePhaseOptions::IsValid(std::string* error) const {
  if (window_levels < 0 || window_levels > 16) {
    return Fail(error, "tree.window_levels", "in [0, 16]", std::to_string(window_levels));
  }
  return AtLeast(error, "tree.max_lps", max_lps, 0) &&
         AtLeast(error, "tree.shape.max_window_lps", shape.max_window_lps, 0) &&
         AtLeast(error, "tree.max_exact_leaf_slots", max_exact_leaf_slots, 0) &&
         AtLeast(error, "tree.max_leaf_net_slots", max_leaf_net_slots, 0) &&
         AtLeast(error, "tree.other_leaf_nets", other_leaf_nets, 0);
}

bool ExchangeOptions::IsValid(std::string* error) const {
  return AtLeast(error, "exchange.max_slots", max_slots, 0) &&
         Share(error, "exchange.time_share", time_share);
}

bool SearchOptions::PhaseEnabled(const std::string& name) const {
  return std::find(disabled_phases.begin(), disabled_phases.end(), name) == disabled_phases.end();
}

const std::vector<std::string>& SearchPhaseNames() {
  static const std::vector<std::string> names = {
      "relaxation", "nets", "tree", "exact", "improvement", "exchange", "windows", "whole_milp"};
  return names;
}

const std::vector<std::string>& SearchPlanNames() {
  static const std::vector<std::string> names = {"default", "exact_first"};
  return names;
}

namespace {

std::string Joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

bool Known(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

bool SearchOptions::IsValid(std::string* error) const {
  if (!Known(SearchPlanNames(), plan)) {
    return Fail(error, "plan", "one of " + Joined(SearchPlanNames()), "\"" + plan + "\"");
  }
  for (size_t k = 0; k < disabled_phases.size(); ++k) {
    if (!Known(SearchPhaseNames(), disabled_phases[k])) {
      return Fail(error, "disabled_phases[" + std::to_string(k) + "]",
                  "a phase (" + Joined(SearchPhaseNames()) + ")", "\"" + disabled_phases[k] + "\"");
    }
  }
  return relaxation.IsValid(error) && nets.IsValid(error) && restricted.IsValid(error) &&
         exact.IsValid(error) && tree.IsValid(error) && exchange.IsValid(error);
}

}  // namespace thrustsched::transcription
