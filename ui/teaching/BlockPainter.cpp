// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/BlockPainter.h"

#include "ui/teaching/TextScale.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

namespace {

QColor modeColor(BlockMode m, bool overturned) {
    if (overturned) return QColor(0xc0, 0x39, 0x2b); // red, as the slab's collapse
    switch (m) {
    case BlockMode::Rest:
        return QColor(0x4a, 0x6f, 0xa5);
    case BlockMode::Slide:
        return QColor(0xe0, 0x7b, 0x00);
    case BlockMode::Rock:
        return QColor(0x2e, 0x8b, 0x57);
    case BlockMode::SlideRock:
        return QColor(0x8e, 0x44, 0xad);
    }
    return Qt::gray;
}

QString modeText(BlockMode m, double theta, bool overturned) {
    if (overturned) return QStringLiteral("overturned");
    const QString side = theta > 0   ? QStringLiteral(" on the right corner")
                         : theta < 0 ? QStringLiteral(" on the left corner")
                                     : QString();
    switch (m) {
    case BlockMode::Rest:
        return QStringLiteral("at rest");
    case BlockMode::Slide:
        return QStringLiteral("sliding");
    case BlockMode::Rock:
        return QStringLiteral("rocking") + side;
    case BlockMode::SlideRock:
        return QStringLiteral("slide-rocking") + side;
    }
    return {};
}

struct World {
    double k = 1, x0 = 0, y0 = 0; // pixels per metre; screen position of world (0, 0)
    QPointF at(QPointF w) const { return {x0 + w.x() * k, y0 - w.y() * k}; }
};

// The world fitted into the area below a two-line header: room for the block lying on either
// side after it overturned, and for its diagonal; the base line at the scene's bottom.
World fitWorld(const QRectF& area, const Block& b, double sliding, double lineH) {
    const double reach = b.halfWidth + 2 * b.halfHeight + std::abs(sliding);
    const double top = 2 * std::hypot(b.halfWidth, b.halfHeight);
    const QRectF scene = area.adjusted(12, 2.4 * lineH + 8, -12, -34);
    World w;
    w.k = std::min(scene.width() / (2.1 * reach), scene.height() / (1.08 * top));
    w.x0 = scene.center().x();
    w.y0 = scene.bottom();
    return w;
}

// The base: hatched ground below y0 and its surface line.
void paintGround(QPainter& p, const QRectF& area, double y0) {
    const QRectF ground(area.left(), y0, area.width(), area.bottom() - y0);
    p.fillRect(ground, QColor(0xd8, 0xd2, 0xc4));
    p.setPen(QPen(QColor(0x80, 0x78, 0x6a), 1.0));
    for (double x = area.left() - ground.height(); x < area.right(); x += 12)
        p.drawLine(QPointF(x, ground.bottom()), QPointF(x + ground.height(), ground.top()));
    p.setPen(QPen(QColor(0x50, 0x48, 0x40), 2.0));
    p.drawLine(QPointF(area.left(), y0), QPointF(area.right(), y0));
}

// The rest outline dashed, then the block tipped and shifted, filled in its mode's colour.
void paintBlockOutlines(QPainter& p, const World& w, const BlockScene& sc, const QColor& mc) {
    const Block& b = sc.block;
    const QPointF corners[4] = {{-b.halfWidth, 0},
                                {b.halfWidth, 0},
                                {b.halfWidth, 2 * b.halfHeight},
                                {-b.halfWidth, 2 * b.halfHeight}};
    QPolygonF rest, block;
    for (const QPointF& c : corners) {
        rest << w.at(c);
        block << w.at(tippedPoint(b, sc.state.theta, sc.state.sliding, c));
    }
    p.setPen(QPen(QColor(0x99, 0x99, 0x99), 1.0, Qt::DashLine));
    p.setBrush(Qt::NoBrush);
    p.drawPolygon(rest);
    p.setPen(QPen(mc.darker(140), 2.0));
    p.setBrush(QColor(mc.red(), mc.green(), mc.blue(), 70));
    p.drawPolygon(block);
}

// The centre of mass, the corner it rocks on, and a ring under the block at an impact.
void paintBlockMarks(QPainter& p, const World& w, const BlockScene& sc, const QColor& mc) {
    const Block& b = sc.block;
    const QPointF cm = w.at(tippedPoint(b, sc.state.theta, sc.state.sliding, {0, b.halfHeight}));
    p.setBrush(mc.darker(150));
    p.setPen(Qt::NoPen);
    p.drawEllipse(cm, 4, 4);
    if (sc.state.theta != 0.0) {
        const QPointF pivot =
            w.at({(sc.state.theta > 0 ? b.halfWidth : -b.halfWidth) + sc.state.sliding, 0});
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(QColor(0x20, 0x20, 0x20), 2.0));
        p.drawEllipse(pivot, 6, 6);
    }
    if (sc.impact) {
        p.setPen(QPen(QColor(0xe6, 0x7e, 0x22), 3.0));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(w.at({sc.state.sliding, 0}), 0.8 * b.halfWidth * w.k + 10, 12);
    }
}

