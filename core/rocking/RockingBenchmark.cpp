// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/RockingBenchmark.h"

#include "core/rocking/OverturningMap.h"
#include "core/rocking/RockingSolver.h"
#include "core/sweep/ParallelFor.h"

#include <algorithm>

namespace kinstab {

namespace {

std::size_t countOverturns(const OverturningMap& m) {
    return static_cast<std::size_t>(std::count(m.overturns.begin(), m.overturns.end(), 1));
}

} // namespace

RockingBenchmark benchmarkRocking(int mapPoints, int repeats, int threads) {
    RockingBenchmark b;
    RockingModel block;
    block.block = {0.2, 0.6};
    Pulse pulse;
    pulse.shape = PulseShape::HalfSine;
    pulse.frequencyHz = 1.0;
    pulse.amplitude = 0.5;
    const PulseMotion motion(pulse);
    // One run takes tens of microseconds: time batches, report per run.
    b.runsPerTiming = 200;
    TimingStats batch = timeRuns(
        [&] {
            for (int i = 0; i < b.runsPerTiming; ++i)
                simulateRocking(block, motion);
        },
        repeats);
    const double per = 1.0 / b.runsPerTiming;
    b.pulseRun = {batch.minSeconds * per, batch.medianSeconds * per, batch.medianCpuSeconds * per,
                  batch.runs};

    RockingModel zm;
    zm.block = blockFromAlphaP(0.25, 2.14);
    zm.restitution = 0.9;
    OverturningMapSpec spec;
    spec.shape = PulseShape::OneSine;
    spec.amplitudePoints = spec.frequencyPoints = mapPoints;
    spec.threads = threads;
    b.threads = poolThreads(threads, static_cast<std::size_t>(mapPoints) * mapPoints);
    b.mapPoints = static_cast<std::size_t>(mapPoints) * static_cast<std::size_t>(mapPoints);
    zm.equations = RockingEquations::Linearised;
    b.mapLinear =
        timeRuns([&] { b.overturnsLinear = countOverturns(overturningMap(zm, spec)); }, repeats);
    zm.equations = RockingEquations::Exact;
    b.mapExact =
        timeRuns([&] { b.overturnsExact = countOverturns(overturningMap(zm, spec)); }, repeats);
    return b;
}

} // namespace kinstab
