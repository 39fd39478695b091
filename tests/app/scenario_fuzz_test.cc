// Fuzz-style robustness test of the scenario path of the real binary:
// several hundred deterministic mutations (deleted keys, wrong types,
// zero/negative/huge/non-integer numbers, unknown keys, broken JSON, NaN and
// overflowing literals, duplicate keys) of four valid scenarios are run
// through `thrustsched validate` (parse + validate + build, the path of
// `solve`). Never a crash or a hang; never exit 0 on a file that is invalid
// by construction; mutations that stay valid may pass or fail cleanly (exit
// 2). A sample of the mutations that stay valid is also solved end to end.
#include <cmath>
#include <filesystem>
#include <random>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "tests/app/cli_runner.h"

namespace thrustsched::testing {
namespace {

using nlohmann::json;

std::vector<json> Bases() {
  return {
      json::parse(R"({
        "name": "fuzz_hcw",
        "description": "HCW base with most optional sections",
        "model": {"type": "hcw", "mean_motion_rad_s": 7.2921159e-5, "length_scale_m": 1000},
        "spacecraft": {"mass_kg": 4850, "isp_s": 2005, "thrust_n": 0.265,
                       "thrusters": {"preset": "ideal6"}, "disabled": ["+R"]},
        "initial_state": {"hcw_position_m": [1000, 0, 0], "hcw_velocity_m_s": [0, 0, 0]},
        "horizon": {"start_s": 0, "duration_s": 21600, "step_s": 1800},
        "window": {"half_width_m": 36800, "enforce_from_s": 0, "soft": true, "soft_penalty": 100,
                   "intersample_points": 1},
        "operations": {"max_simultaneous": 1, "min_burn_s": 1800, "min_off_same_s": 3600,
                       "min_gap_other_s": 1800, "max_burn_s": 7200, "max_burns_per_thruster": 3,
                       "allow_burn_across_end": false},
        "history": {"-T": {"off_for_s": 600}},
        "forced_off": [{"thruster": "+N", "start_s": 0, "end_s": 3600}],
        "terminal": {"type": "state_box", "hcw_position_m": [0, 0, 0], "hcw_velocity_m_s": [0, 0, 0],
                     "tolerance": [50000, 50000, 50000, 10, 10, 10]},
        "objective": {"kind": "l1", "burn_start_penalty": 0.0001},
        "discretisation": {"scheme": "exact_zoh", "rk4_substeps": 2},
        "transcription": {"formulation": "sparse", "encoding": "tight", "scale": true},
        "solver": {"time_limit_s": 2, "relative_gap": 0.01, "threads": 1, "random_seed": 3,
                   "absolute_gap": 1e-9, "log_level": 0, "presolve": true},
        "check": {"samples_per_interval": 2, "window_tolerance": 40, "include_intersample": false}
      })"),
      json::parse(R"({
        "name": "fuzz_geo",
        "model": {"type": "geo", "station_longitude_deg": 118, "epoch": "2034-01-01T00:00:00Z",
                  "perturbations": ["j2", "tesseral", "sun", "moon", "srp"],
                  "area_to_mass_m2_kg": 0.0227, "reflectivity_cr": 1.2, "gravity_degree": 4},
        "spacecraft": {"mass_kg": 4850, "isp_s": 2005, "thrust_n": 0.265,
                       "thrusters": {"preset": "anzel4", "theta_deg": 63.64, "alpha_deg": 7.03},
                       "disabled": ["SE"]},
        "initial_state": {"relative_equinoctial": [0, 0, 0, 0, 0, 0.0001]},
        "horizon": {"duration_s": 21600, "step_s": 1800},
        "window": {"half_width_deg": 0.05, "enforce_from_s": 0},
        "operations": {"max_simultaneous": 1, "min_burn_s": 300, "min_off_same_s": 1200,
                       "min_gap_other_s": 300},
        "terminal": {"type": "station_keeping", "facets_out_of_plane": 8, "facets_cone_plus": 8,
                     "facets_cone_minus": 8, "lookahead_s": [0, 21600], "margin": 0.05},
        "objective": "propellant",
        "discretisation": {"scheme": "frozen_mid"},
        "solver": {"time_limit_s": 2, "relative_gap": 0.05, "threads": 1},
        "check": {"nonlinear": false}
      })"),
      json::parse(R"({
        "name": "fuzz_ya",
        "model": {"type": "yamanaka_ankersen", "semi_major_axis_m": 24616000, "eccentricity": 0.73074,
                  "true_anomaly_at_epoch_rad": 0.3141592653589793, "mu_m3_s2": 3.986004418e14},
        "spacecraft": {"mass_kg": 1000, "isp_s": 300, "thrust_n": 10,
                       "thrusters": {"preset": "ideal6", "use": ["+N", "-N"]}},
        "initial_state": {"hcw_position_m": [0, 0, -10000], "hcw_velocity_m_s": [0, 0, 3]},
        "horizon": {"end_true_anomaly_rad": 5.2, "num_intervals": 40},
        "input_mode": "impulsive",
        "max_impulse_m_s": 100,
        "terminal": {"type": "fixed_state", "state": [0, 0, 0, 0, 0, 0]},
        "objective": "l1",
        "solver": {"time_limit_s": 2}
      })"),
      json::parse(R"({
        "name": "fuzz_di",
        "model": {"type": "double_integrator", "time_scale_s": 1, "length_scale_m": 1},
        "spacecraft": {"mass_kg": 1, "isp_s": 300, "thrust_n": 8,
                       "thrusters": {"custom": [{"name": "+X", "direction_rtn": [1, 0, 0]},
                                                {"name": "-X", "direction_rtn": [-1, 0, 0]}]}},
        "initial_state": {"state": [0, 0, 0, 0, 0, 0]},
        "horizon": {"duration_s": 1, "num_intervals": 20},
        "operations": {"max_simultaneous": 1},
        "terminal": {"type": "fixed_state", "hcw_position_m": [1, 0, 0]},
        "solver": {"time_limit_s": 2, "relative_gap": 1e-6}
      })"),
  };
}

