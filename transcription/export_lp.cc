#include "transcription/export_lp.h"

#include "milp/chain_bounds.h"

namespace thrustsched::transcription {

milp::LpData ExportLp(const ScheduleMilp& milp) {
  milp::LpData lp = milp.lp();
  if (!milp.state_chain().blocks.empty()) milp::TightenToChainBounds(&lp, milp.state_chain());
  return lp;
}

}  // namespace thrustsched::transcription
