// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/check/RecordBenchmark.h"

#include "core/check/RecordAnalysis.h"
#include "core/slab/RecordRun.h"
#include "core/sweep/CriticalRecordScale.h"
#include "core/sweep/Sweep.h"

#include <cmath>

namespace kinstab {

namespace {

// A sine run takes tens of microseconds, near the CPU clock's grain: it is timed as a batch and
// divided back, so that each figure is per run.
TimingStats perRun(TimingStats t, int batch) {
    t.minSeconds /= batch;
    t.medianSeconds /= batch;
    t.medianCpuSeconds /= batch;
    return t;
}

} // namespace

RecordBenchmark benchmarkRecord(const Slab1DCase& c, const RecordExcitation& record,
                                const CriticalSearch& search, double amplitude, double frequency,
                                int repeats) {
    RecordBenchmark b;
    b.sineAmplitude = amplitude;
    b.sineFrequency = frequency;
    b.sineBatch = 32;
    const PointFunction sine = slab1DPoint(c);
    volatile double sink = 0; // keeps the timed results alive
    const auto recordRun = [&] {
        const RecordAnalysis a = recordMotions(record, c);
        sink = runRecord1D(c, a.motion, a.peak).tauEnd;
    };
    PairedTiming t = timePaired(
        recordRun,
        [&] {
            for (int i = 0; i < b.sineBatch; ++i)
                sink = sine(amplitude, frequency).tauC;
        },
        repeats);
    b.recordRun = t.first;
    b.sineRun = perRun(t.second, b.sineBatch);
    b.recordOverSine = t.ratioWall * b.sineBatch;
    b.recordOverSineCpu = t.ratioCpu * b.sineBatch;

    const RecordAnalysis a = recordMotions(record, c);
    t = timePaired([&] { sink = fitOrNone(a.motion) ? 1.0 : 0.0; }, recordRun, repeats);
    b.fit = t.first;
    b.fitRecordRun = t.second;
    b.fitShare = t.ratioWall;
    b.fitShareCpu = t.ratioCpu;

    t = timePaired(
        [&] { b.recordCriticalRuns = criticalRecordScale(c, a.motion, search).runs; },
        [&] { b.sineCriticalRuns = criticalAmplitude(sine, frequency, c.slab.mu, search).runs; },
        repeats);
    b.recordCritical = t.first;
    b.sineCritical = t.second;
    b.criticalRatio = t.ratioWall;
    b.criticalRatioCpu = t.ratioCpu;
    return b;
}

} // namespace kinstab
