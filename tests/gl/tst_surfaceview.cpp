// SPDX-License-Identifier: GPL-3.0-or-later
// The 3D γc surface under xcb + Xvfb (Mesa software OpenGL): it renders, reports picks as
// (amplitude index, frequency index), keeps its overlays, and the window's screenshot carries
// the rendered surface (a plain grab() of the GL window would be blank).

#include "ui/ColourBar.h"
#include "ui/GridPanel.h"
#include "ui/HeatMapView.h"
#include "ui/MainWindow.h"
#include "ui/SurfaceView.h"

#include <QAction>
#include <QGuiApplication>
#include <QSet>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QToolButton>
#include <QtDataVisualization/Q3DCamera>
#include <QtDataVisualization/Q3DSurface>
#include <QtDataVisualization/QSurface3DSeries>
#include <QtDataVisualization/QSurfaceDataProxy>

#include <cmath>

using namespace kinstab;
using namespace kinstab::ui;

namespace {
int distinctColours(const QImage& img, const QRect& r) {
    QSet<QRgb> colours;
    for (int y = r.top(); y <= r.bottom(); y += 3)
        for (int x = r.left(); x <= r.right(); x += 3)
            colours.insert(img.pixel(x, y));
    return static_cast<int>(colours.size());
}
// gamma = A * f on a 4 x 3 grid: every point distinct, so a wrong index shows.
GammaGrid testGrid() {
    GammaGrid g;
    g.amplitudes = {0.8, 0.9, 1.0, 1.1};
    g.frequencies = {0.5, 1.0, 1.5};
    for (double a : g.amplitudes)
        for (double f : g.frequencies)
            g.gamma.push_back(a * f);
    return g;
}
// Pixels of a neutral mid grey (the shaded "not computed" patch; the theme's background and
// the γc colours are not grey in that range).
long greyPixels(const QImage& img) {
    long n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const QColor c(img.pixel(x, y));
            n += std::abs(c.red() - c.green()) < 8 && std::abs(c.green() - c.blue()) < 8 &&
                 c.red() > 110 && c.red() < 225;
        }
    return n;
}
// The stable half computed (γc = 0), the other half not: a cancelled sweep.
GammaGrid halfCancelled() {
    GammaGrid g = testGrid();
    for (std::size_t k = 0; k < g.gamma.size(); ++k)
        g.gamma[k] = k < g.gamma.size() / 2 ? 0.0 : std::nan("");
    return g;
}
// The view at 640 × 480 on screen (the GL window renders only when exposed).
bool shown(SurfaceView& view) {
    view.resize(640, 480);
    view.show();
    return QTest::qWaitForWindowExposed(&view);
}
GammaGrid squareGrid(int n) {
    GammaGrid g;
    for (int i = 0; i < n; ++i) {
        g.amplitudes.push_back(0.5 + 0.01 * i);
        g.frequencies.push_back(0.5 + 0.02 * i);
    }
    for (double a : g.amplitudes)
        for (double f : g.frequencies)
            g.gamma.push_back(a * f);
    return g;
}
Q3DSurface* graphWindow() {
    for (QWindow* win : QGuiApplication::allWindows())
        if (auto* graph = qobject_cast<Q3DSurface*>(win)) return graph;
    return nullptr;
}
// The γc series: the one coloured by the range gradient.
QSurface3DSeries* surfaceSeries() {
    if (Q3DSurface* graph = graphWindow())
        for (QSurface3DSeries* s : graph->seriesList())
            if (s->colorStyle() == Q3DTheme::ColorStyleRangeGradient) return s;
    return nullptr;
}
// The "not computed" series of the 3D graph: finite points only where γc is NaN.
QSurface3DSeries* notComputedSeries() {
    for (QWindow* win : QGuiApplication::allWindows())
        if (auto* graph = qobject_cast<Q3DSurface*>(win))
            for (QSurface3DSeries* s : graph->seriesList())
                if (s->baseColor() == notComputedColor()) return s;
    return nullptr;
}
} // namespace

