// The adaptive integrator of transfer/ (Runge-Kutta-Fehlberg 7(8) of
// Boost.Odeint, step by step so that callers can observe every step, cap its
// length and stop on an event).
//
//   std::array<double, 13> y = ...;
//   double t = internal::Integrate(rhs, y, 0.0, tf, 1e-12, 0.5,
//                                  [](double t, const std::array<double, 13>& y) { return true; });
//
// rhs(y, dydt, t) fills dydt. The observer is called after every accepted
// step (and once at t0); returning false stops the integration there. Returns
// the time reached (t1 unless stopped). Not installed: only transfer/ uses it.
#ifndef THRUSTSCHED_TRANSFER_INTERNAL_INTEGRATOR_H_
#define THRUSTSCHED_TRANSFER_INTERNAL_INTEGRATOR_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

// Odeint copies its (deliberately uninitialised) std::array stage buffers when
// the controlled stepper is built; GCC flags that copy inside the Boost header.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#include <boost/numeric/odeint/algebra/array_algebra.hpp>
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#pragma GCC diagnostic pop

namespace thrustsched::transfer::internal {

/// Integrates from t0 towards t1 (t1 > t0) with absolute and relative
/// tolerance `tolerance` and steps no longer than max_step.
/// @throws std::runtime_error if the step underflows or max_steps steps
///         (accepted or not) are not enough (a stiff or discontinuous field).
template <std::size_t N, class Rhs, class Observer>
double Integrate(Rhs&& rhs, std::array<double, N>& y, double t0, double t1, double tolerance,
                 double max_step, Observer&& observe, long max_steps = 5000000) {
  namespace odeint = boost::numeric::odeint;
  using State = std::array<double, N>;
  using Stepper =
      odeint::runge_kutta_fehlberg78<State, double, State, double, odeint::array_algebra>;
  using Checker =
      odeint::default_error_checker<double, odeint::array_algebra, odeint::default_operations>;
  odeint::controlled_runge_kutta<Stepper, Checker> stepper(Checker(tolerance, tolerance));
  double t = t0, dt = std::min(max_step, (t1 - t0) / 100);
  if (!observe(t, static_cast<const State&>(y))) return t;
  for (long steps = 0; t < t1; ++steps) {
    if (steps > max_steps) {
      throw std::runtime_error("integration: more than " + std::to_string(max_steps) +
                               " steps (stiff or discontinuous dynamics)");
    }
    const bool last = t + dt >= t1;
    double step = last ? t1 - t : dt;
    const double before = t;
    if (stepper.try_step(rhs, y, t, step) == odeint::success) {
      if (last) t = t1;  // exactly, not t + (t1 - t)
      dt = std::min(max_step, step);
      if (!observe(t, static_cast<const State&>(y))) return t;
    } else {
      dt = step;
      if (!(dt > 1e-14 * std::max(1.0, std::abs(before)))) {
        throw std::runtime_error("integration: step size underflow");
      }
    }
  }
  return t;
}

}  // namespace thrustsched::transfer::internal

#endif  // THRUSTSCHED_TRANSFER_INTERNAL_INTEGRATOR_H_
