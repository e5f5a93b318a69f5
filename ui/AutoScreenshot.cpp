#include "ui/AutoScreenshot.h"

#include "ui/MainWindow.h"
#include "ui/SurfaceView.h"

#include <QApplication>
#include <QTimer>

#include <cmath>
#include <cstdio>

namespace kinstab::ui {

namespace {
int nearest(const std::vector<double>& v, double x) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < v.size(); ++i)
        if (std::abs(v[i] - x) < std::abs(v[best] - x)) best = i;
    return static_cast<int>(best);
}
} // namespace

void screenshotAfterSweep(MainWindow& window, const QString& path) {
    const auto grab = [&window, path] {
        QTimer::singleShot(1500, &window, [&window, path] {
            const bool ok = window.screenshot().save(path);
            std::fprintf(stderr, "%s %s\n", ok ? "wrote" : "could not write", qPrintable(path));
            QApplication::exit(ok ? 0 : 1);
        });
    };
    // A record as the excitation: the single run and its critical scale, no surface.
    QObject::connect(&window, &MainWindow::recordRunFinished, &window, grab);
    QObject::connect(&window, &MainWindow::sweepFinished, &window, [&window, grab] {
        const SweepGrid& g = window.lastSweep().grid;
        if (!g.amplitudes.empty() && !g.frequencies.empty())
            window.surfaceView()->selectPoint(nearest(g.amplitudes, 1.0),
                                              nearest(g.frequencies, 1.125));
        grab(); // after the charts and the 3D view have repainted
    });
    window.resize(1280, 800); // the documented size, whatever the settings say
    QTimer::singleShot(500, &window, &MainWindow::runSweep);
}

} // namespace kinstab::ui
