// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/RockingSpectrum.h"

#include "core/rocking/RockingSolver.h"
#include "core/sweep/ParallelFor.h"

#include <atomic>
#include <stdexcept>

namespace kinstab {

std::vector<RockingSpectrumPoint> rockingSpectrum(const RockingModel& model,
                                                  const BaseMotion& motion,
                                                  const RockingSpectrumSpec& spec,
                                                  const SweepControl* control) {
    if (!(spec.alpha > 0.0 && spec.alpha < 1.5))
        throw std::invalid_argument("rocking spectrum: alpha must be between 0 and 1.5 rad");
    for (double p : spec.frequencies)
        if (!(p > 0.0 && p < 1e3))
            throw std::invalid_argument("rocking spectrum: p must be between 0 and 1000 rad/s");
    std::vector<RockingSpectrumPoint> out(spec.frequencies.size());
    std::atomic<std::size_t> done{0};
    RockingRunOptions options;
    options.stopAtOverturnDecision = true;
    parallelFor(out.size(), spec.threads, control, [&](std::size_t k) {
        RockingModel m = model;
        m.block = blockFromAlphaP(spec.alpha, spec.frequencies[k]);
        const RockingResult r = simulateRocking(m, motion, options);
        RockingSpectrumPoint& pt = out[k];
        pt.p = spec.frequencies[k];
        pt.halfWidth = m.block.halfWidth;
        pt.halfHeight = m.block.halfHeight;
        pt.maxThetaOverAlpha = r.maxThetaOverAlpha;
        pt.overturns = r.outcome == RockingOutcome::Overturns;
        const std::size_t d = ++done;
        if (control && control->onProgress) control->onProgress(d, out.size());
    });
    return out;
}

} // namespace kinstab
