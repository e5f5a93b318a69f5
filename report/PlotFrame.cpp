// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/PlotFrame.h"

#include <QFontMetricsF>

#include <cmath>

namespace kinstab::report {

std::vector<double> niceTicks(double lo, double hi, int target) {
    std::vector<double> ticks;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {lo};
    const double raw = (hi - lo) / std::max(1, target);
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
        if (m * mag >= raw) {
            step = m * mag;
            break;
        }
    const double first = std::ceil(lo / step - 1e-9) * step;
    for (double v = first; v <= hi + step * 1e-9; v += step)
        ticks.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
    return ticks;
}

QString tickLabel(double v, double step) {
    int digits = 0;
    while (digits < 6 && std::abs(step * std::pow(10.0, digits) -
                                  std::round(step * std::pow(10.0, digits))) > 1e-6)
        ++digits;
    return QString::number(v, 'f', digits);
}

QFont FigureScale::font(double size, bool bold) const {
    QFont f(QStringLiteral("DejaVu Sans"));
    f.setPixelSize(std::max(1, static_cast<int>(std::lround(size * unit()))));
    f.setBold(bold);
    f.setHintingPreference(QFont::PreferNoHinting);
    return f;
}

QPen FigureScale::pen(const QColor& c, double widthUnits) const {
    QPen p(c, widthUnits * unit());
    p.setCapStyle(Qt::FlatCap);
    p.setJoinStyle(Qt::RoundJoin);
    return p;
}

namespace {
double legendRow(const FigureScale& sc) {
    QFont f = sc.font(2.1);
    return QFontMetricsF(f).height() * 1.15;
}
} // namespace

double legendRowsHeight(const FigureScale& sc, std::size_t entries, int columns) {
    const std::size_t rows =
        (entries + static_cast<std::size_t>(columns) - 1) / static_cast<std::size_t>(columns);
    return legendRow(sc) * static_cast<double>(rows) + sc.unit();
}

void drawLegendRows(QPainter& p, const FigureScale& sc, const QRectF& area,
                    const std::vector<LegendEntry>& entries, int columns) {
    const double u = sc.unit(), row = legendRow(sc), line = 4 * u;
    const double column = area.width() / columns;
    p.save();
    p.setFont(sc.font(2.1));
    const QFontMetricsF fm(p.font());
    for (std::size_t k = 0; k < entries.size(); ++k) {
        const double x = area.left() + column * static_cast<double>(k % columns);
        const double y = area.top() + 0.5 * u + row * (static_cast<double>(k / columns) + 0.5);
        QPen pen = sc.pen(entries[k].colour, 0.35);
        pen.setStyle(entries[k].style);
        p.setPen(pen);
        p.drawLine(QPointF(x, y), QPointF(x + line - u, y));
        p.setPen(entries[k].colour);
        p.drawText(QPointF(x + line, y + fm.ascent() / 2 - fm.descent() / 2), entries[k].label);
    }
    p.restore();
}

void drawLegend(QPainter& p, const FigureScale& sc, const QPointF& at,
                const std::vector<LegendEntry>& entries, bool alignRight) {
    if (entries.empty()) return;
    const double u = sc.unit();
    p.save();
    p.setFont(sc.font(2.1));
    const QFontMetricsF fm(p.font());
    double textWidth = 0;
    for (const LegendEntry& e : entries)
        textWidth = std::max(textWidth, fm.horizontalAdvance(e.label));
    const double line = 4 * u, row = fm.height() * 1.15;
    const QRectF box(alignRight ? at.x() - (line + textWidth + 3 * u) : at.x(), at.y(),
                     line + textWidth + 3 * u, row * entries.size() + u);
    p.setPen(sc.pen(QColor(160, 160, 160), 0.1));
    p.setBrush(QColor(255, 255, 255, 235));
    p.drawRect(box);
    for (std::size_t k = 0; k < entries.size(); ++k) {
        const double y = box.top() + 0.5 * u + row * (k + 0.5);
        QPen pen = sc.pen(entries[k].colour, 0.35);
        pen.setStyle(entries[k].style);
        p.setPen(pen);
        p.drawLine(QPointF(box.left() + u, y), QPointF(box.left() + u + line - u, y));
        p.setPen(entries[k].colour);
        p.drawText(QPointF(box.left() + line + u, y + fm.ascent() / 2 - fm.descent() / 2),
                   entries[k].label);
    }
    p.restore();
}

PlotFrame::PlotFrame(const QRectF& area, double xlo, double xhi, double ylo, double yhi,
                     double rightRoom)
    : xlo_(xlo), xhi_(xhi), ylo_(ylo), yhi_(yhi), scale_{area.width()} {
    const double u = scale_.unit();
    plot_ = area.adjusted(9 * u, 3 * u, -(3 + rightRoom) * u, -8 * u);
}

double PlotFrame::mapX(double x) const {
    return plot_.left() + (x - xlo_) / (xhi_ - xlo_) * plot_.width();
}

double PlotFrame::mapY(double y) const {
    return plot_.bottom() - (y - ylo_) / (yhi_ - ylo_) * plot_.height();
}

QPointF PlotFrame::map(double x, double y) const {
    return {mapX(x), mapY(y)};
}

LegendEntry codeRatioEntry(const QString& code, double ratio, const QColor& colour) {
    return {QStringLiteral("%1: %2").arg(code).arg(ratio, 0, 'f', 3), colour, Qt::DashLine};
}

bool PlotFrame::verticalLine(QPainter& p, double x, const QColor& c, Qt::PenStyle style) const {
    const double px = mapX(x);
    if (px < plot_.left() || px > plot_.right()) return false;
    QPen pen = scale_.pen(c, 0.3);
    pen.setStyle(style);
    p.setPen(pen);
    p.drawLine(QPointF(px, plot_.top()), QPointF(px, plot_.bottom()));
    return true;
}

void PlotFrame::drawAxes(QPainter& p, const QString& xLabel, const QString& yLabel) const {
    const double u = scale_.unit();
    p.save();
    p.setBrush(Qt::NoBrush);
    p.setFont(scale_.font(2.3));
    const QFontMetricsF fm(p.font());
    const std::vector<double> xt = niceTicks(xlo_, xhi_, 7);
    const std::vector<double> yt = niceTicks(ylo_, yhi_, 6);
    const double xs = xt.size() > 1 ? xt[1] - xt[0] : 1.0;
    const double ys = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
    for (double x : xt) {
        const double px = mapX(x);
        p.setPen(scale_.pen(QColor(0, 0, 0, 28), 0.12));
        p.drawLine(QPointF(px, plot_.top()), QPointF(px, plot_.bottom()));
        p.setPen(scale_.pen(Qt::black, 0.15));
        p.drawLine(QPointF(px, plot_.bottom()), QPointF(px, plot_.bottom() + 0.8 * u));
        const QString s = tickLabel(x, xs);
        p.drawText(
            QPointF(px - fm.horizontalAdvance(s) / 2, plot_.bottom() + 1.2 * u + fm.ascent()), s);
    }
    for (double y : yt) {
        const double py = mapY(y);
        p.setPen(scale_.pen(QColor(0, 0, 0, 28), 0.12));
        p.drawLine(QPointF(plot_.left(), py), QPointF(plot_.right(), py));
        p.setPen(scale_.pen(Qt::black, 0.15));
        p.drawLine(QPointF(plot_.left() - 0.8 * u, py), QPointF(plot_.left(), py));
        const QString s = tickLabel(y, ys);
        p.drawText(QPointF(plot_.left() - 1.2 * u - fm.horizontalAdvance(s),
                           py + fm.ascent() / 2 - fm.descent() / 2),
                   s);
    }
    p.setPen(scale_.pen(Qt::black, 0.25));
    p.drawRect(plot_);
    p.setFont(scale_.font(2.6));
    const QFontMetricsF lm(p.font());
    p.drawText(QPointF(plot_.center().x() - lm.horizontalAdvance(xLabel) / 2,
                       plot_.bottom() + 3.2 * u + fm.height() + lm.ascent() / 2),
               xLabel);
    p.translate(plot_.left() - 6.6 * u - lm.descent(), plot_.center().y());
    p.rotate(-90);
    p.drawText(QPointF(-lm.horizontalAdvance(yLabel) / 2, 0), yLabel);
    p.restore();
}

} // namespace kinstab::report
