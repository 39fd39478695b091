// Private helper (not installed): adaptive Runge-Kutta-Fehlberg 7(8)
// integration of y' = f(s, y) over [0, s_end] with Boost.Odeint, used by the
// reference discretisation and by PropagateLinear. The state is a flat
// std::vector<double>; callers map it onto Eigen matrices in their RHS.
//
//   internal::AdaptiveIntegrator integ(/*tolerance=*/1e-12, "Discretize");
//   integ.Integrate([&](const std::vector<double>& y, std::vector<double>& dy, double s) {
//     ...
//   }, y, /*s_end=*/2.5);
//
// Error control: odeint's default checker with eps_abs = eps_rel = tolerance
// per component, so the state should be nondimensional (components of order
// one). The accepted step size carries over between calls, so consecutive
// intervals of a grid do not pay the initial step search again.
#ifndef THRUSTSCHED_DYNAMICS_INTERNAL_ADAPTIVE_INTEGRATOR_H_
#define THRUSTSCHED_DYNAMICS_INTERNAL_ADAPTIVE_INTEGRATOR_H_

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

namespace thrustsched::dynamics::internal {

class AdaptiveIntegrator {
 public:
  using State = std::vector<double>;
  using ErrorStepper = boost::numeric::odeint::runge_kutta_fehlberg78<State>;
  using Checker =
      boost::numeric::odeint::default_error_checker<double, boost::numeric::odeint::range_algebra,
                                                    boost::numeric::odeint::default_operations>;
  using Stepper = boost::numeric::odeint::controlled_runge_kutta<ErrorStepper, Checker>;

  // Bound on accepted + rejected steps per Integrate call: a guard against a
  // tolerance below what round-off lets the error estimate resolve.
  static constexpr long kMaxSteps = 2000000;

  /// `where` prefixes error messages (the public function's name).
  AdaptiveIntegrator(double tolerance, std::string where)
      : stepper_(Checker(tolerance, tolerance)), tolerance_(tolerance), where_(std::move(where)) {}

  /// Integrates y from s = 0 to s = s_end (> 0) in place. rhs(y, dy, s) must
  /// fill dy. @throws std::runtime_error if the step size underflows (the
  /// tolerance cannot be met in double precision) or the step count bound is
  /// exceeded.
  template <class Rhs>
  void Integrate(Rhs&& rhs, State& y, double s_end) {
    if (!(s_end > 0.0)) return;
    double s = 0.0;
    double dt = (hint_ > 0.0) ? std::min(hint_, s_end) : s_end;
    long steps = 0;
    while (s < s_end) {
      bool last = false;
      if (s + dt >= s_end * (1.0 - 1e-15)) {  // land exactly on s_end
        dt = s_end - s;
        last = true;
      }
      if (!(dt > std::numeric_limits<double>::epsilon() * std::max(s, s_end))) {
        std::ostringstream msg;
        msg << where_ << ": adaptive integration step size underflow at s = " << s << " of "
            << s_end << " (tolerance " << tolerance_ << " is below what round-off allows)";
        throw std::runtime_error(msg.str());
      }
      const double dt_tried = dt;
      const auto result = stepper_.try_step(rhs, y, s, dt);
      if (++steps > kMaxSteps) {
        std::ostringstream msg;
        msg << where_ << ": adaptive integration took more than " << kMaxSteps
            << " steps without reaching the end of the interval (tolerance " << tolerance_
            << ", reached s = " << s << " of " << s_end << ")";
        throw std::runtime_error(msg.str());
      }
      if (result == boost::numeric::odeint::success) {
        // Keep the proposal for the next interval, unless this step was cut
        // short to land on s_end (then the proposal is artificially small).
        if (!last || dt_tried >= hint_) hint_ = dt;
        if (last) {
          s = s_end;
          break;
        }
      }
    }
  }

  double step_hint() const { return hint_; }

 private:
  Stepper stepper_;
  double tolerance_;
  std::string where_;
  double hint_ = 0.0;
};

}  // namespace thrustsched::dynamics::internal

#endif  // THRUSTSCHED_DYNAMICS_INTERNAL_ADAPTIVE_INTEGRATOR_H_
