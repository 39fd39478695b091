#include "tests/transcription/random_problems.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <unsupported/Eigen/MatrixFunctions>

#include "common/constants.h"
#include "dynamics/models.h"
#include "transcription/checker.h"
#include "transcription/solve.h"

namespace thrustsched::transcription::soak {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A small helper over std::mt19937_64 (its distributions are deterministic
// for one standard library, which is what "seeded" asks here).
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : rng_(seed) {}
  double Uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  int Int(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool Chance(double p) { return Uniform(0.0, 1.0) < p; }

 private:
  std::mt19937_64 rng_;
};

long long Binomial(int n, int k) {
  long long b = 1;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

// On-off combinations of m thrusters in one slot with at most k on.
long long CombinationsPerSlot(int m, int k) {
  long long c = 0;
  for (int j = 0; j <= std::min(m, k); ++j) c += Binomial(m, j);
  return c;
}

// The largest horizon (slots) whose pattern space stays enumerable.
int MaxEnumerableSlots(int m, int k) {
  const double c = static_cast<double>(CombinationsPerSlot(m, k));
  return static_cast<int>(
      std::floor(std::log(static_cast<double>(kMaxEnumeratedLeaves)) / std::log(c)));
}

std::string Fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), format, v);
  return buf;
}

dynamics::ThrusterSet RandomThrusters(Draw* d, int m, std::string* text) {
  std::vector<dynamics::Thruster> list;
  for (int i = 0; i < m; ++i) {
    Eigen::Vector3d dir;
    if (d->Chance(0.5)) {  // along an axis, either sign
      dir.setZero();
      dir[d->Int(0, 2)] = d->Chance(0.5) ? 1.0 : -1.0;
    } else {
      do {
        dir = Eigen::Vector3d(d->Uniform(-1, 1), d->Uniform(-1, 1), d->Uniform(-1, 1));
      } while (dir.norm() < 0.2);
      dir.normalize();
    }
    list.push_back({"T" + std::to_string(i), dir, true});
    *text += (i ? ", [" : "[") + Fmt("%.3f", dir[0]) + Fmt(" %.3f", dir[1]) + Fmt(" %.3f]", dir[2]);
  }
  const double thrust_n = d->Uniform(0.1, 1.0);
  *text += " at " + Fmt("%.3f N", thrust_n) + " on 100 kg, Isp 300 s";
  return dynamics::ThrusterSet(list, thrust_n, 100.0, 300.0);
}

std::vector<double> RandomGrid(Draw* d, int n, double h, std::string* text) {
  std::vector<double> grid = {0.0};
  const bool uniform = d->Chance(0.75);
  for (int j = 0; j < n; ++j) grid.push_back(grid.back() + (uniform ? h : h * d->Int(1, 2)));
  *text += std::to_string(n) + " slots of " + (uniform ? "" : "1-2 x ") + Fmt("%g s", h);
  return grid;
}

OperationalRules RandomRules(Draw* d, int m, int k, double h, std::string* text) {
  OperationalRules r;
  r.max_simultaneous = k;
  r.min_burn_s = h * std::vector<double>{0, 1, 1.5, 2}[d->Int(0, 3)];
  r.min_off_same_s = h * d->Int(0, 3);
  r.min_gap_other_s = m > 1 ? h * d->Int(0, 2) : 0.0;
  if (d->Chance(0.2)) r.max_burn_s = h * d->Int(2, 4);
  if (d->Chance(0.2)) r.max_burns_per_thruster = d->Int(1, 3);
  r.allow_burn_across_end = d->Chance(0.3);
  *text += "; K " + std::to_string(k) + Fmt(", min burn %g s", r.min_burn_s) +
           Fmt(", min off %g s", r.min_off_same_s) + Fmt(", gap other %g s", r.min_gap_other_s) +
           Fmt(", max burn %g s", r.max_burn_s) + ", max burns " +
           std::to_string(r.max_burns_per_thruster) +
           (r.allow_burn_across_end ? ", burn across end" : "");
  return r;
}

void RandomWindow(Draw* d, ScheduleProblem* p, double half_width_m, std::string* text) {
  WindowSpec& w = p->window;
  w.outputs = {0, 1};
  w.half_widths = {half_width_m, half_width_m * d->Uniform(0.7, 1.3)};
  const int n = p->num_intervals();
  w.enforce_from_s = d->Chance(0.7) ? 0.0 : p->grid[d->Int(1, n / 2)];
  w.soft = d->Chance(0.15);
  w.soft_penalty = d->Uniform(0.1, 2.0);
  if (d->Chance(0.1)) w.margin = d->Uniform(0.0, 0.2);
  if (d->Chance(0.15)) w.intersample_points = d->Int(1, 2);
  *text += std::string("; window ") +
           (w.soft ? Fmt("soft (penalty %.3f)", w.soft_penalty) : "hard") +
           Fmt(" %.1f", w.half_widths[0]) + Fmt(" x %.1f m", w.half_widths[1]) +
           Fmt(" from %g s", w.enforce_from_s) + Fmt(", margin %.3f", w.margin) +
           ", inter-sample " + std::to_string(w.intersample_points);
}

}  // namespace

