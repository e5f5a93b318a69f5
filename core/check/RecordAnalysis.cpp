// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/check/RecordAnalysis.h"

#include "core/base/Stopwatch.h"
#include "core/codes/Building.h"
#include "core/excitation/RecordedMotion.h"
#include "core/slab/RecordRun.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace kinstab {

std::string validateRecordAnalysis(const RecordAnalysisInput& in) {
    if (std::string e = validateCase(in.slab); !e.empty()) return "slab: " + e;
    if (in.slab.solver != SolverKind::Exact)
        return "slab.solver = paper: only the exact solver runs recorded motions";
    if (std::string e = validateRecordExcitation(in.record); !e.empty()) return e;
    if (in.critical) return validateCriticalSearch(in.search);
    return {};
}

std::optional<double> recordTauRef(const std::optional<EnvelopeFit>& fit, const Slab1DCase& c) {
    if (c.scale == TauScale::One) return 1.0;
    if (!fit) return std::nullopt;
    return Envelope{fit->alpha, fit->beta, std::nullopt}.tauRef(c.scale, c.tstar);
}

std::optional<EnvelopeFit> fitOrNone(const Accelerogram& motion, std::string* why) {
    try {
        return fitEnvelope(motion);
    } catch (const std::invalid_argument& e) {
        if (why) *why = e.what(); // too few half cycles: gamma_c has no reference time
        return std::nullopt;
    }
}

RecordAnalysis recordMotions(const RecordExcitation& record, const Slab1DCase& slab) {
    RecordAnalysis a;
    a.ground = readGroundRecord(record);
    a.motion = drivingMotion(record, a.ground);
    a.peak = scaledPeak(record, a.motion);
    if (const std::string e = validateRecordedMotion(a.motion, slab.tstar, a.peak); !e.empty())
        throw std::invalid_argument("excitation.record: " + e);
    a.scaleFactor = a.peak / std::abs(a.motion.peak().value);
    a.fit = fitOrNone(a.motion, &a.fitError);
    a.tauRef = recordTauRef(a.fit, slab);
    return a;
}

namespace {
// The runs of the critical search, cancellable and counted for progress.
PointFunction watchedPoint(PointFunction point, SweepControl* control, long estimate) {
    auto runs = std::make_shared<long>(0);
    return [point, control, estimate, runs](double peak, double f) {
        if (control && control->isCancelled()) return PointResult{Outcome::Failed, std::nan("")};
        const PointResult r = point(peak, f);
        ++*runs;
        if (control && control->onProgress)
            control->onProgress(static_cast<std::size_t>(std::min(*runs, estimate)),
                                static_cast<std::size_t>(estimate));
        return r;
    };
}

long runEstimate(const CriticalSearch& s, double mu) {
    const double scan = std::ceil(std::max(0.0, s.to - std::max(s.from, mu)) / s.scanStep);
    return 1 + static_cast<long>(scan) +
           static_cast<long>(std::ceil(std::log2(s.scanStep / s.tolerance)));
}
} // namespace

RecordAnalysis analyseRecord(const RecordAnalysisInput& in, SweepControl* control,
                             SlabRecorder* recorder) {
    if (const std::string e = validateRecordAnalysis(in); !e.empty())
        throw std::invalid_argument(e);
    RecordAnalysis a = recordMotions(in.record, in.slab);
    auto t0 = std::chrono::steady_clock::now();
    a.run = runRecord1D(in.slab, a.motion, a.peak, {}, recorder);
    a.runSeconds = secondsSince(t0);
    if (!in.critical) return a;
    t0 = std::chrono::steady_clock::now();
    const PointFunction point = watchedPoint(recordPoint(in.slab, a.motion), control,
                                             runEstimate(in.search, in.slab.slab.mu));
    a.critical =
        criticalRecordScale(point, in.slab.slab.mu, std::abs(a.motion.peak().value), in.search);
    a.criticalSeconds = secondsSince(t0);
    a.cancelled = control && control->isCancelled();
    if (a.cancelled) {
        a.critical.reset();
        return a;
    }
    a.verdicts = recordVerdicts(in.codes, *a.critical, in.search);
    return a;
}

} // namespace kinstab
