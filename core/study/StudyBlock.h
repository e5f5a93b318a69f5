// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A free-standing block as the model of a study (docs/studies.md, "A block instead of the
// slab"): each case gives the smallest scale of the driving motion (the record, through the
// floor filter or the building to a level) at which the block overturns, censored at the
// search's maximum, by the overturning search of core/rocking/OverturningAmplitude.h with the
// refinement kinstab-cli rocking --critical uses, so a case's critical peak is the
// critical_amplitude_g of `kinstab-cli rocking --record FILE --critical` with
// --max-amplitude max_g --scan-points (max_g / scan_step_g) --tolerance (tolerance_g / max_g).

#include "core/records/Accelerogram.h"
#include "core/rocking/Block.h"
#include "core/rocking/OverturningAmplitude.h"
#include "core/rocking/RockingModel.h"
#include "core/sweep/CriticalAmplitude.h"

#include <optional>
#include <string>

namespace kinstab {

struct StudyBlock {
    Block block;                       // b, h (m)
    std::optional<double> mu;          // none: the base holds it, it never slides
    std::optional<double> restitution; // none: Housner's 1 - 1.5 sin^2 alpha
    bool linear = false;               // the linearised equations (else the exact ones)
    bool operator==(const StudyBlock& o) const {
        return block.halfWidth == o.block.halfWidth && block.halfHeight == o.block.halfHeight &&
               mu == o.mu && restitution == o.restitution && linear == o.linear;
    }
};

RockingModel studyBlockModel(const StudyBlock& b);
// The overturning search of a study's critical-scale search: over (0, to] in scan steps of
// scanStep, each change bisected to tolerance / to relative, refined as kinstab-cli's.
OverturningSearch studyBlockSearch(const CriticalSearch& search);
// "b = 0.2 m, h = 0.6 m, mu = none, restitution = housner, exact": one line, for the study's
// fingerprint and the report's tables (numbers as the shortest text that reads back the same).
std::string studyBlockText(const StudyBlock& b);

// The critical peak of the driving motion for the block: none when nothing up to search.to
// overturns it.
struct BlockCaseCritical {
    std::optional<double> peak; // g, |peak| of the scaled driving motion at the first overturning
    double unitPeak = 0;        // g, |peak| of the unscaled driving motion
    long runs = 0;
    bool runLimitReached = false;
};
BlockCaseCritical blockCaseCritical(const StudyBlock& b, const Accelerogram& motion,
                                    const CriticalSearch& search);

} // namespace kinstab
