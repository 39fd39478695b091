#include "transfer/min_time_shooting.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <cminpack.h>

#include "common/constants.h"
#include "common/error.h"
#include "common/format.h"
#include "transfer/internal/integrator.h"
#include "transfer/lyapunov_feedback.h"

namespace thrustsched::transfer {
namespace {

using common::FormatG;
// Flow state: elements x (6), costate p (6), I = int T |F^T p| / m^2 dt (the
// mass costate p_m(t) = I(t) - I(t_f), from dp_m/dt = -dH/dm and p_m(t_f) = 0).
using FlowState = std::array<double, 13>;

// The extremal flow in scaled units (Mm, h, kg).
struct ExtremalFlow {
  double mu;
  double thrust;  // kg Mm / h^2
  double m0;      // kg
  double flow;    // kg / h (T / (g0 Isp))
  ForceModel force;
  ScaledUnits units;

  double Mass(double t) const { return m0 - flow * t; }

  void operator()(const FlowState& y, FlowState& dy, double t) const {
    Vector6 x, p;
    for (int i = 0; i < 6; ++i) x(i) = y[i], p(i) = y[6 + i];
    if (!(x(0) > 0) || !(x(1) * x(1) + x(2) * x(2) < 1)) {
      throw std::runtime_error("extremal left the ellipses (P <= 0 or e >= 1)");
    }
    const double m = Mass(t);
    if (!(m > 0)) throw std::runtime_error("extremal burnt the whole mass");
    const GaussTerms g = Gauss(x, mu);
    const GaussJacobians d = GaussDerivatives(x, mu);
    const Eigen::Vector3d ftp = g.F.transpose() * p;
    const double norm = ftp.norm();
    const Eigen::Vector3d u = norm > 0 ? Eigen::Vector3d(ftp / norm) : Eigen::Vector3d::Zero();
    const double acc = thrust / m;
    if (force.kind == ForceModelKind::kTwoBody) {
      const Vector6 dx = g.f0 + acc * g.F * u;
      for (int j = 0; j < 6; ++j) {
        dy[j] = dx(j);
        dy[6 + j] = -(p.dot(d.df0.col(j)) + acc * p.dot(d.dF[j] * u));
      }
    } else {
      // H gains p . F gamma(x): its x-derivative p . dF_j gamma + (F^T p) . dgamma/dx_j.
      const Eigen::Vector3d gamma = PerturbationQsw(x, force, units);
      const Eigen::Matrix<double, 3, 6> dgamma = PerturbationJacobianQsw(x, force, units);
      const Eigen::Vector3d a = acc * u + gamma;
      const Vector6 dx = g.f0 + g.F * a;
      for (int j = 0; j < 6; ++j) {
        dy[j] = dx(j);
        dy[6 + j] = -(p.dot(d.df0.col(j)) + p.dot(d.dF[j] * a) + ftp.dot(dgamma.col(j)));
      }
    }
    dy[12] = thrust * norm / (m * m);
  }

