// thrustsched.dynamics: the shipped linear models, thruster sets and the
// discretisation schemes, with numpy arrays in and out.
//
//   hcw = _core.dynamics.Hcw(7.2921159e-5)
//   thr = _core.dynamics.ThrusterSet.preset("ideal6", 0.265, 4850, 2005)
//   d = hcw.discretise(_core.dynamics.uniform_grid(0, 86400, 288), thr, scheme="exact_zoh")
//   d["phi"].shape == (288, 6, 6); d["gamma"].shape == (288, 6, 6); d["drift"].shape == (288, 6)
#include <memory>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "convert.h"
#include "dynamics/discretisation.h"
#include "dynamics/geo_model.h"
#include "dynamics/linear_model.h"
#include "dynamics/models.h"
#include "dynamics/thrusters.h"

namespace thrustsched::python {

namespace {

using dynamics::LinearModel;
using ModelPtr = std::shared_ptr<LinearModel>;

py::array_t<double> VectorArray(const Eigen::VectorXd& v) {
  return py::array_t<double>(v.size(), v.data());
}

// Input columns for the discretisation: a ThrusterSet (its 3 x m acceleration
// matrix), a 3 x k array, or None (the identity: Gamma is the discretised B).
Eigen::MatrixXd InputColumns(const LinearModel& model, const py::object& inputs) {
  if (inputs.is_none()) return Eigen::MatrixXd::Identity(model.num_inputs(), model.num_inputs());
  if (py::isinstance<dynamics::ThrusterSet>(inputs)) {
    return inputs.cast<const dynamics::ThrusterSet&>().AccelerationMatrix();
  }
  return ToMatrix(inputs.cast<DoubleArray>(), "input_matrix", model.num_inputs(), -1);
}

py::dict Discretize(const LinearModel& model, const std::vector<double>& grid_s,
                    const py::object& inputs, const std::string& scheme, int rk4_substeps,
                    double reference_tolerance) {
  dynamics::DiscretizationOptions o;
  o.scheme = dynamics::ParseScheme(scheme);
  o.rk4_substeps = rk4_substeps;
  o.reference_tolerance = reference_tolerance;
  const Eigen::MatrixXd u = InputColumns(model, inputs);
  dynamics::DiscreteModel dm;
  {
    py::gil_scoped_release nogil;
    dm = dynamics::Discretize(model, u, grid_s, o);
  }
  py::dict d;
  d["phi"] = StackMatrices(dm.phi);
  d["gamma"] = StackMatrices(dm.gamma);
  d["drift"] = StackVectors(dm.drift);
  d["grid_s"] = py::array_t<double>(static_cast<py::ssize_t>(dm.grid.size()), dm.grid.data());
  return d;
}

}  // namespace

void BindDynamics(py::module_& m) {
  m.def("uniform_grid", &dynamics::UniformGrid, py::arg("t0_s"), py::arg("t1_s"),
        py::arg("num_intervals"), "N equal intervals on [t0, t1]: the N + 1 node times (s).");
  m.def(
      "schemes",
      [] {
        std::vector<std::string> out;
        for (dynamics::Scheme s : dynamics::AllSchemes()) out.emplace_back(dynamics::ToString(s));
        return out;
      },
      "Names of the discretisation schemes (dynamics/discretisation.h).");

  py::class_<LinearModel, ModelPtr>(
      m, "LinearModel",
      "A continuous-time linear model x' = A(t) x + B(t) a + d(t), y = C(t) x (SI units).")
      .def_property_readonly("name", [](const LinearModel& x) { return std::string(x.name()); })
      .def_property_readonly("num_states", &LinearModel::num_states)
      .def_property_readonly("num_inputs", &LinearModel::num_inputs)
      .def_property_readonly("num_outputs", &LinearModel::num_outputs)
      .def_property_readonly("is_time_invariant", &LinearModel::is_time_invariant)
      .def_property_readonly("state_names", &LinearModel::state_names)
      .def_property_readonly("output_names", &LinearModel::output_names)
      .def_property_readonly(
          "state_scale", [](const LinearModel& x) { return VectorArray(x.state_scale()); },
          "Characteristic magnitude of each state component (SI).")
      .def_property_readonly("time_scale_s", &LinearModel::time_scale)
      .def(
          "evaluate",
          [](const LinearModel& x, double t_s) {
            const dynamics::ModelMatrices mm = x.Evaluate(t_s);
            return py::make_tuple(mm.a, mm.b, VectorArray(mm.d));
          },
          py::arg("t_s"), "(A, B, d) at t (s since the model epoch).")
      .def(
          "output_matrix",
          [](const LinearModel& x, double t_s) { return Eigen::MatrixXd(x.EvaluateOutput(t_s).c); },
          py::arg("t_s"), "C at t.")
      .def("discretise", &Discretize, py::arg("grid_s"), py::arg("inputs") = py::none(),
           py::arg("scheme") = "exact_zoh", py::arg("rk4_substeps") = 1,
           py::arg("reference_tolerance") = 1e-12,
           "x_{j+1} = Phi_j x_j + Gamma_j u_j + drift_j on the grid, with u_j held on each "
           "interval. inputs: a ThrusterSet (Gamma's columns = thrusters), a 3 x k array of "
           "acceleration columns (m/s^2), or None (the identity). Returns a dict of arrays "
           "phi [N, n, n], gamma [N, n, k], drift [N, n], grid_s [N + 1].")
      // The published name above stays; this one matches the C++ API's -ize spelling.
      .def("discretize", &Discretize, py::arg("grid_s"), py::arg("inputs") = py::none(),
           py::arg("scheme") = "exact_zoh", py::arg("rk4_substeps") = 1,
           py::arg("reference_tolerance") = 1e-12, "Same as discretise.");

  py::class_<dynamics::DoubleIntegrator1d, LinearModel,
             std::shared_ptr<dynamics::DoubleIntegrator1d>>(m, "DoubleIntegrator1d",
                                                            "x' = v, v' = a (state [x_m, v_m_s]).")
      .def(py::init<double, double>(), py::arg("time_scale_s") = 1.0,
           py::arg("length_scale_m") = 1.0);
  py::class_<dynamics::DoubleIntegrator3d, LinearModel,
             std::shared_ptr<dynamics::DoubleIntegrator3d>>(
      m, "DoubleIntegrator3d", "r' = v, v' = a in R^3 (state [x, y, z, vx, vy, vz], m and m/s).")
      .def(py::init<double, double>(), py::arg("time_scale_s") = 1.0,
           py::arg("length_scale_m") = 1.0);
  py::class_<dynamics::HcwModel, LinearModel, std::shared_ptr<dynamics::HcwModel>>(
      m, "Hcw",
      "Hill-Clohessy-Wiltshire relative motion about a circular orbit (x radial, y "
      "along-track, z normal; m, m/s).")
      .def(py::init<double, double>(), py::arg("mean_motion_rad_s"),
           py::arg("length_scale_m") = 1000.0)
      .def_property_readonly("mean_motion_rad_s", &dynamics::HcwModel::mean_motion)
      .def(
          "transition_matrix",
          [](const dynamics::HcwModel& h, double tau_s) {
            return Eigen::MatrixXd(h.TransitionMatrix(tau_s));
          },
          py::arg("tau_s"), "Phi(tau) = exp(A tau).");
  py::class_<dynamics::YamanakaAnkersenModel, LinearModel,
             std::shared_ptr<dynamics::YamanakaAnkersenModel>>(
      m, "YamanakaAnkersen", "Linearised relative motion about an elliptic orbit.")
      .def(py::init<double, double, double, double, double>(), py::arg("semi_major_axis_m"),
           py::arg("eccentricity"), py::arg("mu_m3_s2") = dynamics::YamanakaAnkersenModel::kEarthMu,
           py::arg("true_anomaly_at_epoch_rad") = 0.0, py::arg("length_scale_m") = 1000.0);
  py::class_<dynamics::GeoLinearModel, LinearModel, std::shared_ptr<dynamics::GeoLinearModel>>(
      m, "Geo",
      "Linearised GEO station-keeping model (state [da_m, ex, ey, ix, iy, dl_rad], "
      "outputs [dr_m, lat_rad, lon_rad]).")
      .def(py::init([](const py::kwargs& kwargs) {
             dynamics::GeoModelOptions o;
             for (const auto& item : kwargs) {
               const std::string key = py::str(item.first);
               py::handle v = item.second;
               std::string text;
               if (py::isinstance<py::bool_>(v)) {
                 text = v.cast<bool>() ? "true" : "false";
               } else {
                 text = py::str(v);
               }
               o.Set(key, text);
             }
             std::string err;
             if (!o.IsValid(&err)) throw std::invalid_argument(err);
             return std::make_shared<dynamics::GeoLinearModel>(o);
           }),
           "Keyword arguments: the GeoModelOptions fields (station_longitude_deg, epoch, j2, "
           "tesseral, sun, moon, srp, gravity_degree, area_to_mass_m2_kg, reflectivity_cr).");

  py::class_<dynamics::ThrusterSet>(
      m, "ThrusterSet",
      "On-off thrusters: names, unit directions in RTN, thrust (N), mass (kg), Isp (s).")
      .def(py::init([](const std::vector<std::string>& names, const DoubleArray& directions_rtn,
                       double thrust_n, double mass_kg, double isp_s) {
             const Eigen::MatrixXd d =
                 ToMatrix(directions_rtn, "directions_rtn", static_cast<int>(names.size()), 3);
             std::vector<dynamics::Thruster> t;
             for (size_t i = 0; i < names.size(); ++i) {
               dynamics::Thruster x;
               x.name = names[i];
               x.direction = d.row(static_cast<Eigen::Index>(i)).transpose();
               t.push_back(x);
             }
             return dynamics::ThrusterSet(t, thrust_n, mass_kg, isp_s);
           }),
           py::arg("names"), py::arg("directions_rtn"), py::arg("thrust_n"), py::arg("mass_kg"),
           py::arg("isp_s"))
      .def_static("preset", &dynamics::ThrusterSet::FromPreset, py::arg("preset"),
                  py::arg("thrust_n"), py::arg("mass_kg"), py::arg("isp_s"),
                  py::arg("theta_deg") = 63.64, py::arg("alpha_deg") = 7.03,
                  "\"ideal6\" (+R, +T, +N, -R, -T, -N) or \"anzel4\" (NE, SE, NW, SW).")
      .def_property_readonly("names", &dynamics::ThrusterSet::names)
      .def_property_readonly("size", &dynamics::ThrusterSet::size)
      .def("__len__", &dynamics::ThrusterSet::size)
      .def_property_readonly("thrust_n", &dynamics::ThrusterSet::thrust_n)
      .def_property_readonly("mass_kg", &dynamics::ThrusterSet::mass_kg)
      .def_property_readonly("isp_s", &dynamics::ThrusterSet::isp_s)
      .def_property_readonly("acceleration_m_s2", &dynamics::ThrusterSet::acceleration)
      .def_property_readonly("mass_flow_kg_s", &dynamics::ThrusterSet::MassFlow)
      .def_property_readonly("directions_rtn",
                             [](const dynamics::ThrusterSet& s) {
                               Eigen::MatrixXd d(s.size(), 3);
                               for (int i = 0; i < s.size(); ++i)
                                 d.row(i) = s.thruster(i).direction.transpose();
                               return d;
                             })
      .def_property_readonly("enabled",
                             [](const dynamics::ThrusterSet& s) {
                               std::vector<bool> e;
                               for (const auto& t : s.thrusters()) e.push_back(t.enabled);
                               return e;
                             })
      .def_property_readonly("acceleration_matrix", &dynamics::ThrusterSet::AccelerationMatrix,
                             "3 x m: column i = (F/m) d_i, m/s^2 in RTN.")
      .def_property_readonly(
          "l1_factors",
          [](const dynamics::ThrusterSet& s) {
            Eigen::VectorXd v(s.size());
            for (int i = 0; i < s.size(); ++i) v[i] = s.L1Factor(i);
            return VectorArray(v);
          },
          "Thesis L1 cost per second on, (F/m) ||d_i||_1 (m/s^2).")
      .def("index", &dynamics::ThrusterSet::IndexOf, py::arg("name"))
      .def("subset", &dynamics::ThrusterSet::Subset, py::arg("names"))
      .def("disable", &dynamics::ThrusterSet::Disable, py::arg("names"))
      .def("__repr__", [](const dynamics::ThrusterSet& s) {
        std::string n;
        for (const auto& x : s.names()) n += (n.empty() ? "" : ", ") + x;
        return "ThrusterSet([" + n + "], thrust_n=" + std::to_string(s.thrust_n()) +
               ", mass_kg=" + std::to_string(s.mass_kg()) + ", isp_s=" + std::to_string(s.isp_s()) +
               ")";
      });
}

}  // namespace thrustsched::python
