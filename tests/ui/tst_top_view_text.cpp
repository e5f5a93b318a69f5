// SPDX-License-Identifier: GPL-3.0-or-later
// The planar teaching view's top view at 1280 × 800 is about 180 px wide: its header ("top view:
// δx …, δy … (d/2)") and footer ("wall length … d (Θ = …); arrow: base a_h", "a_x …, a_y …")
// were drawn on one line each and cut at the right edge. They now wrap. Each check compares the
// rectangle the layout gives a text with the one Qt measures for that text, wrapped the same way.
// In presentation mode's large text the words would take the whole view: there they get a
// smaller font, so that the plan keeps half the height.

#include "ui/teaching/TopViewPainter.h"

#include <QApplication>
#include <QFontMetrics>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

namespace {

SlabScene planarScene() {
    SlabScene s;
    s.params.theta = 20; // the paper's Θ (ch. VI): a wall 10 d long
    s.frame.delta = -0.123;
    s.frame.deltaY = 0.456;
    s.frame.accel = 0.61;
    s.frame.accelY = -0.55;
    return s;
}

// The text fits its rectangle: Qt's wrapped bounding box is no wider and no taller.
void checkFits(const QFontMetrics& fm, const QRectF& rect, const QString& text) {
    const QRect need = fm.boundingRect(rect.toAlignedRect(), kTopViewTextFlags, text);
    QCOMPARE_LE(need.width(), qCeil(rect.width()));
    QCOMPARE_LE(need.height(), qCeil(rect.height()));
}

} // namespace

class TestTopViewText : public QObject {
    Q_OBJECT
private slots:
    void textFitsItsRoom_data() {
        QTest::addColumn<double>("scale");
        QTest::addColumn<double>("width");
        for (const double s : {1.0, 1.5, 2.0, 3.0})
            for (const double w : {140.0, 180.0, 260.0})
                QTest::addRow("text %d %%, %d px", static_cast<int>(s * 100), static_cast<int>(w))
                    << s << w;
    }
    void textFitsItsRoom() {
        QFETCH(double, scale);
        QFETCH(double, width);
        QFont font = QApplication::font();
        font.setPointSizeF(font.pointSizeF() * scale);
        const QRectF area(10, 20, width, 600);
        const TopViewLayout l = topViewLayout(font, area, planarScene());
        const QFontMetrics fm(l.font);
        checkFits(fm, l.headerRect, l.header);
        checkFits(fm, l.footerRect, l.footer);
        // Inside the area, the plan between the two texts.
        QCOMPARE_GE(l.headerRect.left(), area.left());
        QCOMPARE_LE(l.headerRect.right(), area.right());
        QCOMPARE_GE(l.plan.top(), l.headerRect.bottom());
        QCOMPARE_LE(l.plan.bottom(), l.footerRect.top());
        QCOMPARE_LE(l.footerRect.bottom(), area.bottom());
        // The plan keeps at least half the height; larger text is made smaller to leave it.
        QCOMPARE_GE(l.plan.height(), 0.5 * area.height());
        QCOMPARE_LE(l.font.pointSizeF(), font.pointSizeF());
    }
    // At the width the view has at 1280 × 800 the header does not fit one line, so the test above
    // exercises the wrapping.
    void headerIsWiderThanTheNarrowView() {
        const QFontMetrics fm(QApplication::font());
        const TopViewLayout l =
            topViewLayout(QApplication::font(), QRectF(0, 0, 140, 400), planarScene());
        QCOMPARE_EQ(l.font, QApplication::font()); // room enough: the view's own font
        QCOMPARE_GT(fm.horizontalAdvance(l.header), qRound(l.headerRect.width()));
        QCOMPARE_GT(l.headerRect.height(), 1.5 * fm.height());
    }
};

QTEST_MAIN(TestTopViewText)
#include "tst_top_view_text.moc"
