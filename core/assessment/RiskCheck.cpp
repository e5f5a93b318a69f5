// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/assessment/RiskCheck.h"

#include "core/base/InputError.h"
#include "core/base/TextInput.h"
#include "core/io/Project.h"
#include "core/io/StudySpecJson.h"
#include "core/study/Fragility.h"
#include "core/study/StudyRecords.h"
#include "core/study/StudyResults.h"
#include "core/study/StudyRowsMatch.h"
#include "core/study/StudySpec.h"

#include <filesystem>
#include <map>

namespace kinstab {

std::vector<StudyRow> projectStudyRows(const ProjectStudy& s) {
    const std::string results = "study.results = " + quotedToken(s.results) + ": ";
    std::vector<StudyRow> rows;
    try {
        rows = readStudyRows(s.results);
    } catch (const StudyRowError& e) {
        throw InputError(results + e.what());
    }
    StudySpec spec;
    try {
        spec = loadStudy(s.spec);
        hashStudyRecords(spec); // the rows' fingerprint is checked against the records' bytes
    } catch (const StudyError& e) {
        throw InputError("study.spec = " + quotedToken(s.spec) + ": " + e.what());
    }
    const std::string dir = std::filesystem::path(s.spec).parent_path().string();
    if (const std::string m = studyRowsMismatch(spec, dir, rows); !m.empty())
        throw InputError(results + "not the results of " + s.spec + " (" + m +
                         "); run the study again or remove study.results");
    return rows;
}

RiskCheckParts riskCheckParts(const ProjectHazard& hazard, const HazardCurve& curve,
                              const std::vector<StudyRow>& rows) {
    if (rows.empty()) throw InputError("study.results: the results file holds no rows");
    RiskCheckParts out;
    out.hazard = hazard;
    out.curve = curve;
    out.settings.years = hazard.years;
    out.settings.targetRate = hazard.targetRate;
    out.measure = rows.front().measure;
    std::map<std::size_t, std::vector<StudyRow>> bySet;
    for (const StudyRow& r : rows)
        bySet[r.set].push_back(r);
    // As kinstab-cli risk --set K (setRisk in core/risk/RiskReport.cpp): the fit alone, no
    // resamples, so the check's lambda_C is that command's.
    BootstrapSettings fitOnly;
    fitOnly.resamples = 0;
    for (const auto& [set, setRows] : bySet) {
        const Fragility f = fragilityOf(setRows, fitOnly);
        RiskSetPart part;
        part.parameters = f.parameters;
        part.records = f.records;
        part.collapsed = f.collapsed;
        if (f.fit)
            part.risk = analyzeRisk(curve, {f.fit->median, f.fit->beta}, out.settings);
        else
            part.noFit = f.noFit;
        out.sets.push_back(std::move(part));
    }
    return out;
}

std::optional<RiskCheckParts> projectRiskParts(const Project& p) {
    if (!p.study || !p.study->hazard || p.study->results.empty()) return std::nullopt;
    HazardCurve curve;
    try {
        curve = readProjectHazard(*p.study);
    } catch (const JsonFieldError& e) {
        throw InputError(e.what());
    }
    return riskCheckParts(*p.study->hazard, curve, projectStudyRows(*p.study));
}

} // namespace kinstab
