// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/BlockMapSettings.h"

#include <cmath>

namespace kinstab {

RockingModel blockMapModel(const BlockMapSettings& s) {
    RockingModel m;
    m.block = s.block;
    m.mu = s.mu;
    m.restitution = s.restitution;
    m.equations = s.equations;
    return m;
}

RockingModel otherEquationsModel(const BlockMapSettings& s) {
    RockingModel m = blockMapModel(s);
    m.equations = s.equations == RockingEquations::Exact ? RockingEquations::Linearised
                                                         : RockingEquations::Exact;
    return m;
}

OverturningMapSpec blockMapSpec(const BlockMapSettings& s) {
    OverturningMapSpec spec;
    spec.shape = s.shape;
    spec.amplitudePoints = spec.frequencyPoints = s.points;
    spec.amplitudeMin = s.amplitudeMax / s.points;
    spec.amplitudeMax = s.amplitudeMax;
    spec.frequencyMin = s.frequencyMax / s.points;
    spec.frequencyMax = s.frequencyMax;
    return spec;
}

InputProblem checkBlockMapSettings(const BlockMapSettings& s) {
    if (auto p = checkRockingModel(blockMapModel(s)); !p.empty()) return p;
    if (auto p = checkInput(kMapAmplitudeMaxInput, s.amplitudeMax); !p.empty()) return p;
    if (auto p = checkInput(kMapFrequencyMaxInput, s.frequencyMax); !p.empty()) return p;
    if (auto p = checkInput(kMapPointsInput, s.points); !p.empty()) return p;
    return {};
}

std::string equationsName(RockingEquations e) {
    return e == RockingEquations::Exact ? "exact" : "linearised";
}

std::optional<RockingEquations> equationsFromName(const std::string& name) {
    if (name == "exact") return RockingEquations::Exact;
    if (name == "linearised") return RockingEquations::Linearised;
    return std::nullopt;
}

} // namespace kinstab
