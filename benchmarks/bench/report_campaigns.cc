#include "benchmarks/bench/report_campaigns.h"

#include <fstream>
#include <string>

namespace thrustsched::bench {

void WriteCampaigns(std::ostream& md, const std::string& dir) {
  md << "## 9. Campaigns (`thrustsched-sweep` on Dask)\n\n";
  std::ifstream in(dir + "/campaigns.md");
  if (!in) {
    md << "Not measured in this folder: `PYTHONPATH=build/python /usr/bin/python3 "
          "benchmarks/campaign_scaling.py --out "
       << dir << "/campaigns.md` measures it, then `--report-only` brings it here.\n\n";
    return;
  }
  std::string line;
  bool body = false;  // past the file's own title (this section's) and the blank lines after it
  while (std::getline(in, line)) {
    if (!body && (line.empty() || line.rfind("# ", 0) == 0)) continue;
    body = true;
    if (!line.empty() && line[0] == '#')
      line = "#" + line;  // "## x" becomes "### x", below the section
    md << line << "\n";
  }
  md << "\n(From `campaigns.md`, written by `benchmarks/campaign_scaling.py`.)\n\n";
}

}  // namespace thrustsched::bench
