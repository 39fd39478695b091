#include "app/geo_products.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "app/ccsds_kvn.h"
#include "app/outputs.h"
#include "dynamics/frames.h"
#include "dynamics/geo_simulator.h"
#include "dynamics/time.h"

namespace thrustsched::app {
namespace {

using transcription::Burn;
constexpr double kTimeTolerance = 1e-6;  // s: two times closer than this are one instant
constexpr int kMaxInterpolationDegree = 7;
// A leg's number of sample steps is whole up to this (rounding of end - start).
constexpr double kStepCountSlack = 1e-9;

std::shared_ptr<const dynamics::GeoSimulator> Simulator(const Scenario& s) {
  if (!s.geo) throw std::invalid_argument("flight-dynamics products need a GEO scenario");
  if (s.check.nonlinear) return s.check.nonlinear;
  return std::make_shared<const dynamics::GeoSimulator>(*s.geo);
}

dynamics::Epoch ModelEpoch(const Scenario& s) { return dynamics::Epoch::Parse(s.geo->epoch); }

std::vector<dynamics::InputPulse> Pulses(const std::vector<Burn>& burns) {
  std::vector<dynamics::InputPulse> p;
  for (const Burn& b : burns) p.push_back({b.thruster, b.start_s, b.end_s});
  return p;
}

// Sorted times with near-duplicates merged.
std::vector<double> Unique(std::vector<double> t) {
  std::sort(t.begin(), t.end());
  std::vector<double> out;
  for (double x : t) {
    if (out.empty() || x - out.back() > kTimeTolerance) out.push_back(x);
  }
  return out;
}

void CheckNoLeapSecond(const Scenario& s, double t0, double t1) {
  const dynamics::Epoch from = ModelEpoch(s).PlusSeconds(t0);
  if (dynamics::CrossesLeapSecond(from, t1 - t0)) {
    throw ScenarioError(
        "UTC labels: the run from " + from.ToIso8601() + " to " +
        from.PlusSeconds(t1 - t0).ToIso8601() +
        " crosses a leap second; the model clock is uniform, so UTC labels after it would be 1 s "
        "late (start the scenario after the leap second)");
  }
}

std::string ObjectName(const Scenario& s) {
  return s.initial_orbit && !s.initial_orbit->object_name.empty() ? s.initial_orbit->object_name
                                                                  : s.name;
}
std::string ObjectId(const Scenario& s) {
  return s.initial_orbit && !s.initial_orbit->object_id.empty() ? s.initial_orbit->object_id
                                                                : "UNKNOWN";
}

// Indices of the burns on during (t0, t1) (tested at the midpoint).
std::vector<int> OnDuring(const std::vector<Burn>& burns, double t0, double t1) {
  std::vector<int> on;
  const double mid = 0.5 * (t0 + t1);
  for (size_t k = 0; k < burns.size(); ++k) {
    if (burns[k].start_s <= mid && mid < burns[k].end_s) on.push_back(static_cast<int>(k));
  }
  return on;
}

std::string ArcComment(const Scenario& s, const std::vector<Burn>& burns,
                       const std::vector<int>& on) {
  if (on.empty()) return "coast arc (no thrust)";
  std::ostringstream os;
  os << "burn arc:";
  for (int k : on) {
    const dynamics::Thruster& t = s.problem.thrusters.thruster(burns[k].thruster);
    os << " " << t.name << " on, " << s.problem.thrusters.thrust_n() << " N along RTN ["
       << KvnFixed(t.direction.x(), 6) << " " << KvnFixed(t.direction.y(), 6) << " "
       << KvnFixed(t.direction.z(), 6) << "];";
  }
  return os.str();
}

std::vector<std::string> HeaderComments(const Scenario& s) {
  return {
      "thrustsched nonlinear replay of scenario \"" + s.name + "\" (station " +
          KvnFixed(s.geo->station_longitude_deg, 4) + " deg E)",
      "model frame: mean equator and equinox of " + s.geo->epoch +
          " (IAU 1976 precession), rotated to EME2000 for this file; nutation neglected; UT1 = UTC",
      std::string("UTC labels on a uniform clock with TAI-UTC = 37 s; the leap-second table is "
                  "known up to ") +
          dynamics::kLeapSecondsKnownUntil,
      "segments are split at every burn start and end: do not interpolate across them"};
}

std::vector<OemSegment> LegSegments(const Scenario& s, const dynamics::GeoSimulator& sim,
                                    const ReplayLeg& leg) {
  std::vector<double> events = {leg.start_s, leg.end_s};
  for (const Burn& b : leg.burns) {
    if (b.start_s < leg.start_s - kTimeTolerance || b.end_s > leg.end_s + kTimeTolerance) {
      throw std::invalid_argument("BuildReplayOem: a burn lies outside its leg");
    }
    events.push_back(b.start_s);
    events.push_back(b.end_s);
  }
  events = Unique(events);
  std::vector<double> times = events;
  for (double t : leg.sample_times) {
    if (t >= leg.start_s - kTimeTolerance && t <= leg.end_s + kTimeTolerance) times.push_back(t);
  }
  times = Unique(times);
  const std::vector<dynamics::Vector6d> states = sim.Propagate(
      leg.eci, leg.start_s, s.problem.thrusters.AccelerationMatrix(), Pulses(leg.burns), times);
  const dynamics::Epoch epoch = ModelEpoch(s);
  const Eigen::Matrix3d to_eme =
      dynamics::ModelFrameRotation(dynamics::InertialFrame::kEme2000, epoch).transpose();
  std::vector<OemSegment> out;
  size_t k = 0;
  for (size_t e = 0; e + 1 < events.size(); ++e) {
    OemSegment seg;
    seg.object_name = ObjectName(s);
    seg.object_id = ObjectId(s);
    seg.comments = {ArcComment(s, leg.burns, OnDuring(leg.burns, events[e], events[e + 1]))};
    while (k < times.size() && times[k] < events[e] - kTimeTolerance) ++k;
    for (size_t j = k; j < times.size() && times[j] <= events[e + 1] + kTimeTolerance; ++j) {
      dynamics::Vector6d rv;
      rv << to_eme * states[j].head<3>(), to_eme * states[j].tail<3>();
      seg.points.push_back({epoch.PlusSeconds(times[j]), rv});
    }
    seg.start_time = seg.points.front().epoch;
    seg.stop_time = seg.points.back().epoch;
    seg.interpolation_degree =
        std::min(kMaxInterpolationDegree, static_cast<int>(seg.points.size()) - 1);
    out.push_back(std::move(seg));
  }
  return out;
}

// |integral of the thrust acceleration in ECI| over [t0, t1] along the
// nonlinear motion of this burn from x0: the thrust is fixed in the turning
// RTN frame, so the net velocity increment is below |a| (t1 - t0). Composite
// Simpson on at most 10-s steps (the frame turns 7e-4 rad in 10 s).
double DeliveredDeltaV(const dynamics::GeoSimulator& sim, const Eigen::Vector3d& a_rtn,
                       const dynamics::Vector6d& x0, double t0, double t1) {
  if (!(t1 > t0)) return 0.0;
  const int n = 2 * static_cast<int>(std::ceil((t1 - t0) / 20.0));  // even number of steps
  const double h = (t1 - t0) / n;
  std::vector<double> times;
  for (int k = 0; k <= n; ++k) times.push_back(k == n ? t1 : t0 + k * h);
  Eigen::MatrixXd accel(3, 1);
  accel.col(0) = a_rtn;
  const std::vector<dynamics::Vector6d> xs = sim.Propagate(x0, t0, accel, {{0, t0, t1}}, times);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k <= n; ++k) {
    const double w = (k == 0 || k == n) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    sum += w * (dynamics::RtnBasis(xs[k]) * a_rtn);
  }
  return (sum * h / 3.0).norm();
}

}  // namespace

