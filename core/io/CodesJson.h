// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// JSON forms of the building, the codes' inputs, their results and the design check, with the
// keys of the project file and of `kinstab-cli codes` / `check` (docs/user-guide.md "The command
// line").

#include "core/check/DesignCheck.h"
#include "core/codes/Building.h"
#include "core/codes/CodeSet.h"
#include "core/io/JsonReader.h"

#include <nlohmann/json.hpp>

namespace kinstab {

nlohmann::json buildingToJson(const Building& b);
Building buildingFromJson(const JsonReader& r); // throws JsonFieldError / InputError

nlohmann::json codesToJson(const CodeSelection& c); // only the selected codes
CodeSelection codesFromJson(const JsonReader& r);

// base_shear_coefficient, period_s, top_ratio, story_forces (top last), trail, …
nlohmann::json codeResultJson(const CodeResult& r);
// One object keyed by code.
nlohmann::json codeResultsJson(const std::vector<CodeResult>& results);
nlohmann::json designCheckJson(const DesignCheckResult& d);

} // namespace kinstab
