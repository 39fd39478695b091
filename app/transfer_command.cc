#include "app/transfer_command.h"

#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/ccsds_oem.h"
#include "app/commands.h"
#include "app/interrupt.h"
#include "app/outputs.h"
#include "app/run_folder.h"
#include "app/transfer_handover.h"
#include "app/transfer_report.h"
#include "app/transfer_run.h"
#include "app/transfer_scenario.h"
#include "common/format.h"

namespace thrustsched::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A file asked for inside the output folder is written into its temporary
// folder (moved into place, and named in the manifest, with the rest);
// anywhere else, where it was asked for.
std::string InRunFolder(const std::string& path, const RunFolder& folder) {
  fs::path target = fs::absolute(folder.target()).lexically_normal();
  if (!target.has_filename()) target = target.parent_path();  // "out/x/"
  const fs::path p = fs::absolute(path).lexically_normal();
  return p.parent_path() == target ? (fs::path(folder.path()) / p.filename()).string() : path;
}

}  // namespace

int RunTransfer(const TransferArgs& a) {
  TransferScenario sc = LoadTransferScenario(a.scenario);
  if (!a.method.empty()) sc.method = ParseTransferMethod(a.method, "--method");
  if (!a.oem.empty() && !sc.epoch) {
    throw ScenarioError("--oem " + a.oem +
                        ": needs the transfer's start epoch (scenario.transfer.epoch, UTC)");
  }
  const std::string out_dir =
      a.out_dir.empty() ? "out/" + fs::path(a.scenario).stem().string() : a.out_dir;
  RunFolder folder(out_dir, a.force, a.command_line);
  const std::string oem_path = a.oem.empty() ? "" : InRunFolder(a.oem, folder);
  if (!oem_path.empty()) {
    const fs::path parent = fs::absolute(oem_path).parent_path();
    std::error_code ec;
    if (!fs::is_directory(parent, ec)) {
      throw ScenarioError("--oem " + a.oem + ": the folder " + parent.string() + " does not exist");
    }
  }
  const fs::path dir(folder.path());
  TransferRun run;
  {
    // Ctrl-C (SIGINT, SIGTERM, SIGHUP) stops the shooting or the feedback and
    // keeps the best result so far, written as usual; a second one exits.
    InterruptWatcher watcher;
    TransferHooks hooks;
    hooks.interrupt = InterruptWatcher::flag();
    run = RunTransferScenario(sc, a.scenario, a.quiet, hooks);
  }
  if (run.interrupted && !a.quiet) {
    std::cerr << "interrupted (" << InterruptWatcher::signal_name()
              << "): writing the best result so far\n";
  }
  run.summary["command_line"] = a.command_line;
  WriteJsonFile((dir / "summary.json").string(), run.summary);
  WriteTextFile((dir / "trajectory.csv").string(), run.trajectory_csv);
  WriteTextFile((dir / "orbit.csv").string(), OrbitCsv(run.orbit));
  std::string files = "summary.json, trajectory.csv, orbit.csv";
  const PlotResult plots = WriteTransferPlots(dir.string(), sc, run.summary, run.trajectory_rows,
                                              run.orbit.size(), !a.no_plots);
  for (const std::string& image : plots.images) files += ", " + image;
  if (!plots.message.empty() && !a.quiet) std::cerr << "note: " << plots.message << "\n";
  if (!a.no_report) {
    WriteTransferReport(dir.string(), sc, run.summary);
    files += ", report.html";
  }
  if (!a.oem.empty()) {
    const std::string comment = "thrustsched transfer of scenario \"" + sc.name + "\", " +
                                ToString(sc.method) + ", " + run.summary.value("orbit_source", "") +
                                " states";
    WriteTextFile(oem_path, FormatOem(TransferOem(run.orbit, *sc.epoch, sc.name, comment)));
  }
  const std::string replaced = folder.Commit();
  if (!replaced.empty()) std::cerr << "note: " << replaced << "\n";
  const json& s = run.summary;
  std::cout << "transfer      " << sc.name << " (" << a.scenario << "), " << ToString(sc.method)
            << "\n"
            << "status        "
            << (run.converged     ? "converged"
                : run.interrupted ? "interrupted"
                                  : "not converged")
            << "\n"
            << "duration      " << common::FormatG(s["duration_h"].get<double>(), 8) << " h ("
            << common::FormatG(s["duration_d"].get<double>(), 7) << " d)\n"
            << "propellant    " << common::FormatG(s["propellant_kg"].get<double>(), 7) << " kg\n"
            << "output        " << out_dir << " (" << files << ")\n";
  if (!a.oem.empty()) std::cout << "oem           " << a.oem << "\n";
  if (run.interrupted) return kExitInterrupted;
  return run.converged ? kExitOk : kExitNoSolution;
}

}  // namespace thrustsched::app
