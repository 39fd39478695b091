// Section 9 of report.md: the campaign engine (thrustsched-sweep on Dask) -
// the speed-up of a GEO-week campaign on 1 and 2 workers, the per-task
// overhead and the chapter 5 study on paper. Measured by a Python script
// (benchmarks/campaign_scaling.py --out DIR/campaigns.md), not by this tool:
// the section carries that file over, its headings one level down.
//
//   std::ostringstream md;
//   bench::WriteCampaigns(md, "docs/bench");   // reads docs/bench/campaigns.md
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_CAMPAIGNS_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_CAMPAIGNS_H_

#include <ostream>
#include <string>

namespace thrustsched::bench {

/// Writes the section from dir/campaigns.md (how to measure it if absent).
void WriteCampaigns(std::ostream& md, const std::string& dir);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_CAMPAIGNS_H_
