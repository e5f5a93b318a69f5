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

std::string validateFloorSettings(const FloorSettings& s, int stories) {
    std::ostringstream m;
    if (s.slabLevel && (*s.slabLevel < 1 || *s.slabLevel > stories))
        m << "floors.slab_level = " << *s.slabLevel << ": must be between 1 and " << stories
          << " (the roof)";
    else if (!(s.damping >= 0.0 && s.damping < 1.0))
        m << "floors.damping = " << s.damping << ": must be at least 0 and below 1";
    else if (!(s.omega0 >= 1.0 && s.omega0 <= 5.0))
        m << "floors.asce7_omega0 = " << s.omega0 << ": must be between 1 and 5";
    else if (s.ec8ElementPeriod && !(*s.ec8ElementPeriod >= 0.0 && *s.ec8ElementPeriod <= 100.0))
        m << "floors.ec8_element_period_s = " << *s.ec8ElementPeriod
          << ": must be between 0 and 100 s";
    return m.str();
}

} // namespace kinstab
