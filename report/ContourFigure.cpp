// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/ContourFigure.h"

#include "report/PlotFrame.h"

#include <QFontMetricsF>
#include <QPainterPath>
#include <QPolygonF>

#include <algorithm>
#include <cmath>

namespace kinstab::report {

namespace {

struct Vertex {
    QPointF p;
    double v;
};
using Poly = std::vector<Vertex>;

// Sutherland–Hodgman against the half-plane v >= level (keepAbove) or v < level.
Poly clip(const Poly& in, double level, bool keepAbove) {
    Poly out;
    auto inside = [&](const Vertex& x) { return keepAbove ? x.v >= level : x.v < level; };
    for (std::size_t k = 0; k < in.size(); ++k) {
        const Vertex& a = in[k];
        const Vertex& b = in[(k + 1) % in.size()];
        if (inside(a)) out.push_back(a);
        if (inside(a) != inside(b)) {
            const double t = (level - a.v) / (b.v - a.v);
            out.push_back({a.p + (b.p - a.p) * t, level});
        }
    }
    return out;
}

// YlOrRd-like ramp: light yellow through orange to dark red.
QColor ramp(double t) {
    static const QColor stops[] = {QColor(255, 240, 170), QColor(254, 178, 76), QColor(240, 59, 32),
                                   QColor(128, 0, 38)};
    t = std::clamp(t, 0.0, 1.0) * 3;
    const int k = std::min(2, static_cast<int>(t));
    const double f = t - k;
    const QColor& a = stops[k];
    const QColor& b = stops[k + 1];
    return QColor::fromRgbF(a.redF() + (b.redF() - a.redF()) * f,
                            a.greenF() + (b.greenF() - a.greenF()) * f,
                            a.blueF() + (b.blueF() - a.blueF()) * f);
}

const QColor kStable(245, 247, 250);

// Band 0 is γc = 0 (stable); bands 1.. run up the ramp.
QColor bandColour(std::size_t k, std::size_t levelCount) {
    if (k == 0) return kStable;
    const double n = static_cast<double>(std::max<std::size_t>(levelCount, 4) - 3);
    return ramp((k - 1.0) / n);
}

void paintBands(QPainter& p, const PlotFrame& fr, const SurfaceData& s,
                const std::vector<double>& levels) {
    const std::size_t na = s.amplitudes.size(), nf = s.frequencies.size();
    const double seam = 0.06 * fr.scale().unit();
    auto vertex = [&](std::size_t i, std::size_t j) {
        return Vertex{fr.map(s.amplitudes[i], s.frequencies[j]), s.at(i, j)};
    };
    for (std::size_t i = 0; i + 1 < na; ++i)
        for (std::size_t j = 0; j + 1 < nf; ++j) {
            const Vertex a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1),
                         d = vertex(i, j + 1);
            if (!std::isfinite(a.v + b.v + c.v + d.v)) continue;
            for (const Poly& tri : {Poly{a, b, c}, Poly{a, c, d}})
                for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
                    const Poly band = clip(clip(tri, levels[k], true), levels[k + 1], false);
                    if (band.size() < 3) continue;
                    QPolygonF poly;
                    for (const Vertex& v : band)
                        poly << v.p;
                    const QColor col = bandColour(k, levels.size());
                    p.setPen(QPen(col, seam)); // closes hairline seams between polygons
                    p.setBrush(col);
                    p.drawPolygon(poly);
                }
        }
}

void paintColourBar(QPainter& p, const PlotFrame& fr, const std::vector<double>& levels,
                    const QString& label) {
    const double u = fr.scale().unit();
    const QRectF plot = fr.plot();
    const double x = plot.right() + 3 * u, w = 2.2 * u;
    const double h = plot.height() / (levels.size() - 1);
    p.setFont(fr.scale().font(2.1));
    const QFontMetricsF fm(p.font());
    const double step = levels.size() > 3 ? levels[3] - levels[2] : 1.0;
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
        const QRectF r(x, plot.bottom() - (k + 1) * h, w, h);
        p.setPen(fr.scale().pen(Qt::black, 0.1));
        p.setBrush(bandColour(k, levels.size()));
        p.drawRect(r);
        // Band 0 is labelled in its middle; the others at their upper edge.
        const QString t = k == 0 ? QStringLiteral("stable") : tickLabel(levels[k + 1], step);
        const double y = k == 0 ? r.center().y() : r.top();
        p.drawText(QPointF(x + w + 0.8 * u, y + fm.ascent() / 2 - fm.descent() / 2), t);
    }
    p.drawText(QPointF(x, plot.top() - 1.2 * u), label.section(QLatin1Char(' '), 0, 0));
}

