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

// One line of text across the area's width, from its left edge, height h.
void drawTextLine(QPainter& p, const QRectF& area, double top, double h, const QString& text) {
    p.drawText(QRectF(area.left() + 6, top, area.width() - 12, h), Qt::AlignLeft | Qt::AlignVCenter,
               text);
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

} // namespace

void paintTopView(QPainter& p, const QRectF& area, const SlabScene& s) {
    const TeachingFrame& fr = s.frame;
    const double wallLength = s.params.theta / 2.0; // in d: theta = 2 wall length / wall width
    const double worldW = kSpan + 2.4, worldH = wallLength + 3.0;
    const PlanWorld w{area.center(), std::min(area.width() / worldW, area.height() / worldH)};
    p.save();
    p.setClipRect(area);
    p.setPen(QColor(0x33, 0x33, 0x33));
    drawTextLine(p, area, area.top(), 18,
                 QStringLiteral("top view: δx = %1, δy = %2 (d/2)")
                     .arg(fr.delta, 0, 'f', 3)
                     .arg(fr.deltaY, 0, 'f', 3));
    paintPlan(p, w, s, wallLength);
    paintPlanArrow(p, w, fr);
    p.setPen(QColor(0x33, 0x33, 0x33));
    drawTextLine(p, area, area.bottom() - 36, 16,
                 QStringLiteral("wall length %1 d (Θ = %2); arrow: base a_h")
                     .arg(wallLength, 0, 'g', 3)
                     .arg(s.params.theta, 0, 'g', 3));
    drawTextLine(p, area, area.bottom() - 18, 16,
                 QStringLiteral("a_x = %1 g, a_y = %2 g")
                     .arg(fr.accel, 0, 'f', 2)
                     .arg(fr.accelY, 0, 'f', 2));
    p.restore();
}

} // namespace kinstab::ui
