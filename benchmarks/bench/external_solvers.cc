#include "benchmarks/bench/external_solvers.h"

#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "benchmarks/bench/case_common.h"
#include "benchmarks/bench/runner.h"

namespace thrustsched::bench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kHighsRunner = THRUSTSCHED_SOURCE_DIR "/benchmarks/external/highs_solve.mjs";

std::string FirstLineContaining(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find(needle) != std::string::npos) return line;
  }
  return "";
}

std::string Trim(std::string s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

struct CommandOutcome {
  int exit_code = -1;  // 124: killed by `timeout`
  double seconds = kNaN;
};

// `command` (a shell command line redirecting its own output) under
// `timeout`: the solver's own limit plus 60 s of grace, because a solver
// does not always honour its limit (CBC's root LP ignores `sec`).
CommandOutcome RunTimed(const std::string& command, double limit_s) {
  const std::string cmd =
      "timeout " + std::to_string(static_cast<int>(limit_s) + 60) + " " + command;
  const auto t0 = std::chrono::steady_clock::now();
  const int rc = std::system(cmd.c_str());
  CommandOutcome o;
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  o.exit_code = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  return o;
}

std::string KilledAfter(const CommandOutcome& o) {
  return "killed by `timeout` after " + FormatValue(std::round(o.seconds)) + " s";
}

ExternalResult RunCbcProgram(const std::string& mps, const std::string& stem, double limit) {
  ExternalResult r;
  const std::string sol = stem + ".cbc.sol", log = stem + ".cbc.log";
  std::remove(sol.c_str());
  const CommandOutcome o = RunTimed("cbc '" + mps + "' sec " + std::to_string(limit) +
                                        " threads 1 solve solu '" + sol + "' > '" + log + "' 2>&1",
                                    limit);
  r.seconds = o.seconds;
  std::ifstream in(sol);
  std::string first;
  if (!in || !std::getline(in, first)) {
    r.status = o.exit_code == 124 ? KilledAfter(o) + " (the root LP ignores `sec`)"
                                  : "no solution file (exit " + std::to_string(o.exit_code) + ")";
    return r;
  }
  // e.g. "Optimal - objective value 0.08195883" or "Stopped on time - objective value 1.75"
  const auto dash = first.find(" - objective value");
  r.status = Trim(dash == std::string::npos ? first : first.substr(0, dash));
  if (dash != std::string::npos) {
    r.objective = std::strtod(first.c_str() + dash + 18, nullptr);
  }
  // "Stopped on time (no integer solution - continuous used)": the value is
  // the LP relaxation's, not a schedule's.
  if (r.status.rfind("Infeasible", 0) == 0 || r.status.find("no solution") != std::string::npos ||
      r.status.find("no integer solution") != std::string::npos) {
    r.objective = kNaN;
  }
  return r;
}

ExternalResult RunGlpsol(const std::string& mps, const std::string& stem, double limit) {
  ExternalResult r;
  const std::string out = stem + ".glpsol.txt", log = stem + ".glpsol.log";
  std::remove(out.c_str());
  const CommandOutcome o = RunTimed("glpsol --freemps '" + mps + "' --tmlim " +
                                        std::to_string(static_cast<int>(std::ceil(limit))) +
                                        " -o '" + out + "' > '" + log + "' 2>&1",
                                    limit);
  r.seconds = o.seconds;
  std::string text;
  try {
    text = ReadTextFile(out);
  } catch (const std::exception&) {
    r.status = o.exit_code == 124 ? KilledAfter(o)
                                  : "no output (exit " + std::to_string(o.exit_code) + ")";
    return r;
  }
  // "Status:     INTEGER OPTIMAL" / "INTEGER NON-OPTIMAL" / "INTEGER UNDEFINED" / "INTEGER EMPTY"
  const std::string status = FirstLineContaining(text, "Status:");
  r.status = Trim(status.empty() ? "unknown" : status.substr(status.find(':') + 1));
  const std::string obj = FirstLineContaining(text, "Objective:");
  const auto eq = obj.find('=');
  if (eq != std::string::npos && r.status.find("UNDEFINED") == std::string::npos &&
      r.status.find("EMPTY") == std::string::npos) {
    r.objective = std::strtod(obj.c_str() + eq + 1, nullptr);
  }
  return r;
}

// Last line of `path` that is a JSON object (node prints nothing else on
// stdout, but a warning line must not hide the result).
std::string LastJsonLine(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!Trim(line).empty() && Trim(line).front() == '{') last = Trim(line);
  }
  return last;
}

