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
// 50 years, 50 years). The curve is read when the project is loaded, in the study's measure, so
// that a bad curve or another measure is an error naming study.hazard.file at once.

#include "core/io/JsonReader.h"
#include "core/risk/HazardFile.h"
#include "core/risk/RiskTargets.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace kinstab {

struct ProjectHazard {
    std::string file; // the hazard curve (absolute once loaded)
    HazardFormat format = HazardFormat::Auto;
    std::optional<HazardSite> site;       // OpenQuake: the row of this site; none: the first
    double targetRate = codeTargetRate(); // per year, the risk check's capacity
    double years = 50;                    // of the probability of collapse in the report
    bool operator==(const ProjectHazard& o) const {
        const bool sameSite = site.has_value() == o.site.has_value() &&
                              (!site || (site->lon == o.site->lon && site->lat == o.site->lat));
        return file == o.file && format == o.format && sameSite && targetRate == o.targetRate &&
               years == o.years;
    }
};

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
// Reads the study file once: throws JsonFieldError "study.spec = 'PATH': message"; and the
// hazard curve in the study's measure: "study.hazard.file = 'PATH': message".
void checkStudyFile(const ProjectStudy& s);
// The hazard curve the study names, read in the study's measure (core/risk/HazardFile.h).
// Throws JsonFieldError naming study.spec or study.hazard.file.
HazardCurve readProjectHazard(const ProjectStudy& s);

} // namespace kinstab
