// Test helper: runs the real `thrustsched` binary (or another program) as a
// child process, with a wall-clock timeout, and reports how it ended.
//
//   RunResult r = RunCli({"solve", scenario, "--out", dir});
//   EXPECT_TRUE(r.exited) << r.Describe();
//   EXPECT_EQ(r.exit_code, 0) << r.err;
#ifndef THRUSTSCHED_TESTS_APP_CLI_RUNNER_H_
#define THRUSTSCHED_TESTS_APP_CLI_RUNNER_H_

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

namespace thrustsched::testing {

struct RunResult {
  bool exited = false;  // normal exit (exit_code valid)
  int exit_code = -1;
  bool signaled = false;  // killed by a signal (a crash, or our timeout)
  int signal = 0;
  bool timed_out = false;
  std::string out, err;
  std::string Describe() const {
    std::ostringstream os;
    os << (exited ? "exit " + std::to_string(exit_code) : "")
       << (signaled ? "signal " + std::to_string(signal) : "") << (timed_out ? " (timeout)" : "")
       << "\n--- stdout ---\n"
       << out << "\n--- stderr ---\n"
       << err;
    return os.str();
  }
};

inline std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void WriteFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

/// A CSV file as its header line and its rows split at commas (blank lines skipped).
struct CsvRows {
  std::string header;
  std::vector<std::vector<std::string>> rows;
};

inline CsvRows ReadCsv(const std::string& path) {
  CsvRows c;
  std::istringstream in(ReadFile(path));
  std::string line;
  std::getline(in, c.header);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    c.rows.push_back(cells);
  }
  return c;
}

inline nlohmann::json ReadJson(const std::string& path) {
  return nlohmann::json::parse(ReadFile(path));
}

/// A fresh directory under the system temp dir.
inline std::string TempDir(const std::string& tag) {
  static std::mt19937_64 rng(std::random_device{}());
  const std::filesystem::path p = std::filesystem::temp_directory_path() /
                                  ("thrustsched_" + tag + "_" + std::to_string(getpid()) + "_" +
                                   std::to_string(rng() % 1000000000ULL));
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p.string();
}

/// Runs `child()` in a forked child process whose stdout/stderr go to files
/// (read back into the result) and stdin is /dev/null; `child` must end the
/// process (exec or _exit). `on_started(pid, err_path)` is called in the
/// parent after the fork (e.g. to send a signal later). Kills the child with
/// SIGKILL after `timeout_s`.
inline RunResult RunForked(
    const std::function<void()>& child, double timeout_s,
    const std::function<void(pid_t, const std::string& err_path)>& on_started = nullptr) {
  const std::string dir = TempDir("run");
  const std::string out_path = dir + "/stdout", err_path = dir + "/stderr";
  RunResult r;
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int o = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int in = open("/dev/null", O_RDONLY);
    dup2(o, 1);
    dup2(e, 2);
    dup2(in, 0);
    child();
    _exit(127);
  }
  if (on_started) on_started(pid, err_path);
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  while (true) {
    const pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > timeout_s) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (WIFEXITED(status)) {
    r.exited = true;
    r.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    r.signaled = true;
    r.signal = WTERMSIG(status);
  }
  r.out = ReadFile(out_path);
  r.err = ReadFile(err_path);
  std::filesystem::remove_all(dir);
  return r;
}

/// Runs `program args...` (see RunForked).
inline RunResult RunProgram(
    const std::string& program, const std::vector<std::string>& args, double timeout_s = 300.0,
    const std::function<void(pid_t, const std::string& err_path)>& on_started = nullptr) {
  return RunForked(
      [&] {
        std::vector<char*> argv;
        argv.push_back(const_cast<char*>(program.c_str()));
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execvp(program.c_str(), argv.data());
      },
      timeout_s, on_started);
}

/// Runs `body()` in a forked child and exits with what it returns (the
/// streams flushed first): for in-process runs of the CLI with injected
/// hooks (app/cli.h), whose crashes and signals stay in the child.
inline RunResult RunInChild(const std::function<int()>& body, double timeout_s = 300.0) {
  return RunForked(
      [&] {
        const int code = body();
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
        _exit(code);
      },
      timeout_s);
}

#ifdef THRUSTSCHED_CLI
inline RunResult RunCli(const std::vector<std::string>& args, double timeout_s = 300.0) {
  return RunProgram(THRUSTSCHED_CLI, args, timeout_s);
}
#endif

/// True if `program` is found in PATH.
inline bool HaveProgram(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::stringstream ss(path);
  std::string d;
  while (std::getline(ss, d, ':')) {
    if (!d.empty() && access((d + "/" + program).c_str(), X_OK) == 0) return true;
  }
  return false;
}

}  // namespace thrustsched::testing

#endif  // THRUSTSCHED_TESTS_APP_CLI_RUNNER_H_
