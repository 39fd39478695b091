// The shipped LEO rendezvous with the Schweighart-Sedwick J2 model
// (data/scenarios/leo_ss_j2_rendezvous.json) end to end: the `thrustsched`
// binary solves it to proven optimality and its checker passes; the optimum
// is at least a lower bound computed here from the discretised model alone
// (weak duality, no solver), and equals the HCW model's optimum for the same
// orbit, as the J2 terms move a 500 m rendezvous by centimetres over one
// orbit while one slot of one thruster is 24 mm/s.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include "app/scenario.h"
#include "dynamics/discretisation.h"
#include "tests/app/cli_runner.h"

namespace thrustsched::testing {
namespace {

using nlohmann::json;

const std::string kScenario =
    std::string(THRUSTSCHED_DATA_DIR) + "/scenarios/leo_ss_j2_rendezvous.json";

// Weak-duality lower bound on the L1 cost. For any lambda, the final state
// x_N = Phi x_0 + d + sum_j G_j u_j (G_j: the ZOH response at t_N of
// thruster column j on one interval, transported) satisfies
//   lambda' (x_N - Phi x_0 - d) <= max_j (lambda' G_j)_+ sum_j u_j,
// and x_N in the box gives lambda' x_N >= lambda' target - |lambda|' tol;
// each unit of u costs L1Factor * step. Any lambda gives a valid bound; the
// best one found by a seeded random search is used.
double DualLowerBound(const app::Scenario& s) {
  const dynamics::DiscreteModel dm =
      dynamics::Discretize(*s.problem.model, s.problem.thrusters.AccelerationMatrix(),
                           s.problem.grid, dynamics::DiscretizationOptions{});
  const int n = dm.num_states(), m = dm.num_inputs(), steps = dm.num_intervals();
  Eigen::VectorXd free = s.problem.initial_state;  // x_N with no thrust
  Eigen::MatrixXd columns(n, m * steps);           // G_j, all intervals
  for (int k = 0; k < steps; ++k) {
    free = dm.phi[k] * free + dm.drift[k];
    columns = dm.phi[k] * columns;
    columns.middleCols(k * m, m) = dm.gamma[k];
  }
  const double slot_cost = s.problem.thrusters.L1Factor(0) * s.step_s;
  const Eigen::VectorXd scale = s.problem.model->state_scale();
  const auto slots = [&](const Eigen::VectorXd& lambda) {  // lower bound on sum u
    const double need = lambda.dot(s.problem.terminal.target - free) -
                        lambda.cwiseAbs().dot(s.problem.terminal.tolerance);
    const double gain = (lambda.transpose() * columns).maxCoeff();
    return need > 0.0 && gain > 0.0 ? need / gain : 0.0;
  };
  // Random directions (in scaled units), then a random-step hill climb from the best.
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  const auto random_direction = [&] {
    Eigen::VectorXd v(n);
    for (int i = 0; i < n; ++i) v[i] = normal(rng) / scale[i];
    return v;
  };
  Eigen::VectorXd best = random_direction();
  for (int trial = 0; trial < 5000; ++trial) {
    const Eigen::VectorXd lambda = random_direction();
    if (slots(lambda) > slots(best)) best = lambda;
  }
  for (double step = 0.3; step > 1e-3; step *= 0.7) {
    for (int trial = 0; trial < 500; ++trial) {
      const Eigen::VectorXd lambda = best + step * best.norm() * random_direction().normalized();
      if (slots(lambda) > slots(best)) best = lambda;
    }
  }
  // sum u is an integer (on-off binaries).
  return slot_cost * std::ceil(slots(best) - 1e-9);
}

TEST(SchweighartSedwickCli, LeoRendezvousIsSolvedCheckedAndAboveItsBound) {
  const app::Scenario s = app::LoadScenario(kScenario);
  ASSERT_EQ(s.model_type, app::ModelType::kSchweighartSedwick);
  for (int i = 0; i < s.problem.thrusters.size(); ++i) {
    ASSERT_DOUBLE_EQ(s.problem.thrusters.L1Factor(i), 2e-4);  // 0.02 N / 100 kg, ideal6
  }
  const double bound = DualLowerBound(s);
  std::printf("dual lower bound %.4f m/s\n", bound);

  const std::string dir = TempDir("leo_ss");
  RunResult r = RunCli({"solve", kScenario, "--out", dir + "/ss", "--no-plots", "--no-report"});
  ASSERT_EQ(r.exit_code, 0) << r.Describe();
  const json summary = ReadJson(dir + "/ss/summary.json");
  EXPECT_EQ(summary["status"], "optimal");
  EXPECT_TRUE(summary["check"]["passed"].get<bool>());
  EXPECT_TRUE(summary["check"]["terminal_ok"].get<bool>());
  const double objective = summary["objective"].get<double>();
  // Measured: 0.192 m/s (8 slots of 24 mm/s), bound 0.144 m/s (6 slots).
  EXPECT_GE(objective, bound - 1e-9);
  EXPECT_GE(bound, 0.7 * objective);  // the bound is not vacuous
  EXPECT_NEAR(objective, 0.192, 1e-9);

  // The same rendezvous with HCW at n = sqrt(mu / r^3): the same optimum.
  json hcw = ReadJson(kScenario);
  const double r_m = 6378137.0 + 650e3;
  hcw["model"] = {{"type", "hcw"},
                  {"mean_motion_rad_s", std::sqrt(3.986004418e14 / (r_m * r_m * r_m))}};
  WriteFile(dir + "/hcw.json", hcw.dump());
  RunResult rh =
      RunCli({"solve", dir + "/hcw.json", "--out", dir + "/hcw", "--no-plots", "--no-report"});
  ASSERT_EQ(rh.exit_code, 0) << rh.Describe();
  const json hcw_summary = ReadJson(dir + "/hcw/summary.json");
  EXPECT_EQ(hcw_summary["status"], "optimal");
  EXPECT_NEAR(hcw_summary["objective"].get<double>(), objective, 1e-9);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace thrustsched::testing
