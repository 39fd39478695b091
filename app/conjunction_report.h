// CLI reporting of a conjunction: the keep-out rows the MILP got (binaries,
// big-M range, budget, covariance repair) and the plan's verification
// (computed maximum instantaneous risk, Monte Carlo collisions), as human
// lines and as the "conjunction" object of summary.json / check.json.
//
//   if (auto v = app::VerifyConjunction(scenario, schedule.burns, schedule.impulses)) {
//     app::PrintConjunctionCheck(std::cout, *v);
//     summary["conjunction"] = app::ConjunctionJson(milp.keep_out(), &*v);
//   }
#ifndef THRUSTSCHED_APP_CONJUNCTION_REPORT_H_
#define THRUSTSCHED_APP_CONJUNCTION_REPORT_H_

#include <optional>
#include <ostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/scenario.h"
#include "transcription/conjunction_check.h"
#include "transcription/conjunction_solve.h"
#include "transcription/keep_out.h"

namespace thrustsched::app {

/// The verification of the scenario's conjunction with its own settings;
/// empty if the scenario has none.
std::optional<transcription::ConjunctionCheckReport> VerifyConjunction(
    const Scenario& scenario, const std::vector<transcription::Burn>& burns,
    const std::vector<transcription::Impulse>& impulses);

/// One line: keep-out binaries, rows, clear checks, big-M range, budget.
void PrintKeepOut(std::ostream& os, const transcription::KeepOutStats& stats);
/// Risk, Monte Carlo and verdict lines.
void PrintConjunctionCheck(std::ostream& os, const transcription::ConjunctionCheckReport& report);

/// The start and the budget rounds of SolveConjunction, one line each.
void PrintConjunctionSolve(std::ostream& os, const transcription::ConjunctionSolve& solve);

/// {"keep_out": {...} | null, "solve": {...} | null, "verification": {...} | null}.
nlohmann::json ConjunctionJson(const std::optional<transcription::KeepOutStats>& keep_out,
                               const transcription::ConjunctionSolve* solve,
                               const transcription::ConjunctionCheckReport* verification);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_CONJUNCTION_REPORT_H_
