// Worker thread + signal polling for long C++ work (see runner.h).
//
//   RunInterruptible(job, [job, data] { data->result = Work(&job->stop); }, callback, "solve");
#include "runner.h"

#include <pthread.h>
#include <signal.h>

#include <chrono>
#include <thread>
#include <utility>
#include <vector>

namespace thrustsched::python {

void Job::Post(Event event) {
  {
    std::lock_guard<std::mutex> lock(mu_);
    if (!has_callback_) return;
    events_.push_back(std::move(event));
  }
  cv_.notify_all();
}

namespace {

// Message of the first interrupt, on Python's sys.stderr (a notebook shows it).
void SayStopping(const std::string& what) {
  try {
    py::module_ sys = py::module_::import("sys");
    py::object err = sys.attr("stderr");
    if (!err.is_none()) {
      err.attr("write")("thrustsched: interrupted: stopping the " + what +
                        " and keeping the best result found (interrupt again to abort)\n");
      err.attr("flush")();
    }
  } catch (const py::error_already_set&) {
    // A broken stderr must not turn the stop request into an error.
  }
}

[[noreturn]] void RaiseKeyboardInterrupt() {
  PyErr_SetNone(PyExc_KeyboardInterrupt);
  throw py::error_already_set();
}

}  // namespace

void RunInterruptible(const std::shared_ptr<Job>& job, std::function<void()> work,
                      py::object callback, const std::string& what) {
  job->has_callback_ = !callback.is_none();
  std::thread worker([job, work = std::move(work)] {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    try {
      work();
    } catch (...) {
      job->error_ = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(job->mu_);
      job->done_ = true;
    }
    job->cv_.notify_all();
  });

  // Leaving with the worker still running (second interrupt, or an error
  // here): it was asked to stop and owns what it uses, so let it finish alone.
  struct DetachGuard {
    std::thread& worker;
    Job& job;
    ~DetachGuard() {
      if (worker.joinable()) {
        job.stop.store(true);
        worker.detach();
      }
    }
  } guard{worker, *job};

  std::unique_ptr<py::error_already_set> callback_error;
  // Returns normally on the first interrupt, throws on the second.
  auto on_interrupt = [&] {
    job->stop.store(true);
    if (job->interrupts_.fetch_add(1) > 0) RaiseKeyboardInterrupt();
    SayStopping(what);
    if (callback.is_none() || callback_error) return;
    // Tell the callback (it may raise KeyboardInterrupt: the second one).
    py::dict d;
    d["phase"] = "stopping";
    d["message"] = "interrupted: stopping the " + what + ", keeping the best result found";
    try {
      callback(d);
    } catch (py::error_already_set& e) {
      if (e.matches(PyExc_KeyboardInterrupt)) {
        job->interrupts_.fetch_add(1);
        throw;
      }
      callback_error = std::make_unique<py::error_already_set>(std::move(e));
    }
  };

  for (;;) {
    std::deque<Event> events;
    bool done = false;
    {
      py::gil_scoped_release nogil;
      std::unique_lock<std::mutex> lock(job->mu_);
      job->cv_.wait_for(lock, std::chrono::milliseconds(100),
                        [&] { return job->done_ || !job->events_.empty(); });
      events.swap(job->events_);
      done = job->done_;
    }
    for (Event& e : events) {
      if (callback.is_none() || callback_error) continue;
      try {
        e(callback);
      } catch (py::error_already_set& err) {
        if (err.matches(PyExc_KeyboardInterrupt)) {
          on_interrupt();
        } else {
          job->stop.store(true);
          callback_error = std::make_unique<py::error_already_set>(std::move(err));
        }
      }
    }
    if (done) break;
    if (PyErr_CheckSignals() != 0) {
      py::error_already_set err;  // fetches and clears the pending exception
      if (err.matches(PyExc_KeyboardInterrupt)) {
        on_interrupt();
      } else if (!callback_error) {
        // A signal handler of the user's raised something else: stop, re-raise it.
        job->stop.store(true);
        callback_error = std::make_unique<py::error_already_set>(std::move(err));
      }
    }
  }
  {
    py::gil_scoped_release nogil;
    worker.join();
  }
  if (callback_error) throw std::move(*callback_error);
  if (job->error_) std::rethrow_exception(job->error_);
}

}  // namespace thrustsched::python
