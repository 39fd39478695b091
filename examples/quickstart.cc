// Quick start (verbatim in README.md): two days of HCW station keeping, thesis Table 4.1.
#include <iostream>
#include <memory>

#include "dynamics/models.h"
#include "milp/cbc_solver.h"
#include "transcription/solve.h"

int main() {
  namespace ts = thrustsched;
  ts::transcription::ScheduleProblem p;
  p.model = std::make_shared<ts::dynamics::HcwModel>(7.2921159e-5);    // GEO mean motion, rad/s
  p.thrusters = ts::dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005);  // N, kg, s
  p.grid = ts::dynamics::UniformGrid(0, 2 * 86400, 576);               // 2 days, 5-min steps
  p.initial_state = (Eigen::VectorXd(6) << 1000, 0, 0, 0, 0, 0).finished();  // m, m/s
  p.window.outputs = {1, 2};              // along-track y, normal z
  p.window.half_widths = {36800, 36800};  // m
  p.rules.min_burn_s = 300;
  p.rules.min_off_same_s = 1200;
  p.rules.min_gap_other_s = 300;
  auto solver = ts::milp::MakeCbcSolver();
  ts::transcription::ScheduleResult r = ts::transcription::SolveSchedule(p, *solver);
  std::cout << ts::milp::ToString(r.solve.status) << ": " << r.schedule.consumption_l1_m_s
            << " m/s in " << r.schedule.num_burns() << " burns; checker "
            << (r.check.operational_ok ? "ok" : "FAILED") << "\n";
  return r.has_schedule() && r.check.operational_ok ? 0 : 1;
}
