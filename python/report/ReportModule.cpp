// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab._report: the design report for kinstab.Project.report (python/kinstab/project.py),
// written by the report library `kinstab-cli report` links (report/ReportWriter.h): the same
// analyses (computeReportAnalysis) and the same PDF. A module of its own so that `import
// kinstab` never loads Qt: this one is imported only when a report is asked for. Qt Gui needs
// a QGuiApplication to lay text out; without one this makes one on the offscreen platform (no
// display), unless QT_QPA_PLATFORM names another.

#include "core/io/Project.h"
#include "report/ReportWriter.h"

#include <pybind11/pybind11.h>

#include <QFile>
#include <QGuiApplication>

#include <nlohmann/json.hpp>

namespace py = pybind11;

namespace {

using namespace kinstab;
using namespace kinstab::report;

void ensureGuiApplication() {
    if (QCoreApplication::instance()) return;
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "kinstab-python";
    static char* argv[] = {name, nullptr};
    new QGuiApplication(argc, argv); // lives as long as the process: Qt allows one per process
}

ReportSource sourceOf(const std::string& projectPath) {
    ReportSource source;
    try {
        source.project = loadProject(projectPath);
    } catch (const ProjectError& e) {
        throw py::value_error(e.what());
    }
    source.fileName = QString::fromStdString(projectPath);
    QFile f(source.fileName);
    if (!f.open(QIODevice::ReadOnly))
        throw py::value_error(projectPath + ": cannot read this file");
    source.fileContents = f.readAll();
    return source;
}

std::string writeReportJson(const std::string& projectPath, const std::string& pdfPath,
                            const std::string& page, int figureGrid) {
    const std::optional<PaperSize> paper = paperSizeFromName(QString::fromStdString(page));
    if (!paper) throw py::value_error("page='" + page + "' must be one of a4|letter");
    if (figureGrid < 5 || figureGrid > 201)
        throw py::value_error("figure_grid=" + std::to_string(figureGrid) + ": must be 5 to 201");
    const ReportSource source = sourceOf(projectPath);
    AnalysisOptions options;
    options.figureGrid = figureGrid;
    ReportAnalysis analysis;
    try {
        py::gil_scoped_release unlocked;
        analysis = computeReportAnalysis(source.project, options);
    } catch (const std::invalid_argument& e) { // InputError: a bad value in the project
        throw py::value_error(projectPath + ": " + e.what());
    } catch (const ProjectError& e) {
        throw py::value_error(projectPath + ": " + e.what());
    }
    ensureGuiApplication();
    int pages = 0;
    try {
        pages = writeReport(source, analysis, QString::fromStdString(pdfPath), *paper);
    } catch (const ReportError& e) {
        throw py::value_error("pdf_path='" + pdfPath + "': " + e.what());
    } catch (const std::runtime_error& e) { // WriteError: the file cannot be written
        throw py::value_error("pdf_path='" + pdfPath + "': " + e.what());
    }
    return nlohmann::json{{"output", pdfPath}, {"pages", pages}, {"page", page}}.dump();
}

} // namespace

PYBIND11_MODULE(_report, m) {
    m.doc() = "kinstab's design report (Qt Gui, offscreen): kinstab.Project.report";
    m.def("write_report", &writeReportJson, py::arg("project"), py::arg("pdf_path"),
          py::arg("page") = "a4", py::arg("figure_grid") = 41);
}