ExternalResult RunHighs(const std::string& mps, const std::string& stem, double limit) {
  ExternalResult r;
  if (!ProgramAvailable("node")) {
    r.status = "skipped: node not found";
    return r;
  }
  const std::string out = stem + ".highs.txt", log = stem + ".highs.log";
  std::remove(out.c_str());
  const CommandOutcome o =
      RunTimed("node '" + std::string(kHighsRunner) + "' '" + mps + "' --format mps --time-limit " +
                   FormatValue(limit) + " > '" + out + "' 2> '" + log + "'",
               limit);
  std::string text;
  try {
    text = ReadTextFile(out);
  } catch (const std::exception&) {
  }
  try {
    r = ParseHighsOutput(text);
  } catch (const std::exception&) {
    // No result line: killed, or node itself failed (e.g. out of memory:
    // the first line of its error output says so).
    std::string why;
    try {
      std::istringstream err(ReadTextFile(log));
      std::string line;
      while (why.empty() && std::getline(err, line)) why = Trim(line);
    } catch (const std::exception&) {
    }
    r.status = o.exit_code == 124 ? KilledAfter(o)
                                  : "no result (exit " + std::to_string(o.exit_code) + ")" +
                                        (why.empty() ? "" : ": " + why.substr(0, 200));
  }
  r.seconds = o.seconds;
  return r;
}

double JsonNumber(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : kNaN;
}

}  // namespace

const std::vector<std::string>& ExternalSolverNames() {
  static const std::vector<std::string> kNames = {"cbc", "glpsol", "highs"};
  return kNames;
}

ExternalResult ParseHighsOutput(const std::string& text) {
  const std::string line = LastJsonLine(text);
  if (line.empty()) throw std::runtime_error("no JSON line in the HiGHS runner's output");
  const nlohmann::json j = nlohmann::json::parse(line);
  ExternalResult r;
  const std::string status = j.value("status", "unknown");
  if (status == "skipped" || status == "error") {
    r.status = status + ": " + j.value("reason", "no reason given");
    return r;
  }
  r.status = status;
  if (j.value("has_solution", false)) {
    r.objective = JsonNumber(j, "objective");
    r.gap = JsonNumber(j, "gap");
  }
  r.bound = JsonNumber(j, "bound");
  return r;
}

ExternalResult RunExternalSolver(const std::string& solver, const std::string& mps,
                                 const std::string& stem, double limit_s) {
  if (solver == "highs") return RunHighs(mps, stem, limit_s);
  if (solver != "cbc" && solver != "glpsol") {
    throw std::invalid_argument("RunExternalSolver: unknown solver " + solver);
  }
  if (!ProgramAvailable(solver)) {
    ExternalResult r;
    r.status = "not installed";
    return r;
  }
  return solver == "cbc" ? RunCbcProgram(mps, stem, limit_s) : RunGlpsol(mps, stem, limit_s);
}

void RunExternalSolvers(const std::string& mps, const std::string& stem, double limit_s, Row* row) {
  for (const std::string& solver : ExternalSolverNames()) {
    const ExternalResult e = RunExternalSolver(solver, mps, stem, limit_s);
    const std::string prefix = "ext_" + solver;
    row->Set(prefix + "_status", e.status);
    row->Set(prefix + "_objective", e.objective);
    row->Set(prefix + "_s", e.seconds);
    if (solver == "highs") {
      row->Set(prefix + "_bound", e.bound);
      row->Set(prefix + "_gap", e.gap);
    }
  }
}

std::vector<std::string> ExternalOutputFiles(const std::string& stem) {
  return {stem + ".cbc.sol",    stem + ".cbc.log",   stem + ".glpsol.txt",
          stem + ".glpsol.log", stem + ".highs.txt", stem + ".highs.log"};
}

std::string HighsVersionNote() {
  FILE* p = popen(("node '" + std::string(kHighsRunner) + "' --version 2>/dev/null").c_str(), "r");
  std::string text;
  if (p != nullptr) {
    char buf[512];
    while (std::fgets(buf, sizeof(buf), p) != nullptr) text += buf;
    pclose(p);
  }
  try {
    const nlohmann::json j = nlohmann::json::parse(LastJsonLine(text));
    if (j.contains("version")) {
      return "highs-js " + j.value("version", "?") + " (HiGHS " + j.value("highs_version", "?") +
             ")";
    }
    return "HiGHS skipped: " + j.value("reason", "unknown reason");
  } catch (const std::exception&) {
    return "HiGHS skipped: node not found or the runner failed";
  }
}

std::string ExternalBeatsOptimum(const Row& row, const std::string& solver) {
  const std::string prefix = "ext_" + solver;
  const double o = row.Num(prefix + "_objective");
  // An LP value reported in place of a solution is not a schedule.
  if (!std::isfinite(o) ||
      row.Get(prefix + "_status").find("no integer solution") != std::string::npos) {
    return "";
  }
  const double ours = row.Num("objective");
  if (row.Get("status") == "optimal" && std::isfinite(ours)) {
    // Relative 1e-6: the MPS file carries 15+ significant digits, the
    // solvers' feasibility tolerances are 1e-6 to 1e-7.
    if (o < ours - 1e-6 * std::max(1.0, std::abs(ours))) {
      return solver + " objective " + FormatValue(o) + " is below our proven optimum " +
             FormatValue(ours) + ": a wrong optimum or a wrong export";
    }
    return "";
  }
  const double published = row.Num("published");
  if (std::isfinite(published) && o < published * (1.0 - 0.005)) {
    return solver + " objective " + FormatValue(o) + " is more than 0.5 % below the published " +
           FormatValue(published) + " (" + row.Get("published_source") +
           "): our model may be looser than the published one";
  }
  return "";
}

}  // namespace thrustsched::bench
