// Independent verification of a plan against problem.conjunction: the
// keep-out MILP is conservative by construction (polytope cover, risk
// selection, instantaneous risks on a grid; Serra 2015 sec. 4.2-4.3), but
// the result is checked, not trusted:
//
//  - the maximum instantaneous collision probability P(|r_p - r_s| <= R)
//    along the plan, computed (BallProbability) at the check times, and the
//    same without manoeuvre (Serra 2015 Tables 4.2, 4.5 and the
//    "unmanoeuvred" risks of sec. 4.4);
//  - a Monte Carlo of the relative initial state (Serra 2015 sec. 4.4:
//    10^5 samples): each sample is propagated through the linear model and,
//    where the model has an exact inertial meaning, through nonlinear
//    two-body motion of both objects with the planned thrust; a collision is
//    a distance below R on a fine time grid (closest approach on each step,
//    linear in between). Zero collisions are expected.
//
// Shares no code with the MILP builder: the linear paths come from adaptive
// integration of the continuous model (dynamics::PropagateLinear), not from
// the MILP's discretisation; the nonlinear ones from Kepler's equation.
//
//   transcription::ConjunctionCheckOptions o;
//   o.monte_carlo_samples = 100000;
//   transcription::ConjunctionCheckReport r =
//       transcription::CheckConjunction(problem, schedule.burns, schedule.impulses, o);
//   std::cout << r.max_risk << " " << r.collisions_linear << " " << r.collisions_nonlinear << "\n";
//
// Nonlinear models: Yamanaka-Ankersen (impulses applied in the reference
// frame at their node; the reference orbit in its perifocal frame,
// dynamics/two_body.h) and GEO (on-off burns; both objects in the
// Earth-centred inertial frame of dynamics::GeoSimulator, propagated without
// perturbations, thrust in the satellite's own RTN frame). The nonlinear
// Monte Carlo starts at the check-window start from the linear model's
// states there (exact conversion). Other models: linear only, and
// `nonlinear_note` says why.
#ifndef THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_CHECK_H_
#define THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_CHECK_H_

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "transcription/operations.h"
#include "transcription/problem.h"
#include "transcription/schedule_milp.h"

namespace thrustsched::transcription {

struct ConjunctionCheckOptions {
  int monte_carlo_samples = 100000;  // 0: no Monte Carlo
  std::uint64_t seed = 1;
  /// Step of the Monte Carlo time grid over the check window (s); 0: the
  /// window divided into 2000 steps.
  double sample_step_s = 0.0;
  bool nonlinear = true;  // also the two-body Monte Carlo, where available
  double propagation_tolerance = 1e-11;

  /// monte_carlo_samples >= 0; sample_step_s finite and >= 0;
  /// propagation_tolerance finite and > 0. On failure `*error` (if given)
  /// names the field and the value.
  bool IsValid(std::string* error) const;
};

struct ConjunctionCheckReport {
  double threshold = 0.0;  // eps' of the problem
  // Computed instantaneous risk at the check times.
  double max_risk = 0.0;
  double max_risk_time_s = std::numeric_limits<double>::quiet_NaN();
  double max_risk_unmanoeuvred = 0.0;
  double max_risk_unmanoeuvred_time_s = std::numeric_limits<double>::quiet_NaN();
  bool risk_ok = false;              // max_risk <= threshold
  double min_mean_distance_m = 0.0;  // planned mean relative distance, on the fine grid
  double min_mean_distance_time_s = std::numeric_limits<double>::quiet_NaN();
  double min_mean_distance_unmanoeuvred_m = 0.0;
  // Monte Carlo (sample_step_s over the check window).
  int samples = 0;
  double step_s = 0.0;
  long long collisions_linear = 0;
  long long collisions_unmanoeuvred_linear = 0;  // the same samples without manoeuvre
  double min_distance_linear_m = std::numeric_limits<double>::quiet_NaN();
  bool nonlinear_checked = false;
  std::string nonlinear_note;  // why not, if not
  long long collisions_nonlinear = 0;
  double min_distance_nonlinear_m = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0.0;
  /// Risk below the threshold and no Monte Carlo collision.
  bool passed() const {
    return risk_ok && collisions_linear == 0 && (!nonlinear_checked || collisions_nonlinear == 0);
  }
};

/// Verifies burns (on-off mode) or impulses (impulsive mode) against
/// problem.conjunction.
/// @throws std::invalid_argument if the problem has no (valid) conjunction or
///         the options are out of range (samples < 0, step < 0).
ConjunctionCheckReport CheckConjunction(const ScheduleProblem& problem,
                                        const std::vector<Burn>& burns,
                                        const std::vector<Impulse>& impulses,
                                        const ConjunctionCheckOptions& options = {});

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TRANSCRIPTION_CONJUNCTION_CHECK_H_
