#include "transcription/operations.h"

#include <cmath>
#include <sstream>

#include "common/error.h"
#include "common/format.h"

namespace thrustsched::transcription {

using common::Fail;
using common::FormatG;

namespace {

// Durations must be finite and >= 0 (max_burn_s may be +inf).
bool CheckDuration(const char* field, double v, bool allow_inf, std::string* error) {
  if (std::isnan(v) || v < 0.0 || (!allow_inf && std::isinf(v))) {
    return Fail(error, std::string("operations.") + field + " must be " +
                           (allow_inf ? "> 0 (or infinite)" : "finite and >= 0") + ", got " +
                           FormatG(v, 10));
  }
  return true;
}

}  // namespace

bool OperationalRules::IsValid(std::string* error) const {
  if (max_simultaneous < 1) {
    return Fail(
        error, "operations.max_simultaneous must be >= 1, got " + std::to_string(max_simultaneous));
  }
  if (!CheckDuration("min_burn_s", min_burn_s, false, error)) return false;
  if (!CheckDuration("min_off_same_s", min_off_same_s, false, error)) return false;
  if (!CheckDuration("min_gap_other_s", min_gap_other_s, false, error)) return false;
  if (std::isnan(max_burn_s) || max_burn_s <= 0.0) {
    return Fail(error,
                "operations.max_burn_s must be > 0 (or infinite), got " + FormatG(max_burn_s, 10));
  }
  if (max_burn_s + kTimeTolerance < min_burn_s) {
    return Fail(error, "operations.max_burn_s (" + FormatG(max_burn_s, 10) +
                           ") is smaller than operations.min_burn_s (" + FormatG(min_burn_s, 10) +
                           ")");
  }
  return true;
}

BoundaryHistory BoundaryHistory::AllOff(int num_thrusters) {
  BoundaryHistory h;
  h.on_for_s.assign(num_thrusters, 0.0);
  h.off_for_s.assign(num_thrusters, std::numeric_limits<double>::infinity());
  return h;
}

bool BoundaryHistory::IsValid(int num_thrusters, std::string* error) const {
  if (!on_for_s.empty() && static_cast<int>(on_for_s.size()) != num_thrusters) {
    return Fail(error, "history.on_for_s has " + std::to_string(on_for_s.size()) +
                           " entries, expected one per thruster (" + std::to_string(num_thrusters) +
                           ")");
  }
  if (!off_for_s.empty() && static_cast<int>(off_for_s.size()) != num_thrusters) {
    return Fail(error, "history.off_for_s has " + std::to_string(off_for_s.size()) +
                           " entries, expected one per thruster (" + std::to_string(num_thrusters) +
                           ")");
  }
  for (size_t i = 0; i < on_for_s.size(); ++i) {
    if (!std::isfinite(on_for_s[i]) || on_for_s[i] < 0.0) {
      return Fail(error, "history.on_for_s[" + std::to_string(i) +
                             "] must be finite and >= 0, got " + FormatG(on_for_s[i], 10));
    }
  }
  for (size_t i = 0; i < off_for_s.size(); ++i) {
    if (std::isnan(off_for_s[i]) || off_for_s[i] < 0.0) {
      return Fail(error, "history.off_for_s[" + std::to_string(i) +
                             "] must be >= 0 (or infinite), got " + FormatG(off_for_s[i], 10));
    }
  }
  return true;
}

bool BoundaryHistory::is_on(int thruster) const { return on_for(thruster) > 0.0; }

double BoundaryHistory::on_for(int thruster) const {
  if (thruster < 0 || thruster >= static_cast<int>(on_for_s.size())) return 0.0;
  return on_for_s[thruster];
}

double BoundaryHistory::off_for(int thruster) const {
  if (thruster < 0 || thruster >= static_cast<int>(off_for_s.size())) {
    return std::numeric_limits<double>::infinity();
  }
  return off_for_s[thruster];
}

}  // namespace thrustsched::transcription
