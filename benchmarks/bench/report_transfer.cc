#include "benchmarks/bench/report_transfer.h"

#include <string>
#include <vector>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/report_format.h"

namespace thrustsched::bench {
namespace {

// "value (published)" or "-" when the run has none.
std::string WithPublished(const Row& r, const char* ours, const char* published, int sig) {
  if (!r.Has(ours)) return "-";
  return G(r.Num(ours), sig) + (r.Has(published) ? " (" + G(r.Num(published), sig) + ")" : "");
}

std::vector<std::string> Cells(const Row& r) {
  const std::string unit = r.Get("transfer_unit") == "km_s" ? "km/s" : r.Get("transfer_unit");
  return {r.Get("scenario"),
          r.Get("variant"),
          r.Get("status"),
          G(r.Num("transfer_figure"), 7) + " " + unit,
          G(r.Num("published"), 7) + " " + unit,
          G(r.Num("ratio"), 6) + " (" + Pct(r.Num("ratio") - 1) + ")",
          WithPublished(r, "feedback_phase", "published_feedback_phase", 5),
          WithPublished(r, "propellant_kg", "propellant_limit_kg", 5),
          G(r.Num("revolutions"), 5),
          Sec(r.Num("solve_s"))};
}

}  // namespace

void WriteTransfers(std::ostream& md, const std::vector<Row>& rows) {
  md << "## 10. Orbit transfers (transfer/)\n\n";
  std::vector<const Row*> cases;
  for (const Row& r : rows) {
    if (r.Get("section") == kSectionTransfer) cases.push_back(&r);
  }
  if (cases.empty()) {
    md << "Not run.\n\n";
    return;
  }
  md << "`thrustsched transfer`'s run of each scenario of data/scenarios/transfer/ (the "
        "variant's patch applied), timed whole, one thread, against "
        "data/reference/transfers.json. Published: Caillau, Gergaud & Noailles 2003 (60 N, "
        "0.7 N, as computed by Kepler.jl), Bombrun 2007 Table 5.2 (0.2 N = case 2, TFMIN; case "
        "1, MIPELEC averaged minimum time 137.38 d; feedback + optimal end 136.45 d and 177.41 "
        "d, of which 134 d and 175 d in feedback), MAP434 (two impulses, derived). Propellant: "
        "ours, and in brackets T t_f / (g0 Isp) of the published minimum time. What each "
        "figure means and its limits: docs/transfer.md.\n\n";
  MdTable t({"scenario", "variant", "status", "figure", "published", "ratio",
             "feedback phase, d (published)", "propellant, kg (published minimum time)",
             "revolutions", "tool time (s)"},
            2);
  for (const Row* r : cases) t.Add(Cells(*r));
  md << t.Str() << "\n";
}

}  // namespace thrustsched::bench
