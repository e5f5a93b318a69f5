// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sweep/ModelPoint.h"

namespace kinstab {

ModelPoint modelPoint(const Slab1DCase& slab, const std::optional<PlanarCase>& planar) {
    if (!planar) return {slab1DPoint(slab), slab.slab.mu, slab.tauRef()};
    return {planarPoint(*planar), planarNoSlipAmplitude(*planar), planar->tauRef()};
}

} // namespace kinstab
