// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/TopViewPainter.h"

#include "ui/teaching/StateStyle.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

namespace {
constexpr double kSpan = 6.0; // outer face to outer face, in d, as the side view

// World (x across, y along the walls, both in d) to screen, y up; origin mid-span.
struct PlanWorld {
    QPointF c;
    double k = 1; // pixels per d
    QPointF at(double x, double y) const { return {c.x() + (x - kSpan / 2) * k, c.y() - y * k}; }
    QRectF box(double x0, double y0, double x1, double y1) const {
        return QRectF(at(x0, y1), at(x1, y0));
    }
};

// A line of words across the area, 6 px in from each side.
QRectF textRect(const QRectF& area, double top, double h) {
    return QRectF(area.left() + 6, top, area.width() - 12, h);
}
// The height the text takes, wrapped at spaces in textRect's width.
double wrappedHeight(const QFontMetrics& fm, const QRectF& area, const QString& text) {
    const QRect column(0, 0, static_cast<int>(textRect(area, 0, 0).width()), 100000);
    return fm.boundingRect(column, kTopViewTextFlags, text).height() + 2.0;
}

// The walls, the slab at rest (dotted) and now, translucent so the walls show through.
void paintPlan(QPainter& p, const PlanWorld& w, const SlabScene& s, double wallLength) {
    const TeachingFrame& fr = s.frame;
    const double L = s.params.limit;
    p.setPen(QPen(QColor(0x55, 0x52, 0x4c), 1.2));
    p.setBrush(QColor(0xc9, 0xc4, 0xbb));
    p.drawRect(w.box(0, -wallLength / 2, 1, wallLength / 2));
    p.drawRect(w.box(kSpan - 1, -wallLength / 2, kSpan, wallLength / 2));
    const double xl0 = 1.0 - L / 2, xr0 = kSpan - 1.0 + L / 2;
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(0x55, 0x55, 0x55), 1, Qt::DotLine));
    p.drawRect(w.box(xl0, -wallLength / 2, xr0, wallLength / 2));
    const double dx = fr.delta / 2, dy = fr.deltaY / 2; // d/2 -> d
    QColor fill = stateColor(fr.state);
    fill.setAlpha(150);
    p.setBrush(fill);
    p.setPen(QPen(stateColor(fr.state).darker(150), 1.5));
    p.drawRect(w.box(xl0 + dx, -wallLength / 2 + dy, xr0 + dx, wallLength / 2 + dy));
}

// Base acceleration in plan, 1.5 d per g.
void paintPlanArrow(QPainter& p, const PlanWorld& w, const TeachingFrame& fr) {
    const QPointF o = w.at(kSpan / 2, 0);
    const QPointF tip = o + QPointF(fr.accel, -fr.accelY) * 1.5 * w.k;
    p.setPen(QPen(QColor(0x1f, 0x3b, 0x73), 2.5));
    p.drawLine(o, tip);
    p.setBrush(QColor(0x1f, 0x3b, 0x73));
    p.drawEllipse(tip, 3, 3);
}

// The words and their rectangles in one font.
TopViewLayout layoutInFont(const QFont& font, const QRectF& area, const SlabScene& s) {
    const TeachingFrame& fr = s.frame;
    TopViewLayout l;
    l.font = font;
    l.header = QStringLiteral("top view: δx = %1, δy = %2 (d/2)")
                   .arg(fr.delta, 0, 'f', 3)
                   .arg(fr.deltaY, 0, 'f', 3);
    l.footer = QStringLiteral("wall length %1 d (Θ = %2); arrow: base a_h\n"
                              "a_x = %3 g, a_y = %4 g")
                   .arg(s.params.theta / 2.0, 0, 'g', 3)
                   .arg(s.params.theta, 0, 'g', 3)
                   .arg(fr.accel, 0, 'f', 2)
                   .arg(fr.accelY, 0, 'f', 2);
    const QFontMetrics fm(font);
    const double headerH = wrappedHeight(fm, area, l.header);
    const double footerH = wrappedHeight(fm, area, l.footer);
    l.headerRect = textRect(area, area.top(), headerH);
    l.footerRect = textRect(area, area.bottom() - footerH, footerH);
    l.plan = area.adjusted(0, headerH, 0, -footerH);
    return l;
}

} // namespace

TopViewLayout topViewLayout(const QFont& font, const QRectF& area, const SlabScene& s) {
    TopViewLayout l = layoutInFont(font, area, s);
    QFont smaller = font;
    constexpr int kMaxShrinks = 8; // 0.85^8 = 0.27: 300 % text down to about 80 %
    for (int i = 0; i < kMaxShrinks && l.plan.height() < 0.5 * area.height(); ++i) {
        if (smaller.pixelSize() > 0)
            smaller.setPixelSize(std::max(6, static_cast<int>(smaller.pixelSize() * 0.85)));
        else
            smaller.setPointSizeF(smaller.pointSizeF() * 0.85);
        l = layoutInFont(smaller, area, s);
    }
    return l;
}

void paintTopView(QPainter& p, const QRectF& area, const SlabScene& s) {
    const double wallLength = s.params.theta / 2.0; // in d: theta = 2 wall length / wall width
    const TopViewLayout l = topViewLayout(p.font(), area, s);
    // The plan takes what the text leaves, with 0.6 d around it for the arrow.
    const double worldW = kSpan + 2.4, worldH = wallLength + 1.2;
    const double k = std::min(l.plan.width() / worldW, l.plan.height() / worldH);
    const PlanWorld w{l.plan.center(), std::max(0.0, k)};
    p.save();
    p.setClipRect(area);
    p.setFont(l.font);
    p.setPen(QColor(0x33, 0x33, 0x33));
    p.drawText(l.headerRect, kTopViewTextFlags, l.header);
    paintPlan(p, w, s, wallLength);
    paintPlanArrow(p, w, s.frame);
    p.setPen(QColor(0x33, 0x33, 0x33));
    p.drawText(l.footerRect, kTopViewTextFlags, l.footer);
    p.restore();
}

} // namespace kinstab::ui
