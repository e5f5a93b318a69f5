// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/HeatMapView.h"

#include "ui/ColourBar.h"
#include "ui/NiceTicks.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

QString emptyHint() {
    return HeatMapView::tr("Press Run (F5) to compute γc(A, f) for these inputs");
}

HeatMapView::HeatMapView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(300, 250);
    setToolTip(tr("γc(A, f) as a colour map (OpenGL is not available for the 3D view). Click a "
                  "cell to see that run."));
}

void HeatMapView::setData(const GammaGrid& g) {
    m_grid = g;
    updateRanges();
    update();
}

void HeatMapView::setOverlays(const SurfaceOverlays& o) {
    m_overlays = o;
    updateRanges();
    update();
}

void HeatMapView::setStale(bool stale) {
    m_stale = stale;
    update();
}

void HeatMapView::setSelected(int ai, int fi) {
    m_selA = ai;
    m_selF = fi;
    update();
}

// The axes fit the grid's cells (half a step beyond the first and last points); code ratios
// outside it are listed in the legend, not drawn by stretching the axis.
void HeatMapView::updateRanges() {
    if (m_grid.empty()) return;
    auto half = [](const std::vector<double>& v) {
        return v.size() > 1 ? 0.5 * (v[1] - v[0]) : 0.025;
    };
    m_aMin = m_grid.amplitudes.front() - half(m_grid.amplitudes);
    m_aMax = m_grid.amplitudes.back() + half(m_grid.amplitudes);
    m_fMin = m_grid.frequencies.front() - half(m_grid.frequencies);
    m_fMax = m_grid.frequencies.back() + half(m_grid.frequencies);
    m_gMax = colourScaleMaximum(m_grid);
}

QRectF HeatMapView::plotRect() const {
    const QFontMetrics fm(font());
    const int right = colourBarWidth(fm, m_gMax) + 30;
    const int left = fm.horizontalAdvance(QStringLiteral("00.00")) + fm.height() + 12;
    return QRectF(left, fm.height() + 14, width() - left - right, height() - 3 * fm.height() - 26);
}

double HeatMapView::xOf(double a) const {
    const QRectF r = plotRect();
    return r.left() + (a - m_aMin) / (m_aMax - m_aMin) * r.width();
}

double HeatMapView::yOf(double f) const {
    const QRectF r = plotRect();
    return r.bottom() - (f - m_fMin) / (m_fMax - m_fMin) * r.height();
}

void HeatMapView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().base());
    if (m_grid.empty()) {
        p.setPen(palette().placeholderText().color());
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, emptyHint());
        return;
    }
    p.setRenderHint(QPainter::Antialiasing);
    paintCells(p);
    paintOverlays(p);
    paintAxes(p);
    if (m_stale) p.fillRect(rect(), QColor(255, 255, 255, 165)); // dimmed, still readable
}

void HeatMapView::paintCells(QPainter& p) const {
    const auto& as = m_grid.amplitudes;
    const auto& fs = m_grid.frequencies;
    // One pixel per grid point, scaled up without smoothing: thousands of antialiased
    // rectangles would take tens of milliseconds per repaint during a sweep.
    QImage cells(static_cast<int>(as.size()), static_cast<int>(fs.size()), QImage::Format_RGB32);
    for (std::size_t i = 0; i < as.size(); ++i)
        for (std::size_t j = 0; j < fs.size(); ++j) {
            const double g = m_grid.at(i, j);
            const QColor c = std::isfinite(g) ? gammaColor(g / m_gMax) : notComputedColor();
            cells.setPixel(static_cast<int>(i), static_cast<int>(fs.size() - 1 - j), c.rgb());
        }
    // The axes end at the cell edges (updateRanges), so the image fills the plot.
    const QRectF target = plotRect();
    p.save();
    p.setClipRect(plotRect());
    p.setRenderHint(QPainter::SmoothPixmapTransform, false);
    p.drawImage(target, cells);
    p.restore();
    if (m_selA >= 0 && m_selF >= 0 && static_cast<std::size_t>(m_selA) < as.size() &&
        static_cast<std::size_t>(m_selF) < fs.size()) {
        p.setPen(QPen(Qt::white, 2));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(QPointF(xOf(as[static_cast<std::size_t>(m_selA)]),
                              yOf(fs[static_cast<std::size_t>(m_selF)])),
                      6, 6);
    }
}

