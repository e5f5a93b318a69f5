#pragma once
// The main window. Panels, surface and charts arrive with the GUI issue.

#include <QMainWindow>

namespace kinstab::ui {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
};

} // namespace kinstab::ui
