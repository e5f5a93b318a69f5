// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The design check against a record as `kinstab-cli check` writes it beside the assessment (keys
// kept from before the assessment, never renamed; docs/user-guide.md "The command line").

#include "core/check/RecordAnalysis.h"
#include "core/excitation/FloorFilter.h"

#include <nlohmann/json.hpp>

#include <optional>

namespace kinstab {

// designCheckJson of the record's verdicts, with record, floor_filter (null: the ground motion
// drives the slab), amplitude, critical_peak_g and outcome. a must have searched its critical
// scale (a.critical set).
nlohmann::json recordCheckJson(const RecordAnalysis& a,
                               const std::optional<FloorFilterParams>& floor);

} // namespace kinstab
