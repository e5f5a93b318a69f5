// SPDX-License-Identifier: GPL-3.0-or-later
// assess: a project file's assessment (core/assessment), the same object `kinstab-cli check`
// prints under "assessment". The project is read by core's reader, so a bad field raises
// ValueError naming it, as the CLI's exit 2 does.

#include "core/assessment/AssessmentJson.h"
#include "core/assessment/RunAssessment.h"
#include "core/io/Project.h"
#include "core/records/RecordReader.h"
#include "python/src/Arguments.h"
#include "python/src/Bindings.h"

#include <filesystem>

namespace py = pybind11;
namespace fs = std::filesystem;

namespace kinstab::python {

namespace {

// The shipped vertical record (planar "rsn68_up") sits in the records folder beside the examples
// folder, in the source tree (resources/) and as installed (/usr/share/kinstab/).
std::string shippedVertical(const std::string& projectPath) {
    const fs::path beside =
        fs::absolute(projectPath).parent_path().parent_path() / "records" / kRsn68UpFileName;
    const fs::path installed = fs::path("/usr/share/kinstab/records") / kRsn68UpFileName;
    for (const fs::path& p : {beside, installed})
        if (fs::exists(p)) return p.string();
    badArgument(std::string("planar.vertical = 'rsn68_up': ") + kRsn68UpFileName +
                " not found in " + beside.parent_path().string() + " or " +
                installed.parent_path().string() + "; give {\"file\": PATH}");
}

std::optional<PlanarCase> planarOf(const Project& p, const std::string& projectPath) {
    if (p.model != ModelKind::Planar) return std::nullopt;
    std::shared_ptr<const Excitation1D> vertical;
    if (p.planar.vertical != VerticalSource::None) {
        const std::string file = p.planar.vertical == VerticalSource::Rsn68Up
                                     ? shippedVertical(projectPath)
                                     : p.planar.verticalPath;
        try {
            vertical = verticalMotion(readRecord(file), p.slab.tstar);
        } catch (const RecordError& e) {
            badArgument("planar.vertical = '" + file + "': " + e.what());
        }
    }
    return kinstab::planarCaseFrom(p.slab, p.planar, vertical);
}

std::string assessJson(const std::string& path) {
    try {
        const Project p = loadProject(path);
        const std::optional<PlanarCase> planar = planarOf(p, path);
        AssessmentRun run;
        {
            py::gil_scoped_release unlocked;
            AnalysisControl control;
            run = runAssessment(p, planar, control);
        }
        return assessmentJson(run.assessment).dump();
    } catch (const ProjectError& e) {
        badArgument(e.what());
    } catch (const RecordError& e) {
        badArgument(e.what());
    } catch (const std::invalid_argument& e) { // InputError and the analyses' bad input
        badArgument(e.what());
    }
}

} // namespace

void bindAssess(py::module_& m) {
    m.def("_assess_json", &assessJson, py::arg("path"));
}

} // namespace kinstab::python
