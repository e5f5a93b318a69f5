// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The speed of the block's solver (kinstab-cli bench --rocking; issue 32's targets): one pulse
// run, and the 257 x 257 overturning map of the one-sine pulse of Zhang & Makris 2001 (alpha
// 0.25, p 2.14 rad/s, eta 0.9) with the linearised and the exact equations. Timing belongs here
// and in the bench command only, never in the tests.

#include "core/numerics/Timing.h"

#include <cstddef>

namespace kinstab {

struct RockingBenchmark {
    TimingStats pulseRun;  // seconds per run: Makris & Roussos's block, half-sine 0.5 g 1 Hz
    int runsPerTiming = 0; // runs timed together for each of pulseRun's samples
    TimingStats mapLinear; // the whole map
    TimingStats mapExact;
    std::size_t mapPoints = 0;
    std::size_t overturnsLinear = 0, overturnsExact = 0; // points that overturn
    int threads = 0;
};

// repeats timed runs of each after a warm-up; threads <= 0: all hardware threads.
RockingBenchmark benchmarkRocking(int mapPoints, int repeats, int threads);

} // namespace kinstab
