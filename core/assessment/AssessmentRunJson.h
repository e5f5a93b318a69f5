// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `kinstab-cli check`'s JSON (docs/user-guide.md "The command line"): the assessment with the
// figures each basis wrote before there was one, composed here, on the floor that knows the
// assessment, from core/io's writers.

#include "core/assessment/RunAssessment.h"
#include "core/io/Project.h"

#include <nlohmann/json.hpp>

namespace kinstab {

// The per-basis figures kept from before the assessment (keys are never renamed: "codes" holds
// the record's verdicts for a record project, the sine's otherwise), "assessment", "project"
// (its name), the model's keys (a record replaces the envelope), "search" and wall_time_s.
nlohmann::json assessmentRunJson(const Project& p, const AssessmentRun& run, double wallSeconds);

} // namespace kinstab
