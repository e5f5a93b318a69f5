// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sweep/CriticalRecordScale.h"

#include "core/excitation/RecordedMotion.h"
#include "core/slab/RecordRun.h"

#include <cmath>

namespace kinstab {

PointFunction recordPoint(const Slab1DCase& c, const Accelerogram& motion) {
    // The samples once for the whole search; each run scales its own view of them.
    const auto samples = std::make_shared<const RecordSamples>(motion, c.tstar);
    return [c, samples](double peak, double /*frequency: a record has none*/) {
        const SlabResult r = runRecord1D(c, samples, peak);
        return PointResult{r.outcome, r.tauC};
    };
}

RecordCriticalScale criticalRecordScale(const Slab1DCase& c, const Accelerogram& motion,
                                        const CriticalSearch& search) {
    return criticalRecordScale(recordPoint(c, motion), c.slab.mu, std::abs(motion.peak().value),
                               search);
}

RecordCriticalScale criticalRecordScale(const PointFunction& point, double mu, double motionPeak,
                                        const CriticalSearch& search) {
    // A scaled record peaks at exactly its scale, so below mu nothing slips: the scan of
    // criticalAmplitude starts at mu, as for the sine.
    const CriticalResult r = criticalAmplitude(point, 0.0, mu, search);
    RecordCriticalScale out;
    out.peak = r.amplitude;
    out.motionPeak = motionPeak;
    out.runs = r.runs;
    if (r.amplitude && motionPeak > 0.0) out.factor = *r.amplitude / motionPeak;
    return out;
}

} // namespace kinstab
