// PyJob.h -- a long computation called from Python: it runs on a worker thread with the GIL released, while
// the calling thread keeps the interpreter responsive: it checks for signals (Ctrl-C stops the computation
// through its ToolControl and raises KeyboardInterrupt) and calls the optional progress callback, both on the
// caller's own thread, so that the computation itself never touches Python.
#pragma once
#include "dynamics/tools/ToolControl.h"

#include <functional>
#include <pybind11/pybind11.h>

namespace rv::py {

/// Runs `work` to its end. `progress` is None or a callable taking the fraction done in [0, 1]. Exceptions of
/// `work` propagate; a signal's Python exception (KeyboardInterrupt) or one raised by the callback is raised
/// once `work` has stopped.
void runJob(const pybind11::object& progress, const std::function<void(const ToolControl&)>& work);

} // namespace rv::py
