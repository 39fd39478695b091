// Low-precision analytic Sun and Moon ephemerides (Montenbruck & Gill 2000,
// "Satellite Orbits", sec. 3.3.2; the "of date" forms are those of Montenbruck
// & Pfleger 2000, "Astronomy on the Personal Computer", MiniSun and MiniMoon).
// Geocentric positions in metres, time as a Julian date in TT.
//
//   double jd_tt = dynamics::Epoch::Parse("2034-01-01T00:00:00Z").JulianDateTt();
//   Eigen::Vector3d sun = dynamics::SunPositionMeanOfEpoch(jd_tt, jd_tt);   // of date
//   Eigen::Vector3d moon = dynamics::MoonPositionJ2000(jd_tt);             // J2000 series
//
// Two variants:
//  * "J2000" series: mean ecliptic and equinox J2000 with the Sun's perihelion
//    held fixed (0.11 deg off by 2034); kept because it is the series
//    Montenbruck & Gill 2000 print, and the tests check values computed from it.
//  * "of date" series (used by the GEO models): the mean longitudes include the
//    general precession and the Sun's perihelion drift (Sun within ~0.01 deg,
//    Moon within ~0.07 deg of ERFA in 2034). `...MeanOfEpoch(jd_tt, jd_frame_tt)`
//    refers the result to the mean equator and equinox of the fixed date
//    jd_frame_tt (precession accumulated since then, 5029.0966"/century in
//    ecliptic longitude, is removed; obliquity of jd_frame_tt), i.e. to an
//    inertial frame. jd_frame_tt = jd_tt gives plain "mean of date" coordinates.
// Accuracy ~0.01-0.1 deg in direction, ~1e-4 in distance: ample for the luni-solar
// and radiation-pressure perturbations of a GEO satellite.
// Every function throws std::invalid_argument naming the argument if a Julian
// date is not finite.
#ifndef THRUSTSCHED_DYNAMICS_EPHEMERIDES_H_
#define THRUSTSCHED_DYNAMICS_EPHEMERIDES_H_

#include <Eigen/Core>

namespace thrustsched::dynamics {

/// Sun, J2000 series, mean equator and equinox of J2000 (m).
Eigen::Vector3d SunPositionJ2000(double jd_tt);
/// Moon, J2000 series, mean equator and equinox of J2000 (m).
Eigen::Vector3d MoonPositionJ2000(double jd_tt);
/// Sun, of-date series, mean equator and equinox of jd_frame_tt (m).
Eigen::Vector3d SunPositionMeanOfEpoch(double jd_tt, double jd_frame_tt);
/// Moon, of-date series, mean equator and equinox of jd_frame_tt (m).
Eigen::Vector3d MoonPositionMeanOfEpoch(double jd_tt, double jd_frame_tt);

/// Mean obliquity of the ecliptic (rad), 23.43929111 deg - 0.0130042 deg T.
double MeanObliquityRad(double jd_tt);

}  // namespace thrustsched::dynamics

#endif  // THRUSTSCHED_DYNAMICS_EPHEMERIDES_H_
