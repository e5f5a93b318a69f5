// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/PointRun.h"

#include "core/excitation/EnvelopedSine.h"

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

PointRun runPoint(const Slab1DCase& c, double amplitude, double frequencyHz) {
    PointRun p;
    p.amplitude = amplitude;
    p.frequency = frequencyHz;
    p.mu = c.slab.mu;
    p.limit = c.slab.limit;
    p.tauRef = c.tauRef();
    const EnvelopedSine a(c.envelope, amplitude, frequencyHz, c.tstar);
    SlabHistoryLog log(a, c.slab.mu);
    p.result = runSlab1D(c, amplitude, frequencyHz, {}, &log);
    const double period = 1.0 / (frequencyHz * c.tstar); // in tau
    // Up to the collapse; a stable run is shown at least past the envelope's peak.
    const bool ended =
        p.result.outcome == Outcome::Collapsed || p.result.outcome == Outcome::LiftOff;
    const double tauEnd =
        ended ? p.result.tauEnd
              : std::max(p.result.tauEnd, 1.2 * c.envelope.computedTimes(c.tstar).tauMax);
    const double step = std::max(period / 40.0, tauEnd / 40000.0);
    p.history = log.history(tauEnd, step);
    const int n = 400;
    for (int k = 0; k <= n; ++k) {
        const double tau = tauEnd * k / n;
        p.envelope.push_back({tau, amplitude / a.sMax() * a.envelopeAt(tau)});
    }
    return p;
}

} // namespace kinstab::ui
