// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/OverturningMapPlot.h"

#include "ui/ColourBar.h"
#include "ui/HeatMapView.h" // gammaColor
#include "ui/NiceTicks.h"

#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

namespace {
constexpr double kLeft = 58, kTop = 30, kBottom = 46, kRight = 12;

// A cell's edges lie halfway between its point and the next: the axis from the first point
// minus half a step to the last plus half a step.
std::pair<double, double> cellSpan(const std::vector<double>& v) {
    if (v.size() < 2) return {v.empty() ? 0.0 : v.front() * 0.5, v.empty() ? 1.0 : v.front() * 1.5};
    const double step = (v.back() - v.front()) / static_cast<double>(v.size() - 1);
    return {v.front() - step / 2, v.back() + step / 2};
}
} // namespace

QColor overturnColor() {
    return QColor(45, 40, 45);
}
QColor leavesBaseColor() {
    return QColor(185, 185, 185); // grey: no fate the model can tell
}
QColor survivesColor(double r) {
    return gammaColor(r);
}
// Bright on the dark overturning cells and on the colour scale alike.
QPen otherBoundaryPen() {
    return QPen(QColor(255, 0, 200), 2.0, Qt::DashLine, Qt::FlatCap);
}

OverturningMapPlot::OverturningMapPlot(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setObjectName(QStringLiteral("overturningMapPlot"));
}

void OverturningMapPlot::setMaps(const OverturningMap& main,
                                 const std::optional<OverturningMap>& other,
                                 const QString& mainName, const QString& otherName) {
    m_main = main;
    m_other = other;
    m_mainName = mainName;
    m_otherName = otherName;
    rebuildImage();
    update();
}

void OverturningMapPlot::clear() {
    setMaps(OverturningMap{}, std::nullopt, QString(), QString());
}

void OverturningMapPlot::rebuildImage() {
    const int na = static_cast<int>(m_main.amplitudes.size());
    const int nf = static_cast<int>(m_main.frequencies.size());
    if (na == 0 || nf == 0) {
        m_cells = QImage();
        return;
    }
    m_cells = QImage(nf, na, QImage::Format_RGB32);
    for (int i = 0; i < nf; ++i)
        for (int j = 0; j < na; ++j) {
            const std::size_t k = m_main.at(i, j);
            const unsigned char o = m_main.overturns[k];
            const QColor c = o == 1   ? overturnColor()
                             : o == 2 ? leavesBaseColor()
                                      : survivesColor(m_main.maxThetaOverAlpha[k]);
            m_cells.setPixelColor(i, na - 1 - j, c);
        }
}

int OverturningMapPlot::legendWidth() const {
    return fontMetrics().horizontalAdvance(QStringLiteral("— — linearised boundary")) + 24;
}

QRectF OverturningMapPlot::plotRect() const {
    return QRectF(kLeft, kTop, std::max(40.0, width() - kLeft - kRight - legendWidth()),
                  std::max(40.0, height() - kTop - kBottom));
}

std::optional<std::pair<int, int>> OverturningMapPlot::cellAt(QPointF pos) const {
    const QRectF r = plotRect();
    const int na = static_cast<int>(m_main.amplitudes.size());
    const int nf = static_cast<int>(m_main.frequencies.size());
    if (na == 0 || nf == 0 || !r.contains(pos)) return std::nullopt;
    const int i = std::clamp(static_cast<int>((pos.x() - r.left()) / r.width() * nf), 0, nf - 1);
    const int j = std::clamp(static_cast<int>((r.bottom() - pos.y()) / r.height() * na), 0, na - 1);
    return std::make_pair(i, j);
}

void OverturningMapPlot::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().base());
    const QRectF r = plotRect();
    if (m_cells.isNull()) {
        p.setPen(palette().color(QPalette::PlaceholderText));
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                   tr("Run (F5) computes the overturning map of the block"));
        return;
    }
    p.drawImage(r, m_cells); // one pixel per point, scaled without smoothing
    p.setRenderHint(QPainter::Antialiasing);
    paintBoundary(p, m_main, QPen(Qt::white, 1.6));
    if (m_other) {
        paintBoundary(p, *m_other, otherBoundaryPen());
    }
    if (m_hoverI >= 0) {
        const double cw = r.width() / m_cells.width(), ch = r.height() / m_cells.height();
        p.setPen(QPen(Qt::white, 1.5));
        p.setBrush(Qt::NoBrush);
        p.drawRect(QRectF(r.left() + m_hoverI * cw, r.bottom() - (m_hoverJ + 1) * ch, cw, ch));
    }
    paintAxes(p);
    paintLegend(p);
}