const char* ToString(ReferenceKind kind) {
  return kind == ReferenceKind::kEnumeration ? "enumeration" : "plain CBC";
}

long long PatternSpaceSize(const ScheduleProblem& p, long long limit) {
  const long long c = CombinationsPerSlot(p.thrusters.size(), p.rules.max_simultaneous);
  long long leaves = 1;
  for (int j = 0; j < p.num_intervals(); ++j) {
    leaves *= c;
    if (leaves > limit) return limit + 1;
  }
  return leaves;
}

RandomCase GenerateCase(std::uint64_t seed, int max_slots) {
  if (max_slots < kMinSlots || max_slots > kMaxSlots) {
    throw std::invalid_argument("GenerateCase: max_slots must be in [6, 40], got " +
                                std::to_string(max_slots));
  }
  Draw d(seed);
  RandomCase c;
  c.seed = seed;
  ScheduleProblem& p = c.problem;
  std::string text = "seed " + std::to_string(seed) + ": ";
  if (d.Chance(0.5)) {
    const double n = d.Uniform(2e-4, 1.2e-3);
    p.model = std::make_shared<dynamics::HcwModel>(n, 1000.0);
    text += Fmt("HCW n %.6g rad/s; ", n);
  } else {
    p.model = std::make_shared<dynamics::DoubleIntegrator3d>(100.0, 100.0);
    text += "double integrator; ";
  }
  const int m = d.Int(1, 3);
  const int k = d.Int(1, m);
  p.thrusters = RandomThrusters(&d, m, &text);
  text += "; ";
  const int n_max = MaxEnumerableSlots(m, k);
  const bool small = n_max >= kMinSlots && d.Chance(0.6);
  const int n = small ? d.Int(kMinSlots, std::min(n_max, 16))
                      : d.Int(std::min(std::max(kMinSlots, n_max + 1), max_slots), max_slots);
  const double h = 30.0 * d.Int(1, 4);
  p.grid = RandomGrid(&d, n, h, &text);
  p.rules = RandomRules(&d, m, k, h, &text);
  if (d.Chance(0.2)) {
    const int a = d.Int(0, n - 1), b = d.Int(a + 1, n);
    p.forced_off.push_back({d.Int(0, m - 1), p.grid[a], p.grid[b]});
    text += Fmt("; T%g forced off", p.forced_off.back().thruster) + Fmt(" [%g,", p.grid[a]) +
            Fmt(" %g) s", p.grid[b]);
  }
  // A drift, mostly in the window's plane, of 0.3-1.5 slots of thrust, which
  // leaves a window of 0.35-1 times its span over the horizon unless
  // corrected, from a start inside it.
  const double horizon_s = p.grid.back();
  Eigen::Vector3d dir;
  do {
    dir = Eigen::Vector3d(d.Uniform(-1, 1), d.Uniform(-1, 1), 0.3 * d.Uniform(-1, 1));
  } while (dir.norm() < 0.2);
  const double speed = p.thrusters.acceleration() * h * d.Uniform(0.3, 1.5);
  const double half_width_m = std::max(20.0, speed * horizon_s * d.Uniform(0.35, 1.0));
  p.initial_state = Eigen::VectorXd::Zero(6);
  p.initial_state.segment<3>(3) = speed * dir.normalized();
  for (int i = 0; i < 3; ++i) p.initial_state[i] = d.Uniform(-0.3, 0.3) * half_width_m;
  text += Fmt("; start [%.1f", p.initial_state[0]) + Fmt(" %.1f", p.initial_state[1]) +
          Fmt(" %.1f] m", p.initial_state[2]) + Fmt(" [%.4f", p.initial_state[3]) +
          Fmt(" %.4f", p.initial_state[4]) + Fmt(" %.4f] m/s", p.initial_state[5]);
  RandomWindow(&d, &p, half_width_m, &text);
  if (d.Chance(0.2)) {
    const double box = d.Uniform(0.3, 1.0) * half_width_m;
    p.terminal.kind = TerminalKind::kStateBox;
    p.terminal.target = Eigen::VectorXd::Zero(6);
    p.terminal.tolerance = (Eigen::VectorXd(6) << box, box, kInf, kInf, kInf, kInf).finished();
    text += Fmt("; terminal box |x|,|y| <= %.1f m", box);
  }
  const int objective = d.Int(0, 4);
  p.objective.kind = objective <= 2   ? ObjectiveKind::kL1
                     : objective == 3 ? ObjectiveKind::kDeltaV
                                      : ObjectiveKind::kPropellant;
  if (d.Chance(0.2)) p.objective.burn_start_penalty = d.Uniform(0.001, 0.05);
  text += std::string("; objective ") + std::string(ToString(p.objective.kind)) +
          Fmt(", burn start penalty %g", p.objective.burn_start_penalty);
  c.enumerable = PatternSpaceSize(p) <= kMaxEnumeratedLeaves;
  text += c.enumerable ? "; reference enumeration" : "; reference plain CBC";
  c.description = text;
  return c;
}

}  // namespace thrustsched::transcription::soak
