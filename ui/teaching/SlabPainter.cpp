// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/SlabPainter.h"
#include "ui/NiceTicks.h"

#include "ui/teaching/TextScale.h"

#include "ui/teaching/StateStyle.h"
#include "ui/teaching/TopViewPainter.h"
#include "ui/teaching/TracePainter.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kinstab::ui {

namespace {

// World units: the wall width d; x to the right, y up from the top of the walls.
constexpr double kSpan = 6.0;    // outer face to outer face, shortened (not to scale)
constexpr double kMargin = 1.3;  // each side
constexpr double kSlabT = 0.7;   // slab thickness
constexpr double kWallH = 1.9;   // visible wall height
constexpr double kBaseH = 0.35;  // the base (floor below) the walls stand on
constexpr double kRulerH = 0.75; // fixed ground ruler
constexpr double kTopPad = 0.9;  // room for the bearing dimensions

struct Frame2D {
    double k = 1, x0 = 0, y0 = 0; // pixels per d; screen position of world (0, 0)
    QPointF at(double x, double y) const { return {x0 + x * k, y0 - y * k}; }
    QRectF box(double x0w, double y0w, double x1w, double y1w) const {
        return QRectF(at(x0w, y1w), at(x1w, y0w)).normalized();
    }
};

// A length in the unit system's small unit: whole mm, or inches to 0.01.
QString lengthText(double metres, UnitSystem u) {
    const LengthScale detail = LengthScale::Detail;
    return QString::number(metres / metresPerDisplayUnit(u, detail), 'f',
                           u == UnitSystem::US ? 2 : 0) +
           QLatin1Char(' ') + lengthSymbol(u, detail);
}

void arrow(QPainter& p, QPointF from, QPointF to, const QColor& c, double width) {
    p.setPen(QPen(c, width, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(from, to);
    const QPointF d = to - from;
    const double len = std::hypot(d.x(), d.y());
    if (len < 1.0) return;
    const QPointF u = d / len, n(-u.y(), u.x());
    const double h = std::min(len, 4.0 * width + 4.0);
    QPolygonF head{to, to - u * h + n * h * 0.45, to - u * h - n * h * 0.45};
    p.setBrush(c);
    p.setPen(Qt::NoPen);
    p.drawPolygon(head);
    p.setBrush(Qt::NoBrush);
}

void labelBox(QPainter& p, QPointF centre, const QString& text, const QColor& fg) {
    const QRectF r = p.fontMetrics().boundingRect(text).adjusted(-4, -1, 4, 1);
    const QRectF box(centre.x() - r.width() / 2, centre.y() - r.height() / 2, r.width(),
                     r.height());
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 255, 255, 225));
    p.drawRoundedRect(box, 3, 3);
    p.setPen(fg);
    p.drawText(box, Qt::AlignCenter, text);
    p.setBrush(Qt::NoBrush);
}

// Masonry: grey units in running bond, courses 0.4 d high.
void paintWall(QPainter& p, const Frame2D& f, double x0, double x1) {
    const QRectF r = f.box(x0, -kWallH, x1, 0.0);
    p.fillRect(r, QColor(0xc9, 0xc4, 0xbb));
    p.setPen(QPen(QColor(0x9a, 0x94, 0x8a), 1.0));
    const double course = 0.4;
    for (int i = 1; i * course < kWallH; ++i) {
        const double y = -i * course;
        p.drawLine(f.at(x0, y), f.at(x1, y));
        const double xj = x0 + ((i % 2) ? 0.33 : 0.67) * (x1 - x0);
        p.drawLine(f.at(xj, y), f.at(xj, y + course));
    }
    p.setPen(QPen(QColor(0x55, 0x52, 0x4c), 1.5));
    p.drawRect(r);
}

void paintBaseAndRuler(QPainter& p, const Frame2D& f, const SlabScene& s) {
    const double left = -kMargin + 0.2, right = kSpan + kMargin - 0.2;
    // The base moves with the walls: a concrete strip.
    const QRectF base = f.box(left, -kWallH - kBaseH, right, -kWallH);
    p.fillRect(base, QColor(0xb0, 0xab, 0xa2));
    p.setPen(QPen(QColor(0x55, 0x52, 0x4c), 1.2));
    p.drawRect(base);
    // Base acceleration arrow, 1.2 d per g.
    const double a = s.frame.accel;
    const QPointF c = f.at(kSpan / 2, -kWallH - kBaseH / 2);
    if (std::abs(a) > 1e-3) arrow(p, c, c + QPointF(a * 1.2 * f.k, 0), QColor(0x1f, 0x3b, 0x73), 3);
    // Between the walls: in a small view or at 200 % text the long form ran over the wall
    // width's "d = …" label at the left wall.
    QString accel = QStringLiteral("base acceleration a = %1 g").arg(a, 0, 'f', 2);
    if (p.fontMetrics().horizontalAdvance(accel) > (kSpan - 2.6) * f.k)
        accel = QStringLiteral("a = %1 g").arg(a, 0, 'f', 2);
    labelBox(p, c + QPointF(0, -0.42 * f.k), accel, QColor(0x1f, 0x3b, 0x73));
    // Fixed ground: ticks every d/2 in the inertial frame, seen from the moving base.
    const double yTop = -kWallH - kBaseH - 0.12, yBot = yTop - 0.25;
    p.setPen(QPen(QColor(0x33, 0x33, 0x33), 1.2));
    p.drawLine(f.at(left, yTop), f.at(right, yTop));
    const double shift = s.frame.baseDisp / 2.0; // base displacement in d
    // Ticks at round mm or inches; world x = length / d.
    const double dMetres = s.params.wallWidthM,
                 cmPerD = dMetres / metresPerDisplayUnit(s.units, LengthScale::Detail);
    const double step = niceTickStep((right - left) * cmPerD, 8), minor = step / 2;
    const long n0 = static_cast<long>(std::ceil((left + shift) * cmPerD / minor));
    const long n1 = static_cast<long>(std::floor((right + shift) * cmPerD / minor));
    for (long n = n0; n <= n1; ++n) {
        const double x = n * minor / cmPerD - shift;
        const bool major = n % 2 == 0;
        p.setPen(
            QPen(n == 0 ? QColor(0xc0, 0x39, 0x2b) : QColor(0x33, 0x33, 0x33), n == 0 ? 2.0 : 1.0));
        p.drawLine(f.at(x, yTop), f.at(x, major ? yBot : yTop - 0.12));
        if (major)
            p.drawText(QRectF(f.at(x - 0.5, yBot), f.at(x + 0.5, yBot - 0.3)), Qt::AlignCenter,
                       QString::number(n * minor, 'g', 6));
    }
    p.setPen(QColor(0x33, 0x33, 0x33));
    const QRectF ground(f.at(left, yBot - 0.28), f.at(right, yBot - 0.6));
    const QString unit = lengthSymbol(s.units, LengthScale::Detail),
                  yb = lengthText(s.frame.baseDisp * dMetres / 2, s.units);
    QString groundText =
        QStringLiteral("fixed ground (%1) — base displacement y_b = %2").arg(unit, yb);
    if (p.fontMetrics().horizontalAdvance(groundText) > ground.width()) // was cut at the right
        groundText = QStringLiteral("ground (%1), y_b = %2").arg(unit, yb);
    p.drawText(ground, Qt::AlignLeft | Qt::AlignVCenter, groundText);
}

// The slab as two pieces with a break in the middle, so the shortened span is not taken as
// to scale. Drawn in slab coordinates (u along the slab from its left end, v up).
QPainterPath slabPiece(double length, double gapHalf, int side) {
    const double mid = length / 2, zig = mid + side * gapHalf;
    const double end = side < 0 ? 0.0 : length;
    QPainterPath path;
    path.moveTo(end, 0);
    path.lineTo(zig, 0);
    path.lineTo(zig + 0.12, kSlabT * 0.33);
    path.lineTo(zig - 0.08, kSlabT * 0.66);
    path.lineTo(zig, kSlabT);
    path.lineTo(end, kSlabT);
    path.closeSubpath();
    return path;
}

void paintSlab(QPainter& p, const Frame2D& f, const SlabScene& s) {
    const TeachingFrame& fr = s.frame;
    const double L = s.params.limit;
    const double xl0 = 1.0 - L / 2, xr0 = kSpan - 1.0 + L / 2;
    const double shift = fr.delta / 2.0; // delta is in d/2
    const double xl = xl0 + shift, length = xr0 - xl0;
    // Where the slab started, dotted (as in the paper's Fig. 36b).
    p.setPen(QPen(QColor(0x77, 0x77, 0x77), 1.0, Qt::DashLine));
    p.drawLine(f.at(xl0, -0.15), f.at(xl0, kSlabT + 0.15));
    p.drawLine(f.at(xr0, -0.15), f.at(xr0, kSlabT + 0.15));
    const QColor c = stateColor(fr.state);
    const double gap = 0.18;
    // After collapse the end that left its wall falls under gravity and the slab tips over the
    // other wall's inner corner (a shear: exact for the small angles of a real, longer span).
    QTransform tip;
    if (fr.fallDrop > 0.0 && s.exit != ExitSide::Along) {
        const bool leftFalls = fr.direction > 0;
        const double pivot = (leftFalls ? kSpan - 1.0 : 1.0) - xl;
        const double arm = leftFalls ? pivot : length - pivot;
        const double slope = std::min(fr.fallDrop / 2.0, 1.0) / arm; // drop in d, shown up to d
        tip = leftFalls ? QTransform(1, slope, 0, 1, 0, -slope * pivot)
                        : QTransform(1, -slope, 0, 1, 0, slope * pivot);
    }
    p.save();
    p.translate(f.at(xl, 0));
    p.scale(f.k, -f.k);
    p.setTransform(tip, true);
    p.setBrush(c.lighter(115));
    p.setPen(QPen(c.darker(150), 2.0 / f.k));
    for (int side : {-1, 1})
        p.drawPath(slabPiece(length, gap, side));
    p.restore();
    p.setBrush(Qt::NoBrush);
    // Under the slab, between the walls, where nothing else is drawn: above it, where it used
    // to be, the bearing dimensions' labels ran into it once the view was narrow.
    labelBox(p, f.at(kSpan / 2, -0.45), QStringLiteral("span not to scale"),
             QColor(0x66, 0x66, 0x66));
    if (fr.direction != 0 && fr.fallDrop == 0.0 && fr.state != DisplayState::Collapse) {
        const QPointF from = f.at(kSpan / 2 + shift - 0.9 * fr.direction, kSlabT / 2);
        arrow(p, from, from + QPointF(1.8 * fr.direction * f.k, 0), Qt::white, 3.5);
    }
}

// Bearing left on each wall, to scale, with the smaller one in the state colour.
void paintBearings(QPainter& p, const Frame2D& f, const SlabScene& s) {
    if (s.frame.fallDrop > 0.0) return;
    const double L = s.params.limit, shift = s.frame.delta / 2.0;
    const double dM = s.params.wallWidthM;
    const double left = L / 2 - shift, right = L / 2 + shift; // in d
    const double y = kSlabT + 0.25;
    auto dim = [&](double x0, double x1, double value, bool warn) {
        const QColor c = warn ? stateColor(DisplayState::Collapse) : QColor(0x44, 0x44, 0x44);
        p.setPen(QPen(c, 1.2));
        if (value > 0) {
            p.drawLine(f.at(x0, y), f.at(x1, y));
            p.drawLine(f.at(x0, y - 0.08), f.at(x0, y + 0.08));
            p.drawLine(f.at(x1, y - 0.08), f.at(x1, y + 0.08));
        }
        labelBox(p, f.at((x0 + x1) / 2, y + 0.28),
                 QStringLiteral("bearing %1").arg(lengthText(std::max(0.0, value) * dM, s.units)),
                 c);
    };
    dim(1.0 - left, 1.0, left, left < 0.3 * L);
    dim(kSpan - 1.0, kSpan - 1.0 + right, right, right < 0.3 * L);
}

void paintWallWidth(QPainter& p, const Frame2D& f, const SlabScene& s) {
    const double y = -kWallH * 0.72;
    p.setPen(QPen(QColor(0x22, 0x22, 0x22), 1.2));
    arrow(p, f.at(0.5, y), f.at(0.0, y), QColor(0x22, 0x22, 0x22), 1.2);
    arrow(p, f.at(0.5, y), f.at(1.0, y), QColor(0x22, 0x22, 0x22), 1.2);
    labelBox(p, f.at(0.5, y - 0.28),
             QStringLiteral("d = %1").arg(lengthText(s.params.wallWidthM, s.units)),
             QColor(0x22, 0x22, 0x22));
}

// font at fontPx, or smaller (down to 55 %) so that text fits width: in presentation mode at
// 1280 × 800 the header's second line ran past the scene and "|a| vs μ" was cut off.
QFont fitted(QFont font, double fontPx, const QString& text, double width) {
    font.setPixelSize(static_cast<int>(fontPx));
    const double needed = QFontMetricsF(font).horizontalAdvance(text);
    if (needed > width && width > 0)
        font.setPixelSize(static_cast<int>(fontPx * std::max(0.55, width / needed)));
    return font;
}

void paintHeader(QPainter& p, const QRectF& area, const SlabScene& s, double fontPx) {
    const TeachingFrame& fr = s.frame;
    QFont big = p.font();
    big.setPixelSize(static_cast<int>(fontPx * 1.6));
    big.setBold(true);
    p.setFont(big);
    p.setPen(stateColor(fr.state));
    const QRectF line1(area.left() + 10, area.top() + 4, area.width() - 20, fontPx * 2.0);
    QString state = stateLabel(fr.state, fr.direction).toUpper();
    if (fr.state == DisplayState::Collapse && s.exit == ExitSide::Along)
        state += QStringLiteral(" — slid off along the walls");
    else if (fr.state ==
             DisplayState::Collapse) // delta > limit: the slab went right, off the left wall
        state += fr.direction > 0 ? QStringLiteral(" — off the left wall")
                                  : QStringLiteral(" — off the right wall");
    p.drawText(line1, Qt::AlignLeft | Qt::AlignVCenter, state);
    const double stateW = p.fontMetrics().horizontalAdvance(state);
    QFont normal = p.font();
    normal.setBold(false);
    p.setPen(QColor(0x22, 0x22, 0x22));
    const QString time =
        QStringLiteral("τ = %1   t = %2 s").arg(fr.tau, 0, 'f', 2).arg(fr.tau * s.tstar, 0, 'f', 3);
    p.setFont(fitted(normal, fontPx, time, line1.width() - stateW - fontPx));
    p.drawText(line1, Qt::AlignRight | Qt::AlignVCenter, time);
    const double dM = s.params.wallWidthM;
    const QRectF line2(line1.left(), line1.bottom(), line1.width(), fontPx * 1.5);
    const QString motion =
        QStringLiteral("δ = %1 (d/2) = %2     slab y_s = %3     |a| vs μ: %4 %5 %6")
            .arg(fr.delta, 0, 'f', 3)
            .arg(lengthText(fr.delta * dM / 2, s.units))
            .arg(lengthText((fr.baseDisp + fr.delta) * dM / 2, s.units))
            .arg(std::abs(fr.accel), 0, 'f', 2)
            .arg(std::abs(fr.accel) > s.params.mu ? QStringLiteral(">") : QStringLiteral("≤"))
            .arg(s.params.mu, 0, 'f', 2);
    p.setFont(fitted(normal, fontPx, motion, line2.width()));
    p.drawText(line2, Qt::AlignLeft | Qt::AlignVCenter, motion);
}

} // namespace

