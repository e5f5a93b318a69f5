// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Progress, cancel and a per-point hook for one runAnalysis (core/analysis/RunAnalysis.h), shared
// between the worker and whoever watches it: the watcher polls done() / total() (atomics, no
// lock), and onPoint hands over each γc grid point with its index as it is finished, so a view
// can paint points as they come.

#include "core/sweep/Sweep.h"
#include "core/sweep/SweepControl.h"

#include <atomic>
#include <cstddef>
#include <functional>

namespace kinstab {

class AnalysisControl {
public:
    void cancel() { sweep_.cancel(); }
    bool isCancelled() const { return sweep_.isCancelled(); }
    // Steps done and planned: one per grid point, one per A_crit frequency, one per check.
    std::size_t done() const { return done_.load(std::memory_order_relaxed); }
    std::size_t total() const { return total_.load(std::memory_order_relaxed); }

    // Called from worker threads once per finished γc grid point: its index (row-major, as
    // SweepResult::points) and its result. Keep it cheap and thread-safe.
    std::function<void(std::size_t index, const PointResult& result)> onPoint;

    // For runAnalysis: the control its sweeps and searches poll, and the step count.
    SweepControl& sweepControl() { return sweep_; }
    void begin(std::size_t total) { total_.store(total, std::memory_order_relaxed); }
    void step() { done_.fetch_add(1, std::memory_order_relaxed); }

private:
    SweepControl sweep_;
    std::atomic<std::size_t> done_{0};
    std::atomic<std::size_t> total_{0};
};

} // namespace kinstab
