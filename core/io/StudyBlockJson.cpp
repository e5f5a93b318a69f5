// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/StudyBlockJson.h"

#include "core/base/TextInput.h"
#include "core/io/JsonValue.h"

#include <array>
#include <stdexcept>
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

nlohmann::ordered_json studyBlockJson(const StudyBlock& b) {
    using ojson = nlohmann::ordered_json;
    return {{"half_width_m", b.block.halfWidth},
            {"half_height_m", b.block.halfHeight},
            {"mu", orNull<ojson>(b.mu)},
            {"restitution", orNull<ojson>(b.restitution)},
            {"linear", b.linear}};
}

namespace {

double rowNumber(const nlohmann::json& j, const char* key, const NumberInput& in) {
    const std::string at = std::string("block.") + key;
    if (!j.contains(key) || !j[key].is_number())
        throw std::invalid_argument(at + ": expected a number");
    const double x = j[key].get<double>();
    if (const InputProblem p = checkInput(in, x); !p.empty())
        throw std::invalid_argument(describeAs(p, at));
    return x;
}

std::optional<double> optionalRowNumber(const nlohmann::json& j, const char* key,
                                        const NumberInput& in) {
    if (!j.contains(key) || j[key].is_null()) return std::nullopt;
    return rowNumber(j, key, in);
}

} // namespace

StudyBlock studyBlockFromRowJson(const nlohmann::json& j) {
    if (!j.is_object()) throw std::invalid_argument("block: expected an object");
    StudyBlock b;
    b.block.halfWidth = rowNumber(j, "half_width_m", kHalfWidthInput);
    b.block.halfHeight = rowNumber(j, "half_height_m", kHalfHeightInput);
    b.mu = optionalRowNumber(j, "mu", kBlockMuInput);
    b.restitution = optionalRowNumber(j, "restitution", kRestitutionInput);
    if (!j.contains("linear") || !j["linear"].is_boolean())
        throw std::invalid_argument("block.linear: expected true or false");
    b.linear = j["linear"].get<bool>();
    return b;
}

} // namespace kinstab
