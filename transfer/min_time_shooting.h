// Minimum-time low-thrust transfer by indirect single shooting, with
// continuation on the thrust (Caillau, Gergaud & Noailles 2003, 3D
// geosynchronous transfer; Bombrun 2007 sec. 2.3, problem P_T).
//
// The thruster is always on at full thrust (minimum time), so the mass is
// m(t) = m0 - T t / (g0 Isp); Pontryagin's maximum principle gives the
// direction u = F^T p / |F^T p| of the thrust in the QSW frame, where p is the
// costate of the equinoctial elements x = (P, ex, ey, hx, hy, L). The
// shooting unknowns are the final time and p(0) (normalised |p(0)| = 1: the
// free final time fixes only its scale); the equations are the five target
// elements at t_f (or p_j(t_f) = 0 for an element left free), p_L(t_f) = 0
// (free final longitude) and |p(0)|^2 = 1. The costate equations are the
// hand-written derivatives of transfer/equinoctial.h (and, with J2, of
// transfer/force_model.h); MINPACK's hybrd solves
// the shooting equations with a forward-difference Jacobian; the flow is
// Runge-Kutta-Fehlberg 7(8) (Boost.Odeint) at a tight tolerance.
//
//   transfer::MinTimeProblem p = transfer::CaillauGtoProblem(60.0);     // 60 N
//   transfer::ShootingGuess g = transfer::InitialGuess(p);
//   transfer::MinTimeSolution s = transfer::SolveMinTime(p, g);
//   // s.duration_s = 14.8004 h; then, 60 N down to 0.2 N:
//   transfer::ContinuationResult c = transfer::ContinueOnThrust(p, s, 0.2);
//
// Checks reported with every solution: the shooting residual, the drift of
// the maximised Hamiltonian H = p.(f0 + F gamma) + (T/m)|F^T p| + p_m dm/dt
// (gamma: the force model's perturbation, transfer/force_model.h; the problem
// is autonomous once the mass costate p_m is carried: H is constant, equal to
// -p^0 > 0 at the free final time, with p_m(t_f) = 0 for a free final mass),
// and the propellant T t_f / (g0 Isp).
#ifndef THRUSTSCHED_TRANSFER_MIN_TIME_SHOOTING_H_
#define THRUSTSCHED_TRANSFER_MIN_TIME_SHOOTING_H_

#include <array>
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "transfer/equinoctial.h"
#include "transfer/force_model.h"

