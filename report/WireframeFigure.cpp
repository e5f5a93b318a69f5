// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/WireframeFigure.h"

#include "report/PlotFrame.h"

#include <QFontMetricsF>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kinstab::report {

namespace {

// Orthographic projection of the unit box u (A), v (f), w (γ) onto the figure.
class Projection {
public:
    Projection(const WireframeView& view, double heightRatio)
        : c_(std::cos(view.azimuthDeg * std::numbers::pi / 180)),
          s_(std::sin(view.azimuthDeg * std::numbers::pi / 180)),
          ce_(std::cos(view.elevationDeg * std::numbers::pi / 180)),
          se_(std::sin(view.elevationDeg * std::numbers::pi / 180)), h_(heightRatio) {}

    // Screen coordinates before fitting: x right, y up. The eye looks at the corner
    // (u = 0, v = 1): low A in front, so the steep rise at high A stands at the back.
    QPointF raw(double u, double v, double w) const {
        const double x = u - 0.5, y = 0.5 - v;
        const double x1 = x * c_ - y * s_;
        const double y1 = x * s_ + y * c_;
        return {x1, w * h_ * ce_ + y1 * se_};
    }
    double depth(double u, double v, double w) const {
        const double x = u - 0.5, y = 0.5 - v;
        return (x * s_ + y * c_) * ce_ - w * h_ * se_;
    }
    void fit(const QRectF& target) {
        double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
        for (double u : {0.0, 1.0})
            for (double v : {0.0, 1.0})
                for (double w : {0.0, 1.0}) {
                    const QPointF q = raw(u, v, w);
                    x0 = std::min(x0, q.x()), x1 = std::max(x1, q.x());
                    y0 = std::min(y0, q.y()), y1 = std::max(y1, q.y());
                }
        k_ = std::min(target.width() / (x1 - x0), target.height() / (y1 - y0));
        ox_ = target.center().x() - k_ * (x0 + x1) / 2;
        oy_ = target.center().y() + k_ * (y0 + y1) / 2;
    }
    QPointF operator()(double u, double v, double w) const {
        const QPointF q = raw(u, v, w);
        return {ox_ + k_ * q.x(), oy_ - k_ * q.y()};
    }

private:
    double c_, s_, ce_, se_, h_;
    double k_ = 1, ox_ = 0, oy_ = 0;
};

struct Primitive {
    double depth = 0;
    QPolygonF shape;
    bool closed = true; // a cell; otherwise an overlay line
};

double unitOf(double x, double lo, double hi) {
    return hi > lo ? (x - lo) / (hi - lo) : 0.5;
}

void drawTicksAlong(QPainter& p, const Projection& pr, const FigureScale& sc,
                    const std::vector<double>& ticks, double lo, double hi, bool alongA,
                    const QString& label) {
    const double u = sc.unit();
    const QFontMetricsF fm(p.font());
    const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
    // The front edges: v = 1 for the A axis, u = 0 for the f axis; labels pushed outwards.
    const QPointF centre = pr(0.5, 0.5, 0);
    QPointF mid;
    for (double t : ticks) {
        const double q = unitOf(t, lo, hi);
        const QPointF a = alongA ? pr(q, 1, 0) : pr(0, q, 0);
        const QPointF out = alongA ? pr(q, 1.06, 0) : pr(-0.06, q, 0);
        p.drawLine(a, out);
        const QString s = tickLabel(t, step);
        const QPointF dir = out - a;
        const QPointF c = out + dir * 1.4;
        const double w = fm.horizontalAdvance(s);
        const double x = dir.x() < 0 ? c.x() - w : (dir.x() > 0 ? c.x() : c.x() - w / 2);
        p.drawText(QPointF(x, c.y() + fm.ascent() / 2), s);
    }
    mid = alongA ? pr(0.5, 1.3, 0) : pr(-0.3, 0.5, 0);
    const double w = fm.horizontalAdvance(label);
    const double x = mid.x() < centre.x() ? mid.x() - w : mid.x();
    p.drawText(QPointF(x, mid.y() + fm.ascent() + 0.5 * u), label);
}

// The box's axes mapped to [0, 1]: u along A, v along f, w along γ (0 at the floor).
struct UnitBox {
    double aLo, aHi, fLo, fHi, gTop;
    double u(double a) const { return unitOf(a, aLo, aHi); }
    double v(double f) const { return unitOf(f, fLo, fHi); }
    double w(double g) const { return g / gTop; }
};

// The γ ticks on 1-2-5 steps, one more above the top when the surface rises past it: the box
// must hold the surface.
std::vector<double> gammaTicks(const SurfaceData& s) {
    std::vector<double> ticks = niceTicks(0, std::max(s.maxGamma(), 1e-3), 4);
    if (ticks.size() > 1 && ticks.back() < s.maxGamma())
        ticks.push_back(ticks.back() + (ticks[1] - ticks[0]));
    return ticks;
}

// Back walls with the γ grid, and the box's hidden edges: they lie behind the net.
void paintBackWalls(QPainter& p, const Projection& pr, const FigureScale& sc,
                    const std::vector<double>& gTicks, double gTop) {
    p.setPen(sc.pen(QColor(150, 150, 150), 0.12));
    for (double g : gTicks) {
        const double w = g / gTop;
        p.drawLine(pr(0, 0, w), pr(1, 0, w));
        p.drawLine(pr(1, 0, w), pr(1, 1, w));
    }
    p.drawLine(pr(1, 0, 0), pr(1, 0, 1));
    p.drawLine(pr(1, 1, 0), pr(1, 1, 1));
    p.setPen(sc.pen(Qt::black, 0.2));
    p.drawLine(pr(0, 0, 0), pr(0, 0, 1));
    p.drawLine(pr(0, 0, 0), pr(1, 0, 0));
    p.drawLine(pr(1, 0, 0), pr(1, 1, 0));
}

// The γ axis's ticks, labels and title on the back left edge.
void paintGammaAxis(QPainter& p, const Projection& pr, const FigureScale& sc,
                    const std::vector<double>& gTicks, double gTop, const QString& gammaLabel) {
    const double u = sc.unit();
    const QFontMetricsF fm(p.font());
    const double gStep = gTicks.size() > 1 ? gTicks[1] - gTicks[0] : 1.0;
    for (double g : gTicks) {
        const QPointF a = pr(0, 0, g / gTop);
        p.drawLine(a, a - QPointF(u, 0));
        const QString t = tickLabel(g, gStep);
        p.drawText(QPointF(a.x() - 1.5 * u - fm.horizontalAdvance(t), a.y() + fm.ascent() / 2), t);
    }
    const QPointF top = pr(0, 0, 1);
    p.drawText(QPointF(top.x() - fm.horizontalAdvance(gammaLabel) / 2, top.y() - 1.5 * u),
               gammaLabel);
}

// The net's finite cells, farthest first (painter's algorithm).
std::vector<Primitive> netCells(const SurfaceData& s, const Projection& pr, const UnitBox& box) {
    auto point = [&](std::size_t i, std::size_t j) {
        const double g = s.at(i, j);
        return std::pair{QPointF(pr(box.u(s.amplitudes[i]), box.v(s.frequencies[j]), box.w(g))), g};
    };
    std::vector<Primitive> cells;
    for (std::size_t i = 0; i + 1 < s.amplitudes.size(); ++i)
        for (std::size_t j = 0; j + 1 < s.frequencies.size(); ++j) {
            const auto [p00, g00] = point(i, j);
            const auto [p10, g10] = point(i + 1, j);
            const auto [p11, g11] = point(i + 1, j + 1);
            const auto [p01, g01] = point(i, j + 1);
            if (!std::isfinite(g00 + g10 + g11 + g01)) continue;
            const double uc = box.u((s.amplitudes[i] + s.amplitudes[i + 1]) / 2);
            const double vc = box.v((s.frequencies[j] + s.frequencies[j + 1]) / 2);
            const double wc = (g00 + g10 + g11 + g01) / 4 / box.gTop;
            cells.push_back({pr.depth(uc, vc, wc), QPolygonF({p00, p10, p11, p01}), true});
        }
    std::stable_sort(cells.begin(), cells.end(),
                     [](const Primitive& a, const Primitive& b) { return a.depth > b.depth; });
    return cells;
}

// A_crit(f) on the floor, as segments painted after the net: on the floor it would hide behind
// the rising cells. Segments leaving the box are left out.
std::vector<Primitive> critSegments(const DesignOverlay& overlay, const Projection& pr,
                                    const UnitBox& box) {
    std::vector<Primitive> segments;
    for (std::size_t k = 0; k + 1 < overlay.critFrequencies.size(); ++k) {
        const auto& a0 = overlay.critAmplitude[k];
        const auto& a1 = overlay.critAmplitude[k + 1];
        if (!a0 || !a1) continue;
        const double u0 = box.u(*a0), u1 = box.u(*a1);
        const double v0 = box.v(overlay.critFrequencies[k]);
        const double v1 = box.v(overlay.critFrequencies[k + 1]);
        if (u0 < 0 || u0 > 1 || u1 < 0 || u1 > 1 || v0 < 0 || v1 > 1) continue;
        segments.push_back({0, QPolygonF({pr(u0, v0, 0), pr(u1, v1, 0)}), false});
    }
    return segments;
}

// Cells filled white and outlined, overlay lines in red, in the order given.
void paintPrimitives(QPainter& p, const FigureScale& sc, const std::vector<Primitive>& prims) {
    const QPen net = sc.pen(Qt::black, 0.12);
    const QPen crit = sc.pen(QColor(200, 30, 30), 0.45);
    for (const Primitive& pm : prims) {
        if (pm.closed) {
            p.setPen(net);
            p.setBrush(Qt::white);
            p.drawPolygon(pm.shape);
        } else {
            p.setPen(crit);
            p.drawPolyline(pm.shape);
        }
    }
}

// Front floor edges with the A and f scales.
void paintFrontEdges(QPainter& p, const Projection& pr, const FigureScale& sc, const UnitBox& box) {
    p.setPen(sc.pen(Qt::black, 0.2));
    p.setBrush(Qt::NoBrush);
    p.drawLine(pr(0, 1, 0), pr(1, 1, 0));
    p.drawLine(pr(0, 0, 0), pr(0, 1, 0));
    drawTicksAlong(p, pr, sc, niceTicks(box.aLo, box.aHi, 5), box.aLo, box.aHi, true,
                   QStringLiteral("A (g)"));
    drawTicksAlong(p, pr, sc, niceTicks(box.fLo, box.fHi, 5), box.fLo, box.fHi, false,
                   QStringLiteral("f (Hz)"));
}

} // namespace