// The base acceleration: an arrow under the ground line, 1 g = a quarter of the width.
void paintBaseArrow(QPainter& p, const QRectF& area, double y0, double a) {
    if (a == 0.0) return;
    const QPointF from(area.center().x(), y0 + 17);
    const QPointF to = from + QPointF(std::clamp(a, -2.0, 2.0) * area.width() / 8, 0);
    p.setPen(QPen(QColor(0x20, 0x40, 0x90), 3.0, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(from, to);
    const double dir = a > 0 ? 1 : -1;
    p.setBrush(QColor(0x20, 0x40, 0x90));
    p.setPen(Qt::NoPen);
    p.drawPolygon(QPolygonF{to + QPointF(dir * 8, 0), to + QPointF(0, -6), to + QPointF(0, 6)});
}

// The header's second line: time, θ/α, sliding and base acceleration.
QString stateLine(const BlockScene& sc) {
    const double lu = metresPerDisplayUnit(sc.units, LengthScale::Detail);
    return QStringLiteral("t = %1 s   θ/α = %2   u = %3 %4   base a = %5 g")
        .arg(sc.state.t, 0, 'f', 3)
        .arg(sc.state.theta / blockAlpha(sc.block), 0, 'f', 3)
        .arg(sc.state.sliding / lu, 0, 'f', sc.units == UnitSystem::US ? 2 : 1)
        .arg(lengthSymbol(sc.units, LengthScale::Detail))
        .arg(sc.baseAcceleration, 0, 'f', 3);
}

// The header: the mode in bold in its colour, then the state line.
void paintHeader(QPainter& p, const QRectF& area, const BlockScene& sc, const QColor& mc,
                 double lineH) {
    const QFont f = p.font();
    p.setPen(mc.darker(120));
    QFont bold = f;
    bold.setBold(true);
    p.setFont(bold);
    const QString head = modeText(sc.state.mode, sc.state.theta, sc.overturned) +
                         (sc.impact ? QStringLiteral(" — impact") : QString());
    p.drawText(QPointF(area.left() + 10, area.top() + lineH), head);
    p.setFont(f);
    p.setPen(QColor(0x30, 0x30, 0x30));
    p.drawText(QPointF(area.left() + 10, area.top() + 2 * lineH + 2), stateLine(sc));
}

} // namespace

QPointF tippedPoint(const Block& b, double theta, double u, QPointF q) {
    const double px = theta > 0 ? b.halfWidth : theta < 0 ? -b.halfWidth : 0.0;
    const double dx = q.x() - px, dy = q.y();
    const double c = std::cos(theta), s = std::sin(theta);
    // Clockwise by theta (y up): the top moves towards +x for theta > 0.
    return {px + u + dx * c + dy * s, -dx * s + dy * c};
}

void paintBlockScene(QPainter& p, const QRectF& area, const BlockScene& sc) {
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(area, QColor(0xfb, 0xfb, 0xf8));
    QFont f = p.font();
    f.setPixelSize(scaledPixels(p, 14));
    p.setFont(f);
    const double lineH = QFontMetricsF(f).height();
    const World w = fitWorld(area, sc.block, sc.state.sliding, lineH);
    paintGround(p, area, w.y0);
    const QColor mc = modeColor(sc.state.mode, sc.overturned);
    paintBlockOutlines(p, w, sc, mc);
    paintBlockMarks(p, w, sc, mc);
    paintBaseArrow(p, area, w.y0, sc.baseAcceleration);
    paintHeader(p, area, sc, mc, lineH);
    p.restore();
}

} // namespace kinstab::ui