// The edges between overturning and other points, cell by cell: a staircase that follows the
// grid exactly (no interpolation claims more than the points say).
void OverturningMapPlot::paintBoundary(QPainter& p, const OverturningMap& m,
                                       const QPen& pen) const {
    const int na = static_cast<int>(m.amplitudes.size()),
              nf = static_cast<int>(m.frequencies.size());
    if (na == 0 || nf == 0 || na != m_cells.height() || nf != m_cells.width()) return;
    const QRectF r = plotRect();
    const double cw = r.width() / nf, ch = r.height() / na;
    auto over = [&](int i, int j) { return m.overturns[m.at(i, j)] == 1; };
    QVector<QLineF> lines;
    for (int i = 0; i < nf; ++i)
        for (int j = 0; j < na; ++j) {
            const double x0 = r.left() + i * cw, y0 = r.bottom() - j * ch;
            if (i + 1 < nf && over(i, j) != over(i + 1, j))
                lines.append(QLineF(x0 + cw, y0, x0 + cw, y0 - ch));
            if (j + 1 < na && over(i, j) != over(i, j + 1))
                lines.append(QLineF(x0, y0 - ch, x0 + cw, y0 - ch));
        }
    p.setPen(pen);
    p.drawLines(lines);
}

void OverturningMapPlot::paintAxes(QPainter& p) const {
    const QRectF r = plotRect();
    p.setRenderHint(QPainter::Antialiasing, false);
    p.setPen(palette().color(QPalette::Text));
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
    const QFontMetricsF fm(font());
    const auto [f0, f1] = cellSpan(m_main.frequencies);
    const auto [a0, a1] = cellSpan(m_main.amplitudes);
    const int fd = niceAxis(f0, f1, 8).decimals(), ad = niceAxis(a0, a1, 8).decimals();
    for (double t : niceTicks(f0, f1, 8)) {
        const double x = r.left() + (t - f0) / (f1 - f0) * r.width();
        p.drawLine(QPointF(x, r.bottom()), QPointF(x, r.bottom() + 4));
        const QString s = QString::number(t, 'f', fd);
        p.drawText(QPointF(x - fm.horizontalAdvance(s) / 2, r.bottom() + 6 + fm.ascent()), s);
    }
    for (double t : niceTicks(a0, a1, 8)) {
        const double y = r.bottom() - (t - a0) / (a1 - a0) * r.height();
        p.drawLine(QPointF(r.left() - 4, y), QPointF(r.left(), y));
        const QString s = QString::number(t, 'f', ad);
        p.drawText(QPointF(r.left() - 7 - fm.horizontalAdvance(s), y + fm.ascent() / 2 - 1), s);
    }
    const QString xt = QStringLiteral("ω_p / p");
    p.drawText(QPointF(r.center().x() - fm.horizontalAdvance(xt) / 2, height() - 6), xt);
    p.save();
    p.translate(14, r.center().y());
    p.rotate(-90);
    const QString yt = QStringLiteral("a_p / (α g)");
    p.drawText(QPointF(-fm.horizontalAdvance(yt) / 2, 0), yt);
    p.restore();
}

// Right of the plot: the colour scale of the surviving points, then the swatches and the two
// boundaries' line styles.
void OverturningMapPlot::paintLegend(QPainter& p) const {
    const QRectF r = plotRect();
    const QFontMetricsF fm(font());
    const double x = r.right() + 14;
    const QRectF bar(x, r.top() + fm.height() + 4, 0, std::min(160.0, r.height() * 0.45));
    p.setPen(palette().color(QPalette::Text));
    paintColourBar(p, bar, 1.0, tr("survives: max |θ|/α"));
    double y = bar.bottom() + fm.height() + 8;
    auto swatch = [&](const QColor& c, const QString& text) {
        p.fillRect(QRectF(x, y - fm.ascent() + 1, 14, fm.ascent() - 1), c);
        p.setPen(palette().color(QPalette::Text));
        p.drawText(QPointF(x + 20, y), text);
        y += fm.height() + 4;
    };
    swatch(overturnColor(), tr("overturns"));
    swatch(leavesBaseColor(), tr("leaves the base"));
    // Each line on a patch of the overturning colour, as it shows on the map's edge.
    auto line = [&](const QPen& pen, const QString& text) {
        p.fillRect(QRectF(x - 2, y - fm.ascent(), 20, fm.ascent() + 2), overturnColor());
        p.setPen(pen);
        p.drawLine(QPointF(x, y - fm.ascent() / 2), QPointF(x + 16, y - fm.ascent() / 2));
        p.setPen(palette().color(QPalette::Text));
        p.drawText(QPointF(x + 22, y), text);
        y += fm.height() + 4;
    };
    line(QPen(Qt::white, 1.6), tr("%1 boundary").arg(m_mainName));
    if (m_other) line(otherBoundaryPen(), tr("%1 boundary").arg(m_otherName));
}

void OverturningMapPlot::mouseMoveEvent(QMouseEvent* e) {
    const auto c = cellAt(e->position());
    const int i = c ? c->first : -1, j = c ? c->second : -1;
    if (i == m_hoverI && j == m_hoverJ) return;
    m_hoverI = i;
    m_hoverJ = j;
    update();
    emit hovered(i, j);
}

void OverturningMapPlot::leaveEvent(QEvent*) {
    if (m_hoverI < 0) return;
    m_hoverI = m_hoverJ = -1;
    update();
    emit hovered(-1, -1);
}

} // namespace kinstab::ui
