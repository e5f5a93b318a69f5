// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RecordPointRun.h"

#include "core/excitation/RecordedMotion.h"

#include <algorithm>
#include <cstdio>

namespace kinstab::ui {

PointRun recordPointRun(const Slab1DCase& c, const RecordAnalysis& a,
                        const std::vector<SlabEvent>& events) {
    PointRun p;
    p.amplitude = a.peak;
    p.mu = c.slab.mu;
    p.limit = c.slab.limit;
    p.tauRef = a.tauRef.value_or(1.0);
    p.result = a.run;
    char peak[32];
    std::snprintf(peak, sizeof peak, "%.3f", a.peak);
    p.drive =
        (a.ground.component.empty() ? std::string("record") : "record " + a.ground.component) +
        " at " + std::string(peak) + " g";
    const RecordedMotion motion(a.motion, c.tstar, a.peak);
    // Up to the collapse, else the whole record; about 4 samples per record interval.
    const bool ended = a.run.outcome == Outcome::Collapsed || a.run.outcome == Outcome::LiftOff;
    const double tauEnd = ended ? a.run.tauEnd : std::max(a.run.tauEnd, motion.endTau());
    const double step = std::max(motion.sampleStep() / 4.0, tauEnd / 40000.0);
    p.history = sampleHistory(motion, c.slab.mu, events, tauEnd, step);
    if (a.fit) {
        const int n = 400;
        for (int k = 0; k <= n; ++k) {
            const double tau = tauEnd * k / n;
            p.envelope.push_back({tau, a.scaleFactor * a.fit->at(tau * c.tstar)});
        }
    }
    return p;
}

} // namespace kinstab::ui
