#include "benchmarks/bench/report_conjunction.h"

#include <string>
#include <vector>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/report_format.h"

namespace thrustsched::bench {
namespace {

// "linear, two-body" Monte Carlo collision counts of a row ("-" when the
// two-body count was not made).
std::string Collisions(const Row& r, const char* linear, const char* nonlinear) {
  return r.Get(linear) + ", " + (r.Has(nonlinear) ? r.Get(nonlinear) : std::string("-"));
}

// One case: cost and time next to the published ones, then the verification.
std::vector<std::string> CaseCells(const Row& r) {
  return {r.Get("scenario"),
          r.Get("status"),
          G(1e3 * r.Num("objective"), 5),
          G(1e3 * r.Num("published"), 5),
          G(r.Num("ratio"), 4),
          Sec(r.Num("time_to_opt_s")),
          G(r.Num("published_time_s"), 4),
          r.Get("budget_rounds"),
          r.Get("keep_out_binaries"),
          G(r.Num("max_risk"), 3),
          G(r.Num("max_risk_unmanoeuvred"), 4) + " (" + G(r.Num("published_risk_unmanoeuvred"), 3) +
              ")",
          Collisions(r, "mc_collisions_linear", "mc_collisions_nonlinear") + " (" +
              r.Get("mc_samples") + ")"};
}

// One on-off case: the plan against the same problem's plan without the
// conjunction, both verified against it.
std::vector<std::string> OnOffCells(const Row& r) {
  return {r.Get("scenario"),
          r.Get("status"),
          G(r.Num("objective"), 6),
          G(r.Num("without_conjunction"), 6),
          G(r.Num("extra_cost"), 3) + " (" +
              Pct(r.Num("extra_cost") / r.Num("without_conjunction")) + ")",
          G(r.Num("best_bound"), 6),
          Pct(r.Num("gap")),
          Sec(r.Num("solve_s")),
          r.Get("budget_rounds"),
          G(r.Num("max_risk"), 3),
          G(r.Num("without_max_risk"), 3),
          Collisions(r, "mc_collisions_linear", "mc_collisions_nonlinear"),
          Collisions(r, "without_mc_collisions_linear", "without_mc_collisions_nonlinear") + " (" +
              r.Get("mc_samples") + ")"};
}

}  // namespace

void WriteCollisionAvoidance(std::ostream& md, const std::vector<Row>& rows) {
  md << "## 7. Collision avoidance (Serra 2015 ch. 4)\n\n";
  std::vector<const Row*> cases, on_off;
  for (const Row& r : rows) {
    if (r.Get("section") != kSectionCollisionAvoidance) continue;
    (r.Has("without_conjunction") ? on_off : cases).push_back(&r);
  }
  if (cases.empty() && on_off.empty()) {
    md << "Not run.\n\n";
    return;
  }
  if (!cases.empty()) {
    md << "Risk selection (Problem 10) solved by `SolveConjunction`: fixed-face LP start, then "
          "budget rounds (the problem rebuilt with the best known cost as its budget, big-M "
          "bounded with the terminal constraint) to a proven optimum. Time = start + every round, "
          "builds included, one CBC thread; Gurobi 5.6 on unstated hardware. Risks are computed "
          "(not sampled) at the check times; the Monte Carlo has the scenario's sample count, "
          "linear and two-body. Data defects and the covariance repair: data/scenarios/README.md "
          "section 11.\n\n";
    MdTable t({"scenario", "status", "cost (mm/s)", "published (mm/s)", "ratio",
               "CBC time to optimum (s)", "Gurobi (s)", "rounds", "keep-out binaries (last round)",
               "max risk", "unmanoeuvred risk (published)",
               "Monte Carlo collisions: linear, two-body (samples)"});
    for (const Row* r : cases) t.Add(CaseCells(*r));
    md << t.Str() << "\n";
  }
  if (on_off.empty()) return;
  md << "Avoidance with on-off thrusters (data/scenarios/README.md section 11): station keeping, "
        "the thesis rules and the keep-out rows in one MILP, solved by `SolveConjunction` (the "
        "plan without the conjunction by the problem-aware search, repaired at fixed faces, then "
        "budget rounds if the gap asks for them). The plan without the conjunction is also the "
        "lower bound; both plans are verified against the conjunction (computed risk, Monte "
        "Carlo linear and two-body). Time: the whole solve on 2 threads (the box and rules check "
        "included, the conjunction verification not).\n\n";
  MdTable t({"scenario", "status", "cost (m/s)", "without the conjunction (m/s)",
             "extra cost (m/s)", "bound", "gap", "time (s)", "rounds", "max risk",
             "max risk without", "Monte Carlo collisions: linear, two-body", "without (samples)"});
  for (const Row* r : on_off) t.Add(OnOffCells(*r));
  md << t.Str() << "\n";
}

}  // namespace thrustsched::bench
