// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The project's study (docs/studies.md) as JSON: the study file and, optionally, its results
// (JSONL written by `kinstab-cli study`), both stored relative to the project's directory like
// a record's file:
//   "study": {"spec": "study-example.json", "results": "study-example.jsonl"}
// Absent: the project has no study. The study file is read when the project is loaded, so that
// a missing or broken one is an error naming study.spec, not a surprise in the report.

#include "core/io/JsonReader.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace kinstab {

struct ProjectStudy {
    std::string spec;    // the study file (absolute once loaded)
    std::string results; // the study's JSONL results; empty: the report runs the study
    bool operator==(const ProjectStudy&) const = default;
};

// baseDir: the project file's directory ("" keeps paths as they are).
nlohmann::json studyToJson(const ProjectStudy& s, const std::string& baseDir);
// Reads "study" (r is the project's top level). Throws JsonFieldError naming the field.
std::optional<ProjectStudy> studyFromJson(const JsonReader& r, const std::string& baseDir);
// Reads the study file once: throws JsonFieldError "study.spec = 'PATH': message".
void checkStudyFile(const ProjectStudy& s);

} // namespace kinstab
