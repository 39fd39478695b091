// Lyapunov (Jurdjevic-Quinn) feedback for low-thrust orbit raising, Bombrun
// 2007 sec. 4.1 (4.7) and 5.1: with V a weighted distance of the slow
// elements to the target and F the Gauss control fields, the thrust direction
// in QSW is
//
//   u = -F^T grad V / |F^T grad V|   if |F^T grad V| > delta,
//   u = -F^T grad V / delta          otherwise (saturation, |u| < 1),
//
// V = 4 (a/a_t - 1)^2 + 3 |e - e_t|^2 + 10 |i - i_t|^2 (Bombrun's (5.1) for
// GEO: 4 (a/a_geo - 1)^2 + 3 e^2 + 10 i^2), e the eccentricity vector
// (ex, ey), i the inclination vector 2 atan|h| h/|h|; delta = 1e-5 in the
// scaled units of ScaledUnits (Mm, h). An element the target leaves free
// drops out of V (a_t still uses the target's P and e values).
//
// The optional on-off variant (Bombrun (4.68)-(4.71)) fires, in the i-th
// revolution of the longitude L in [2 i pi, 2 (i+1) pi), only where the
// efficiency |F^T grad V| is at least s_i = m_i + p (M_i - m_i), with
// M_i = 2 M_{i-1} - M_{i-2} and m_i = 2 m_{i-1} - m_{i-2} extrapolated from
// the largest and smallest efficiencies of the two previous revolutions
// (always on during the first two).
//
//   transfer::MinTimeProblem p = ...;                 // orbit, target, thrust, Isp, mass
//   transfer::FeedbackOptions o;                      // Bombrun's weights, delta = 1e-5
//   transfer::FeedbackResult r = transfer::RunFeedback(p, o);
//   // r.reached, r.duration_s, r.propellant_kg, r.trajectory (V decreasing)
//
// Contract: SI at the API; the run stops when V <= options.v_stop
// (reached), when |F^T grad V| <= delta if stop_at_saturation (Bombrun
// sec. 5.1.1: then an optimal end), or at options.max_duration_s.
#ifndef THRUSTSCHED_TRANSFER_LYAPUNOV_FEEDBACK_H_
#define THRUSTSCHED_TRANSFER_LYAPUNOV_FEEDBACK_H_

#include <atomic>
#include <string>
#include <vector>

#include "transfer/equinoctial.h"
#include "transfer/min_time_shooting.h"

namespace thrustsched::transfer {

struct LyapunovWeights {
  double a = 4.0, e = 3.0, i = 10.0;  // Bombrun 2007 (5.1)
};

/// V and its gradient at the scaled elements x = (P [Mm], ex, ey, hx, hy, L)
/// (the gradient's L component is 0).
double LyapunovValue(const Vector6& x, const TargetElements& target, const LyapunovWeights& w,
                     const ScaledUnits& units);
Vector6 LyapunovGradient(const Vector6& x, const TargetElements& target, const LyapunovWeights& w,
                         const ScaledUnits& units);

struct FeedbackOptions {
  LyapunovWeights weights;
  double delta = 1e-5;   // saturation threshold of |F^T grad V|, scaled units
  double v_stop = 1e-6;  // reached when V <= v_stop
  /// Bombrun's end of the feedback phase: stop when |F^T grad V| <= delta
  /// (then an optimal end, FinishWithMinimumTime, joins the target).
  bool stop_at_saturation = true;
  double max_duration_s = 4e7;  // ~463 days
  bool on_off = false;          // Bombrun (4.68)-(4.71)
  double on_off_p = 0.5;        // threshold fraction p in [0, 1]
  double integration_tolerance = 1e-10;
  double sample_step_s = 600.0;  // trajectory output
  /// A stop request (Ctrl-C; may be null), polled at every accepted step:
  /// the run stops there with stop_reason "interrupted".
  const std::atomic<bool>* interrupt = nullptr;
  bool IsValid(std::string* error) const;
};

struct FeedbackSample {
  double t_s = 0.0;
  Equinoctial elements;
  double mass_kg = 0.0;
  double lyapunov = 0.0;
  double throttle = 0.0;                                  // |u| in [0, 1]
  double efficiency = 0.0;                                // |F^T grad V|, scaled units
  Eigen::Vector3d command_qsw = Eigen::Vector3d::Zero();  // u (QSW), |u| = throttle
};

struct FeedbackResult {
  bool reached = false;
  /// "target" (V <= v_stop), "saturation" (|F^T grad V| <= delta), "max_duration",
  /// "propellant" (mass exhausted), "interrupted" (FeedbackOptions::interrupt) or "integration:
  /// ..." (the step control failed: the saturated law is stiff when delta is small against the
  /// thrust).
  std::string stop_reason;
  double duration_s = 0.0;
  double propellant_kg = 0.0;
  double final_mass_kg = 0.0;
  Equinoctial final_elements;
  double final_lyapunov = 0.0;
  double revolutions = 0.0;
  double max_lyapunov_increase = 0.0;  // largest V(t_k+1) - V(t_k) over the samples (<= 0 ideally)
  std::vector<FeedbackSample> trajectory;
};

/// The feedback's thrust direction times throttle (|u| <= 1) in QSW at the
/// scaled elements x; `efficiency` (may be null) receives |F^T grad V|.
Eigen::Vector3d FeedbackControl(const Vector6& x, const TargetElements& target,
                                const FeedbackOptions& o, const ScaledUnits& units,
                                double* efficiency);

/// Integrates the Gauss equations under the feedback from p.initial.
/// @throws std::invalid_argument if p or o is invalid.
FeedbackResult RunFeedback(const MinTimeProblem& p, const FeedbackOptions& o);

/// Bombrun's "feedback + optimal end" (Table 5.2): from where the feedback
/// stopped, the minimum-time transfer (min_time_shooting.h) to the target,
/// shot from InitialGuess with its t_f scaled by 1, 1.5, 2, 3 and 0.7 in
/// turn until one converges.
struct FeedbackWithEnd {
  FeedbackResult feedback;
  MinTimeSolution end;  // end.converged says whether the end was found
  double total_duration_s = 0.0;
  double total_propellant_kg = 0.0;
};
FeedbackWithEnd FinishWithMinimumTime(const MinTimeProblem& p, const FeedbackResult& feedback,
                                      const ShootingOptions& options = {});

}  // namespace thrustsched::transfer

#endif  // THRUSTSCHED_TRANSFER_LYAPUNOV_FEEDBACK_H_
