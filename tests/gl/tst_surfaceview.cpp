// The 3D γc surface under xcb + Xvfb (Mesa software OpenGL): it renders, reports picks as
// (amplitude index, frequency index), keeps its overlays, and the window's screenshot carries
// the rendered surface (a plain grab() of the GL window would be blank).

#include "ui/GridPanel.h"
#include "ui/MainWindow.h"
#include "ui/SurfaceView.h"

#include <QAction>
#include <QSet>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

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
        view.resize(640, 480);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
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
};

QTEST_MAIN(TestSurfaceView)
#include "tst_surfaceview.moc"
