// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/RockingFlags.h"

namespace kinstab::cli {

std::set<std::string> rockingModelFlagNames() {
    return {"half-width", "half-height", "restitution", "mu", "initial-tilt", "duration"};
}

RockingModel rockingModelFromFlags(const Args& args) {
    for (const char* f : {"half-width", "half-height"})
        if (!args.has(f))
            throw UsageError(std::string("missing required flag --") + f + " (metres)");
    RockingModel m;
    m.block.halfWidth = args.input(kHalfWidthInput);
    m.block.halfHeight = args.input(kHalfHeightInput);
    m.restitution = args.optionalInput(kRestitutionInput);
    m.equations = args.has("linear") ? RockingEquations::Linearised : RockingEquations::Exact;
    m.mu = args.optionalInput(kBlockMuInput);
    m.initialTilt = args.input(kInitialTiltInput);
    m.duration = args.optionalInput(kRockingDurationInput);
    args.refuse(checkRockingModel(m));
    return m;
}

} // namespace kinstab::cli
