// Long C++ work called from Python (solves, checks, the year loop): the work
// runs in a worker thread that never touches Python, the calling thread waits
// with the GIL released, hands the work's progress events to a Python
// callback (with the GIL), and polls Python's signal handlers, so that
//  - other Python threads run during the work (the GIL is free);
//  - the first Ctrl-C (KeyboardInterrupt from the signal handler or from the
//    callback) raises job->stop: the work stops as at a time limit and keeps
//    its best result, which is returned normally;
//  - a second Ctrl-C raises KeyboardInterrupt at once; the worker, already
//    asked to stop, finishes on its own with the data it owns.
//
//   auto job = std::make_shared<Job>();
//   auto data = std::make_shared<MyData>();           // owned by the work
//   RunInterruptible(job, [job, data] {
//     data->options.interrupt = &job->stop;
//     data->options.progress = [job](const milp::SolveProgress& p) {
//       job->Post([p](const py::handle& cb) { cb(ProgressDict(p)); });
//     };
//     data->result = Solve(data->problem, data->options);
//   }, callback);
//   if (job->interrupted()) ...
//
// Signals are only seen in the main thread (CPython runs handlers there), so
// a solve started from another thread is stopped by its own limits only.
// The worker blocks SIGINT, SIGTERM and SIGHUP (so the signal goes to the
// waiting main thread and no system call of the solver is interrupted), and
// the threads it starts (CBC's) inherit that.
#ifndef THRUSTSCHED_PYTHON_RUNNER_H_
#define THRUSTSCHED_PYTHON_RUNNER_H_

#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include <pybind11/pybind11.h>

namespace thrustsched::python {

namespace py = pybind11;

/// Something to do in the calling thread, with the GIL, given the callback
/// (never None when called).
using Event = std::function<void(const py::handle& callback)>;

class Job {
 public:
  /// The stop request handed to the solver (milp::SolveOptions::interrupt).
  std::atomic<bool> stop{false};

  /// From the worker: queues an event for the callback (dropped when there
  /// is no callback). Thread-safe.
  void Post(Event event);
  /// A Ctrl-C (or KeyboardInterrupt raised by the callback) asked the work to stop.
  bool interrupted() const { return interrupts_.load() > 0; }

 private:
  friend void RunInterruptible(const std::shared_ptr<Job>&, std::function<void()>, py::object,
                               const std::string&);
  std::mutex mu_;
  std::condition_variable cv_;
  std::deque<Event> events_;
  bool done_ = false;
  bool has_callback_ = false;
  std::exception_ptr error_;
  std::atomic<int> interrupts_{0};
};

/// Runs `work` as described above; returns when it is done, rethrowing its
/// exception (translated to Python by pybind11). `callback` may be None.
/// `what` names the work in the message printed on the first Ctrl-C.
/// An exception raised by the callback (other than KeyboardInterrupt) stops
/// the work and is re-raised once the work has stopped.
/// @throws py::error_already_set (KeyboardInterrupt) on a second interrupt.
void RunInterruptible(const std::shared_ptr<Job>& job, std::function<void()> work,
                      py::object callback, const std::string& what);

}  // namespace thrustsched::python

#endif  // THRUSTSCHED_PYTHON_RUNNER_H_