  // Maximised Hamiltonian without the mass term, and the control direction.
  double ReducedHamiltonian(const FlowState& y, double t, Eigen::Vector3d* u) const {
    Vector6 x, p;
    for (int i = 0; i < 6; ++i) x(i) = y[i], p(i) = y[6 + i];
    const GaussTerms g = Gauss(x, mu);
    const Eigen::Vector3d ftp = g.F.transpose() * p;
    if (u != nullptr) *u = ftp.norm() > 0 ? Eigen::Vector3d(ftp.normalized()) : ftp;
    const double perturbation =
        force.kind == ForceModelKind::kTwoBody ? 0.0 : ftp.dot(PerturbationQsw(x, force, units));
    return p.dot(g.f0) + perturbation + thrust / Mass(t) * ftp.norm();
  }
};

ExtremalFlow MakeFlow(const MinTimeProblem& p, const ScaledUnits& u) {
  const double thrust = u.Thrust(p.thrust_n);
  return ExtremalFlow{u.mu(),        thrust,
                      p.mass_kg,     thrust / u.Speed(common::kStandardGravity_m_s2 * p.isp_s),
                      p.force_model, u};
}

ScaledUnits UnitsOf(const MinTimeProblem& p) {
  ScaledUnits u;
  u.mu_si = p.mu;
  return u;
}

FlowState InitialFlowState(const Vector6& x0, const Vector6& p0) {
  FlowState y{};
  for (int i = 0; i < 6; ++i) y[i] = x0(i), y[6 + i] = p0(i);
  return y;
}

FlowState FlowTo(const ExtremalFlow& flow, FlowState y, double tf_h, double tolerance) {
  internal::Integrate(flow, y, 0.0, tf_h, tolerance, 1.0,
                      [](double, const FlowState&) { return true; });
  return y;
}

// The shooting function, with the target moved along the homotopy
// target(lambda) = (1 - lambda) start + lambda target (lambda = 1: the problem).
struct Shooting {
  const MinTimeProblem* problem;
  ExtremalFlow flow;
  Vector6 x0;
  double tf_ref_h;
  double tolerance;
  std::array<double, 6> start{};  // at lambda = 0: the residual terms of the guess's end
  double lambda = 1.0;
  int evaluations = 0;
  const std::atomic<bool>* interrupt = nullptr;

  // Final-condition terms (targets or costates, then p_L) without the homotopy.
  std::array<double, 6> Terms(const FlowState& yf) const {
    std::array<double, 6> t{};
    for (int j = 0; j < 5; ++j) {
      const double target = j == 0 ? problem->target.value[0] / 1e6 : problem->target.value[j];
      t[j] = problem->target.free[j] ? yf[6 + j] : yf[j] - target;
    }
    t[5] = yf[11];
    return t;
  }

