// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One case's result as one line of JSON (JSONL, docs/studies.md): its inputs and the intensity at
// which the scaled record first collapses the slab, or none up to the search limit (then the
// record is censored at the limit's intensity). No timing: a rerun writes the same bytes.

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

namespace kinstab {

struct StudyRow {
    std::size_t index = 0, cases = 0, set = 0;
    std::string record; // label: the path relative to the study file
    double mu = 0, tstar = 0, limit = 0;
    std::optional<double> floorPeriod, floorDamping;
    std::string measure;                     // intensityName(), e.g. "pga"
    double recordIntensity = 0;              // g, the unscaled record's intensity measure
    std::optional<double> criticalIntensity; // g; none: no collapse up to the limit
    std::optional<double> criticalPeak;      // g, peak of the driving motion at collapse
    double limitIntensity = 0;               // g, the intensity at the search limit
    long runs = 0;
};

struct StudyRowError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string studyRowLine(const StudyRow& r); // one line, no newline
// Throws StudyRowError saying which key is missing or wrong.
StudyRow parseStudyRow(const std::string& line);

} // namespace kinstab
