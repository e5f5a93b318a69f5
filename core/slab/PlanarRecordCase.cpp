// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/PlanarRecordCase.h"

#include "core/excitation/RecordedMotion.h"

#include <cmath>

namespace kinstab {

std::string validatePlanarRecordMotions(const PlanarRecordMotions& m, double tstar) {
    if (std::string e = validateRecordedMotion(m.x, tstar, m.peakX); !e.empty())
        return "x record: " + e;
    if (m.y)
        if (std::string e = validateRecordedMotion(*m.y, tstar, std::nullopt); !e.empty())
            return "y record: " + e;
    return {};
}

SlabModel2D planarRecordModel(const PlanarCase& c, const PlanarRecordMotions& m) {
    if (const std::string e = validatePlanarRecordMotions(m, c.common.tstar); !e.empty())
        throw std::invalid_argument(e);
    auto x = std::make_shared<RecordedMotion>(m.x, c.common.tstar, m.peakX);
    std::shared_ptr<const Excitation1D> y;
    const double yPeak = m.y ? std::abs(m.y->peak().value) : 0.0;
    if (m.y && yPeak > 0.0)
        y = std::make_shared<RecordedMotion>(*m.y, c.common.tstar, x->scale() * yPeak);
    return SlabModel2D(std::move(x), std::move(y), c.vertical, c.params());
}

PlanarResult runPlanarRecord(const PlanarCase& c, const PlanarRecordMotions& m) {
    return solvePlanar(planarRecordModel(c, m), c.solver);
}

} // namespace kinstab