  void Evaluate(const double* z, double* f) {
    ++evaluations;
    Vector6 p0;
    for (int i = 0; i < 6; ++i) p0(i) = z[1 + i];
    const double tf = z[0] * tf_ref_h;
    if (!(tf > 0)) throw std::runtime_error("negative final time");
    const std::array<double, 6> t = Terms(FlowTo(flow, InitialFlowState(x0, p0), tf, tolerance));
    for (int j = 0; j < 6; ++j) f[j] = t[j] - (1 - lambda) * start[j];
    f[6] = p0.squaredNorm() - 1;
  }
};

int ShootingCallback(void* data, int n, const double* z, double* f, int /*iflag*/) {
  auto* s = static_cast<Shooting*>(data);
  if (s->interrupt != nullptr && s->interrupt->load()) {
    std::fill(f, f + n, 0.0);
    return -1;  // a stop request: hybrd returns at once
  }
  try {
    s->Evaluate(z, f);
  } catch (const std::runtime_error&) {
    std::fill(f, f + n, 0.0);
    return -1;  // stops hybrd: this guess leaves the domain of the dynamics
  }
  return 0;
}

struct HybrdOutcome {
  int info = 0;
  double residual = HUGE_VAL;
};

HybrdOutcome RunHybrd(Shooting* s, std::array<double, 7>* z, const ShootingOptions& o) {
  constexpr int n = 7;
  std::array<double, n> f{}, diag{}, qtf{}, wa1{}, wa2{}, wa3{}, wa4{};
  std::array<double, n * n> fjac{};
  std::array<double, n*(n + 1) / 2> r{};
  int nfev = 0;
  // Forward differences of relative step sqrt(epsfcn) = 1e-6, well above the
  // integration noise (1e-12).
  const double epsfcn = 1e-12;
  HybrdOutcome out;
  out.info =
      hybrd(ShootingCallback, s, n, z->data(), f.data(), o.xtol, o.max_evaluations, n - 1, n - 1,
            epsfcn, diag.data(), 1, 10.0, 0, &nfev, fjac.data(), n, r.data(),
            static_cast<int>(r.size()), qtf.data(), wa1.data(), wa2.data(), wa3.data(), wa4.data());
  if (out.info >= 0) {
    s->Evaluate(z->data(), f.data());  // at the returned point
    double sq = 0;
    for (double v : f) sq += v * v;
    out.residual = std::sqrt(sq);
  }
  return out;
}

}  // namespace

TargetElements TargetElements::Circular(double radius_m) {
  TargetElements t;
  t.value = {radius_m, 0, 0, 0, 0};
  return t;
}

bool MinTimeProblem::IsValid(std::string* error) const {
  if (!(std::isfinite(mu) && mu > 0)) return common::Fail(error, "mu must be > 0");
  if (!(std::isfinite(mass_kg) && mass_kg > 0)) {
    return common::Fail(error, "mass_kg must be > 0, got " + FormatG(mass_kg, 10));
  }
  if (!(std::isfinite(thrust_n) && thrust_n > 0)) {
    return common::Fail(error, "thrust_n must be > 0, got " + FormatG(thrust_n, 10));
  }
  if (!(std::isfinite(isp_s) && isp_s > 0)) {
    return common::Fail(error, "isp_s must be > 0, got " + FormatG(isp_s, 10));
  }
  if (!(std::isfinite(initial.p_m) && initial.p_m > 0)) {
    return common::Fail(error, "initial P must be > 0, got " + FormatG(initial.p_m, 10));
  }
  const double e0 = Eccentricity(initial);
  if (!(e0 < 1))
    return common::Fail(error, "initial orbit is not an ellipse: e = " + FormatG(e0, 10));
  if (!(target.free[0] || (std::isfinite(target.value[0]) && target.value[0] > 0))) {
    return common::Fail(error, "target P must be > 0, got " + FormatG(target.value[0], 10));
  }
  const double et = std::hypot(target.value[1], target.value[2]);
  if (!(et < 1)) return common::Fail(error, "target is not an ellipse: e = " + FormatG(et, 10));
  return force_model.IsValid(error);
}

bool ShootingOptions::IsValid(std::string* error) const {
  if (!(integration_tolerance > 0 && integration_tolerance <= 1e-6)) {
    return common::Fail(error, "integration_tolerance must be in (0, 1e-6], got " +
                                   FormatG(integration_tolerance, 10));
  }
  if (!(xtol > 0 && xtol < 1)) return common::Fail(error, "xtol must be in (0, 1)");
  if (max_evaluations < 10) return common::Fail(error, "max_evaluations must be >= 10");
  if (target_homotopy_steps < 0) return common::Fail(error, "target_homotopy_steps must be >= 0");
  return true;
}

MinTimeProblem CaillauGtoProblem(double thrust_n) {
  MinTimeProblem p;
  p.initial = Equinoctial{11625e3, 0.75, 0.0, 6.12e-2, 0.0, common::kPi};
  p.target = TargetElements::Circular(42165e3);
  p.mass_kg = 1500.0;
  p.isp_s = 1994.75;
  p.thrust_n = thrust_n;
  p.mu = kMuEarth;
  return p;
}

ShootingGuess InitialGuess(const MinTimeProblem& p) {
  const ScaledUnits u = UnitsOf(p);
  // Velocity budget: the circular speeds' difference at the initial and the
  // target semi-major axes plus the plane change and the eccentricity removal
  // at the target speed (an overestimate of Edelbaum's, on purpose: the
  // homotopy shortens t_f more easily than it lengthens it).
  const double a0 = SemiMajorAxis(p.initial);
  const double pt = p.target.free[0] ? p.initial.p_m : p.target.value[0];
  const double vt = std::sqrt(p.mu / pt), v0 = std::sqrt(p.mu / a0);
  const double di = std::abs(Inclination(p.initial) -
                             2 * std::atan(std::hypot(p.target.value[3], p.target.value[4])));
  const double de =
      std::abs(Eccentricity(p.initial) - std::hypot(p.target.value[1], p.target.value[2]));
  const double dv = std::abs(v0 - vt) + vt * (di + de / 2);
  const double c = common::kStandardGravity_m_s2 * p.isp_s;
  ShootingGuess g;
  g.duration_s = p.mass_kg * c * (1 - std::exp(-dv / c)) / p.thrust_n;
  g.costate = -LyapunovGradient(u.ToScaled(p.initial), p.target, LyapunovWeights{}, u);
  return g;
}

MinTimeSolution Extremal(const MinTimeProblem& p, double duration_s, const Vector6& costate,
                         const ShootingOptions& options, double samples_per_hour) {
  const ScaledUnits u = UnitsOf(p);
  const ExtremalFlow flow = MakeFlow(p, u);
  const double tf = duration_s / u.time_s;
  MinTimeSolution s;
  s.duration_s = duration_s;
  s.costate = costate;
  // Pass 1: the samples; pass 2 is not needed: I(t_f) is known at the end.
  FlowState y = InitialFlowState(u.ToScaled(p.initial), costate);
  const int n = std::max(2, static_cast<int>(std::ceil(tf * samples_per_hour)));
  std::vector<FlowState> states;
  std::vector<double> times;
  states.push_back(y);
  times.push_back(0.0);
  for (int k = 1; k <= n; ++k) {
    const double t0 = tf * (k - 1) / n, t1 = tf * k / n;
    internal::Integrate(flow, y, t0, t1, options.integration_tolerance, 1.0,
                        [](double, const FlowState&) { return true; });
    states.push_back(y);
    times.push_back(t1);
  }
  const double i_f = y[12];
  const double hf = flow.ReducedHamiltonian(y, tf, nullptr);  // p_m(t_f) = 0
  s.hamiltonian = hf;
  for (std::size_t k = 0; k < states.size(); ++k) {
    TrajectorySample ts;
    Vector6 x;
    for (int i = 0; i < 6; ++i) x(i) = states[k][i];
    ts.t_s = times[k] * u.time_s;
    ts.elements = u.FromScaled(x);
    ts.mass_kg = flow.Mass(times[k]);
    const double pm = states[k][12] - i_f;
    ts.hamiltonian =
        flow.ReducedHamiltonian(states[k], times[k], &ts.direction_qsw) - flow.flow * pm;
    Vector6 costate_k;
    for (int i = 0; i < 6; ++i) costate_k(i) = states[k][6 + i];
    ts.switching_norm = (Gauss(x, flow.mu).F.transpose() * costate_k).norm();
    s.hamiltonian_drift =
        std::max(s.hamiltonian_drift, std::abs(ts.hamiltonian - hf) / std::abs(hf));
    s.trajectory.push_back(ts);
  }
  s.mass_costate_initial = -i_f;
  s.final_elements = s.trajectory.back().elements;
  s.final_mass_kg = flow.Mass(tf);
  s.propellant_kg = p.mass_kg - s.final_mass_kg;
  s.revolutions = (s.final_elements.l_rad - p.initial.l_rad) / (2 * common::kPi);
  return s;
}

MinTimeSolution SolveMinTime(const MinTimeProblem& p, const ShootingGuess& guess,
                             const ShootingOptions& options) {
  std::string error;
  if (!p.IsValid(&error)) throw std::invalid_argument("minimum-time problem: " + error);
  if (!options.IsValid(&error)) throw std::invalid_argument("shooting options: " + error);
  if (!(guess.duration_s > 0) || !(guess.costate.norm() > 0)) {
    throw std::invalid_argument("shooting guess: duration_s and the costate must be > 0");
  }
  const ScaledUnits u = UnitsOf(p);
  Shooting s{&p, MakeFlow(p, u), u.ToScaled(p.initial), guess.duration_s / u.time_s,
             options.integration_tolerance};
  s.interrupt = options.interrupt;
  std::array<double, 7> z{};
  z[0] = 1.0;
  const Vector6 p0 = guess.costate.normalized();
  for (int i = 0; i < 6; ++i) z[1 + i] = p0(i);
  std::array<double, 7> start = z;
  HybrdOutcome out = RunHybrd(&s, &z, options);
  if (!(out.info == 1 && out.residual < 1e-6) && options.target_homotopy_steps > 0 &&
      !options.Interrupted()) {
    // Homotopy on the target from the end of the guess's extremal.
    z = start;
    try {
      const FlowState yf = FlowTo(s.flow, InitialFlowState(s.x0, p0), s.tf_ref_h, s.tolerance);
      s.start = s.Terms(yf);
    } catch (const std::runtime_error&) {
      s.start.fill(0.0);
    }
    double lambda = 0, step = 1.0 / options.target_homotopy_steps;
    while (lambda < 1 && step > 1e-4 && !options.Interrupted()) {
      std::array<double, 7> trial = z;
      s.lambda = std::min(1.0, lambda + step);
      const HybrdOutcome o = RunHybrd(&s, &trial, options);
      if (o.info == 1 && o.residual < 1e-6) {
        z = trial, lambda = s.lambda, out = o;
        step = std::min(1.5 * step, 0.25);
      } else {
        step /= 2;
        out = o;
      }
    }
    if (lambda < 1) out.info = std::min(out.info, 0);
  }
  Vector6 costate;
  for (int i = 0; i < 6; ++i) costate(i) = z[1 + i];
  MinTimeSolution sol;
  const bool interrupted = options.Interrupted();
  const double tf_s = z[0] * guess.duration_s;
  if (tf_s > 0 && out.info >= 0 && !interrupted) {
    try {
      sol = Extremal(p, tf_s, costate, options, 20.0);
    } catch (const std::runtime_error&) {
      sol = MinTimeSolution{};
    }
  }
  sol.hybrd_info = out.info;
  sol.evaluations = s.evaluations;
  sol.residual_norm = out.residual;
  sol.converged = !interrupted && out.info == 1 && out.residual < 1e-6 && sol.hamiltonian > 0;
  sol.interrupted = interrupted;
  return sol;
}

ContinuationResult ContinueOnThrust(const MinTimeProblem& p, const MinTimeSolution& start,
                                    double final_thrust_n, const ShootingOptions& options,
                                    const std::function<void(const ContinuationStep&)>& progress) {
  if (!(final_thrust_n > 0) || !start.converged) {
    throw std::invalid_argument("continuation: needs a converged start and a thrust > 0, got " +
                                FormatG(final_thrust_n, 10));
  }
  ShootingOptions o = options;
  o.target_homotopy_steps = 0;  // the previous solution is the guess
  ContinuationResult c;
  c.solution = start;
  c.thrust_n = p.thrust_n;
  // ln of the thrust ratio per step. Capped: longer steps at low thrust jump
  // to extremals with other revolution counts (60 N to 0.2 N with steps up
  // to e reached a 239.8-revolution extremal 0.4 % slower than Bombrun's).
  constexpr double kMaxLogStep = 0.35;
  double log_step = 0.25;
  const double direction = final_thrust_n < p.thrust_n ? -1.0 : 1.0;
  while (c.thrust_n != final_thrust_n && log_step > 1e-4) {
    if (options.Interrupted()) {
      c.interrupted = true;
      break;
    }
    double next = c.thrust_n * std::exp(direction * log_step);
    if ((next - final_thrust_n) * direction > 0) next = final_thrust_n;
    MinTimeProblem q = p;
    q.thrust_n = next;
    ShootingGuess g;
    g.duration_s = c.solution.duration_s * c.thrust_n / next;
    g.costate = c.solution.costate;
    const MinTimeSolution s = SolveMinTime(q, g, o);
    if (s.interrupted) {
      c.interrupted = true;  // not a failed step: keep the last converged solution
      break;
    }
    ContinuationStep step{next, s.duration_s, s.converged, s.evaluations};
    c.steps.push_back(step);
    if (progress) progress(step);
    if (s.converged) {
      c.solution = s, c.thrust_n = next;
      log_step = std::min(1.5 * log_step, kMaxLogStep);
    } else {
      log_step /= 2;
    }
  }
  return c;
}

}  // namespace thrustsched::transfer
