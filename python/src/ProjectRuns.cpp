// SPDX-License-Identifier: GPL-3.0-or-later
// The project-level runs of kinstab.Project (python/kinstab/project.py) beside _assess_json:
// the floor-motion check (the JSON of `kinstab-cli floors --project`) and the project's study
// (its rows, from the results file or run here, and the fragility per parameter set as
// `kinstab-cli fragility` gives it). Each calls core directly.

#include "core/assessment/AssessmentJson.h"
#include "core/assessment/RiskCheck.h"
#include "core/assessment/RunAssessment.h"
#include "core/building/FloorAnalysis.h"
#include "core/excitation/RecordExcitation.h"
#include "core/io/FloorsJson.h"
#include "core/io/FragilityText.h"
#include "core/io/Project.h"
#include "core/io/StudyRowJson.h"
#include "core/io/StudySpecJson.h"
#include "core/study/StudyRecords.h"
#include "core/study/StudyRunner.h"
#include "python/src/Arguments.h"
#include "python/src/Bindings.h"
#include "python/src/Interruptible.h"

#include <filesystem>

namespace py = pybind11;

namespace kinstab::python {

namespace {

Project projectOrRaise(const std::string& path) {
    try {
        return loadProject(path);
    } catch (const ProjectError& e) {
        badArgument(e.what());
    }
}

nlohmann::json floorsOf(const Project& p, const std::string& path) {
    if (!p.record)
        badArgument(path + ": the project has no excitation.record, the ground motion of the "
                           "floor check");
    FloorAnalysisInput in = floorAnalysisInput(p, readGroundRecord(*p.record));
    FloorAnalysis a;
    {
        py::gil_scoped_release unlocked;
        a = analyseFloors(in);
    }
    nlohmann::json j = floorAnalysisJson(a, p.building);
    AssessmentParts parts; // the checks at the slab's level, as `kinstab-cli floors` states them
    parts.floors = floorCheckParts(a, p.building.stories);
    parts.recordName = in.ground.name;
    j["checks"] = assessmentJson(composeAssessment(p, parts))["checks"];
    j["project"] = p.name;
    j["record"] = {{"file", p.record->file},
                   {"name", in.ground.name},
                   {"component", in.ground.component},
                   {"peak_g", in.ground.peak().value}};
    return j;
}

std::string floorsJson(const std::string& path) {
    const Project p = projectOrRaise(path);
    try {
        return floorsOf(p, path).dump();
    } catch (const RecordError& e) {
        badArgument("excitation.record.file = '" + p.record->file + "': " + e.what());
    } catch (const std::invalid_argument& e) { // InputError and the analysis' bad input
        badArgument(e.what());
    }
}

// The study's rows: read from the project's results file when it names one (checked against
// the study file, core/study/StudyRowsMatch.h), else every case run here on `threads` threads.
std::vector<StudyRow> studyRowsOf(const ProjectStudy& ps, unsigned threads) {
    if (!ps.results.empty()) return projectStudyRows(ps);
    StudySpec spec = loadStudy(ps.spec);
    loadStudyRecords(spec);
    std::vector<StudyRow> rows;
    SweepControl control;
    StudyRunOptions options;
    options.threads = threads;
    options.control = &control;
    const bool finished = runWatchingSignals(control, [&] { rows = runStudyRows(spec, options); });
    if (!finished) throw py::error_already_set();
    return rows;
}

std::string studyJson(const std::string& path, std::size_t bootstrap, unsigned long long seed,
                      unsigned threads) {
    const Project p = projectOrRaise(path);
    if (!p.study) badArgument(path + ": the project has no study (\"study\": {\"spec\": ...})");
    try {
        const std::vector<StudyRow> rows = studyRowsOf(*p.study, threads);
        BootstrapSettings b;
        b.resamples = bootstrap;
        b.seed = seed;
        std::vector<Fragility> sets;
        {
            py::gil_scoped_release unlocked;
            sets = studyFragility(rows, b);
        }
        nlohmann::json out;
        out["rows"] = nlohmann::json::array();
        for (const StudyRow& r : rows)
            out["rows"].push_back(nlohmann::json::parse(studyRowLine(r)));
        out["fragility"] = nlohmann::json::parse(fragilityJson(sets, b).dump());
        return out.dump();
    } catch (const StudyError& e) {
        badArgument("study.spec = '" + p.study->spec + "': " + e.what());
    } catch (const std::invalid_argument& e) { // InputError naming study.results or study.spec
        badArgument(e.what());
    }
}

// The project as core reads it (every field checked, defaults filled in), written back as the
// project file's JSON with paths relative to the file's folder.
std::string projectJson(const std::string& path) {
    const Project p = projectOrRaise(path);
    return projectToJson(p, std::filesystem::absolute(path).parent_path().string()).dump();
}

} // namespace

void bindProjectRuns(py::module_& m) {
    m.def("_project_json", &projectJson, py::arg("path"));
    m.def("_floors_json", &floorsJson, py::arg("path"));
    m.def("_study_json", &studyJson, py::arg("path"), py::arg("bootstrap"), py::arg("seed"),
          py::arg("threads"));
}

} // namespace kinstab::python
