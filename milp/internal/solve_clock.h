// The wall clock and stop sources of one solve (internal to the CBC backend).
//
//   SolveClock clock(options.time_limit_s, options.interrupt);
//   while (!clock.ShouldStop()) Work();
//   if (clock.stopped_by_interrupt()) ...
//
// steady_clock is system-wide, so a clock copied into a child process (fork)
// keeps the same start and deadline as the parent's.
#ifndef THRUSTSCHED_MILP_INTERNAL_SOLVE_CLOCK_H_
#define THRUSTSCHED_MILP_INTERNAL_SOLVE_CLOCK_H_

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

namespace thrustsched::milp::internal {

class SolveClock {
 public:
  using Clock = std::chrono::steady_clock;

  SolveClock() : SolveClock(std::numeric_limits<double>::infinity(), nullptr) {}
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

}  // namespace thrustsched::milp::internal

#endif  // THRUSTSCHED_MILP_INTERNAL_SOLVE_CLOCK_H_
