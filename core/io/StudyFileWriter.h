// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Writes a study file (the format core/io/StudySpecJson.h reads: "kinstab-study", version
// kStudyVersion) from the fields the GUI's Study tab edits, over the file as it was opened: keys
// the fields do not cover (the study's name, a building, levels, motions, the search's other
// settings) are kept as the file had them, so opening and saving changes nothing else.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct StudyFileFields {
    // The records: one folder entry, or the opened file's own records array (kept as written,
    // with its per-record scales) while the folder fields still read as they did when opened.
    std::string folder;
    std::vector<std::string> include, exclude; // file-name patterns
    std::optional<nlohmann::json> openedRecords;
    std::string measure;   // intensity.measure ("pga", "sa", ...)
    double saPeriodS = 0;  // intensity.period_s, written for "sa"
    std::string mu, tstar; // the lists as the file accepts them: "0.4, 0.6" or "0.3:0.8:0.1"
    std::optional<std::string> floorPeriods; // parameters.floor_filter.periods_s; none: no filter
    double maxG = 0, scanStepG = 0;          // search.max_g, search.scan_step_g
};

// The study file's text (two-space indent, keys sorted): base (the file as opened, or an empty
// object) with the fields written over it.
std::string studyFileText(const nlohmann::json& base, const StudyFileFields& f);

} // namespace kinstab
