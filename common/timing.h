// Wall-clock durations for reports and time limits, on the monotonic clock
// (a system-clock change must not stretch or cut a time limit).
//
//   const auto t0 = common::Clock::now();
//   ...
//   report.seconds = common::Since(t0);
//
//   common::SolveClock clock(options.time_limit_s, options.interrupt);  // one solve's clock
//   while (!clock.ShouldStop()) Work(clock.Remaining());
//   result.wall_seconds = clock.Elapsed();
//
// steady_clock is system-wide, so a SolveClock copied into a child process
// (fork) keeps the same start and deadline as the parent's.
#ifndef THRUSTSCHED_COMMON_TIMING_H_
#define THRUSTSCHED_COMMON_TIMING_H_

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

namespace thrustsched::common {

using Clock = std::chrono::steady_clock;

/// Seconds elapsed since `t0`.
inline double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// The wall clock and stop sources of one solve: the time since its start,
/// the time left to its limit (+inf without one) and the caller's interrupt
/// flag (null: none). The one implementation of a solve's clock: the CBC
/// backend, row generation and the schedule search all use it.
class SolveClock {
 public:
  SolveClock() : SolveClock(std::numeric_limits<double>::infinity(), nullptr) {}
  /// `time_limit_s` >= 0 or +inf (a non-finite limit means none).
  SolveClock(double time_limit_s, const std::atomic<bool>* interrupt)
      : start_(Clock::now()), interrupt_(interrupt) {
    has_deadline_ = std::isfinite(time_limit_s);
    if (has_deadline_) {
      deadline_ = start_ + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(time_limit_s));
    }
  }

  double Elapsed() const { return Seconds(Clock::now() - start_); }
  bool has_deadline() const { return has_deadline_; }
  /// Seconds to the deadline (negative once passed); +inf without one.
  double Remaining() const {
    if (!has_deadline_) return std::numeric_limits<double>::infinity();
    return Seconds(deadline_ - Clock::now());
  }
  bool DeadlinePassed() const { return has_deadline_ && Clock::now() >= deadline_; }
  bool Interrupted() const {
    return interrupt_ != nullptr && interrupt_->load(std::memory_order_relaxed);
  }
  /// True once interrupted or past the deadline (an interrupt is remembered).
  bool ShouldStop() {
    if (Interrupted()) stopped_by_interrupt_ = true;
    return stopped_by_interrupt_ || DeadlinePassed();
  }
  bool stopped_by_interrupt() const { return stopped_by_interrupt_; }
  /// Moves the start and the deadline later by d (time not charged to the solve).
  void Shift(Clock::duration d) {
    start_ += d;
    deadline_ += d;
  }
  /// Moves the deadline earlier by s seconds (if there is one).
  void ShortenDeadline(double s) {
    deadline_ -= std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
  }
  /// Replaces the interrupt flag (a child process watches its own).
  void set_interrupt(const std::atomic<bool>* interrupt) { interrupt_ = interrupt; }

  static double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

 private:
  Clock::time_point start_;
  Clock::time_point deadline_{};
  bool has_deadline_ = false;
  const std::atomic<bool>* interrupt_ = nullptr;
  bool stopped_by_interrupt_ = false;
};

}  // namespace thrustsched::common

#endif  // THRUSTSCHED_COMMON_TIMING_H_
