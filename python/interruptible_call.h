// Long C++ work called from Python that Ctrl-C can interrupt. Python runs its signal
// handlers (KeyboardInterrupt) only on the main thread and only between bytecodes, so a
// solve running on the calling thread with the GIL released could not be interrupted. Here
// the work runs on a thread of its own while the calling thread, the GIL released, waits
// for it and takes the GIL every 50 ms to run Python's handlers (PyErr_CheckSignals). When
// a handler raises (Ctrl-C: KeyboardInterrupt), `stop` is set (solvers read it through
// SolveLimits::stop and end at their next budget check), the work is waited for and the
// handler's exception is raised; otherwise the work's result is returned, or its exception
// rethrown. Work that calls back into Python takes the GIL itself, as it would anyway.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace sightline::python {

// Called with the GIL held; returns work()'s result.
template <class Work>
auto call_interruptibly(std::atomic<bool>& stop, Work work) -> decltype(work()) {
  namespace py = pybind11;
  std::optional<decltype(work())> result;
  std::exception_ptr error;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::thread worker([&] {
    try {
      result.emplace(work());
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mutex);
    done = true;
    finished.notify_all();
  });
  std::optional<py::error_already_set> interrupt;
  while (true) {
    {
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock(mutex);
      if (finished.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; })) break;
    }
    if (!interrupt && PyErr_CheckSignals() != 0) {
      interrupt.emplace();  // the handler's exception, raised once the work has stopped
      stop.store(true, std::memory_order_relaxed);
    }
  }
  worker.join();
  if (interrupt) throw std::move(*interrupt);
  if (error) std::rethrow_exception(error);
  return std::move(*result);
}

}  // namespace sightline::python
