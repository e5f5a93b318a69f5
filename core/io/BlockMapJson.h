// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The project's "block_map": the GUI's free-standing block model and its overturning map
// (core/rocking/BlockMapSettings.h),
//   {"selected": true, "half_width_m": 0.2, "half_height_m": 0.6, "mu": null | 0.6,
//    "restitution": null | 0.9, "equations": "exact" | "linearised",
//    "pulse": "half-sine" | "one-sine" | "one-cosine" | "rectangular",
//    "amplitude_max": 10, "frequency_max": 10, "points": 101}
// Lengths in metres whatever the unit system shown. Absent keys take their defaults; a project
// without "block_map" (every file written before it) opens with the slab model.

#include "core/io/JsonReader.h"
#include "core/rocking/BlockMapSettings.h"

#include <nlohmann/json.hpp>

namespace kinstab {

nlohmann::json blockMapToJson(const BlockMapSettings& s);
// Throws JsonFieldError naming "block_map.FIELD".
BlockMapSettings blockMapFromJson(const JsonReader& r);

} // namespace kinstab
