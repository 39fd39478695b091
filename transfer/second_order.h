// Second-order necessary conditions of a minimum-time extremal
// (min_time_shooting.h), the checks a user can trust without a direct
// method:
//
//  - the strengthened Legendre condition: the control maximises
//    H_u = (T/m) u . F^T p on the sphere |u| = 1, whose second variation on
//    the sphere's tangent is -(T/m) |F^T p| |du|^2: negative definite exactly
//    where |F^T p| > 0, so it holds along the extremal iff the switching
//    function F^T p never vanishes (checked on the samples);
//  - the conjugate-point test of Bonnard, Caillau & Trelat 2007 (sec. 2, the
//    time-minimal case, as in their cotcot tool): t_c is conjugate when the
//    Jacobian of the endpoint map (t, p0) -> x(t, p0) loses rank, i.e. when
//    det[dx(t)/dp0 e_1, ..., dx(t)/dp0 e_5, dx/dt] = 0 with e_1..e_5 an
//    orthonormal basis of the tangent space of |p0| = 1 (the p0 direction
//    itself is in the kernel: the control depends on the costate's
//    direction only). An extremal with a conjugate time before t_f is not
//    locally time-minimal even to its own end point. The Jacobi fields are
//    central differences of the flow in p0 (steps costate_step and
//    check_step); the determinant is computed with rows and columns scaled
//    to unit norm (its sign is the determinant's). Near t = 0 it vanishes
//    (the fields start at zero) and is lost in the differences' noise: a
//    sample is "resolved" when the two steps give it within 10 %, and a
//    conjugate time is a sign change between two consecutive resolved
//    samples.
//
//   transfer::MinTimeSolution s = transfer::SolveMinTime(p, transfer::InitialGuess(p));
//   transfer::SecondOrderCheck c = transfer::CheckSecondOrder(p, s);
//   // c.legendre_holds, c.conjugate_times_s (empty: none before t_f)
//
// Not checked: the focal-point condition of the free final longitude (the
// target manifold); the test is necessary, not sufficient, for the manifold
// problem.
#ifndef THRUSTSCHED_TRANSFER_SECOND_ORDER_H_
#define THRUSTSCHED_TRANSFER_SECOND_ORDER_H_

#include <string>
#include <vector>

#include "transfer/min_time_shooting.h"

namespace thrustsched::transfer {

struct SecondOrderOptions {
  double samples_per_hour = 20.0;  // of the determinant along the extremal
  double costate_step = 1e-7;      // central differences in p0 (|p0| = 1)
  double check_step = 1e-6;        // the second step, which tells noise from value
  ShootingOptions shooting;        // the flow's integration tolerance
};

struct SecondOrderCheck {
  bool legendre_holds = false;
  double min_switching_norm = 0.0;        // min over the samples of |F^T p| / max |F^T p|
  std::vector<double> t_s;                // sample times (the first after t = 0)
  std::vector<double> determinant;        // the normalised determinant at t_s
  std::vector<double> conjugate_times_s;  // sign changes (midpoint of the interval)
  double resolved_from_s = -1.0;          // the first resolved sample (-1: none)
  double last_resolved_s = -1.0;          // the last one
  int resolved_samples = 0;
  double min_abs_determinant = 0.0;  // over the samples in the second half of [0, t_f]
  double final_determinant = 0.0;    // at t_f
  /// No sign change from resolved_from_s to t_f, and t_f resolved.
  bool no_conjugate_point = false;
  /// Resolved samples in the second half of [0, t_f] over all samples there.
  double resolved_fraction_second_half = 0.0;
  /// "no_conjugate_point", "conjugate_point" (a sign change) or
  /// "undetermined" (t_f or more than 10 % of the second half's samples not resolved:
  /// the long low-thrust extremals, whose flow is too sensitive to p0 for
  /// these differences; then conjugate_times_s is not to be trusted).
  std::string verdict;
};

/// @throws std::invalid_argument if s has no extremal (not converged).
SecondOrderCheck CheckSecondOrder(const MinTimeProblem& p, const MinTimeSolution& s,
                                  const SecondOrderOptions& o = {});

}  // namespace thrustsched::transfer

#endif  // THRUSTSCHED_TRANSFER_SECOND_ORDER_H_
