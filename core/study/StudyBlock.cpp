// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyBlock.h"

#include "core/base/TextInput.h"
#include "core/rocking/RockingMotions.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

RockingModel studyBlockModel(const StudyBlock& b) {
    RockingModel m;
    m.block = b.block;
    m.mu = b.mu;
    m.restitution = b.restitution;
    m.equations = b.linear ? RockingEquations::Linearised : RockingEquations::Exact;
    return m;
}

// The scan step of the slab's search, as the project's block checks take it
// (core/assessment/BlockCheck.cpp); its absolute tolerance relative to the limit, within the
// range kinstab-cli rocking --tolerance accepts.
OverturningSearch studyBlockSearch(const CriticalSearch& search) {
    OverturningSearch s;
    s.maxAmplitude = search.to;
    const double points = std::ceil(search.to / search.scanStep - 1e-9);
    s.scanPoints = static_cast<int>(std::clamp(points, 2.0, 100000.0));
    s.tolerance = std::clamp(search.tolerance / search.to, 1e-12, 0.1);
    s.refineDepth = kOverturningRefineDepth;
    s.maxRuns = kOverturningMaxRuns;
    return s;
}

std::string studyBlockText(const StudyBlock& b) {
    return "b = " + formatDouble(b.block.halfWidth) +
           " m, h = " + formatDouble(b.block.halfHeight) +
           " m, mu = " + (b.mu ? formatDouble(*b.mu) : std::string("none")) + ", restitution = " +
           (b.restitution ? formatDouble(*b.restitution) : std::string("housner")) + ", " +
           (b.linear ? "linearised" : "exact");
}

BlockCaseCritical blockCaseCritical(const StudyBlock& b, const Accelerogram& motion,
                                    const CriticalSearch& search) {
    const OverturningIntervals iv =
        overturningIntervals(studyBlockModel(b), recordFamily(motion), studyBlockSearch(search));
    BlockCaseCritical out;
    out.peak = iv.critical();
    out.unitPeak = std::abs(motion.peak().value);
    out.runs = iv.runs;
    out.runLimitReached = iv.runLimitReached;
    return out;
}

} // namespace kinstab
