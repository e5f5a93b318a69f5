// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/FigureData.h"

#include "core/sweep/Sweep.h"

#include <cmath>
#include <limits>

namespace kinstab::report {

double SurfaceData::maxGamma() const {
    double m = 0;
    for (double g : gamma)
        if (std::isfinite(g)) m = std::max(m, g);
    return m;
}

SurfaceData surfaceFromSweep(const SweepResult& r, double tauRef) {
    SurfaceData s;
    s.amplitudes = r.grid.amplitudes;
    s.frequencies = r.grid.frequencies;
    s.gamma = collapseFactors(r, tauRef);
    for (std::size_t k = 0; k < s.gamma.size(); ++k)
        if (!r.done[k] || r.points[k].outcome == Outcome::Failed)
            s.gamma[k] = std::numeric_limits<double>::quiet_NaN();
    return s;
}

} // namespace kinstab::report