// Fields whose zero or negative value is invalid, and those only negative is invalid.
const std::set<std::string> kPositive = {"mean_motion_rad_s",
                                         "length_scale_m",
                                         "time_scale_s",
                                         "semi_major_axis_m",
                                         "mu_m3_s2",
                                         "mass_kg",
                                         "isp_s",
                                         "thrust_n",
                                         "duration_s",
                                         "step_s",
                                         "num_intervals",
                                         "half_width_m",
                                         "half_width_deg",
                                         "soft_penalty",
                                         "time_limit_s",
                                         "progress_interval_s",
                                         "max_impulse_m_s",
                                         "max_burn_s",
                                         "rk4_substeps",
                                         "reference_tolerance",
                                         "propagation_tolerance",
                                         "max_simultaneous",
                                         "threads",
                                         "facets_out_of_plane",
                                         "facets_cone_plus",
                                         "facets_cone_minus",
                                         "on_for_s"};
const std::set<std::string> kNonNegative = {
    "min_burn_s",       "min_off_same_s",       "min_gap_other_s",        "relative_gap",
    "absolute_gap",     "area_to_mass_m2_kg",   "reflectivity_cr",        "eccentricity",
    "window_tolerance", "samples_per_interval", "intersample_points",     "off_for_s",
    "margin",           "burn_start_penalty",   "max_burns_per_thruster", "random_seed",
    "log_level",        "gravity_degree"};
// Keys whose deletion must be rejected (required where they appear in the bases).
const std::set<std::string> kRequired = {"name",
                                         "model",
                                         "type",
                                         "mean_motion_rad_s",
                                         "station_longitude_deg",
                                         "epoch",
                                         "semi_major_axis_m",
                                         "eccentricity",
                                         "spacecraft",
                                         "mass_kg",
                                         "isp_s",
                                         "thrust_n",
                                         "thrusters",
                                         "preset",
                                         "custom",
                                         "initial_state",
                                         "hcw_position_m",
                                         "relative_equinoctial",
                                         "state",
                                         "horizon",
                                         "duration_s",
                                         "step_s",
                                         "num_intervals",
                                         "end_true_anomaly_rad",
                                         "half_width_m",
                                         "half_width_deg",
                                         "direction_rtn",
                                         "thruster",
                                         "start_s",
                                         "end_s",
                                         "tolerance",
                                         "kind"};
// Arrays of fixed length: removing an element is invalid.
const std::set<std::string> kFixedArrays = {"hcw_position_m", "hcw_velocity_m_s",
                                            "state",          "relative_equinoctial",
                                            "direction_rtn",  "tolerance"};

struct Mutation {
  std::string description;
  std::string text;
  bool must_reject;
};

// Every (pointer, parent key) in the document.
void CollectPaths(const json& j, const json::json_pointer& p,
                  std::vector<json::json_pointer>* out) {
  if (!p.empty()) out->push_back(p);
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) CollectPaths(it.value(), p / it.key(), out);
  } else if (j.is_array()) {
    for (size_t i = 0; i < j.size(); ++i) CollectPaths(j[i], p / i, out);
  }
}

