// kinstab: the desktop application.

#include "core/numerics/VectorState.h"
#include "ui/AutoScreenshot.h"
#include "ui/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>

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
    parser.addPositionalArgument("project", "Project file (.json) to open.", "[project]");
    parser.process(app);

    kinstab::ui::MainWindow window;
    window.show();
    if (const QStringList files = parser.positionalArguments(); !files.isEmpty()) {
        if (!window.openProject(files.front(), parser.isSet(shot))) return 2;
    }
    if (parser.isSet(shot)) kinstab::ui::screenshotAfterSweep(window, parser.value(shot));
    return QApplication::exec();
}
