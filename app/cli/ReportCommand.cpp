// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli report --project FILE -o FILE.pdf [--page a4|letter] [--figure-grid N]
//                    [--units si|us]
// Built into kinstab-report, which kinstab-cli report runs (ReportLauncher.cpp). Runs the analyses
// the report needs and writes the same PDF as the GUI's File → Export report…; `-o -` writes the
// PDF to stdout and the summary to stderr. Needs no display: a QGuiApplication on the offscreen
// platform unless the caller chose another.

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "core/io/JsonText.h"
#include "core/io/Project.h"
#include "report/ReportWriter.h"

#include <QFile>
#include <QGuiApplication>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace kinstab::cli {

namespace {

std::unique_ptr<QGuiApplication> ensureGuiApplication() {
    if (QCoreApplication::instance()) return nullptr;
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "kinstab-cli";
    static char* argv[] = {name, nullptr};
    return std::make_unique<QGuiApplication>(argc, argv);
}

// The run times the report leaves out (its numerics appendix is for the engineer).
nlohmann::json reportTimings(const report::ReportAnalysis& a) {
    nlohmann::json j = {{"project_sweep_s", a.projectSweep.wallTimeSeconds},
                        {"figure_sweeps_s", a.figureSweepSeconds},
                        {"design_check_s", a.checkSeconds},
                        {"project_sweep_runs", a.projectSweep.completed},
                        {"figure_runs", a.figureRuns},
                        {"critical_curve_runs", a.critRuns},
                        {"design_check_runs", a.check.runs}};
    if (a.crossCheck)
        j.update({{"cross_check_exact_s", a.crossCheck->exactSeconds},
                  {"cross_check_paper_s", a.crossCheck->paperSeconds}});
    return j;
}

QByteArray readProjectBytes(const std::string& path) {
    QFile f(QString::fromStdString(path));
    if (!f.open(QIODevice::ReadOnly))
        throw UsageError("--project " + path + ": cannot read this file");
    return f.readAll();
}

// The project of --project with --sections and --units applied; a bad value: exit 2 naming
// the flag.
report::ReportSource reportSource(const Args& args, const std::string& path) {
    using namespace kinstab::report;
    ReportSource source;
    if (args.has("sections")) {
        try {
            source.sections = parseSections(args.text("sections"));
        } catch (const ReportError& e) {
            throw UsageError("--sections " + args.text("sections").substr(0, 80) + ": " + e.what());
        }
    }
    try {
        source.project = loadProject(path);
    } catch (const ProjectError& e) {
        throw UsageError("--project " + path + ": " + e.what());
    }
    // Lengths print in the project's unit system ("units", else its building's: ft gives US);
    // --units prints them in the other without editing the file.
    if (args.has("units"))
        source.project.units = unitSystemFromName(args.choice("units", {"si", "us"}, "si"));
    source.fileName = QString::fromStdString(path);
    source.fileContents = readProjectBytes(path);
    return source;
}

// The report's analyses; a bad value in the project: exit 2 naming --project.
report::ReportAnalysis analyse(const Project& project, const report::AnalysisOptions& options,
                               const std::string& path) {
    try {
        return report::computeReportAnalysis(project, options);
    } catch (const std::invalid_argument& e) { // InputError: a bad value in the project
        throw UsageError("--project " + path + ": " + e.what());
    } catch (const ProjectError& e) {
        throw UsageError("--project " + path + ": " + e.what());
    }
}

} // namespace

int writeReport(const ArgList& argv) {
    const Args args(argv, {"project", "o", "page", "figure-grid", "sections", "units"});
    using namespace kinstab::report;
    const auto t0 = std::chrono::steady_clock::now();
    if (!args.has("project")) throw UsageError("--project FILE is required");
    if (!args.has("o")) throw UsageError("-o FILE.pdf is required");
    const std::string path = args.text("project");
    const std::string out = args.text("o");
    const PaperSize paper =
        *paperSizeFromName(QString::fromStdString(args.choice("page", {"a4", "letter"}, "a4")));
    AnalysisOptions options;
    options.figureGrid = args.integer("figure-grid", 41);
    if (options.figureGrid < 5 || options.figureGrid > 201)
        throw UsageError("--figure-grid " + args.text("figure-grid") + ": must be 5 to 201");

    checkOutputPath("o", out); // an empty name or a missing folder: exit 2 before any work
    const ReportSource source = reportSource(args, path);
    const ReportAnalysis analysis = analyse(source.project, options, path);

    const auto app = ensureGuiApplication();
    QByteArray pdf;
    int pages = 0;
    try {
        pages = renderReportPdf(buildReportDocument(source, analysis), paper, pdf);
    } catch (const ReportError& e) {
        throw UsageError("-o " + out + ": " + e.what());
    }
    writeOutput(args, "o", std::string(pdf.constData(), static_cast<std::size_t>(pdf.size())));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const nlohmann::json j = {{"output", out},
                              {"pages", pages},
                              {"page", paper == PaperSize::A4 ? "a4" : "letter"},
                              {"units", unitSystemName(projectUnits(source.project))},
                              {"analysis_wall_time_s", analysis.totalSeconds},
                              {"timings", reportTimings(analysis)},
                              {"wall_time_s", seconds}};
    (out == "-" ? std::cerr : std::cout) << jsonText(j, 2) << "\n"; // -o -: stdout holds the PDF
    return 0;
}

} // namespace kinstab::cli
