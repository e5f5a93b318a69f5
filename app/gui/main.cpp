// kinstab: the desktop application.

#include "core/numerics/VectorState.h"
#include "ui/AutoScreenshot.h"
#include "ui/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>

#include <cstdio>

int main(int argc, char** argv) {
    kinstab::clearUpperVectorState();     // see core/numerics/VectorState.h
    qputenv("QSG_RHI_BACKEND", "opengl"); // required by Qt Data Visualization on Qt 6
    QApplication app(argc, argv);
    QApplication::setApplicationName("kinstab");
    QApplication::setOrganizationName("kinstab");
    QApplication::setApplicationVersion(KINSTAB_VERSION);

    QCommandLineParser parser;
    parser.setApplicationDescription("Kinetic stability of friction-held slabs in earthquakes");
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption shot("screenshot", "Run the sweep, save the window to FILE and quit.",
                                  "FILE");
    parser.addOption(shot);
    const QCommandLineOption scenario(
        "scenario",
        "With --screenshot: one step after the sweep (open:PROJECT, codes, mu, cancel).", "STEP");
    parser.addOption(scenario);
    parser.addPositionalArgument("project", "Project file (.json) to open.", "[project]");
    parser.process(app);

    kinstab::ui::MainWindow window;
    window.show();
    if (const QStringList files = parser.positionalArguments(); !files.isEmpty()) {
        if (!window.openProject(files.front(), parser.isSet(shot))) return 2;
    }
    if (parser.isSet(shot) && parser.isSet(scenario)) {
        const QString e =
            kinstab::ui::screenshotScenario(window, parser.value(scenario), parser.value(shot));
        if (!e.isEmpty()) {
            std::fprintf(stderr, "kinstab: %s\n", qPrintable(e));
            return 2;
        }
    } else if (parser.isSet(shot)) {
        kinstab::ui::screenshotAfterSweep(window, parser.value(shot));
    }
    return QApplication::exec();
}
