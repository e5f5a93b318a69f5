// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The "planar" object of a project file (docs/user-guide.md): the planar model's settings.
//   {"fy_hz": 1, "ay_ratio": 0.9, "theta": 20, "normalization": "product",
//    "vertical": "none" | "rsn68_up" | {"file": "path/to/record"}}
// Every key is optional (defaults of PlanarSettings); a bad one is a JsonFieldError naming it.
// A vertical record file is stored relative to the project's directory when one is given and
// resolved against it on load, as the excitation's record is (MotionJson.h).

#include "core/io/JsonReader.h"
#include "core/slab/PlanarSettings.h"

#include <nlohmann/json.hpp>

namespace kinstab {

// baseDir: the project file's directory ("" keeps paths as they are).
nlohmann::json planarSettingsToJson(const PlanarSettings& s, const std::string& baseDir = "");
// r reads the "planar" object.
PlanarSettings planarSettingsFromJson(const JsonReader& r, const std::string& baseDir = "");

} // namespace kinstab
