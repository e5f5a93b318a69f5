// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/assessment/RiskCheck.h"

#include "core/base/InputError.h"
#include "core/base/TextInput.h"
#include "core/io/Project.h"
#include "core/io/StudyResults.h"
#include "core/io/StudySpecJson.h"
#include "core/study/Fragility.h"
#include "core/study/StudyRecords.h"
#include "core/study/StudyRowsMatch.h"
#include "core/study/StudySpec.h"

#include <filesystem>
#include <map>

namespace kinstab {

HazardCurve readProjectHazard(const ProjectStudy& s) {
    StudySpec spec;
    try {
        spec = loadStudy(s.spec);
    } catch (const StudyError& e) {
        throw InputError("study.spec = " + quotedToken(s.spec) + ": " + e.what());
    }
    const std::string where = "study.hazard.file = " + quotedToken(s.hazard->file) + ": ";
    // The study's measure picks the USGS response and refuses a curve of another measure.
    const std::string name = intensityName(spec.intensity);
    const std::optional<HazardMeasure> measure = measureFromStudy(name);
    if (!measure)
        throw InputError(where + "the study's intensity measure " + quotedToken(name) +
                         " is no measure a hazard curve is given in");
    const std::optional<HazardFormat> format = hazardFormatFromName(s.hazard->format);
    if (!format) throw InputError("study.hazard.format = " + quotedToken(s.hazard->format));
    std::optional<HazardSite> site;
    if (s.hazard->site) site = HazardSite{s.hazard->site->first, s.hazard->site->second};
    try {
        return readHazardFile(s.hazard->file, {*format, site, measure});
    } catch (const HazardError& e) {
        throw InputError(where + e.what());
    }
}

RiskSettings riskSettingsOf(const ProjectHazard& h) {
    RiskSettings s;
    s.years = h.years;
    s.targetRate = h.targetRate.value_or(codeTargetRate());
    return s;
}

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
    out.settings = riskSettingsOf(hazard);
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
    return riskCheckParts(*p.study->hazard, readProjectHazard(*p.study),
                          projectStudyRows(*p.study));
}

} // namespace kinstab
