// CBC's driver in a child process (see cbc_child.h).
//
// The pipe carries frames: one type byte, a 64-bit payload length, the
// payload. Progress and incumbent payloads are the trivially copyable
// structs of solver.h (same binary on both ends of a fork), followed for an
// incumbent by its column values.
#include "milp/internal/cbc_child.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <string>
#include <type_traits>
#include <vector>

#include "CoinError.hpp"
#include "milp/internal/child_stderr.h"
#include "milp/internal/pipe_io.h"

namespace thrustsched::milp::internal {
namespace {

static_assert(std::is_trivially_copyable<SolveProgress>::value, "frames copy SolveProgress");
static_assert(std::is_trivially_copyable<Incumbent>::value, "frames copy Incumbent");

enum FrameType : char { kProgress = 'P', kIncumbent = 'I', kOutcome = 'O' };

// Fixed part of the outcome frame.
struct OutcomeHeader {
  int status, secondary;
  bool proven_optimal, proven_infeasible, continuous_unbounded, root_lp_stopped, stopped,
      stopped_by_request;
  double bound_min;
  long long nodes;
  long long x_size;
  long long detail_size;
};
static_assert(std::is_trivially_copyable<OutcomeHeader>::value, "frames copy OutcomeHeader");

// ------------------------------------------------------------------ child

std::atomic<bool> g_child_stop{false};

extern "C" void OnStopSignal(int /*signal*/) { g_child_stop.store(true); }

class FrameWriter {
 public:
  explicit FrameWriter(int fd) : fd_(fd) {}
  void Send(char type, const std::vector<char>& payload) {
    const uint64_t size = payload.size();
    WriteAll(&type, 1);
    WriteAll(&size, sizeof(size));
    WriteAll(payload.data(), payload.size());
  }

 private:
  void WriteAll(const void* data, size_t size) { WriteAllOrExit(fd_, data, size); }
  int fd_;
};

template <typename T>
void Append(std::vector<char>* buf, const T& value) {
  const char* p = reinterpret_cast<const char*>(&value);
  buf->insert(buf->end(), p, p + sizeof(T));
}

void AppendVector(std::vector<char>* buf, const Eigen::VectorXd& x) {
  const char* p = reinterpret_cast<const char*>(x.data());
  buf->insert(buf->end(), p, p + sizeof(double) * static_cast<size_t>(x.size()));
}

class ChildListener : public DriverListener {
 public:
  explicit ChildListener(int fd) : writer_(fd) {}
  void OnProgress(const SolveProgress& progress) override {
    std::vector<char> buf;
    Append(&buf, progress);
    writer_.Send(kProgress, buf);
  }
  void OnIncumbent(const Incumbent& incumbent, const Eigen::VectorXd& x_partial) override {
    std::vector<char> buf;
    Append(&buf, incumbent);
    Append(&buf, static_cast<long long>(x_partial.size()));
    AppendVector(&buf, x_partial);
    writer_.Send(kIncumbent, buf);
  }
  bool StopRequested() override { return g_child_stop.load(); }
  void SendOutcome(const DriverOutcome& o) {
    OutcomeHeader h{o.status,
                    o.secondary,
                    o.proven_optimal,
                    o.proven_infeasible,
                    o.continuous_unbounded,
                    o.root_lp_stopped,
                    o.stopped,
                    o.stopped_by_request,
                    o.bound_min,
                    o.nodes,
                    static_cast<long long>(o.x.size()),
                    static_cast<long long>(o.detail.size())};
    std::vector<char> buf;
    Append(&buf, h);
    AppendVector(&buf, o.x);
    buf.insert(buf.end(), o.detail.begin(), o.detail.end());
    writer_.Send(kOutcome, buf);
  }

