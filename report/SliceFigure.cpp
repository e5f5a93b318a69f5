// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/SliceFigure.h"

#include "report/PlotFrame.h"
#include "report/ReportSections.h"

#include <QFontMetricsF>
#include <QPolygonF>

#include <algorithm>
#include <cmath>

namespace kinstab::report {

namespace {

// The γ axis's ticks: up to the largest finite γ plus 8 % headroom (at least 0.001).
std::vector<double> sliceTicks(const SliceData& s) {
    double gMax = 0;
    for (double g : s.gamma)
        if (std::isfinite(g)) gMax = std::max(gMax, g);
    return niceTicks(0, std::max(gMax, 1e-3) * 1.08, 5);
}

// Points joined where neighbours both collapsed; the jump at A_crit is left open, and so are
// the gaps where γ is unknown.
std::vector<QPolygonF> sliceRuns(const PlotFrame& fr, const SliceData& s) {
    std::vector<QPolygonF> runs;
    QPolygonF run;
    auto flush = [&] {
        if (run.size() > 1) runs.push_back(run);
        run.clear();
    };
    for (std::size_t k = 0; k < s.amplitudes.size(); ++k) {
        const double g = s.gamma[k];
        if (!std::isfinite(g)) {
            flush();
            continue;
        }
        if (!run.isEmpty() && (g > 0) != (s.gamma[k - 1] > 0)) flush();
        run << fr.map(s.amplitudes[k], g);
    }
    flush();
    return runs;
}

// A_crit (solid red) and the code ratios (dashed) as vertical lines; returns their legend.
std::vector<LegendEntry> paintMarks(QPainter& p, const PlotFrame& fr, const SliceData& s,
                                    const std::vector<CodeMark>& codes) {
    std::vector<LegendEntry> legend;
    if (s.aCrit) {
        fr.verticalLine(p, *s.aCrit, QColor(200, 30, 30), Qt::SolidLine);
        legend.push_back({QStringLiteral("A_crit = %1 g").arg(accelG(*s.aCrit)),
                          QColor(200, 30, 30), Qt::SolidLine});
    }
    for (const CodeMark& c : codes) {
        fr.verticalLine(p, c.ratio, c.colour, Qt::DashLine);
        legend.push_back(codeRatioEntry(c.label, c.ratio, c.colour));
    }
    return legend;
}

} // namespace

void paintSlice(QPainter& p, const QRectF& area, const SliceData& s,
                const std::vector<CodeMark>& codes, const QString& gammaLabel) {
    if (s.amplitudes.size() < 2) return;
    const std::vector<double> yt = sliceTicks(s);
    // The legend goes in a strip under the axes: inside the plot it covered the curve above
    // A_crit wherever the code lines lie far left.
    const FigureScale scale{area.width()};
    const std::size_t entries = (s.aCrit ? 1 : 0) + codes.size();
    const double strip = entries > 0 ? legendRowsHeight(scale, entries, 3) : 0.0;
    const QRectF plotArea = area.adjusted(0, 0, 0, -strip);
    const PlotFrame fr(plotArea, s.amplitudes.front(), s.amplitudes.back(), 0, yt.back());
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    fr.drawAxes(p, QStringLiteral("peak floor acceleration A (g)"), gammaLabel);
    p.setPen(fr.scale().pen(Qt::black, 0.35));
    for (const QPolygonF& run : sliceRuns(fr, s))
        p.drawPolyline(run);
    const std::vector<LegendEntry> legend = paintMarks(p, fr, s, codes);
    if (!legend.empty())
        drawLegendRows(p, fr.scale(),
                       QRectF(fr.plot().left(), plotArea.bottom(), fr.plot().width(), strip),
                       legend, 3);
    p.restore();
}

void paintExcitation(QPainter& p, const QRectF& area, const ExcitationPlot& e) {
    if (e.timeSeconds.size() < 2) return;
    const PlotFrame fr(area, e.timeSeconds.front(), e.timeSeconds.back(), -1.1, 1.1);
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    fr.drawAxes(p, QStringLiteral("time t (s)"), QStringLiteral("a(t) / A"));
    QPolygonF acc, up, down;
    for (std::size_t k = 0; k < e.timeSeconds.size(); ++k) {
        acc << fr.map(e.timeSeconds[k], e.accel[k]);
        up << fr.map(e.timeSeconds[k], e.envelope[k]);
        down << fr.map(e.timeSeconds[k], -e.envelope[k]);
    }
    p.setPen(fr.scale().pen(QColor(60, 60, 60), 0.12));
    p.drawPolyline(acc);
    p.setPen(fr.scale().pen(QColor(200, 30, 30), 0.35));
    p.drawPolyline(up);
    p.drawPolyline(down);
    if (!e.title.isEmpty()) {
        p.setFont(fr.scale().font(2.1));
        const QFontMetricsF fm(p.font());
        const double u = fr.scale().unit();
        const QRectF plot = fr.plot();
        p.drawText(
            QPointF(plot.right() - u - fm.horizontalAdvance(e.title), plot.top() + u + fm.ascent()),
            e.title);
    }
    p.restore();
}

} // namespace kinstab::report
