// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/building/FloorSettings.h"

#include <cmath>
#include <sstream>

namespace kinstab {

std::string stiffnessName(StiffnessProfile s) {
    return s == StiffnessProfile::Weight ? "weight" : "uniform";
}

std::optional<StiffnessProfile> stiffnessFromName(const std::string& s) {
    if (s == "uniform") return StiffnessProfile::Uniform;
    if (s == "weight") return StiffnessProfile::Weight;
    return std::nullopt;
}

InputProblem checkFloorSettings(const FloorSettings& s, int stories) {
    if (s.slabLevel && (*s.slabLevel < 1 || *s.slabLevel > stories))
        return {"slab_level", static_cast<double>(*s.slabLevel), "",
                "must be between 1 and " + std::to_string(stories) + " (the roof)"};
    if (InputProblem p = checkInput(kModalDampingInput, s.damping); !p.empty()) return p;
    if (InputProblem p = checkInput(kOmega0Input, s.omega0); !p.empty()) return p;
    if (s.ec8ElementPeriod) return checkInput(kEc8ElementPeriodInput, *s.ec8ElementPeriod);
    return {};
}

std::string validateFloorSettings(const FloorSettings& s, int stories) {
    return describe(checkFloorSettings(s, stories), "floors.");
}

} // namespace kinstab
