// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/AutoScreenshot.h"

#include "ui/CodesPanel.h"
#include "ui/GridPanel.h"
#include "ui/MainWindow.h"
#include "ui/NumberField.h"
#include "ui/SlabPanel.h"
#include "ui/SurfaceView.h"
#include "ui/teaching/PresentationMode.h"
#include "ui/teaching/TeachingPlayer.h"
#include "ui/teaching/TeachingView.h"

#include <QApplication>
#include <QScrollArea>
#include <QTabWidget>
#include <QTimer>

#include <cmath>
#include <cstdio>
#include <memory>

namespace kinstab::ui {

namespace {
int nearest(const std::vector<double>& v, double x) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < v.size(); ++i)
        if (std::abs(v[i] - x) < std::abs(v[best] - x)) best = i;
    return static_cast<int>(best);
}
void saveAndQuit(MainWindow& window, const QString& path) {
    // After the charts and the 3D view have repainted.
    QTimer::singleShot(1500, &window, [&window, path] {
        const bool ok = window.screenshot().save(path);
        std::fprintf(stderr, "%s %s\n", ok ? "wrote" : "could not write", qPrintable(path));
        QApplication::exit(ok ? 0 : 1);
    });
}

void pickFig35(MainWindow& window) {
    const SweepGrid& g = window.lastSweep().grid;
    if (!g.amplitudes.empty() && !g.frequencies.empty())
        window.surfaceView()->selectPoint(nearest(g.amplitudes, 1.0),
                                          nearest(g.frequencies, 1.125));
}

// The step after the first sweep: changes inputs through the panels, as a user would.
void applyStep(MainWindow& window, const QString& step) {
    if (step.startsWith(QLatin1String("open:"))) {
        window.openProject(step.mid(5), true);
    } else if (step == QLatin1String("codes")) {
        CodeSelection c = window.codesPanel()->codes();
        if (c.ubc1976) c.ubc1976->zone = 3;
        window.codesPanel()->setCodes(c);
    } else if (step == QLatin1String("mu")) {
        if (auto* mu = window.slabPanel()->findChild<NumberField*>(QStringLiteral("mu")))
            mu->setValue(window.currentCase().slab.mu + 0.05);
    }
}

// A 200 × 200 grid over the paper's range and beyond (A 0.505-1.5 g, f 0.26-2.25 Hz).
void fineGrid(MainWindow& window) {
    window.gridPanel()->setRanges(GridRanges{0.505, 1.5, 0.005, 0.26, 2.25, 0.01});
}

// The Teaching view in presentation mode, a moment into the "moderate shaking" preset's run.
void present(MainWindow& window, const QString& path) {
    TeachingView* view = window.teachingView();
    view->applyPreset(QStringLiteral("fig29"));
    if (auto* mode = window.findChild<PresentationMode*>()) mode->enter();
    view->player()->seek(view->run().displayEnd() * 0.55);
    saveAndQuit(window, path);
}

bool isViewStep(const QString& step) {
    return step == QLatin1String("top") || step == QLatin1String("map");
}

// "STEP@WIDTHxHEIGHT": the window size (1280 × 800 without it); false for a malformed size.
bool splitSize(QString& step, QSize& size) {
    size = QSize(1280, 800);
    const qsizetype at = step.lastIndexOf(QLatin1Char('@'));
    if (at < 0) return true;
    const QStringList wh = step.mid(at + 1).split(QLatin1Char('x'));
    step.truncate(at);
    bool okW = false, okH = false;
    if (wh.size() == 2) size = QSize(wh[0].toInt(&okW), wh[1].toInt(&okH));
    return okW && okH && size.width() >= 640 && size.height() >= 480 && size.width() <= 7680 &&
           size.height() <= 4320;
}

} // namespace

