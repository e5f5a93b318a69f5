#pragma once
// `kinstab --screenshot FILE`: run the sweep of the open inputs, pick the paper's Fig. 35 point
// (A = 1.0 g, f = 1.125 Hz, or the nearest grid point), save the window as an image and quit.
// Used for the documentation screenshots, taken from the running app under Xvfb.

#include <QString>

namespace kinstab::ui {

class MainWindow;

void screenshotAfterSweep(MainWindow& window, const QString& path);

} // namespace kinstab::ui
