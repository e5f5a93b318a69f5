// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/PlanarPointRun.h"

namespace kinstab::ui {

PlanarPointRun runPlanarPoint(const PlanarCase& c, double amplitude, double frequencyHz) {
    PlanarPathLog log;
    PlanarPointRun p;
    p.amplitude = amplitude;
    p.frequency = frequencyHz;
    p.limit = c.common.slab.limit;
    p.theta = c.theta;
    p.tauRef = c.tauRef();
    p.result = runPlanar(c, amplitude, frequencyHz, &log);
    p.path = std::move(log.path);
    return p;
}

} // namespace kinstab::ui
