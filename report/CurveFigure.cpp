// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/CurveFigure.h"

#include "report/PlotFrame.h"

namespace kinstab::report {

void paintCurves(QPainter& p, const QRectF& area, const CurvePlot& plot) {
    const PlotFrame fr(area, plot.xlo, plot.xhi, plot.ylo, plot.yhi);
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    fr.drawAxes(p, plot.xLabel, plot.yLabel);
    p.setClipRect(fr.plot());
    std::vector<LegendEntry> legend;
    for (const Curve& c : plot.curves) {
        QPolygonF line;
        for (const QPointF& q : c.points)
            line << fr.map(q.x(), q.y());
        p.setPen(fr.scale().pen(c.colour, c.width));
        p.drawPolyline(line);
        if (!c.label.isEmpty()) legend.push_back({c.label, c.colour, Qt::SolidLine});
    }
    p.setClipping(false);
    const double u = fr.scale().unit();
    if (!legend.empty())
        drawLegend(p, fr.scale(), QPointF(fr.plot().right() - 1.5 * u, fr.plot().top() + 1.5 * u),
                   legend, true);
    p.restore();
}

} // namespace kinstab::report