void HeatMapView::paintOverlays(QPainter& p) const {
    const QRectF r = plotRect();
    p.save();
    p.setClipRect(r);
    for (const CodeRatio& c : m_overlays.codes) {
        p.setPen(QPen(c.color, 2.5, Qt::DashLine));
        p.drawLine(QPointF(xOf(c.ratio), r.top()), QPointF(xOf(c.ratio), r.bottom()));
    }
    if (m_overlays.buildingFrequency) {
        p.setPen(QPen(Qt::black, 2, Qt::DotLine));
        const double y = yOf(*m_overlays.buildingFrequency);
        p.drawLine(QPointF(r.left(), y), QPointF(r.right(), y));
        for (const CodeRatio& c : m_overlays.codes) {
            p.setPen(QPen(Qt::black, 1.5));
            p.setBrush(c.color);
            p.drawEllipse(QPointF(xOf(c.ratio), y), 5, 5);
        }
    }
    if (!m_overlays.aCrit.empty()) {
        QPainterPath path;
        path.moveTo(xOf(m_overlays.aCrit.front().second), yOf(m_overlays.aCrit.front().first));
        for (const auto& [f, a] : m_overlays.aCrit)
            path.lineTo(xOf(a), yOf(f));
        p.setPen(QPen(Qt::white, 2.5));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
    }
    p.restore();
}

void HeatMapView::paintAxes(QPainter& p) const {
    const QRectF r = plotRect();
    p.setPen(palette().text().color());
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
    const QFontMetrics fm(font());
    const NiceAxis ax = niceAxis(m_aMin, m_aMax, 6), fx = niceAxis(m_fMin, m_fMax, 6);
    for (double a : niceTicks(m_aMin, m_aMax, 6)) {
        const QString t = QString::number(a, 'f', ax.decimals());
        p.drawLine(QPointF(xOf(a), r.bottom()), QPointF(xOf(a), r.bottom() + 4));
        p.drawText(QPointF(xOf(a) - fm.horizontalAdvance(t) / 2.0, r.bottom() + 4 + fm.ascent()),
                   t);
    }
    for (double f : niceTicks(m_fMin, m_fMax, 6)) {
        const QString t = QString::number(f, 'f', fx.decimals());
        p.drawLine(QPointF(r.left() - 4, yOf(f)), QPointF(r.left(), yOf(f)));
        p.drawText(QPointF(r.left() - fm.horizontalAdvance(t) - 6, yOf(f) + fm.ascent() / 2.0 - 1),
                   t);
    }
    p.drawText(QRectF(r.left(), r.bottom() + fm.height() + 6, r.width(), fm.height() + 4),
               Qt::AlignCenter, tr("Peak floor acceleration A (g)"));
    p.save();
    p.translate(fm.height() / 2.0 + 2, r.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-r.height() / 2, -fm.height() / 2.0 - 2, r.height(), fm.height() + 4),
               Qt::AlignCenter, tr("Frequency f (Hz)"));
    p.restore();
    paintColourBar(p, QRectF(r.right() + 16, r.top(), 16, r.height()), m_gMax, m_grid.gammaTitle);
}

void HeatMapView::mousePressEvent(QMouseEvent* e) {
    if (m_grid.empty() || !plotRect().contains(e->position())) return;
    auto nearest = [](const std::vector<double>& v, auto coord, double pos) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < v.size(); ++i)
            if (std::abs(coord(v[i]) - pos) < std::abs(coord(v[best]) - pos)) best = i;
        return static_cast<int>(best);
    };
    const int ai = nearest(
        m_grid.amplitudes, [this](double a) { return xOf(a); }, e->position().x());
    const int fi = nearest(
        m_grid.frequencies, [this](double f) { return yOf(f); }, e->position().y());
    setSelected(ai, fi);
    emit pointSelected(ai, fi);
}

} // namespace kinstab::ui
