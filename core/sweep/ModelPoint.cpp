// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sweep/ModelPoint.h"

namespace kinstab {

ModelPoint modelPoint(const Slab1DCase& slab, const std::optional<PlanarInputs>& planar) {
    if (!planar) return {slab1DPoint(slab), slab.slab.mu, slab.tauRef()};
    const PlanarCase c(slab, *planar);
    return {planarPoint(c), planarNoSlipAmplitude(c), c.tauRef()};
}

} // namespace kinstab