ReplayLeg ScenarioReplayLeg(const Scenario& s, const std::vector<Burn>& burns,
                            const std::vector<double>& sample_times) {
  ReplayLeg leg;
  leg.start_s = s.problem.grid.front();
  leg.end_s = s.problem.grid.back();
  leg.eci = Simulator(s)->EciFromRelative(s.problem.initial_state, leg.start_s);
  leg.burns = burns;
  leg.sample_times = sample_times.empty() ? s.problem.grid : sample_times;
  return leg;
}

std::vector<BurnFacts> ComputeBurnFacts(const Scenario& s, const std::vector<Burn>& burns,
                                        const ReplayLeg& leg) {
  const std::shared_ptr<const dynamics::GeoSimulator> sim = Simulator(s);
  if (burns.empty()) return {};
  const dynamics::Epoch epoch = ModelEpoch(s);
  const Eigen::MatrixXd accel = s.problem.thrusters.AccelerationMatrix();
  std::vector<size_t> order(burns.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return burns[a].start_s < burns[b].start_s; });
  std::vector<double> starts;
  for (size_t k : order) starts.push_back(std::max(burns[k].start_s, leg.start_s));
  const std::vector<dynamics::Vector6d> at_start =
      sim->Propagate(leg.eci, leg.start_s, accel, Pulses(burns), starts);
  std::vector<BurnFacts> out(burns.size());
  for (size_t j = 0; j < order.size(); ++j) {
    const Burn& b = burns[order[j]];
    BurnFacts& f = out[order[j]];
    f.start_utc = epoch.PlusSeconds(b.start_s).FormatUtc(3, true);
    f.end_utc = epoch.PlusSeconds(b.end_s).FormatUtc(3, true);
    f.direction_rtn = s.problem.thrusters.thruster(b.thruster).direction;
    f.delta_v_m_s = DeliveredDeltaV(*sim, accel.col(b.thruster), at_start[j], starts[j], b.end_s);
  }
  return out;
}

