// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/RunAnalysis.h"

#include "core/base/Stopwatch.h"
#include "core/slab/FiniteResult.h"
#include "core/sweep/ModelPoint.h"

#include <chrono>
#include <stdexcept>

namespace kinstab {

namespace {

using Clock = SteadyClock;

ModelPoint requestModel(const AnalysisRequest& q) {
    ModelPoint m = modelPoint(q.slab, q.planar);
    if (q.requireSoundRuns && !q.planar)
        m.point = [c = q.slab](double amplitude, double frequency) {
            const SlabResult s = runSlab1D(c, amplitude, frequency);
            requireSound(s, caseName(c, amplitude, frequency));
            return PointResult{s.outcome, s.tauC};
        };
    return m;
}

// For the searches: after a cancel a run returns at once, so a search ends within one run (its
// result is then dropped). The surface keeps the plain point: each of its points is one run.
PointFunction stoppable(const PointFunction& point, const SweepControl& control) {
    return [&control, point](double amplitude, double frequency) {
        if (control.isCancelled()) return PointResult{Outcome::Failed, 0};
        return point(amplitude, frequency);
    };
}

void runSurface(const AnalysisRequest& q, const ModelPoint& m, AnalysisControl& control,
                AnalysisResult& out) {
    SweepControl& sweep = control.sweepControl();
    sweep.onPointDone = [&control](std::size_t k, const PointResult& r) {
        control.step();
        if (control.onPoint) control.onPoint(k, r);
    };
    const auto t0 = Clock::now();
    out.surface = runSweep(q.grid, m.point, &sweep, q.threads);
    out.surfaceSeconds = secondsSince(t0);
    sweep.onPointDone = nullptr;
}

void runCurve(const AnalysisRequest& q, const ModelPoint& m, AnalysisControl& control,
              AnalysisResult& out) {
    SweepControl& sweep = control.sweepControl();
    sweep.onProgress = [&control](std::size_t, std::size_t) { control.step(); };
    const auto t0 = Clock::now();
    out.critical = criticalCurve(stoppable(m.point, sweep), q.criticalFrequencies, m.scanFrom,
                                 q.criticalSearch, &sweep, q.threads);
    out.criticalSeconds = secondsSince(t0);
    sweep.onProgress = nullptr;
}

// A bad case, search or period is kept in checkError: the surface computed before stays.
void runDesignCheck(const AnalysisRequest& q, const ModelPoint& m, AnalysisControl& control,
                    AnalysisResult& out) {
    const auto t0 = Clock::now();
    try {
        out.check = designCheck(q.codes, q.slab, q.checkSearch,
                                stoppable(m.point, control.sweepControl()), m.scanFrom);
    } catch (...) {
        out.checkError = std::current_exception();
    }
    out.checkSeconds = secondsSince(t0);
    control.step();
}

void runRecordCheck(const AnalysisRequest& q, AnalysisControl& control, AnalysisResult& out) {
    if (!q.record) throw std::invalid_argument("record check asked for without a record");
    RecordAnalysisInput in{q.slab, *q.record, q.checkSearch, q.codes, true, false};
    const auto t0 = Clock::now();
    out.record = analyseRecord(in, &control.sweepControl());
    out.recordSeconds = secondsSince(t0);
    control.step();
}

} // namespace

std::size_t analysisSteps(const AnalysisRequest& q) {
    return (q.parts.surface ? q.grid.size() : 0) +
           (q.parts.criticalCurve ? q.criticalFrequencies.size() : 0) +
           (q.parts.designCheck ? 1 : 0) + (q.parts.recordCheck ? 1 : 0);
}

AnalysisResult runAnalysis(const AnalysisRequest& q, AnalysisControl& control) {
    control.begin(analysisSteps(q));
    const ModelPoint m = requestModel(q);
    AnalysisResult out;
    out.tauRef = m.tauRef;
    out.scanFrom = m.scanFrom;
    if (q.parts.surface) runSurface(q, m, control, out);
    if (q.parts.criticalCurve && !control.isCancelled()) runCurve(q, m, control, out);
    if (q.parts.designCheck && !control.isCancelled()) runDesignCheck(q, m, control, out);
    if (q.parts.recordCheck && !control.isCancelled()) runRecordCheck(q, control, out);
    out.cancelled = control.isCancelled();
    if (out.cancelled) { // what the searches found after the cancel may be cut short
        out.critical.reset();
        out.check.reset();
        out.checkError = nullptr;
        out.record.reset();
    }
    return out;
}

} // namespace kinstab
