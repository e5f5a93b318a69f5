// SPDX-License-Identifier: GPL-3.0-or-later
// The γc surface without OpenGL (offscreen): the empty state says what to do, the 2D map and
// the colour bar share one colour scale whose ticks fall on 1-2-5 steps, the axes fit the grid
// (code ratios outside it are listed, not drawn by stretching the axis), and the 3D-only
// switches are disabled. The tick values are worked by hand from the 1-2-5 rule.

#include "ui/ColourBar.h"
#include "ui/HeatMapView.h"
#include "ui/NiceTicks.h"
#include "ui/SurfaceView.h"

#include <QLabel>
#include <QStackedWidget>
#include <QToolButton>
#include <QtTest>

#include <cmath>

using namespace kinstab::ui;

namespace {
// gamma = 2.3 (A - 0.6) f on A 0.6-1.5 step 0.1, f 0.5-2.0 step 0.5: largest 4.14 at (1.5, 2).
GammaGrid testGrid() {
    GammaGrid g;
    for (int i = 0; i <= 9; ++i)
        g.amplitudes.push_back(0.6 + 0.1 * i);
    g.frequencies = {0.5, 1.0, 1.5, 2.0};
    for (double a : g.amplitudes)
        for (double f : g.frequencies)
            g.gamma.push_back(2.3 * (a - 0.6) * f);
    return g;
}
} // namespace

class TestSurfaceMap : public QObject {
    Q_OBJECT
private slots:
    void niceSteps_data() {
        QTest::addColumn<double>("lo");
        QTest::addColumn<double>("hi");
        QTest::addColumn<int>("maxTicks");
        QTest::addColumn<double>("step");
        QTest::addColumn<double>("min");
        QTest::addColumn<double>("max");
        // span / maxTicks, then the next of 1, 2, 5 × 10^k at or above it.
        QTest::newRow("A 0.505-1.5, 10") << 0.505 << 1.5 << 10 << 0.1 << 0.5 << 1.5;
        QTest::newRow("f 0.26-2.25, 10") << 0.26 << 2.25 << 10 << 0.2 << 0.2 << 2.4;
        QTest::newRow("gamma 0-4.14, 6") << 0.0 << 4.14 << 6 << 1.0 << 0.0 << 5.0;
        QTest::newRow("gamma 0-0.37, 6") << 0.0 << 0.37 << 6 << 0.1 << 0.0 << 0.4;
        QTest::newRow("0.7-1.15, 6") << 0.7 << 1.15 << 6 << 0.1 << 0.7 << 1.2;
    }
    void niceSteps() {
        QFETCH(double, lo);
        QFETCH(double, hi);
        QFETCH(int, maxTicks);
        QFETCH(double, step);
        QFETCH(double, min);
        QFETCH(double, max);
        const NiceAxis a = niceAxis(lo, hi, maxTicks);
        QCOMPARE_LE(std::abs(a.step - step), 1e-12);
        QCOMPARE_LE(std::abs(a.min - min), 1e-12);
        QCOMPARE_LE(std::abs(a.max - max), 1e-12);
        for (double t : niceTicks(lo, hi, maxTicks)) {
            const double k = t / a.step;
            QCOMPARE_LE(std::abs(k - std::round(k)), 1e-9); // every tick a whole step
            QVERIFY(t >= lo - 1e-12 && t <= hi + 1e-12);
        }
    }

    void emptyStateSaysPressRun() {
        SurfaceView v;
        v.resize(800, 600);
        auto* hint = v.findChild<QLabel*>(QStringLiteral("emptyHint"));
        QVERIFY(hint);
        QVERIFY(hint->text().contains(QStringLiteral("Press Run (F5)")));
        QCOMPARE(v.findChild<QStackedWidget*>()->currentWidget(), hint);
        QVERIFY(!v.colourBar()->isVisibleTo(&v));
        v.setData(testGrid());
        QCOMPARE(v.graphWidget(), static_cast<QWidget*>(v.heatMap()));
        v.setData(GammaGrid{});
        QCOMPARE(v.findChild<QStackedWidget*>()->currentWidget(), hint);
    }

    void withoutOpenGlOnlyTheMap() {
        SurfaceView v;
        QVERIFY(!v.is3D());
        QCOMPARE(v.mode(), SurfaceMode::Map);
        QVERIFY(v.findChild<QToolButton*>(QStringLiteral("viewMap"))->isEnabled());
        for (const char* name : {"view3D", "viewTop", "wireframe", "resetView"})
            QVERIFY2(!v.findChild<QToolButton*>(QLatin1String(name))->isEnabled(), name);
        v.setMode(SurfaceMode::Top);
        QCOMPARE(v.mode(), SurfaceMode::Map);
    }

    // A cell's colour is gammaColor(γ / top of the scale), the scale's top is the largest γc
    // (4.14) rounded up to a whole step (5), and the colour bar shows the same top.
    void mapAndColourBarShareTheScale() {
        const GammaGrid g = testGrid();
        QCOMPARE(colourScaleMaximum(g), 5.0);
        SurfaceView v;
        v.resize(900, 600);
        v.setData(g);
        QCOMPARE(v.colourBar()->maximum(), 5.0);
        HeatMapView* map = v.heatMap();
        map->resize(900, 600);
        const QImage img = map->grab().toImage();
        // The cell (A = 1.5, f = 2.0) is the top-right one: its colour is γ = 4.14 of 5.
        const QColor expected = gammaColor(4.14 / 5.0);
        bool found = false;
        for (int y = 0; y < img.height() && !found; ++y)
            for (int x = 0; x < img.width() && !found; ++x)
                found = QColor(img.pixel(x, y)) == expected;
        QVERIFY(found);
    }

    // Code ratios below the grid do not widen the A axis: the legend says they are outside.
    void codesOutsideTheGridAreListedNotDrawn() {
        SurfaceView v;
        v.setData(testGrid());
        SurfaceOverlays o;
        o.codes.push_back({QStringLiteral("UBC 1976"), 0.23, Qt::magenta});
        o.codes.push_back({QStringLiteral("Inside"), 1.0, Qt::green});
        v.setOverlays(o);
        QVERIFY(v.legendText().contains(QStringLiteral("UBC 1976 0.230 g (outside the grid)")));
        QVERIFY(v.legendText().contains(QStringLiteral("Inside 1.000 g")));
        QVERIFY(!v.legendText().contains(QStringLiteral("Inside 1.000 g (outside")));
        // No magenta pixel: the 0.23 g line is not in the map.
        HeatMapView* map = v.heatMap();
        map->resize(700, 500);
        const QImage img = map->grab().toImage();
        bool magenta = false, green = false;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) {
                const QColor c(img.pixel(x, y));
                magenta |= c == QColor(Qt::magenta);
                green |= c == QColor(Qt::green);
            }
        QVERIFY(!magenta);
        QVERIFY(green);
    }
};

QTEST_MAIN(TestSurfaceMap)
#include "tst_surface_map.moc"