OemFile BuildReplayOem(const Scenario& s, const std::vector<ReplayLeg>& legs) {
  if (legs.empty()) throw std::invalid_argument("BuildReplayOem: no leg");
  CheckNoLeapSecond(s, legs.front().start_s, legs.back().end_s);
  const std::shared_ptr<const dynamics::GeoSimulator> sim = Simulator(s);
  OemFile f;
  f.comments = HeaderComments(s);
  f.creation_date = CreationDate();
  f.originator = "THRUSTSCHED";
  for (const ReplayLeg& leg : legs) {
    for (OemSegment& seg : LegSegments(s, *sim, leg)) {
      // A leg starts where the previous one ended: continue a coast arc
      // across the junction instead of opening a segment there.
      if (!f.segments.empty() && f.segments.back().comments == seg.comments &&
          std::abs(seg.start_time.SecondsSince(f.segments.back().stop_time)) < kTimeTolerance) {
        OemSegment& prev = f.segments.back();
        prev.points.insert(prev.points.end(), seg.points.begin() + 1, seg.points.end());
        prev.stop_time = prev.points.back().epoch;
        prev.interpolation_degree =
            std::min(kMaxInterpolationDegree, static_cast<int>(prev.points.size()) - 1);
        continue;
      }
      f.segments.push_back(std::move(seg));
    }
  }
  return f;
}

