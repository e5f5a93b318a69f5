// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/StudyBlockJson.h"

#include "core/base/TextInput.h"

#include <array>
#include <string_view>

namespace kinstab {

namespace {

constexpr std::array<std::string_view, 5> kBlockKeys{"half_width_m", "half_height_m", "mu",
                                                     "restitution", "linear"};

void refuseUnknownKeys(const JsonReader& r, const nlohmann::json& j) {
    for (const auto& [key, value] : j.items()) {
        bool known = false;
        for (std::string_view k : kBlockKeys)
            known = known || key == k;
        if (!known)
            r.fail(key, "unknown key (a block has half_width_m, half_height_m, mu, "
                        "restitution and linear)");
    }
}

// A size: required, in its declared range.
double size(const JsonReader& r, const NumberInput& in, const std::string& key) {
    if (!r.has(key)) r.fail(key, "missing (a number is required)");
    return r.input(in, key);
}

} // namespace

std::optional<StudyBlock> studyBlockFromJson(const JsonReader& top) {
    if (!top.has("block")) return std::nullopt;
    const JsonReader r = top.object("block");
    refuseUnknownKeys(r, top.raw("block"));
    StudyBlock b;
    b.block.halfWidth = size(r, kHalfWidthInput, "half_width_m");
    b.block.halfHeight = size(r, kHalfHeightInput, "half_height_m");
    b.mu = r.optionalInput(kBlockMuInput, "mu");
    b.restitution = r.optionalInput(kRestitutionInput, "restitution");
    b.linear = r.boolean("linear", false);
    return b;
}

void refuseSlabParameters(const JsonReader& top) {
    const auto p = top.optionalObject("parameters");
    if (!p) return;
    for (const char* key : {"mu", "tstar", "wall_width_in", "limit", "motion"})
        if (p->has(key))
            p->fail(key, "a slab parameter: the study's model is its \"block\" (its friction is "
                         "block.mu)");
}

} // namespace kinstab
