// Builds and solves a one-day HCW problem through the installed headers and
// libraries; prints the consumption (thesis Table 4.1: one 5-min slot).
#include <iostream>
#include <memory>

#include "dynamics/models.h"
#include "milp/cbc_solver.h"
#include "transcription/solve.h"

int main() {
  namespace ts = thrustsched;
  ts::transcription::ScheduleProblem p;
  p.model = std::make_shared<ts::dynamics::HcwModel>(7.2921159e-5);
  p.thrusters = ts::dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005);
  p.grid = ts::dynamics::UniformGrid(0, 86400, 288);
  p.initial_state = Eigen::VectorXd::Zero(6);
  p.initial_state[0] = 1000;
  p.window.outputs = {1, 2};
  p.window.half_widths = {36800, 36800};
  auto solver = ts::milp::MakeCbcSolver();
  const auto r = ts::transcription::SolveSchedule(p, *solver);
  std::cout << "consumer: " << ts::milp::ToString(r.solve.status) << " "
            << r.schedule.consumption_l1_m_s << " m/s\n";
  return r.has_schedule() ? 0 : 1;
}
