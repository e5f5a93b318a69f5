// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The risk part of a project's assessment (docs/assessment.md, "risk"): for a study with results
// and a hazard curve (core/io/StudyJson.h), per parameter set the fitted collapse fragility
// integrated against the site's hazard curve - the same fit and integral as `kinstab-cli risk
// --results R --set K` (core/risk/RiskReport.cpp), so the check's lambda_C is that command's.

#include "core/io/StudyJson.h"
#include "core/risk/HazardFile.h"
#include "core/risk/RiskAnalysis.h"
#include "core/study/StudyRow.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct Project;

struct RiskSetPart {
    StudyRow parameters; // the set's first row: set, mu, t*, floor or level, measure
    std::size_t records = 0, collapsed = 0;
    std::optional<RiskResult> risk; // none: the set has no fitted fragility (noFit says why)
    std::string noFit;
};

struct RiskCheckParts {
    ProjectHazard hazard; // as the project names it
    HazardCurve curve;
    RiskSettings settings; // the project's target rate and years
    std::string measure;   // the study's, e.g. "pga"
    std::vector<RiskSetPart> sets;
};

// The hazard curve the study names, read in the study's measure (core/risk/HazardFile.h).
// Throws InputError naming study.spec or study.hazard.file.
HazardCurve readProjectHazard(const ProjectStudy& s);
// The project's hazard settings as the risk engine takes them (the code's target when none).
RiskSettings riskSettingsOf(const ProjectHazard& h);

// The study's rows from its results file, refused when they are not the results of the study
// file as it is now (core/study/StudyRowsMatch.h). Throws InputError naming study.results or
// study.spec.
std::vector<StudyRow> projectStudyRows(const ProjectStudy& s);

// Each set of rows fitted (without bootstrap, as kinstab-cli risk --set K) and integrated
// against the curve. Throws InputError when the rows hold no set.
RiskCheckParts riskCheckParts(const ProjectHazard& hazard, const HazardCurve& curve,
                              const std::vector<StudyRow>& rows);

// The risk part of a project whose study has results and a hazard curve; none otherwise (the
// assessment then says why in a note). Throws InputError naming the field on a bad file.
std::optional<RiskCheckParts> projectRiskParts(const Project& p);

} // namespace kinstab
