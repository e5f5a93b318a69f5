// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/assessment/ProjectRequest.h"

#include "core/codes/CodeSet.h"
#include "core/slab/VerticalRecord.h"

#include <stdexcept>

namespace kinstab {

AnalysisRequest analysisRequest(const Project& p, const AnalysisParts& parts) {
    if (p.model != ModelKind::Planar) return analysisRequest(p, parts, std::nullopt);
    return analysisRequest(p, parts, planarCaseWithVertical(p.slab, p.planar));
}

AnalysisRequest analysisRequest(const Project& p, const AnalysisParts& parts,
                                const std::optional<PlanarCase>& planar) {
    if (p.model == ModelKind::Planar && !planar)
        throw std::logic_error("analysisRequest: a planar project needs its planar case");
    AnalysisRequest q;
    q.slab = p.slab;
    if (p.model == ModelKind::Planar) q.planar = planar->own();
    q.record = p.record;
    q.grid = p.grid;
    q.criticalFrequencies = p.grid.frequencies;
    q.criticalSearch = p.critical;
    q.codes = runCodes(p.building, p.codes);
    q.checkSearch = p.critical;
    q.parts = parts;
    return q;
}

} // namespace kinstab
