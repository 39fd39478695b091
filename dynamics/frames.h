// Inertial frames in which GEO states are exchanged with other tools (EME2000,
// GCRF) and the rotation to the frame of the GEO models, the mean equator and
// mean equinox of the model epoch ("MOE(t0)", dynamics/geo_simulator.h).
//
//   auto epoch = dynamics::Epoch::Parse("2034-01-01T00:00:00Z");
//   dynamics::Vector6d rv_model = dynamics::ToModelFrame(rv_eme2000,
//   dynamics::InertialFrame::kEme2000, epoch); dynamics::Vector6d back =
//   dynamics::FromModelFrame(rv_model, dynamics::InertialFrame::kEme2000, epoch);
//
// EME2000 (mean equator and equinox of J2000.0) -> MOE(t0) is the IAU 1976
// precession (Lieske et al. 1977, A&A 58, 1; the zeta, z, theta series of the
// Explanatory Supplement to the Astronomical Almanac, 1992, eq. 3.211-2),
// evaluated at the model epoch in TT. GCRF -> EME2000 is the constant frame
// bias of the IERS Conventions 2003 (IERS TN 32, §5.5.1: d_alpha0 = -14.6 mas,
// xi0 = -16.617 mas, eta0 = -6.8192 mas; 23 mas is 4.7 m at the GEO radius).
// All three frames are taken as non-rotating, so
// velocities rotate like positions: MOE(t0) is fixed by construction, and
// the precession that the model neglects during a run (50"/yr) is not a
// frame rotation here but a documented model error.
#ifndef THRUSTSCHED_DYNAMICS_FRAMES_H_
#define THRUSTSCHED_DYNAMICS_FRAMES_H_

#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "dynamics/orbital_elements.h"
#include "dynamics/time.h"

namespace thrustsched::dynamics {

/// Exchange frames, named as in the SANA registry used by CCSDS 502.0-B-3
/// (REF_FRAME values).
enum class InertialFrame { kEme2000, kGcrf };

/// "EME2000", "GCRF".
std::string_view ToString(InertialFrame frame);
/// The frame of a REF_FRAME value ("EME2000", "GCRF"; "J2000", a spelling of
/// older ODM files, is read as EME2000), nullopt otherwise.
std::optional<InertialFrame> ParseInertialFrame(std::string_view name);

/// IAU 1976 precession matrix P with r_MOD(date) = P r_EME2000, date in TT
/// (Julian date). @throws std::invalid_argument if jd_tt is not finite.
Eigen::Matrix3d PrecessionIau1976(double jd_tt);
/// IERS 2003 frame-bias matrix B with r_EME2000 = B r_GCRF.
Eigen::Matrix3d FrameBiasIers2003();

/// R with r_model = R r_frame, the model frame being MOE(model_epoch).
Eigen::Matrix3d ModelFrameRotation(InertialFrame frame, const Epoch& model_epoch);
/// Position and velocity (any consistent units) from `frame` to MOE(model_epoch).
Vector6d ToModelFrame(const Vector6d& rv, InertialFrame frame, const Epoch& model_epoch);
/// Position and velocity from MOE(model_epoch) to `frame`.
Vector6d FromModelFrame(const Vector6d& rv_model, InertialFrame frame, const Epoch& model_epoch);

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_FRAMES_H_