// The object key that names a value: for array elements, the array's key.
std::string FieldKey(const json::json_pointer& p) {
  json::json_pointer q = p;
  while (!q.empty()) {
    const std::string last = q.back();
    const bool index = !last.empty() && last.find_first_not_of("0123456789") == std::string::npos;
    if (!index) return last;
    q.pop_back();
  }
  return "";
}

bool IsArrayElement(const json::json_pointer& p) {
  const std::string last = p.back();
  return !last.empty() && last.find_first_not_of("0123456789") == std::string::npos;
}

std::vector<Mutation> MakeMutations(const json& base, std::mt19937* rng, int count) {
  std::vector<json::json_pointer> paths;
  CollectPaths(base, json::json_pointer(), &paths);
  std::vector<json::json_pointer> numbers, objects;
  for (const auto& p : paths) {
    if (base.at(p).is_number()) numbers.push_back(p);
    if (base.at(p).is_object()) objects.push_back(p);
  }
  objects.push_back(json::json_pointer());
  auto pick = [rng](const auto& v) {
    return v[std::uniform_int_distribution<size_t>(0, v.size() - 1)(*rng)];
  };
  std::vector<Mutation> out;
  const std::string text = base.dump(2);
  for (int k = 0; k < count; ++k) {
    json j = base;
    Mutation m;
    const int kind = std::uniform_int_distribution<int>(0, 11)(*rng);
    switch (kind) {
      case 0: {  // delete a key or array element
        const json::json_pointer p = pick(paths);
        const std::string key = FieldKey(p);
        const bool element = IsArrayElement(p);
        if (element) {
          j.at(p.parent_pointer()).erase(std::stoul(p.back()));
        } else {
          j.at(p.parent_pointer()).erase(p.back());
        }
        m.description = "delete " + p.to_string();
        m.must_reject = element ? kFixedArrays.count(key) > 0 : kRequired.count(key) > 0;
        break;
      }
      case 1:
      case 2: {  // wrong type
        const json::json_pointer p = pick(paths);
        const json& v = base.at(p);
        static const std::vector<json> kinds = {json("text"),  json(true),     json(nullptr),
                                                json::array(), json::object(), json(7)};
        json repl;
        do {
          repl = pick(kinds);
        } while (std::string(repl.type_name()) == v.type_name() ||
                 (repl.is_number() && v.is_number()));
        j.at(p) = repl;
        m.description = "type of " + p.to_string() + " -> " + repl.dump();
        // "objective" accepts a string or an object; a tolerance entry accepts null.
        const std::string key = FieldKey(p);
        m.must_reject = !(key == "objective" && (repl.is_string() || repl.is_object())) &&
                        !(key == "tolerance" && IsArrayElement(p) && repl.is_null()) &&
                        !(key == "description" && repl.is_string());
        if (key == "objective" && repl.is_string()) m.must_reject = true;  // "text" is not a kind
        break;
      }
      case 3: {  // zero
        const json::json_pointer p = pick(numbers);
        j.at(p) = 0;
        m.description = p.to_string() + " = 0";
        m.must_reject = kPositive.count(FieldKey(p)) > 0;
        break;
      }
      case 4: {  // negative
        const json::json_pointer p = pick(numbers);
        j.at(p) = -std::abs(base.at(p).get<double>()) - 1.0;
        m.description = p.to_string() + " negative";
        const std::string key = FieldKey(p);
        m.must_reject = kPositive.count(key) > 0 || kNonNegative.count(key) > 0;
        break;
      }
      case 5: {  // huge or tiny
        const json::json_pointer p = pick(numbers);
        const double v = std::uniform_int_distribution<int>(0, 1)(*rng) ? 1e300 : 1e-300;
        j.at(p) = v;
        m.description = p.to_string() + " = " + json(v).dump();
        m.must_reject = false;  // may be valid (e.g. a huge mass)
        break;
      }
      case 6: {  // non-integer
        const json::json_pointer p = pick(numbers);
        j.at(p) = base.at(p).get<double>() + 0.5;
        m.description = p.to_string() + " + 0.5";
        m.must_reject = false;
        break;
      }
      case 7: {  // unknown key in some object
        const json::json_pointer p = pick(objects);
        j.at(p)["zz_unknown_field"] = 1;
        m.description = "unknown key in " + p.to_string();
        m.must_reject = true;
        break;
      }
      case 8: {  // truncated JSON text
        const size_t cut = std::uniform_int_distribution<size_t>(0, text.size() - 2)(*rng);
        m.text = text.substr(0, cut);
        m.description = "truncated at " + std::to_string(cut);
        m.must_reject = true;
        break;
      }
      case 9: {  // NaN / Infinity / overflowing literal instead of a number
        const json::json_pointer p = pick(numbers);
        static const std::vector<std::string> lits = {"NaN",   "Infinity", "-Infinity",
                                                      "1e999", "-1e999",   "nan"};
        const std::string lit = pick(lits);
        const std::string marker = "\"__number_marker__\"";
        j.at(p) = "__number_marker__";
        m.text = j.dump(2);
        m.text.replace(m.text.find(marker), marker.size(), lit);
        m.description = p.to_string() + " = " + lit;
        m.must_reject = true;
        break;
      }
      case 10: {  // duplicate key
        const std::string dump = text;
        const size_t pos = dump.find("\"name\"");
        m.text = dump.substr(0, pos) + "\"name\": \"dup\",\n  " + dump.substr(pos);
        m.description = "duplicate name";
        m.must_reject = true;
        break;
      }
      case 11: {  // random byte flipped (may stay valid inside a string)
        m.text = text;
        const size_t at = std::uniform_int_distribution<size_t>(0, text.size() - 1)(*rng);
        const char c = "{}[]\",:x0-."[std::uniform_int_distribution<int>(0, 10)(*rng)];
        m.text[at] = c;
        m.description = "byte " + std::to_string(at) + " -> " + std::string(1, c);
        m.must_reject = false;
        break;
      }
    }
    if (m.text.empty()) m.text = j.dump(2);
    out.push_back(m);
  }
  return out;
}