// A_crit(f): the boundary between stable and collapsed, open where no A_crit was found.
QPainterPath critPath(const PlotFrame& fr, const DesignOverlay& o) {
    QPainterPath crit;
    bool open = false;
    for (std::size_t k = 0; k < o.critFrequencies.size(); ++k) {
        if (!o.critAmplitude[k]) {
            open = false;
            continue;
        }
        const QPointF q = fr.map(*o.critAmplitude[k], o.critFrequencies[k]);
        open ? crit.lineTo(q) : crit.moveTo(q);
        open = true;
    }
    return crit;
}

// The design points (F_top/w_top, 1/T) of the codes with a period.
void paintDesignPoints(QPainter& p, const PlotFrame& fr, const std::vector<CodeMark>& codes) {
    const double u = fr.scale().unit();
    for (const CodeMark& c : codes) {
        if (c.frequency <= 0) continue;
        p.setPen(fr.scale().pen(Qt::black, 0.15));
        p.setBrush(c.colour);
        p.drawEllipse(fr.map(c.ratio, c.frequency), 0.8 * u, 0.8 * u);
    }
}

// The overlay's lines and points; returns their legend, drawn below the plot by the caller.
std::vector<LegendEntry> paintOverlay(QPainter& p, const PlotFrame& fr, const DesignOverlay& o) {
    const FigureScale& sc = fr.scale();
    const QRectF plot = fr.plot();
    p.setBrush(Qt::NoBrush);
    p.setPen(sc.pen(Qt::black, 0.55));
    p.drawPath(critPath(fr, o));
    if (o.designFrequency) {
        QPen dotted = sc.pen(QColor(30, 60, 160), 0.25);
        dotted.setStyle(Qt::DotLine);
        p.setPen(dotted);
        const double y = fr.mapY(*o.designFrequency);
        p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
    }
    std::vector<LegendEntry> legend{{QStringLiteral("A_crit(f)"), Qt::black, Qt::SolidLine}};
    for (const CodeMark& c : o.codes)
        if (fr.verticalLine(p, c.ratio, c.colour, Qt::DashLine))
            legend.push_back(codeRatioEntry(c.label, c.ratio, c.colour));
    paintDesignPoints(p, fr, o.codes);
    if (o.designFrequency)
        legend.push_back({QStringLiteral("f = 1/T = %1 Hz").arg(*o.designFrequency, 0, 'f', 3),
                          QColor(30, 60, 160), Qt::DotLine});
    return legend;
}

// Entries the overlay will list: A_crit(f), the codes in range and f = 1/T.
std::size_t legendSize(const DesignOverlay& o) {
    return 1 + o.codes.size() + (o.designFrequency ? 1 : 0);
}

} // namespace

void paintContourMap(QPainter& p, const QRectF& area, const SurfaceData& s,
                     const DesignOverlay& overlay, const QString& gammaLabel) {
    if (s.amplitudes.size() < 2 || s.frequencies.size() < 2) return;
    // The legend goes in a strip under the axes, never over the bands or the design points.
    const FigureScale scale{area.width()};
    const double strip = legendRowsHeight(scale, legendSize(overlay), 3);
    const QRectF plotArea = area.adjusted(0, 0, 0, -strip);
    const PlotFrame fr(plotArea, s.amplitudes.front(), s.amplitudes.back(), s.frequencies.front(),
                       s.frequencies.back(), 13);
    // Band edges: 0 (stable) | a sliver above 0 | round steps up to the largest γc.
    const double top = std::max(s.maxGamma(), 1e-3);
    std::vector<double> ticks = niceTicks(0, top, 7);
    const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : top;
    if (ticks.back() < top * (1 + 1e-12)) ticks.push_back(ticks.back() + step); // cover the max
    std::vector<double> levels{-1e-300, 1e-12};
    for (double t : ticks)
        if (t > 0) levels.push_back(t);
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    paintBands(p, fr, s, levels);
    levels.front() = 0;
    fr.drawAxes(p, QStringLiteral("peak floor acceleration A (g)"),
                QStringLiteral("frequency f (Hz)"));
    const std::vector<LegendEntry> legend = paintOverlay(p, fr, overlay);
    drawLegendRows(p, fr.scale(),
                   QRectF(fr.plot().left(), plotArea.bottom(), fr.plot().width(), strip), legend,
                   3);
    paintColourBar(p, fr, levels, gammaLabel);
    p.restore();
}

} // namespace kinstab::report
