// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab: the desktop application.

#include "core/numerics/VectorState.h"
#include "ui/AutoScreenshot.h"
#include "ui/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QIcon>

#include <cstdio>
#include <cstdlib>
#include <cstring>

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
    if (parser.isSet(kShot) && parser.isSet(kScenario)) {
        const QString e =
            kinstab::ui::screenshotScenario(window, parser.value(kScenario), parser.value(kShot));
        if (!e.isEmpty()) {
            std::fprintf(stderr, "kinstab: %s\n", qPrintable(e));
            return 2;
        }
    } else if (parser.isSet(kShot)) {
        QSize size(1280, 800);
        if (parser.isSet(kSize)) {
            const QStringList wh = parser.value(kSize).split('x');
            size = wh.size() == 2 ? QSize(wh[0].toInt(), wh[1].toInt()) : QSize();
            if (size.width() < 640 || size.height() < 480 || size.width() > 7680 ||
                size.height() > 4320) {
                std::fprintf(stderr, "kinstab: --size %s: must be WxH, 640x480 to 7680x4320\n",
                             qPrintable(parser.value(kSize)));
                return 2;
            }
        }
        int grid = 0;
        if (parser.isSet(kGrid)) {
            bool ok = false;
            grid = parser.value(kGrid).toInt(&ok);
            if (!ok || grid < 2 || grid > 400) {
                std::fprintf(stderr, "kinstab: --grid %s: must be a whole number 2 to 400\n",
                             qPrintable(parser.value(kGrid)));
                return 2;
            }
        }
        kinstab::ui::screenshotAfterSweep(window, parser.value(kShot), size, grid,
                                          parser.value(kTab));
    }
    return QApplication::exec();
}
