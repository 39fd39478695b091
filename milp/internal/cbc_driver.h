// One run of CBC's driver (CbcMain1 "-solve") on a MILP, in this process
// (internal to the CBC backend; see cbc_child.h for the same run in a child
// process).
//
//   class Recorder : public DriverListener { ... };    // incumbents, progress, stop
//   DriverRequest request{lp, options, clock, start_x, start_min};
//   Recorder recorder;
//   DriverOutcome out = RunDriverHere(request, &recorder);
//
// Every incumbent of the main search is handed to the listener as soon as CBC
// has it, in the original column space (CBC's callbacks see the preprocessed
// model; the columns preprocessing removed are NaN), so that a run stopped
// at any point (time limit in the root heuristics, interrupt, crash) loses
// no schedule: the driver itself drops its incumbent when a limit falls
// before its post-processing (coin-or/Cbc#214, #353).
#ifndef THRUSTSCHED_MILP_INTERNAL_CBC_DRIVER_H_
#define THRUSTSCHED_MILP_INTERNAL_CBC_DRIVER_H_

#include <limits>
#include <string>

#include <Eigen/Core>

#include "milp/internal/solve_clock.h"
#include "milp/lp_data.h"
#include "milp/solver.h"

namespace thrustsched::milp::internal {

/// CBC's "no value" for objectives and bounds (COIN_DBL_MAX-like sentinels):
/// a magnitude at or above it is no number. Shared by the driver and the backend
/// that reads the driver's outcome.
inline constexpr double kCbcInfinity = 1e50;

/// Receives what the driver finds while it runs. Called from the solving
/// thread(s); with threads > 1 calls are serialised by the driver.
class DriverListener {
 public:
  virtual ~DriverListener() = default;
  /// Progress (root LP iterations, incumbent, bound, nodes), at most every
  /// options.progress_interval_s and on every new incumbent.
  virtual void OnProgress(const SolveProgress& progress) = 0;
  /// A new incumbent of the main search: its objective and the bound at that
  /// time in the model's sense (with offset), and the column values in the
  /// original column space, NaN where the column is not in CBC's model.
  virtual void OnIncumbent(const Incumbent& incumbent, const Eigen::VectorXd& x_partial) = 0;
  /// Polled by the driver's handlers: true stops the run as at a time limit.
  virtual bool StopRequested() = 0;
};

struct DriverRequest {
  const LpData& lp;
  const SolveOptions& options;  // progress and interrupt are not read (the listener's job)
  SolveClock clock;             // start and deadline of the solve
  Eigen::VectorXd start_x;      // verified MIP start (empty: none)
  double start_min = std::numeric_limits<double>::infinity();  // its CBC (minimisation) objective
};

/// What the driver concluded.
struct DriverOutcome {
  int status = -1;     // CbcModel::status()
  int secondary = -1;  // CbcModel::secondaryStatus()
  bool proven_optimal = false;
  bool proven_infeasible = false;
  bool continuous_unbounded = false;
  /// Our handler stopped the root LP relaxation: nothing is proven.
  bool root_lp_stopped = false;
  /// The run ended at a limit or a stop request.
  bool stopped = false;
  bool stopped_by_request = false;
  double bound_min = -std::numeric_limits<double>::infinity();  // best CBC (min form) bound
  long long nodes = 0;
  Eigen::VectorXd x;  // CBC's final best solution (original space, not verified); empty if none
  std::string detail;
  bool completed = true;  // false: the run did not end normally (child killed or crashed)
};

DriverOutcome RunDriverHere(const DriverRequest& request, DriverListener* listener);

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_CBC_DRIVER_H_