Opm BuildManeuverOpm(const Scenario& s, const std::vector<ReplayLeg>& legs) {
  if (legs.empty()) throw std::invalid_argument("BuildManeuverOpm: no leg");
  CheckNoLeapSecond(s, legs.front().start_s, legs.back().end_s);
  const dynamics::Epoch epoch = ModelEpoch(s);
  const dynamics::ThrusterSet& thr = s.problem.thrusters;
  Opm o;
  o.comments = HeaderComments(s);
  o.comments.pop_back();
  o.comments.push_back(
      "finite burns: thrust constant in the satellite's RTN frame for MAN_DURATION; MAN_DV = F/m x "
      "duration x direction; thrustsched holds the mass constant (MAN_DELTA_MASS = propellant "
      "used)");
  o.creation_date = CreationDate();
  o.originator = "THRUSTSCHED";
  o.object_name = ObjectName(s);
  o.object_id = ObjectId(s);
  o.frame = dynamics::InertialFrame::kEme2000;
  o.state_comments = {"state at the plan start (nonlinear replay start)"};
  o.epoch = epoch.PlusSeconds(legs.front().start_s);
  o.rv = dynamics::FromModelFrame(legs.front().eci, dynamics::InertialFrame::kEme2000, epoch);
  OpmSpacecraft sc;
  sc.mass_kg = thr.mass_kg();
  sc.solar_rad_area_m2 = s.geo->area_to_mass_m2_kg * thr.mass_kg();
  sc.solar_rad_coeff = s.geo->reflectivity_cr;
  o.spacecraft = sc;  // no drag at GEO: DRAG_AREA = DRAG_COEFF = 0
  std::vector<Burn> burns;
  for (const ReplayLeg& leg : legs) burns.insert(burns.end(), leg.burns.begin(), leg.burns.end());
  std::stable_sort(burns.begin(), burns.end(),
                   [](const Burn& a, const Burn& b) { return a.start_s < b.start_s; });
  for (size_t k = 0; k < burns.size(); ++k) {
    const Burn& b = burns[k];
    OpmManeuver m;
    m.comments = {"burn " + std::to_string(k + 1) + ": thruster " + thr.thruster(b.thruster).name};
    m.ignition = epoch.PlusSeconds(b.start_s);
    m.duration_s = b.duration_s();
    m.delta_mass_kg = -thr.MassFlow() * b.duration_s();
    m.ref_frame = "RTN";
    m.dv_m_s = thr.acceleration() * b.duration_s() * thr.thruster(b.thruster).direction;
    o.maneuvers.push_back(m);
  }
  return o;
}

ReplayLeg CycleReplayLeg(const planning::CycleRecord& c, double step_s) {
  ReplayLeg leg;
  leg.start_s = c.start_s;
  leg.end_s = c.applied_end_s;
  leg.eci = c.eci_start;
  leg.burns = c.burns;
  const int n =
      static_cast<int>(std::ceil((c.applied_end_s - c.start_s) / step_s - kStepCountSlack));
  for (int k = 0; k <= n; ++k)
    leg.sample_times.push_back(std::min(c.start_s + k * step_s, c.applied_end_s));
  return leg;
}

void CheckFlightDynamicsFiles(const Scenario& s, const FlightDynamicsFiles& files, double t0,
                              double t1) {
  if (!files.any()) return;
  const std::string option =
      files.oem.empty() ? "--opm-maneuvers " + files.opm_maneuvers : "--oem " + files.oem;
  if (!s.geo) {
    throw ScenarioError(option + ": CCSDS files need a GEO scenario (model.type \"geo\"), got \"" +
                        std::string(ToString(s.model_type)) + "\"");
  }
  if (s.impulsive())
    throw ScenarioError(option + ": CCSDS files need on-off thrusters, not impulsive mode");
  try {
    CheckNoLeapSecond(s, t0, t1);
  } catch (const ScenarioError& e) {
    throw ScenarioError(option + ": " + e.what());
  }
}

std::vector<std::string> WriteFlightDynamicsFiles(const Scenario& s,
                                                  const FlightDynamicsFiles& files,
                                                  const std::vector<ReplayLeg>& legs) {
  std::vector<std::string> written;
  if (!files.oem.empty()) {
    WriteTextFile(files.oem, FormatOem(BuildReplayOem(s, legs)));
    written.push_back(files.oem);
  }
  if (!files.opm_maneuvers.empty()) {
    WriteTextFile(files.opm_maneuvers, FormatOpm(BuildManeuverOpm(s, legs)));
    written.push_back(files.opm_maneuvers);
  }
  return written;
}

}  // namespace thrustsched::app
