#pragma once
// The "planar" object of a project file (SPEC §10): the planar model's settings.
//   {"fy_hz": 1, "ay_ratio": 0.9, "theta": 20, "normalization": "product",
//    "vertical": "none" | "rsn68_up" | {"file": "path/to/record"}}
// Every key is optional (defaults of PlanarSettings); a bad one is a JsonFieldError naming it.

#include "core/io/JsonReader.h"
#include "core/slab/PlanarSettings.h"

#include <nlohmann/json.hpp>

namespace kinstab {

nlohmann::json planarSettingsToJson(const PlanarSettings& s);
PlanarSettings planarSettingsFromJson(const JsonReader& r); // r reads the "planar" object

} // namespace kinstab
