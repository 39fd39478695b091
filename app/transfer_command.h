// `thrustsched transfer SCENARIO --out DIR [--method minimum_time|feedback|two_impulse]`:
// an orbit transfer from a transfer scenario file (app/transfer_scenario.h),
// written as summary.json (duration, propellant, final elements and their
// errors against the target, revolutions, convergence figures, the
// Cartesian replay's check, the end state as a station-keeping
// initial_state), trajectory.csv (time, elements, mass, thrust command in
// QSW), orbit.csv (Cartesian states), the plots elements.svg and orbit.svg,
// report.html and, with --oem, a CCSDS OEM. Fields in
// data/scenarios/transfer/README.md.
//
//   app::TransferArgs a;
//   a.scenario = "data/scenarios/transfer/gto_geo_caillau_60n.json";
//   a.out_dir = "out/gto60";
//   int exit_code = app::RunTransfer(a);   // 0 converged / reached, 4 not or interrupted, 2 bad
//   input
//
// The first Ctrl-C (SIGINT, SIGTERM, SIGHUP) stops the transfer and writes its best result so far
// (summary "status": "interrupted", exit 4); a second one exits at once (128 + signal).
#ifndef THRUSTSCHED_APP_TRANSFER_COMMAND_H_
#define THRUSTSCHED_APP_TRANSFER_COMMAND_H_

#include <string>

namespace thrustsched::app {

struct TransferArgs {
  std::string scenario;
  std::string out_dir;  // empty: out/<scenario file stem>
  std::string method;   // empty: the scenario's
  bool quiet = false;
  bool force = false;      // replace an earlier run's files in out_dir
  bool no_plots = false;   // write the gnuplot scripts, do not run gnuplot
  bool no_report = false;  // no report.html
  std::string oem;         // also write the trajectory as a CCSDS OEM here (needs "epoch")
  std::string command_line;
};

/// @throws ScenarioError (exit 2) on bad input; returns the exit code otherwise.
int RunTransfer(const TransferArgs& args);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_TRANSFER_COMMAND_H_
