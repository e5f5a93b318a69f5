#include "ui/MainWindow.h"

#include <QLabel>

namespace kinstab::ui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("kinstab — kinetic stability of friction-held slabs"));
    auto* label = new QLabel(tr("kinstab"), this);
    label->setAlignment(Qt::AlignCenter);
    setCentralWidget(label);
    resize(1280, 800);
}

} // namespace kinstab::ui
