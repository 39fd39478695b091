#include "app/interrupt.h"

#include <pthread.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>

namespace thrustsched::app {
namespace {

std::atomic<bool> g_interrupt{false};
std::atomic<bool> g_test_interrupt_sent{false};

}  // namespace

InterruptWatcher::InterruptWatcher() {
  g_interrupt.store(false);
  sigemptyset(&set_);
  sigaddset(&set_, SIGINT);
  blocked_ = pthread_sigmask(SIG_BLOCK, &set_, &old_) == 0;
  if (blocked_) thread_ = std::thread([this] { Watch(); });
}

InterruptWatcher::~InterruptWatcher() {
  done_.store(true);
  if (thread_.joinable()) thread_.join();
  if (blocked_) {
    timespec zero{0, 0};
    while (sigtimedwait(&set_, nullptr, &zero) == SIGINT) g_interrupt.store(true);
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
}

const std::atomic<bool>* InterruptWatcher::flag() { return &g_interrupt; }

bool InterruptWatcher::interrupted() { return g_interrupt.load(); }

void InterruptWatcher::Watch() {
  // The watcher's own mask: SIGINT blocked, taken only through sigtimedwait.
  pthread_sigmask(SIG_BLOCK, &set_, nullptr);
  while (!done_.load()) {
    timespec wait{0, 100000000};  // 0.1 s: how soon the destructor is noticed
    if (sigtimedwait(&set_, nullptr, &wait) != SIGINT) continue;
    if (g_interrupt.exchange(true)) {
      static const char kMsg[] = "\nsecond Ctrl-C: exiting now\n";
      (void)!write(2, kMsg, sizeof(kMsg) - 1);
      _exit(130);
    }
    static const char kMsg[] =
        "\ninterrupt: stopping the solver, keeping the best solution found (Ctrl-C again to "
        "quit at once)\n";
    (void)!write(2, kMsg, sizeof(kMsg) - 1);
  }
}

void InterruptForTestAtIncumbent(const milp::SolveProgress& p) {
  if (!p.new_incumbent || std::getenv("THRUSTSCHED_TEST_INTERRUPT_AT_INCUMBENT") == nullptr) return;
  if (g_test_interrupt_sent.exchange(true)) return;
  kill(getpid(), SIGINT);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!g_interrupt.load() && std::chrono::steady_clock::now() < until) {
    timespec nap{0, 1000000};  // 1 ms
    nanosleep(&nap, nullptr);
  }
}

}  // namespace thrustsched::app
