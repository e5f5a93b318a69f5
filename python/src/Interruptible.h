// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Long work with Ctrl+C honoured. Python runs its signal handlers only when the main thread
// reaches the interpreter, and a call into C++ holds that thread until it returns: without a
// poll, KeyboardInterrupt waits for the whole batch (13 s for 3000 study cases). One loop for
// every long call: runInterruptibly (python/src/Models.h, surface and critical) and study_rows.

#include "core/sweep/SweepControl.h"

#include <functional>

namespace kinstab::python {

// Runs work on a helper thread with the GIL released while the calling thread polls for signals
// every 50 ms (PyErr_CheckSignals, with the GIL). On a signal whose handler raises (Ctrl+C:
// KeyboardInterrupt) it cancels through control, which work must poll, waits for work to return
// and returns false with the Python error set; true when work ran to its end. An exception of
// work is rethrown on the calling thread.
bool runWatchingSignals(SweepControl& control, const std::function<void()>& work);

} // namespace kinstab::python
