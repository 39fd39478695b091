// Continuous-time linear (possibly time-varying) relative-motion models.
//
//   x'(t) = A(t) x(t) + B(t) a(t) + d(t)        a = thrust acceleration, m/s^2,
//   y(t)  = C(t) x(t)                               in the model's input frame
//   y'(t) = C'(t) x(t) + C(t) x'(t)                 (local RTN for 3-input models)
//
// Units at the API are SI (m, m/s, rad, s); each model documents its state and
// output components. `t` is seconds since the model's epoch (0 for
// time-invariant models). Models also publish characteristic scales so that
// numerical code (matrix exponentials, MILP rows) can work on quantities near 1.
//
//   dynamics::HcwModel hcw(7.2921159e-5);                 // dynamics/models.h
//   dynamics::ModelMatrices m = hcw.Evaluate(0.0);        // m.a (6x6), m.b (6x3), m.d (6)
//   bool lti = hcw.is_time_invariant();                   // true: schemes may use expm
#ifndef THRUSTSCHED_DYNAMICS_LINEAR_MODEL_H_
#define THRUSTSCHED_DYNAMICS_LINEAR_MODEL_H_

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace thrustsched::dynamics {

/// A(t) (n x n), B(t) (n x num_inputs), d(t) (n).
struct ModelMatrices {
  Eigen::MatrixXd a;
  Eigen::MatrixXd b;
  Eigen::VectorXd d;
};

/// C(t) (num_outputs x n) and its time derivative C'(t).
struct OutputMatrices {
  Eigen::MatrixXd c;
  Eigen::MatrixXd c_dot;
};

class LinearModel {
 public:
  virtual ~LinearModel() = default;

  virtual std::string_view name() const = 0;
  virtual int num_states() const = 0;
  /// Number of acceleration components the model takes (3 = R, T, N).
  virtual int num_inputs() const = 0;
  virtual int num_outputs() const = 0;
  /// True when A, B, d, C do not depend on t (exact closed forms apply).
  virtual bool is_time_invariant() const = 0;

  /// @throws std::invalid_argument if t is not finite.
  virtual ModelMatrices Evaluate(double t) const = 0;
  virtual OutputMatrices EvaluateOutput(double t) const = 0;

  /// Names with units, e.g. "x_m", "vy_m_s", "lon_rad".
  virtual std::vector<std::string> state_names() const = 0;
  virtual std::vector<std::string> output_names() const = 0;

  /// Characteristic magnitude of each state component (SI, > 0): a state of
  /// this size is "order one". Used to nondimensionalise and to scale MILP rows.
  virtual Eigen::VectorXd state_scale() const = 0;
  /// Characteristic time (s, > 0), e.g. 1/n for orbital models.
  virtual double time_scale() const = 0;

  /// P(t) (3 x n, metres per state unit): the position, to first order, of a
  /// state in the model's local Cartesian frame at t, so that two states x, y
  /// of the same model are P(t) (x - y) apart. Empty when the model defines
  /// none; the relative-motion models' positions are their first three states
  /// and need none.
  virtual Eigen::MatrixXd LocalPositionMap(double /*t*/) const { return {}; }
};

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_LINEAR_MODEL_H_
