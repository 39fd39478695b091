#include "app/conjunction_section.h"

#include <cmath>
#include <string>
#include <vector>

#include "transcription/conjunction.h"

namespace thrustsched::app {
namespace {

Eigen::Vector3d ReadVector3(JsonObject& o, const std::string& key) {
  const std::vector<double> v = o.NumberArray(key, 3);
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

void ParseChecks(JsonObject ch, transcription::ConjunctionSpec* c) {
  c->num_checks = ch.Integer("count", 1, 100000);
  if (auto t = ch.OptionalNumber("start_s")) c->check_start_s = *t;
  if (auto t = ch.OptionalNumber("end_s")) c->check_end_s = *t;
  if (!std::isnan(c->check_start_s) && !std::isnan(c->check_end_s) &&
      !(c->check_end_s > c->check_start_s)) {
    ch.Fail("end_s", FormatNumber(c->check_end_s) + " s is not after start_s " +
                         FormatNumber(c->check_start_s) + " s");
  }
  ch.Finish();
}

void ParseSolveStrategy(JsonObject v, transcription::ConjunctionSolveOptions* o) {
  o->fixed_face_start = v.OptionalBool("fixed_face_start").value_or(o->fixed_face_start);
  o->tighten_budget = v.OptionalBool("tighten_budget").value_or(o->tighten_budget);
  if (auto r = v.OptionalNumber("restart_ratio", Bound::kPositive)) {
    if (*r > 1.0) v.Fail("restart_ratio", "must be in (0, 1], got " + FormatNumber(*r));
    o->restart_ratio = *r;
  }
  o->max_rounds = v.OptionalInteger("max_rounds", 1, 1000).value_or(o->max_rounds);
  o->lp_bounds = v.OptionalBool("lp_bounds").value_or(o->lp_bounds);
  v.Finish();
}

void ParseVerification(JsonObject v, transcription::ConjunctionCheckOptions* o) {
  o->monte_carlo_samples =
      v.OptionalInteger("monte_carlo_samples", 0, 10000000).value_or(o->monte_carlo_samples);
  o->seed = static_cast<std::uint64_t>(v.OptionalInteger("seed", 0, 2147483647).value_or(1));
  o->sample_step_s = v.OptionalNumber("sample_step_s", Bound::kPositive).value_or(0.0);
  o->nonlinear = v.OptionalBool("nonlinear").value_or(true);
  v.Finish();
}

// Polytope: "cube" or {"faces": [[ax, ay, az], ...], "offsets_m": [...]}, in the section's frame.
void ParsePolytope(JsonObject& c, const Eigen::Matrix3d& to_local,
                   transcription::ConjunctionSpec* spec) {
  if (!c.Has("polytope")) return;
  const nlohmann::json& v = c.Raw("polytope");
  if (v.is_string()) {
    c.Choice("polytope", {"cube"});
    return;
  }
  JsonObject p = c.Object("polytope");
  const nlohmann::json& faces = p.Raw("faces");
  if (!faces.is_array() || faces.empty()) {
    p.Fail("faces", "expected a non-empty array of [ax, ay, az], got " + DescribeJson(faces));
  }
  const int m = static_cast<int>(faces.size());
  const Eigen::MatrixXd a = p.NumberMatrix("faces", m, 3);
  const std::vector<double> b = p.NumberArray("offsets_m", m);
  p.Finish();
  spec->polytope.faces = a * to_local.transpose();  // rows a_j^T in the local frame
  spec->polytope.offsets = Eigen::Map<const Eigen::VectorXd>(b.data(), m);
  for (int j = 0; j < m; ++j) {
    if (spec->polytope.faces.row(j).norm() == 0.0) {
      p.Fail("faces", "face " + std::to_string(j) + " has a zero normal");
    }
  }
}

}  // namespace

void ParseConjunction(JsonObject c, Scenario* s) {
  transcription::ConjunctionSpec spec;
  const std::string frame = c.Has("frame") ? c.Choice("frame", {"local", "serra_lvlh"}) : "local";
  const Eigen::Matrix3d to_local =
      frame == "serra_lvlh" ? transcription::SerraLvlhToLocal() : Eigen::Matrix3d::Identity();

  JsonObject sec = c.Object("secondary");
  spec.state_time_s = sec.OptionalNumber("time_s").value_or(s->start_s);
  spec.secondary_state.resize(6);
  spec.secondary_state << to_local * ReadVector3(sec, "position_m"),
      to_local * ReadVector3(sec, "velocity_m_s");
  sec.Finish();

  Eigen::MatrixXd t6 = Eigen::MatrixXd::Zero(6, 6);
  t6.topLeftCorner(3, 3) = to_local;
  t6.bottomRightCorner(3, 3) = to_local;
  const Eigen::MatrixXd cov = c.NumberMatrix("covariance", 6, 6);
  spec.covariance = t6 * cov * t6.transpose();
  if (c.Has("covariance_repair")) {
    spec.repair = transcription::ParseCovarianceRepair(
        c.Choice("covariance_repair", {"none", "clip_eigenvalues"}));
  }
  spec.radius_m = c.Number("radius_m", Bound::kPositive);

  c.ExactlyOneOf({"instantaneous_threshold", "risk_threshold"}, /*required=*/true);
  JsonObject checks = c.Object("checks");
  ParseChecks(checks, &spec);
  if (c.Has("instantaneous_threshold")) {
    spec.instantaneous_threshold = c.Number("instantaneous_threshold", Bound::kPositive);
    if (c.Has("risk_t0_s")) c.Fail("risk_t0_s", "is only used with risk_threshold");
  } else {
    const double risk = c.Number("risk_threshold", Bound::kPositive);
    const double t0 = c.OptionalNumber("risk_t0_s", Bound::kPositive).value_or(1.0);
    const double a = std::isnan(spec.check_start_s) ? s->problem.grid.front() : spec.check_start_s;
    const double b = std::isnan(spec.check_end_s) ? s->problem.grid.back() : spec.check_end_s;
    if (!(risk < 1.0)) c.Fail("risk_threshold", "must be in (0, 1), got " + FormatNumber(risk));
    spec.instantaneous_threshold = Wrap(c.FieldPath("risk_threshold"), [&] {
      return transcription::InstantaneousThreshold(risk, b - a, t0);
    });
  }
  ParsePolytope(c, to_local, &spec);
  if (auto budget = c.OptionalNumber("cost_budget", Bound::kPositive)) spec.cost_budget = *budget;

  transcription::ConjunctionCheckOptions check;
  if (c.Has("verification")) ParseVerification(c.Object("verification"), &check);
  if (c.Has("solve")) ParseSolveStrategy(c.Object("solve"), &s->conjunction_solve);
  c.Finish();

  std::string err;
  if (!spec.IsValid(&err)) throw ScenarioError(c.path() + ": " + err);
  if (!check.IsValid(&err)) throw ScenarioError(c.FieldPath("verification") + "." + err);
  if (!s->conjunction_solve.IsValid(&err)) throw ScenarioError(c.FieldPath("solve") + "." + err);
  s->problem.conjunction = spec;
  s->conjunction_check = check;
}

}  // namespace thrustsched::app
