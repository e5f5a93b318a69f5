// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/RunAnalysis.h"

#include "core/base/InputError.h"
#include "core/base/Stopwatch.h"
#include "core/base/TextInput.h"
#include "core/codes/Building.h"
#include "core/slab/FiniteResult.h"
#include "core/sweep/ModelPoint.h"
#include "core/sweep/SearchWork.h"

#include <algorithm>
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

// What a run of the request's sine model costs at f (core/sweep/SearchWork.h).
SineWorkModel sineWork(const AnalysisRequest& q, double frequencyHz) {
    if (q.planar) return planarWork(*q.planarCase(), frequencyHz);
    return {frequencyHz, 1.0, solverCostFactor(q.slab)};
}

// Every search's frequency, before the first run: a search too long for its inputs is refused.
void requireSearchWork(const AnalysisRequest& q, const std::vector<double>& frequencies,
                       double scanFrom, const CriticalSearch& search) {
    for (double f : frequencies)
        if (const InputProblem p = checkSearchWork(q.slab, scanFrom, search, sineWork(q, f));
            !p.empty())
            throw InputError(describe(p));
}

// A code's period (entered, or its own formula's for a very low building) below the shortest
// building period kinstab checks: the sine at 1 / T would be no building's motion.
void requireCheckablePeriod(const CodeResult& r) {
    if (r.periodSeconds >= kMinPeriodS) return;
    throw InputError(r.code + ".period_s = " + formatDouble(r.periodSeconds) + " s: below " +
                     formatDouble(kMinPeriodS) +
                     " s, the shortest building period the slab check accepts (building.period_s, "
                     "or the code's formula from building.height)");
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
    if (!q.grid.amplitudes.empty() && !q.grid.frequencies.empty()) {
        const double aMax = *std::max_element(q.grid.amplitudes.begin(), q.grid.amplitudes.end());
        const double fMax = *std::max_element(q.grid.frequencies.begin(), q.grid.frequencies.end());
        if (const InputProblem p = checkSurfaceWork(q.slab, q.grid.size(), aMax, sineWork(q, fMax));
            !p.empty())
            throw InputError(describe(p));
    }
    const auto t0 = Clock::now();
    out.surface = runSweep(q.grid, m.point, &sweep, q.threads);
    out.surfaceSeconds = secondsSince(t0);
    sweep.onPointDone = nullptr;
}

void runCurve(const AnalysisRequest& q, const ModelPoint& m, AnalysisControl& control,
              AnalysisResult& out) {
    SweepControl& sweep = control.sweepControl();
    sweep.onProgress = [&control](std::size_t, std::size_t) { control.step(); };
    requireSearchWork(q, q.criticalFrequencies, m.scanFrom, q.criticalSearch);
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
        std::vector<double> frequencies;
        for (const CodeResult& r : q.codes) {
            requireCheckablePeriod(r);
            frequencies.push_back(1.0 / r.periodSeconds);
        }
        requireSearchWork(q, frequencies, m.scanFrom, q.checkSearch);
        // designCheck validates the 1-DOF case; the planar model's own inputs run too.
        if (const std::optional<PlanarCase> c = q.planarCase())
            if (const std::string e = validatePlanarCase(*c); !e.empty()) throw InputError(e);
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
    RecordAnalysisInput in{q.slab, *q.record, q.checkSearch, q.codes, true};
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
