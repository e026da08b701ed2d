#pragma once
// Ctrl-C (SIGINT, Jupyter's "Interrupt kernel") during a long run from Python. A run releases
// the GIL, so Python's signal handler only sets a flag; these checks ask Python about it from
// the run's progress callback, at most every 0.1 s of wall time, with the GIL taken for the
// question only.

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <memory>

namespace cosserat::python {

/// Thrown out of a run whose Python caller was interrupted; the binding turns it back into the
/// KeyboardInterrupt Python has set (pybind11::error_already_set).
struct Interrupted : std::exception {
  const char* what() const noexcept override { return "interrupted"; }
};

/// Whether Python has a signal pending (its handler raised: KeyboardInterrupt for SIGINT),
/// asked at most every 0.1 s; call without the GIL.
class InterruptCheck {
 public:
  bool Pending() {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(100)) return false;
    last_ = now;
    pybind11::gil_scoped_acquire acquire;
    return PyErr_CheckSignals() != 0;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

/// A progress callback for run::RunOptions that throws Interrupted when Python has a signal
/// pending.
inline std::function<void(double, double)> InterruptibleProgress() {
  auto check = std::make_shared<InterruptCheck>();
  return [check](double, double) {
    if (check->Pending()) throw Interrupted{};
  };
}

}  // namespace cosserat::python
