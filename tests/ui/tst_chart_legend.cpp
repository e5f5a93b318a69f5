// SPDX-License-Identifier: GPL-3.0-or-later
// The titles and legends of the three charts along the bottom of the window (ui/DockedChart.h)
// at 1280×800, where each dock is about 270 px wide: the title is shown whole and every named
// series is listed in full (QChart elided them to "…(cf…", "sli…", "A…"), all their lines fit
// inside the chart's view, and a series kept out of the legend (the lower envelope, -μ) stays
// out. The legend under the surface wraps too
// (its code ratios ran off the window's right edge).

#include "ui/CriticalChart.h"
#include "ui/HistoryChart.h"
#include "ui/MainWindow.h"
#include "ui/SliceChart.h"
#include "ui/SurfaceView.h"

#include <QChart>
#include <QChartView>
#include <QLabel>
#include <QLegendMarker>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTextDocument>
#include <QtTest>

using namespace kinstab::ui;

namespace {

// The label's text as shown (the entries join with no-break spaces).
QString shownText(const QLabel* l) {
    QTextDocument d;
    d.setHtml(l->text());
    return d.toPlainText().replace(QChar(0x00a0), QLatin1Char(' '));
}

// The names the chart gives its series, as QLegend would list them (unnamed ones left out).
QStringList seriesNames(const QChartView* v) {
    QStringList out;
    for (const QAbstractSeries* s : v->chart()->series())
        if (!s->name().isEmpty()) out << s->name();
    return out;
}

} // namespace

class TestChartLegend : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear(); // a first start: the default layout
    }

    void everyEntryInFullAt1280() {
        MainWindow w;
        w.resize(1280, 800);
        w.resetLayout();
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTest::qWait(100); // the views paint, and the legends follow
        const QList<QChartView*> views{w.sliceChart(), w.historyChart(),
                                       w.findChild<CriticalChart*>()};
        for (QChartView* v : views) {
            QVERIFY(v && v->isVisible());
            QCOMPARE_LE(v->width(), 330); // narrow: the case QLegend elided
            auto* legend = v->findChild<QLabel*>(QStringLiteral("chartLegend"));
            QVERIFY(legend);
            QVERIFY(legend->isVisible());
            const QString text = shownText(legend);
            const QStringList names = seriesNames(v);
            QVERIFY(!names.isEmpty());
            for (const QString& n : names)
                QVERIFY2(text.contains(n), qPrintable(n + " not in: " + text));
            QVERIFY2(!text.contains(QStringLiteral("…")), qPrintable(text));
            // All of its lines inside the view, below the plot.
            QCOMPARE_GE(legend->height(), legend->heightForWidth(legend->width()));
            QVERIFY(v->rect().contains(legend->geometry()));
            QCOMPARE_GE(legend->geometry().top(), qRound(v->chart()->plotArea().bottom()));
            auto* title = v->findChild<QLabel*>(QStringLiteral("chartTitle"));
            QVERIFY(title && title->isVisible());
            QCOMPARE(shownText(title), v->chart()->title());
            QCOMPARE_GE(title->height(), title->heightForWidth(title->width()));
            QCOMPARE_LE(title->geometry().bottom(), qRound(v->chart()->plotArea().top()));
        }
        // The history's lower envelope and -μ have no entry of their own.
        const QString history =
            shownText(w.historyChart()->findChild<QLabel*>(QStringLiteral("chartLegend")));
        QCOMPARE(history.count(QStringLiteral("envelope")), 1);

        // The surface's legend after a run, when it lists the code ratios outside the grid:
        // every line shown, inside the view's width.
        QSignalSpy done(&w, &MainWindow::sweepFinished);
        w.runSweep();
        QVERIFY(done.wait(60000));
        QTest::qWait(50);
        QLabel* surface = nullptr;
        for (QLabel* l : w.surfaceView()->findChildren<QLabel*>())
            if (l->text() == w.surfaceView()->legendText()) surface = l;
        QVERIFY(surface && surface->isVisible());
        QVERIFY(shownText(surface).contains(QStringLiteral("EC8 0.177 g (outside the grid)")));
        QCOMPARE_LE(surface->width(), w.surfaceView()->width());
        if (surface->wordWrap())
            QCOMPARE_GE(surface->height(), surface->heightForWidth(surface->width()));
        else // one line per <br>, cut at the label's right edge when longer
            QCOMPARE_LE(surface->sizeHint().width(), surface->width());
    }
};

QTEST_MAIN(TestChartLegend)
#include "tst_chart_legend.moc"