TEST(ScenarioFuzz, MutatedScenariosNeverCrashNorPassWhenInvalid) {
  const std::string dir = TempDir("fuzz");
  std::mt19937 rng(20240605);
  int runs = 0, rejected = 0, must = 0, solved = 0;
  std::vector<std::string> valid_files;
  const std::vector<json> bases = Bases();
  // The bases themselves are valid.
  for (size_t b = 0; b < bases.size(); ++b) {
    const std::string f = dir + "/base" + std::to_string(b) + ".json";
    WriteFile(f, bases[b].dump(2));
    const RunResult r = RunCli({"validate", f}, 120);
    ASSERT_EQ(r.exit_code, 0) << "base " << b << r.Describe();
  }
  const int per_base = 120;
  for (size_t b = 0; b < bases.size(); ++b) {
    const std::vector<Mutation> muts = MakeMutations(bases[b], &rng, per_base);
    for (size_t k = 0; k < muts.size(); ++k) {
      const Mutation& m = muts[k];
      const std::string f = dir + "/m" + std::to_string(b) + "_" + std::to_string(k) + ".json";
      WriteFile(f, m.text);
      const RunResult r = RunCli({"validate", f}, 120);
      ++runs;
      SCOPED_TRACE("base " + std::to_string(b) + ", mutation " + std::to_string(k) + ": " +
                   m.description);
      ASSERT_TRUE(r.exited) << r.Describe();  // no signal, no hang
      EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 2) << r.Describe();
      if (r.exit_code == 2) {
        ++rejected;
        EXPECT_FALSE(r.err.empty());
        EXPECT_NE(r.err.find("error: "), std::string::npos) << r.err;
      }
      if (m.must_reject) {
        ++must;
        EXPECT_EQ(r.exit_code, 2) << "invalid file accepted\n" << m.text;
      }
      if (r.exit_code == 0 && !m.must_reject) valid_files.push_back(f);
      if (std::getenv("THRUSTSCHED_FUZZ_VERBOSE") != nullptr) {
        std::cout << "[" << r.exit_code << (m.must_reject ? "!" : "?") << "] " << m.description
                  << ": " << r.err.substr(0, r.err.find('\n')) << "\n";
      }
    }
  }
  // A sample of the mutations that stayed valid, solved end to end.
  for (size_t k = 0; k < valid_files.size() && solved < 12; k += 5) {
    SCOPED_TRACE(valid_files[k]);
    const RunResult r = RunCli({"solve", valid_files[k], "--out", dir + "/out" + std::to_string(k),
                                "--time-limit", "2", "--quiet", "--no-plots"},
                               120);
    ASSERT_TRUE(r.exited) << r.Describe();
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 2 || r.exit_code == 3 || r.exit_code == 4)
        << r.Describe();
    ++solved;
  }
  std::cout << runs << " mutated files: " << rejected << " rejected (" << must
            << " invalid by construction), " << solved << " valid ones solved\n";
  EXPECT_GE(runs, 300);
  EXPECT_GE(must, 150);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace thrustsched::testing
