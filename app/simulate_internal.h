// Internals of `thrustsched simulate` shared by its files (app/simulate*.cc):
// small formatting and file helpers, the crash guard, the checkpoint, the
// long_horizon section parser and the year plots. Not a public API.
//
//   simulate_detail::WriteAtomically(dir + "/checkpoint.json", text);
//   simulate_detail::InProgressGuard guard(dir + "/in_progress.json", fingerprint, 3, false);
#ifndef THRUSTSCHED_APP_SIMULATE_INTERNAL_H_
#define THRUSTSCHED_APP_SIMULATE_INTERNAL_H_

#include <chrono>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "app/simulate.h"
#include "common/constants.h"
#include "common/timing.h"
#include "dynamics/models.h"
#include "milp/solver.h"
#include "planning/long_horizon.h"

namespace thrustsched::app::simulate_detail {

using common::Clock;
using common::kRadToDeg;
using common::Since;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kCheckpointFormat = "thrustsched-year-checkpoint-1";
constexpr const char* kInProgressFile = "in_progress.json";

// ---- Formatting and files (simulate_files.cc).
/// %g with `digits` significant digits; "nan", "inf", "-inf" spelled out.
std::string G(double v, int digits = 12);
/// hh:mm:ss ("--:--:--" when unknown).
std::string Hms(double seconds);
/// "cycle_NNN" of the 0-based cycle `index`.
std::string CycleTag(int index);
/// ISO 8601 UTC of `t` seconds after `epoch` ("" if the epoch does not parse).
std::string Utc(const std::string& epoch, double t);
/// 64-bit FNV-1a of a text, as 16 hex digits (stable across builds).
std::string Fingerprint(const std::string& text);
std::string CsvQuote(const std::string& s);
/// @throws ScenarioError naming the folder.
void MakeDirectory(const std::string& dir);
/// Writes through a temporary file and a rename, so a reader (or a resume
/// after a crash) never sees half a file.
void WriteAtomically(const std::string& path, const std::string& text);

// ---- Crash guard (simulate_crash_guard.cc).
// ---- Crash guard.
// A cycle's solve runs inside CBC; a defect there can kill the process
// (CoinUtils 2.11 was seen to SIGSEGV in the postsolve of CBC's preprocessing
// on a six-thruster week), which no exception handler can catch. Before each
// cycle, `in_progress.json` names it; a normal end of the cycle (recorded,
// interrupted or failed with an exception) removes the file. A file that
// survives means the process died inside that cycle: `--resume` then solves
// the cycle with CBC's preprocessing and presolve off (the configuration that
// avoided the crash), and the cycle's note says so. A second death in the same
// cycle stops with an error instead of looping.
struct InProgress {
  int cycle = 0;      // 1-based
  bool safe = false;  // that attempt already ran without preprocessing
};

/// The marker an earlier process left for this scenario, if any.
std::optional<InProgress> ReadInProgress(const std::string& path, const std::string& fingerprint);

/// Writes the marker; removes it when the cycle ends in any way the process
/// survives (the destructor does not run when the process is killed).
class InProgressGuard {
 public:
  InProgressGuard(std::string path, const std::string& fingerprint, int cycle, bool safe);
  ~InProgressGuard();
  InProgressGuard(const InProgressGuard&) = delete;
  InProgressGuard& operator=(const InProgressGuard&) = delete;

 private:
  std::string path_;
};

// ---- Checkpoint (simulate_checkpoint.cc). Numbers round-trip exactly:
// nlohmann writes the shortest representation that reads back to the same double.
/// @throws ScenarioError naming the file on an unknown status name.
milp::SolveStatus ParseStatus(const std::string& name, const std::string& path);
double GetNumber(const nlohmann::json& j, const char* key, const std::string& path);
/// An integer-valued number in [min, max] (not null), so that the caller's
/// cast to an integer type is defined. @throws ScenarioError naming the key.
double GetInteger(const nlohmann::json& j, const char* key, const std::string& path, double min,
                  double max);
/// More cycles than a checkpoint can hold (a century of weekly cycles):
/// bounds next_cycle and the cycle indices read back.
inline constexpr double kMaxCheckpointCycles = 100 * 53;
std::vector<double> GetNumbers(const nlohmann::json& j, const char* key, const std::string& path,
                               double null_value = kNaN);
nlohmann::json VectorJson(const Eigen::VectorXd& v);
Eigen::VectorXd ToVector(const std::vector<double>& v);
dynamics::Vector6d ToVector6(const std::vector<double>& v, const std::string& path);
nlohmann::json CheckpointJson(const SimulationSetup& setup, const planning::LongHorizonState& st,
                              const std::vector<planning::CycleRecord>& cycles);
/// @throws ScenarioError when the checkpoint is of another scenario or malformed.
void ReadCheckpoint(const std::string& path, const SimulationSetup& setup, int num_thrusters,
                    planning::LongHorizonState* st, std::vector<planning::CycleRecord>* cycles);
/// ReadCheckpoint of text already read (`path` names it in messages).
void ParseCheckpoint(const std::string& text, const std::string& path, const SimulationSetup& setup,
                     int num_thrusters, planning::LongHorizonState* st,
                     std::vector<planning::CycleRecord>* cycles);

// ---- The long_horizon section (simulate_setup.cc).
/// Fills setup->options and setup->failures from setup->scenario's JSON.
/// @throws ScenarioError naming the field and value.
void ParseLongHorizon(SimulationSetup* setup);

// ---- trajectory.csv and the year plots (simulate_plots.cc).
std::string TrajectoryHeader();
std::string TrajectoryRows(const SimulationSetup& setup, const planning::CycleRecord& c,
                           bool last_cycle);
struct PlotFiles {
  std::vector<std::string> images;
  std::string message;
};
/// Writes the gnuplot scripts of the year plots into `dir` and, if `run`, draws them.
PlotFiles WriteYearPlots(const std::string& dir, const SimulationSetup& setup,
                         const std::vector<planning::CycleRecord>& cycles, bool run);

}  // namespace thrustsched::app::simulate_detail

#endif  // THRUSTSCHED_APP_SIMULATE_INTERNAL_H_
