#include "app/transfer_handover.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "app/ccsds_kvn.h"
#include "common/constants.h"

namespace thrustsched::app {

nlohmann::json StationKeepingInitialState(const transfer::Equinoctial& q, double mu_m3_s2,
                                          const std::optional<dynamics::Epoch>& epoch) {
  // The exact inverse of the Keplerian -> equinoctial map the parser uses
  // (dynamics/keplerian.h): hx + j hy = tan(i/2) exp(jW), ex + j ey =
  // e exp(j(w + W)), L = W + w + nu. Without the thresholds of
  // dynamics::KeplerianFromCartesian (W = 0 below tan(i/2) = 1e-10, w = 0
  // below e = 1e-10), which would move a transfer's end (e ~ 1e-11) by 1 mm.
  const double e = std::hypot(q.ex, q.ey), tan_half_i = std::hypot(q.hx, q.hy);
  if (!(e < 1))
    throw std::invalid_argument("final state: not an ellipse, e = " + std::to_string(e));
  const double raan = std::atan2(q.hy, q.hx), perigee_longitude = std::atan2(q.ey, q.ex);
  auto wrap_deg = [](double rad) {
    const double d = std::fmod(rad * common::kRadToDeg, 360.0);
    return d < 0 ? d + 360.0 : d;
  };
  nlohmann::json kep = {{"frame", "EME2000"}};
  if (epoch) kep["epoch"] = epoch->ToIso8601();
  kep["semi_major_axis_km"] = q.p_m / (1 - e * e) / 1e3;
  kep["eccentricity"] = e;
  kep["inclination_deg"] = 2 * std::atan(tan_half_i) * common::kRadToDeg;
  kep["ra_of_asc_node_deg"] = wrap_deg(raan);
  kep["arg_of_pericenter_deg"] = wrap_deg(perigee_longitude - raan);
  kep["true_anomaly_deg"] = wrap_deg(q.l_rad - perigee_longitude);
  kep["gm_km3_s2"] = mu_m3_s2 / 1e9;
  return {{"keplerian", kep}};
}

OemFile TransferOem(const std::vector<transfer::ReplayState>& orbit, const dynamics::Epoch& start,
                    const std::string& name, const std::string& comment) {
  if (orbit.empty()) throw std::invalid_argument("TransferOem: no state");
  constexpr int kMaxInterpolationDegree = 7;
  OemFile f;
  f.originator = "THRUSTSCHED";
  f.creation_date = CreationDate();
  f.comments = {comment, "frame: the transfer's inertial frame, taken as EME2000; two-body model",
                "a new segment at each impulse (two_impulse): do not interpolate across segments"};
  // A repeated time is an impulse (two_impulse): the velocity jumps there,
  // so a new segment starts, sharing the epoch (never interpolate across).
  OemSegment seg;
  seg.object_name = name.empty() ? "TRANSFER" : name;
  seg.object_id = "UNKNOWN";
  auto close_segment = [&] {
    seg.start_time = seg.points.front().epoch;
    seg.stop_time = seg.points.back().epoch;
    seg.interpolation_degree =
        std::min(kMaxInterpolationDegree, static_cast<int>(seg.points.size()) - 1);
    f.segments.push_back(seg);
    seg.points.clear();
  };
  for (std::size_t k = 0; k < orbit.size(); ++k) {
    const transfer::ReplayState& s = orbit[k];
    const dynamics::Epoch e = start.PlusSeconds(s.t_s);
    if (k > 0 && s.t_s == orbit[k - 1].t_s) {
      close_segment();
    } else if (!seg.points.empty() && e.SecondsSince(seg.points.back().epoch) < 1e-3) {
      // The file's epochs have a millisecond resolution where whole: a step
      // shorter than that would repeat an epoch.
      if (k + 1 == orbit.size()) seg.points.back() = {e, s.rv};  // keep the end state exact
      continue;
    }
    seg.points.push_back({e, s.rv});
  }
  close_segment();
  return f;
}

}  // namespace thrustsched::app
