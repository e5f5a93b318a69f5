// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A study row (core/study/StudyRow.h) as one line of JSON (JSONL, docs/studies.md), written and
// read back: core/study computes the rows, this is the one place their text is made and checked.
// No timing in a row: a rerun writes the same bytes.

#include "core/study/StudyRow.h"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace kinstab {

struct StudyRowError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string studyRowLine(const StudyRow& r); // one line, no newline
// The keys that name a row's parameter set, added to j in their order: the model ("block", or
// "mu", "tstar", "limit"), "floor_period_s", "floor_damping" (null without a floor filter) and,
// when the study uses them, "level" and "motion". A row and a fragility set (FragilityText.h)
// write them alike.
void addStudySetJson(nlohmann::ordered_json& j, const StudyRow& r);
// The rows as a results file holds them: each row's line and a newline.
std::string studyRowsText(const std::vector<StudyRow>& rows);
// Throws StudyRowError saying which key is missing or wrong: of the wrong type, or out of its
// range (a critical intensity that is not > 0, or above the row's search limit).
StudyRow parseStudyRow(const std::string& line);

} // namespace kinstab
