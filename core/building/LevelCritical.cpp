// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/building/LevelCritical.h"

#include "core/sweep/CriticalRecordScale.h"

#include <cmath>
#include <memory>

namespace kinstab {

namespace {
// The level's slab runs, stopping at once (as a failed run) after a cancel.
PointFunction cancellable(PointFunction point, SweepControl* control) {
    if (!control) return point;
    return [point, control](double peak, double f) {
        if (control->isCancelled()) return PointResult{Outcome::Failed, std::nan("")};
        return point(peak, f);
    };
}
} // namespace

std::vector<LevelCritical> levelCriticalPga(const Slab1DCase& slab,
                                            const std::vector<Accelerogram>& motions, double pga,
                                            const CriticalSearch& search, SweepControl* control) {
    std::vector<LevelCritical> out;
    for (std::size_t i = 0; i < motions.size(); ++i) {
        if (control && control->isCancelled()) break;
        const double peak = std::abs(motions[i].peak().value);
        const RecordCriticalScale c = criticalRecordScale(
            cancellable(recordPoint(slab, motions[i]), control), slab.slab.mu, peak, search);
        if (control && control->isCancelled()) break;
        LevelCritical l;
        l.level = static_cast<int>(i) + 1;
        l.floorPeak = peak;
        l.criticalFloorPeak = c.peak;
        if (c.factor) l.criticalPga = *c.factor * pga;
        l.runs = c.runs;
        out.push_back(l);
        if (control && control->onProgress) control->onProgress(i + 1, motions.size());
    }
    return out;
}

} // namespace kinstab
