// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Temporary files removed when the process is told to stop (SIGINT from Ctrl+C, SIGTERM from
// kill, scancel or a Slurm time limit, SIGHUP from a closed terminal), so that an interrupted
// write leaves nothing behind. The handler only unlinks the armed paths and re-raises the
// signal with its default action: unlink and raise are async-signal-safe, the slots are
// lock-free atomics and fixed buffers, and nothing is allocated. kill -9 cannot be caught: its
// temporary file stays (study --resume continues from it).
//
// Only kinstab-cli installs the handler; the GUI and the Python module leave the signals to
// their event loops, and arming a path there does nothing.

#include <string>

namespace kinstab {

// Installs the handler for SIGINT, SIGTERM and SIGHUP (once, at start-up). With a name, SIGINT
// and SIGTERM also print one line on stderr ("kinstab-cli surface: interrupted (SIGINT)"), after
// clearing a progress line when stderr is a terminal; SIGHUP prints nothing (no terminal left).
void removeTemporariesOnSignals(const char* name = nullptr);

// A path armed for removal while this object lives (or until disarm()). Up to 16 at a time;
// beyond that, or for a path longer than PATH_MAX, nothing is armed (the file is still removed
// by its writer on any ordinary failure).
class RemovedOnSignal {
public:
    explicit RemovedOnSignal(const std::string& path);
    ~RemovedOnSignal() { disarm(); }
    RemovedOnSignal(const RemovedOnSignal&) = delete;
    RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;
    void disarm(); // once the file is renamed into place: from then on it is the output

private:
    int slot_ = -1;
};

} // namespace kinstab