 private:
  FrameWriter writer_;
};

// The child stops by itself this long before the deadline, so that its
// answer arrives by the deadline (and it is killed at the deadline if not).
double StopMargin(const DriverRequest& request, double grace_s) {
  if (!request.clock.has_deadline()) return 0.0;
  return std::min(grace_s, 0.1 * std::max(0.0, request.options.time_limit_s));
}

[[noreturn]] void ChildMain(const DriverRequest& request, int fd, pid_t parent, double grace_s) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(2);
  // The terminal's signals are the caller's business: keep them blocked here
  // (CBC installs its own SIGINT handler, which then never fires).
  sigset_t block;
  sigemptyset(&block);
  sigaddset(&block, SIGINT);
  sigaddset(&block, SIGTERM);
  sigaddset(&block, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &block, nullptr);
  signal(SIGPIPE, SIG_IGN);
  struct sigaction stop {};
  stop.sa_handler = OnStopSignal;
  sigemptyset(&stop.sa_mask);
  sigaction(SIGUSR1, &stop, nullptr);
  sigset_t usr1;
  sigemptyset(&usr1);
  sigaddset(&usr1, SIGUSR1);
  pthread_sigmask(SIG_UNBLOCK, &usr1, nullptr);

  ChildListener listener(fd);
  DriverOutcome outcome;
  try {
    DriverRequest own{request.lp, request.options, request.clock, request.start_x,
                      request.start_min};
    own.clock.set_interrupt(nullptr);  // the parent's flag does not change here
    own.clock.ShortenDeadline(StopMargin(request, grace_s));
    outcome = RunDriverHere(own, &listener);
  } catch (const CoinError& e) {  // not a std::exception
    outcome.status = -1;
    outcome.detail = "CBC driver failed: CoinError " + e.className() + "::" + e.methodName() +
                     ": " + e.message();
  } catch (const std::exception& e) {
    outcome.status = -1;
    outcome.detail = std::string("CBC driver failed: ") + e.what();
  } catch (...) {
    outcome.status = -1;
    outcome.detail = "CBC driver failed (unknown exception)";
  }
  listener.SendOutcome(outcome);
  // No destructors, no atexit handlers: the parent owns every resource.
  _exit(0);
}

// ----------------------------------------------------------------- parent

class FrameReader {
 public:
  // Appends what is readable; false at end of file.
  bool Fill(int fd) {
    char chunk[1 << 16];
    for (;;) {
      const ssize_t n = read(fd, chunk, sizeof(chunk));
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
      if (n <= 0) return false;
      buf_.insert(buf_.end(), chunk, chunk + n);
      if (static_cast<size_t>(n) < sizeof(chunk)) return true;
    }
  }
  // The next complete frame, if any.
  bool Next(char* type, std::vector<char>* payload) {
    if (buf_.size() < 1 + sizeof(uint64_t)) return false;
    uint64_t size;
    std::memcpy(&size, buf_.data() + 1, sizeof(size));
    const size_t total = 1 + sizeof(uint64_t) + size;
    if (buf_.size() < total) return false;
    *type = buf_[0];
    payload->assign(buf_.begin() + 1 + sizeof(uint64_t), buf_.begin() + static_cast<long>(total));
    buf_.erase(buf_.begin(), buf_.begin() + static_cast<long>(total));
    return true;
  }

