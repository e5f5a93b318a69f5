// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The assessment as JSON (`kinstab-cli check`'s "assessment", Python's kinstab.assess) and as a
// text table (`kinstab-cli check` on a terminal). Margins and capacities that were not found are
// null, never NaN; "margin_at_least" then gives the bound the search limit sets.

#include "core/assessment/Assessment.h"

#include <nlohmann/json.hpp>

#include <string>

namespace kinstab {

nlohmann::json assessmentJson(const Assessment& a);
std::string assessmentTable(const Assessment& a);

} // namespace kinstab