namespace thrustsched::transfer {

/// Target orbit: P (m), ex, ey, hx, hy; an element marked free is not
/// targeted (its costate vanishes at t_f). The final longitude is free.
struct TargetElements {
  std::array<double, 5> value{};
  std::array<bool, 5> free{};
  /// The circular equatorial orbit of radius radius_m.
  static TargetElements Circular(double radius_m);
};

struct MinTimeProblem {
  Equinoctial initial;
  TargetElements target;
  double mass_kg = 0.0;
  double thrust_n = 0.0;
  double isp_s = 0.0;
  double mu = kMuEarth;
  /// Used everywhere: the shooting's state and costate equations (with
  /// the hand-written J2 derivatives of force_model.h), the feedback
  /// (lyapunov_feedback.h), the Gauss propagation and the replay.
  ForceModel force_model;
  bool IsValid(std::string* error) const;
};

/// Caillau, Gergaud & Noailles 2003 (and Bombrun 2007's case 2): P0 = 11625
/// km, ex0 = 0.75, hx0 = 6.12e-2 (i = 7 deg), L0 = pi, 1500 kg, Isp =
/// 1994.75 s, to GEO (P = 42165 km, e = 0, i = 0).
MinTimeProblem CaillauGtoProblem(double thrust_n);

struct ShootingGuess {
  double duration_s = 0.0;
  Vector6 costate = Vector6::Zero();  // p(0) in the scaled units (ScaledUnits), any norm
};

/// A deterministic first guess: t_f from the propellant of an Edelbaum-like
/// velocity budget, p(0) = -grad V(x0) for the Lyapunov function of
/// lyapunov_feedback.h (the feedback's control is the extremal's control
/// with that costate).
ShootingGuess InitialGuess(const MinTimeProblem& p);

struct ShootingOptions {
  double integration_tolerance = 1e-12;  // Odeint, absolute and relative, scaled state
  double xtol = 1e-10;                   // hybrd's relative step tolerance
  int max_evaluations = 400;             // of the shooting function per solve
  /// Continuation on the target (0 -> 1) from the orbit the guess reaches,
  /// when the direct solve from the guess fails.
  int target_homotopy_steps = 20;
  /// A stop request (Ctrl-C; may be null), polled before every evaluation of
  /// the shooting function and every continuation step: once it is set the
  /// solve returns unconverged with `interrupted`, the continuation its last
  /// converged solution.
  const std::atomic<bool>* interrupt = nullptr;
  bool Interrupted() const { return interrupt != nullptr && interrupt->load(); }
  bool IsValid(std::string* error) const;
};

struct TrajectorySample {
  double t_s = 0.0;
  Equinoctial elements;
  double mass_kg = 0.0;
  Eigen::Vector3d direction_qsw = Eigen::Vector3d::Zero();  // unit thrust direction
  double hamiltonian = 0.0;                                 // scaled units
  double switching_norm = 0.0;  // |F^T p|, scaled units (the thrust direction's definition)
};

struct MinTimeSolution {
  bool converged = false;
  bool interrupted = false;  // stopped by ShootingOptions::interrupt
  int hybrd_info = 0;        // MINPACK's info (1: converged to xtol)
  int evaluations = 0;
  double residual_norm = 0.0;  // shooting function, scaled units
  double duration_s = 0.0;
  Vector6 costate = Vector6::Zero();  // p(0), |p(0)| = 1, scaled units
  Equinoctial final_elements;
  double final_mass_kg = 0.0;
  double propellant_kg = 0.0;
  double revolutions = 0.0;           // (L(t_f) - L(0)) / 2 pi
  double hamiltonian = 0.0;           // H at t_f (scaled): -p^0, > 0 for a normal extremal
  double hamiltonian_drift = 0.0;     // max |H(t) - H(t_f)| / H(t_f) over the samples
  double mass_costate_initial = 0.0;  // p_m(0) (scaled)
  std::vector<TrajectorySample> trajectory;
};

/// Solves the shooting equations from `guess`.
/// @throws std::invalid_argument if the problem or the options are invalid.
MinTimeSolution SolveMinTime(const MinTimeProblem& p, const ShootingGuess& guess,
                             const ShootingOptions& options = {});

/// Re-integrates the extremal of (duration_s, costate) and fills everything
/// but the convergence fields; `samples_per_hour` output points.
MinTimeSolution Extremal(const MinTimeProblem& p, double duration_s, const Vector6& costate,
                         const ShootingOptions& options, double samples_per_hour);

struct ContinuationStep {
  double thrust_n = 0.0;
  double duration_s = 0.0;
  bool converged = false;
  int evaluations = 0;
};

struct ContinuationResult {
  MinTimeSolution solution;  // at the final thrust (converged or the last one that did)
  double thrust_n = 0.0;     // the thrust of `solution`
  bool interrupted = false;  // stopped by options.interrupt before final_thrust_n
  std::vector<ContinuationStep> steps;
};

/// Continuation on the thrust from the solution `start` of `p` (at
/// p.thrust_n) down (or up) to final_thrust_n: geometric steps, grown after
/// a success and halved after a failure; the next guess scales t_f by the
/// thrust ratio (T t_f nearly constant, Bombrun 2007 Theorem 45) and keeps
/// p(0). `progress` (may be empty) is told every step.
ContinuationResult ContinueOnThrust(
    const MinTimeProblem& p, const MinTimeSolution& start, double final_thrust_n,
    const ShootingOptions& options = {},
    const std::function<void(const ContinuationStep&)>& progress = {});

}  // namespace thrustsched::transfer

#endif  // THRUSTSCHED_TRANSFER_MIN_TIME_SHOOTING_H_
