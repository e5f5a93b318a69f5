// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/building/FloorSettings.h"

#include "core/base/NameTable.h"

#include <cmath>
#include <sstream>

namespace kinstab {

// StiffnessProfile's names, in its declaration order (Uniform, Weight).
constexpr std::array<const char*, 2> kStiffnessNames = {"uniform", "weight"};
static_assert(kStiffnessNames.size() == static_cast<std::size_t>(StiffnessProfile::Weight) + 1);

std::string stiffnessName(StiffnessProfile s) {
    return enumName(kStiffnessNames, s);
}

std::optional<StiffnessProfile> stiffnessFromName(const std::string& s) {
    return enumFromName<StiffnessProfile>(kStiffnessNames, s);
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