void paintSlabScene(QPainter& p, const QRectF& area, const SlabScene& s) {
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(area, Qt::white);
    const double scale = textScale(p); // presentation mode: larger text, same drawing
    const double headerPx = std::clamp(area.height() * 0.045, 11.0, 16.0) * scale;
    const double headerH = headerPx * 3.8;
    const double worldW = kSpan + 2 * kMargin;
    const double worldH = kTopPad + kSlabT + kWallH + kBaseH + kRulerH + 0.35;
    const bool planar = s.params.model == TeachingModel::Planar;
    const QRectF side(area.left(), area.top(), area.width() * (planar ? 0.6 : 1.0), area.height());
    Frame2D f;
    f.k = std::min(side.width() / worldW, (area.height() - headerH) / worldH);
    f.x0 = side.left() + (side.width() - worldW * f.k) / 2 + kMargin * f.k;
    f.y0 = area.top() + headerH + (kTopPad + kSlabT) * f.k;
    QFont font = p.font();
    font.setPixelSize(
        static_cast<int>(std::clamp(f.k * 0.2, 10.0, 15.0) * std::min(scale, kLabelMaxScale)));
    p.setFont(font);
    paintBaseAndRuler(p, f, s);
    paintWall(p, f, 0.0, 1.0);
    paintWall(p, f, kSpan - 1.0, kSpan);
    paintWallWidth(p, f, s);
    paintSlab(p, f, s);
    paintBearings(p, f, s);
    if (planar)
        paintTopView(p,
                     QRectF(side.right(), area.top() + headerH, area.width() - side.width(),
                            area.height() - headerH),
                     s);
    paintHeader(p, area, s, headerPx);
    p.restore();
}

} // namespace kinstab::ui
