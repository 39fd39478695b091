#include "benchmarks/bench/report_conjunction.h"

#include <string>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/report_format.h"

namespace thrustsched::bench {
namespace {

// One case: cost and time next to the published ones, then the verification.
void WriteCase(std::ostream& md, const Row& r) {
  md << "| " << r.Get("scenario") << " | " << r.Get("status") << " | "
     << G(1e3 * r.Num("objective"), 5) << " | " << G(1e3 * r.Num("published"), 5) << " | "
     << G(r.Num("ratio"), 4) << " | " << Sec(r.Num("time_to_opt_s")) << " | "
     << G(r.Num("published_time_s"), 4) << " | " << r.Get("budget_rounds") << " | "
     << r.Get("keep_out_binaries") << " | " << G(r.Num("max_risk"), 3) << " | "
     << G(r.Num("max_risk_unmanoeuvred"), 4) << " (" << G(r.Num("published_risk_unmanoeuvred"), 3)
     << ") | " << r.Get("mc_collisions_linear") << ", "
     << (r.Has("mc_collisions_nonlinear") ? r.Get("mc_collisions_nonlinear") : "-") << " ("
     << r.Get("mc_samples") << ") |\n";
}

}  // namespace

void WriteCollisionAvoidance(std::ostream& md, const std::vector<Row>& rows) {
  md << "## 7. Collision avoidance (Serra 2015 ch. 4)\n\n";
  std::vector<const Row*> cases;
  for (const Row& r : rows) {
    if (r.Get("section") == kSectionCollisionAvoidance) cases.push_back(&r);
  }
  if (cases.empty()) {
    md << "Not run.\n\n";
    return;
  }
  md << "Risk selection (Problem 10) solved by `SolveConjunction`: fixed-face LP start, then "
        "budget rounds (the problem rebuilt with the best known cost as its budget, big-M "
        "bounded with the terminal constraint) to a proven optimum. Time = start + every round, "
        "builds included, one CBC thread; Gurobi 5.6 on unstated hardware. Risks are computed "
        "(not sampled) at the check times; the Monte Carlo has the scenario's sample count, "
        "linear and two-body. Data defects and the covariance repair: data/scenarios/README.md "
        "section 11.\n\n";
  md << "| scenario | status | cost (mm/s) | published (mm/s) | ratio | CBC time to optimum (s) | "
        "Gurobi (s) "
        "| rounds | keep-out binaries (last round) | max risk | unmanoeuvred risk (published) "
        "| Monte Carlo collisions: linear, two-body (samples) |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row* r : cases) WriteCase(md, *r);
  md << "\n";
}

}  // namespace thrustsched::bench