void paintWireframe(QPainter& p, const QRectF& area, const SurfaceData& s,
                    const DesignOverlay& overlay, const QString& gammaLabel,
                    const WireframeView& view) {
    if (s.amplitudes.size() < 2 || s.frequencies.size() < 2) return;
    const FigureScale sc{area.width()};
    const double u = sc.unit();
    const std::vector<double> gTicks = gammaTicks(s);
    const UnitBox box{s.amplitudes.front(), s.amplitudes.back(), s.frequencies.front(),
                      s.frequencies.back(), gTicks.back() > 0 ? gTicks.back() : 1.0};
    Projection pr(view, view.heightRatio);
    pr.fit(area.adjusted(14 * u, 5 * u, -14 * u, -9 * u));

    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    p.setFont(sc.font(2.2));
    paintBackWalls(p, pr, sc, gTicks, box.gTop);
    paintGammaAxis(p, pr, sc, gTicks, box.gTop, gammaLabel);
    std::vector<Primitive> prims = netCells(s, pr, box);
    const std::vector<Primitive> crit = critSegments(overlay, pr, box);
    prims.insert(prims.end(), crit.begin(), crit.end());
    paintPrimitives(p, sc, prims);
    paintFrontEdges(p, pr, sc, box);
    p.restore();
}

} // namespace kinstab::report
