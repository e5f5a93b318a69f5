// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab: the desktop application.

#include "core/numerics/VectorState.h"
#include "ui/AutoScreenshot.h"
#include "ui/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QIcon>
#include <QSize>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

namespace {

const QCommandLineOption kShot("screenshot", "Run the sweep, save the window to FILE and quit.",
                               "FILE");
const QCommandLineOption
    kScenario("scenario",
              "With --screenshot: one step after the sweep (open:PROJECT, codes, mu, cancel, top, "
              "map) or present, optionally @WIDTHxHEIGHT.",
              "STEP");

const QCommandLineOption kSize("size", "With --screenshot: the window's size (default 1280x800).",
                               "WxH");
const QCommandLineOption kTab("tab",
                              "With --screenshot: show the centre tab whose title begins with "
                              "TITLE (Records, Teaching, Floors, ...) in the image; TAB/VIEW also "
                              "shows a view inside it (Study/Risk).",
                              "TITLE");
const QCommandLineOption kGrid("grid",
                               "With --screenshot: N amplitudes by N frequencies over the "
                               "project's ranges (2..400).",
                               "N");

void describe(QCoreApplication& app, QCommandLineParser& parser) {
    QCoreApplication::setApplicationName("kinstab");
    QCoreApplication::setOrganizationName("kinstab");
    QCoreApplication::setApplicationVersion(KINSTAB_VERSION);
    parser.setApplicationDescription(
        "Kinetic stability of friction-held slabs in earthquakes (Furgerson 1980).\n"
        "Licence GPL-3.0-or-later. Manual: man kinstab; Help > User guide (F1).");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption(kShot);
    parser.addOption(kScenario);
    parser.addOption(kSize);
    parser.addOption(kGrid);
    parser.addOption(kTab);
    parser.addPositionalArgument("project", "Project file (.json) to open.", "[project]");
    parser.process(app);
}

// --help and --version print and exit without a display: answer them before QApplication,
// which aborts when no platform can be opened.
bool textOnly(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        for (const char* f : {"-h", "--help", "--help-all", "-v", "--version"})
            if (std::strcmp(argv[i], f) == 0) return true;
    return false;
}

// Exit status when no display can be opened (docs/man/kinstab.1.in): like kinstab-cli's 3, a
// failure of the surroundings that a retry may cure, not of the input or of the program.
constexpr int kNoDisplay = 3;
QtMessageHandler qtHandler = nullptr;

// Qt ends with qFatal, so SIGABRT, when its platform plugin cannot open the display (an X server
// that is not, or no longer, reachable: under Xvfb a server that another start was tearing down,
// issue 31). While QApplication starts, a fatal message is that: say so and exit kNoDisplay.
void whileStarting(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    if (qtHandler) qtHandler(type, context, message);
    if (type != QtFatalMsg) return;
    std::fprintf(stderr,
                 "kinstab: no display could be opened (DISPLAY=%s): the window system is not "
                 "reachable. Without one, use kinstab-cli, or xvfb-run for screenshots.\n",
                 qgetenv("DISPLAY").isEmpty() ? "unset" : qgetenv("DISPLAY").constData());
    std::_Exit(kNoDisplay);
}

// --size: the screenshot window's size (default 1280x800); nullopt, after saying why, when it is
// not WxH within 640x480 to 7680x4320.
std::optional<QSize> screenshotSize(const QCommandLineParser& parser) {
    if (!parser.isSet(kSize)) return QSize(1280, 800);
    const QStringList wh = parser.value(kSize).split('x');
    const QSize size = wh.size() == 2 ? QSize(wh[0].toInt(), wh[1].toInt()) : QSize();
    if (size.width() < 640 || size.height() < 480 || size.width() > 7680 || size.height() > 4320) {
        std::fprintf(stderr, "kinstab: --size %s: must be WxH, 640x480 to 7680x4320\n",
                     qPrintable(parser.value(kSize)));
        return std::nullopt;
    }
    return size;
}

// --grid: N by N points (0: the project's own); nullopt, after saying why, outside 2..400.
std::optional<int> screenshotGrid(const QCommandLineParser& parser) {
    if (!parser.isSet(kGrid)) return 0;
    bool ok = false;
    const int grid = parser.value(kGrid).toInt(&ok);
    if (!ok || grid < 2 || grid > 400) {
        std::fprintf(stderr, "kinstab: --grid %s: must be a whole number 2 to 400\n",
                     qPrintable(parser.value(kGrid)));
        return std::nullopt;
    }
    return grid;
}

// --screenshot: the scenario's step, else the window after the sweep. The exit status when a
// flag is refused (2), else 0 and the image follows from the event loop.
int startScreenshot(kinstab::ui::MainWindow& window, const QCommandLineParser& parser) {
    if (parser.isSet(kScenario)) {
        const QString e =
            kinstab::ui::screenshotScenario(window, parser.value(kScenario), parser.value(kShot));
        if (e.isEmpty()) return 0;
        std::fprintf(stderr, "kinstab: %s\n", qPrintable(e));
        return 2;
    }
    const std::optional<QSize> size = screenshotSize(parser);
    if (!size) return 2;
    const std::optional<int> grid = screenshotGrid(parser);
    if (!grid) return 2;
    kinstab::ui::screenshotAfterSweep(window, parser.value(kShot), *size, *grid,
                                      parser.value(kTab));
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    kinstab::clearUpperVectorState(); // see core/numerics/VectorState.h
    if (textOnly(argc, argv)) {
        QCoreApplication app(argc, argv);
        QCommandLineParser parser;
        describe(app, parser); // prints and exits
        return 0;
    }
    qputenv("QSG_RHI_BACKEND", "opengl"); // required by Qt Data Visualization on Qt 6
    qtHandler = qInstallMessageHandler(whileStarting);
    QApplication app(argc, argv);
    qInstallMessageHandler(qtHandler); // started: Qt's own handling from here on
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/kinstab.svg")));
    QGuiApplication::setDesktopFileName(QStringLiteral("io.github.kinstab"));
    QCommandLineParser parser;
    describe(app, parser);

    kinstab::ui::MainWindow window;
    window.show();
    if (const QStringList files = parser.positionalArguments(); !files.isEmpty()) {
        if (!window.openProject(files.front(), parser.isSet(kShot))) return 2;
    }
    if (parser.isSet(kShot))
        if (const int status = startScreenshot(window, parser); status != 0) return status;
    return QApplication::exec();
}
