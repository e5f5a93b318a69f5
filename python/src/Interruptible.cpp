// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/Interruptible.h"

#include <pybind11/pybind11.h>

#include <chrono>
#include <future>

namespace py = pybind11;

namespace kinstab::python {

bool runWatchingSignals(SweepControl& control, const std::function<void()>& work) {
    bool interrupted = false;
    py::gil_scoped_release unlocked;
    auto job = std::async(std::launch::async, work);
    while (job.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
        py::gil_scoped_acquire locked;
        if (!interrupted && PyErr_CheckSignals() != 0) {
            interrupted = true;
            control.cancel();
        }
    }
    job.get(); // rethrows work's exception
    return !interrupted;
}

} // namespace kinstab::python
