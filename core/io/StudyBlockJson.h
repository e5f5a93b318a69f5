// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The "block" of a study file (docs/studies.md, "A block instead of the slab"):
//   "block": {"half_width_m": 0.2, "half_height_m": 0.6, "mu": null | 0.6,
//             "restitution": null | 0.9, "linear": false}
// mu null or absent: the base holds the block (no sliding); restitution null: Housner's. Every
// key is checked: an unknown one, a missing size or a value out of its range is refused naming
// "block.KEY" (a JsonFieldError, the study's exit 2). A study row and a fragility set write the
// block in the same keys, mu and restitution null when not given.

#include "core/io/JsonReader.h"
#include "core/study/StudyBlock.h"

#include <nlohmann/json.hpp>

#include <optional>

namespace kinstab {

// None when the study file has no "block".
std::optional<StudyBlock> studyBlockFromJson(const JsonReader& top);

// A block study has no slab: the slab's parameters (mu, tstar, wall_width_in, limit, motion)
// are refused naming them.
void refuseSlabParameters(const JsonReader& top);

// The block as a row or a fragility set writes it: {"half_width_m", "half_height_m", "mu",
// "restitution", "linear"}.
nlohmann::ordered_json studyBlockJson(const StudyBlock& b);
// Parses what studyBlockJson writes; throws std::invalid_argument naming the key ("block.mu").
StudyBlock studyBlockFromRowJson(const nlohmann::json& j);

} // namespace kinstab