class TestSurfaceView : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        if (qEnvironmentVariableIsEmpty("DISPLAY"))
            QSKIP("needs an X display (run under xvfb-run)");
    }

    void rendersAndSelects() {
        SurfaceView view;
        if (!view.is3D()) QSKIP("no OpenGL context");
        QVERIFY(shown(view));
        view.setData(testGrid());
        SurfaceOverlays o;
        o.codes = {{"UBC 1976", 0.16, Qt::magenta}, {"ATC 3-06", 0.275, QColor(255, 140, 0)}};
        o.buildingFrequency = 1.0;
        o.aCrit = {{0.5, 0.85}, {1.0, 0.95}, {1.5, 1.05}};
        view.setOverlays(o);
        QSignalSpy spy(&view, &SurfaceView::pointSelected);
        view.selectPoint(2, 1); // A = 1.0, f = 1.0
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toInt(), 2);
        QCOMPARE(spy.at(0).at(1).toInt(), 1);
        const QImage img = view.renderImage(QSize(400, 300));
        QCOMPARE(img.size(), QSize(400, 300));
        QVERIFY(distinctColours(img, img.rect()) > 50); // a rendered scene, not a blank
    }

    // After Cancel: points never computed are a grey patch named in the legend, distinct from
    // stable (γc = 0, dark blue), not a hole or a stable-looking floor.
    void notComputedIsDrawnDistinctFromStable() {
        SurfaceView view;
        if (!view.is3D()) QSKIP("no OpenGL context");
        QVERIFY(shown(view));
        GammaGrid all = halfCancelled();
        for (double& g : all.gamma)
            g = 0.0; // everything computed and stable
        view.setData(all);
        QCOMPARE(view.notComputedCount(), 0);
        QVERIFY(!view.legendText().contains("not computed"));
        const long greyAllStable = greyPixels(view.renderImage(QSize(400, 300)));

        const GammaGrid half = halfCancelled();
        view.setData(half);
        QCOMPARE(view.notComputedCount(), 6);
        QVERIFY(view.legendText().contains("not computed (6 points)"));
        QSurface3DSeries* s = notComputedSeries();
        QVERIFY(s);
        int patch = 0;
        const QSurfaceDataArray& rows = *s->dataProxy()->array();
        for (qsizetype r = 0; r < rows.size(); ++r)
            for (qsizetype c = 0; c < rows[r]->size(); ++c) {
                const float y = rows[r]->at(c).y();
                const bool missing = std::isnan(half.at(std::size_t(c), std::size_t(r)));
                QCOMPARE(std::isfinite(y), missing);
                patch += missing;
            }
        QCOMPARE(patch, 6);
        const long greyHalf = greyPixels(view.renderImage(QSize(400, 300)));
        QVERIFY2(greyHalf > greyAllStable + 500,
                 qPrintable(QStringLiteral("%1 vs %2").arg(greyHalf).arg(greyAllStable)));
    }

    void screenshotAfterSweepShowsTheSurface() {
        MainWindow w;
        if (!w.surfaceView()->is3D()) QSKIP("no OpenGL context");
        w.gridPanel()->setRanges(GridRanges{0.9, 1.1, 0.05, 0.5, 1.25, 0.25});
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QSignalSpy done(&w, &MainWindow::sweepFinished);
        w.runAction()->trigger();
        QVERIFY(done.wait(60000));
        w.surfaceView()->selectPoint(2, 2);
        QVERIFY(w.pickedRun().has_value());
        const QImage shot = w.screenshot();
        QWidget* graph = w.surfaceView()->graphWidget();
        const QRect r(graph->mapTo(&w, QPoint(0, 0)) * shot.devicePixelRatio(),
                      graph->size() * shot.devicePixelRatio());
        QVERIFY(distinctColours(shot, r.intersected(shot.rect())) > 50);
    }

    // Grid lines on by default up to 60 × 60 points, off above; the toggle sets the series'
    // draw mode either way.
    void wireframeDefaultAndToggle() {
        SurfaceView view;
        if (!view.is3D()) QSKIP("no OpenGL context");
        QVERIFY(shown(view));
        view.setData(testGrid()); // 4 × 3
        QVERIFY(view.wireframe());
        QSurface3DSeries* surface = surfaceSeries();
        QVERIFY(surface);
        QCOMPARE(surface->drawMode(), QSurface3DSeries::DrawSurfaceAndWireframe);
        view.setData(squareGrid(61)); // 61 × 61 > 60 × 60
        QVERIFY(!view.wireframe());
        QCOMPARE(surface->drawMode(), QSurface3DSeries::DrawSurface);
        auto* toggle = view.findChild<QToolButton*>(QStringLiteral("wireframe"));
        QVERIFY(toggle && toggle->isEnabled() && !toggle->isChecked());
        toggle->click();
        QCOMPARE(surface->drawMode(), QSurface3DSeries::DrawSurfaceAndWireframe);
        view.setData(squareGrid(61)); // same shape again: the user's choice stays
        QVERIFY(view.wireframe());
        view.setData(squareGrid(60));
        QVERIFY(view.wireframe());
    }

    // Top view: orthographic, camera straight above; reset puts a rotated camera back; the 2D
    // map page replaces the GL window and the screenshot comes from it.
    void topViewMapAndReset() {
        SurfaceView view;
        if (!view.is3D()) QSKIP("no OpenGL context");
        QVERIFY(shown(view));
        view.setData(testGrid());
        Q3DSurface* graph = graphWindow();
        QVERIFY(graph);
        Q3DCamera* camera = graph->scene()->activeCamera();
        const float x0 = camera->xRotation(), y0 = camera->yRotation(), z0 = camera->zoomLevel();
        camera->setCameraPosition(75.0f, 10.0f, 300.0f); // as a user's drag and wheel would
        view.findChild<QToolButton*>(QStringLiteral("resetView"))->click();
        QCOMPARE(camera->xRotation(), x0);
        QCOMPARE(camera->yRotation(), y0);
        QCOMPARE(camera->zoomLevel(), z0);
        view.findChild<QToolButton*>(QStringLiteral("viewTop"))->click();
        QCOMPARE(view.mode(), SurfaceMode::Top);
        QVERIFY(graph->isOrthoProjection());
        QCOMPARE(camera->yRotation(), 90.0f); // looking straight down
        QVERIFY(view.showsGL());
        QVERIFY(view.colourBar()->isVisible());
        view.findChild<QToolButton*>(QStringLiteral("viewMap"))->click();
        QCOMPARE(view.mode(), SurfaceMode::Map);
        QVERIFY(!view.showsGL());
        QCOMPARE(view.graphWidget(), static_cast<QWidget*>(view.heatMap()));
        QVERIFY(!view.findChild<QToolButton*>(QStringLiteral("wireframe"))->isEnabled());
        view.findChild<QToolButton*>(QStringLiteral("view3D"))->click();
        QVERIFY(!graph->isOrthoProjection());
        QCOMPARE(camera->yRotation(), y0);
    }
};

QTEST_MAIN(TestSurfaceView)
#include "tst_surfaceview.moc"
