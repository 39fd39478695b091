#include "app/interrupt.h"

#include <pthread.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>

namespace thrustsched::app {
namespace {

std::atomic<bool> g_interrupt{false};
std::atomic<int> g_signal{0};
std::atomic<bool> g_test_interrupt_sent{false};

const char* Name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "";
  }
}

void Say(const char* text) { (void)!write(2, text, std::strlen(text)); }

}  // namespace

InterruptWatcher::InterruptWatcher() {
  g_interrupt.store(false);
  g_signal.store(0);
  sigemptyset(&set_);
  sigaddset(&set_, SIGINT);
  sigaddset(&set_, SIGTERM);
  sigaddset(&set_, SIGHUP);
  blocked_ = pthread_sigmask(SIG_BLOCK, &set_, &old_) == 0;
  if (blocked_) thread_ = std::thread([this] { Watch(); });
}

InterruptWatcher::~InterruptWatcher() {
  done_.store(true);
  if (thread_.joinable()) thread_.join();
  if (blocked_) {
    timespec zero{0, 0};
    for (int sig; (sig = sigtimedwait(&set_, nullptr, &zero)) > 0;) {
      int none = 0;
      g_signal.compare_exchange_strong(none, sig);
      g_interrupt.store(true);
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
}

const std::atomic<bool>* InterruptWatcher::flag() { return &g_interrupt; }

bool InterruptWatcher::interrupted() { return g_interrupt.load(); }

const char* InterruptWatcher::signal_name() { return Name(g_signal.load()); }

void InterruptWatcher::Watch() {
  // The watcher's own mask: the signals blocked, taken only through sigtimedwait.
  pthread_sigmask(SIG_BLOCK, &set_, nullptr);
  while (!done_.load()) {
    timespec wait{0, 100000000};  // 0.1 s: how soon the destructor is noticed
    const int sig = sigtimedwait(&set_, nullptr, &wait);
    if (sig <= 0) continue;
    if (g_interrupt.exchange(true)) {
      Say("\n");
      Say(Name(sig));
      Say(" again: exiting now\n");
      _exit(128 + sig);
    }
    g_signal.store(sig);
    Say("\n");
    Say(Name(sig));
    Say(": stopping the solver, keeping the best schedule found (send it again, e.g. Ctrl-C, "
        "to quit at once)\n");
  }
}

void InterruptSelfAtFirstIncumbent(const milp::SolveProgress& p) {
  if (!p.new_incumbent) return;
  if (g_test_interrupt_sent.exchange(true)) return;
  kill(getpid(), SIGINT);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!g_interrupt.load() && std::chrono::steady_clock::now() < until) {
    timespec nap{0, 1000000};  // 1 ms
    nanosleep(&nap, nullptr);
  }
}

}  // namespace thrustsched::app
