// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/BlockMapJson.h"

#include "core/base/TextInput.h"
#include "core/io/JsonValue.h"

#include <cmath>

namespace kinstab {

using nlohmann::json;

json blockMapToJson(const BlockMapSettings& s) {
    return {{"selected", s.selected},
            {"half_width_m", s.block.halfWidth},
            {"half_height_m", s.block.halfHeight},
            {"mu", orNull(s.mu)},
            {"restitution", orNull(s.restitution)},
            {"equations", equationsName(s.equations)},
            {"pulse", std::string(pulseShapeName(s.shape))},
            {"amplitude_max", s.amplitudeMax},
            {"frequency_max", s.frequencyMax},
            {"points", s.points}};
}

BlockMapSettings blockMapFromJson(const JsonReader& r) {
    BlockMapSettings s;
    s.selected = r.boolean("selected", false);
    s.block.halfWidth = r.input(kHalfWidthInput, "half_width_m");
    s.block.halfHeight = r.input(kHalfHeightInput, "half_height_m");
    s.mu = r.optionalInput(kBlockMuInput);
    s.restitution = r.optionalInput(kRestitutionInput);
    const std::string eq = r.text("equations", "exact");
    const auto e = equationsFromName(eq);
    if (!e) r.fail("equations", quotedToken(eq) + " must be exact or linearised");
    s.equations = *e;
    const std::string pulse = r.text("pulse", "one-sine");
    const auto shape = pulseShapeFromName(pulse);
    if (!shape)
        r.fail("pulse",
               quotedToken(pulse) + " must be half-sine, one-sine, one-cosine or rectangular");
    s.shape = *shape;
    s.amplitudeMax = r.input(kMapAmplitudeMaxInput);
    s.frequencyMax = r.input(kMapFrequencyMaxInput);
    const double n = r.input(kMapPointsInput);
    if (n != std::floor(n)) r.fail("points", "must be a whole number");
    s.points = static_cast<int>(n);
    return s;
}

} // namespace kinstab