 private:
  std::vector<char> buf_;
};

template <typename T>
T Take(const std::vector<char>& buf, size_t* offset) {
  T value;
  std::memcpy(&value, buf.data() + *offset, sizeof(T));
  *offset += sizeof(T);
  return value;
}

Eigen::VectorXd TakeVector(const std::vector<char>& buf, size_t* offset, long long size) {
  Eigen::VectorXd x(size);
  // memcpy's pointers must not be null, even for zero bytes (an empty x has none).
  if (size > 0)
    std::memcpy(x.data(), buf.data() + *offset, sizeof(double) * static_cast<size_t>(size));
  *offset += sizeof(double) * static_cast<size_t>(size);
  return x;
}

DriverOutcome ParseOutcome(const std::vector<char>& buf) {
  size_t at = 0;
  const OutcomeHeader h = Take<OutcomeHeader>(buf, &at);
  DriverOutcome o;
  o.status = h.status;
  o.secondary = h.secondary;
  o.proven_optimal = h.proven_optimal;
  o.proven_infeasible = h.proven_infeasible;
  o.continuous_unbounded = h.continuous_unbounded;
  o.root_lp_stopped = h.root_lp_stopped;
  o.stopped = h.stopped;
  o.stopped_by_request = h.stopped_by_request;
  o.bound_min = h.bound_min;
  o.nodes = h.nodes;
  o.x = TakeVector(buf, &at, h.x_size);
  o.detail.assign(buf.data() + at, static_cast<size_t>(h.detail_size));
  return o;
}

// Follows the child: frames to the listener, stop and kill on time.
class ChildWatch {
 public:
  ChildWatch(const DriverRequest& request, DriverListener* listener, pid_t pid, int fd,
             double stop_grace_s)
      : request_(request), listener_(listener), pid_(pid), fd_(fd), grace_s_(stop_grace_s) {
    sign_ = request.lp.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
  }

  DriverOutcome Run() {
    FrameReader reader;
    bool open = true;
    while (open) {
      pollfd p{fd_, POLLIN, 0};
      const int ready = poll(&p, 1, 50);
      if (ready > 0) open = reader.Fill(fd_);
      char type;
      std::vector<char> payload;
      while (reader.Next(&type, &payload)) Dispatch(type, payload);
      if (open) Supervise();
    }
    int wstatus = 0;
    while (waitpid(pid_, &wstatus, 0) < 0 && errno == EINTR) {
    }
    if (have_outcome_) return outcome_;
    return Synthesized(wstatus);
  }

 private:
  void Dispatch(char type, const std::vector<char>& payload) {
    size_t at = 0;
    if (type == kProgress) {
      SolveProgress p = Take<SolveProgress>(payload, &at);
      // A report made before a heartbeat of ours may arrive after it.
      p.wall_seconds = std::max(p.wall_seconds, last_delivered_);
      last_delivered_ = p.wall_seconds;
      last_phase_ = p.phase;
      if (std::isfinite(p.best_bound)) best_bound_ = p.best_bound;
      if (std::isfinite(p.objective)) objective_ = p.objective;
      nodes_ = p.nodes;
      last_report_ = request_.clock.Elapsed();
      listener_->OnProgress(p);
    } else if (type == kIncumbent) {
      const Incumbent inc = Take<Incumbent>(payload, &at);
      const long long n = Take<long long>(payload, &at);
      listener_->OnIncumbent(inc, TakeVector(payload, &at, n));
    } else if (type == kOutcome) {
      outcome_ = ParseOutcome(payload);
      have_outcome_ = true;
    }
  }

  // Asks the child to stop on request (kill grace_s later) or at its own
  // deadline, the margin before ours (kill at ours).
  void Supervise() {
    const double now = request_.clock.Elapsed();
    const double margin = StopMargin(request_, grace_s_);
    if (stop_sent_at_ < 0.0) {
      if (listener_->StopRequested()) {
        stop_requested_ = true;
        stop_sent_at_ = now;
        kill_at_ = now + grace_s_;
        kill(pid_, SIGUSR1);
      } else if (request_.clock.Remaining() <= margin) {
        stop_sent_at_ = now;
        kill_at_ = now + std::max(0.0, request_.clock.Remaining());
        kill(pid_, SIGUSR1);
      }
    } else if (!stop_requested_ && listener_->StopRequested()) {
      stop_requested_ = true;
      kill_at_ = std::min(kill_at_, now + grace_s_);
    }
    if (stop_sent_at_ >= 0.0 && !killed_ && now >= kill_at_) {
      kill(pid_, SIGKILL);
      killed_ = true;
    }
    if (now - last_report_ >= request_.options.progress_interval_s) {
      // The child is busy in a phase without reports: say so.
      last_report_ = now;
      SolveProgress p;
      p.wall_seconds = std::max(now, last_delivered_);
      last_delivered_ = p.wall_seconds;
      p.phase = stop_sent_at_ >= 0.0 ? SolvePhase::kFinishing : last_phase_;
      p.in_root_lp = p.phase == SolvePhase::kRootLp;
      p.objective = objective_;
      p.best_bound = best_bound_;
      if (std::isfinite(objective_)) p.gap = RelativeGap(objective_, best_bound_);
      p.nodes = nodes_;
      listener_->OnProgress(p);
    }
  }