QString screenshotScenario(MainWindow& window, const QString& scenario, const QString& path) {
    QString step = scenario;
    QSize size;
    if (!splitSize(step, size))
        return QStringLiteral("--scenario %1: the size after @ must be WIDTHxHEIGHT, from 640x480 "
                              "to 7680x4320")
            .arg(scenario);
    const bool known = step.startsWith(QLatin1String("open:")) || step == QLatin1String("codes") ||
                       step == QLatin1String("mu") || step == QLatin1String("cancel") ||
                       isViewStep(step) || step == QLatin1String("present");
    if (!known)
        return QStringLiteral("--scenario %1: must be open:PROJECT, codes, mu, cancel, top, map or "
                              "present "
                              "(optionally @WIDTHxHEIGHT)")
            .arg(scenario);
    window.resize(size);
    if (step == QLatin1String("present")) {
        QTimer::singleShot(500, &window, [&window, path] { present(window, path); });
        return {};
    }
    auto once = std::make_shared<bool>(false);
    QObject::connect(&window, &MainWindow::sweepFinished, &window, [&window, step, path, once] {
        if (*once) return;
        *once = true;
        pickFig35(window);
        if (step == QLatin1String("top")) window.surfaceView()->setMode(SurfaceMode::Top);
        if (step == QLatin1String("map")) window.surfaceView()->setMode(SurfaceMode::Map);
        if (step != QLatin1String("cancel")) applyStep(window, step);
        saveAndQuit(window, path);
    });
    if (step == QLatin1String("cancel")) {
        // Long enough that the cancel comes first (tests/ui/tst_mainwindow: seconds of work).
        window.gridPanel()->setRanges(GridRanges{0.6, 1.5, 0.01, 10.0, 30.0, 0.1});
        QTimer::singleShot(2000, &window, &MainWindow::cancelSweep);
    }
    if (isViewStep(step)) fineGrid(window);
    QTimer::singleShot(500, &window, &MainWindow::runSweep);
    return {};
}

void screenshotAfterSweep(MainWindow& window, const QString& path, QSize size, int gridPoints,
                          const QString& tab) {
    if (gridPoints > 1) {
        GridRanges r = window.gridPanel()->ranges();
        // A hair under the exact step, so that rounding cannot drop the last point.
        const double n = (gridPoints - 1) * (1 + 1e-9);
        r.aStep = (r.aTo - r.aFrom) / n;
        r.fStep = (r.fTo - r.fFrom) / n;
        window.gridPanel()->setRanges(r);
    }
    const auto grab = [&window, path, tab] {
        // "Study/Risk": the centre's Study tab, then its Risk view.
        for (const QString& part : tab.split('/', Qt::SkipEmptyParts))
            for (QTabWidget* t : window.findChildren<QTabWidget*>())
                for (int i = 0; i < t->count(); ++i)
                    if (t->tabText(i).startsWith(part)) {
                        t->setCurrentIndex(i);
                        // A view inside a scrolled tab: scrolled into sight for the image.
                        for (QWidget* w = t->parentWidget(); w; w = w->parentWidget())
                            if (auto* area = qobject_cast<QScrollArea*>(w))
                                area->ensureWidgetVisible(t, 0, 0);
                    }
        QTimer::singleShot(1500, &window, [&window, path] {
            const bool ok = window.screenshot().save(path);
            std::fprintf(stderr, "%s %s\n", ok ? "wrote" : "could not write", qPrintable(path));
            QApplication::exit(ok ? 0 : 1);
        });
    };
    // A record as the excitation: the single run and its critical scale, no surface. Either way
    // the image waits for the whole assessment (it follows the run).
    QObject::connect(&window, &MainWindow::assessmentFinished, &window, grab);
    QObject::connect(&window, &MainWindow::sweepFinished, &window, [&window] {
        const SweepGrid& g = window.lastSweep().grid;
        if (!g.amplitudes.empty() && !g.frequencies.empty())
            window.surfaceView()->selectPoint(nearest(g.amplitudes, 1.0),
                                              nearest(g.frequencies, 1.125));
    });
    window.resize(size); // the documented size, whatever the settings say
    window.resetLayout();
    QTimer::singleShot(500, &window, &MainWindow::runSweep);
}

} // namespace kinstab::ui
