// Test helper: the thesis's HCW scheduling problems (Gazzino 2018, sec. 4.3.3,
// Table 4.1), shared by the transcription tests.
//
//   ScheduleProblem p = ThesisTable41(2.0);   // 2 days, optimum 0.0819 m/s
#ifndef THRUSTSCHED_TESTS_TRANSCRIPTION_THESIS_CASES_H_
#define THRUSTSCHED_TESTS_TRANSCRIPTION_THESIS_CASES_H_

#include <cmath>
#include <memory>

#include "dynamics/discretisation.h"
#include "dynamics/models.h"
#include "transcription/problem.h"

namespace thrustsched::transcription {

/// HCW at GEO (thesis mean motion), ideal six thrusters, 4850 kg, 0.265 N,
/// X0 = [1 km, 0, 0, 0, 0, 0], 5-min grid over `days`, window +-36.8 km on
/// y and z, operations 5 / 20 / 5 min, L1 objective.
inline ScheduleProblem ThesisTable41(double days) {
  ScheduleProblem p;
  p.model = std::make_shared<dynamics::HcwModel>(7.2921159e-5);
  p.thrusters = dynamics::ThrusterSet::Ideal6(0.265, 4850, 2005);
  p.grid = dynamics::UniformGrid(0.0, days * 86400.0, static_cast<int>(std::lround(days * 288)));
  p.initial_state = Eigen::VectorXd::Zero(6);
  p.initial_state[0] = 1000.0;
  p.window.outputs = {1, 2};
  p.window.half_widths = {36800.0, 36800.0};
  p.rules.min_burn_s = 300;
  p.rules.min_off_same_s = 1200;
  p.rules.min_gap_other_s = 300;
  p.objective.kind = ObjectiveKind::kL1;
  return p;
}

}  // namespace thrustsched::transcription

#endif  // THRUSTSCHED_TESTS_TRANSCRIPTION_THESIS_CASES_H_