  // The child ended without its outcome: made of what it reported.
  DriverOutcome Synthesized(int wstatus) {
    DriverOutcome o;
    o.completed = false;
    o.stopped = stop_sent_at_ >= 0.0;
    o.stopped_by_request = stop_requested_;
    o.root_lp_stopped = last_phase_ == SolvePhase::kRootLp;
    o.nodes = nodes_;
    if (std::isfinite(best_bound_)) {
      o.bound_min = sign_ * (best_bound_ - request_.lp.objective_offset);
    }
    if (killed_) {
      o.detail = std::string("the CBC process did not stop in time (") +
                 (stop_requested_ ? "interrupt" : "deadline") +
                 ") and was killed; what it had reported is kept";
    } else if (WIFSIGNALED(wstatus)) {
      o.detail = "the CBC process died (signal " + std::to_string(WTERMSIG(wstatus)) + ": " +
                 strsignal(WTERMSIG(wstatus)) + "); what it had reported is kept";
    } else {
      o.detail = "the CBC process exited with code " +
                 std::to_string(WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1) +
                 " before reporting its outcome";
    }
    return o;
  }

  const DriverRequest& request_;
  DriverListener* listener_;
  pid_t pid_;
  int fd_;
  double grace_s_;
  double sign_ = 1.0;
  double stop_sent_at_ = -1.0;
  double kill_at_ = 0.0;
  bool stop_requested_ = false;
  bool killed_ = false;
  double last_report_ = 0.0;
  double last_delivered_ = 0.0;  // wall time of the last report handed over
  SolvePhase last_phase_ = SolvePhase::kRootLp;
  double best_bound_ = std::numeric_limits<double>::quiet_NaN();
  double objective_ = std::numeric_limits<double>::quiet_NaN();
  long long nodes_ = 0;
  bool have_outcome_ = false;
  DriverOutcome outcome_;
};

}  // namespace

DriverOutcome RunDriverInChild(const DriverRequest& request, DriverListener* listener,
                               double stop_grace_s) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    throw std::runtime_error(std::string("cannot create a pipe for the CBC process: ") +
                             std::strerror(errno));
  }
  const ChildStderr child_stderr;
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    const int err = errno;
    close(fds[0]);
    close(fds[1]);
    throw std::runtime_error(std::string("cannot start the CBC process: ") + std::strerror(err));
  }
  if (pid == 0) {
    close(fds[0]);
    child_stderr.AttachInChild();
    ChildMain(request, fds[1], parent, stop_grace_s);
  }
  close(fds[1]);
  fcntl(fds[0], F_SETFL, fcntl(fds[0], F_GETFL) | O_NONBLOCK);
  DriverOutcome out;
  try {
    out = ChildWatch(request, listener, pid, fds[0], stop_grace_s).Run();
  } catch (...) {
    // A listener threw (e.g. a progress callback): end the child first.
    kill(pid, SIGKILL);
    int wstatus = 0;
    while (waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
    }
    close(fds[0]);
    throw;
  }
  close(fds[0]);
  // A child that died says why on stderr (an assertion of CBC or CLP).
  out.detail += child_stderr.AfterExit(!out.completed);
  return out;
}

}  // namespace thrustsched::milp::internal
