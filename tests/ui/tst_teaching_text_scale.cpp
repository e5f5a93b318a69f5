// SPDX-License-Identifier: GPL-3.0-or-later
// Presentation mode's "Text 200 %" at 1920 × 1080 (issue 35): the traces' tick labels and
// rotated axis titles, and the "Where am I?" map's labels, get the room their larger font needs.
// Before, the margins were fixed pixel counts for 11 px text, so the y-titles and the bearing
// limit's label were clipped and the map's "f [Hz]" ran into its legend. Each check compares a
// layout's margin with the width or height Qt measures for the text that must fit in it.

#include "ui/teaching/SurfaceMarker.h"
#include "ui/teaching/TeachingRun.h"
#include "ui/teaching/TextScale.h"
#include "ui/teaching/TracePainter.h"

#include <QApplication>
#include <QFontMetricsF>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

namespace {

QFont scaledFont(double scale) {
    QFont f = QApplication::font();
    f.setPointSizeF(f.pointSizeF() * scale);
    return f;
}

QFont labelFont(const QFont& view) {
    QFont f = view;
    f.setPixelSize(traceLabelPixels(view));
    return f;
}

} // namespace

class TestTeachingTextScale : public QObject {
    Q_OBJECT
private slots:
    void traceMarginsHoldTheirLabels_data() {
        QTest::addColumn<double>("scale");
        for (const double s : {1.0, 1.5, 2.0, 3.0})
            QTest::addRow("text %d %%", static_cast<int>(s * 100)) << s;
    }
    void traceMarginsHoldTheirLabels() {
        QFETCH(double, scale);
        const QFont view = scaledFont(scale);
        const QFontMetricsF fm(labelFont(view));
        const QRectF area(0, 0, 1200, 420);
        const TeachingRun run;
        const TraceLayout l = traceLayout(area, run, traceLabelPixels(view));
        // Left: the widest tick label of the a(τ) axis beside the rotated title's line.
        const double leftNeeded = fm.horizontalAdvance(QStringLiteral("-0.75")) + fm.height();
        QCOMPARE_GE(l.accelPlot.left() - area.left(), leftNeeded);
        // Below the δ plot: the τ tick labels and the τ caption, one line each.
        QCOMPARE_GE(area.bottom() - l.deltaPlot.bottom(), 2 * fm.height());
        QCOMPARE_GE(l.lineHeight, fm.height());
        // The two plots keep their order and a positive height.
        QCOMPARE_GT(l.accelPlot.height(), 0.0);
        QCOMPARE_GE(l.deltaPlot.top(), l.accelPlot.bottom());
    }

    void mapMarginsHoldTheirLabels() {
        const QFont view = scaledFont(2.0);
        SurfaceMarker map;
        map.setFont(view);
        map.resize(460, 260);
        const QFontMetricsF fm(labelFont(view));
        const QRectF r = map.plotRect();
        // Left: a tick label such as "0.85" and the rotated "A [g]" title.
        QCOMPARE_GE(r.left(), fm.horizontalAdvance(QStringLiteral("0.85")) + fm.height());
        // Top: the heading line; bottom: tick labels, then "f [Hz]" and the legend.
        QCOMPARE_GE(r.top(), fm.height());
        QCOMPARE_GE(map.height() - r.bottom(), 2 * fm.height());
    }
};

QTEST_MAIN(TestTeachingTextScale)
#include "tst_teaching_text_scale.moc"
