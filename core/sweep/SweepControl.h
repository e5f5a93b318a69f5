// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Cancellation and progress for long work, shared between a worker and whoever watches it.
// An atomic flag (a plain bool would be a data race, as in QGIS's QgsFeedback).

#include <atomic>
#include <cstddef>
#include <functional>

namespace kinstab {

struct PointResult; // core/sweep/Sweep.h

class SweepControl {
public:
    void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
    bool isCancelled() const { return cancelled_.load(std::memory_order_relaxed); }

    // Called from worker threads with (points done, total); keep it cheap and thread-safe.
    std::function<void(std::size_t, std::size_t)> onProgress;
    // Called from worker threads when one grid point is finished: its index into the grid
    // (row-major, as SweepResult::points) and its result.
    std::function<void(std::size_t, const PointResult&)> onPointDone;

private:
    std::atomic<bool> cancelled_{false};
};

} // namespace kinstab
