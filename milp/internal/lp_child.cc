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
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "milp/internal/child_stderr.h"
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

// One child: its process, the read end of its pipe and what came through it.
struct Child {
  pid_t pid = -1;
  int fd = -1;  // closed (-1) at EOF
  std::vector<char> buf;
  double offset_s = 0.0;  // the parent's clock when the child's started
  bool in_outcome = false;
  LpChildOutcome result;
  std::unique_ptr<ChildStderr> err;  // what the child writes to stderr
};

// Forks the child for `job`; on failure marks the result as died.
void Start(const LpCoreJob& job, const SolveOptions& options, SolveClock* clock, Child* c) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    c->result.died = true;
    c->result.why = std::string("pipe: ") + std::strerror(errno);
    return;
  }
  c->err = std::make_unique<ChildStderr>();
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    c->result.died = true;
    c->result.why = std::string("fork: ") + std::strerror(errno);
    return;
  }
  if (pid == 0) {
    close(fds[0]);
    c->err->AttachInChild();
    RunChild(fds[1], *job.lp, *job.arrays, options, clock->Remaining());
  }
  close(fds[1]);
  c->pid = pid;
  c->fd = fds[0];
  c->offset_s = clock->Elapsed();
}

// Hands on the progress frames at the front of c->buf; stops at the outcome.
// Returns whether a report went on.
bool Drain(const SolveOptions& options, Child* c) {
  size_t at = 0;
  bool reported = false;
  while (!c->in_outcome && at < c->buf.size()) {
    if (c->buf[at] == kOutcomeFrame) {
      c->in_outcome = true;
      ++at;
      break;
    }
    if (c->buf.size() - at < 1 + sizeof(SolveProgress)) break;
    SolveProgress pr;
    std::memcpy(&pr, c->buf.data() + at + 1, sizeof(pr));
    at += 1 + sizeof(pr);
    pr.wall_seconds += c->offset_s;
    reported = true;
    if (options.progress) options.progress(pr);
  }
  c->buf.erase(c->buf.begin(), c->buf.begin() + static_cast<std::ptrdiff_t>(at));
  return reported;
}

// Reaps the child and turns what it sent into its outcome.
void Finish(bool stopped, SolveClock* clock, Child* c) {
  if (c->fd >= 0) close(c->fd);
  c->fd = -1;
  const int wstatus = Reap(c->pid);
  LpChildOutcome& r = c->result;
  if (stopped) {
    r.outcome.status = SolveStatus::kNoSolutionFound;
    r.outcome.detail = clock->stopped_by_interrupt() ? "interrupted" : "time limit";
    return;
  }
  if (c->in_outcome && WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0 &&
      Parse(c->buf, &r.outcome)) {
    c->err->AfterExit(false);
    return;
  }
  r.died = true;
  if (WIFSIGNALED(wstatus)) {
    r.why = "killed by signal " + std::to_string(WTERMSIG(wstatus)) + " (" +
            strsignal(WTERMSIG(wstatus)) + ")";
  } else {
    r.why = "exited with status " + std::to_string(WEXITSTATUS(wstatus)) + " without an outcome";
  }
  r.why += c->err->AfterExit(true);  // an assertion of CLP, say
}

}  // namespace

std::vector<LpChildOutcome> SolveLpCoresInChildren(const std::vector<LpCoreJob>& jobs,
                                                   const SolveOptions& options, SolveClock* clock) {
  // Every child is forked here, from this one thread, before any is read:
  // a fork taken while another thread of this process holds a lock (of the
  // allocator, say) can leave the child waiting on that lock forever.
  std::vector<Child> children(jobs.size());
  for (size_t i = 0; i < jobs.size(); ++i) Start(jobs[i], options, clock, &children[i]);
  double next_report = clock->Elapsed() + options.progress_interval_s;
  bool stopped = false;
  char chunk[1 << 16];
  std::vector<pollfd> polled;
  std::vector<Child*> owner;
  for (;;) {
    polled.clear();
    owner.clear();
    for (Child& c : children) {
      if (c.fd < 0) continue;
      polled.push_back(pollfd{c.fd, POLLIN, 0});
      owner.push_back(&c);
    }
    if (polled.empty()) break;
    const int ready = poll(polled.data(), polled.size(), 50);
    if (ready > 0) {
      for (size_t k = 0; k < polled.size(); ++k) {
        if (polled[k].revents == 0) continue;
        Child& c = *owner[k];
        const ssize_t n = read(c.fd, chunk, sizeof(chunk));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {  // EOF: the child is done (or dead)
          close(c.fd);
          c.fd = -1;
          continue;
        }
        c.buf.insert(c.buf.end(), chunk, chunk + n);
        if (Drain(options, &c)) next_report = clock->Elapsed() + options.progress_interval_s;
      }
      continue;
    }
    if (clock->ShouldStop()) {
      for (Child& c : children) {
        if (c.fd >= 0) kill(c.pid, SIGKILL);
      }
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
  std::vector<LpChildOutcome> out;
  out.reserve(children.size());
  for (Child& c : children) {
    // A child that ended before the stop keeps its outcome.
    if (c.pid > 0) Finish(stopped && c.fd >= 0, clock, &c);
    out.push_back(std::move(c.result));
  }
  return out;
}

LpChildOutcome SolveLpCoreInChild(const LpData& lp, const CoinArrays& arrays,
                                  const SolveOptions& options, SolveClock* clock) {
  return SolveLpCoresInChildren({LpCoreJob{&lp, &arrays}}, options, clock).front();
}

}  // namespace thrustsched::milp::internal
