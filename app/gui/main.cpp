// kinstab: the desktop application.

#include "ui/MainWindow.h"

#include <QApplication>

int main(int argc, char** argv) {
    qputenv("QSG_RHI_BACKEND", "opengl"); // required by Qt Data Visualization on Qt 6
    QApplication app(argc, argv);
    QApplication::setApplicationName("kinstab");
    QApplication::setOrganizationName("kinstab");
    QApplication::setApplicationVersion(KINSTAB_VERSION);
    kinstab::ui::MainWindow window;
    window.show();
    return QApplication::exec();
}
