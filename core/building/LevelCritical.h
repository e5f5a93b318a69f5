// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The stability of a slab at each level: the ground record's critical peak ground acceleration
// (PGA) at which the slab on that level falls. The building is linear, so scaling the ground
// record by s scales every floor motion by s: the critical scale of a level's motion (the
// record search of core/sweep/CriticalRecordScale.h driven by that motion) gives the critical
// PGA as factor x |PGA|.

#include "core/records/Accelerogram.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/CriticalAmplitude.h"
#include "core/sweep/SweepControl.h"

#include <optional>
#include <vector>

namespace kinstab {

struct LevelCritical {
    int level = 0;                           // 1-based
    double floorPeak = 0;                    // g, |peak| of the level's motion, record as given
    std::optional<double> criticalFloorPeak; // g; none: nothing collapses up to the limit
    std::optional<double> criticalPga;       // g, the ground record's peak at that collapse
    long runs = 0;
};

// motions: one per level, bottom first; pga: |peak| of the ground record (g). control may
// cancel between slab runs (the result then ends at the level being searched).
std::vector<LevelCritical> levelCriticalPga(const Slab1DCase& slab,
                                            const std::vector<Accelerogram>& motions, double pga,
                                            const CriticalSearch& search,
                                            SweepControl* control = nullptr);

} // namespace kinstab
