// SPDX-License-Identifier: GPL-3.0-or-later
// The 2-D charts (issue 35): every value axis ticks on 1-2-5 steps whatever range it is given
// (0.5, 1.0, 1.5 and not 0.96, 1.44, 1.92), a right-hand axis draws no second grid, and a
// right-click on any chart offers Save image… and Copy image.

#include "ui/ChartMenu.h"
#include "ui/CriticalChart.h"
#include "ui/MainWindow.h"
#include "ui/NiceAxisTicks.h"

#include <QAction>
#include <QApplication>
#include <QChartView>
#include <QClipboard>
#include <QContextMenuEvent>
#include <QMenu>
#include <QStandardPaths>
#include <QValueAxis>
#include <QtTest>

#include <cmath>

using namespace kinstab::ui;

namespace {
// 1, 2 or 5 times a power of ten.
bool isOneTwoFive(double step) {
    if (!(step > 0)) return false;
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-12));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (std::abs(mantissa - m) < 1e-9) return true;
    return false;
}
} // namespace

class TestChartTicks : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void oneTwoFiveWhateverTheRange() {
        QChart chart;
        auto* a = new QValueAxis;
        chart.addAxis(a, Qt::AlignLeft);
        useNiceTicks(a);
        // The ranges the issue saw: 0 … 1.92 (ticks 0.48 apart), 0.151 … 0.303, 0 … 16.3 τ.
        const std::pair<double, double> ranges[] = {{0, 1.92}, {0.151, 0.303}, {0, 16.3}};
        const double steps[] = {0.5, 0.05, 5.0}; // the 1-2-5 step giving at most 6 intervals
        for (int i = 0; i < 3; ++i) {
            a->setRange(ranges[i].first, ranges[i].second);
            QCOMPARE(a->tickType(), QValueAxis::TicksDynamic);
            QCOMPARE(a->tickAnchor(), 0.0);
            QCOMPARE_LE(std::abs(a->tickInterval() - steps[i]), 1e-12);
        }
        QCOMPARE(a->labelFormat(), QStringLiteral("%.0f")); // steps of 5: no decimals
        auto* right = new QValueAxis;
        chart.addAxis(right, Qt::AlignRight);
        useNiceTicks(right);
        right->setRange(-1.1, 1.1);
        QVERIFY(!right->isGridLineVisible());
    }

    void everyChartOfTheWindow() {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.runSweep();
        QTRY_VERIFY_WITH_TIMEOUT(!w.lastSweep().points.empty(), 60000);
        int axes = 0;
        for (QChartView* v : w.findChildren<QChartView*>()) {
            useNiceTicks(v->chart()); // as showing it does (charts on hidden tabs not yet shown)
            for (QAbstractAxis* x : v->chart()->axes()) {
                auto* a = qobject_cast<QValueAxis*>(x);
                if (!a || !(a->max() > a->min())) continue; // no data yet: nothing to tick
                ++axes;
                QVERIFY2(isOneTwoFive(a->tickInterval()),
                         qPrintable(v->chart()->title() + " " + a->titleText() + ": " +
                                    QString::number(a->tickInterval())));
            }
        }
        QCOMPARE_GE(axes, 8);
    }

    void rightClickSavesOrCopies() {
        MainWindow w; // installs the menus
        auto* chart = w.findChild<CriticalChart*>();
        QVERIFY(chart);
        chart->resize(400, 300);
        QMenu* menu = chartMenu(chart);
        auto* save = menu->findChild<QAction*>(QStringLiteral("saveChartImage"));
        auto* copy = menu->findChild<QAction*>(QStringLiteral("copyChartImage"));
        QVERIFY(save && copy);
        copy->trigger();
        const QImage img = QApplication::clipboard()->image();
        QCOMPARE(img.size(), QSize(800, 600)); // rendered at twice the view's size
        // The application's filter answers a right-click on the chart's viewport.
        QContextMenuEvent e(QContextMenuEvent::Mouse, QPoint(10, 10),
                            chart->viewport()->mapToGlobal(QPoint(10, 10)));
        QVERIFY(QApplication::sendEvent(chart->viewport(), &e));
        QTRY_VERIFY(QApplication::activePopupWidget() != nullptr ||
                    !chart->findChildren<QMenu*>().isEmpty());
        delete menu;
    }
};

QTEST_MAIN(TestChartTicks)
#include "tst_chart_ticks.moc"
