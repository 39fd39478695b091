// The force model of a transfer beyond the point mass: Earth's J2 zonal
// harmonic as a perturbing acceleration in the local QSW frame, added to the
// thrust in the Gauss equations of transfer/equinoctial.h (Bombrun 2007
// (1.29)-(1.34): dq/dt = f0(q) + F(q) (T/m u + gamma_pert)), with its
// derivatives for the minimum-time costate equations. The J2 components are
// those of Betts 2010 (ch. 6, the low-thrust orbit transfer's Delta_r,
// Delta_theta, Delta_h; Walker, Ireland & Owens 1985 for the elements), in
// the modified equinoctial elements:
//
//   Z = hx sin L - hy cos L,  Zl = hx cos L + hy sin L,  s2 = 1 + hx^2 + hy^2,
//   gamma_Q = -3 mu J2 R^2 / (2 r^4) (1 - 12 Z^2 / s2^2),
//   gamma_S = -12 mu J2 R^2 / r^4 Z Zl / s2^2,
//   gamma_W = -6 mu J2 R^2 / r^4 (1 - hx^2 - hy^2) Z / s2^2,   r = P / w.
//
//   transfer::ForceModel f{transfer::ForceModelKind::kJ2};        // EGM2008's J2 and R
//   transfer::ScaledUnits u;
//   Eigen::Vector3d g = transfer::PerturbationQsw(x, f, u);       // scaled units
//   transfer::Vector6 dx = transfer::GaussRates(x, thrust_acceleration_qsw, f, u);
//   std::vector<transfer::GaussSample> s =
//       transfer::PropagateGauss(problem, 86400.0, command, 600.0);
//
// Contract: the elements x in ScaledUnits (Mm, h); the pole of the J2 field
// is the z axis of the frame of the elements (EME2000 here: precession and
// nutation over a transfer are neglected). The independent Cartesian replay
// (transfer/replay.h) adds J2 in its Cartesian form, so it checks this one.
#ifndef THRUSTSCHED_TRANSFER_FORCE_MODEL_H_
#define THRUSTSCHED_TRANSFER_FORCE_MODEL_H_

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/geo_model.h"
#include "transfer/equinoctial.h"

namespace thrustsched::transfer {

enum class ForceModelKind { kTwoBody, kJ2 };

/// "two_body", "j2" (the scenario's "force_model").
std::string ToString(ForceModelKind k);

/// EGM2008's J2 = -sqrt(5) C20 (the degree-2 zonal term of the GEO
/// simulator's geopotential, dynamics/geo_model.h, with its reference radius
/// dynamics::geo::kEarthRadius).
inline constexpr double kEarthJ2 = 1.0826261738522227e-3;

struct ForceModel {
  ForceModelKind kind = ForceModelKind::kTwoBody;
  double j2 = kEarthJ2;
  double radius_m = dynamics::geo::kEarthRadius;
  bool IsValid(std::string* error) const;
};

/// The perturbing acceleration (zero for two_body) in QSW at the scaled
/// elements x, in scaled units (length / time^2).
Eigen::Vector3d PerturbationQsw(const Vector6& x, const ForceModel& f, const ScaledUnits& u);

/// Its derivatives with respect to the scaled elements, written by hand
/// (tested against finite differences): column j is d gamma / d x_j. The
/// minimum-time costate equations need them.
Eigen::Matrix<double, 3, 6> PerturbationJacobianQsw(const Vector6& x, const ForceModel& f,
                                                    const ScaledUnits& u);

/// dx/dt = f0 + F (control_acceleration_qsw + PerturbationQsw), scaled units.
Vector6 GaussRates(const Vector6& x, const Eigen::Vector3d& control_acceleration_qsw,
                   const ForceModel& f, const ScaledUnits& u);

/// Thrust command at time t (s) and elements (SI): the thrust in QSW as a
/// fraction of the maximum thrust (norm <= 1).
using ElementsCommand =
    std::function<Eigen::Vector3d(double t_s, const Equinoctial& q, double mass_kg)>;

struct GaussSample {
  double t_s = 0.0;
  Equinoctial elements;
  double mass_kg = 0.0;
};

struct MinTimeProblem;

/// Integrates the Gauss equations of p (its thrust, Isp, mass and
/// force_model) from p.initial for duration_s under `command`
/// (Runge-Kutta-Fehlberg 7(8), tolerance on the scaled state), sampled every
/// sample_step_s and at the end. @throws std::invalid_argument if p is
/// invalid, duration_s <= 0 or sample_step_s <= 0.
std::vector<GaussSample> PropagateGauss(const MinTimeProblem& p, double duration_s,
                                        const ElementsCommand& command, double sample_step_s,
                                        double tolerance = 1e-12);

}  // namespace thrustsched::transfer

#endif  // THRUSTSCHED_TRANSFER_FORCE_MODEL_H_
