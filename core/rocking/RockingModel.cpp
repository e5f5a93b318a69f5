// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/RockingModel.h"

namespace kinstab {

double restitutionOf(const RockingModel& m) {
    return m.restitution ? *m.restitution : housnerRestitution(blockAlpha(m.block));
}

InputProblem checkRockingModel(const RockingModel& m) {
    if (auto p = checkBlock(m.block); !p.empty()) return p;
    if (m.restitution)
        if (auto p = checkInput(kRestitutionInput, *m.restitution); !p.empty()) return p;
    if (m.mu)
        if (auto p = checkInput(kBlockMuInput, *m.mu); !p.empty()) return p;
    if (auto p = checkInput(kInitialTiltInput, m.initialTilt); !p.empty()) return p;
    if (m.duration)
        if (auto p = checkInput(kRockingDurationInput, *m.duration); !p.empty()) return p;
    return {};
}

} // namespace kinstab
