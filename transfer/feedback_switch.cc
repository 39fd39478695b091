#include "transfer/feedback_switch.h"

#include <cmath>
#include <stdexcept>

#include "common/constants.h"
#include "common/error.h"
#include "common/format.h"

namespace thrustsched::transfer {

std::string ToString(SwitchRule r) {
  switch (r) {
    case SwitchRule::kSaturation:
      return "saturation";
    case SwitchRule::kEarliestConvergent:
      return "earliest_convergent";
    case SwitchRule::kShortestConvergent:
      return "shortest_convergent";
  }
  return "?";
}

bool SwitchOptions::IsValid(std::string* error) const {
  if (!(std::isfinite(interval_s) && interval_s > 0)) {
    return common::Fail(error, "interval_s must be > 0, got " + common::FormatG(interval_s, 10));
  }
  if (max_attempts < 1) return common::Fail(error, "max_attempts must be >= 1");
  return true;
}

FeedbackResult TruncateFeedback(const FeedbackResult& f, std::size_t k, double initial_l_rad) {
  if (k >= f.trajectory.size()) throw std::invalid_argument("TruncateFeedback: no such sample");
  FeedbackResult r = f;
  r.trajectory.resize(k + 1);
  const FeedbackSample& s = r.trajectory.back();
  r.reached = false;
  r.stop_reason = "switch";
  r.duration_s = s.t_s;
  r.final_elements = s.elements;
  r.final_mass_kg = s.mass_kg;
  r.propellant_kg = f.final_mass_kg + f.propellant_kg - s.mass_kg;
  r.final_lyapunov = s.lyapunov;
  r.revolutions = (s.elements.l_rad - initial_l_rad) / (2 * common::kPi);
  return r;
}

SwitchedTransfer SwitchToMinimumTime(const MinTimeProblem& p, const FeedbackResult& feedback,
                                     const SwitchOptions& s, const ShootingOptions& shooting,
                                     const std::function<void(const SwitchAttempt&)>& progress) {
  std::string error;
  if (!s.IsValid(&error)) throw std::invalid_argument("switch options: " + error);
  SwitchedTransfer out;
  auto attempt = [&](const FeedbackResult& f) {
    FeedbackWithEnd e = FinishWithMinimumTime(p, f, shooting);
    const SwitchAttempt a{f.duration_s, e.end.converged, e.end.duration_s};
    out.attempts.push_back(a);
    if (progress) progress(a);
    return e;
  };
  out.transfer = attempt(feedback);
  out.switch_s = feedback.duration_s;
  if (s.rule == SwitchRule::kSaturation || !out.transfer.end.converged) return out;
  // Backwards from the saturation point, one try per interval_s.
  std::size_t k = feedback.trajectory.size() - 1;
  for (int n = 1; n <= s.max_attempts && !shooting.Interrupted(); ++n) {
    const double t = feedback.duration_s - n * s.interval_s;
    if (t < 0) break;
    while (k > 0 && feedback.trajectory[k].t_s > t) --k;
    const FeedbackWithEnd e = attempt(TruncateFeedback(feedback, k, p.initial.l_rad));
    if (!e.end.converged) break;
    if (s.rule == SwitchRule::kEarliestConvergent ||
        e.total_duration_s < out.transfer.total_duration_s) {
      out.transfer = e;
      out.switch_s = e.feedback.duration_s;
    }
    if (k == 0) break;
  }
  return out;
}

}  // namespace thrustsched::transfer
