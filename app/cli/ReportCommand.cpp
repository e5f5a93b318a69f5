// kinstab-cli report --project FILE -o FILE.pdf [--page a4|letter] [--figure-grid N]
// Runs the analyses the report needs and writes the same PDF as the GUI's File → Export
// report…. Needs no display: a QGuiApplication on the offscreen platform unless the caller
// chose another.

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/JsonText.h"
#include "core/io/Project.h"
#include "ui/report/ReportWriter.h"

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

QByteArray readProjectBytes(const std::string& path) {
    QFile f(QString::fromStdString(path));
    if (!f.open(QIODevice::ReadOnly))
        throw UsageError("--project " + path + ": cannot read this file");
    return f.readAll();
}

} // namespace

int runReport(const ArgList& argv) {
    const Args args(argv, {"project", "o", "page", "figure-grid"});
    using namespace kinstab::ui::report;
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

    const std::filesystem::path dir = std::filesystem::absolute(out).parent_path();
    if (!std::filesystem::is_directory(dir))
        throw UsageError("-o " + out + ": the folder " + dir.string() + " does not exist");

    ReportSource source;
    try {
        source.project = loadProject(path);
    } catch (const ProjectError& e) {
        throw UsageError("--project " + path + ": " + e.what());
    }
    source.fileName = QString::fromStdString(path);
    source.fileContents = readProjectBytes(path);
    ReportAnalysis analysis;
    try {
        analysis = computeReportAnalysis(source.project, options);
    } catch (const std::invalid_argument& e) { // InputError: a bad value in the project
        throw UsageError("--project " + path + ": " + e.what());
    } catch (const ProjectError& e) {
        throw UsageError("--project " + path + ": " + e.what());
    }

    const auto app = ensureGuiApplication();
    const std::string part = out + ".part";
    int pages = 0;
    try {
        pages = writeReport(source, analysis, QString::fromStdString(part), paper);
    } catch (const ReportError& e) {
        throw UsageError("-o " + out + ": " + e.what());
    }
    std::error_code ec;
    std::filesystem::rename(part, out, ec);
    if (ec) throw UsageError("-o " + out + ": " + ec.message());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const nlohmann::json j = {{"output", out},
                              {"pages", pages},
                              {"page", paper == PaperSize::A4 ? "a4" : "letter"},
                              {"analysis_wall_time_s", analysis.totalSeconds},
                              {"wall_time_s", seconds}};
    std::cout << jsonText(j, 2) << "\n";
    return 0;
}

} // namespace kinstab::cli
