// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/CaseCritical.h"

#include "core/check/RecordAnalysis.h"
#include "core/excitation/FourierSpectrum.h"
#include "core/sweep/CriticalRecordScale.h"
#include "core/sweep/SearchWork.h"
#include "core/sweep/Sweep.h"

#include <cmath>

namespace kinstab {

namespace {

CaseCritical recordCritical(const Slab1DCase& slab, const Accelerogram& motion,
                            const CriticalSearch& search) {
    const RecordCriticalScale crit = criticalRecordScale(slab, motion, search);
    return {crit.peak, crit.motionPeak, crit.runs, {}};
}

// The surrogate is scaled as a whole like the record it stands for: its amplitude at the
// unscaled record is the fitted envelope's peak.
CaseCritical fittedSineCritical(Slab1DCase slab, const Accelerogram& motion,
                                const CriticalSearch& search) {
    CaseCritical out;
    out.unitPeak = std::abs(motion.peak().value); // the limit's intensity when there is no fit
    const std::optional<EnvelopeFit> fit = fitOrNone(motion, &out.noFit);
    if (!fit) return out;
    if (const std::string e = validateEnvelope(fit->alpha, fit->beta); !e.empty()) {
        out.noFit = "the fitted envelope: " + e;
        return out;
    }
    const auto peaks = spectrumPeaks(amplitudeSpectrum(motion.samples, motion.dt), 1);
    if (peaks.empty() || !(peaks.front().frequency > 0.0)) {
        out.noFit = "the motion's spectrum has no peak above 0 Hz";
        return out;
    }
    slab.envelope = Envelope{fit->alpha, fit->beta, std::nullopt};
    const double f = peaks.front().frequency;
    if (const InputProblem p =
            checkSearchWork(slab, slab.slab.mu, search, {f, 1.0, solverCostFactor(slab)});
        !p.empty()) {
        out.noFit = "the fitted sine: " + describe(p);
        return out;
    }
    const CriticalResult r = criticalAmplitude(slab1DPoint(slab), f, slab.slab.mu, search);
    return {r.amplitude, fit->peak(), r.runs, {}};
}

} // namespace

CaseCritical caseCritical(const Slab1DCase& slab, const Accelerogram& motion, StudyMotion kind,
                          const CriticalSearch& search) {
    return kind == StudyMotion::Record ? recordCritical(slab, motion, search)
                                       : fittedSineCritical(slab, motion, search);
}

} // namespace kinstab
