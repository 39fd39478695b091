#include "dynamics/geo_model.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "common/error.h"
#include "common/format.h"
#include "dynamics/internal/geo_dual.h"
#include "dynamics/internal/geo_force_model.h"
#include "dynamics/internal/geo_physics.h"
#include "dynamics/time.h"

namespace thrustsched::dynamics {

using common::FormatG;

namespace {

// common::Fail with this struct's name in front of the message.
bool Fail(std::string* error, const std::string& message) {
  return common::Fail(error, "GeoModelOptions: " + message);
}

void CheckTime(double t, const char* where) {
  if (!std::isfinite(t))
    throw std::invalid_argument(std::string(where) + ": t must be finite, got " + FormatG(t, 17));
}

void CheckState(const Eigen::VectorXd& x, const char* where) {
  if (x.size() != 6) {
    throw std::invalid_argument(std::string(where) + ": state x must have 6 components, got " +
                                std::to_string(x.size()));
  }
  if (!x.allFinite()) throw std::invalid_argument(std::string(where) + ": state x must be finite");
  if (!(geo::kStationRadius + x(0) > 0.0)) {
    throw std::invalid_argument(std::string(where) + ": da_m must be > -a_mp, got " +
                                FormatG(x(0), 17));
  }
  if (!(x(1) * x(1) + x(2) * x(2) < 1.0)) {
    throw std::invalid_argument(std::string(where) + ": eccentricity |(ex, ey)| must be < 1");
  }
}

// f_L(x, t) and G(x, t) for a relative state of scalar type T.
template <typename T>
struct RateAndGauss {
  std::array<T, 6> f;
  std::array<internal::Vec3<T>, 6> g;
};

template <typename T>
RateAndGauss<T> Rate(const internal::GeoForceModel& forces, const std::array<T, 6>& x, double t) {
  const double theta = forces.Theta(t);
  const internal::GeoForceModel::Bodies bodies = forces.BodiesAt(t);
  const T a = geo::kStationRadius + x[0];
  const T k = (forces.station_longitude_rad() + theta) + x[5];
  const internal::OrbitGeometry<T> o =
      internal::Geometry<T>(a, x[1], x[2], x[3], x[4], k, geo::kEarthMu);
  const internal::Vec3<T> acc = forces.Acceleration(o.pos, theta, bodies);
  const internal::Vec3<T> a_rtn = {internal::Dot(o.u_r, acc), internal::Dot(o.u_t, acc),
                                   internal::Dot(o.w, acc)};
  RateAndGauss<T> out;
  out.g = internal::GaussMatrix(o);
  for (int i = 0; i < 6; ++i) {
    out.f[i] = out.g[i][0] * a_rtn[0] + out.g[i][1] * a_rtn[1] + out.g[i][2] * a_rtn[2];
  }
  out.f[5] += o.n - geo::kEarthRotationRate;
  return out;
}

bool ParseBool(std::string_view v, bool* out) {
  if (v == "true" || v == "1" || v == "on" || v == "yes") {
    *out = true;
    return true;
  }
  if (v == "false" || v == "0" || v == "off" || v == "no") {
    *out = false;
    return true;
  }
  return false;
}

bool ParseDouble(std::string_view v, double* out) {
  const std::string s(v);
  if (s.empty()) return false;
  char* end = nullptr;
  *out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

bool ParseInt(std::string_view v, int* out) {
  const std::string s(v);
  if (s.empty()) return false;
  char* end = nullptr;
  const long value = std::strtol(s.c_str(), &end, 10);
  if (end != s.c_str() + s.size() || value < -1000000 || value > 1000000) return false;
  *out = static_cast<int>(value);
  return true;
}

}  // namespace

// ---- GeoModelOptions ----

bool GeoModelOptions::IsValid(std::string* error) const {
  if (!std::isfinite(station_longitude_deg) || station_longitude_deg < -180.0 ||
      station_longitude_deg > 360.0) {
    return Fail(error, "station_longitude_deg must be finite and in [-180, 360], got " +
                           FormatG(station_longitude_deg, 17));
  }
  try {
    Epoch::Parse(epoch);
  } catch (const std::invalid_argument& e) {
    return Fail(error, "epoch '" + epoch + "' is invalid: " + e.what());
  }
  if (gravity_degree < 2 || gravity_degree > 4) {
    return Fail(error, "gravity_degree must be in 2..4, got " + std::to_string(gravity_degree));
  }
  if (!std::isfinite(area_to_mass_m2_kg) || area_to_mass_m2_kg < 0.0) {
    return Fail(error, "area_to_mass_m2_kg must be finite and >= 0, got " +
                           FormatG(area_to_mass_m2_kg, 17));
  }
  if (!std::isfinite(reflectivity_cr) || reflectivity_cr < 0.0 || reflectivity_cr > 2.0) {
    return Fail(
        error, "reflectivity_cr must be finite and in [0, 2], got " + FormatG(reflectivity_cr, 17));
  }
  return true;
}

std::vector<std::string> GeoModelOptions::FieldNames() {
  return {"station_longitude_deg",
          "epoch",
          "j2",
          "tesseral",
          "sun",
          "moon",
          "srp",
          "gravity_degree",
          "area_to_mass_m2_kg",
          "reflectivity_cr"};
}

void GeoModelOptions::Set(std::string_view field, std::string_view value) {
  const auto bad = [&](const char* type) {
    return std::invalid_argument("GeoModelOptions: field '" + std::string(field) + "' expects " +
                                 type + ", got '" + std::string(value) + "'");
  };
  bool* flag = nullptr;
  double* number = nullptr;
  if (field == "j2")
    flag = &j2;
  else if (field == "tesseral")
    flag = &tesseral;
  else if (field == "sun")
    flag = &sun;
  else if (field == "moon")
    flag = &moon;
  else if (field == "srp")
    flag = &srp;
  else if (field == "station_longitude_deg")
    number = &station_longitude_deg;
  else if (field == "area_to_mass_m2_kg")
    number = &area_to_mass_m2_kg;
  else if (field == "reflectivity_cr")
    number = &reflectivity_cr;
  if (flag != nullptr) {
    if (!ParseBool(value, flag)) throw bad("a boolean (true/false)");
    return;
  }
  if (number != nullptr) {
    if (!ParseDouble(value, number)) throw bad("a number");
    return;
  }
  if (field == "gravity_degree") {
    if (!ParseInt(value, &gravity_degree)) throw bad("an integer");
    return;
  }
  if (field == "epoch") {
    epoch = std::string(value);
    return;
  }
  std::string names;
  for (const std::string& n : FieldNames()) names += (names.empty() ? "" : ", ") + n;
  throw std::invalid_argument("GeoModelOptions: unknown field '" + std::string(field) +
                              "' (known: " + names + ")");
}

// ---- GeoLinearModel ----

GeoLinearModel::GeoLinearModel(const GeoModelOptions& options)
    : forces_(std::make_shared<const internal::GeoForceModel>(options)) {}

ModelMatrices GeoLinearModel::Evaluate(double t) const {
  CheckTime(t, "GeoLinearModel::Evaluate");
  using D = internal::Dual<6>;
  std::array<D, 6> x;
  for (int k = 0; k < 6; ++k) x[k] = D::Variable(0.0, k);
  const RateAndGauss<D> r = Rate(*forces_, x, t);
  ModelMatrices m;
  m.a.resize(6, 6);
  m.b.resize(6, 3);
  m.d.resize(6);
  for (int i = 0; i < 6; ++i) {
    m.d(i) = r.f[i].v;
    for (int k = 0; k < 6; ++k) m.a(i, k) = r.f[i].d[k];
    for (int j = 0; j < 3; ++j) m.b(i, j) = r.g[i][j].v;
  }
  return m;
}

OutputMatrices GeoLinearModel::EvaluateOutput(double t) const {
  CheckTime(t, "GeoLinearModel::EvaluateOutput");
  const double kappa = forces_->station_longitude_rad() + forces_->Theta(t);
  const double c = std::cos(kappa), s = std::sin(kappa), a = geo::kStationRadius,
               w = geo::kEarthRotationRate;
  OutputMatrices out;
  out.c = Eigen::MatrixXd::Zero(3, 6);
  out.c_dot = Eigen::MatrixXd::Zero(3, 6);
  out.c(0, 0) = 1.0;
  out.c(0, 1) = -a * c;
  out.c(0, 2) = -a * s;
  out.c(1, 3) = 2.0 * s;
  out.c(1, 4) = -2.0 * c;
  out.c(2, 1) = 2.0 * s;
  out.c(2, 2) = -2.0 * c;
  out.c(2, 5) = 1.0;
  out.c_dot(0, 1) = w * a * s;
  out.c_dot(0, 2) = -w * a * c;
  out.c_dot(1, 3) = 2.0 * w * c;
  out.c_dot(1, 4) = 2.0 * w * s;
  out.c_dot(2, 1) = 2.0 * w * c;
  out.c_dot(2, 2) = 2.0 * w * s;
  return out;
}

Eigen::MatrixXd GeoLinearModel::LocalPositionMap(double t) const {
  const Eigen::MatrixXd c = EvaluateOutput(t).c;
  Eigen::MatrixXd p(3, 6);
  p.row(0) = c.row(0);                        // radial
  p.row(1) = geo::kStationRadius * c.row(2);  // east: the longitude's arc
  p.row(2) = geo::kStationRadius * c.row(1);  // north: the latitude's arc
  return p;
}

std::vector<std::string> GeoLinearModel::state_names() const {
  return {"da_m", "ex", "ey", "ix", "iy", "dl_rad"};
}

std::vector<std::string> GeoLinearModel::output_names() const {
  return {"dr_m", "lat_rad", "lon_rad"};
}

Eigen::VectorXd GeoLinearModel::state_scale() const {
  const double delta = geo::kWindowHalfWidthRad;
  Eigen::VectorXd s(6);
  s << delta * geo::kStationRadius, delta, delta, delta, delta, delta;
  return s;
}

double GeoLinearModel::time_scale() const { return 1.0 / geo::kEarthRotationRate; }
double GeoLinearModel::mean_motion() const { return geo::kEarthRotationRate; }
double GeoLinearModel::station_radius_m() const { return geo::kStationRadius; }
double GeoLinearModel::station_longitude_rad() const { return forces_->station_longitude_rad(); }
const GeoModelOptions& GeoLinearModel::options() const { return forces_->options(); }
double GeoLinearModel::EarthRotationAngle(double t) const {
  CheckTime(t, "GeoLinearModel::EarthRotationAngle");
  return forces_->Theta(t);
}

Eigen::VectorXd GeoLinearModel::NaturalRate(const Eigen::VectorXd& x, double t) const {
  CheckTime(t, "GeoLinearModel::NaturalRate");
  CheckState(x, "GeoLinearModel::NaturalRate");
  std::array<double, 6> xs;
  for (int i = 0; i < 6; ++i) xs[i] = x(i);
  const RateAndGauss<double> r = Rate(*forces_, xs, t);
  Eigen::VectorXd f(6);
  for (int i = 0; i < 6; ++i) f(i) = r.f[i];
  return f;
}

Eigen::MatrixXd GeoLinearModel::InputMatrix(const Eigen::VectorXd& x, double t) const {
  CheckTime(t, "GeoLinearModel::InputMatrix");
  CheckState(x, "GeoLinearModel::InputMatrix");
  std::array<double, 6> xs;
  for (int i = 0; i < 6; ++i) xs[i] = x(i);
  const RateAndGauss<double> r = Rate(*forces_, xs, t);
  Eigen::MatrixXd g(6, 3);
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 3; ++j) g(i, j) = r.g[i][j];
  }
  return g;
}

}  // namespace thrustsched::dynamics
