// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The project's study (docs/studies.md) as JSON: the study file and, optionally, its results
// (JSONL written by `kinstab-cli study`), both stored relative to the project's directory like
// a record's file:
//   "study": {"spec": "study-example.json", "results": "study-example.jsonl"}
// Absent: the project has no study. The study file is read when the project is loaded, so that
// a missing or broken one is an error naming study.spec, not a surprise in the report.
// A study may name the site's hazard curve (docs/studies.md, "Risk"); the assessment then has a
// risk check per parameter set (docs/assessment.md):
//   "hazard": {"file": "hazard.csv", "format": "auto", "site": [lon, lat],
//              "target_rate": 2.0101e-4, "years": 50}
// file is required; the rest optional (format auto, the file's first site, the code's 1 % in
// 50 years, 50 years). Loading checks the fields; the curve itself is read by the assessment
// (core/assessment/RiskCheck.h), in the study's measure, because reading hazard files is
// core/risk's, a floor above io.

#include "core/io/JsonReader.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace kinstab {

struct ProjectHazard {
    std::string file;                              // the hazard curve (absolute once loaded)
    std::string format = "auto";                   // a name of core/risk/HazardFile.h's formats
    std::optional<std::pair<double, double>> site; // lon, lat; OpenQuake's row (none: the first)
    std::optional<double> targetRate;              // per year; none: the code's 1 % in 50 years
    double years = 50;                             // of the probability of collapse
    bool operator==(const ProjectHazard&) const = default;
};

// The hazard formats' names and the most years asked about, declared here, on the lowest floor
// that reads them: the project file's reader checks them, and core/risk (a floor above) takes
// its hazardFormatName and kMaxRiskYears from these. 10,000 years is beyond any structure's life.
inline constexpr const char* kProjectHazardFormats[] = {"auto", "openquake", "usgs", "csv"};
inline constexpr double kMaxProjectHazardYears = 10'000;

struct ProjectStudy {
    std::string spec;    // the study file (absolute once loaded)
    std::string results; // the study's JSONL results; empty: the report runs the study
    std::optional<ProjectHazard> hazard;
    bool operator==(const ProjectStudy&) const = default;
};

// baseDir: the project file's directory ("" keeps paths as they are).
nlohmann::json studyToJson(const ProjectStudy& s, const std::string& baseDir);
// Reads "study" (r is the project's top level). Throws JsonFieldError naming the field.
std::optional<ProjectStudy> studyFromJson(const JsonReader& r, const std::string& baseDir);
// Reads the study file once: throws JsonFieldError "study.spec = 'PATH': message".
void checkStudyFile(const ProjectStudy& s);

} // namespace kinstab
