// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The planar slab driven by recorded horizontal motions (docs/theory.md §5, §7): a_x from a record
// (the across-wall component) and optionally a_y from a second component, in place of the enveloped
// sines of PlanarCase; mu, limit, theta, the vertical motion and the solver options come from
// the PlanarCase. Both components are scaled by one factor (the one that brings a_x to its
// target peak), so the pair keeps the ratio of its recorded peaks.

#include "core/records/Accelerogram.h"
#include "core/slab/PlanarCase.h"

#include <optional>

namespace kinstab {

struct PlanarRecordMotions {
    Accelerogram x;                // across the walls, unscaled
    std::optional<Accelerogram> y; // along the walls; none: no motion along them
    double peakX = 0;              // g: a_x is scaled to this peak, a_y by the same factor
};

// Empty when fine, else a message naming the component.
std::string validatePlanarRecordMotions(const PlanarRecordMotions& m, double tstar);
SlabModel2D planarRecordModel(const PlanarCase& c, const PlanarRecordMotions& m);
PlanarResult runPlanarRecord(const PlanarCase& c, const PlanarRecordMotions& m);

} // namespace kinstab
