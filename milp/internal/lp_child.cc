#include "milp/internal/lp_child.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "milp/internal/pipe_io.h"

namespace thrustsched::milp::internal {
namespace {

constexpr char kProgressFrame = 'P';
constexpr char kOutcomeFrame = 'O';
static_assert(std::is_trivially_copyable<SolveProgress>::value, "frames copy SolveProgress");

struct Header {
  int32_t status = 0;
  int64_t iterations = 0;
  double min_objective = 0.0;
  int64_t num_x = 0;
  int64_t num_duals = 0;
  int64_t detail_size = 0;
};

[[noreturn]] void RunChild(int fd, const LpData& lp, const CoinArrays& arrays,
                           const SolveOptions& options, double remaining_s) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  signal(SIGINT, SIG_IGN);
  signal(SIGTERM, SIG_IGN);
  signal(SIGHUP, SIG_IGN);
  SolveOptions o = options;
  if (options.progress) {
    // Each report (the interior point's iterate) as a frame: 'P', then the struct.
    o.progress = [fd](const SolveProgress& p) {
      const char type = kProgressFrame;
      WriteAllOrExit(fd, &type, 1);
      WriteAllOrExit(fd, &p, sizeof(p));
    };
  }
  o.interrupt = nullptr;  // the parent kills the child instead
  SolveClock clock(remaining_s, nullptr);
  LpOutcome r;
  try {
    r = SolveLpCore(lp, arrays, o, &clock);
  } catch (const std::exception& e) {
    r.status = SolveStatus::kError;
    r.detail = e.what();
  }
  const char type = kOutcomeFrame;  // the outcome: 'O', then everything up to EOF
  WriteAllOrExit(fd, &type, 1);
  Header h;
  h.status = static_cast<int32_t>(r.status);
  h.iterations = r.iterations;
  h.min_objective = r.min_objective;
  h.num_x = r.x.size();
  h.num_duals = r.duals.size();
  h.detail_size = static_cast<int64_t>(r.detail.size());
  WriteAllOrExit(fd, &h, sizeof(h));
  WriteAllOrExit(fd, r.x.data(), sizeof(double) * static_cast<size_t>(h.num_x));
  WriteAllOrExit(fd, r.duals.data(), sizeof(double) * static_cast<size_t>(h.num_duals));
  WriteAllOrExit(fd, r.detail.data(), r.detail.size());
  close(fd);
  _exit(0);
}

bool Parse(const std::vector<char>& buf, LpOutcome* out) {
  Header h;
  if (buf.size() < sizeof(h)) return false;
  std::memcpy(&h, buf.data(), sizeof(h));
  const size_t need = sizeof(h) + sizeof(double) * static_cast<size_t>(h.num_x + h.num_duals) +
                      static_cast<size_t>(h.detail_size);
  if (h.num_x < 0 || h.num_duals < 0 || h.detail_size < 0 || buf.size() != need) return false;
  size_t at = sizeof(h);
  out->status = static_cast<SolveStatus>(h.status);
  out->iterations = h.iterations;
  out->min_objective = h.min_objective;
  out->x.resize(h.num_x);
  // memcpy's pointers must not be null, even for zero bytes (an empty vector has none).
  if (h.num_x > 0) {
    std::memcpy(out->x.data(), buf.data() + at, sizeof(double) * static_cast<size_t>(h.num_x));
  }
  at += sizeof(double) * static_cast<size_t>(h.num_x);
  out->duals.resize(h.num_duals);
  if (h.num_duals > 0) {
    std::memcpy(out->duals.data(), buf.data() + at,
                sizeof(double) * static_cast<size_t>(h.num_duals));
  }
  at += sizeof(double) * static_cast<size_t>(h.num_duals);
  out->detail.assign(buf.data() + at, static_cast<size_t>(h.detail_size));
  return true;
}

int Reap(pid_t pid) {
  int wstatus = 0;
  while (waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
  }
  return wstatus;
}

}  // namespace

LpChildOutcome SolveLpCoreInChild(const LpData& lp, const CoinArrays& arrays,
                                  const SolveOptions& options, SolveClock* clock) {
  LpChildOutcome c;
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    c.died = true;
    c.why = std::string("pipe: ") + std::strerror(errno);
    return c;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    c.died = true;
    c.why = std::string("fork: ") + std::strerror(errno);
    return c;
  }
  if (pid == 0) {
    close(fds[0]);
    RunChild(fds[1], lp, arrays, options, clock->Remaining());
  }
  close(fds[1]);
  std::vector<char> buf;
  char chunk[1 << 16];
  const double offset_s = clock->Elapsed();  // the child's clock starts here
  double next_report = offset_s + options.progress_interval_s;
  bool stopped = false;
  bool in_outcome = false;
  // Hands on the progress frames at the front of buf; stops at the outcome.
  auto drain = [&]() {
    size_t at = 0;
    while (!in_outcome && at < buf.size()) {
      if (buf[at] == kOutcomeFrame) {
        in_outcome = true;
        ++at;
        break;
      }
      if (buf.size() - at < 1 + sizeof(SolveProgress)) break;
      SolveProgress pr;
      std::memcpy(&pr, buf.data() + at + 1, sizeof(pr));
      at += 1 + sizeof(pr);
      pr.wall_seconds += offset_s;
      next_report = clock->Elapsed() + options.progress_interval_s;
      if (options.progress) options.progress(pr);
    }
    buf.erase(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(at));
  };
  for (;;) {
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, 50);
    if (ready > 0) {
      const ssize_t n = read(fds[0], chunk, sizeof(chunk));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;  // EOF: the child is done (or dead)
      buf.insert(buf.end(), chunk, chunk + n);
      drain();
      continue;
    }
    if (clock->ShouldStop()) {
      kill(pid, SIGKILL);
      stopped = true;
      break;
    }
    if (options.progress && clock->Elapsed() >= next_report) {
      next_report = clock->Elapsed() + options.progress_interval_s;
      SolveProgress pr;
      pr.wall_seconds = clock->Elapsed();
      pr.phase = SolvePhase::kRootLp;
      pr.in_root_lp = true;
      options.progress(pr);
    }
  }
  close(fds[0]);
  const int wstatus = Reap(pid);
  if (stopped) {
    c.outcome.status = SolveStatus::kNoSolutionFound;
    c.outcome.detail = clock->stopped_by_interrupt() ? "interrupted" : "time limit";
    return c;
  }
  if (in_outcome && WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0 && Parse(buf, &c.outcome)) {
    return c;
  }
  c.died = true;
  if (WIFSIGNALED(wstatus)) {
    c.why = "killed by signal " + std::to_string(WTERMSIG(wstatus)) + " (" +
            strsignal(WTERMSIG(wstatus)) + ")";
  } else {
    c.why = "exited with status " + std::to_string(WEXITSTATUS(wstatus)) + " without an outcome";
  }
  return c;
}

}  // namespace thrustsched::milp::internal
